//! A query client that follows a short script: wait until a time, send a
//! request (asynchronous use), wait for a given answer, ask and block
//! (synchronous use), or check whether an answer is here.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use crate::FieldError;
use crate::component::{Component, Interface};
use crate::object::Object;
use crate::pattern::{Pattern, PortSpec, Signature};
use crate::runtime::Ctx;
use crate::trace::Status;

/// One step of a client's script: exactly one of the fields.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Step {
    /// Do nothing until this time, s.
    pub at: Option<f64>,
    /// Send a request labelled so, with `value`, and go on.
    pub request: Option<String>,
    pub value: Option<f64>,
    /// Block until the answer to this label is here.
    pub wait: Option<String>,
    /// Synchronous use: request this value and block until the answer.
    pub ask: Option<f64>,
    /// Check, without blocking, whether this label's answer is here.
    pub receive: Option<String>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClientParams {
    pub steps: Vec<Step>,
    /// The request type the port sends.
    #[serde(default = "super::server::number")]
    pub object: String,
    /// The answer type the port expects.
    #[serde(default = "super::server::number")]
    pub answer: String,
}

/// What the client got, in the order it got it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Got {
    pub label: String,
    pub at: f64,
    pub value: Option<f64>,
    pub status: Option<Status>,
}

#[derive(Debug, Clone)]
pub struct Client {
    params: ClientParams,
    next: usize,
    ids: BTreeMap<String, u64>,
    blocked: Option<String>,
    pub got: Vec<Got>,
}

/// The timer tag for `at` steps.
const AT: u32 = 1;
const PORT: &str = "ask";

impl Client {
    pub fn new(params: ClientParams) -> Result<Self, FieldError> {
        if params.steps.len() > 10_000 {
            return Err(FieldError::new("params.steps", "at most 10000 steps"));
        }
        for (i, s) in params.steps.iter().enumerate() {
            let field = format!("params.steps[{i}]");
            let set = [
                s.at.is_some(),
                s.request.is_some(),
                s.wait.is_some(),
                s.ask.is_some(),
                s.receive.is_some(),
            ];
            if set.iter().filter(|x| **x).count() != 1 {
                return Err(FieldError::new(
                    field,
                    "needs exactly one of at, request, wait, ask, receive",
                ));
            }
            if let Some(t) = s.at {
                kinolab_common::error::in_range(format!("{field}.at"), t, 0.0, 3600.0)?;
            }
            if s.request.is_some() && s.value.is_none() {
                return Err(FieldError::new(
                    format!("{field}.value"),
                    "a request needs a value",
                ));
            }
        }
        Ok(Self {
            params,
            next: 0,
            ids: BTreeMap::new(),
            blocked: None,
            got: Vec::new(),
        })
    }

    fn got(&mut self, label: &str, result: Result<Object, Status>, cx: &mut Ctx<'_>) {
        let (value, status) = match &result {
            Ok(o) => (o.as_f64(), None),
            Err(s) => (None, Some(*s)),
        };
        let text = match (value, status) {
            (Some(v), _) => format!("{label} answered: {v}"),
            (_, Some(s)) => format!("{label} returned {}", s.name()),
            _ => format!("{label} answered"),
        };
        cx.note(&text);
        self.got.push(Got {
            label: label.to_owned(),
            at: cx.now(),
            value,
            status,
        });
    }

    fn run(&mut self, cx: &mut Ctx<'_>) {
        while self.blocked.is_none() && self.next < self.params.steps.len() {
            let step = self.params.steps[self.next].clone();
            if let Some(t) = step.at
                && t > cx.now() + 1e-12
            {
                cx.after(t - cx.now(), AT);
                return;
            }
            self.next += 1;
            if let Some(label) = step.request {
                let value = Object::number(&self.params.object, step.value.unwrap_or(0.0));
                match cx.request(PORT, value) {
                    Ok(id) => {
                        self.ids.insert(label, id);
                    }
                    Err(s) => cx.note(&format!("{label} not sent: {}", s.name())),
                }
            } else if let Some(label) = step.wait {
                let Some(&id) = self.ids.get(&label) else {
                    cx.note(&format!("{label} was never requested"));
                    continue;
                };
                match cx.wait(PORT, id) {
                    Some(result) => self.got(&label, result, cx),
                    None => self.blocked = Some(label),
                }
            } else if let Some(x) = step.ask {
                let label = format!("ask {x}");
                match cx.query(PORT, Object::number(&self.params.object, x)) {
                    Ok(id) => {
                        self.ids.insert(label.clone(), id);
                        self.blocked = Some(label);
                    }
                    Err(s) => self.got(&label, Err(s), cx),
                }
            } else if let Some(label) = step.receive {
                let here = self.ids.get(&label).and_then(|&id| cx.receive(PORT, id));
                match here {
                    Some(result) => self.got(&label, result, cx),
                    None => cx.note(&format!("{label}: not here yet")),
                }
            }
        }
    }
}

impl Component for Client {
    fn interface(&self) -> Interface {
        Interface {
            services: Vec::new(),
            ports: vec![PortSpec::new(
                PORT,
                Pattern::Query,
                Signature::two(&self.params.object, &self.params.answer),
                true,
            )],
            master: false,
        }
    }

    fn start(&mut self, cx: &mut Ctx<'_>) {
        self.run(cx);
    }

    fn timer(&mut self, _tag: u32, cx: &mut Ctx<'_>) {
        self.run(cx);
    }

    fn answered(
        &mut self,
        _port: &str,
        _id: u64,
        result: Result<Object, Status>,
        cx: &mut Ctx<'_>,
    ) {
        if let Some(label) = self.blocked.take() {
            self.got(&label, result, cx);
        }
        self.run(cx);
    }

    fn status(&self) -> String {
        match &self.blocked {
            Some(label) => format!("blocked, waiting for {label}"),
            None if self.next >= self.params.steps.len() => {
                format!("done, {} answers", self.got.len())
            }
            None => format!("step {} of {}", self.next + 1, self.params.steps.len()),
        }
    }
}
