//! What a component is to the runtime: the services it provides, the ports
//! it uses, and handlers the runtime calls when something arrives. A
//! component never sees another component; it talks through [`Ctx`].

use serde::Serialize;

use crate::object::Object;
use crate::pattern::{PortSpec, ServiceSpec};
use crate::runtime::{Ctx, Ticket};
use crate::trace::Status;

/// A component's public face: nothing else of it is visible outside.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Interface {
    pub services: Vec<ServiceSpec>,
    pub ports: Vec<PortSpec>,
    /// A master may wire other components' wireable ports.
    pub master: bool,
}

/// Where a component is in its life.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Lifecycle {
    Initialising,
    Running,
    Stopped,
    Failed,
}

impl Lifecycle {
    pub fn name(self) -> &'static str {
        match self {
            Lifecycle::Initialising => "initialising",
            Lifecycle::Running => "running",
            Lifecycle::Stopped => "stopped",
            Lifecycle::Failed => "failed",
        }
    }
}

/// A copy of a component behind a box, so a whole runtime can be copied
/// (the lab's player keeps copies to scrub back); every `Clone` component
/// has it.
pub trait ComponentClone {
    fn clone_box(&self) -> Box<dyn Component>;
}

impl<T: Component + Clone + 'static> ComponentClone for T {
    fn clone_box(&self) -> Box<dyn Component> {
        Box::new(self.clone())
    }
}

impl Clone for Box<dyn Component> {
    fn clone(&self) -> Self {
        self.clone_box()
    }
}

/// The handlers of a component. Every handler has a default that ignores
/// the call, so a component writes only the ones it needs.
pub trait Component: std::fmt::Debug + ComponentClone {
    fn interface(&self) -> Interface;

    /// Called once when initialising is over.
    fn start(&mut self, cx: &mut Ctx<'_>);

    /// A timer set with [`Ctx::after`] is due (delayed while the activity
    /// is blocked in a call or busy).
    fn timer(&mut self, _tag: u32, _cx: &mut Ctx<'_>) {}

    /// A send-pattern command arrived at `service`.
    fn command(&mut self, _service: &str, _object: &Object, _cx: &mut Ctx<'_>) {}

    /// A query arrived; answer now or later with [`Ctx::answer`].
    fn request(&mut self, _service: &str, _ticket: Ticket, _object: &Object, _cx: &mut Ctx<'_>) {}

    /// A call this component waited for (sync use, or `wait`) returned:
    /// with the answer, or with why not (cancelled, disconnected, …).
    fn answered(
        &mut self,
        _port: &str,
        _id: u64,
        _result: Result<Object, Status>,
        _cx: &mut Ctx<'_>,
    ) {
    }

    /// A push update is the newest value on `port`.
    fn update(&mut self, _port: &str, _object: &Object, _cx: &mut Ctx<'_>) {}

    /// An event this component activated fired.
    fn notified(&mut self, _port: &str, _id: u64, _object: &Object, _cx: &mut Ctx<'_>) {}

    /// A client activated an event on `service`: test it now.
    fn activated(&mut self, _service: &str, _cx: &mut Ctx<'_>) {}

    /// One short line of the component's own state, for the lab.
    fn status(&self) -> String {
        String::new()
    }
}
