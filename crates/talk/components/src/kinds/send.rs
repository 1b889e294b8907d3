//! The send pattern on its own: a sender that sends a number every period,
//! and a sink that counts what arrives (and never answers).

use serde::Deserialize;

use crate::FieldError;
use crate::component::{Component, Interface};
use crate::object::Object;
use crate::pattern::{Pattern, PortSpec, ServiceSpec, Signature};
use crate::runtime::Ctx;

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SenderParams {
    #[serde(default = "half")]
    pub period: f64,
}

fn half() -> f64 {
    0.5
}

#[derive(Debug, Clone)]
pub struct Sender {
    period: f64,
    sent: u64,
}

impl Sender {
    pub fn new(p: SenderParams) -> Result<Self, FieldError> {
        let period = kinolab_common::error::in_range("params.period", p.period, 0.01, 3600.0)?;
        Ok(Self { period, sent: 0 })
    }
}

impl Component for Sender {
    fn interface(&self) -> Interface {
        Interface {
            services: Vec::new(),
            ports: vec![PortSpec::new(
                "out",
                Pattern::Send,
                Signature::one("Number"),
                false,
            )],
            master: false,
        }
    }

    fn start(&mut self, cx: &mut Ctx<'_>) {
        cx.after(self.period, 0);
    }

    fn timer(&mut self, _tag: u32, cx: &mut Ctx<'_>) {
        self.sent += 1;
        let _ = cx.send("out", Object::number("Number", self.sent as f64));
        cx.after(self.period, 0);
    }

    fn status(&self) -> String {
        format!("sent {}", self.sent)
    }
}

#[derive(Debug, Clone, Default)]
pub struct Sink {
    got: u64,
}

impl Component for Sink {
    fn interface(&self) -> Interface {
        Interface {
            services: vec![ServiceSpec::new(
                "in",
                Pattern::Send,
                Signature::one("Number"),
            )],
            ports: Vec::new(),
            master: false,
        }
    }

    fn start(&mut self, _cx: &mut Ctx<'_>) {}

    fn command(&mut self, _service: &str, _object: &Object, _cx: &mut Ctx<'_>) {
        self.got += 1;
    }

    fn status(&self) -> String {
        format!("got {}", self.got)
    }
}
