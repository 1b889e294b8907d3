//! Reactive skills: a small behaviour stack from the behaviours crate,
//! avoid over go-to-goal by subsumption. The reactive robot runs it on the
//! mission's goal; the hybrid robot's sequencer points it at waypoints.

use kinolab_behaviours::coordinate::subsumption::{Node, NodeKind};
use kinolab_behaviours::coordinate::{Coordinator, Memory, Responses, Subsumption, decide};
use kinolab_behaviours::{Behaviour, Drive, Named, Response};
use kinolab_world::sensors::Percepts;
use kinolab_world::{Body, Command};

/// A behaviour stack and what it remembers.
#[derive(Debug, Clone)]
pub struct Skills {
    pub behaviours: Vec<Named>,
    pub coordinator: Coordinator,
    memory: Memory,
    pub drive: Drive,
    /// Behaviour evaluations so far (each behaviour, each step).
    pub evaluations: usize,
}

/// What the stack did this step.
#[derive(Debug, Clone, PartialEq)]
pub struct SkillStep {
    pub command: Command,
    /// The behaviour whose response reached the wheels.
    pub in_control: Option<String>,
}

impl Skills {
    /// Avoid (something within 0.6 m ahead, or a bump) suppresses going to
    /// the goal for half a second after its last message.
    pub fn avoid_and_go(body: &Body) -> Self {
        let behaviours = vec![
            Named::new(
                "go",
                Behaviour::GoToGoal {
                    gain: 0.5,
                    slow_within: 0.5,
                },
            ),
            Named::new(
                "avoid",
                Behaviour::Avoid {
                    range: 0.6,
                    gain: 0.4,
                },
            ),
        ];
        let coordinator = Coordinator::Subsumption(Subsumption {
            layers: vec!["go".into(), "avoid".into()],
            nodes: vec![Node {
                node: NodeKind::Suppress,
                by: "avoid".into(),
                on: "go".into(),
                hold: 0.5,
            }],
        });
        Self {
            memory: Memory::new(&coordinator),
            behaviours,
            coordinator,
            drive: Drive {
                body: body.clone(),
                heading_gain: 3.0,
            },
            evaluations: 0,
        }
    }

    /// Every behaviour responds to `p`; the coordinator picks the command.
    pub fn act(&mut self, p: &Percepts, dt: f64) -> SkillStep {
        let responses: Vec<Option<Response>> =
            self.behaviours.iter_mut().map(|b| b.respond(p)).collect();
        self.evaluations += responses.len();
        let decision = decide(
            &self.coordinator,
            &mut self.memory,
            &Responses {
                behaviours: &self.behaviours,
                responses: &responses,
            },
            p,
            &self.drive,
            dt,
        );
        SkillStep {
            command: decision.command,
            in_control: decision
                .in_control
                .and_then(|i| self.behaviours.get(i))
                .map(|b| b.name.clone()),
        }
    }
}
