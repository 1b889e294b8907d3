//! A publisher of a counter: the count goes up after each interval in
//! `every` (in turn), and goes out by push newest (at once) or push timed
//! (at the service's period). Its event service `above` fires when the
//! count passes a client's threshold, and its query service `read` answers
//! with the count on demand (for clients that poll).

use serde::Deserialize;

use crate::FieldError;
use crate::component::{Component, Interface};
use crate::object::Object;
use crate::pattern::{Pattern, ServiceSpec, Signature};
use crate::runtime::{Ctx, Ticket};

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PublisherParams {
    #[serde(default = "newest")]
    pub pattern: String,
    /// Push timed: the service's period, s.
    #[serde(default = "kinolab_common::defaults::tenth")]
    pub period: f64,
    /// Seconds between changes of the count, used in turn.
    #[serde(default = "every")]
    pub every: Vec<f64>,
    /// Count back to 0 after reaching this (a sawtooth), so a condition on
    /// it comes true again and again.
    #[serde(default)]
    pub wrap: Option<u64>,
}

fn newest() -> String {
    "push-newest".to_owned()
}
fn every() -> Vec<f64> {
    vec![0.1]
}

#[derive(Debug, Clone)]
pub struct Publisher {
    pattern: Pattern,
    period: f64,
    every: Vec<f64>,
    wrap: Option<u64>,
    count: u64,
    changes: u64,
}

impl Publisher {
    pub fn new(p: PublisherParams) -> Result<Self, FieldError> {
        let pattern = super::push_pattern(&p.pattern)?;
        let period = kinolab_common::error::in_range("params.period", p.period, 0.01, 3600.0)?;
        if p.every.is_empty() || p.every.len() > 100 {
            return Err(FieldError::new("params.every", "needs 1 to 100 intervals"));
        }
        for (i, e) in p.every.iter().enumerate() {
            kinolab_common::error::in_range(format!("params.every[{i}]"), *e, 0.01, 3600.0)?;
        }
        if p.wrap == Some(0) {
            return Err(FieldError::new("params.wrap", "must be at least 1"));
        }
        Ok(Self {
            pattern,
            period,
            every: p.every,
            wrap: p.wrap,
            count: 0,
            changes: 0,
        })
    }

    fn value(&self) -> Object {
        Object::number("Count", self.count as f64)
    }
}

impl Component for Publisher {
    fn interface(&self) -> Interface {
        Interface {
            services: vec![
                ServiceSpec::new("value", self.pattern, Signature::one("Count")),
                ServiceSpec::new(
                    "above",
                    Pattern::Event,
                    Signature::two("Threshold", "Count"),
                ),
                ServiceSpec::new("read", Pattern::Query, Signature::two("Read", "Count")),
            ],
            ports: Vec::new(),
            master: false,
        }
    }

    fn start(&mut self, cx: &mut Ctx<'_>) {
        cx.publish("value", self.value());
        if self.pattern == Pattern::PushTimed {
            cx.start_timed("value", self.period);
        }
        cx.after(self.every[0], 0);
    }

    fn timer(&mut self, _tag: u32, cx: &mut Ctx<'_>) {
        self.changes += 1;
        self.count = match self.wrap {
            Some(w) => self.changes % (w + 1),
            None => self.changes,
        };
        cx.publish("value", self.value());
        self.activated("above", cx);
        let next = self.every[(self.changes as usize) % self.every.len()];
        cx.after(next, 0);
    }

    fn request(&mut self, _service: &str, ticket: Ticket, _object: &Object, cx: &mut Ctx<'_>) {
        cx.answer(ticket, self.value());
    }

    fn activated(&mut self, _service: &str, cx: &mut Ctx<'_>) {
        let count = self.count as f64;
        cx.test_events("above", &|params: &Object| {
            let threshold = params.field("above").unwrap_or(f64::INFINITY);
            (count > threshold).then(|| Object::number("Count", count))
        });
    }

    fn status(&self) -> String {
        format!("count {}", self.count)
    }
}
