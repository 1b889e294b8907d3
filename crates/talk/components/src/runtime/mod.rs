//! The discrete-event runtime: one simulated clock, a queue of things due,
//! and components that run only when something arrives for them. Nothing
//! depends on the host's clock or on hash order, so the same system and
//! seed give the same trace everywhere.

mod ctx;
mod deliver;
mod wiring;

use std::cmp::{Ordering, Reverse};
use std::collections::{BTreeMap, BinaryHeap};

use kinolab_world::Sim;
use serde::Serialize;

pub use ctx::Ctx;

use crate::FieldError;
use crate::component::{Component, Lifecycle};
use crate::link::Latency;
use crate::object::Object;
use crate::pattern::{PortSpec, Refusal, ServiceSpec};
use crate::trace::{Record, Status};

/// The most records a trace keeps; later messages still run and count.
pub const MAX_RECORDS: usize = 50_000;
/// The most queue items one `run_until` processes (a runaway guard).
pub const MAX_STEPS: u64 = 2_000_000;
/// The shortest timer, s: a component cannot spin at one instant.
pub const MIN_DELAY: f64 = 1e-4;

/// A server's handle on one query, for answering it (now or later).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Ticket {
    pub(crate) service: usize,
    pub id: u64,
}

/// An event's mode: fire once and end, or every time the condition
/// becomes true.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Mode {
    Once,
    Continuous,
}

/// (component, port or service index).
type Ref = (usize, usize);

/// A live connection of a port to a service.
#[derive(Debug, Clone, PartialEq)]
pub struct Wire {
    /// A fresh id per connection: messages of an older one are dropped.
    pub id: u64,
    pub service: Ref,
    pub latency: Latency,
    /// The last arrival time each way (to the server, to the client).
    last: [f64; 2],
}

/// What a port has seen, for "why did this port get nothing?".
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub struct PortStats {
    pub sent: u64,
    pub received: u64,
    pub lost: u64,
    pub skipped: u64,
    pub cancelled: u64,
    /// Push timed: updates the prescale held back.
    pub withheld: u64,
    pub disconnected: u64,
    pub not_connected: u64,
    pub activations: u64,
}

#[derive(Debug, Clone)]
pub(crate) struct PortSlot {
    pub spec: PortSpec,
    pub wire: Option<Wire>,
    pub blocking: bool,
    /// Outstanding query ids and, once arrived, their answers.
    pub answers: BTreeMap<u64, Option<Result<Object, Status>>>,
    pub newest: Option<Object>,
    /// The trace record of an update not read yet.
    pub unread: Option<usize>,
    /// Whether the component asked to be subscribed (kept across rewiring).
    pub subscribed: Option<u32>,
    pub events: Vec<(u64, Mode)>,
    pub stats: PortStats,
    pub refusal: Option<Refusal>,
}

#[derive(Debug, Clone)]
pub(crate) struct Subscriber {
    pub port: Ref,
    pub wire: u64,
    pub prescale: u32,
    pub ticks: u64,
}

#[derive(Debug, Clone)]
pub(crate) struct Activation {
    pub id: u64,
    pub port: Ref,
    pub wire: u64,
    pub params: Object,
    pub mode: Mode,
    pub was_true: bool,
}

#[derive(Debug, Clone)]
pub(crate) struct ServiceSlot {
    pub spec: ServiceSpec,
    pub current: Option<Object>,
    pub subscribers: Vec<Subscriber>,
    /// Push timed: period (s) and whether the timer runs.
    pub period: f64,
    pub running: bool,
    pub activations: Vec<Activation>,
    /// Queries not answered yet: id → (port, wire id).
    pub pending: BTreeMap<u64, (Ref, u64)>,
}

#[derive(Debug, Clone)]
pub(crate) struct Slot {
    pub name: String,
    pub component: Option<Box<dyn Component>>,
    pub state: Lifecycle,
    pub services: Vec<ServiceSlot>,
    pub ports: Vec<PortSlot>,
    pub master: bool,
    /// The call the activity is blocked in.
    pub waiting: Option<(usize, u64)>,
    /// Timers that fell due while blocked.
    pub deferred: Vec<u32>,
    pub busy_until: f64,
    pub wake_due: bool,
}

/// A message on its way.
#[derive(Debug, Clone)]
pub(crate) struct Message {
    pub record: Option<usize>,
    pub wire: u64,
    pub port: Ref,
    pub service: Ref,
    pub kind: Kind,
    pub object: Object,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Kind {
    Command,
    Request(u64),
    /// An answer, or why there is none.
    Answer(u64, Option<Status>),
    Subscribe(u32),
    Unsubscribe,
    Update,
    Activate(u64, Mode),
    Deactivate(u64),
    Notify(u64),
}

impl Kind {
    /// Whether the message goes from the client port to the service.
    pub fn upstream(self) -> bool {
        matches!(
            self,
            Kind::Command
                | Kind::Request(_)
                | Kind::Subscribe(_)
                | Kind::Unsubscribe
                | Kind::Activate(..)
                | Kind::Deactivate(_)
        )
    }

    pub fn name(self) -> &'static str {
        match self {
            Kind::Command => "command",
            Kind::Request(_) => "request",
            Kind::Answer(..) => "answer",
            Kind::Subscribe(_) => "subscribe",
            Kind::Unsubscribe => "unsubscribe",
            Kind::Update => "update",
            Kind::Activate(..) => "activate",
            Kind::Deactivate(_) => "deactivate",
            Kind::Notify(_) => "notify",
        }
    }
}

/// A change made from outside the components (by the system file's
/// deployer or by a learner in the lab).
#[derive(Debug, Clone, PartialEq, Serialize, serde::Deserialize)]
#[serde(tag = "do", rename_all = "kebab-case")]
pub enum Action {
    /// Wire `port` (`component.port`) to `service` (`component.service`).
    Connect {
        port: String,
        service: String,
    },
    Disconnect {
        port: String,
    },
    /// Switch a port to non-blocking: waiting calls return "cancelled".
    Cancel {
        port: String,
    },
    /// Switch a port back to blocking.
    Block {
        port: String,
    },
    Stop {
        component: String,
    },
    Fail {
        component: String,
    },
    Restart {
        component: String,
    },
}

#[derive(Debug, Clone)]
enum What {
    Start(usize),
    Timer(usize, u32),
    Tick(usize, usize),
    Deliver(Box<Message>),
    Wake(usize),
    /// A waiting call released with this status (cancel, disconnect).
    Release(usize, usize, u64, Status),
    Act(Box<Action>),
}

#[derive(Debug, Clone)]
struct Due {
    at: f64,
    seq: u64,
    what: What,
}

impl PartialEq for Due {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Due {}
impl PartialOrd for Due {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Due {
    fn cmp(&self, other: &Self) -> Ordering {
        self.at.total_cmp(&other.at).then(self.seq.cmp(&other.seq))
    }
}

/// The runtime: components, their connections, the clock and the trace.
/// A copy runs on exactly as the original.
#[derive(Debug, Clone)]
pub struct Runtime {
    now: f64,
    seed: u64,
    seq: u64,
    queue: BinaryHeap<Reverse<Due>>,
    /// Messages put on connections so far (each draws its jitter and loss
    /// by its number).
    messages: u64,
    pub(crate) slots: Vec<Slot>,
    pub(crate) trace: Vec<Record>,
    /// Records left out past [`MAX_RECORDS`].
    pub dropped_records: u64,
    /// The latency new connections get.
    pub latency: Latency,
    /// The physical world the robot's components sense and drive.
    pub world: Option<Sim>,
}

impl Runtime {
    pub fn new(seed: u64, latency: Latency) -> Result<Self, FieldError> {
        latency.check().map_err(|e| e.within("latency"))?;
        Ok(Self {
            now: 0.0,
            seed,
            seq: 0,
            queue: BinaryHeap::new(),
            messages: 0,
            slots: Vec::new(),
            trace: Vec::new(),
            dropped_records: 0,
            latency,
            world: None,
        })
    }

    pub fn now(&self) -> f64 {
        self.now
    }

    pub fn seed(&self) -> u64 {
        self.seed
    }

    pub fn trace(&self) -> &[Record] {
        &self.trace
    }

    /// Add a component that starts running after `init` seconds.
    pub fn add(
        &mut self,
        name: &str,
        component: Box<dyn Component>,
        init: f64,
    ) -> Result<usize, FieldError> {
        let field = |f: &str| format!("components[{}].{f}", self.slots.len());
        if name.is_empty() || name.contains('.') {
            return Err(FieldError::new(
                field("name"),
                "a component needs a name without dots",
            ));
        }
        if self.find(name).is_some() {
            return Err(FieldError::new(
                field("name"),
                format!("two components are called `{name}`"),
            ));
        }
        let init = kinolab_common::error::in_range(field("init"), init, 0.0, 3600.0)?;
        let face = component.interface();
        let index = self.slots.len();
        self.slots.push(Slot {
            name: name.to_owned(),
            component: Some(component),
            state: Lifecycle::Initialising,
            services: face
                .services
                .into_iter()
                .map(|spec| ServiceSlot {
                    spec,
                    current: None,
                    subscribers: Vec::new(),
                    period: 0.1,
                    running: false,
                    activations: Vec::new(),
                    pending: BTreeMap::new(),
                })
                .collect(),
            ports: face
                .ports
                .into_iter()
                .map(|spec| PortSlot {
                    spec,
                    wire: None,
                    blocking: true,
                    answers: BTreeMap::new(),
                    newest: None,
                    unread: None,
                    subscribed: None,
                    events: Vec::new(),
                    stats: PortStats::default(),
                    refusal: None,
                })
                .collect(),
            master: face.master,
            waiting: None,
            deferred: Vec::new(),
            busy_until: 0.0,
            wake_due: false,
        });
        self.push(init, What::Start(index));
        Ok(index)
    }

    /// Schedule `action` at time `at`.
    pub fn schedule(&mut self, at: f64, action: Action) {
        self.push(at.max(self.now), What::Act(Box::new(action)));
    }

    /// Run everything due up to and including `until`. Returns `false`
    /// when the step guard stopped the run first.
    pub fn run_until(&mut self, until: f64) -> bool {
        let mut steps = 0;
        while let Some(Reverse(due)) = self.queue.peek() {
            if due.at > until {
                break;
            }
            if steps >= MAX_STEPS {
                return false;
            }
            steps += 1;
            if let Some(Reverse(due)) = self.queue.pop() {
                self.now = due.at;
                self.handle(due.what);
            }
        }
        self.now = self.now.max(until);
        true
    }

    /// The time of the next thing due, if any.
    pub fn next_due(&self) -> Option<f64> {
        self.queue.peek().map(|Reverse(d)| d.at)
    }

    fn push(&mut self, at: f64, what: What) {
        self.seq += 1;
        self.queue.push(Reverse(Due {
            at,
            seq: self.seq,
            what,
        }));
    }

    fn next_seq(&mut self) -> u64 {
        self.seq += 1;
        self.seq
    }

    pub(crate) fn find(&self, name: &str) -> Option<usize> {
        self.slots.iter().position(|s| s.name == name)
    }

    /// Add a trace record; its index, unless the trace is full.
    pub(crate) fn record(&mut self, mut r: Record) -> Option<usize> {
        if self.trace.len() >= MAX_RECORDS {
            self.dropped_records += 1;
            return None;
        }
        r.seq = self.trace.len() as u64;
        self.trace.push(r);
        Some(self.trace.len() - 1)
    }

    pub(crate) fn set_status(&mut self, record: Option<usize>, status: Status) {
        if let Some(r) = record.and_then(|i| self.trace.get_mut(i)) {
            r.status = status;
        }
    }

    fn handle(&mut self, what: What) {
        match what {
            What::Start(c) => {
                self.set_state(c, Lifecycle::Running, "");
                self.call(c, |comp, cx| comp.start(cx));
            }
            What::Timer(c, tag) => self.timer(c, tag),
            What::Tick(c, s) => self.tick(c, s),
            What::Deliver(m) => self.deliver(*m),
            What::Wake(c) => self.wake(c),
            What::Release(c, p, id, status) => self.release(c, p, id, status),
            What::Act(action) => self.act(&action, "deployer"),
        }
    }

    /// Run a handler of component `c`, if it is running.
    pub(crate) fn call(&mut self, c: usize, f: impl FnOnce(&mut dyn Component, &mut Ctx<'_>)) {
        if self.slots[c].state != Lifecycle::Running {
            return;
        }
        let Some(mut comp) = self.slots[c].component.take() else {
            return;
        };
        {
            let mut cx = Ctx::new(self, c);
            f(comp.as_mut(), &mut cx);
        }
        self.slots[c].component = Some(comp);
    }

    fn timer(&mut self, c: usize, tag: u32) {
        let slot = &mut self.slots[c];
        if slot.state != Lifecycle::Running {
            return;
        }
        if slot.waiting.is_some() {
            slot.deferred.push(tag);
        } else if slot.busy_until > self.now {
            let at = slot.busy_until;
            self.push(at, What::Timer(c, tag));
        } else {
            self.call(c, |comp, cx| comp.timer(tag, cx));
        }
    }

    /// The activity is free again: deferred timers run and unread updates
    /// are handed over.
    fn resume(&mut self, c: usize) {
        let tags = std::mem::take(&mut self.slots[c].deferred);
        for tag in tags {
            self.push(self.now, What::Timer(c, tag));
        }
        if self.slots[c].ports.iter().any(|p| p.unread.is_some()) {
            self.schedule_wake(c);
        }
    }

    fn wake(&mut self, c: usize) {
        self.slots[c].wake_due = false;
        for p in 0..self.slots[c].ports.len() {
            let slot = &self.slots[c];
            if slot.waiting.is_some() || slot.state != Lifecycle::Running {
                // `resume` wakes it again when the call returns.
                return;
            }
            if slot.busy_until > self.now {
                self.schedule_wake(c);
                return;
            }
            self.hand_over(c, p);
        }
    }

    /// Hand over unread updates when the component is next free.
    pub(crate) fn schedule_wake(&mut self, c: usize) {
        let slot = &mut self.slots[c];
        if !slot.wake_due {
            slot.wake_due = true;
            let at = slot.busy_until.max(self.now);
            self.push(at, What::Wake(c));
        }
    }

    /// Give the unread newest value of port `p` to its component.
    fn hand_over(&mut self, c: usize, p: usize) {
        let port = &mut self.slots[c].ports[p];
        if port.unread.take().is_none() {
            return;
        }
        let (Some(object), name) = (port.newest.clone(), port.spec.name.clone()) else {
            return;
        };
        self.call(c, |comp, cx| comp.update(&name, &object, cx));
    }

    fn release(&mut self, c: usize, p: usize, id: u64, status: Status) {
        if self.slots[c].waiting != Some((p, id)) {
            return;
        }
        self.slots[c].waiting = None;
        self.slots[c].ports[p].answers.remove(&id);
        let name = self.slots[c].ports[p].spec.name.clone();
        self.call(c, |comp, cx| comp.answered(&name, id, Err(status), cx));
        self.resume(c);
    }

    fn set_state(&mut self, c: usize, state: Lifecycle, by: &str) {
        self.slots[c].state = state;
        let name = self.slots[c].name.clone();
        self.record(Record {
            seq: 0,
            pattern: "state",
            kind: "state",
            from: if by.is_empty() {
                name.clone()
            } else {
                by.to_owned()
            },
            to: name,
            port: String::new(),
            service: String::new(),
            sent: self.now,
            delivered: Some(self.now),
            status: Status::Done,
            summary: state.name().to_owned(),
        });
    }

    /// Carry out an outside action (`by` names who asked).
    pub fn act(&mut self, action: &Action, by: &str) {
        match action {
            Action::Connect { port, service } => {
                // The deployer may wire any port; refusals are in the trace.
                let _ = self.connect(port, service, by, None);
            }
            Action::Disconnect { port } => self.disconnect_named(port, by),
            Action::Cancel { port } => self.set_blocking_named(port, false, by),
            Action::Block { port } => self.set_blocking_named(port, true, by),
            Action::Stop { component } | Action::Fail { component } => {
                if let Some(c) = self.find(component) {
                    let state = if matches!(action, Action::Stop { .. }) {
                        Lifecycle::Stopped
                    } else {
                        Lifecycle::Failed
                    };
                    self.set_state(c, state, by);
                }
            }
            Action::Restart { component } => {
                if let Some(c) = self.find(component)
                    && self.slots[c].state != Lifecycle::Running
                {
                    self.slots[c].waiting = None;
                    self.push(self.now, What::Start(c));
                }
            }
        }
    }
}
