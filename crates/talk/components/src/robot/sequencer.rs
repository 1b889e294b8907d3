//! The sequencer is the wiring master: at a set time it sends the goal to
//! the planner, rewires the motion component's source from the joystick
//! to the planner, and activates the base's "arrived" event. When that
//! fires it hands motion back to the joystick, and its own event service
//! `done` tells whoever asked that the mission is over.

use serde::Deserialize;

use crate::FieldError;
use crate::component::{Component, Interface};
use crate::object::Object;
use crate::pattern::{Pattern, PortSpec, ServiceSpec, Signature};
use crate::runtime::{Ctx, Mode};

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SequencerParams {
    /// When to rewire and send the goal, s; `null`: never.
    #[serde(default = "two")]
    pub rewire_at: Option<f64>,
    /// The goal [x, y], m (the world's goal when left out).
    #[serde(default)]
    pub goal: Option<[f64; 2]>,
    /// Within this distance the goal is reached, m.
    #[serde(default = "quarter")]
    pub within: f64,
}

fn two() -> Option<f64> {
    Some(2.0)
}
fn quarter() -> f64 {
    0.25
}

#[derive(Debug, Clone)]
pub struct Sequencer {
    params: SequencerParams,
    goal: Option<[f64; 2]>,
    /// When the goal was reached.
    pub reached_at: Option<f64>,
    phase: &'static str,
}

impl Sequencer {
    pub fn new(params: SequencerParams) -> Result<Self, FieldError> {
        if let Some(t) = params.rewire_at {
            kinolab_common::error::in_range("params.rewire_at", t, 0.0, 3600.0)?;
        }
        if let Some([x, y]) = params.goal {
            kinolab_common::error::finite("params.goal[0]", x)?;
            kinolab_common::error::finite("params.goal[1]", y)?;
        }
        kinolab_common::error::in_range("params.within", params.within, 0.01, 10.0)?;
        Ok(Self {
            goal: params.goal,
            params,
            reached_at: None,
            phase: "joystick drives",
        })
    }

    fn rewire(&mut self, to: &str, cx: &mut Ctx<'_>) {
        if let Err(refusal) = cx.connect("motion.source", to) {
            cx.note(&format!("rewiring refused: {refusal}"));
        }
    }
}

impl Component for Sequencer {
    fn interface(&self) -> Interface {
        Interface {
            services: vec![ServiceSpec::new(
                "done",
                Pattern::Event,
                Signature::two("Mission", "Report"),
            )],
            ports: vec![
                PortSpec::new("goal", Pattern::Send, Signature::one("Goal"), true),
                PortSpec::new(
                    "arrived",
                    Pattern::Event,
                    Signature::two("Goal", "Pose"),
                    true,
                ),
            ],
            master: true,
        }
    }

    fn start(&mut self, cx: &mut Ctx<'_>) {
        if self.goal.is_none() {
            self.goal = cx.world().and_then(|s| s.world.goal).map(|g| [g.x, g.y]);
        }
        if let Some(t) = self.params.rewire_at {
            cx.after(t - cx.now(), 0);
        }
    }

    fn timer(&mut self, _tag: u32, cx: &mut Ctx<'_>) {
        let Some([x, y]) = self.goal else {
            cx.note("no goal to go to");
            return;
        };
        self.rewire("planner.route", cx);
        let goal = Object::new(
            "Goal",
            serde_json::json!({ "x": x, "y": y, "within": self.params.within }),
        );
        if let Err(s) = cx.send("goal", goal.clone()) {
            cx.note(&format!("goal not sent: {}", s.name()));
        }
        match cx.activate("arrived", goal, Mode::Once) {
            Ok(_) => self.phase = "planner drives",
            Err(s) => cx.note(&format!("could not watch for arrival: {}", s.name())),
        }
    }

    fn notified(&mut self, _port: &str, _id: u64, object: &Object, cx: &mut Ctx<'_>) {
        self.reached_at = Some(cx.now());
        self.phase = "goal reached";
        cx.note(&format!("goal reached: {}", object.summary()));
        self.rewire("joystick.route", cx);
        self.activated("done", cx);
    }

    fn activated(&mut self, _service: &str, cx: &mut Ctx<'_>) {
        let reached = self.reached_at;
        cx.test_events("done", &|_| {
            reached.map(|t| Object::new("Report", serde_json::json!({ "reached_at": t })))
        });
    }

    fn status(&self) -> String {
        self.phase.to_owned()
    }
}
