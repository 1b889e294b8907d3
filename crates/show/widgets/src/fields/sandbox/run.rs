//! The point robot's descent as the player plays it, a step at a time
//! (as if the robot moved at 1 m/s: a step of H metres takes H seconds),
//! and what the sandbox exports: a PNG of the field, a CSV of the path and
//! the field file `kinolab field --descend` follows.

use std::sync::Arc;

use kinolab_fields::descend::Descent;

use super::Sandbox;
use super::analysis::STEPS;
use crate::export::{self, Export};
use crate::player::Simulation;

/// The saved field file's name.
pub(super) const FILE: &str = "sandbox.field.json";

/// Seconds a step takes at 1 m/s.
const DT: f64 = STEPS.step;

/// A descent (computed whole by the core), played step by step.
#[derive(Debug, Clone)]
pub(super) struct Descending {
    pub descent: Arc<Descent>,
    /// Steps taken: the robot is at `descent.path[k]`.
    pub k: usize,
}

impl Descending {
    pub fn new(descent: Arc<Descent>) -> Self {
        Self { descent, k: 0 }
    }
}

impl Simulation for Descending {
    type Tick = ();
    type Event = ();

    fn step(&mut self) -> Option<()> {
        (self.k + 1 < self.descent.path.len()).then(|| self.k += 1)
    }

    fn time(&self) -> f64 {
        self.k as f64 * DT
    }

    fn dt(&self) -> f64 {
        DT
    }

    fn spring(&mut self, (): &()) {}
}

/// The command that follows the saved field from `start`, after `kinolab`.
pub(super) fn args(start: [f64; 2]) -> Vec<String> {
    vec![
        "field".into(),
        FILE.into(),
        "--descend".into(),
        format!("{},{}", start[0], start[1]),
        "--step".into(),
        STEPS.step.to_string(),
        "--max-steps".into(),
        STEPS.max_steps.to_string(),
    ]
}

impl Sandbox {
    /// The player's scrub bar over the descent.
    pub(super) fn timeline(&mut self, ui: &mut egui::Ui) {
        let steps = self.descent.as_ref().map_or(1, |d| d.steps());
        if let Some(player) = &mut self.player {
            player.timeline(
                ui,
                "The point robot's descent (1 m/s)",
                steps,
                &mut |_, _, _, _| {},
            );
            player.run(ui, 40);
        }
    }

    /// The path as a CSV: time (s at 1 m/s), x and y, a row per step.
    pub(super) fn path_csv(&self) -> String {
        let path = self.descent.as_ref().map_or(&[][..], |d| &d.path[..]);
        let along = |i: usize| -> Vec<[f64; 2]> {
            path.iter()
                .enumerate()
                .map(|(k, p)| [k as f64 * DT, p[i]])
                .collect()
        };
        export::series_csv("t (s)", &[("x (m)", along(0)), ("y (m)", along(1))])
    }

    pub(super) fn exports(&mut self, ui: &mut egui::Ui, view: egui::Rect) {
        let csv = || self.path_csv();
        let file = || {
            self.file
                .clone()
                .ok_or_else(|| "these fields do not make a field".to_owned())
        };
        let command = format!("kinolab {}", args(self.design.start).join(" "));
        export::bar(
            ui,
            ui.scope_id().with("sandbox-exports"),
            &[
                Export::Png {
                    file: "kinolab-field.png",
                    rect: view,
                },
                Export::Csv {
                    file: "kinolab-descent.csv",
                    make: &csv,
                },
                Export::Run {
                    file: FILE,
                    command: &command,
                    make: &file,
                },
            ],
        );
    }
}
