//! A query server that squares numbers, taking its time: request k takes
//! `work[k mod n]` seconds, so answers can overtake each other.

use std::collections::BTreeMap;

use serde::Deserialize;

use crate::FieldError;
use crate::component::{Component, Interface};
use crate::object::Object;
use crate::pattern::{Pattern, ServiceSpec, Signature};
use crate::runtime::{Ctx, Ticket};

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ServerParams {
    /// Seconds each request takes, used in turn.
    #[serde(default = "a_tenth_each")]
    pub work: Vec<f64>,
    /// The answer's type (change it to see wiring refuse a client).
    #[serde(default = "number")]
    pub answer: String,
}

/// A tenth of a second for every request.
fn a_tenth_each() -> Vec<f64> {
    vec![0.1]
}

pub(crate) fn number() -> String {
    "Number".to_owned()
}

#[derive(Debug, Clone)]
pub struct Server {
    params: ServerParams,
    served: usize,
    working: BTreeMap<u32, (Ticket, f64)>,
}

impl Server {
    pub fn new(params: ServerParams) -> Result<Self, FieldError> {
        if params.work.is_empty() || params.work.len() > 100 {
            return Err(FieldError::new("params.work", "needs 1 to 100 durations"));
        }
        for (i, w) in params.work.iter().enumerate() {
            kinolab_common::error::in_range(format!("params.work[{i}]"), *w, 0.0, 3600.0)?;
        }
        Ok(Self {
            params,
            served: 0,
            working: BTreeMap::new(),
        })
    }
}

impl Component for Server {
    fn interface(&self) -> Interface {
        Interface {
            services: vec![ServiceSpec::new(
                "compute",
                Pattern::Query,
                Signature::two("Number", &self.params.answer),
            )],
            ports: Vec::new(),
            master: false,
        }
    }

    fn start(&mut self, _cx: &mut Ctx<'_>) {}

    fn request(&mut self, _service: &str, ticket: Ticket, object: &Object, cx: &mut Ctx<'_>) {
        let work = self.params.work[self.served % self.params.work.len()];
        let tag = (self.served % 1_000_000) as u32;
        self.served += 1;
        self.working
            .insert(tag, (ticket, object.as_f64().unwrap_or(0.0)));
        // The handler returns now; the answer goes out later (an active
        // handler handing the work to another thread).
        cx.after(work, tag);
    }

    fn timer(&mut self, tag: u32, cx: &mut Ctx<'_>) {
        if let Some((ticket, x)) = self.working.remove(&tag) {
            cx.answer(ticket, Object::number(&self.params.answer, x * x));
        }
    }

    fn status(&self) -> String {
        format!(
            "served {}, working on {}",
            self.served - self.working.len(),
            self.working.len()
        )
    }
}
