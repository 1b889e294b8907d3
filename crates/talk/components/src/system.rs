//! System files: which components, how they are wired at start, what the
//! deployer changes while the system runs, and in which world the robot
//! lives. Running one gives the trace and the final state.

use kinolab_world::{Body, Sensors, Sim, World};
use serde::{Deserialize, Serialize};

use crate::FieldError;
use crate::link::Latency;
use crate::runtime::{Action, Runtime};
use crate::trace::{Record, Status};
use crate::view::ComponentView;
use crate::why::Why;

/// The longest run, s of simulated time.
pub const MAX_UNTIL: f64 = 600.0;
pub const MAX_COMPONENTS: usize = 64;
const MAX_CONNECTIONS: usize = 512;
const MAX_SCRIPT: usize = 1000;
/// The robot's simulation step, s.
const ROBOT_DT: f64 = 0.05;

#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ComponentFile {
    pub name: String,
    pub kind: String,
    /// Seconds spent initialising before it runs.
    #[serde(default)]
    pub init: f64,
    #[serde(default)]
    pub params: serde_json::Value,
}

#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ConnectionFile {
    pub port: String,
    pub service: String,
    /// This connection's latency (the system's when left out).
    #[serde(default)]
    pub latency: Option<Latency>,
}

/// A change at a set time, made by the deployer.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
pub struct ScriptItem {
    pub at: f64,
    #[serde(flatten)]
    pub action: Action,
}

/// A system file.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a system file (an object with `components`)"
)]
pub struct System {
    #[serde(default)]
    pub name: String,
    #[serde(default)]
    pub seed: u64,
    /// How long to run, s (the command line's `--until` overrides it).
    #[serde(default = "ten")]
    pub until: f64,
    /// Every connection's latency unless it names its own.
    #[serde(default)]
    pub latency: Latency,
    /// A catalogue world's id or a world object: the robot's world.
    #[serde(default)]
    pub world: Option<serde_json::Value>,
    pub components: Vec<ComponentFile>,
    #[serde(default)]
    pub connections: Vec<ConnectionFile>,
    #[serde(default)]
    pub script: Vec<ScriptItem>,
}

fn ten() -> f64 {
    10.0
}

/// What a run gives back.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Report {
    pub name: String,
    pub seed: u64,
    pub until: f64,
    pub trace: Vec<Record>,
    /// Trace lines left out past the cap (the run itself went on).
    pub dropped_records: u64,
    pub components: Vec<ComponentView>,
    pub counts: Counts,
    /// Every port that got nothing, and why.
    pub quiet_ports: Vec<QuietPort>,
    /// The robot's final pose [x, y, θ] when there is a world.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub robot: Option<[f64; 3]>,
    /// `false` when the runaway guard stopped the run early.
    pub complete: bool,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub struct Counts {
    pub messages: u64,
    pub delivered: u64,
    pub lost: u64,
    pub skipped: u64,
    pub cancelled: u64,
    pub refused: u64,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct QuietPort {
    pub port: String,
    #[serde(flatten)]
    pub why: Why,
}

impl System {
    pub fn from_json(text: &str) -> Result<Self, FieldError> {
        let system: System = kinolab_common::error::from_json(text)?;
        system.check()?;
        Ok(system)
    }

    pub fn check(&self) -> Result<(), FieldError> {
        kinolab_common::error::in_range("until", self.until, 0.0, MAX_UNTIL)?;
        self.latency.check().map_err(|e| e.within("latency"))?;
        if self.components.is_empty() || self.components.len() > MAX_COMPONENTS {
            return Err(FieldError::new(
                "components",
                format!(
                    "needs 1 to {MAX_COMPONENTS} components, got {}",
                    self.components.len()
                ),
            ));
        }
        if self.connections.len() > MAX_CONNECTIONS {
            return Err(FieldError::new(
                "connections",
                format!("at most {MAX_CONNECTIONS}"),
            ));
        }
        if self.script.len() > MAX_SCRIPT {
            return Err(FieldError::new(
                "script",
                format!("at most {MAX_SCRIPT} items"),
            ));
        }
        for (i, c) in self.connections.iter().enumerate() {
            if let Some(l) = &c.latency {
                l.check()
                    .map_err(|e| e.within(&format!("connections[{i}].latency")))?;
            }
        }
        for (i, s) in self.script.iter().enumerate() {
            kinolab_common::error::in_range(format!("script[{i}].at"), s.at, 0.0, MAX_UNTIL)?;
        }
        Ok(())
    }

    /// The world the file names, if any.
    fn world(&self) -> Result<Option<World>, FieldError> {
        let Some(value) = &self.world else {
            return Ok(None);
        };
        let world = match value {
            serde_json::Value::String(id) => kinolab_world::catalogue::world(id),
            other => World::from_value(other.clone()),
        };
        world.map(Some).map_err(|e| e.within("world"))
    }

    /// Build the runtime: components, the world, the initial wiring (a
    /// refused connection is an error naming it) and the script.
    pub fn build(&self) -> Result<Runtime, FieldError> {
        self.check()?;
        let mut rt = Runtime::new(self.seed, self.latency)?;
        if let Some(world) = self.world()? {
            let sensors = Sensors::rays(16, 360.0, 3.0);
            rt.world = Some(
                Sim::new(world, Body::default(), sensors, ROBOT_DT, self.seed)
                    .map_err(|e| e.within("world"))?,
            );
        }
        for (i, c) in self.components.iter().enumerate() {
            let component = crate::kinds::build(&c.kind, &c.params)
                .map_err(|e| e.within(&format!("components[{i}]")))?;
            rt.add(&c.name, component, c.init)?;
        }
        for (i, c) in self.connections.iter().enumerate() {
            rt.connect(&c.port, &c.service, "deployer", None)
                .map_err(|r| FieldError::new(format!("connections[{i}]"), r.message))?;
            if let Some(l) = c.latency {
                rt.set_latency(&c.port, l)
                    .map_err(|r| FieldError::new(format!("connections[{i}]"), r.message))?;
            }
        }
        for s in &self.script {
            rt.schedule(s.at, s.action.clone());
        }
        Ok(rt)
    }

    /// Build and run until `until` (the file's when `None`).
    pub fn run(&self, until: Option<f64>) -> Result<Report, FieldError> {
        let until = match until {
            Some(t) => kinolab_common::error::in_range("until", t, 0.0, MAX_UNTIL)?,
            None => self.until,
        };
        let mut rt = self.build()?;
        let complete = rt.run_until(until);
        Ok(rt.report(&self.name, until, complete))
    }
}

impl Runtime {
    /// The trace and the final state, as a report.
    pub fn report(&self, name: &str, until: f64, complete: bool) -> Report {
        let mut counts = Counts::default();
        for r in self.trace() {
            match r.status {
                Status::Refused => counts.refused += 1,
                _ if matches!(r.pattern, "wiring" | "state" | "note") => continue,
                Status::Delivered => counts.delivered += 1,
                Status::Lost => counts.lost += 1,
                Status::Skipped => counts.skipped += 1,
                Status::Cancelled => counts.cancelled += 1,
                _ => {}
            }
            if !matches!(r.pattern, "wiring" | "state" | "note") {
                counts.messages += 1;
            }
        }
        let components = self.view();
        let quiet_ports = components
            .iter()
            .flat_map(|c| {
                c.ports
                    .iter()
                    .map(move |p| format!("{}.{}", c.name, p.name))
            })
            .filter_map(|port| {
                let why = self.why_nothing(&port);
                (!matches!(why.reason, "received" | "one-way")).then_some(QuietPort { port, why })
            })
            .collect();
        Report {
            name: name.to_owned(),
            seed: self.seed(),
            until,
            trace: self.trace().to_vec(),
            dropped_records: self.dropped_records,
            components,
            counts,
            quiet_ports,
            robot: self
                .world
                .as_ref()
                .map(|s| [s.pose.x, s.pose.y, s.pose.theta]),
            complete,
        }
    }
}

/// The example systems shipped with the lab: (id, file).
pub const EXAMPLES: [(&str, &str); 4] = [
    (
        "out-of-order",
        include_str!("../systems/out-of-order.system.json"),
    ),
    (
        "newest-vs-timed",
        include_str!("../systems/newest-vs-timed.system.json"),
    ),
    ("events", include_str!("../systems/events.system.json")),
    ("robot", include_str!("../systems/robot.system.json")),
];

/// The example system `id`.
pub fn example(id: &str) -> Result<System, FieldError> {
    let (_, text) = EXAMPLES
        .iter()
        .find(|(name, _)| *name == id)
        .ok_or_else(|| FieldError::new("system", format!("no example system `{id}`")))?;
    System::from_json(text)
}
