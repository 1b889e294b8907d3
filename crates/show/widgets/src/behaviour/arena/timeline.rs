//! The player's buttons with what the run has done so far, its timeline
//! coloured by who had control with the bumps marked, what the run shows
//! as `kinolab run` prints it, and the exports.

use egui::{RichText, Stroke, pos2};
use kinolab_behaviours::run::{Sample, Setup};
use kinolab_common::display::fixed;
use kinolab_common::trajectory::Sample as Motion;

use super::canvas::in_control_color;
use super::{Arena, DURATION, Run};
use crate::export::{self, Export};
use crate::player::Player;

impl Arena {
    pub(super) fn controls(&mut self, ui: &mut egui::Ui) {
        let Some(player) = &mut self.player else {
            return;
        };
        player.controls(ui);
        let shown = player.ticks_shown();
        let bumps = shown.iter().filter(|r| r.bump()).count();
        let goal = shown
            .iter()
            .position(|r| r.goal())
            .map(|k| player.time_at(k + 1));
        ui.horizontal_wrapped(|ui| {
            if let Some(t) = goal {
                ui.label(
                    RichText::new(format!("goal reached at {} s", fixed(t, 1)))
                        .color(crate::theme::good_color(ui)),
                );
            }
            if bumps > 0 {
                ui.label(
                    RichText::new(format!("{bumps} bump{}", if bumps == 1 { "" } else { "s" }))
                        .color(crate::theme::error_color(ui)),
                );
            }
        });
    }

    /// The player's scrub bar, coloured by the behaviour in control at
    /// each step (faint past the instant shown), bumps as red ticks.
    pub(super) fn timeline(&mut self, ui: &mut egui::Ui) {
        let dt = self.setup.as_ref().map_or(0.05, |s| s.dt);
        let steps = (DURATION / dt).round().max(1.0) as usize;
        let red = crate::theme::error_color(ui);
        let colors = self.colors();
        let Some(player) = &mut self.player else {
            return;
        };
        let cursor = player.cursor();
        player.timeline(
            ui,
            "Timeline: who had control",
            steps,
            &mut |painter, rect, x, ticks| {
                for (k, r) in ticks.iter().enumerate() {
                    let cell = egui::Rect::from_min_max(
                        pos2(x(k), rect.top()),
                        pos2(x(k + 1) + 0.5, rect.bottom()),
                    );
                    let faint = if k < cursor { 0.9 } else { 0.35 };
                    painter.rect_filled(
                        cell,
                        0.0,
                        in_control_color(&colors, r.in_control).gamma_multiply(faint),
                    );
                    if r.bump() {
                        painter.line_segment(
                            [pos2(x(k), rect.top()), pos2(x(k), rect.bottom())],
                            Stroke::new(2.0, red),
                        );
                    }
                }
            },
        );
        player.run(ui, 8);
        ui.label(RichText::new("Timeline: the colour of the behaviour in control at each moment; red ticks are bumps. Click or drag on it to go back and forth.").small());
    }

    pub(super) fn exports(&mut self, ui: &mut egui::Ui, view: egui::Rect) {
        let file = || {
            self.setup
                .as_ref()
                .map(Setup::to_json)
                .ok_or_else(|| "this set-up cannot run".to_owned())
        };
        export::bar(
            ui,
            ui.scope_id().with("arena-exports"),
            &[
                Export::Png {
                    file: "kinolab-behaviour-arena.png",
                    rect: view,
                },
                Export::Run {
                    file: "arena.run.json",
                    command: "kinolab run arena.run.json",
                    make: &file,
                },
            ],
        );
    }
}

/// What the run has done up to the instant shown, as `kinolab run` prints
/// it: the samples (every step, from the start) and the events.
pub(super) fn shows(
    setup: &Setup,
    player: &Player<Run>,
) -> Option<Vec<(String, serde_json::Value)>> {
    let start = setup.world.start;
    let name = |i: usize| setup.behaviours.get(i).map(|b| b.name.clone());
    let mut samples = vec![Sample {
        motion: Motion::new(0.0, [start.x, start.y, start.theta], 0.0, 0.0),
        control: None,
    }];
    let mut events = Vec::new();
    for (k, r) in player.ticks_shown().iter().enumerate() {
        samples.push(Sample {
            motion: Motion::new(
                player.time_at(k + 1),
                [r.pose.x, r.pose.y, r.pose.theta],
                r.v,
                r.omega,
            ),
            control: r.in_control.and_then(name),
        });
        events.extend(r.events.iter().cloned());
    }
    use kinolab_common::display::tidy_report;
    Some(vec![
        ("/samples".into(), tidy_report(&samples).ok()?),
        ("/events".into(), tidy_report(&events).ok()?),
    ])
}
