//! The CPG lab: four coupled oscillators, one per leg, drawn as dots on
//! circles; edit the coupling weights, pick the gait whose phase offsets
//! they pull towards, kick the phases, and watch the lags converge while
//! the feet below step in the pattern the oscillators make. With the speed
//! switch on, a speed slider picks the gait through the Froude number and
//! sets the frequency, so the network changes gait on the move.
//!
//! The player plays the core's integration (`kinolab cpg`'s, step for
//! step); kicks and changes made while it runs are events on the player,
//! so scrubbing replays them, a link carries them, and "Save run" writes
//! them into the CPG file.

use egui::{RichText, Sense, Stroke, vec2};
use egui_plot::{Plot, PlotPoints};
use kinolab_common::Feedback;
use kinolab_common::display::fixed;
use kinolab_common::random::unit_hash;
use kinolab_locomotion::Cpg;
use kinolab_locomotion::cpg::{Change, CpgRun, Kick};
use kinolab_locomotion::network::{self, Network};
use kinolab_locomotion::speed::quadruped_pace;
use serde::{Deserialize, Serialize};

use super::{numbers_range, options};
use crate::draw::canvas;
use crate::draw::plot::{series_legend, series_lines};
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::player::{Player, Simulation};
use crate::theme;
use crate::widget::{LabWidget, Params, SavedRun, feedback_ui, range};

/// The widget's name in the schema.
const NAME: &str = "cpg-lab";
const LEGS: [&str; 4] = ["LF", "RF", "LH", "RH"];
/// The walker the speed switch imagines: leg length and stride, m.
const LEG: f64 = 0.5;
const STRIDE: f64 = 0.5;
/// The speed the switch starts from when turned on, m/s.
const FIRST_SPEED: f64 = 1.0;
/// The integration step, s: a power of two, so that every tick's time and
/// a saved run's duration are exact and `kinolab cpg` takes the same steps.
const DT: f64 = 1.0 / 512.0;
/// Integration steps per tick of the player (1/64 s).
const STEPS_PER_TICK: usize = 8;
/// Seconds of lag history in the plot.
const HISTORY: f64 = 12.0;
/// The run file's name.
const FILE: &str = "lab.cpg.json";

/// What the lesson sets and a link carries: the schema's parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    gait: String,
    /// Some(v): the speed picks the gait and the frequency.
    speed: Option<f64>,
    weight: f64,
    /// Each w_ij (every one `weight` when `None`).
    weights: Option<[[f64; 4]; 4]>,
    frequency: f64,
    model: Model,
    task: Option<Task>,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum Model {
    Phase,
    VanDerPol,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum Task {
    LockTrot,
}

/// The links of the first format: the network as it was edited.
#[derive(Deserialize)]
struct Legacy {
    gait: String,
    weights: [[f64; 4]; 4],
    frequency: f64,
    van_der_pol: bool,
    speed: Option<f64>,
}

impl Legacy {
    /// The same network as settings (the schema checks the values).
    fn settings(self, lesson: &Settings) -> Result<Settings, String> {
        let numbers = self.weights.iter().flatten().chain([&self.frequency]);
        if !numbers.chain(&self.speed).all(|x| x.is_finite()) {
            return Err("its numbers are damaged".into());
        }
        Ok(Settings {
            gait: self.gait,
            speed: self.speed,
            weights: Some(self.weights),
            // With the speed on, it chose the frequency.
            frequency: if self.speed.is_some() {
                lesson.frequency
            } else {
                self.frequency
            },
            model: if self.van_der_pol {
                Model::VanDerPol
            } else {
                Model::Phase
            },
            ..lesson.clone()
        })
    }
}

/// What can change while the network runs: the gait it pulls towards,
/// the speed that picks it, the frequency and the weights.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Tune {
    gait: String,
    speed: Option<f64>,
    frequency: f64,
    weights: [[f64; 4]; 4],
}

impl Tune {
    fn of(s: &Settings) -> Self {
        let weights = s.weights.unwrap_or_else(|| {
            let mut w = [[s.weight; 4]; 4];
            for (i, row) in w.iter_mut().enumerate() {
                row[i] = 0.0;
            }
            w
        });
        let mut tune = Self {
            gait: s.gait.clone(),
            speed: s.speed,
            frequency: s.frequency,
            weights,
        };
        tune.follow_speed();
        tune
    }

    /// With the speed switch on, take the gait and frequency the speed asks for.
    fn follow_speed(&mut self) {
        let Some(v) = self.speed else { return };
        if let Ok(pace) = quadruped_pace(v, LEG, STRIDE) {
            self.gait = pace.gait.name;
            self.frequency = pace.frequency;
        }
    }

    /// The lift-off phases of the gait pulled towards.
    fn phases(&self) -> Vec<f64> {
        kinolab_locomotion::named(&self.gait)
            .or_else(|| kinolab_locomotion::named("quadruped-trot"))
            .map_or_else(
                || vec![0.0; 4],
                |g| g.legs.iter().map(|l| l.phase).collect(),
            )
    }

    /// The duty factor β of the gait pulled towards (which feet stand).
    fn duty_factor(&self) -> f64 {
        kinolab_locomotion::named(&self.gait).map_or(0.5, |g| g.duty_factor)
    }

    fn rows(&self) -> Vec<Vec<f64>> {
        self.weights.iter().map(|r| r.to_vec()).collect()
    }

    /// This tune as a change of the network at `at` s (a CPG file's).
    fn change(&self, at: f64) -> Change {
        Change {
            at,
            frequency: Some(self.frequency),
            target_phases: Some(self.phases()),
            weights: Some(self.rows()),
        }
    }
}

/// Something sprung on the running network.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum Event {
    /// Every leg's phase turned on by its angle, degrees: a kick scatters
    /// the phases.
    Kick { by_deg: [f64; 4] },
    /// The network changed on the move.
    Retune(Tune),
}

impl Settings {
    /// The run file these settings start (no kicks or changes yet, and no
    /// time): the phases scattered as the first kick scatters them.
    fn file(&self) -> Cpg {
        let tune = Tune::of(self);
        Cpg {
            frequency: tune.frequency,
            legs: LEGS.map(str::to_owned).to_vec(),
            target_phases: tune.phases(),
            weight: self.weight,
            weights: Some(tune.rows()),
            model: match self.model {
                Model::Phase => network::Model::Phase,
                Model::VanDerPol => network::Model::VanDerPol,
            },
            initial_deg: scatter(1).to_vec(),
            dt: DT,
            duration: 0.0,
            kicks: Vec::new(),
            changes: Vec::new(),
        }
    }
}

/// The `n`-th kick's angles (seeded: the same everywhere).
fn scatter(n: u64) -> [f64; 4] {
    [0, 1, 2, 3].map(|i| 360.0 * unit_hash(n, i, 7))
}

/// The network running, a tick at a time: the core's run, and what the
/// learner set it to.
#[derive(Debug, Clone)]
struct Oscillating {
    run: CpgRun,
    tune: Tune,
}

impl Oscillating {
    /// Each leg's lag error behind LF (its lag less the gait's), wrapped
    /// to half a cycle either way: every one goes to 0 as the network locks.
    fn errors(&self) -> [f64; 3] {
        let lags = self.run.network.lags(&self.run.state);
        let targets = self.run.network.target_lags();
        let wrap = |k: usize| {
            let e = lags[k] - targets[k];
            e - e.round()
        };
        [wrap(1), wrap(2), wrap(3)]
    }
}

impl Simulation for Oscillating {
    type Tick = [f64; 3];
    type Event = Event;

    fn step(&mut self) -> Option<[f64; 3]> {
        self.run.advance(STEPS_PER_TICK);
        Some(self.errors())
    }

    fn time(&self) -> f64 {
        self.run.time()
    }

    fn dt(&self) -> f64 {
        DT * STEPS_PER_TICK as f64
    }

    fn spring(&mut self, event: &Event) {
        match event {
            Event::Kick { by_deg } => {
                for (leg, by) in by_deg.iter().enumerate() {
                    self.run.kick(leg, *by);
                }
            }
            Event::Retune(tune) => {
                self.run.change(&tune.change(self.run.time()));
                self.tune = tune.clone();
            }
        }
    }
}

struct CpgLab {
    settings: Settings,
    initial: Settings,
    player: Player<Oscillating>,
    /// A change being dragged: it reaches the network when let go.
    draft: Option<Tune>,
    feedback: Option<Feedback>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    Ok(Box::new(CpgLab::new(settings)))
}

fn player(settings: &Settings) -> Player<Oscillating> {
    Player::new(Oscillating {
        run: CpgRun::start(&settings.file()),
        tune: Tune::of(settings),
    })
}

impl CpgLab {
    fn new(settings: Settings) -> Self {
        Self {
            player: player(&settings),
            initial: settings.clone(),
            settings,
            draft: None,
            feedback: None,
        }
    }

    /// The run the settings start, paused at its start.
    fn rebuild(&mut self) {
        self.player = player(&self.settings);
        self.draft = None;
        self.feedback = None;
    }

    /// The network at the instant shown.
    fn network(&mut self) -> Network {
        self.player.state().run.network.clone()
    }

    /// Scatter the phases now, and play.
    fn kick(&mut self) {
        let kicks = self
            .player
            .events()
            .iter()
            .filter(|(_, e)| matches!(e, Event::Kick { .. }))
            .count() as u64;
        self.player.spring(Event::Kick {
            by_deg: scatter(kicks + 2),
        });
        self.player.playing = true;
        self.feedback = None;
    }

    /// Take `tune` from now on: before the run has started, as the
    /// settings it starts from; after, as a change on the move.
    fn retune(&mut self, tune: Tune) {
        self.feedback = None;
        if self.player.cursor() == 0 && self.player.events().is_empty() {
            let s = &mut self.settings;
            s.speed = tune.speed;
            if tune.speed.is_none() {
                (s.gait, s.frequency) = (tune.gait.clone(), tune.frequency);
            }
            s.weights = Some(tune.weights);
            self.rebuild();
            return;
        }
        // A CPG file's changes come before its kicks at one instant: a
        // change after a kick at this instant waits a tick.
        let now = self.player.time();
        let kicked = self
            .player
            .events()
            .iter()
            .any(|(t, e)| *t == now && matches!(e, Event::Kick { .. }));
        if kicked {
            self.player.step_forward();
        }
        self.player.spring(Event::Retune(tune));
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        let current = self.player.state().tune.clone();
        let mut tune = self.draft.clone().unwrap_or_else(|| current.clone());
        let mut model = self.settings.model;
        speed_controls(ui, &mut tune);
        ui.add_enabled_ui(tune.speed.is_none(), |ui| {
            ui.horizontal_wrapped(|ui| {
                ui.label("pull towards:");
                for g in options(NAME, "gait") {
                    let label = g.trim_start_matches("quadruped-");
                    crate::widget::choose(ui, &mut tune.gait, (*g).to_owned(), label);
                }
            });
        });
        ui.horizontal_wrapped(|ui| {
            crate::widget::choose(ui, &mut model, Model::Phase, "phase oscillators");
            crate::widget::choose(ui, &mut model, Model::VanDerPol, "Van der Pol");
            if ui
                .button("Kick")
                .on_hover_text("Scatter the phases, and play")
                .clicked()
            {
                self.kick();
            }
        });
        ui.add_enabled(
            tune.speed.is_none(),
            egui::Slider::new(&mut tune.frequency, range(NAME, "frequency"))
                .text("frequency f (Hz)"),
        );
        weight_grid(ui, &mut tune.weights);
        if model != self.settings.model {
            // Other oscillators: the run starts again.
            self.settings.model = model;
            self.rebuild();
            return;
        }
        let busy = ui.input(|i| i.pointer.any_down());
        self.draft = None;
        if tune != current {
            if busy {
                self.draft = Some(tune);
            } else {
                self.retune(tune);
            }
        }
    }

    /// The oscillators as dots on circles, and the feet below them.
    fn dials(&mut self, ui: &mut egui::Ui) -> egui::Rect {
        let width = ui.available_width();
        let (response, painter) = canvas(ui, vec2(width, 170.0), Sense::hover());
        let rect = response.rect;
        let ink = ui.visuals().text_color();
        let now = self.player.state();
        let state = &now.run.state;
        let beta = now.tune.duty_factor();
        let r = (width / 12.0).min(38.0);
        for (i, name) in LEGS.iter().enumerate() {
            let centre = rect.left_top() + vec2(width * (0.125 + 0.25 * i as f32), 60.0);
            painter.circle_stroke(centre, r, Stroke::new(1.5, ink.gamma_multiply(0.4)));
            let th = state.theta[i] as f32;
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
            let stance = Network::in_stance(state, i, beta);
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
        rect
    }

    /// Each leg's lag error against time, the last seconds up to the
    /// instant shown.
    fn series(&self, history: f64) -> Vec<(&'static str, Vec<[f64; 2]>)> {
        let ticks = self.player.ticks_shown();
        let from = self.player.time() - history;
        (0..3)
            .map(|k| {
                let points = ticks
                    .iter()
                    .enumerate()
                    .map(|(n, e)| [self.player.time_at(n + 1), e[k]])
                    .filter(|p| p[0] >= from)
                    .collect();
                (LEGS[k + 1], points)
            })
            .collect()
    }

    /// The lag errors: every line goes to 0 as the network locks; the
    /// area it drew.
    fn plot(&self, ui: &mut egui::Ui) -> egui::Rect {
        let series = self.series(HISTORY);
        let top = ui.cursor().min;
        Plot::new(ui.scope_id().with("lags"))
            .height(160.0)
            .x_axis_label("t (s)")
            .y_axis_label("lag error (cycles)")
            .include_y(-0.5)
            .include_y(0.5)
            // Halves and quarters of a cycle: the base-10 grid would label
            // only 0 in a plot this short.
            .y_grid_spacer(egui_plot::log_grid_spacer(2))
            .y_axis_formatter(crate::draw::plot::axis_number)
            .allow_scroll(false)
            .show(ui, |plot| {
                let lines = series
                    .into_iter()
                    .map(|(name, points)| (name, PlotPoints::from(points)))
                    .collect();
                series_lines(plot, lines, None);
            });
        series_legend(ui, &LEGS[1..], &[]);
        egui::Rect::from_min_max(
            top,
            egui::pos2(top.x + ui.available_width(), ui.cursor().min.y),
        )
    }

    /// The run up to the instant shown as a CPG file: the settings'
    /// network, every kick and change, and the instant as its duration.
    fn run_file(&self) -> Cpg {
        let instant = self.player.time();
        let mut file = self.settings.file();
        file.duration = instant;
        for (at, event) in self.player.events() {
            if at > instant {
                continue;
            }
            match event {
                Event::Kick { by_deg } => {
                    file.kicks
                        .extend(
                            (0..)
                                .zip(by_deg)
                                .map(|(leg, by_deg)| Kick { at, leg, by_deg }),
                        );
                }
                Event::Retune(tune) => file.changes.push(tune.change(at)),
            }
        }
        file
    }

    fn exports(&self, ui: &mut egui::Ui, view: egui::Rect) {
        let csv = || export::series_csv("t (s)", &self.series(f64::INFINITY));
        let file = || serde_json::to_string_pretty(&self.run_file()).map_err(|e| e.to_string());
        export::bar(
            ui,
            ui.scope_id().with("cpg-exports"),
            &[
                Export::Png {
                    file: "kinolab-cpg.png",
                    rect: view,
                },
                Export::Csv {
                    file: "kinolab-cpg-lags.csv",
                    make: &csv,
                },
                Export::Run {
                    file: FILE,
                    command: &format!("kinolab cpg {FILE}"),
                    make: &file,
                },
            ],
        );
    }

    fn task_ui(&mut self, ui: &mut egui::Ui, net: &Network) {
        ui.separator();
        ui.label(RichText::new("Task: set the weights and the gait so the oscillators lock into a trot from any start, then check.").strong());
        if ui.button("Check").clicked() {
            self.feedback = Some(kinolab_locomotion::exercise::lock_trot(net));
        }
        feedback_ui(ui, self.feedback.as_ref());
    }
}

/// The speed switch, the speed slider and what the speed implies.
fn speed_controls(ui: &mut egui::Ui, tune: &mut Tune) {
    let mut on = tune.speed.is_some();
    ui.checkbox(&mut on, "speed picks the gait (legs and stride 0.5 m)");
    if !on {
        if tune.speed.take().is_some() {
            // The frequency the speed chose, within the slider's reach.
            let reach = range(NAME, "frequency");
            tune.frequency = tune.frequency.clamp(*reach.start(), *reach.end());
        }
        return;
    }
    let mut v = tune.speed.unwrap_or(FIRST_SPEED);
    ui.add(egui::Slider::new(&mut v, range(NAME, "speed")).text("speed v (m/s)"));
    tune.speed = Some(v);
    tune.follow_speed();
    if let Ok(pace) = quadruped_pace(v, LEG, STRIDE) {
        ui.label(format!(
            "Fr = v²/(g l) = {} → {}, f = βv/L = {} Hz",
            fixed(pace.froude, 2),
            pace.gait.name.trim_start_matches("quadruped-"),
            fixed(pace.frequency, 2)
        ));
    }
}

/// The coupling weights, row i pulled by column j.
fn weight_grid(ui: &mut egui::Ui, weights: &mut [[f64; 4]; 4]) {
    ui.label("Coupling weights w (1/s): row i is pulled by column j");
    egui::Grid::new(ui.scope_id().with("weights")).show(ui, |ui| {
        ui.label("");
        for name in LEGS {
            ui.label(name);
        }
        ui.end_row();
        for (i, row) in weights.iter_mut().enumerate() {
            ui.label(LEGS[i]);
            for (j, w) in row.iter_mut().enumerate() {
                if i == j {
                    ui.label("–");
                } else {
                    let value = *w;
                    ui.add(
                        egui::DragValue::new(w)
                            .range(numbers_range(NAME, "weights"))
                            .speed(0.05)
                            .max_decimals(2),
                    )
                    .widget_info(|| {
                        let name = format!("weight {} from {}", LEGS[i], LEGS[j]);
                        let mut info =
                            egui::WidgetInfo::labeled(egui::Role::SpinButton, true, name);
                        info.value = Some(value);
                        info
                    });
                }
            }
            ui.end_row();
        }
    });
}

impl CpgLab {
    /// The gait pulled towards, how far the network is from it at the
    /// instant shown, and which feet stand.
    fn description(&self) -> String {
        let now = self.player.peek();
        let (net, state) = (&now.run.network, &now.run.state);
        let beta = now.tune.duty_factor();
        let standing: Vec<&str> = (0..LEGS.len())
            .filter(|&i| Network::in_stance(state, i, beta))
            .map(|i| LEGS[i])
            .collect();
        format!(
            "Pulling towards the {} at {} Hz, {} s into the run: largest lag error {} cycles. Feet in stance: {}.",
            now.tune.gait.trim_start_matches("quadruped-"),
            fixed(now.tune.frequency, 2),
            fixed(self.player.time(), 1),
            fixed(net.lag_error(state), 3),
            if standing.is_empty() {
                "none".to_owned()
            } else {
                standing.join(", ")
            }
        )
    }
}

impl LabWidget for CpgLab {
    fn describe(&self) -> Option<String> {
        Some(self.description())
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        self.player.controls(ui);
        let dials = self.dials(ui);
        self.player
            .timeline(ui, "Time the network has run", 0, &mut |_, _, _, _| {});
        self.player.run(ui, 64);
        let net = self.network();
        let state = self.player.state().run.state.clone();
        ui.label(
            RichText::new(format!(
                "largest lag error: {} cycles",
                fixed(net.lag_error(&state), 3)
            ))
            .strong(),
        );
        let plot = self.plot(ui);
        self.exports(ui, dials.union(plot));
        if self.settings.task == Some(Task::LockTrot) {
            self.task_ui(ui, &net);
        }
    }

    fn state(&self) -> Option<String> {
        link::write(NAME, &self.settings, &self.initial, &self.player.moment())
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let (settings, moment) = match link::read::<Settings, Event>(NAME, state) {
            Ok(read) => read,
            Err(why) => match link::decode::<Legacy>(state) {
                Some(old) => (old.settings(&self.initial)?, Moment::default()),
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema too.
        link::check(NAME, &settings)?;
        check_events(&settings, &moment.events)?;
        self.settings = settings;
        self.rebuild();
        self.player.replay(&moment.events, moment.instant);
        Ok(())
    }

    fn seek(&mut self, t: f64) {
        self.player.seek_time(t);
    }

    fn saved_run(&mut self) -> Option<SavedRun> {
        let settled = self.player.state().run.settled();
        let legs = LEGS.map(str::to_owned);
        let report = kinolab_locomotion::report::settled(&legs, settled);
        let report = kinolab_common::display::tidy_report(&report).ok()?;
        let shows = ["/final_deg", "/lag", "/target_lag", "/steps"]
            .into_iter()
            .filter_map(|p| Some((p.to_owned(), report.pointer(p)?.clone())))
            .collect();
        Some(SavedRun {
            file: FILE.into(),
            text: serde_json::to_string_pretty(&self.run_file()).ok()?,
            args: vec!["cpg".into(), FILE.into()],
            shows,
        })
    }
}

/// A link's events, checked as a CPG file checks its kicks and changes,
/// and each change against the schema (gaits, weights, speed, frequency).
fn check_events(settings: &Settings, events: &[(f64, Event)]) -> Result<(), String> {
    let mut file = settings.file();
    for (at, event) in events {
        match event {
            Event::Kick { by_deg } => {
                if !by_deg.iter().all(|a| (0.0..=360.0).contains(a)) {
                    return Err("one of its kicks is out of range".into());
                }
                file.kicks
                    .extend((0..).zip(by_deg).map(|(leg, by_deg)| Kick {
                        at: *at,
                        leg,
                        by_deg: *by_deg,
                    }));
            }
            Event::Retune(tune) => {
                if !fits(tune) {
                    return Err("one of its changes is out of range".into());
                }
                file.changes.push(tune.change(*at));
            }
        }
    }
    file.check().map(|_| ()).map_err(|e| e.to_string())
}

/// Whether a change is one the controls could make.
fn fits(tune: &Tune) -> bool {
    let weights = numbers_range(NAME, "weights");
    let set = match tune.speed {
        Some(v) => {
            let mut picked = tune.clone();
            picked.follow_speed();
            range(NAME, "speed").contains(&v) && picked == *tune
        }
        None => {
            options(NAME, "gait").contains(&tune.gait.as_str())
                && range(NAME, "frequency").contains(&tune.frequency)
        }
    };
    set && tune.weights.iter().flatten().all(|w| weights.contains(w))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::spec;

    fn widget(params: &[(&str, &str)]) -> CpgLab {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        CpgLab::new(p.settings().unwrap_or_else(|e| panic!("{e}")))
    }

    /// The saved file, run by the core as `kinolab cpg` runs it, ends
    /// where the widget shows.
    fn file_reproduces(w: &mut CpgLab) {
        let shown = w.player.state().run.settled();
        let text = serde_json::to_string(&w.run_file()).unwrap_or_default();
        let run = Cpg::from_json(&text).and_then(|c| c.run());
        assert_eq!(run, Ok(shown));
    }

    #[test]
    fn kicks_and_changes_on_the_move_are_in_the_file_and_the_link() {
        let mut w = widget(&[("model", "van-der-pol")]);
        w.seek(1.0);
        w.kick();
        w.player.playing = false;
        w.seek(2.5);
        let mut tune = w.player.state().tune.clone();
        tune.gait = "quadruped-crawl".into();
        tune.weights[1][2] = 0.25;
        w.retune(tune.clone());
        // A change at the instant of a kick waits a tick.
        w.kick();
        w.player.playing = false;
        w.retune(Tune {
            frequency: 1.5,
            ..tune
        });
        w.seek(4.0);
        let file = w.run_file();
        assert_eq!((file.kicks.len(), file.changes.len()), (8, 2));
        assert_eq!(file.duration, 4.0);
        file_reproduces(&mut w);
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.player.time(), 4.0);
        assert_eq!(again.saved_run(), w.saved_run());
        // Scrubbed back before the second kick: the file ends there.
        w.seek(2.0);
        assert_eq!(w.run_file().kicks.len(), 4);
        file_reproduces(&mut w);
    }

    #[test]
    fn before_the_run_starts_a_change_is_the_settings() {
        let mut w = widget(&[]);
        let mut tune = w.player.state().tune.clone();
        tune.weights[0][1] = 2.5;
        w.retune(tune);
        assert_eq!(w.player.events().len(), 0);
        assert_eq!(w.settings.weights.map(|w| w[0][1]), Some(2.5));
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.settings, w.settings);
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        let mut weights = [[1.5_f64; 4]; 4];
        weights[2][3] = 0.0;
        let old = (
            "quadruped-pace".to_owned(),
            weights,
            1.25_f64,
            true,
            None::<f64>,
        );
        let mut w = widget(&[]);
        assert_eq!(w.restore(&link::encode(&old).unwrap_or_default()), Ok(()));
        assert_eq!(w.settings.gait, "quadruped-pace");
        assert_eq!(w.settings.weights, Some(weights));
        assert_eq!(w.settings.frequency, 1.25);
        assert_eq!(w.settings.model, Model::VanDerPol);
        // A weight out of the schema's range: refused, the lesson's kept.
        let mut bad = old;
        bad.1[0][1] = 9.0;
        let mut w = widget(&[("weight", "2")]);
        assert!(w.restore(&link::encode(&bad).unwrap_or_default()).is_err());
        assert_eq!(w.settings, w.initial);
    }

    #[test]
    fn damaged_events_are_refused() {
        let w = widget(&[]);
        let mut tune = Tune::of(&w.settings);
        tune.weights[0][1] = 50.0;
        assert!(check_events(&w.settings, &[(1.0, Event::Retune(tune))]).is_err());
        let kick = Event::Kick {
            by_deg: [1e300, 0.0, 0.0, 0.0],
        };
        assert!(check_events(&w.settings, &[(1.0, kick)]).is_err());
        let mut tune = Tune::of(&w.settings);
        tune.speed = Some(2.0);
        assert!(check_events(&w.settings, &[(1.0, Event::Retune(tune))]).is_err());
    }
}
