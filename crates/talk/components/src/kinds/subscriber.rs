//! A subscriber that takes `work` seconds over each value it reads: a slow
//! one shows push newest skipping values, and prescale asking for less.

use serde::Deserialize;

use crate::FieldError;
use crate::component::{Component, Interface};
use crate::object::Object;
use crate::pattern::{Pattern, PortSpec, Signature};
use crate::runtime::Ctx;

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SubscriberParams {
    #[serde(default = "newest")]
    pub pattern: String,
    /// Seconds of work per value read.
    #[serde(default)]
    pub work: f64,
    /// Push timed: take every n-th update.
    #[serde(default = "kinolab_common::defaults::one")]
    pub prescale: u32,
    /// When to subscribe, s.
    #[serde(default)]
    pub subscribe_at: f64,
}

fn newest() -> String {
    "push-newest".to_owned()
}

#[derive(Debug, Clone)]
pub struct Subscriber {
    pattern: Pattern,
    work: f64,
    prescale: u32,
    subscribe_at: f64,
    /// The values read, in order.
    pub read: Vec<f64>,
}

impl Subscriber {
    pub fn new(p: SubscriberParams) -> Result<Self, FieldError> {
        let pattern = super::push_pattern(&p.pattern)?;
        let work = kinolab_common::error::in_range("params.work", p.work, 0.0, 3600.0)?;
        if !(1..=1000).contains(&p.prescale) {
            return Err(FieldError::new("params.prescale", "must be 1 to 1000"));
        }
        let subscribe_at =
            kinolab_common::error::in_range("params.subscribe_at", p.subscribe_at, 0.0, 3600.0)?;
        Ok(Self {
            pattern,
            work,
            prescale: p.prescale,
            subscribe_at,
            read: Vec::new(),
        })
    }
}

impl Component for Subscriber {
    fn interface(&self) -> Interface {
        Interface {
            services: Vec::new(),
            ports: vec![PortSpec::new(
                "value",
                self.pattern,
                Signature::one("Count"),
                true,
            )],
            master: false,
        }
    }

    fn start(&mut self, cx: &mut Ctx<'_>) {
        cx.after(self.subscribe_at - cx.now(), 0);
    }

    fn timer(&mut self, _tag: u32, cx: &mut Ctx<'_>) {
        cx.subscribe("value", self.prescale);
    }

    fn update(&mut self, _port: &str, object: &Object, cx: &mut Ctx<'_>) {
        if self.read.len() < 100_000 {
            self.read.push(object.as_f64().unwrap_or(f64::NAN));
        }
        cx.busy(self.work);
    }

    fn status(&self) -> String {
        match self.read.last() {
            Some(v) => format!("read {} values, last {v}", self.read.len()),
            None => "read nothing yet".to_owned(),
        }
    }
}
