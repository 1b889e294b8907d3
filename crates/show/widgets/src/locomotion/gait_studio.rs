//! The gait studio: a walker's feet through one cycle, seen from above,
//! with the support polygon and the stability margin at every instant, the
//! footfall diagram and the margin over the cycle beside it. Scrub or play
//! the cycle; change the duty factor, the stride, the centre of mass and
//! each leg's lift-off phase.

use egui::{Align2, Color32, FontId, Painter, Pos2, Rect, RichText, Sense, Stroke, vec2};
use kinolab_common::display::fixed;
use kinolab_locomotion::gait::{Instant, min_margin};
use kinolab_locomotion::{Gait, named, named_ids, static_stability};
use serde::{Deserialize, Serialize};

use super::{draw_foot, draw_support};
use crate::draw::labels::Labels;
use crate::draw::{PlaneView, canvas};
use crate::widget::{LabWidget, Params};
use crate::{link, theme};

/// Samples of the margin curve over one cycle.
const CURVE_SAMPLES: usize = 240;
/// Seconds one cycle takes when playing.
const CYCLE_SECONDS: f64 = 3.0;
/// A smallest margin below this, m, is called "only just" stable.
const EDGE: f64 = 0.002;
/// Below this width the panels stack.
const NARROW: f32 = 620.0;

/// What the learner changed, and what a link carries.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Setup {
    preset: String,
    duty_factor: f64,
    stride: f64,
    com: [f64; 2],
    phases: Vec<f64>,
    tau: f64,
}

struct GaitStudio {
    setup: Setup,
    initial: Setup,
    /// The graded task's duty factor, when the lesson sets one: find phases
    /// that keep the walker statically stable at this β.
    task: Option<f64>,
    feedback: Option<kinolab_common::Feedback>,
    playing: bool,
    /// The margin over the cycle, for `curve_key`.
    curve: Vec<Instant>,
    curve_key: Option<Setup>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let preset = p.choice("gait").unwrap_or("quadruped-crawl");
    let mut setup = Setup::of(preset).ok_or_else(|| format!("no gait called `{preset}`"))?;
    if let Some(beta) = p.number("duty_factor") {
        setup.duty_factor = beta;
    }
    let task = (p.choice("task") == Some("static-phases")).then_some(setup.duty_factor);
    if task.is_some() {
        // Every leg lifting at once: the learner starts from the worst.
        setup.phases.iter_mut().for_each(|p| *p = 0.0);
    }
    Ok(Box::new(GaitStudio {
        initial: setup.clone(),
        setup,
        task,
        feedback: None,
        playing: false,
        curve: Vec::new(),
        curve_key: None,
    }))
}

/// The gaits a lesson may start from.
pub fn presets() -> impl Iterator<Item = &'static str> {
    named_ids()
}

impl Setup {
    fn of(preset: &str) -> Option<Self> {
        let g = named(preset)?;
        Some(Self {
            preset: preset.to_owned(),
            duty_factor: g.duty_factor,
            stride: g.stride,
            com: g.com,
            phases: g.legs.iter().map(|l| l.phase).collect(),
            tau: 0.0,
        })
    }

    /// The gait this set-up describes: the preset's legs with these values.
    fn gait(&self) -> Option<Gait> {
        let mut g = named(&self.preset)?;
        g.duty_factor = self.duty_factor;
        g.stride = self.stride;
        g.com = self.com;
        for (leg, phase) in g.legs.iter_mut().zip(&self.phases) {
            leg.phase = *phase;
        }
        g.check().ok().map(|()| g)
    }

    /// Whether a set-up from a link fits its preset and the sliders' ranges.
    fn valid(&self) -> bool {
        let Some(g) = named(&self.preset) else {
            return false;
        };
        self.phases.len() == g.legs.len()
            && self.phases.iter().all(|p| (0.0..1.0).contains(p))
            && (0.05..=0.95).contains(&self.duty_factor)
            && (0.0..=0.4).contains(&self.stride)
            && self.com.iter().all(|c| (-0.2..=0.2).contains(c))
            && (0.0..1.0).contains(&self.tau)
    }
}

impl GaitStudio {
    fn controls(&mut self, ui: &mut egui::Ui, gait: &Gait) {
        crate::widget::control_row(ui, |ui| {
            let before = self.setup.preset.clone();
            egui::ComboBox::new(ui.scope_id().with("preset"), "gait")
                .selected_text(&self.setup.preset)
                .show_ui(ui, |ui| {
                    for id in presets() {
                        ui.selectable_value(&mut self.setup.preset, id.to_owned(), id);
                    }
                });
            if self.setup.preset != before
                && let Some(s) = Setup::of(&self.setup.preset)
            {
                self.setup = s;
            }
            let label = if self.playing { "Pause" } else { "Play" };
            if ui.button(label).clicked() {
                self.playing = !self.playing;
            }
            ui.add(egui::Slider::new(&mut self.setup.tau, 0.0..=0.999).text("τ (cycle)"));
        });
        crate::widget::control_row(ui, |ui| {
            ui.add(
                egui::Slider::new(&mut self.setup.duty_factor, 0.05..=0.95).text("β duty factor"),
            );
            ui.add(egui::Slider::new(&mut self.setup.stride, 0.0..=0.4).text("L stride (m)"));
        });
        crate::widget::control_row(ui, |ui| {
            ui.add(egui::Slider::new(&mut self.setup.com[0], -0.2..=0.2).text("CoM x (m)"));
            ui.add(egui::Slider::new(&mut self.setup.com[1], -0.2..=0.2).text("CoM y (m)"));
        });
        crate::widget::control_row(ui, |ui| {
            for (leg, phase) in gait.legs.iter().zip(self.setup.phases.iter_mut()) {
                ui.add(
                    egui::Slider::new(phase, 0.0..=0.999)
                        .text(format!("φ {}", leg.name))
                        .max_decimals(3),
                );
            }
        });
    }

    /// The margin over the cycle, recomputed only when the gait changes.
    fn curve(&mut self, gait: &Gait) -> &[Instant] {
        let key = Setup {
            tau: 0.0,
            ..self.setup.clone()
        };
        if self.curve_key.as_ref() != Some(&key) {
            self.curve = gait.sample(CURVE_SAMPLES);
            self.curve_key = Some(key);
        }
        &self.curve
    }
}

/// The walker from above at one instant.
fn top_view(ui: &egui::Ui, painter: &Painter, rect: Rect, gait: &Gait, now: &Instant) {
    let view = PlaneView::fit(rect.shrink(12.0), [-0.55, -0.4], [0.55, 0.4]);
    let ink = ui.visuals().text_color();
    let stability = static_stability(gait.com, &now.feet).ok();
    let color = match now.margin {
        Some(m) if m > 0.0 => theme::good_color(ui),
        _ => theme::error_color(ui),
    };
    let mut labels = Labels::default();
    if let Some(s) = &stability {
        draw_support(painter, &mut labels, &view, s, gait.com, color);
    }
    let body = Rect::from_center_size(
        view.to_screen([0.0, 0.0]),
        vec2(view.length(0.5), view.length(0.3)),
    );
    painter.rect_stroke(
        body,
        8.0,
        Stroke::new(1.0, ink.gamma_multiply(0.4)),
        egui::StrokeKind::Middle,
    );
    for (i, leg) in gait.legs.iter().enumerate() {
        let standing = now.stance.iter().position(|&k| k == i);
        let at = match standing {
            Some(k) => view.to_screen(now.feet[k]),
            None => view.to_screen([leg.x, leg.y]),
        };
        let out = vec2(leg.x as f32, -leg.y as f32);
        draw_foot(
            painter,
            &mut labels,
            at,
            standing.is_some(),
            out,
            &leg.name,
            ink,
        );
    }
    let com = view.to_screen(gait.com);
    painter.circle(
        com,
        7.0,
        theme::accent(ui),
        Stroke::new(1.5, Color32::WHITE),
    );
    labels.reserve(Rect::from_center_size(com, vec2(16.0, 16.0)));
    labels.draw(painter, &FontId::proportional(theme::LABEL_SIZE));
    painter.text(
        rect.right_top() + vec2(-8.0, 8.0),
        Align2::RIGHT_TOP,
        "from above, front to the right →",
        FontId::proportional(theme::SMALL_SIZE),
        ui.visuals().weak_text_color(),
    );
}

/// The footfall diagram (a bar per leg where it stands) over the margin
/// curve, both against τ, with a cursor at `tau`.
fn cycle_view(
    ui: &egui::Ui,
    painter: &Painter,
    rect: Rect,
    gait: &Gait,
    curve: &[Instant],
    tau: f64,
) {
    let ink = ui.visuals().text_color();
    let weak = ui.visuals().weak_text_color();
    let left = rect.left() + 34.0;
    let width = rect.right() - 8.0 - left;
    let x_of = |t: f64| left + width * t as f32;
    let rows = gait.legs.len() as f32;
    let row_h = ((rect.height() * 0.5) / rows).min(18.0);
    for (i, leg) in gait.legs.iter().enumerate() {
        let y = rect.top() + 8.0 + row_h * i as f32;
        painter.text(
            Pos2::new(rect.left() + 2.0, y + row_h / 2.0),
            Align2::LEFT_CENTER,
            &leg.name,
            FontId::proportional(theme::SMALL_SIZE),
            ink,
        );
        // Stance runs from σ = 1 − β to 1, i.e. τ from φ + 1 − β to φ + 1.
        let start = (leg.phase + 1.0 - gait.duty_factor).rem_euclid(1.0);
        let end = start + gait.duty_factor;
        for (a, b) in [(start, end.min(1.0)), (0.0, (end - 1.0).max(0.0))] {
            if b > a {
                let bar = Rect::from_min_max(
                    Pos2::new(x_of(a), y + 2.0),
                    Pos2::new(x_of(b), y + row_h - 2.0),
                );
                painter.rect_filled(bar, 2.0, ink.gamma_multiply(0.55));
            }
        }
    }
    let top = rect.top() + 16.0 + row_h * rows;
    let plot = Rect::from_min_max(
        Pos2::new(left, top),
        Pos2::new(left + width, rect.bottom() - 18.0),
    );
    let margins: Vec<f64> = curve.iter().filter_map(|s| s.margin).collect();
    let span = margins.iter().fold(0.02f64, |m, v| m.max(v.abs()));
    let y_of = |m: f64| plot.center().y - (m / span) as f32 * plot.height() / 2.0;
    painter.line_segment(
        [
            Pos2::new(plot.left(), y_of(0.0)),
            Pos2::new(plot.right(), y_of(0.0)),
        ],
        Stroke::new(1.0, weak),
    );
    let good = theme::good_color(ui);
    let bad = theme::error_color(ui);
    for pair in curve.windows(2) {
        if let (Some(a), Some(b)) = (pair[0].margin, pair[1].margin) {
            let color = if a.min(b) > 0.0 { good } else { bad };
            painter.line_segment(
                [
                    Pos2::new(x_of(pair[0].tau), y_of(a)),
                    Pos2::new(x_of(pair[1].tau), y_of(b)),
                ],
                Stroke::new(2.0, color),
            );
        }
    }
    let tick = |at: Pos2, align: Align2, text: &str| {
        painter.text(
            at,
            align,
            text,
            FontId::proportional(theme::TINY_SIZE),
            weak,
        );
    };
    tick(
        Pos2::new(rect.left() + 2.0, y_of(0.0)),
        Align2::LEFT_CENTER,
        "S = 0",
    );
    tick(
        Pos2::new(plot.left(), rect.bottom() - 2.0),
        Align2::LEFT_BOTTOM,
        "τ = 0",
    );
    tick(
        Pos2::new(plot.right(), rect.bottom() - 2.0),
        Align2::RIGHT_BOTTOM,
        "1",
    );
    painter.text(
        Pos2::new(plot.right() - 4.0, plot.bottom()),
        Align2::RIGHT_BOTTOM,
        format!("margin S, ±{} cm", fixed(span * 100.0, 1)),
        FontId::proportional(theme::SMALL_SIZE),
        weak,
    );
    let cursor = x_of(tau);
    painter.line_segment(
        [
            Pos2::new(cursor, rect.top() + 4.0),
            Pos2::new(cursor, rect.bottom() - 16.0),
        ],
        Stroke::new(1.5, theme::accent(ui)),
    );
}

/// The verdict over the whole cycle, in words.
fn verdict(gait: &Gait, curve: &[Instant]) -> (bool, String) {
    let below = curve
        .iter()
        .filter(|s| s.margin.is_none_or(|m| m <= 0.0))
        .count();
    match min_margin(curve) {
        Some(m) if m > 0.0 && m < EDGE => (
            false,
            format!(
                "Only just: the margin touches zero ({} cm at its smallest), so the slightest push tips the walker.",
                fixed(m * 100.0, 2)
            ),
        ),
        Some(m) if m > 0.0 => (
            true,
            format!(
                "Statically stable through the whole cycle: the smallest margin is {} cm.",
                fixed(m * 100.0, 1)
            ),
        ),
        _ => {
            let share = 100.0 * below as f64 / curve.len().max(1) as f64;
            let mut text = format!(
                "Not statically stable: the margin is zero or negative for {}% of the cycle.",
                fixed(share, 0)
            );
            if gait.legs.len() == 4 && gait.duty_factor < 0.75 {
                text.push_str(" With four legs and β below 3/4 no choice of phases can fix that.");
            }
            (false, text)
        }
    }
}

impl LabWidget for GaitStudio {
    fn ui(&mut self, ui: &mut egui::Ui) {
        let Some(gait) = self.setup.gait() else {
            self.setup = self.initial.clone();
            return;
        };
        self.controls(ui, &gait);
        let Some(gait) = self.setup.gait() else {
            return;
        };
        if self.playing {
            let dt = crate::widget::frame_dt(ui);
            self.setup.tau = (self.setup.tau + dt / CYCLE_SECONDS)
                .rem_euclid(1.0)
                .min(0.999);
            crate::widget::animate(ui);
        }
        let now = gait.at(self.setup.tau);
        let tau = self.setup.tau;
        let curve = self.curve(&gait).to_vec();
        let width = ui.available_width();
        let narrow = width < NARROW;
        let (w, h) = if narrow {
            (width, 560.0)
        } else {
            (width, 300.0)
        };
        let (response, painter) = canvas(ui, vec2(w, h), Sense::hover());
        let rect = response.rect;
        let (a, b) = if narrow {
            let (top, bottom) = rect.split_top_bottom_at_fraction(0.5);
            (top, bottom)
        } else {
            rect.split_left_right_at_fraction(0.5)
        };
        top_view(ui, &painter, a, &gait, &now);
        cycle_view(ui, &painter, b, &gait, &curve, tau);
        let margin = now.margin.map_or("no foot down".to_owned(), |m| {
            format!("margin {} cm", fixed(m * 100.0, 1))
        });
        // How far the polygon reaches ahead of and behind the CoM.
        let margin = match kinolab_locomotion::longitudinal_margins(gait.com, &now.feet) {
            Some((front, rear)) => format!(
                "{margin}; the polygon reaches {} cm ahead and {} cm behind the CoM",
                fixed(front * 100.0, 1),
                fixed(rear * 100.0, 1)
            ),
            None => margin,
        };
        ui.label(
            RichText::new(format!(
                "At τ = {}: {} feet down, {margin}.",
                fixed(tau, 3),
                now.stance.len()
            ))
            .small(),
        );
        let (ok, text) = verdict(&gait, &curve);
        let color = if ok {
            theme::good_color(ui)
        } else {
            theme::error_color(ui)
        };
        ui.label(RichText::new(text).strong().color(color));
        ui.horizontal_wrapped(|ui| {
            if let Some(beta) = self.task
                && ui.button("Check my phases").clicked()
            {
                self.feedback = Some(
                    kinolab_locomotion::exercise::static_phases(&gait, beta)
                        .unwrap_or_else(|e| kinolab_common::Feedback::from_error(&e)),
                );
            }
            if ui.button("Reset").clicked() {
                self.setup = self.initial.clone();
                self.playing = false;
                self.feedback = None;
            }
        });
        if let Some(beta) = self.task {
            ui.label(RichText::new(format!(
                "Task: keep β = {} and set the lift-off phases φ so the walker is statically stable at every instant of the cycle.",
                fixed(beta, 2)
            )).small());
        }
        crate::widget::feedback_ui(ui, self.feedback.as_ref());
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.setup, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(s) = link::decode::<Setup>(state)
            && s.valid()
        {
            self.setup = s;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_preset_makes_a_valid_set_up() {
        for id in presets() {
            let s = Setup::of(id).unwrap();
            assert!(s.valid(), "{id}");
            assert!(s.gait().is_some(), "{id}");
        }
    }

    #[test]
    fn the_verdict_names_mcghee_and_frank_for_a_slow_quadruped() {
        let mut s = Setup::of("quadruped-crawl").unwrap();
        // At β = 3/4 the crawl's margin touches zero when a hind foot lifts.
        let g = s.gait().unwrap();
        let (ok, text) = verdict(&g, &g.sample(CURVE_SAMPLES));
        assert!(!ok && text.starts_with("Only just"), "{text}");
        s.duty_factor = 0.8;
        let g = s.gait().unwrap();
        let (ok, text) = verdict(&g, &g.sample(CURVE_SAMPLES));
        assert!(ok, "{text}");
        s.duty_factor = 0.7;
        let g = s.gait().unwrap();
        let (ok, text) = verdict(&g, &g.sample(CURVE_SAMPLES));
        assert!(!ok && text.contains("3/4"), "{text}");
    }

    #[test]
    fn damaged_links_are_ignored() {
        let mut s = Setup::of("hexapod-tripod").unwrap();
        s.phases.pop();
        assert!(!s.valid());
        let mut s = Setup::of("hexapod-tripod").unwrap();
        s.duty_factor = 1.0;
        assert!(!s.valid());
    }
}
