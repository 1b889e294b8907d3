//! The cart-table: a body on one foot, pushed. The ankle holds the zero
//! moment point at the capture point as far as the foot reaches; the side
//! view shows the body, the foot, the ZMP and the capture point, and a plot
//! follows x, ẋ and the ZMP through the run, which the player plays,
//! steps and scrubs.

use std::sync::Arc;

use egui::{Color32, Pos2, RichText, Sense, Stroke, vec2};
use egui_plot::{Line, Plot, PlotPoints};
use kinolab_common::Feedback;
use kinolab_common::display::fixed;
use kinolab_locomotion::balance::{BalanceSample, CartTable, PushRun, Recovery};
use serde::{Deserialize, Serialize};

use crate::draw::labels::Labels;
use crate::draw::plot::{REFERENCE, series_legend, series_lines};
use crate::draw::{PlaneView, canvas};
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::player::{Player, Simulation};
use crate::theme;
use crate::widget::{LabWidget, Params, SavedRun, feedback_ui, range};

/// The widget's name in the schema.
const NAME: &str = "zmp-cart-table";

/// The plotted series, in palette order.
const NAMES: [&str; 3] = ["x (CoM)", "v (CoM speed)", "ZMP"];

/// The foot, m: heel and toe along x, the ankle at 0.
const HEEL: f64 = -0.05;
const TOE: f64 = 0.15;
/// Seconds a push is followed for, and the step.
const DURATION: f64 = 4.0;
const DT: f64 = 0.005;

/// What the lesson sets and a link carries: the schema's parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    height: f64,
    push: f64,
    task: Option<Task>,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum Task {
    LargestPush,
}

/// The links of the first format: the two sliders.
#[derive(Deserialize)]
struct Legacy {
    height: f64,
    push: f64,
}

impl Settings {
    /// The push as a run file (`kinolab zmp` reads it).
    fn run_file(&self) -> PushRun {
        PushRun {
            height: self.height,
            heel: HEEL,
            toe: TOE,
            x0: 0.0,
            push: self.push,
            duration: DURATION,
            dt: DT,
        }
    }
}

/// A push's run, played a step at a time (the core computes it whole).
#[derive(Debug, Clone)]
struct Pushed {
    run: Arc<Recovery>,
    k: usize,
}

impl Simulation for Pushed {
    type Tick = BalanceSample;
    type Event = ();

    fn step(&mut self) -> Option<BalanceSample> {
        let next = self.run.samples.get(self.k + 1).copied()?;
        self.k += 1;
        Some(next)
    }

    fn time(&self) -> f64 {
        self.run.samples.get(self.k).map_or(0.0, |s| s.t)
    }

    fn dt(&self) -> f64 {
        DT
    }

    fn spring(&mut self, (): &()) {}
}

impl Pushed {
    fn now(&self) -> Option<BalanceSample> {
        self.run.samples.get(self.k).copied()
    }
}

struct ZmpCartTable {
    settings: Settings,
    initial: Settings,
    /// The run the settings make, whole, and the player that plays it.
    run: Option<Arc<Recovery>>,
    player: Option<Player<Pushed>>,
    feedback: Option<Feedback>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    let mut widget = ZmpCartTable {
        initial: settings.clone(),
        settings,
        run: None,
        player: None,
        feedback: None,
    };
    widget.rebuild();
    Ok(Box::new(widget))
}

impl ZmpCartTable {
    fn table(&self) -> Option<CartTable> {
        CartTable::new(self.settings.height, HEEL, TOE).ok()
    }

    /// The run the settings make, paused at its start.
    fn rebuild(&mut self) {
        self.run = self.settings.run_file().run().ok().map(Arc::new);
        self.player = self
            .run
            .clone()
            .map(|run| Player::new(Pushed { run, k: 0 }));
        self.feedback = None;
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        let before = self.settings.clone();
        let s = &mut self.settings;
        ui.add(egui::Slider::new(&mut s.height, range(NAME, "height")).text("CoM height (m)"));
        ui.add(
            egui::Slider::new(&mut s.push, range(NAME, "push"))
                .step_by(0.005)
                .text("push (m/s)"),
        );
        if self.settings != before {
            self.rebuild();
        }
        ui.horizontal_wrapped(|ui| {
            if ui
                .button("Push")
                .on_hover_text("Give the body its speed and play")
                .clicked()
                && let Some(player) = &mut self.player
            {
                player.restart();
            }
            if ui.button("Reset").clicked() {
                self.settings = self.initial.clone();
                self.rebuild();
            }
            if let Some(table) = self.table() {
                ui.label(format!(
                    "ω = √(g / CoM height) = {} 1/s",
                    fixed(table.omega(), 2)
                ));
            }
        });
    }

    /// The sample shown now (the body at rest before the push plays).
    fn now(&mut self) -> Option<BalanceSample> {
        self.player.as_mut()?.state().now()
    }

    fn side_view(&mut self, ui: &mut egui::Ui) -> egui::Rect {
        let width = ui.available_width();
        let (response, painter) = canvas(ui, vec2(width, 280.0), Sense::hover());
        let rect = response.rect;
        let z = self.settings.height;
        let view = PlaneView::fit(rect.shrink(12.0), [-0.35, -0.08], [0.65, z + 0.12]);
        let ink = ui.visuals().text_color();
        let ground = [view.to_screen([-0.35, 0.0]), view.to_screen([0.65, 0.0])];
        painter.line_segment(ground, Stroke::new(1.5, ink.gamma_multiply(0.5)));
        let foot =
            egui::Rect::from_two_pos(view.to_screen([HEEL, 0.03]), view.to_screen([TOE, 0.0]));
        painter.rect_filled(foot, 2.0, ink.gamma_multiply(0.6));
        let s = self.now();
        let (x, zmp, wanted) = s.map_or((0.0, 0.0, 0.0), |s| (s.x, s.zmp, s.wanted));
        let fallen = s.is_some_and(|s| !s.inside);
        let body = view.to_screen([x, z]);
        let ankle = view.to_screen([0.0, 0.03]);
        painter.line_segment([ankle, body], Stroke::new(3.0, ink));
        let color = if fallen {
            theme::error_color(ui)
        } else {
            theme::accent(ui)
        };
        painter.circle(body, 14.0, color, Stroke::new(1.5, ink));
        // Marks on the ground, their names below it, clear of each other,
        // of the ground line and of the foot.
        let mut labels = Labels::default();
        labels.within(rect);
        labels.avoid_line(ground[0], ground[1]);
        labels.reserve(foot);
        let mut mark = |at: f64, color: Color32, text: &str| {
            let p = view.to_screen([at, 0.0]);
            painter.circle_filled(p, 5.0, color);
            labels.reserve(egui::Rect::from_center_size(p, vec2(10.0, 10.0)));
            labels
                .add(p, text, color)
                .toward(vec2(0.0, 1.0))
                .beyond(4.0);
        };
        mark(zmp, theme::good_color(ui), "ZMP");
        if s.is_some() {
            mark(
                wanted.clamp(-0.35, 0.65),
                theme::error_color(ui),
                "capture point",
            );
        }
        let com_ground: Pos2 = view.to_screen([x, 0.0]);
        painter.line_segment(
            [body, com_ground],
            Stroke::new(1.0, ink.gamma_multiply(0.3)),
        );
        labels.avoid_line(body, com_ground);
        labels.draw(&painter, &egui::FontId::proportional(theme::LABEL_SIZE));
        rect
    }

    /// x, ẋ and the ZMP against time, with the instant shown.
    fn series(&self) -> Vec<(&'static str, Vec<[f64; 2]>)> {
        let Some(run) = &self.run else {
            return Vec::new();
        };
        let run = &run.samples;
        let values: [fn(&BalanceSample) -> f64; 3] = [|s| s.x, |s| s.xd, |s| s.zmp];
        NAMES
            .into_iter()
            .zip(values)
            .map(|(name, f)| (name, run.iter().map(|s| [s.t, f(s)]).collect()))
            .collect()
    }

    fn plot(&self, ui: &mut egui::Ui) -> egui::Rect {
        let now = self.player.as_ref().map_or(0.0, Player::time);
        let series = self.series();
        let top = ui.cursor().min;
        Plot::new(ui.scope_id().with("zmp-plot"))
            .height(170.0)
            .x_axis_label("t (s)")
            .y_axis_label("m, m/s")
            .allow_scroll(false)
            .show(ui, |plot| {
                let lines = series
                    .iter()
                    .map(|(name, points)| (*name, PlotPoints::from(points.clone())))
                    .collect();
                series_lines(plot, lines, Some(now));
                let toe: PlotPoints<'_> = vec![[0.0, TOE], [DURATION, TOE]].into();
                plot.line(Line::new("toe", toe).color(REFERENCE));
            });
        series_legend(ui, &NAMES, &[("toe and now", REFERENCE)]);
        egui::Rect::from_min_max(
            top,
            egui::pos2(top.x + ui.available_width(), ui.cursor().min.y),
        )
    }

    fn verdict(&mut self) -> String {
        let (Some(player), Some(run)) = (&self.player, &self.run) else {
            return "These settings cannot be pushed.".to_owned();
        };
        if player.cursor() == 0 {
            return "Press Push (or Play) to give the body the chosen speed.".to_owned();
        }
        // The run is computed whole when pushed: say how it ends.
        match run.left_foot_at {
            Some(t) => format!(
                "From t = {} s the ZMP this motion needs lies past the toe. The real ZMP stays on the foot, at the toe, and the body falls forwards.",
                fixed(t, 2)
            ),
            None if run.recovered => {
                "Caught: the capture point stayed on the foot, and the body came to rest over it."
                    .to_owned()
            }
            None => "Still settling.".to_owned(),
        }
    }

    fn exports(&self, ui: &mut egui::Ui, view: egui::Rect, plot: egui::Rect) {
        let series = || export::series_csv("t (s)", &self.series());
        let file =
            || serde_json::to_string_pretty(&self.settings.run_file()).map_err(|e| e.to_string());
        export::bar(
            ui,
            ui.scope_id().with("zmp-exports"),
            &[
                Export::Png {
                    file: "kinolab-cart-table.png",
                    rect: view.union(plot),
                },
                Export::Csv {
                    file: "kinolab-cart-table.csv",
                    make: &series,
                },
                Export::Run {
                    file: "push.zmp.json",
                    command: "kinolab zmp push.zmp.json",
                    make: &file,
                },
            ],
        );
    }

    fn task_ui(&mut self, ui: &mut egui::Ui) {
        ui.separator();
        ui.label(RichText::new("Task: find the largest push the ankle can still catch (to within 5 %), then check.").strong());
        if ui.button("Check").clicked()
            && let Some(table) = self.table()
        {
            self.feedback = Some(
                kinolab_locomotion::exercise::largest_push(&table, self.settings.push)
                    .unwrap_or_else(|e| Feedback::not_yet(e.to_string())),
            );
        }
        feedback_ui(ui, self.feedback.as_ref());
    }
}

impl ZmpCartTable {
    /// The sample at the instant shown, without moving the player.
    fn shown(&self) -> Option<BalanceSample> {
        let (player, run) = (self.player.as_ref()?, self.run.as_ref()?);
        run.samples.get(player.cursor()).copied()
    }

    /// The instant shown: where the body and the ZMP are, and whether the
    /// ZMP the motion needs (the capture point) is on the foot.
    fn description(&self) -> String {
        let Some(s) = self.shown() else {
            return "These settings cannot be pushed.".to_owned();
        };
        let cm = |x: f64| fixed(x * 100.0, 1);
        let foot = if s.inside {
            format!(
                "inside the foot (heel {} cm to toe {} cm)",
                cm(HEEL),
                cm(TOE)
            )
        } else {
            "past the toe, so the real ZMP stays at the toe and the body falls".to_owned()
        };
        let foot = format!(
            "the ZMP this motion needs (the capture point, {} cm) is {foot}",
            cm(s.wanted)
        );
        format!(
            "Push of {} m/s, {} s after it: CoM at {} cm moving {} m/s, ZMP at {} cm; {foot}.",
            fixed(self.settings.push, 2),
            fixed(s.t, 2),
            cm(s.x),
            fixed(s.xd, 2),
            cm(s.zmp)
        )
    }
}

impl LabWidget for ZmpCartTable {
    fn describe(&self) -> Option<String> {
        Some(self.description())
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        if let Some(player) = &mut self.player {
            player.controls(ui);
        }
        let view = self.side_view(ui);
        if let Some(player) = &mut self.player {
            player.timeline(
                ui,
                "Time since the push",
                (DURATION / DT) as usize,
                &mut |_, _, _, _| {},
            );
            player.run(ui, 400);
        }
        let verdict = self.verdict();
        ui.label(RichText::new(verdict).strong());
        let plot = self.plot(ui);
        self.exports(ui, view, plot);
        if self.settings.task == Some(Task::LargestPush) {
            self.task_ui(ui);
        }
    }

    fn state(&self) -> Option<String> {
        let moment = self.player.as_ref().map(Player::moment).unwrap_or_default();
        link::write(NAME, &self.settings, &self.initial, &moment)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let (settings, moment) = match link::read::<Settings, ()>(NAME, state) {
            Ok(read) => read,
            Err(why) => match link::decode::<Legacy>(state) {
                Some(old) => (
                    Settings {
                        height: old.height,
                        push: old.push,
                        ..self.initial.clone()
                    },
                    Moment::default(),
                ),
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema's ranges too.
        link::check(NAME, &settings)?;
        self.settings = settings;
        self.rebuild();
        if let Some(player) = &mut self.player {
            player.replay(&moment.events, moment.instant);
        }
        Ok(())
    }

    fn seek(&mut self, t: f64) {
        if let Some(player) = &mut self.player {
            player.seek_time(t);
        }
    }

    fn saved_run(&mut self) -> Option<SavedRun> {
        let (player, run) = (self.player.as_ref()?, self.run.as_ref()?);
        let shown = &run.samples[..=player.cursor()];
        Some(SavedRun {
            file: "push.zmp.json".into(),
            text: serde_json::to_string_pretty(&self.settings.run_file()).ok()?,
            args: vec!["zmp".into(), "push.zmp.json".into()],
            shows: vec![(
                "/samples".into(),
                kinolab_common::display::tidy_report(&shown).ok()?,
            )],
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::{create, spec};

    fn widget(params: &[(&str, &str)]) -> ZmpCartTable {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        let settings: Settings = p.settings().unwrap_or_else(|e| panic!("{e}"));
        let mut w = ZmpCartTable {
            initial: settings.clone(),
            settings,
            run: None,
            player: None,
            feedback: None,
        };
        w.rebuild();
        w
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        let old = link::encode(&(1.2_f64, 0.35_f64)).unwrap_or_default();
        let mut w = widget(&[]);
        assert_eq!(w.restore(&old), Ok(()));
        assert_eq!((w.settings.height, w.settings.push), (1.2, 0.35));
        // Out of the schema's range: refused, the lesson's settings kept.
        let bad = link::encode(&(9.0_f64, 0.35_f64)).unwrap_or_default();
        let mut w = widget(&[("push", "0.4")]);
        assert!(w.restore(&bad).is_err());
        assert_eq!(w.settings.push, 0.4);
        assert!(create(&spec(NAME, &[])).is_ok());
    }

    #[test]
    fn the_description_follows_the_instant_shown() {
        let mut w = widget(&[("push", "0.3")]);
        let Ok(run) = w.settings.run_file().run() else {
            panic!("the push does not run")
        };
        let at = |w: &ZmpCartTable| w.describe().unwrap_or_default();
        let start = at(&w);
        assert!(start.contains(" 0.00 s after it"), "{start}");
        w.seek(1.0);
        let s = run.samples[w.player.as_ref().map_or(0, Player::cursor)];
        assert!((s.t - 1.0).abs() < 1e-9);
        let words = at(&w);
        for part in [
            format!("{} s after it", fixed(s.t, 2)),
            format!("CoM at {} cm", fixed(s.x * 100.0, 1)),
            format!("ZMP at {} cm", fixed(s.zmp * 100.0, 1)),
        ] {
            assert!(words.contains(&part), "{part} missing from: {words}");
        }
        assert_ne!(words, start);
        assert_eq!(words.contains("inside the foot"), s.inside, "{words}");
    }

    #[test]
    fn the_instant_travels_in_the_link() {
        let mut w = widget(&[("push", "0.5")]);
        w.seek(1.25);
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.settings.push, 0.5);
        assert_eq!(again.now(), w.now());
        assert!((again.player.as_ref().map_or(0.0, Player::time) - 1.25).abs() < 1e-9);
        assert_eq!(again.saved_run(), w.saved_run());
    }
}
