//! The mechanism viewer: any catalogue mechanism (or a loaded model file)
//! in 3D, from above or from the side. A slider per joint the learner
//! drives; followers and loop joints move by themselves. Drag the target
//! and inverse kinematics follows; bounding shapes light up where they
//! collide; the model tree lists mechanisms, bodies and joints.
//!
//! - this file: the state (the model stays apart from the joint values),
//!   the constructor, the toolbar and the link;
//! - [`canvas`]: the drawing and the draggable target;
//! - [`panels`]: joint sliders, read-outs, the tree, the file, the exercise;
//! - [`bounds`]: how much of the scene to show.

mod bounds;
mod canvas;
#[cfg(test)]
mod opening_tests;
mod panels;

use kinolab_common::Feedback;
use kinolab_mechanism::exercise::Task;
use kinolab_mechanism::{FrameRef, JointKind, Model, Obstacle, Vector3, catalogue, file, urdf};
use serde::{Deserialize, Serialize};

use crate::draw::scene3d::{Camera, ViewKind};
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::open;
use crate::widget::{LabWidget, Params};

/// The widget's name in the schema.
const NAME: &str = "mechanism-viewer";

/// What the lesson sets and a link carries: the schema's parameters (the
/// joint values, the view and the switches as the learner leaves them).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    model: String,
    view: Option<String>,
    /// The driven joints, as people write them (degrees or metres).
    q: Option<Vec<f64>>,
    frames: bool,
    shapes: bool,
    obstacles: Option<Vec<[f64; 3]>>,
    drag: bool,
    tree: bool,
    task: Option<TaskKind>,
    target: Option<Vec<f64>>,
    tolerance: f64,
    sets: Option<Vec<Vec<f64>>>,
    /// The configurations marked singular, by number from 1.
    marked: Option<Vec<f64>>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum TaskKind {
    Reach,
    SpotSingular,
}

/// The frame a learner moves, by model: the first one the model has, else
/// its hand ([`Model::hand`]). `tool0` and `flange` are the tool frames
/// that ROS-Industrial's arms name.
const END_FRAMES: [&str; 7] = [
    "tool",
    "tool0",
    "flange",
    "arm/gripper",
    "left-front/foot",
    "coupler-point",
    "left-front-wheel",
];

struct Exercise {
    task: Task,
    marks: Vec<bool>,
    feedback: Option<Feedback>,
}

struct Viewer {
    model: Model,
    /// A mechanism that moves in the x–y plane: targets stay in it.
    flat: bool,
    /// Every joint variable (followers and loop joints included).
    q: Vec<f64>,
    initial_q: Vec<f64>,
    /// The variables the learner sets.
    driven: Vec<usize>,
    camera: Camera,
    initial_kind: ViewKind,
    frames: bool,
    shapes: bool,
    drag: bool,
    tree: bool,
    obstacles: Vec<Obstacle>,
    end: Option<(String, FrameRef)>,
    /// Where the dragged target is, while the learner drags it.
    target: Option<Vector3<f64>>,
    ik_note: Option<String>,
    closure_note: Option<String>,
    selected: Option<usize>,
    exercise: Option<Exercise>,
    file_text: String,
    file_note: Option<String>,
    /// The settings the viewer opened with (`initial_q` and
    /// `initial_kind` are their joints and camera), and what the lesson
    /// set up; both `None` once a model file is loaded.
    initial: Option<Settings>,
    lesson: Option<Settings>,
}

fn planar(id: &str) -> bool {
    matches!(id, "planar-2r" | "planar-3r" | "four-bar")
}

/// A joint value as people write it: degrees for turning joints.
fn to_shown(model: &Model, v: usize, value: f64) -> f64 {
    match model.variable_joint(v).map(|j| j.kind) {
        Some(JointKind::Prismatic) => value,
        _ => value.to_degrees(),
    }
}

fn from_shown(model: &Model, v: usize, value: f64) -> f64 {
    match model.variable_joint(v).map(|j| j.kind) {
        Some(JointKind::Prismatic) => value,
        _ => value.to_radians(),
    }
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    Ok(Box::new(Viewer::from_settings(p.settings()?)?))
}

/// The camera a model opens with when the lesson names none.
fn default_view(id: &str) -> ViewKind {
    match id {
        _ if planar(id) => ViewKind::Plan,
        "rocker-bogie" => ViewKind::Side,
        _ => ViewKind::Orbit,
    }
}

impl Viewer {
    /// The viewer `settings` set up.
    fn from_settings(settings: Settings) -> Result<Self, String> {
        let id = settings.model.as_str();
        let model =
            catalogue::mechanism(id).map_err(|e| format!("parameter `model`: {}", e.message))?;
        let kind = match settings.view.as_deref() {
            Some(v) => ViewKind::parse(v).unwrap_or(ViewKind::Orbit),
            None => default_view(id),
        };
        let mut viewer = Viewer::new(model, kind);
        viewer.flat = planar(id);
        if viewer.flat {
            let (centre, extent) = bounds::bounds(&viewer.model, &viewer.q, true);
            viewer.camera = Camera::new(kind, centre, extent);
        }
        if let Some(values) = &settings.q {
            viewer
                .set_driven(values)
                .map_err(|e| format!("parameter `q`: {e}"))?;
        }
        viewer.initial_q = viewer.q.clone();
        viewer.frames = settings.frames;
        viewer.shapes = settings.shapes;
        viewer.drag = settings.drag;
        viewer.tree = settings.tree;
        viewer.obstacles = settings
            .obstacles
            .iter()
            .flatten()
            .map(|[x, y, r]| Obstacle::Circle {
                center: [*x, *y],
                radius: r.abs(),
            })
            .collect();
        viewer.exercise = viewer.exercise_from(&settings)?;
        viewer.initial = Some(settings.clone());
        viewer.lesson = Some(settings);
        Ok(viewer)
    }

    /// The settings as the learner has them now; `None` for a model loaded
    /// from a file (a link cannot carry it).
    fn settings(&self) -> Option<Settings> {
        let mut s = self.initial.clone()?;
        if self.camera.kind != self.initial_kind {
            s.view = Some(self.camera.kind.key().to_owned());
        }
        if self.q != self.initial_q {
            s.q = Some(
                self.driven
                    .iter()
                    .map(|&v| to_shown(&self.model, v, self.q[v]))
                    .collect(),
            );
        }
        (s.frames, s.shapes, s.drag, s.tree) = (self.frames, self.shapes, self.drag, self.tree);
        if let Some(ex) = &self.exercise
            && matches!(ex.task, Task::SpotSingular { .. })
        {
            let marked: Vec<f64> = (1..=ex.marks.len())
                .zip(&ex.marks)
                .filter(|(_, m)| **m)
                .map(|(n, _)| n as f64)
                .collect();
            s.marked = (!marked.is_empty()).then_some(marked);
        }
        Some(s)
    }
}

impl Viewer {
    fn new(model: Model, kind: ViewKind) -> Self {
        let mut q = model.zero_state();
        let closure = model.close_loops(&mut q).ok();
        let driven: Vec<usize> = (0..model.dof()).filter(|&v| model.is_driven(v)).collect();
        let end = END_FRAMES
            .iter()
            .copied()
            .chain([model.hand()])
            .find_map(|n| model.frame(n).ok().map(|f| (n.to_string(), f)));
        let (centre, extent) = bounds::bounds(&model, &q, false);
        Self {
            camera: Camera::new(kind, centre, extent),
            initial_kind: kind,
            q: q.clone(),
            initial_q: q,
            driven,
            frames: true,
            shapes: false,
            drag: true,
            tree: false,
            obstacles: Vec::new(),
            end,
            target: None,
            ik_note: None,
            closure_note: closure
                .filter(|c| !c.closed)
                .map(|c| format!("The loop stays open by {:.1} mm.", c.gap * 1000.0)),
            selected: None,
            exercise: None,
            file_text: String::new(),
            file_note: None,
            flat: false,
            initial: None,
            lesson: None,
            model,
        }
    }

    /// The exercise a lesson set up, if any.
    fn exercise_from(&self, settings: &Settings) -> Result<Option<Exercise>, String> {
        let frame = self
            .end
            .as_ref()
            .map_or_else(|| "tool".to_owned(), |(n, _)| n.clone());
        let task = match settings.task {
            Some(TaskKind::Reach) => {
                let t = settings.target.clone().unwrap_or_default();
                let at = |k: usize| t.get(k).copied().unwrap_or(0.0);
                Task::Reach {
                    frame,
                    target: Vector3::new(at(0), at(1), at(2)),
                    tolerance: settings.tolerance,
                }
            }
            Some(TaskKind::SpotSingular) => {
                let mut sets = Vec::new();
                for values in settings.sets.iter().flatten() {
                    let mut probe = Viewer::new(self.model.clone(), self.camera.kind);
                    probe
                        .set_driven(values)
                        .map_err(|e| format!("parameter `sets`: {e}"))?;
                    sets.push(probe.q);
                }
                Task::SpotSingular { frame, sets }
            }
            None => return Ok(None),
        };
        let marks = match &task {
            Task::SpotSingular { sets, .. } => {
                let marked = settings.marked.clone().unwrap_or_default();
                (1..=sets.len())
                    .map(|n| marked.contains(&(n as f64)))
                    .collect()
            }
            _ => Vec::new(),
        };
        Ok(Some(Exercise {
            task,
            marks,
            feedback: None,
        }))
    }

    /// Set the driven joints from values as people write them.
    fn set_driven(&mut self, values: &[f64]) -> Result<(), String> {
        if values.len() != self.driven.len() {
            return Err(format!(
                "{} takes {} values (one per joint you drive), found {}.",
                self.model.name(),
                self.driven.len(),
                values.len()
            ));
        }
        for (&v, &value) in self.driven.iter().zip(values) {
            self.q[v] = from_shown(&self.model, v, value);
        }
        self.model.clamp(&mut self.q);
        self.settle();
        Ok(())
    }

    /// Apply couplings and close loops after the driven joints changed.
    fn settle(&mut self) {
        let before = self.q.clone();
        self.closure_note = match self.model.close_loops(&mut self.q) {
            Ok(c) if c.closed => None,
            Ok(c) => {
                // Keep the last closed configuration rather than a broken one.
                self.q = before;
                Some(format!(
                    "The linkage cannot close there (gap {:.1} mm); it stays where it was.",
                    c.gap * 1000.0
                ))
            }
            Err(e) => Some(e.to_string()),
        };
        if let Some(ex) = &mut self.exercise {
            ex.feedback = None;
        }
    }

    /// Open a model file's text (JSON or URDF) in place of the model
    /// shown. The note says what
    /// happened, and what the file had that the lab leaves out.
    fn open_file(&mut self, name: &str, text: &str) {
        let opened = if urdf::looks_like_xml(text) {
            urdf::read(text).map(|r| (r.notices, r.model))
        } else {
            file::from_json(text).map(|m| (Vec::new(), m))
        };
        match opened {
            Ok((notices, model)) => {
                let title = model.name().to_owned();
                self.replace_model(model);
                let mut note = format!("Opened {title} from {name}.");
                for n in notices {
                    note.push_str(&format!(" Note: {n}."));
                }
                self.file_note = Some(note);
            }
            Err(e) => self.file_note = Some(format!("{name} was not opened: {e}")),
        }
    }

    fn replace_model(&mut self, model: Model) {
        let kind = self.camera.kind;
        let keep = (self.frames, self.shapes, self.drag, self.tree);
        *self = Viewer::new(model, kind);
        // A loaded model (which no link can carry: `initial` stays empty) is flat if nothing in it leaves the x–y plane.
        self.flat = self
            .model
            .joints()
            .iter()
            .all(|j| j.axis.z.abs() > 1.0 - 1e-12 || !j.kind.moves());
        (self.frames, self.shapes, self.drag, self.tree) = keep;
    }

    fn toolbar(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.label("view:");
            for kind in [ViewKind::Orbit, ViewKind::Plan, ViewKind::Side] {
                if crate::widget::choice(ui, self.camera.kind == kind, kind.label()).clicked() {
                    self.camera = Camera::new(kind, self.camera.centre, self.camera.extent);
                }
            }
            self.camera.buttons(ui);
            ui.separator();
            ui.checkbox(&mut self.frames, "frames");
            ui.checkbox(&mut self.shapes, "shapes");
            let reach_task = self
                .exercise
                .as_ref()
                .is_some_and(|e| matches!(e.task, Task::Reach { .. }));
            if !reach_task && self.end.is_some() {
                ui.checkbox(&mut self.drag, "drag target");
            }
            if ui.button("home").clicked() {
                self.q = self.initial_q.clone();
                self.target = None;
                self.ik_note = None;
            }
        });
    }
}

/// Over the drawing while a file is dragged over the page: where it goes.
fn drop_hint(ui: &egui::Ui, rect: egui::Rect) {
    let painter = ui.painter_at(rect);
    let visuals = ui.visuals();
    painter.rect_filled(rect, 4.0, visuals.extreme_bg_color.gamma_multiply(0.85));
    painter.text(
        rect.center(),
        egui::Align2::CENTER_CENTER,
        "Drop a URDF or a model file to open it",
        egui::FontId::proportional(18.0),
        visuals.strong_text_color(),
    );
}

/// The view and the driven joints' values, as the first format of links
/// carried them.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct LinkState {
    view: u8,
    driven: Vec<f64>,
}

const VIEWS: [ViewKind; 3] = [ViewKind::Orbit, ViewKind::Plan, ViewKind::Side];

impl LabWidget for Viewer {
    fn describe(&self) -> Option<String> {
        Some(self.description())
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        if let Some(file) = open::take_dropped(ui.ctx()) {
            self.open_file(&file.name, &file.text());
        }
        self.toolbar(ui);
        let drawing = self.canvas(ui);
        if open::files_hovering(ui.ctx()) {
            drop_hint(ui, drawing);
        }
        export::bar(
            ui,
            ui.scope_id().with("mechanism-exports"),
            &[Export::Png {
                file: "kinolab-mechanism.png",
                rect: drawing,
            }],
        );
        self.readout(ui);
        self.sliders(ui);
        self.exercise_ui(ui);
        self.tree_ui(ui);
        self.file_ui(ui);
    }

    fn state(&self) -> Option<String> {
        let (now, initial) = (self.settings()?, self.lesson.as_ref()?);
        link::write(NAME, &now, initial, &Moment::<()>::default())
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let lesson = self
            .lesson
            .clone()
            .ok_or("a model loaded from a file takes no link")?;
        let settings = match link::read::<Settings, ()>(NAME, state) {
            Ok((settings, _)) => settings,
            Err(why) => match link::decode::<LinkState>(state) {
                Some(old) => Settings {
                    view: VIEWS.get(usize::from(old.view)).map(|k| k.key().to_owned()),
                    q: Some(old.driven),
                    ..lesson.clone()
                },
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema's ranges too.
        link::check(NAME, &settings)?;
        let mut viewer = Viewer::from_settings(settings.clone())?;
        if settings.model == lesson.model {
            // Home is still where the lesson started.
            let home = Viewer::from_settings(lesson.clone())?;
            (viewer.initial_q, viewer.initial_kind) = (home.initial_q, home.initial_kind);
            viewer.initial = Some(Settings {
                q: lesson.q.clone(),
                view: lesson.view.clone(),
                ..settings
            });
        }
        viewer.lesson = Some(lesson);
        *self = viewer;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::create as build;

    fn spec(params: &[(&str, &str)]) -> kinolab_lessons::WidgetSpec {
        crate::registry::spec("mechanism-viewer", params)
    }

    #[test]
    fn every_catalogue_mechanism_opens() {
        for (id, _, _) in catalogue::CATALOGUE {
            assert!(build(&spec(&[("model", id)])).is_ok(), "{id}");
        }
    }

    #[test]
    fn joint_values_and_links_round_trip() {
        let Ok(mut w) = build(&spec(&[("model", "planar-2r"), ("q", "30, 45")])) else {
            panic!("valid joint values")
        };
        assert_eq!(w.state(), None);
        let side = link::encode(&LinkState {
            view: 2,
            driven: vec![10.0, -20.0],
        })
        .unwrap_or_default();
        assert_eq!(w.restore(&side), Ok(()));
        let state = w.state().unwrap_or_default();
        let Ok((back, _)) = link::read::<Settings, ()>(NAME, &state) else {
            panic!("a changed viewer goes into the link")
        };
        assert_eq!(back.view.as_deref(), Some("side"));
        let q = back.q.unwrap_or_default();
        assert!((q[0] - 10.0).abs() < 1e-9 && (q[1] + 20.0).abs() < 1e-9);
        // Out of the schema's range: refused, the lesson's values kept.
        let bad = link::encode(&LinkState {
            view: 0,
            driven: vec![1e9, 0.0],
        })
        .unwrap_or_default();
        let Ok(mut w) = build(&spec(&[("q", "30, 45")])) else {
            panic!()
        };
        assert!(w.restore(&bad).is_err());
        assert_eq!(w.state(), None);
    }

    #[test]
    fn the_view_switches_and_marks_travel_in_the_link() {
        let params = [
            ("model", "planar-2r"),
            ("task", "spot-singular"),
            ("sets", "0, 0; 30, 90; 10, 180"),
        ];
        let Ok(p) = kinolab_schema::validate(&spec(&params)) else {
            panic!()
        };
        let Ok(mut w) = p.settings().and_then(Viewer::from_settings) else {
            panic!()
        };
        w.shapes = true;
        if let Some(ex) = &mut w.exercise {
            ex.marks[2] = true;
        }
        w.camera = Camera::new(ViewKind::Orbit, w.camera.centre, w.camera.extent);
        let text = w.state().unwrap_or_default();
        let Ok(mut again) = p.settings().and_then(Viewer::from_settings) else {
            panic!()
        };
        assert_eq!(again.restore(&text), Ok(()));
        assert!(again.shapes);
        assert_eq!(again.camera.kind, ViewKind::Orbit);
        assert_eq!(
            again.exercise.map(|e| e.marks),
            Some(vec![false, false, true])
        );
    }

    #[test]
    fn bad_parameters_say_what_is_wrong() {
        let message = |p: &[(&str, &str)]| match build(&spec(p)) {
            Err(e) => e,
            Ok(_) => panic!("accepted {p:?}"),
        };
        assert!(message(&[("model", "warp-drive")]).contains("must be one of planar-2r"));
        assert!(message(&[("q", "1, 2, 3")]).contains("`q` needs 2 values"));
        assert!(message(&[("view", "sideways")]).contains("3d, plan, side"));
        assert!(message(&[("task", "reach")]).contains("needs `target"));
        assert!(message(&[("obstacles", "1, 2")]).contains("groups separated by `;`"));
    }

    #[test]
    fn the_four_bar_and_rocker_bogie_show_only_driven_joints() {
        let rover = Viewer::new(
            catalogue::mechanism("rocker-bogie").unwrap_or_else(|e| panic!("{e}")),
            ViewKind::Side,
        );
        assert_eq!(rover.driven.len(), 3);
        let mut linkage = Viewer::new(
            catalogue::mechanism("four-bar").unwrap_or_else(|e| panic!("{e}")),
            ViewKind::Plan,
        );
        assert_eq!(linkage.driven.len(), 1);
        linkage
            .set_driven(&[120.0])
            .unwrap_or_else(|e| panic!("{e}"));
        assert!(linkage.closure_note.is_none());
        assert!(linkage.model.closure(&linkage.q).is_ok_and(|c| c.closed));
    }
}
