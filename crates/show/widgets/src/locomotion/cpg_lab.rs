//! The CPG lab: four coupled oscillators, one per leg, drawn as dots on
//! circles; edit the coupling weights, pick the gait whose phase offsets
//! they pull towards, kick the phases, and watch the lags converge while
//! the feet below step in the pattern the oscillators make. With the speed
//! switch on, a speed slider picks the gait through the Froude number and
//! sets the frequency, so the network changes gait on the move.

use egui::{RichText, Sense, Stroke, vec2};
use egui_plot::{Plot, PlotPoints};
use kinolab_common::Feedback;
use kinolab_common::display::fixed;
use kinolab_common::random::unit_hash;
use kinolab_locomotion::network::{Model, Network, State};
use kinolab_locomotion::speed::quadruped_pace;
use serde::{Deserialize, Serialize};

use crate::draw::canvas;
use crate::draw::plot::{series_legend, series_lines};
use crate::widget::{LabWidget, Params, feedback_ui};
use crate::{link, theme};

const LEGS: [&str; 4] = ["LF", "RF", "LH", "RH"];
use kinolab_locomotion::QUADRUPED_IDS as GAITS;
/// The walker the speed switch imagines: leg length and stride, m.
const LEG: f64 = 0.5;
const STRIDE: f64 = 0.5;
const SPEEDS: std::ops::RangeInclusive<f64> = 0.2..=5.0;
/// Integration step, s, and steps per frame at most.
const DT: f64 = 0.002;
/// Seconds of lag history kept for the plot.
const HISTORY: f64 = 12.0;

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Setup {
    gait: String,
    weights: [[f64; 4]; 4],
    frequency: f64,
    van_der_pol: bool,
    /// Some(v): the speed picks the gait and the frequency.
    #[serde(default)]
    speed: Option<f64>,
}

struct CpgLab {
    setup: Setup,
    initial: Setup,
    state: State,
    history: Vec<(f64, [f64; 4])>,
    kicks: u64,
    playing: bool,
    task: bool,
    feedback: Option<Feedback>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let w = p.number("weight").unwrap_or(1.0);
    let mut weights = [[w; 4]; 4];
    for (i, row) in weights.iter_mut().enumerate() {
        row[i] = 0.0;
    }
    let mut setup = Setup {
        gait: p.choice("gait").unwrap_or("quadruped-trot").to_owned(),
        weights,
        frequency: 1.0,
        van_der_pol: p.choice("model") == Some("van-der-pol"),
        speed: p.number("speed"),
    };
    follow_speed(&mut setup);
    let mut lab = CpgLab {
        initial: setup.clone(),
        setup,
        state: State {
            t: 0.0,
            theta: vec![0.0; 4],
            x: vec![0.0; 4],
            v: vec![0.0; 4],
        },
        history: Vec::new(),
        kicks: 0,
        playing: true,
        task: p.choice("task") == Some("lock-trot"),
        feedback: None,
    };
    lab.kick();
    Ok(Box::new(lab))
}

/// With the speed switch on, take the gait and frequency the speed asks for.
fn follow_speed(s: &mut Setup) {
    let Some(v) = s.speed else { return };
    if let Ok(pace) = quadruped_pace(v, LEG, STRIDE) {
        s.gait = pace.gait.name;
        s.frequency = pace.frequency;
    }
}

/// The network the set-up describes.
fn network(s: &Setup) -> Network {
    let gait =
        kinolab_locomotion::named(&s.gait).or_else(|| kinolab_locomotion::named("quadruped-trot"));
    let phases = gait.map_or_else(
        || vec![0.0; 4],
        |g| g.legs.iter().map(|l| l.phase).collect(),
    );
    Network {
        model: if s.van_der_pol {
            Model::VanDerPol
        } else {
            Model::Phase
        },
        frequency: s.frequency,
        phases,
        weights: s.weights.iter().map(|r| r.to_vec()).collect(),
        mu: 1.0,
    }
}

impl CpgLab {
    /// Scatter the phases (seeded: the n-th kick is the same everywhere).
    fn kick(&mut self) {
        self.kicks += 1;
        let theta: Vec<f64> = (0..4)
            .map(|i| std::f64::consts::TAU * unit_hash(self.kicks, i, 7))
            .collect();
        self.state = network(&self.setup).start(&theta);
        self.history.clear();
        self.feedback = None;
    }

    fn advance(&mut self, seconds: f64) {
        let net = network(&self.setup);
        if net.check().is_err() {
            return;
        }
        let steps = (seconds / DT).round().clamp(0.0, 200.0) as usize;
        for _ in 0..steps {
            net.step(&mut self.state, DT);
        }
        let lags = net.lags(&self.state);
        self.history
            .push((self.state.t, [lags[0], lags[1], lags[2], lags[3]]));
        let start = self.state.t - HISTORY;
        self.history.retain(|(t, _)| *t >= start);
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        let before = self.setup.clone();
        self.speed_controls(ui);
        ui.add_enabled_ui(self.setup.speed.is_none(), |ui| {
            ui.horizontal_wrapped(|ui| {
                ui.label("pull towards:");
                for g in GAITS {
                    ui.selectable_value(
                        &mut self.setup.gait,
                        g.to_owned(),
                        g.trim_start_matches("quadruped-"),
                    );
                }
            });
        });
        ui.horizontal_wrapped(|ui| {
            ui.selectable_value(&mut self.setup.van_der_pol, false, "phase oscillators");
            ui.selectable_value(&mut self.setup.van_der_pol, true, "Van der Pol");
            let label = if self.playing { "Pause" } else { "Play" };
            if ui.button(label).clicked() {
                self.playing = !self.playing;
            }
            if ui.button("Kick").clicked() {
                self.kick();
            }
        });
        ui.add_enabled(
            self.setup.speed.is_none(),
            egui::Slider::new(&mut self.setup.frequency, 0.2..=3.0).text("frequency ν (Hz)"),
        );
        ui.label("Coupling weights w (1/s): row i is pulled by column j");
        egui::Grid::new(ui.scope_id().with("weights")).show(ui, |ui| {
            ui.label("");
            for name in LEGS {
                ui.label(name);
            }
            ui.end_row();
            for (i, row) in self.setup.weights.iter_mut().enumerate() {
                ui.label(LEGS[i]);
                for (j, w) in row.iter_mut().enumerate() {
                    if i == j {
                        ui.label("–");
                    } else {
                        ui.add(
                            egui::DragValue::new(w)
                                .range(0.0..=5.0)
                                .speed(0.05)
                                .max_decimals(2),
                        );
                    }
                }
                ui.end_row();
            }
        });
        if self.setup.van_der_pol != before.van_der_pol {
            let theta = self.state.theta.clone();
            self.state = network(&self.setup).start(&theta);
        }
        if self.setup != before {
            self.feedback = None;
        }
    }

    /// The speed switch, the speed slider and what the speed implies.
    fn speed_controls(&mut self, ui: &mut egui::Ui) {
        let mut on = self.setup.speed.is_some();
        ui.checkbox(&mut on, "speed picks the gait (legs and stride 0.5 m)");
        if !on {
            self.setup.speed = None;
            return;
        }
        let mut v = self.setup.speed.unwrap_or(1.0);
        ui.add(egui::Slider::new(&mut v, SPEEDS).text("speed v (m/s)"));
        self.setup.speed = Some(v);
        follow_speed(&mut self.setup);
        if let Ok(pace) = quadruped_pace(v, LEG, STRIDE) {
            ui.label(format!(
                "Fr = v²/(g l) = {} → {}, ν = βv/L = {} Hz",
                fixed(pace.froude, 2),
                pace.gait.name.trim_start_matches("quadruped-"),
                fixed(pace.frequency, 2)
            ));
        }
    }

    /// The oscillators as dots on circles, and the feet below them.
    fn dials(&self, ui: &mut egui::Ui) {
        let width = ui.available_width();
        let (response, painter) = canvas(ui, vec2(width, 170.0), Sense::hover());
        let rect = response.rect;
        let ink = ui.visuals().text_color();
        let beta = kinolab_locomotion::named(&self.setup.gait).map_or(0.5, |g| g.duty_factor);
        let r = (width / 12.0).min(38.0);
        for (i, name) in LEGS.iter().enumerate() {
            let centre = rect.left_top() + vec2(width * (0.125 + 0.25 * i as f32), 60.0);
            painter.circle_stroke(centre, r, Stroke::new(1.5, ink.gamma_multiply(0.4)));
            let th = self.state.theta[i] as f32;
            let dot = centre + vec2(th.cos(), -th.sin()) * r;
            painter.circle_filled(dot, 6.0, theme::accent(ui));
            painter.line_segment(
                [centre, centre + vec2(r, 0.0)],
                Stroke::new(1.0, ink.gamma_multiply(0.3)),
            );
            painter.text(
                centre,
                egui::Align2::CENTER_CENTER,
                *name,
                egui::FontId::proportional(theme::TITLE_SIZE),
                ink,
            );
            let stance = Network::in_stance(&self.state, i, beta);
            let foot = centre + vec2(0.0, r + 34.0);
            let color = if stance {
                theme::good_color(ui)
            } else {
                ink.gamma_multiply(0.25)
            };
            painter.circle(foot, 9.0, color, Stroke::new(1.0, ink));
            painter.text(
                foot + vec2(0.0, 14.0),
                egui::Align2::CENTER_TOP,
                if stance { "stance" } else { "swing" },
                egui::FontId::proportional(theme::SMALL_SIZE),
                ink,
            );
        }
    }

    /// Each leg's lag error (its lag behind LF less the gait's), wrapped to
    /// half a cycle either way: every line goes to 0 as the network locks.
    fn plot(&self, ui: &mut egui::Ui) {
        let targets = network(&self.setup).target_lags();
        let wrap = |e: f64| e - e.round();
        Plot::new(ui.scope_id().with("lags"))
            .height(160.0)
            .x_axis_label("t (s)")
            .y_axis_label("lag error (cycles)")
            .include_y(-0.5)
            .include_y(0.5)
            .allow_scroll(false)
            .show(ui, |plot| {
                let lags = (1..LEGS.len()).map(|k| -> PlotPoints<'static> {
                    self.history
                        .iter()
                        .map(|(t, l)| [*t, wrap(l[k] - targets[k])])
                        .collect()
                });
                series_lines(plot, LEGS[1..].iter().copied().zip(lags).collect(), None);
            });
        series_legend(ui, &LEGS[1..], &[]);
    }
}

impl LabWidget for CpgLab {
    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        self.dials(ui);
        let net = network(&self.setup);
        ui.label(
            RichText::new(format!(
                "largest lag error: {} cycles",
                fixed(net.lag_error(&self.state), 3)
            ))
            .strong(),
        );
        self.plot(ui);
        if self.task {
            ui.separator();
            ui.label(RichText::new("Task: set the weights and the gait so the oscillators lock into a trot from any start, then check.").strong());
            if ui.button("Check").clicked() {
                self.feedback = Some(kinolab_locomotion::exercise::lock_trot(&net));
            }
            feedback_ui(ui, self.feedback.as_ref());
        }
        if self.playing {
            let dt = crate::widget::frame_dt(ui);
            self.advance(dt);
            crate::widget::animate(ui);
        }
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.setup, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(s) = link::decode::<Setup>(state)
            && GAITS.contains(&s.gait.as_str())
            && (0.2..=5.0).contains(&s.frequency)
            && s.speed.is_none_or(|v| SPEEDS.contains(&v))
            && s.weights.iter().flatten().all(|w| (0.0..=5.0).contains(w))
        {
            self.setup = s;
            self.kick();
        }
        Ok(())
    }
}
