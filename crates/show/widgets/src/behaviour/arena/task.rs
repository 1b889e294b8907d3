//! The layer exercise: order three layers and place one node so the robot
//! reaches the goal without touching anything on three seeded worlds. The
//! behaviours crate grades it by running all three.

use egui::{RichText, Slider};
use kinolab_behaviours::coordinate::Coordinator;
use kinolab_behaviours::coordinate::subsumption::{Node, NodeKind, Subsumption};
use kinolab_behaviours::exercise::{
    LayerTask, layers_from_text, layers_text, node_from_text, node_text,
};
use kinolab_common::Feedback;
use serde::Deserialize;

use super::{Arena, NAME, Settings};
use crate::widget::{feedback_ui, range};

/// The learner's node.
#[derive(Debug, Clone, PartialEq, Deserialize)]
pub(super) struct NodeChoice {
    suppress: bool,
    by: String,
    on: String,
    hold: f64,
}

/// The learner's layers (level 0 first), node, and which world is shown
/// (0 to 2).
#[derive(Debug, Clone, PartialEq, Deserialize)]
pub(super) struct LayerDesign {
    order: Vec<String>,
    node: Option<NodeChoice>,
    world: usize,
}

/// The layer design of the first links' format.
pub(super) type LegacyLayers = LayerDesign;

/// Where the exercise starts: the layers in an unhelpful order.
const START: [&str; 3] = ["avoid", "wander", "go"];

impl LayerDesign {
    /// The design `settings` hold (the exercise's start where they are
    /// silent).
    pub fn read(settings: &Settings) -> Result<Self, String> {
        let order = match &settings.layers {
            Some(text) => layers_from_text(text)?,
            None => START.iter().map(|l| (*l).to_owned()).collect(),
        };
        let node = match &settings.node {
            Some(text) => {
                let n = node_from_text(text, settings.hold)?;
                Some(NodeChoice {
                    suppress: n.node == NodeKind::Suppress,
                    by: n.by,
                    on: n.on,
                    hold: n.hold,
                })
            }
            None => None,
        };
        Ok(Self {
            order,
            node,
            world: settings.task_world.saturating_sub(1),
        })
    }

    /// Put this design into `settings`.
    pub fn write(&self, settings: &mut Settings) {
        settings.layers = Some(layers_text(&self.order));
        settings.node = self.node().as_ref().map(node_text);
        if let Some(n) = &self.node {
            settings.hold = n.hold;
        }
        settings.task_world = self.world + 1;
    }

    /// The old format's design as it was written.
    pub fn design(self) -> Self {
        self
    }

    pub fn world_seed(&self) -> u64 {
        LayerTask::default().seeds[self.world.min(2)]
    }

    fn node(&self) -> Option<Node> {
        self.node.as_ref().map(|n| Node {
            node: if n.suppress {
                NodeKind::Suppress
            } else {
                NodeKind::Inhibit
            },
            by: n.by.clone(),
            on: n.on.clone(),
            hold: n.hold,
        })
    }

    pub fn coordinator(&self) -> Coordinator {
        Coordinator::Subsumption(Subsumption {
            layers: self.order.clone(),
            nodes: self.node().into_iter().collect(),
        })
    }
}

/// What the task box remembers.
pub(super) struct TaskUi {
    feedback: Option<Feedback>,
}

impl TaskUi {
    pub fn new() -> Self {
        Self { feedback: None }
    }
}

impl Arena {
    pub(super) fn task_ui(&mut self, ui: &mut egui::Ui) {
        let Ok(Some(mut design)) = self.settings.layer_design() else {
            return;
        };
        let before = design.clone();
        let hold = self.settings.hold;
        let Some(task) = self.task.as_mut() else {
            return;
        };
        egui::Frame::group(ui.style()).show(ui, |ui| {
            ui.label(RichText::new(
                "Exercise: order the layers and place one node so the robot reaches the goal without touching anything, on all three worlds.",
            ).strong());
            ui.label("Layers, the highest first (level 0 is at the bottom and drives the motors):");
            let n = design.order.len();
            for shown in 0..n {
                let level = n - 1 - shown;
                ui.horizontal(|ui| {
                    ui.label(format!("level {level}: {}", design.order[level]));
                    if level + 1 < n && ui.small_button("up").clicked() {
                        design.order.swap(level, level + 1);
                    }
                    if level > 0 && ui.small_button("down").clicked() {
                        design.order.swap(level, level - 1);
                    }
                });
            }
            let mut placed = design.node.is_some();
            ui.checkbox(&mut placed, "place a node");
            if placed && design.node.is_none() {
                design.node = Some(NodeChoice { suppress: true, by: design.order[n - 1].clone(), on: design.order[0].clone(), hold });
            } else if !placed {
                design.node = None;
            }
            if let Some(node) = &mut design.node {
                node_ui(ui, node, &design.order);
            }
            ui.horizontal(|ui| {
                for w in 0..3 {
                    crate::widget::choose(ui, &mut design.world, w, format!("world {}", w + 1));
                }
            });
            if ui.button("Check on all three worlds").clicked() {
                let node = design.node();
                task.feedback = Some(Feedback::from(LayerTask::default().check(&design.order, node.as_ref())));
            }
            feedback_ui(ui, task.feedback.as_ref());
        });
        if design != before {
            if let Some(t) = &mut self.task {
                t.feedback = None;
            }
            // A design that cannot run says why (the exercise stays).
            design.write(&mut self.settings);
            self.rebuild();
            self.play();
        }
    }
}

fn node_ui(ui: &mut egui::Ui, node: &mut NodeChoice, layers: &[String]) {
    ui.horizontal_wrapped(|ui| {
        ui.radio_value(&mut node.suppress, true, "suppress");
        ui.radio_value(&mut node.suppress, false, "inhibit");
    });
    ui.horizontal_wrapped(|ui| {
        ui.label("driven");
        for l in layers {
            ui.radio_value(&mut node.by, l.clone(), format!("by {l}"));
        }
    });
    ui.horizontal_wrapped(|ui| {
        ui.label("sitting on the wire");
        for l in layers {
            ui.radio_value(&mut node.on, l.clone(), format!("of {l}"));
        }
    });
    ui.add(Slider::new(&mut node.hold, range(NAME, "hold")).text("hold (s)"));
}
