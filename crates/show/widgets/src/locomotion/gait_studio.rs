//! The gait studio: a walker's feet through one cycle, seen from above,
//! with the support polygon and the stability margin at every instant, the
//! footfall diagram and the margin over the cycle beside it. The player
//! plays, steps and scrubs the cycle; change the duty factor, the stride,
//! the centre of mass and each leg's lift-off phase.

use std::sync::Arc;

use egui::{Align2, Color32, FontId, Painter, Pos2, Rect, RichText, Sense, Stroke, vec2};
use kinolab_common::display::fixed;
use kinolab_locomotion::gait::{Instant, min_margin};
use kinolab_locomotion::{Gait, named, static_stability};
use serde::{Deserialize, Serialize};

use super::{draw_foot, draw_support, numbers_range, options};
use crate::draw::labels::Labels;
use crate::draw::{PlaneView, canvas};
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::player::{Player, Simulation};
use crate::theme;
use crate::widget::{LabWidget, Params, SavedRun, range};

/// The widget's name in the schema.
const NAME: &str = "gait-studio";
/// Instants of the cycle: the player's ticks, the margin curve, and the
/// samples `kinolab gait --samples` prints (at τ = (k + ½)/N).
const SAMPLES: usize = 360;
/// Seconds one cycle takes at 1×, and so the time of a tick.
const CYCLE_SECONDS: f64 = 6.0;
const DT: f64 = CYCLE_SECONDS / SAMPLES as f64;
/// A smallest margin below this, m, is called "only just" stable.
const EDGE: f64 = 0.002;
/// Below this width the panels stack.
const NARROW: f32 = 620.0;
/// The run file's name.
const FILE: &str = "studio.gait.json";
/// Room for one leg's phase slider (its label, slider and number), points.
const PHASE_CELL: f32 = 270.0;

/// What the lesson sets and a link carries: the schema's parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    gait: String,
    /// β, the stride and the phases: the gait's own when `None`.
    duty_factor: Option<f64>,
    stride: Option<f64>,
    com: [f64; 2],
    phases: Option<Vec<f64>>,
    task: Option<Task>,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum Task {
    StaticPhases,
}

/// The links of the first format: the set-up and the instant τ.
#[derive(Deserialize)]
struct Legacy {
    preset: String,
    duty_factor: f64,
    stride: f64,
    com: [f64; 2],
    phases: Vec<f64>,
    tau: f64,
}

impl Legacy {
    /// The same set-up as settings (the schema checks the values), and τ
    /// as the instant on the player.
    fn settings(self, task: Option<Task>) -> Result<(Settings, Moment<()>), String> {
        let numbers = [self.duty_factor, self.stride, self.tau];
        if !numbers
            .iter()
            .chain(&self.com)
            .chain(&self.phases)
            .all(|x| x.is_finite())
            || !(0.0..1.0).contains(&self.tau)
        {
            return Err("its numbers are damaged".into());
        }
        let k = (self.tau * SAMPLES as f64 - 0.5).round().max(0.0);
        let moment = Moment {
            instant: k * DT,
            events: Vec::new(),
        };
        let settings = Settings {
            gait: self.preset,
            duty_factor: Some(self.duty_factor),
            stride: Some(self.stride),
            com: self.com,
            phases: Some(self.phases),
            task,
        };
        Ok((settings, moment))
    }
}

impl Settings {
    /// With the task, every leg lifts at once to begin with: the learner
    /// starts from the worst.
    fn for_task(mut self) -> Self {
        if self.task.is_some() && self.phases.is_none() {
            let legs = named(&self.gait).map_or(0, |g| g.legs.len());
            self.phases = Some(vec![0.0; legs]);
        }
        self
    }

    /// The gait these settings describe: the named gait's legs with these
    /// values.
    fn gait(&self) -> Option<Gait> {
        let mut g = named(&self.gait)?;
        g.duty_factor = self.duty_factor.unwrap_or(g.duty_factor);
        g.stride = self.stride.unwrap_or(g.stride);
        g.com = self.com;
        if let Some(phases) = &self.phases {
            for (leg, phase) in g.legs.iter_mut().zip(phases) {
                leg.phase = *phase;
            }
        }
        g.check().ok().map(|()| g)
    }

    /// The gait as a gait file (`kinolab gait` reads it).
    fn gait_file(&self) -> Result<String, String> {
        let gait = self.gait().ok_or("these settings make no gait")?;
        serde_json::to_string_pretty(&gait).map_err(|e| e.to_string())
    }
}

/// The cycle, an instant a tick (the core samples it whole).
#[derive(Debug, Clone)]
struct Cycle {
    instants: Arc<Vec<Instant>>,
    k: usize,
}

impl Simulation for Cycle {
    type Tick = ();
    type Event = ();

    fn step(&mut self) -> Option<()> {
        if self.k + 1 >= self.instants.len() {
            return None;
        }
        self.k += 1;
        Some(())
    }

    fn time(&self) -> f64 {
        self.k as f64 * DT
    }

    fn dt(&self) -> f64 {
        DT
    }

    fn spring(&mut self, (): &()) {}
}

struct GaitStudio {
    settings: Settings,
    initial: Settings,
    feedback: Option<kinolab_common::Feedback>,
    /// The gait the settings make, its cycle, and the player that plays it.
    gait: Option<Gait>,
    curve: Arc<Vec<Instant>>,
    player: Player<Cycle>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings = p.settings::<Settings>()?.for_task();
    if named(&settings.gait).is_none() {
        return Err(format!("no gait called `{}`", settings.gait));
    }
    Ok(Box::new(GaitStudio::new(settings)))
}

impl GaitStudio {
    fn new(settings: Settings) -> Self {
        let mut w = Self {
            initial: settings.clone(),
            settings,
            feedback: None,
            gait: None,
            curve: Arc::default(),
            player: Player::new(Cycle {
                instants: Arc::default(),
                k: 0,
            }),
        };
        w.rebuild();
        w
    }

    /// The cycle the settings make, at the instant shown before (the
    /// cycle is a function of τ alone, so the instant stays).
    fn rebuild(&mut self) {
        let (k, playing) = (self.player.cursor(), self.player.playing);
        self.gait = self.settings.gait();
        let instants = self
            .gait
            .as_ref()
            .map_or_else(Vec::new, |g| g.sample(SAMPLES));
        self.curve = Arc::new(instants);
        self.player = Player::new(Cycle {
            instants: self.curve.clone(),
            k: 0,
        });
        self.player.seek(k);
        self.player.playing = playing;
    }

    /// The instant shown.
    fn now(&mut self) -> Option<Instant> {
        let k = self.player.state().k;
        self.curve.get(k).cloned()
    }

    /// The duty factor the task fixes: the lesson's.
    fn task_beta(&self) -> Option<f64> {
        self.settings.task?;
        self.initial.gait().map(|g| g.duty_factor)
    }

    fn controls(&mut self, ui: &mut egui::Ui, gait: &Gait) {
        let before = self.settings.clone();
        let s = &mut self.settings;
        crate::widget::control_row(ui, |ui| {
            let chosen = s.gait.clone();
            egui::ComboBox::new(ui.scope_id().with("preset"), "gait")
                .selected_text(&s.gait)
                .show_ui(ui, |ui| {
                    for id in options(NAME, "gait") {
                        crate::widget::choose(ui, &mut s.gait, (*id).to_owned(), *id);
                    }
                });
            if s.gait != chosen {
                // Another gait: its own β, stride and phases.
                (s.duty_factor, s.stride, s.phases) = (None, None, None);
            }
        });
        let mut beta = gait.duty_factor;
        let mut stride = gait.stride;
        let mut phases: Vec<f64> = gait.legs.iter().map(|l| l.phase).collect();
        crate::widget::control_row(ui, |ui| {
            ui.add(egui::Slider::new(&mut beta, range(NAME, "duty_factor")).text("β duty factor"));
            ui.add(egui::Slider::new(&mut stride, range(NAME, "stride")).text("L stride (m)"));
        });
        crate::widget::control_row(ui, |ui| {
            let com = numbers_range(NAME, "com");
            ui.add(egui::Slider::new(&mut s.com[0], com.clone()).text("CoM x (m)"));
            ui.add(egui::Slider::new(&mut s.com[1], com).text("CoM y (m)"));
        });
        crate::widget::control_grid(ui, "gait-phases", phases.len(), PHASE_CELL, |ui, i| {
            let name = gait.legs.get(i).map_or("", |l| l.name.as_str());
            if let Some(phase) = phases.get_mut(i) {
                ui.add(
                    egui::Slider::new(phase, numbers_range(NAME, "phases"))
                        .text(format!("φ {name}"))
                        .max_decimals(3),
                );
            }
        });
        if s.gait == before.gait {
            if beta != gait.duty_factor {
                s.duty_factor = Some(beta);
            }
            if stride != gait.stride {
                s.stride = Some(stride);
            }
            if gait.legs.iter().zip(&phases).any(|(l, p)| l.phase != *p) {
                s.phases = Some(phases);
            }
        }
        if self.settings != before {
            self.rebuild();
        }
    }

    /// The cycle's instants as a table: τ, the margin (blank with no foot
    /// down) and whether each leg stands.
    fn cycle_csv(&self) -> String {
        let Some(gait) = &self.gait else {
            return String::new();
        };
        let mut out = String::from("tau,margin (m)");
        for leg in &gait.legs {
            out += &format!(",{} stands", leg.name);
        }
        out.push('\n');
        for s in self.curve.iter() {
            let margin = s.margin.map(|m| m.to_string()).unwrap_or_default();
            out += &format!("{},{margin}", s.tau);
            for i in 0..gait.legs.len() {
                out += if s.stance.contains(&i) { ",1" } else { ",0" };
            }
            out.push('\n');
        }
        out
    }

    fn exports(&self, ui: &mut egui::Ui, view: Rect) {
        let csv = || self.cycle_csv();
        let file = || self.settings.gait_file();
        let command = format!("kinolab gait {FILE} --samples {SAMPLES}");
        export::bar(
            ui,
            ui.scope_id().with("gait-exports"),
            &[
                Export::Png {
                    file: "kinolab-gait.png",
                    rect: view,
                },
                Export::Csv {
                    file: "kinolab-gait.csv",
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

    /// The task's line and its check.
    fn task_ui(&mut self, ui: &mut egui::Ui, gait: &Gait) {
        let Some(beta) = self.task_beta() else {
            return;
        };
        if ui.button("Check my phases").clicked() {
            self.feedback = Some(
                kinolab_locomotion::exercise::static_phases(gait, beta)
                    .unwrap_or_else(|e| kinolab_common::Feedback::from_error(&e)),
            );
        }
        ui.label(RichText::new(format!(
            "Task: keep β = {} and set the lift-off phases φ so the walker is statically stable at every instant of the cycle.",
            fixed(beta, 2)
        )).small());
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

/// The footfall diagram: a row per leg, a bar where it stands.
fn footfalls(
    ui: &egui::Ui,
    painter: &Painter,
    rect: Rect,
    gait: &Gait,
    row_h: f32,
    x_of: &dyn Fn(f64) -> f32,
) {
    let ink = ui.visuals().text_color();
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
    let weak = ui.visuals().weak_text_color();
    let left = rect.left() + 34.0;
    let width = rect.right() - 8.0 - left;
    let x_of = |t: f64| left + width * t as f32;
    let rows = gait.legs.len() as f32;
    let row_h = ((rect.height() * 0.5) / rows).min(18.0);
    footfalls(ui, painter, rect, gait, row_h, &x_of);
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
    // One polyline per run of stable (or unstable) samples, not a shape per
    // sample: the curve is redrawn on every frame while the cycle plays.
    let good = theme::good_color(ui);
    let bad = theme::error_color(ui);
    let mut run: Vec<Pos2> = Vec::new();
    let mut run_good = true;
    let finish = |run: &mut Vec<Pos2>, good_run: bool| {
        if run.len() > 1 {
            let color = if good_run { good } else { bad };
            painter.add(egui::Shape::line(
                std::mem::take(run),
                Stroke::new(2.0, color),
            ));
        }
        run.clear();
    };
    for pair in curve.windows(2) {
        let (Some(a), Some(b)) = (pair[0].margin, pair[1].margin) else {
            finish(&mut run, run_good);
            continue;
        };
        let (from, to) = (
            Pos2::new(x_of(pair[0].tau), y_of(a)),
            Pos2::new(x_of(pair[1].tau), y_of(b)),
        );
        let stable = a.min(b) > 0.0;
        if stable != run_good || run.is_empty() {
            finish(&mut run, run_good);
            run_good = stable;
            run.push(from);
        }
        run.push(to);
    }
    finish(&mut run, run_good);
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
    /// The margin at the instant shown, then the verdict on the cycle.
    fn describe(&self) -> Option<String> {
        let gait = self.gait.as_ref()?;
        let now = self
            .curve
            .get(self.player.cursor().min(self.curve.len().saturating_sub(1)))?;
        let margin = now.margin.map_or(
            "no support polygon (fewer than three feet down)".to_owned(),
            |m| format!("stability margin {} cm", fixed(m * 100.0, 1)),
        );
        Some(format!(
            "At {}% of the cycle: {margin}. {}",
            fixed(now.tau * 100.0, 0),
            verdict(gait, &self.curve).1
        ))
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        let Some(gait) = self.gait.clone() else {
            self.settings = self.initial.clone();
            self.rebuild();
            return;
        };
        self.controls(ui, &gait);
        let Some(gait) = self.gait.clone() else {
            return;
        };
        self.player.controls(ui);
        let Some(now) = self.now() else {
            return;
        };
        let width = ui.available_width();
        let narrow = width < NARROW;
        let h = if narrow { 560.0 } else { 300.0 };
        let (response, painter) = canvas(ui, vec2(width, h), Sense::hover());
        let rect = response.rect;
        let (a, b) = if narrow {
            rect.split_top_bottom_at_fraction(0.5)
        } else {
            rect.split_left_right_at_fraction(0.5)
        };
        top_view(ui, &painter, a, &gait, &now);
        cycle_view(ui, &painter, b, &gait, &self.curve, now.tau);
        self.player.timeline(
            ui,
            "The cycle, τ from 0 to 1",
            SAMPLES - 1,
            &mut |_, _, _, _| {},
        );
        self.player.run(ui, 60);
        ui.label(RichText::new(instant_text(&gait, &now)).small());
        let (ok, text) = verdict(&gait, &self.curve);
        let color = if ok {
            theme::good_color(ui)
        } else {
            theme::error_color(ui)
        };
        ui.label(RichText::new(text).strong().color(color));
        ui.horizontal_wrapped(|ui| {
            self.task_ui(ui, &gait);
            if ui.button("Reset").clicked() {
                self.settings = self.initial.clone();
                self.feedback = None;
                self.rebuild();
            }
        });
        crate::widget::feedback_ui(ui, self.feedback.as_ref());
        self.exports(ui, rect);
    }

    fn state(&self) -> Option<String> {
        link::write(NAME, &self.settings, &self.initial, &self.player.moment())
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let (settings, moment) = match link::read::<Settings, ()>(NAME, state) {
            Ok((settings, moment)) => (settings.for_task(), moment),
            Err(why) => match link::decode::<Legacy>(state) {
                Some(old) => old.settings(self.initial.task)?,
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema too.
        link::check(NAME, &settings)?;
        if settings.gait().is_none() {
            return Err("its settings make no gait".into());
        }
        self.settings = settings;
        self.player = Player::new(Cycle {
            instants: Arc::default(),
            k: 0,
        });
        self.rebuild();
        self.player.replay(&moment.events, moment.instant);
        Ok(())
    }

    fn seek(&mut self, t: f64) {
        self.player.seek_time(t);
    }

    fn saved_run(&mut self) -> Option<SavedRun> {
        let gait = self.gait.as_ref()?;
        let report = kinolab_locomotion::report::gait(gait, SAMPLES).ok()?;
        let shown = report.samples.get(..=self.player.cursor())?;
        Some(SavedRun {
            file: FILE.into(),
            text: self.settings.gait_file().ok()?,
            args: vec![
                "gait".into(),
                FILE.into(),
                "--samples".into(),
                SAMPLES.to_string(),
            ],
            shows: vec![(
                "/samples".into(),
                kinolab_common::display::tidy_report(&shown).ok()?,
            )],
        })
    }
}

/// The instant in words: how many feet stand, the margin, and how far the
/// polygon reaches ahead of and behind the centre of mass.
fn instant_text(gait: &Gait, now: &Instant) -> String {
    let margin = now.margin.map_or("no foot down".to_owned(), |m| {
        format!("margin {} cm", fixed(m * 100.0, 1))
    });
    let margin = match kinolab_locomotion::longitudinal_margins(gait.com, &now.feet) {
        Some((front, rear)) => format!(
            "{margin}; the polygon reaches {} cm ahead and {} cm behind the CoM",
            fixed(front * 100.0, 1),
            fixed(rear * 100.0, 1)
        ),
        None => margin,
    };
    format!(
        "At τ = {}: {} feet down, {margin}.",
        fixed(now.tau, 3),
        now.stance.len()
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::spec;

    fn widget(params: &[(&str, &str)]) -> GaitStudio {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        GaitStudio::new(
            p.settings::<Settings>()
                .unwrap_or_else(|e| panic!("{e}"))
                .for_task(),
        )
    }

    #[test]
    fn every_gait_makes_a_cycle() {
        for id in options(NAME, "gait") {
            let w = widget(&[("gait", *id)]);
            assert!(w.gait.is_some(), "{id}");
            assert_eq!(w.curve.len(), SAMPLES, "{id}");
        }
    }

    #[test]
    fn the_verdict_names_mcghee_and_frank_for_a_slow_quadruped() {
        let mut w = widget(&[("gait", "quadruped-crawl")]);
        // At β = 3/4 the crawl's margin touches zero when a hind foot lifts.
        let g = w.settings.gait().unwrap();
        let (ok, text) = verdict(&g, &g.sample(SAMPLES));
        assert!(!ok && text.starts_with("Only just"), "{text}");
        w.settings.duty_factor = Some(0.8);
        let g = w.settings.gait().unwrap();
        let (ok, text) = verdict(&g, &g.sample(SAMPLES));
        assert!(ok, "{text}");
        w.settings.duty_factor = Some(0.7);
        let g = w.settings.gait().unwrap();
        let (ok, text) = verdict(&g, &g.sample(SAMPLES));
        assert!(!ok && text.contains("3/4"), "{text}");
    }

    #[test]
    fn a_link_of_the_first_format_still_opens_at_its_tau() {
        let old = (
            "hexapod-tripod".to_owned(),
            0.6_f64,
            0.25_f64,
            [0.01_f64, -0.02],
            vec![0.0_f64, 0.5, 0.0, 0.5, 0.0, 0.5],
            0.5_f64,
        );
        let mut w = widget(&[]);
        assert_eq!(w.restore(&link::encode(&old).unwrap_or_default()), Ok(()));
        assert_eq!(w.settings.gait, "hexapod-tripod");
        assert_eq!(w.settings.duty_factor, Some(0.6));
        assert_eq!(w.settings.com, [0.01, -0.02]);
        let now = w.now().unwrap();
        assert!((now.tau - 0.5).abs() <= 0.5 / SAMPLES as f64, "{}", now.tau);
        // A phase missing, or β out of the schema's range: refused, the
        // lesson's settings kept.
        let mut short = old.clone();
        short.4.pop();
        let mut w = widget(&[("gait", "quadruped-crawl")]);
        assert!(
            w.restore(&link::encode(&short).unwrap_or_default())
                .is_err()
        );
        let mut wide = old;
        wide.1 = 1.0;
        assert!(w.restore(&link::encode(&wide).unwrap_or_default()).is_err());
        assert_eq!(w.settings, w.initial);
    }

    #[test]
    fn the_instant_travels_in_the_link() {
        let mut w = widget(&[("gait", "quadruped-crawl")]);
        w.settings.phases = Some(vec![0.0, 0.5, 0.75, 0.25]);
        w.rebuild();
        w.seek(1.2);
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.settings, w.settings);
        assert_eq!(again.now(), w.now());
        assert_eq!(again.saved_run(), w.saved_run());
        assert_eq!(w.cycle_csv().lines().count(), SAMPLES + 1);
    }

    #[test]
    fn the_task_starts_with_every_leg_lifting_at_once() {
        let w = widget(&[("gait", "quadruped-crawl"), ("task", "static-phases")]);
        assert_eq!(w.settings.phases, Some(vec![0.0; 4]));
        assert_eq!(w.task_beta(), Some(0.75));
    }
}
