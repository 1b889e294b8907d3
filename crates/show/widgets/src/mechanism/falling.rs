//! Let it fall: an arm (a double pendulum by default) let go under
//! gravity, its forward dynamics integrated by Runge–Kutta and played by
//! the lab's player, its energy plotted. Without damping the energy should
//! stay put: what it does instead is the integrator's error, and the panel
//! says how far it strays in 10 s at the chosen step and at half of it.

use std::rc::Rc;

use egui::{RichText, Sense, Stroke, vec2};
use egui_plot::{Plot, PlotPoints};
use kinolab_common::display::fixed;
use kinolab_mechanism::dynamics::EARTH;
use kinolab_mechanism::dynamics::motion::{Falling, Release};
use kinolab_mechanism::{Model, Plane};
use serde::{Deserialize, Serialize};

use crate::draw::PlaneView;
use crate::draw::plot::{REFERENCE, series_legend, series_lines};
use crate::link::{self, Moment};
use crate::player::{Player, Simulation};
use crate::theme;
use crate::widget::{LabWidget, Params};

/// The widget's name in the schema.
const NAME: &str = "arm-fall";
/// Seconds each run lasts.
const DURATION: f64 = 10.0;
/// Steps the player runs on in one frame, at most.
const MOST_PER_FRAME: usize = 200;

/// What the lesson sets and a link carries.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    model: String,
    /// Where the joints start, degrees.
    q: Option<Vec<f64>>,
    /// Viscous damping at every joint, N·m·s/rad.
    damping: f64,
    /// The integration step, ms.
    step: f64,
}

/// The arm falling, as the player steps it.
#[derive(Clone)]
struct Fall {
    model: Rc<Model>,
    falling: Falling,
    dt: f64,
}

/// One step: the time, the joints and the energy.
#[derive(Debug, Clone)]
struct Instant {
    t: f64,
    q: Vec<f64>,
    energy: f64,
}

impl Simulation for Fall {
    type Tick = Instant;
    type Event = ();

    fn step(&mut self) -> Option<Instant> {
        if !self.falling.step(&self.model).ok()? {
            return None;
        }
        let now = &self.falling.now;
        Some(Instant {
            t: now.t,
            q: now.q.clone(),
            energy: now.energy,
        })
    }

    fn time(&self) -> f64 {
        self.falling.now.t
    }

    fn dt(&self) -> f64 {
        self.dt
    }

    fn spring(&mut self, _: &()) {}
}

struct LetItFall {
    settings: Settings,
    initial: Settings,
    model: Rc<Model>,
    player: Option<Player<Fall>>,
    /// The settings the player and the drifts were made for.
    made_for: Option<Settings>,
    /// How far the energy strays in a whole undamped run at the step and
    /// at half it, measured a few hundred steps a frame.
    drifts: Option<Drifts>,
}

/// Steps of the drift runs taken in one frame: the first frame, and a
/// slider dragged, stay quick; the answer comes a few frames later.
const DRIFT_STEPS_PER_FRAME: usize = 400;

/// Two undamped runs from the same start, at a step and at half it, each
/// with the worst energy drift seen so far.
struct Drifts {
    runs: Vec<(Falling, f64, bool)>,
}

impl Drifts {
    /// Step the runs on by at most `budget` steps in all; the two worst
    /// drifts once both runs have ended.
    fn advance(&mut self, model: &Model, mut budget: usize) -> Option<(f64, f64)> {
        for (run, worst, ended) in &mut self.runs {
            while !*ended && budget > 0 {
                budget -= 1;
                match run.step(model) {
                    Ok(true) => *worst = worst.max(run.drift()),
                    _ => *ended = true,
                }
            }
        }
        match self.runs.as_slice() {
            [(_, at, true), (_, half, true)] => Some((*at, *half)),
            _ => None,
        }
    }
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    Ok(Box::new(LetItFall::new(p.settings()?)?))
}

/// Where an arm starts when the link names no pose: all joints at zero,
/// unless that pose hangs at rest (a pendulum), then the first joint a
/// quarter turn out, so that there is something to fall.
fn level_start(model: &Model) -> Vec<f64> {
    let mut q = vec![0.0; model.dof()];
    let resting = model
        .gravity(&q, EARTH)
        .is_ok_and(|g| g.iter().all(|t| t.abs() < 1e-9));
    if let (true, Some(first)) = (resting, q.first_mut()) {
        *first = 90.0;
    }
    q
}

impl LetItFall {
    fn new(mut settings: Settings) -> Result<Self, String> {
        let model =
            kinolab_mechanism::catalogue::mechanism(&settings.model).map_err(|e| e.to_string())?;
        let q = settings.q.get_or_insert_with(|| level_start(&model));
        q.resize(model.dof(), 0.0);
        Ok(LetItFall {
            initial: settings.clone(),
            settings,
            model: Rc::new(model),
            player: None,
            made_for: None,
            drifts: None,
        })
    }

    fn start(&self) -> Vec<f64> {
        self.settings
            .q
            .iter()
            .flatten()
            .map(|d| d.to_radians())
            .collect()
    }

    fn release(&self, dt: f64, damping: f64) -> Release {
        Release {
            dt,
            steps: (DURATION / dt).round() as usize,
            damping,
            gravity: EARTH,
        }
    }

    /// The run again, from the start, when the settings changed.
    fn refresh(&mut self) {
        if self.made_for.as_ref() == Some(&self.settings) {
            return;
        }
        self.made_for = Some(self.settings.clone());
        let dt = self.settings.step / 1000.0;
        let q = self.start();
        let qd = vec![0.0; q.len()];
        self.player = self
            .model
            .release(&q, &qd, self.release(dt, self.settings.damping))
            .ok()
            .map(|falling| {
                // Waits for Play, like every player: the page rests until asked.
                Player::new(Fall {
                    model: self.model.clone(),
                    falling,
                    dt,
                })
            });
        // How far a whole undamped run strays, at this step and half it.
        let runs: Option<Vec<_>> = [dt, dt / 2.0]
            .into_iter()
            .map(|dt| {
                let run = self.model.release(&q, &qd, self.release(dt, 0.0)).ok()?;
                Some((run, 0.0, false))
            })
            .collect();
        self.drifts = runs.map(|runs| Drifts { runs });
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        let mut q = self.settings.q.clone().unwrap_or_default();
        crate::widget::control_row(ui, |ui| {
            for (i, v) in q.iter_mut().enumerate() {
                ui.add(
                    egui::Slider::new(v, -180.0..=180.0)
                        .suffix("°")
                        .text(format!("joint {} starts at", i + 1)),
                );
            }
        });
        self.settings.q = Some(q);
        crate::widget::control_row(ui, |ui| {
            ui.add(
                egui::Slider::new(
                    &mut self.settings.damping,
                    crate::widget::range(NAME, "damping"),
                )
                .suffix(" N·m·s/rad")
                .text("damping"),
            );
            ui.add(
                egui::Slider::new(&mut self.settings.step, crate::widget::range(NAME, "step"))
                    .logarithmic(true)
                    .suffix(" ms")
                    .text("step"),
            );
        });
    }

    fn scene(&self, ui: &mut egui::Ui, q: &[f64], width: f32) {
        let reach = 1.2;
        let (rect, _) = ui.allocate_exact_size(
            vec2(width, (width * 0.7).clamp(200.0, 360.0)),
            Sense::hover(),
        );
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 4.0, ui.visuals().extreme_bg_color);
        let view = PlaneView::fit(rect.shrink(10.0), [-reach, -reach], [reach, reach]);
        let Ok(pts) = self
            .model
            .frame("tool")
            .and_then(|tool| self.model.chain_in_plane(q, &tool, Plane::Side))
        else {
            return;
        };
        let ink = ui.visuals().text_color();
        for w in pts.windows(2) {
            painter.line_segment(
                [view.to_screen(w[0]), view.to_screen(w[1])],
                Stroke::new(7.0, theme::accent(ui)),
            );
        }
        for p in &pts {
            painter.circle_filled(view.to_screen(*p), 5.0, ink);
        }
    }

    fn energy_plot(&self, ui: &mut egui::Ui, player: &Player<Fall>) {
        let points: Vec<[f64; 2]> = player
            .ticks_shown()
            .iter()
            .map(|k| [k.t, k.energy])
            .collect();
        let now = player.time();
        Plot::new(ui.scope_id().with("energy"))
            .height(150.0)
            .x_axis_label("t (s)")
            .y_axis_label("energy (J)")
            .allow_scroll(false)
            .show(ui, |plot| {
                series_lines(plot, vec![("energy", PlotPoints::from(points))], Some(now));
            });
        series_legend(ui, &["energy"], &[("now", REFERENCE)]);
    }

    fn readout(&self, player: &Player<Fall>) -> String {
        let start = player.peek().falling.start_energy;
        let now = player.ticks_shown().last().map_or(start, |k| k.energy);
        let measured = self.drifts.as_ref().map(|d| match d.runs.as_slice() {
            [(_, at, true), (_, half, true)] => Some((*at, *half)),
            _ => None,
        });
        let drift = match measured {
            Some(Some((at, half))) => format!(
                " Undamped, over {} s the energy strays {} % with a {} ms step and {} % with {} ms.",
                fixed(DURATION, 0),
                fixed(at * 100.0, 4),
                fixed(self.settings.step, 1),
                fixed(half * 100.0, 4),
                fixed(self.settings.step / 2.0, 1)
            ),
            Some(None) => " Measuring how far the energy strays at two steps…".to_owned(),
            None => String::new(),
        };
        format!(
            "At t = {} s the energy is {} J; it started at {} J.{drift}",
            fixed(player.time(), 2),
            fixed(now, 3),
            fixed(start, 3)
        )
    }
}

impl LabWidget for LetItFall {
    fn describe(&self) -> Option<String> {
        self.player.as_ref().map(|p| self.readout(p))
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        self.refresh();
        let Some(mut player) = self.player.take() else {
            crate::widget::error_box(ui, "The arm cannot fall", "these settings give no run");
            return;
        };
        player.run(ui, MOST_PER_FRAME);
        if let Some(drifts) = &mut self.drifts
            && drifts.advance(&self.model, DRIFT_STEPS_PER_FRAME).is_none()
        {
            ui.ctx().request_repaint();
        }
        player.controls(ui);
        let q = player.peek().falling.now.q.clone();
        let shown = player.ticks_shown().last().map_or(q, |k| k.q.clone());
        crate::widget::panels(ui, 2, |ui, i, width| {
            if i == 0 {
                self.scene(ui, &shown, width);
            } else {
                self.energy_plot(ui, &player);
            }
        });
        let expected = (DURATION / (self.settings.step / 1000.0)).round() as usize;
        player.timeline(ui, "The fall, step by step", expected, &mut |_, _, _, _| {});
        crate::widget::status_text(ui, RichText::new(self.readout(&player)), 3);
        self.player = Some(player);
    }

    fn state(&self) -> Option<String> {
        let moment = self.player.as_ref().map(Player::moment).unwrap_or_default();
        link::write(NAME, &self.settings, &self.initial, &moment)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let (settings, moment): (Settings, Moment<()>) = link::read(NAME, state)?;
        let initial = self.initial.clone();
        *self = LetItFall::new(settings)?;
        self.initial = initial;
        self.refresh();
        if let Some(p) = &mut self.player {
            p.replay(&moment.events, moment.instant);
        }
        Ok(())
    }

    fn seek(&mut self, t: f64) {
        self.refresh();
        if let Some(p) = &mut self.player {
            p.seek_time(t);
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn a_smaller_step_strays_less_and_damping_drains_the_energy() {
        let mut w = LetItFall::new(Settings {
            model: "double-pendulum".into(),
            q: Some(vec![90.0, 0.0]),
            damping: 0.0,
            step: 10.0,
        })
        .unwrap();
        w.refresh();
        let drifts = w.drifts.as_mut().unwrap();
        // A 10 ms step: 1 000 and 2 000 steps, a few frames' budget.
        assert!(drifts.advance(&w.model, DRIFT_STEPS_PER_FRAME).is_none());
        let (at, half) = drifts.advance(&w.model, 3000).unwrap();
        assert!(half < at / 4.0, "{half} vs {at}");
        w.seek(5.0);
        let p = w.player.as_ref().unwrap();
        assert!((p.time() - 5.0).abs() < 0.011);
        w.settings.damping = 1.0;
        w.refresh();
        w.seek(9.0);
        let p = w.player.as_mut().unwrap();
        let start = p.peek().falling.start_energy;
        assert!(p.ticks_shown().last().unwrap().energy < start - 1.0);
    }
}
