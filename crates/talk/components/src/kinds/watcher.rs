//! An event client: activates "count above a threshold" on a publisher at
//! a set time, once or continuously, and notes each notification.

use serde::Deserialize;

use crate::FieldError;
use crate::component::{Component, Interface};
use crate::object::Object;
use crate::pattern::{Pattern, PortSpec, Signature};
use crate::runtime::{Ctx, Mode};

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WatcherParams {
    #[serde(default = "five")]
    pub above: f64,
    #[serde(default = "once")]
    pub mode: Mode,
    /// When to activate, s; `null` never does (see why the port is quiet).
    #[serde(default)]
    pub at: Option<f64>,
}

fn five() -> f64 {
    5.0
}
fn once() -> Mode {
    Mode::Once
}

#[derive(Debug, Clone)]
pub struct Watcher {
    params: WatcherParams,
    pub fired: usize,
}

impl Watcher {
    pub fn new(params: WatcherParams) -> Result<Self, FieldError> {
        kinolab_common::error::finite("params.above", params.above)?;
        if let Some(at) = params.at {
            kinolab_common::error::in_range("params.at", at, 0.0, 3600.0)?;
        }
        Ok(Self { params, fired: 0 })
    }
}

impl Component for Watcher {
    fn interface(&self) -> Interface {
        Interface {
            services: Vec::new(),
            ports: vec![PortSpec::new(
                "alarm",
                Pattern::Event,
                Signature::two("Threshold", "Count"),
                true,
            )],
            master: false,
        }
    }

    fn start(&mut self, cx: &mut Ctx<'_>) {
        if let Some(at) = self.params.at {
            cx.after(at - cx.now(), 0);
        }
    }

    fn timer(&mut self, _tag: u32, cx: &mut Ctx<'_>) {
        let params = Object::new(
            "Threshold",
            serde_json::json!({ "above": self.params.above }),
        );
        if let Err(s) = cx.activate("alarm", params, self.params.mode) {
            cx.note(&format!("could not activate: {}", s.name()));
        }
    }

    fn notified(&mut self, _port: &str, _id: u64, object: &Object, cx: &mut Ctx<'_>) {
        self.fired += 1;
        cx.note(&format!("alarm: {}", object.summary()));
    }

    fn status(&self) -> String {
        format!("fired {} times", self.fired)
    }
}
