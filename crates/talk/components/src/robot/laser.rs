//! The laser server: scans the world every period and pushes the newest
//! scan to whoever subscribed.

use crate::FieldError;
use crate::component::{Component, Interface};
use crate::object::Object;
use crate::pattern::{Pattern, ServiceSpec, Signature};
use crate::runtime::Ctx;

#[derive(Debug, Clone)]
pub struct Laser {
    period: f64,
    scans: u64,
}

impl Laser {
    pub fn new(p: super::Periodic) -> Result<Self, FieldError> {
        Ok(Self {
            period: p.check()?,
            scans: 0,
        })
    }
}

impl Component for Laser {
    fn interface(&self) -> Interface {
        Interface {
            services: vec![ServiceSpec::new(
                "scan",
                Pattern::PushNewest,
                Signature::one("Scan"),
            )],
            ports: Vec::new(),
            master: false,
        }
    }

    fn start(&mut self, cx: &mut Ctx<'_>) {
        cx.after(self.period, 0);
    }

    fn timer(&mut self, _tag: u32, cx: &mut Ctx<'_>) {
        let Some(sim) = cx.world() else { return };
        let seen = sim.sense();
        let rays: Vec<[f64; 2]> = seen.rays.iter().map(|r| [r.angle, r.range]).collect();
        let max = sim.sensors.rays.map_or(0.0, |r| r.max_range);
        self.scans += 1;
        let scan = Object::new(
            "Scan",
            serde_json::json!({ "rays": rays, "max_range": max, "t": seen.time }),
        );
        cx.publish("scan", scan);
        cx.after(self.period, 0);
    }

    fn status(&self) -> String {
        format!("{} scans", self.scans)
    }
}
