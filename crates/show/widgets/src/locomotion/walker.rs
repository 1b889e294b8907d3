//! The hexapod walker: the lab's hexapod model carried through a gait by
//! per-leg inverse kinematics. The 3D view shows the legs, the support
//! polygon of the feet on the ground and the centre of mass above it; a
//! plot follows one leg's joint angles through the cycle, which the
//! player plays, steps and scrubs.

use std::sync::Arc;

use egui::{RichText, Sense, Stroke, vec2};
use egui_plot::{Plot, PlotPoints};
use kinolab_common::display::fixed;
use kinolab_locomotion::walker::{Step, Walker};
use kinolab_mechanism::Vector3;
use serde::{Deserialize, Serialize};

use super::options;
use crate::draw::plot::{REFERENCE, series_legend, series_lines};
use crate::draw::scene3d::{Camera, ViewKind, draw_capsule};
use crate::draw::{canvas_3d, corner_text};
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::player::{Player, Simulation};
use crate::theme;
use crate::widget::{LabWidget, Params, SavedRun, range};

/// The widget's name in the schema.
const NAME: &str = "hexapod-walker";
/// The plotted joints of the left front leg, in the model's order.
const JOINTS: [&str; 3] = ["coxa", "femur", "tibia"];
/// Instants τ = k/N of the cycle (k = 0 … N): the player's ticks, the
/// plot's points, and `kinolab walk --samples N`.
const SAMPLES: usize = 120;
/// Seconds one cycle takes at 1×, and so the time of a tick.
const CYCLE_SECONDS: f64 = 4.0;
const DT: f64 = CYCLE_SECONDS / SAMPLES as f64;
/// The run file's name.
const FILE: &str = "walker.gait.json";

/// What the lesson sets and a link carries: the schema's parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    gait: String,
    stride: f64,
    lift: f64,
}

/// The links of the first format (the speed of play now is the player's).
#[derive(Deserialize)]
struct Legacy {
    gait: String,
    stride: f64,
    lift: f64,
    /// Cycles per second: the player's speeds play it now.
    _rate: f64,
}

impl Settings {
    /// The gait walked, as a gait file holds it.
    fn gait(&self) -> Option<kinolab_locomotion::Gait> {
        let mut g = kinolab_locomotion::named(&self.gait)?;
        g.stride = self.stride;
        Some(g)
    }

    fn gait_file(&self) -> Result<String, String> {
        let gait = self.gait().ok_or("no such gait")?;
        serde_json::to_string_pretty(&gait).map_err(|e| e.to_string())
    }

    /// The arguments after `kinolab` that walk it.
    fn args(&self) -> Vec<String> {
        [
            "walk",
            FILE,
            "--lift",
            &self.lift.to_string(),
            "--samples",
            &SAMPLES.to_string(),
            "--stride",
            &self.stride.to_string(),
        ]
        .map(str::to_owned)
        .to_vec()
    }
}

/// The cycle, an instant a tick (the core solves it whole, as `kinolab
/// walk` does).
#[derive(Debug, Clone)]
struct Walking {
    steps: Arc<Vec<Step>>,
    k: usize,
}

impl Simulation for Walking {
    type Tick = ();
    type Event = ();

    fn step(&mut self) -> Option<()> {
        if self.k + 1 >= self.steps.len() {
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

struct HexapodWalker {
    settings: Settings,
    initial: Settings,
    walker: Option<Walker>,
    /// The cycle solved, and the player that plays it.
    steps: Arc<Vec<Step>>,
    player: Player<Walking>,
    camera: Camera,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    Ok(Box::new(HexapodWalker::new(settings)))
}

fn player(steps: &Arc<Vec<Step>>) -> Player<Walking> {
    Player::new(Walking {
        steps: steps.clone(),
        k: 0,
    })
}

impl HexapodWalker {
    fn new(settings: Settings) -> Self {
        let mut w = Self {
            initial: settings.clone(),
            settings,
            walker: None,
            steps: Arc::default(),
            player: player(&Arc::default()),
            camera: Camera::new(ViewKind::Orbit, [0.0, 0.0, 0.08], 0.3),
        };
        w.rebuild();
        w
    }

    /// The cycle the settings make, at the instant shown before (the
    /// cycle is a function of τ alone, so the instant stays).
    fn rebuild(&mut self) {
        let (k, playing) = (self.player.cursor(), self.player.playing);
        self.walker = self
            .settings
            .gait()
            .and_then(|g| Walker::new(g, self.settings.lift).ok());
        let steps = self
            .walker
            .as_ref()
            .and_then(|w| w.cycle(SAMPLES).ok())
            .unwrap_or_default();
        self.steps = Arc::new(steps);
        self.player = player(&self.steps);
        self.player.seek(k);
        self.player.playing = playing;
    }

    /// The walker at the instant shown.
    fn now(&mut self) -> Option<Step> {
        let k = self.player.state().k;
        self.steps.get(k).cloned()
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        let before = self.settings.clone();
        let s = &mut self.settings;
        ui.horizontal_wrapped(|ui| {
            for g in options(NAME, "gait") {
                let label = g.trim_start_matches("hexapod-");
                crate::widget::choose(ui, &mut s.gait, (*g).to_owned(), label);
            }
        });
        ui.add(
            egui::Slider::new(&mut s.stride, range(NAME, "stride"))
                .step_by(0.005)
                .text("stride L (m)"),
        );
        ui.add(
            egui::Slider::new(&mut s.lift, range(NAME, "lift"))
                .step_by(0.005)
                .text("foot lift (m)"),
        );
        if self.settings != before {
            self.rebuild();
        }
    }

    /// The walker at the instant shown, in 3D; the area it drew.
    fn scene(&mut self, ui: &mut egui::Ui) -> egui::Rect {
        let size = vec2(ui.available_width().min(760.0), 340.0);
        let (response, painter) = canvas_3d(ui, size, Sense::click_and_drag(), &self.camera);
        let rect = response.rect;
        self.camera.handle(ui, &response, true);
        let step = self.now();
        let (Some(w), Some(step)) = (&self.walker, step.as_ref()) else {
            return rect;
        };
        let cam = &self.camera;
        let (margin, standing) = support(ui, &painter, cam, rect, w, step);
        let Ok(placed) = w.model.place(&step.q) else {
            return rect;
        };
        let ink = ui.visuals().text_color();
        for s in w.model.shapes() {
            let at = &placed.bodies[s.body];
            let a = at.rotation * s.a + at.translation.vector;
            let b = at.rotation * s.b + at.translation.vector;
            draw_capsule(
                &painter,
                cam,
                rect,
                &a,
                &b,
                s.radius,
                ink.gamma_multiply(0.3),
            );
        }
        for (i, t) in step.targets.iter().enumerate() {
            let (p, _) = cam.project(rect, &Vector3::from(*t));
            let missed = step.errors[i] > kinolab_locomotion::walker::REACHED;
            let c = if missed {
                theme::error_color(ui)
            } else {
                theme::accent(ui)
            };
            painter.circle_stroke(p, 4.0, Stroke::new(1.5, c));
        }
        let text = match margin {
            Some(m) => format!(
                "stance feet {}; static margin S = {} m",
                standing,
                fixed(m, 3)
            ),
            None => "no foot on the ground".to_owned(),
        };
        corner_text(&painter, rect, 0, text, ink);
        if !step.unreachable.is_empty() {
            let text = format!("out of reach: {}", step.unreachable.join(", "));
            corner_text(&painter, rect, 1, text, theme::error_color(ui));
        }
        rect
    }

    /// The left-front leg's three joints (the first three variables)
    /// through the cycle, degrees against τ.
    fn series(&self) -> Vec<(&'static str, Vec<[f64; 2]>)> {
        let joint = |j: usize| -> Vec<[f64; 2]> {
            self.steps
                .iter()
                .enumerate()
                .map(|(n, s)| {
                    let tau = n as f64 / SAMPLES as f64;
                    [tau, s.q.get(j).copied().unwrap_or(0.0).to_degrees()]
                })
                .collect()
        };
        JOINTS
            .into_iter()
            .enumerate()
            .map(|(j, name)| (name, joint(j)))
            .collect()
    }

    /// The joint plot with the instant shown; the area it drew.
    fn plot(&self, ui: &mut egui::Ui) -> egui::Rect {
        let tau = self.player.cursor() as f64 / SAMPLES as f64;
        let series = self.series();
        let top = ui.cursor().min;
        Plot::new(ui.scope_id().with("walker-joints"))
            .height(160.0)
            .x_axis_label("τ (cycle)")
            .y_axis_label("left front leg (°)")
            .allow_scroll(false)
            .show(ui, |plot| {
                let lines = series
                    .into_iter()
                    .map(|(name, points)| (name, PlotPoints::from(points)))
                    .collect();
                series_lines(plot, lines, Some(tau));
            });
        series_legend(ui, &JOINTS, &[("now", REFERENCE)]);
        egui::Rect::from_min_max(
            top,
            egui::pos2(top.x + ui.available_width(), ui.cursor().min.y),
        )
    }

    fn exports(&self, ui: &mut egui::Ui, view: egui::Rect) {
        let csv = || export::series_csv("tau", &self.series());
        let file = || self.settings.gait_file();
        let command = format!("kinolab {}", self.settings.args().join(" "));
        export::bar(
            ui,
            ui.scope_id().with("walker-exports"),
            &[
                Export::Png {
                    file: "kinolab-hexapod.png",
                    rect: view,
                },
                Export::Csv {
                    file: "kinolab-hexapod-joints.csv",
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

/// The stance feet on the ground (the support polygon's corners) and the
/// static margin of the centre of mass above the origin, m.
fn stance(w: &Walker, step: &Step) -> (Vec<[f64; 2]>, Option<f64>) {
    let stance: Vec<[f64; 2]> = (0..6)
        .filter(|&i| w.gait.in_stance(i, step.tau))
        .map(|i| [step.targets[i][0], step.targets[i][1]])
        .collect();
    let margin = kinolab_locomotion::static_stability([0.0, 0.0], &stance)
        .ok()
        .map(|s| s.margin);
    (stance, margin)
}

/// The support polygon under the body (the stance feet on the ground)
/// and the centre of mass above it; the static margin and how many feet
/// stand.
fn support(
    ui: &egui::Ui,
    painter: &egui::Painter,
    cam: &Camera,
    rect: egui::Rect,
    w: &Walker,
    step: &Step,
) -> (Option<f64>, usize) {
    let (stance, margin) = stance(w, step);
    let hull = kinolab_locomotion::convex_hull(&stance);
    let good = margin.is_some_and(|m| m > 0.0);
    let color = if good {
        theme::good_color(ui)
    } else {
        theme::error_color(ui)
    };
    let pts: Vec<egui::Pos2> = hull
        .iter()
        .map(|p| cam.project(rect, &Vector3::new(p[0], p[1], 0.0)).0)
        .collect();
    if pts.len() >= 3 {
        painter.add(egui::Shape::convex_polygon(
            pts,
            color.gamma_multiply(0.2),
            Stroke::new(1.5, color),
        ));
    } else if pts.len() == 2 {
        painter.line_segment([pts[0], pts[1]], Stroke::new(2.0, color));
    }
    let (com, _) = cam.project(rect, &Vector3::zeros());
    painter.circle_filled(com, 5.0, color);
    (margin, stance.len())
}

impl HexapodWalker {
    /// The gait, where in the cycle the instant shown is, the feet down
    /// and the static margin, and any foot out of reach.
    fn description(&self) -> String {
        let gait = self.settings.gait.trim_start_matches("hexapod-");
        let k = self.player.cursor();
        let (Some(w), Some(step)) = (&self.walker, self.steps.get(k)) else {
            return format!("The {gait} gait cannot be walked with these settings.");
        };
        let (feet, margin) = stance(w, step);
        let margin = margin.map_or("no support polygon".to_owned(), |m| {
            format!("static margin {} cm", fixed(m * 100.0, 1))
        });
        let mut text = format!(
            "The {gait} gait, stride {} cm, at {}% of the cycle: {} feet on the ground, {margin}.",
            fixed(self.settings.stride * 100.0, 1),
            fixed(step.tau * 100.0, 0),
            feet.len()
        );
        if !step.unreachable.is_empty() {
            text += &format!(" Out of reach: {}.", step.unreachable.join(", "));
        }
        text
    }
}

impl LabWidget for HexapodWalker {
    fn describe(&self) -> Option<String> {
        Some(self.description())
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        self.player.controls(ui);
        let scene = self.scene(ui);
        self.player.timeline(
            ui,
            "The cycle, τ from 0 to 1",
            SAMPLES,
            &mut |_, _, _, _| {},
        );
        self.player.run(ui, 30);
        ui.label(RichText::new("Drag to turn the view. Rings: where each foot should be (red when the leg cannot reach it); the polygon: the stance feet; the dot: the centre of mass.").small());
        let plot = self.plot(ui);
        self.exports(ui, scene.union(plot));
    }

    fn state(&self) -> Option<String> {
        link::write(NAME, &self.settings, &self.initial, &self.player.moment())
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let (settings, moment) = match link::read::<Settings, ()>(NAME, state) {
            Ok(read) => read,
            Err(why) => match link::decode::<Legacy>(state) {
                Some(old) if old.stride.is_finite() && old.lift.is_finite() => (
                    Settings {
                        gait: old.gait,
                        stride: old.stride,
                        lift: old.lift,
                    },
                    Moment::default(),
                ),
                Some(_) => return Err("its numbers are damaged".into()),
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema too.
        link::check(NAME, &settings)?;
        self.settings = settings;
        self.player = player(&Arc::default());
        self.rebuild();
        self.player.replay(&moment.events, moment.instant);
        Ok(())
    }

    fn seek(&mut self, t: f64) {
        self.player.seek_time(t);
    }

    fn saved_run(&mut self) -> Option<SavedRun> {
        let shown = self.steps.get(..=self.player.cursor())?;
        Some(SavedRun {
            file: FILE.into(),
            text: self.settings.gait_file().ok()?,
            args: self.settings.args(),
            shows: vec![(
                "/steps".into(),
                kinolab_common::display::tidy_report(&shown).ok()?,
            )],
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::spec;

    fn widget(params: &[(&str, &str)]) -> HexapodWalker {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        HexapodWalker::new(p.settings().unwrap_or_else(|e| panic!("{e}")))
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        let old = ("hexapod-wave".to_owned(), 0.1_f64, 0.02_f64, 0.5_f64);
        let mut w = widget(&[]);
        assert_eq!(w.restore(&link::encode(&old).unwrap_or_default()), Ok(()));
        assert_eq!(
            w.settings,
            Settings {
                gait: "hexapod-wave".into(),
                stride: 0.1,
                lift: 0.02,
            }
        );
        assert_eq!(w.steps.len(), SAMPLES + 1);
        // A lift out of the schema's range: refused, the lesson's settings kept.
        let bad = ("hexapod-wave".to_owned(), 0.1_f64, 0.5_f64, 0.5_f64);
        let mut w = widget(&[("stride", "0.08")]);
        assert!(w.restore(&link::encode(&bad).unwrap_or_default()).is_err());
        assert_eq!(w.settings, w.initial);
    }

    #[test]
    fn the_instant_travels_in_the_link() {
        let mut w = widget(&[("gait", "hexapod-ripple")]);
        w.seek(0.9);
        assert_eq!(w.player.cursor(), 27);
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.settings, w.settings);
        assert_eq!(again.now(), w.now());
        assert_eq!(again.saved_run(), w.saved_run());
        let csv = export::series_csv("tau", &w.series());
        assert_eq!(csv.lines().count(), SAMPLES + 2);
    }
}
