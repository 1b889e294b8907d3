//! Sensing routes: sensors on the left, the functions they can feed on the
//! right. Click a sensor, then a function, to draw (or remove) a wire; the
//! core names each sensor's route and the paradigm the wiring amounts to.

use egui::{Color32, Rect, RichText, Sense, Stroke, pos2, vec2};
use kinolab_architectures::Architecture;
use kinolab_architectures::exercise::wire_hybrid;
use kinolab_architectures::routes::{FUNCTIONS, MODEL, Route, SENSORS, Wiring};
use kinolab_common::Feedback;
use serde::{Deserialize, Serialize};

use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::theme;
use crate::widget::{LabWidget, Params, feedback_ui};

/// The widget's name in the schema.
const NAME: &str = "sensing-routes";

/// What the lesson sets and a link carries: the schema's parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    preset: Preset,
    task: Option<Task>,
    /// The learner's wiring, in place of the preset's.
    wiring: Option<Rows>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum Preset {
    Empty,
    Hierarchical,
    Reactive,
    Hybrid,
}

impl Preset {
    fn wiring(self) -> Wiring {
        match self {
            Preset::Empty => Wiring::default(),
            Preset::Hierarchical => Wiring::preset(Architecture::Hierarchical),
            Preset::Reactive => Wiring::preset(Architecture::Reactive),
            Preset::Hybrid => Wiring::preset(Architecture::Hybrid),
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum Task {
    WireHybrid,
}

/// A wiring written as `kinolab routes` takes it: six rows of five 0/1
/// marks, `;` between rows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(try_from = "String", into = "String")]
struct Rows(Wiring);

impl TryFrom<String> for Rows {
    type Error = String;

    fn try_from(text: String) -> Result<Self, String> {
        let bad = || format!("`{text}` is not six rows of five 0/1 marks");
        let mut feeds = [[false; 5]; 6];
        let rows: Vec<&str> = text.split(';').collect();
        if rows.len() != feeds.len() {
            return Err(bad());
        }
        for (row, marks) in feeds.iter_mut().zip(rows) {
            let marks: Vec<char> = marks
                .chars()
                .filter(|c| !c.is_whitespace() && *c != ',')
                .collect();
            if marks.len() != row.len() {
                return Err(bad());
            }
            for (feed, mark) in row.iter_mut().zip(marks) {
                *feed = match mark {
                    '0' => false,
                    '1' => true,
                    _ => return Err(bad()),
                };
            }
        }
        Ok(Rows(Wiring { feeds }))
    }
}

impl From<Rows> for String {
    fn from(r: Rows) -> String {
        let row = |r: &[bool; 5]| {
            r.iter()
                .map(|f| if *f { '1' } else { '0' })
                .collect::<String>()
        };
        r.0.feeds.iter().map(row).collect::<Vec<_>>().join(";")
    }
}

struct SensingRoutes {
    settings: Settings,
    initial: Settings,
    /// The sensor picked, waiting for a function.
    picked: Option<usize>,
    feedback: Option<Feedback>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    Ok(Box::new(SensingRoutes {
        initial: settings.clone(),
        settings,
        picked: None,
        feedback: None,
    }))
}

fn route_color(ui: &egui::Ui, r: Route) -> Color32 {
    match r {
        Route::Unused => ui.visuals().weak_text_color(),
        Route::Global => theme::ARCHITECTURE_COLORS[0],
        Route::Local => theme::ARCHITECTURE_COLORS[1],
        Route::Hybrid => theme::ARCHITECTURE_COLORS[2],
    }
}

impl SensingRoutes {
    /// The wiring drawn: the learner's, or the preset's.
    fn wiring(&self) -> Wiring {
        self.settings
            .wiring
            .map_or_else(|| self.settings.preset.wiring(), |r| r.0)
    }

    /// The two columns of boxes and the wires between them.
    fn diagram(&mut self, ui: &mut egui::Ui) -> Rect {
        let width = ui.available_width();
        let row = 34.0;
        let (rect, _) = ui.allocate_exact_size(
            vec2(width, row * SENSORS.len() as f32 + 8.0),
            Sense::hover(),
        );
        let box_w = (width * 0.34).min(170.0);
        let left = |i: usize| {
            Rect::from_min_size(
                pos2(rect.left(), rect.top() + 4.0 + row * i as f32),
                vec2(box_w, row - 8.0),
            )
        };
        let right_row = row * SENSORS.len() as f32 / FUNCTIONS.len() as f32;
        let right = |j: usize| {
            Rect::from_min_size(
                pos2(
                    rect.right() - box_w,
                    rect.top() + 4.0 + right_row * j as f32 + (right_row - row) / 2.0,
                ),
                vec2(box_w, row - 8.0),
            )
        };
        let wiring = self.wiring();
        let report = wiring.report();
        let painter = ui.painter_at(rect);
        for (s, feeds) in wiring.feeds.iter().enumerate() {
            for (f, on) in feeds.iter().enumerate() {
                if *on {
                    let c = route_color(ui, report.routes[s]);
                    painter.line_segment(
                        [left(s).right_center(), right(f).left_center()],
                        Stroke::new(2.5, c),
                    );
                }
            }
        }
        self.sensor_boxes(ui, &painter, &left, &report.routes);
        self.function_boxes(ui, &painter, &right, wiring);
        rect
    }

    /// The sensors, each with its route; a click picks one.
    fn sensor_boxes(
        &mut self,
        ui: &egui::Ui,
        painter: &egui::Painter,
        left: &dyn Fn(usize) -> Rect,
        routes: &[Route],
    ) {
        let ink = ui.visuals().text_color();
        for (s, name) in SENSORS.iter().enumerate() {
            let r = left(s);
            let picked = self.picked == Some(s);
            let response = ui.interact(r, ui.scope_id().with(("sensor", s)), Sense::click());
            if response.clicked() {
                self.picked = if picked { None } else { Some(s) };
            }
            let stroke = Stroke::new(
                if picked { 3.0 } else { 1.0 },
                if picked { theme::accent(ui) } else { ink },
            );
            painter.rect(
                r,
                4.0,
                ui.visuals().extreme_bg_color,
                stroke,
                egui::StrokeKind::Inside,
            );
            painter.text(
                r.left_center() + vec2(8.0, 0.0),
                egui::Align2::LEFT_CENTER,
                *name,
                egui::FontId::proportional(theme::TITLE_SIZE),
                ink,
            );
            let route = routes.get(s).copied().unwrap_or(Route::Unused);
            painter.text(
                r.right_center() - vec2(6.0, 0.0),
                egui::Align2::RIGHT_CENTER,
                route.name(),
                egui::FontId::proportional(theme::SMALL_SIZE),
                route_color(ui, route),
            );
        }
    }

    /// The functions; a click wires the picked sensor to one, or unwires it.
    fn function_boxes(
        &mut self,
        ui: &egui::Ui,
        painter: &egui::Painter,
        right: &dyn Fn(usize) -> Rect,
        mut wiring: Wiring,
    ) {
        let ink = ui.visuals().text_color();
        for (f, name) in FUNCTIONS.iter().enumerate() {
            let r = right(f);
            let response = ui.interact(r, ui.scope_id().with(("function", f)), Sense::click());
            if response.clicked()
                && let Some(s) = self.picked
            {
                wiring.feeds[s][f] = !wiring.feeds[s][f];
                self.settings.wiring = Some(Rows(wiring));
                self.feedback = None;
            }
            let fill = if f == MODEL {
                theme::accent(ui).gamma_multiply(0.15)
            } else {
                ui.visuals().extreme_bg_color
            };
            painter.rect(
                r,
                4.0,
                fill,
                Stroke::new(1.0, ink),
                egui::StrokeKind::Inside,
            );
            let label = if f == MODEL {
                "world model → planner"
            } else {
                name
            };
            painter.text(
                r.left_center() + vec2(8.0, 0.0),
                egui::Align2::LEFT_CENTER,
                label,
                egui::FontId::proportional(theme::TITLE_SIZE),
                ink,
            );
        }
    }
}

/// What the wiring amounts to, in a sentence.
fn verdict(paradigm: Option<Architecture>) -> &'static str {
    match paradigm {
        None => "Nothing is wired yet.",
        Some(Architecture::Reactive) => {
            "Reactive: every sensor goes straight to behaviours (local routes); there is no world model."
        }
        Some(Architecture::Hierarchical) => {
            "Hierarchical: every sensor is fused into the world model (global routes); nothing reaches a behaviour directly."
        }
        Some(Architecture::Hybrid) => {
            "Hybrid: behaviours read sensors directly and a cartographer also fuses sensors into a world model for the planner."
        }
    }
}

impl LabWidget for SensingRoutes {
    /// Each sensor's route, the wires, and what the wiring amounts to.
    fn describe(&self) -> Option<String> {
        let wiring = self.wiring();
        let report = wiring.report();
        let wires = wiring.feeds.iter().flatten().filter(|f| **f).count();
        let routes: Vec<String> = SENSORS
            .iter()
            .zip(&report.routes)
            .map(|(sensor, route)| format!("{sensor} {}", route.name()))
            .collect();
        Some(format!(
            "{wires} wire{}; routes: {}. {}",
            if wires == 1 { "" } else { "s" },
            routes.join(", "),
            verdict(report.paradigm)
        ))
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.label("Start from:");
            for (name, preset) in [
                ("hierarchical", Preset::Hierarchical),
                ("reactive", Preset::Reactive),
                ("hybrid", Preset::Hybrid),
                ("Clear", Preset::Empty),
            ] {
                if ui.button(name).clicked() {
                    self.settings.preset = preset;
                    self.settings.wiring = None;
                    self.feedback = None;
                }
            }
        });
        ui.horizontal_wrapped(|ui| {
            ui.label(
                RichText::new("Click a sensor, then a function, to add or remove a wire. Routes:")
                    .small(),
            );
            for route in [Route::Local, Route::Global, Route::Hybrid] {
                ui.label(
                    RichText::new(route.name())
                        .small()
                        .color(route_color(ui, route)),
                );
            }
        });
        let rect = self.diagram(ui);
        let report = self.wiring().report();
        ui.label(RichText::new(verdict(report.paradigm)).strong());
        export::bar(
            ui,
            ui.scope_id().with("routes-exports"),
            &[Export::Png {
                file: "kinolab-sensing-routes.png",
                rect,
            }],
        );
        if self.settings.task == Some(Task::WireHybrid) {
            ui.separator();
            ui.label(RichText::new("Task: wire a hybrid robot that uses every sensor.").strong());
            if ui.button("Check").clicked() {
                self.feedback = Some(wire_hybrid(&self.wiring()));
            }
            feedback_ui(ui, self.feedback.as_ref());
        }
    }

    fn state(&self) -> Option<String> {
        link::write(
            NAME,
            &self.settings,
            &self.initial,
            &Moment::<()>::default(),
        )
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if link::is_bare(state) {
            return Err("it is empty (cut short)".into());
        }
        let settings = match link::read::<Settings, ()>(NAME, state) {
            Ok((settings, _)) => settings,
            // The first format: the wiring alone.
            Err(why) => match link::decode::<Wiring>(state) {
                Some(old) => Settings {
                    wiring: Some(Rows(old)),
                    ..self.initial.clone()
                },
                None => return Err(why),
            },
        };
        link::check(NAME, &settings)?;
        self.settings = settings;
        self.picked = None;
        self.feedback = None;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::spec;

    fn widget(params: &[(&str, &str)]) -> SensingRoutes {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        let settings: Settings = p.settings().unwrap_or_else(|e| panic!("{e}"));
        SensingRoutes {
            initial: settings.clone(),
            settings,
            picked: None,
            feedback: None,
        }
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        let hybrid = Wiring::preset(Architecture::Hybrid);
        let old = link::encode(&hybrid.feeds).unwrap_or_default();
        let mut w = widget(&[("task", "wire-hybrid")]);
        assert_eq!(w.restore(&old), Ok(()));
        assert_eq!(w.wiring(), hybrid);
        assert_eq!(
            w.settings.task,
            Some(Task::WireHybrid),
            "the lesson's task kept"
        );
        // Not a wiring: refused, the lesson's settings kept.
        let mut w = widget(&[("preset", "reactive")]);
        assert!(
            w.restore(&link::encode(&[7_u8; 30]).unwrap_or_default())
                .is_err()
        );
        assert_eq!(w.wiring(), Wiring::preset(Architecture::Reactive));
    }

    #[test]
    fn the_learners_wiring_travels_in_the_link() {
        let mut w = widget(&[]);
        let mut wiring = Wiring::preset(Architecture::Reactive);
        wiring.feeds[5][MODEL] = true;
        w.settings.wiring = Some(Rows(wiring));
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[("preset", "hybrid")]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.wiring(), wiring);
        assert_eq!(again.settings.preset, Preset::Empty);
        let rows = String::from(Rows(wiring));
        assert_eq!(Rows::try_from(rows.clone()), Ok(Rows(wiring)), "{rows}");
    }
}
