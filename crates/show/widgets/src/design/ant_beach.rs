//! Simon's ant on the beach: the pebbles, the path the one rule makes at
//! the chosen body size, walked step by step on the player, the core's
//! numbers, and tortuosity against size for this beach.

use std::sync::Arc;

use egui::{RichText, Sense, Stroke, vec2};
use egui_plot::{Line, Plot, PlotPoints, Points};
use kinolab_common::Feedback;
use kinolab_common::display::tidy_report;
use kinolab_design::ant::{self, Beach, BeachWalk, DEFAULT_PEBBLES, Walk};
use serde::{Deserialize, Serialize};

use crate::draw::PlaneView;
use crate::draw::labels::Labels;
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::player::{Player, Simulation};
use crate::theme;
use crate::widget::{LabWidget, Params, SavedRun, feedback_ui, range};

/// The widget's name in the schema.
const NAME: &str = "ant-beach";
/// The file "Save run" writes (`kinolab ant` reads it).
const FILE: &str = "beach.ant.json";
/// Steps of the walk per second on the player's clock.
const STEPS_PER_SECOND: f64 = 50.0;

/// What the lesson sets and a link carries: the schema's parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    size: f64,
    seed: u64,
    task: Option<Task>,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum Task {
    NearlyStraight,
}

/// The links of the first format: the size and the beach.
#[derive(Deserialize)]
struct Legacy {
    size: f64,
    seed: u64,
}

impl Settings {
    /// The walk as a file (`kinolab ant` reads it).
    fn file(&self) -> BeachWalk {
        BeachWalk {
            seed: self.seed,
            pebbles: DEFAULT_PEBBLES,
            size: self.size,
        }
    }
}

/// A walk, played a step at a time (the core computes it whole).
#[derive(Debug, Clone)]
struct Walking {
    walk: Arc<Walk>,
    k: usize,
}

impl Simulation for Walking {
    type Tick = ();
    type Event = ();

    fn step(&mut self) -> Option<()> {
        (self.k + 1 < self.walk.path.len()).then(|| self.k += 1)
    }

    fn time(&self) -> f64 {
        self.k as f64 / STEPS_PER_SECOND
    }

    fn dt(&self) -> f64 {
        1.0 / STEPS_PER_SECOND
    }

    fn spring(&mut self, (): &()) {}
}

impl Walking {
    /// The path walked so far.
    fn walked(&self) -> &[[f64; 2]] {
        &self.walk.path[..=self.k.min(self.walk.path.len().saturating_sub(1))]
    }
}

struct AntBeach {
    settings: Settings,
    initial: Settings,
    beach: Option<Beach>,
    walk: Option<Arc<Walk>>,
    player: Option<Player<Walking>>,
    /// (size, tortuosity) for this beach.
    curve: Vec<[f64; 2]>,
    /// Body sizes still to walk for the curve, largest first: a new beach
    /// fills its curve over a few frames, never in one long one.
    curve_todo: Vec<f64>,
    feedback: Option<Feedback>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    Ok(Box::new(AntBeach::new(settings)))
}

impl AntBeach {
    /// The widget with its settings; the beach is made when first needed
    /// ([`AntBeach::ensure`]), since a link read right after would only
    /// make it again.
    fn new(settings: Settings) -> Self {
        AntBeach {
            initial: settings.clone(),
            settings,
            beach: None,
            walk: None,
            player: None,
            curve: Vec::new(),
            curve_todo: Vec::new(),
            feedback: None,
        }
    }

    /// Make the beach and the walk if they are not made yet.
    fn ensure(&mut self) {
        if self.beach.is_none() {
            self.new_beach();
        }
    }

    fn new_beach(&mut self) {
        self.beach = Beach::new(self.settings.seed, DEFAULT_PEBBLES).ok();
        self.curve.clear();
        self.curve_todo = ant::sizes().collect();
        self.curve_todo.reverse();
        self.rewalk();
    }

    /// Walk more sizes for the curve, for at most `budget` of wall time
    /// (at least one size); whether sizes are left.
    fn grow_curve(&mut self, budget: std::time::Duration) -> bool {
        let started = web_time::Instant::now();
        while let (Some(size), Some(beach)) = (self.curve_todo.pop(), &self.beach) {
            if let Ok(w) = ant::walk(beach, size) {
                self.curve.push([size, w.tortuosity]);
            }
            if started.elapsed() > budget {
                break;
            }
        }
        !self.curve_todo.is_empty()
    }

    /// The walk at the size set, on the player at its start.
    fn rewalk(&mut self) {
        self.walk = self
            .beach
            .as_ref()
            .and_then(|b| ant::walk(b, self.settings.size).ok())
            .map(Arc::new);
        self.player = self
            .walk
            .clone()
            .map(|walk| Player::new(Walking { walk, k: 0 }));
        self.feedback = None;
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        let before = self.settings.clone();
        let seeds = *range(NAME, "seed").end() as u64 + 1;
        crate::widget::control_row(ui, |ui| {
            ui.add(
                egui::Slider::new(&mut self.settings.size, range(NAME, "size"))
                    .logarithmic(true)
                    .text("body size (ant lengths)"),
            );
            if ui.button("New beach").clicked() {
                self.settings.seed = (self.settings.seed + 1) % seeds;
            }
            ui.label(format!("beach {}", self.settings.seed));
        });
        if self.settings.seed != before.seed {
            self.new_beach();
        } else if self.settings != before {
            self.rewalk();
        }
        if self.settings != before
            && let Some(player) = &mut self.player
        {
            // A new walk: watch it from the start.
            player.restart();
        }
    }

    /// The beach, the whole path faint, the path walked so far and the body.
    fn draw(&mut self, ui: &mut egui::Ui) -> egui::Rect {
        let width = ui.available_width();
        let (rect, _) = ui.allocate_exact_size(vec2(width, width * 0.6 * 0.9), Sense::hover());
        let view = PlaneView::fit(
            rect.shrink(4.0),
            [0.0, -ant::HALF_WIDTH],
            [ant::LENGTH, ant::HALF_WIDTH],
        );
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 6.0, theme::sand_color(ui));
        let body = ant::ANT * self.settings.size;
        if let Some(beach) = &self.beach {
            for p in &beach.pebbles {
                painter.circle_filled(
                    view.to_screen([p.x, p.y]),
                    view.length(p.r).max(0.8),
                    theme::pebble_color(p.r > 0.25 * body),
                );
            }
        }
        let accent = theme::accent(ui);
        let line = |path: &[[f64; 2]]| -> Vec<egui::Pos2> {
            path.iter().map(|&p| view.to_screen(p)).collect()
        };
        if let Some(w) = &self.walk {
            painter.add(egui::Shape::line(
                line(&w.path),
                Stroke::new(1.0, accent.gamma_multiply(0.3)),
            ));
        }
        if let Some(player) = &mut self.player {
            let walked = player.state().walked();
            painter.add(egui::Shape::line(line(walked), Stroke::new(2.0, accent)));
            if let Some(&at) = walked.last() {
                let r = view.length(body / 2.0).max(3.0);
                let stroke = Stroke::new(1.5, theme::robot_color(ui));
                painter.circle_stroke(view.to_screen(at), r, stroke);
            }
        }
        let mut labels = Labels::default();
        for (p, label) in [(ant::START, "start"), (ant::GOAL, "goal")] {
            let at = view.to_screen(p);
            labels
                .add(at, label, ui.visuals().text_color())
                .toward(vec2(0.0, -1.0));
        }
        labels.draw(&painter, &egui::FontId::proportional(theme::SMALL_SIZE));
        rect
    }

    fn plot(&self, ui: &mut egui::Ui) -> egui::Rect {
        let curve: PlotPoints<'static> = self.curve.iter().map(|[s, t]| [s.log10(), *t]).collect();
        let here: PlotPoints<'static> = self
            .walk
            .iter()
            .map(|w| [w.size.log10(), w.tortuosity])
            .collect();
        Plot::new(ui.scope_id().with("tortuosity"))
            .height(150.0)
            .x_axis_label("body size (ant lengths, log scale)")
            .y_axis_label("tortuosity")
            .include_y(1.0)
            // The axis runs in log10 of the size; its marks say the size.
            .x_axis_formatter(|mark, _| size_label(mark.value))
            .y_grid_spacer(egui_plot::log_grid_spacer(2))
            .y_axis_formatter(crate::draw::plot::axis_number)
            .allow_scroll(false)
            .show(ui, |plot| {
                plot.line(Line::new("this beach", curve).width(2.0));
                plot.points(Points::new("this body", here).radius(5.0));
            })
            .response
            .rect
    }

    fn exports(&self, ui: &mut egui::Ui, shown: egui::Rect) {
        let csv = || {
            export::series_csv(
                "body size (ant lengths)",
                &[("tortuosity on this beach", self.curve.clone())],
            )
        };
        let file =
            || serde_json::to_string_pretty(&self.settings.file()).map_err(|e| e.to_string());
        let command = format!("kinolab ant {FILE}");
        export::bar(
            ui,
            ui.scope_id().with("ant-beach-exports"),
            &[
                Export::Png {
                    file: "kinolab-ant-beach.png",
                    rect: shown,
                },
                Export::Csv {
                    file: "kinolab-tortuosity.csv",
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

    fn task_ui(&mut self, ui: &mut egui::Ui) {
        ui.separator();
        ui.label(RichText::new("Task: find a body size of at most 100 whose path on this beach is within 1 % of straight, then check.").strong());
        if ui.button("Check").clicked() {
            self.feedback = Some(kinolab_design::exercise::nearly_straight(
                self.settings.seed,
                self.settings.size,
            ));
        }
        feedback_ui(ui, self.feedback.as_ref());
    }
}

impl AntBeach {
    /// The body on this beach, how far along its walk the instant shown
    /// is, and how winding the whole path is.
    fn description(&self) -> String {
        use kinolab_common::display::fixed;
        let s = &self.settings;
        let body = format!(
            "A body of {} ant lengths on beach {}",
            fixed(s.size, 2),
            s.seed
        );
        let (Some(w), Some(player)) = (&self.walk, &self.player) else {
            return format!("{body}: the beach is not laid out yet.");
        };
        format!(
            "{body}: step {} of {} of its walk. The path is {} m long, tortuosity {}, with {} turns; {} pebbles matter at this size{}.",
            player.cursor(),
            w.path.len().saturating_sub(1),
            fixed(w.length, 3),
            fixed(w.tortuosity, 3),
            w.turns,
            w.obstacles,
            if w.reached {
                ""
            } else {
                "; it did not get across"
            }
        )
    }
}

impl LabWidget for AntBeach {
    fn describe(&self) -> Option<String> {
        Some(self.description())
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.ensure();
        self.controls(ui);
        if let Some(player) = &mut self.player {
            player.controls(ui);
        }
        let beach = self.draw(ui);
        if let Some(player) = &mut self.player {
            let steps = self.walk.as_ref().map_or(0, |w| w.path.len() - 1);
            player.timeline(ui, "Steps of the walk", steps, &mut |_, _, _, _| {});
            player.run(ui, 200);
        }
        if let Some(w) = &self.walk {
            ui.label(RichText::new(format!(
                "body {:.3} m · pebbles that matter: {} · path {:.3} m · tortuosity {:.3} · turns {}{}",
                ant::ANT * w.size,
                w.obstacles,
                w.length,
                w.tortuosity,
                w.turns,
                if w.reached { "" } else { " · did not get across" }
            )).strong());
        }
        if self.grow_curve(std::time::Duration::from_millis(8)) {
            ui.ctx().request_repaint();
        }
        let plot = self.plot(ui);
        self.exports(ui, beach.union(plot));
        if self.settings.task == Some(Task::NearlyStraight) {
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
                        size: old.size,
                        seed: old.seed,
                        ..self.initial.clone()
                    },
                    Moment::default(),
                ),
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema's ranges too.
        link::check(NAME, &settings)?;
        // A link is written only when something changed: one holding the
        // lesson's own settings and nothing else is not one of this widget's.
        if settings == self.initial && moment == Moment::default() {
            return Err("it holds nothing this widget would change".into());
        }
        self.settings = settings;
        self.new_beach();
        if let Some(player) = &mut self.player {
            player.replay(&moment.events, moment.instant);
        }
        Ok(())
    }

    fn seek(&mut self, t: f64) {
        self.ensure();
        if let Some(player) = &mut self.player {
            player.seek_time(t);
        }
    }

    fn saved_run(&mut self) -> Option<SavedRun> {
        self.ensure();
        let (player, walk) = (self.player.as_mut()?, self.walk.as_ref()?);
        let mut shows = vec![(
            "/path".to_owned(),
            tidy_report(&player.state().walked()).ok()?,
        )];
        for (pointer, value) in [
            ("/size", tidy_report(&walk.size)),
            ("/length", tidy_report(&walk.length)),
            ("/tortuosity", tidy_report(&walk.tortuosity)),
            ("/turns", tidy_report(&walk.turns)),
            ("/obstacles", tidy_report(&walk.obstacles)),
            ("/reached", tidy_report(&walk.reached)),
        ] {
            shows.push((pointer.to_owned(), value.ok()?));
        }
        Some(SavedRun {
            file: FILE.into(),
            text: serde_json::to_string_pretty(&self.settings.file()).ok()?,
            args: vec!["ant".into(), FILE.into()],
            shows,
        })
    }
}

/// A mark on the log-scale axis as the size it stands for: `0.1`, `1`,
/// `10`; marks between powers of ten keep two significant digits.
fn size_label(log10: f64) -> String {
    let size = 10f64.powf(log10);
    if size >= 10.0 {
        format!("{size:.0}")
    } else {
        let digits = (1.0 - size.log10().floor()).max(0.0) as usize;
        let text = format!("{size:.digits$}");
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    }
}

#[cfg(test)]
mod tests {

    #[test]
    fn log_axis_marks_say_the_size() {
        let labels: Vec<String> = [-1.0, 0.0, 0.5, 1.0, 2.0].map(super::size_label).to_vec();
        assert_eq!(labels, ["0.1", "1", "3.2", "10", "100"]);
    }

    use super::*;
    use crate::registry::spec;

    fn widget(params: &[(&str, &str)]) -> AntBeach {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        AntBeach::new(p.settings().unwrap_or_else(|e| panic!("{e}")))
    }

    fn walked(w: &mut AntBeach) -> Vec<[f64; 2]> {
        w.ensure();
        w.player
            .as_mut()
            .map(|p| p.state().walked().to_vec())
            .unwrap_or_default()
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        let old = link::encode(&(30.0_f64, 7_u64)).unwrap_or_default();
        let mut w = widget(&[("task", "nearly-straight")]);
        assert_eq!(w.restore(&old), Ok(()));
        assert_eq!(
            w.settings,
            Settings {
                size: 30.0,
                seed: 7,
                task: Some(Task::NearlyStraight)
            }
        );
        // Out of the schema's range: refused, the lesson's settings kept.
        let bad = link::encode(&(3000.0_f64, 7_u64)).unwrap_or_default();
        let mut w = widget(&[("size", "5")]);
        assert!(w.restore(&bad).is_err());
        assert_eq!(w.settings.size, 5.0);
    }

    #[test]
    fn the_walk_is_played_step_by_step_and_the_instant_travels_in_the_link() {
        let mut w = widget(&[("size", "3")]);
        assert_eq!(walked(&mut w).len(), 1, "at the start");
        w.seek(0.5);
        let half = walked(&mut w);
        assert_eq!(half.len(), 26);
        let whole = w.walk.as_ref().map(|w| w.path.clone()).unwrap_or_default();
        assert_eq!(half[..], whole[..26]);
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(walked(&mut again), half);
        assert_eq!(again.saved_run(), w.saved_run());
    }

    #[test]
    fn the_saved_file_walks_the_same_path() {
        let mut w = widget(&[("size", "12"), ("seed", "4")]);
        w.seek(1.0);
        let Some(saved) = w.saved_run() else {
            panic!("no run")
        };
        let file = BeachWalk::from_json(&saved.text).unwrap_or_else(|e| panic!("{e}"));
        let walk = file.walk().unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(walk.path[..51], walked(&mut w)[..]);
        // The plot as a table: a header and a row per size plotted.
        assert!(!w.grow_curve(std::time::Duration::MAX));
        let csv = export::series_csv("size", &[("tortuosity", w.curve.clone())]);
        assert_eq!(csv.lines().count(), ant::sizes().count() + 1);
    }
}
