//! One Denavit–Hartenberg link, built motion by motion: frame i−1, the
//! frames after each of the four elementary motions, frame i, and the 4×4
//! matrix. With a target row, a dashed frame shows where frame i must land
//! and the core checks the learner's row by comparing transforms.

use egui::{Painter, Rect, RichText, Sense, Stroke, vec2};
use kinolab_common::Feedback;
use kinolab_common::display::{fixed, signed};
use kinolab_mechanism::dh::{Convention, link, steps};
use kinolab_mechanism::exercise::Task;
use kinolab_mechanism::{Pose, Vector3};
use serde::{Deserialize, Serialize};

use crate::draw::canvas;
use crate::draw::labels::Labels;
use crate::draw::scene3d::{Camera, ViewKind, draw_frame, draw_grid};
use crate::export::{self, Export};
use crate::link::{self as state_link, Moment};
use crate::theme;
use crate::widget::{LabWidget, Params, feedback_ui};

/// The widget's name in the schema.
const NAME: &str = "dh-link";

/// What the lesson sets and a link carries: the schema's parameters. The
/// rows are `a` (m), `α` (°), `d` (m), `θ` (°).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
struct Settings {
    convention: Dh,
    row: [f64; 4],
    target: Option<[f64; 4]>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum Dh {
    Standard,
    Modified,
}

impl Dh {
    fn convention(self) -> Convention {
        match self {
            Dh::Standard => Convention::StandardDh,
            Dh::Modified => Convention::ModifiedDh,
        }
    }
}

/// The slider spans: a and d in metres, the angles in degrees.
const SPANS: [(&str, f64, &str); 4] = [
    ("a", 1.0, " m"),
    ("α", 180.0, "°"),
    ("d", 1.0, " m"),
    ("θ", 180.0, "°"),
];

struct DhLink {
    convention: Convention,
    settings: Settings,
    initial: Settings,
    camera: Camera,
    task: Option<Task>,
    feedback: Option<Feedback>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    Ok(Box::new(DhLink::new(settings)))
}

const NAMES_STANDARD: [&str; 4] = ["Rz(θ)", "Tz(d)", "Tx(a)", "Rx(α)"];
const NAMES_MODIFIED: [&str; 4] = ["Rx(α)", "Tx(a)", "Rz(θ)", "Tz(d)"];

impl DhLink {
    fn new(settings: Settings) -> Self {
        let mut w = DhLink {
            convention: settings.convention.convention(),
            settings,
            initial: settings,
            camera: Camera::new(ViewKind::Orbit, [0.3, 0.0, 0.2], 0.8),
            task: None,
            feedback: None,
        };
        w.apply(settings);
        w
    }

    /// Take `settings`: the row, the convention and the exercise's target.
    fn apply(&mut self, settings: Settings) {
        self.convention = settings.convention.convention();
        let convention = self.convention;
        self.task = settings.target.map(|[a, alpha, d, theta]| Task::DhRow {
            convention,
            target: [a, alpha.to_radians(), d, theta.to_radians()],
        });
        self.settings = settings;
        self.feedback = None;
    }

    fn radians(&self) -> [f64; 4] {
        [
            self.settings.row[0],
            self.settings.row[1].to_radians(),
            self.settings.row[2],
            self.settings.row[3].to_radians(),
        ]
    }

    /// The convention's formula, the view buttons and the four sliders.
    /// Frame i seen from frame i−1: the link's transform.
    fn frame_i(&self) -> Pose {
        let [a, alpha, d, theta] = self.radians();
        link(self.convention, a, alpha, d, theta)
    }

    /// The convention, the four parameters, and where frame i lands.
    fn description(&self) -> String {
        let convention = match self.convention {
            Convention::StandardDh => "Standard",
            Convention::ModifiedDh => "Modified",
        };
        let row: Vec<String> = SPANS
            .iter()
            .zip(self.settings.row)
            .enumerate()
            .map(|(k, ((name, _, unit), value))| {
                format!(
                    "{name} = {}{unit}",
                    fixed(value, if k % 2 == 1 { 0 } else { 2 })
                )
            })
            .collect();
        let o = self.frame_i().translation.vector;
        format!(
            "{convention} DH: {}. Frame i's origin is at ({}, {}, {}) m in frame i−1.",
            row.join(", "),
            fixed(o.x, 3),
            fixed(o.y, 3),
            fixed(o.z, 3)
        )
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.label(match self.convention {
                Convention::StandardDh => {
                    "standard DH: frame i = frame i−1 · Rz(θ) · Tz(d) · Tx(a) · Rx(α)"
                }
                Convention::ModifiedDh => {
                    "modified DH: frame i = frame i−1 · Rx(α) · Tx(a) · Rz(θ) · Tz(d)"
                }
            });
            self.camera.buttons(ui);
        });
        let mut changed = false;
        egui::Grid::new(ui.scope_id().with("dh"))
            .num_columns(2)
            .show(ui, |ui| {
                for (k, (label, span, unit)) in SPANS.into_iter().enumerate() {
                    let name = ui.label(label);
                    let angle = k % 2 == 1;
                    let slider = egui::Slider::new(&mut self.settings.row[k], -span..=span)
                        .suffix(unit)
                        .fixed_decimals(if angle { 0 } else { 2 })
                        .step_by(if angle { 1.0 } else { 0.01 });
                    changed |= ui.add(slider).labelled_by(name.id).changed();
                    ui.end_row();
                }
            });
        if changed {
            self.feedback = None;
        }
    }

    /// Frame i−1, the intermediate frames, the target and frame i.
    fn scene(&self, ui: &egui::Ui, painter: &Painter, rect: Rect) -> Pose {
        let ink = ui.visuals().text_color();
        let [a, alpha, d, theta] = self.radians();
        let names = match self.convention {
            Convention::StandardDh => NAMES_STANDARD,
            Convention::ModifiedDh => NAMES_MODIFIED,
        };
        draw_grid(painter, &self.camera, rect, ink.gamma_multiply(0.08));
        let mut labels = Labels::default();
        let base = draw_frame(
            painter,
            &self.camera,
            rect,
            &Pose::identity(),
            0.25,
            1.0,
            2.5,
        );
        labels.avoid_lines(&base);
        let origin = self.camera.project(rect, &Vector3::zeros()).0;
        labels.add(origin, "i−1", ink);
        // The path through the intermediate frames.
        let mut at = Pose::identity();
        for (k, step) in steps(self.convention, a, alpha, d, theta)
            .iter()
            .enumerate()
        {
            let before = at.translation.vector;
            at *= step;
            let (p0, _) = self.camera.project(rect, &before);
            let (p1, _) = self.camera.project(rect, &at.translation.vector);
            painter.line_segment([p0, p1], Stroke::new(1.5, ink.gamma_multiply(0.5)));
            labels.avoid_line(p0, p1);
            if k < 3 {
                let axes = draw_frame(painter, &self.camera, rect, &at, 0.12, 0.35, 1.0);
                labels.avoid_lines(&axes);
                labels.add(p1, format!("after {}", names[k]), ink.gamma_multiply(0.5));
            }
        }
        if let Some(Task::DhRow { convention, target }) = &self.task {
            let goal = link(*convention, target[0], target[1], target[2], target[3]);
            self.dashed_frame(painter, rect, &goal);
            let at = self.camera.project(rect, &goal.translation.vector).0;
            labels.add(at, "target", ink.gamma_multiply(0.7));
        }
        let frame_i = self.frame_i();
        let axes = draw_frame(painter, &self.camera, rect, &frame_i, 0.25, 1.0, 3.0);
        labels.avoid_lines(&axes);
        labels.add(
            self.camera.project(rect, &frame_i.translation.vector).0,
            "i",
            ink,
        );
        labels.draw(painter, &egui::FontId::proportional(theme::LABEL_SIZE));
        frame_i
    }

    fn dashed_frame(&self, painter: &Painter, rect: Rect, pose: &Pose) {
        let (o, _) = self.camera.project(rect, &pose.translation.vector);
        for (k, color) in theme::AXIS_COLORS.iter().enumerate() {
            let mut axis = Vector3::zeros();
            axis[k] = 0.25;
            let (tip, _) = self
                .camera
                .project(rect, &(pose.rotation * axis + pose.translation.vector));
            painter.extend(egui::Shape::dashed_line(
                &[o, tip],
                Stroke::new(2.0, color.gamma_multiply(0.7)),
                5.0,
                4.0,
            ));
        }
    }

    fn exercise(&mut self, ui: &mut egui::Ui) {
        let radians = self.radians();
        let Some(task) = &self.task else { return };
        let feedback = &mut self.feedback;
        ui.group(|ui| {
            ui.label(RichText::new(format!("Exercise: {}", task.describe())).strong());
            if ui.button("Check").clicked() {
                *feedback = Some(Feedback::from(task.check_row(radians)));
            }
            feedback_ui(ui, feedback.as_ref());
        });
    }
}

/// A 4×4 matrix, three decimals, never "−0.000".
fn matrix(ui: &mut egui::Ui, h: &kinolab_mechanism::Matrix4<f64>) {
    egui::Grid::new(ui.scope_id().with("m"))
        .spacing(vec2(10.0, 2.0))
        .show(ui, |ui| {
            for r in 0..4 {
                for c in 0..4 {
                    ui.label(RichText::new(signed(h[(r, c)], 3)).monospace());
                }
                ui.end_row();
            }
        });
}

impl LabWidget for DhLink {
    fn describe(&self) -> Option<String> {
        Some(self.description())
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        let size = vec2(ui.available_width().min(720.0), 300.0);
        let (response, painter) = canvas(ui, size, Sense::click_and_drag());
        let rect = response.rect;
        self.camera.handle(ui, &response, true);
        let frame_i = self.scene(ui, &painter, rect);
        painter.text(
            rect.left_bottom() + vec2(8.0, -8.0),
            egui::Align2::LEFT_BOTTOM,
            "x red, y green, z blue · drag to turn the view",
            egui::FontId::proportional(theme::LABEL_SIZE),
            ui.visuals().weak_text_color(),
        );
        export::bar(
            ui,
            ui.scope_id().with("dh-link-exports"),
            &[Export::Png {
                file: "kinolab-dh-link.png",
                rect,
            }],
        );
        ui.label("The link's transform, frame i seen from frame i−1:");
        matrix(ui, &frame_i.to_homogeneous());
        self.exercise(ui);
    }

    fn state(&self) -> Option<String> {
        state_link::write(
            NAME,
            &self.settings,
            &self.initial,
            &Moment::<()>::default(),
        )
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let settings = match state_link::read::<Settings, ()>(NAME, state) {
            Ok((settings, _)) => settings,
            Err(why) => match state_link::decode::<[f64; 4]>(state) {
                // The first format: the row alone.
                Some(row) => Settings {
                    row,
                    ..self.initial
                },
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema's ranges too.
        state_link::check(NAME, &settings)?;
        self.apply(settings);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::{create, spec};

    fn widget(params: &[(&str, &str)]) -> DhLink {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        DhLink::new(p.settings().unwrap_or_else(|e| panic!("{e}")))
    }

    #[test]
    fn rows_round_trip_through_links() {
        let params = [("row", "0.5, 90, 0.2, 30"), ("convention", "modified")];
        let mut w = widget(&params);
        assert_eq!(w.state(), None, "as the lesson set it up");
        w.settings.row = [0.1, -90.0, 0.0, 45.0];
        let state = w.state().unwrap_or_default();
        let mut again = widget(&params);
        assert_eq!(again.restore(&state), Ok(()));
        assert_eq!(again.settings, w.settings);
        // A link carries the convention and the exercise too.
        let mut other = widget(&[]);
        assert_eq!(other.restore(&state), Ok(()));
        assert_eq!(other.convention, Convention::ModifiedDh);
        assert!(create(&spec("dh-link", &[("row", "1, 2, 3")])).is_err());
        assert!(create(&spec("dh-link", &[("convention", "craig")])).is_err());
    }

    #[test]
    fn the_description_holds_the_row_and_where_frame_i_lands() {
        let mut w = widget(&[("row", "0.5, 90, 0.2, 30")]);
        let says = |w: &DhLink| {
            let words = w.describe().unwrap_or_default();
            let [a, alpha, d, theta] = w.radians();
            let o = link(w.convention, a, alpha, d, theta).translation.vector;
            let at = format!(
                "({}, {}, {}) m",
                fixed(o.x, 3),
                fixed(o.y, 3),
                fixed(o.z, 3)
            );
            assert!(words.contains(&at), "{at} missing from: {words}");
            words
        };
        let first = says(&w);
        for part in [
            "Standard DH",
            "a = 0.50 m",
            "α = 90°",
            "d = 0.20 m",
            "θ = 30°",
        ] {
            assert!(first.contains(part), "{part} missing from: {first}");
        }
        w.settings.row[3] = -45.0;
        let turned = says(&w);
        assert!(turned.contains("θ = -45°"), "{turned}");
        assert_ne!(turned, first);
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        let old = state_link::encode(&[0.1_f64, -90.0, 0.0, 45.0]).unwrap_or_default();
        let mut w = widget(&[("convention", "modified")]);
        assert_eq!(w.restore(&old), Ok(()));
        assert_eq!(w.settings.row, [0.1, -90.0, 0.0, 45.0]);
        assert_eq!(w.settings.convention, Dh::Modified);
        // Out of the schema's range: refused, the lesson's row kept.
        let bad = state_link::encode(&[9.0_f64, 0.0, 0.0, 0.0]).unwrap_or_default();
        let mut w = widget(&[("row", "0.5, 90, 0.2, 30")]);
        assert!(w.restore(&bad).is_err());
        assert_eq!(w.settings.row, [0.5, 90.0, 0.2, 30.0]);
    }
}
