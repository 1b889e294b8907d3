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
mod panels;

use kinolab_common::Feedback;
use kinolab_mechanism::exercise::Task;
use kinolab_mechanism::{FrameRef, JointKind, Model, Obstacle, Vector3, catalogue};
use serde::{Deserialize, Serialize};

use crate::draw::scene3d::{Camera, ViewKind};
use crate::link;
use crate::widget::{LabWidget, Params};

/// The frame a learner moves, by model: the first one the model has.
const END_FRAMES: [&str; 5] = [
    "tool",
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
    let id = p.choice("model").unwrap_or("planar-2r");
    let model =
        catalogue::mechanism(id).map_err(|e| format!("parameter `model`: {}", e.message))?;
    let kind = match p.choice("view") {
        Some(v) => ViewKind::parse(v).unwrap_or(ViewKind::Orbit),
        None if planar(id) => ViewKind::Plan,
        None if id == "rocker-bogie" => ViewKind::Side,
        None => ViewKind::Orbit,
    };
    let mut viewer = Viewer::new(model, kind);
    viewer.flat = planar(id);
    if viewer.flat {
        let (centre, extent) = bounds::bounds(&viewer.model, &viewer.q, true);
        viewer.camera = Camera::new(kind, centre, extent);
    }
    if let Some(values) = p.numbers("q") {
        viewer
            .set_driven(values)
            .map_err(|e| format!("parameter `q`: {e}"))?;
    }
    viewer.initial_q = viewer.q.clone();
    viewer.frames = p.yes("frames");
    viewer.shapes = p.yes("shapes");
    viewer.drag = p.yes("drag");
    viewer.tree = p.yes("tree");
    viewer.obstacles = p
        .groups("obstacles")
        .unwrap_or_default()
        .iter()
        .map(|g| Obstacle::Circle {
            center: [g[0], g[1]],
            radius: g[2].abs(),
        })
        .collect();
    viewer.exercise = viewer.exercise_from(p)?;
    Ok(Box::new(viewer))
}

impl Viewer {
    fn new(model: Model, kind: ViewKind) -> Self {
        let mut q = model.zero_state();
        let closure = model.close_loops(&mut q).ok();
        let driven: Vec<usize> = (0..model.dof()).filter(|&v| model.is_driven(v)).collect();
        let end = END_FRAMES
            .iter()
            .find_map(|n| model.frame(n).ok().map(|f| ((*n).to_string(), f)));
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
            model,
        }
    }

    /// The exercise a lesson set up, if any.
    fn exercise_from(&self, p: &Params) -> Result<Option<Exercise>, String> {
        let frame = self
            .end
            .as_ref()
            .map_or_else(|| "tool".to_owned(), |(n, _)| n.clone());
        let task = match p.choice("task") {
            Some("reach") => {
                let t = p.numbers("target").unwrap_or_default();
                Task::Reach {
                    frame,
                    target: Vector3::new(
                        t.first().copied().unwrap_or(0.0),
                        t.get(1).copied().unwrap_or(0.0),
                        t.get(2).copied().unwrap_or(0.0),
                    ),
                    tolerance: p.number("tolerance").unwrap_or(0.01),
                }
            }
            Some("spot-singular") => {
                let mut sets = Vec::new();
                for values in p.groups("sets").unwrap_or_default() {
                    let mut probe = Viewer::new(self.model.clone(), self.camera.kind);
                    probe
                        .set_driven(values)
                        .map_err(|e| format!("parameter `sets`: {e}"))?;
                    sets.push(probe.q);
                }
                Task::SpotSingular { frame, sets }
            }
            _ => return Ok(None),
        };
        let marks = match &task {
            Task::SpotSingular { sets, .. } => vec![false; sets.len()],
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

    fn replace_model(&mut self, model: Model) {
        let kind = self.camera.kind;
        let keep = (self.frames, self.shapes, self.drag, self.tree);
        *self = Viewer::new(model, kind);
        // A loaded model is flat if nothing in it leaves the x–y plane.
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
                if ui
                    .selectable_label(self.camera.kind == kind, kind.label())
                    .clicked()
                {
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

/// The view and the driven joints' values, as a link carries them.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct LinkState {
    view: u8,
    driven: Vec<f64>,
}

const VIEWS: [ViewKind; 3] = [ViewKind::Orbit, ViewKind::Plan, ViewKind::Side];

impl LabWidget for Viewer {
    fn ui(&mut self, ui: &mut egui::Ui) {
        self.toolbar(ui);
        self.canvas(ui);
        self.readout(ui);
        self.sliders(ui);
        self.exercise_ui(ui);
        self.tree_ui(ui);
        self.file_ui(ui);
    }

    fn state(&self) -> Option<String> {
        let changed = self.q != self.initial_q || self.camera.kind != self.initial_kind;
        let state = LinkState {
            view: VIEWS
                .iter()
                .position(|k| *k == self.camera.kind)
                .unwrap_or(0) as u8,
            driven: self
                .driven
                .iter()
                .map(|&v| to_shown(&self.model, v, self.q[v]))
                .collect(),
        };
        changed.then(|| link::encode(&state)).flatten()
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let Some(state) = link::decode::<LinkState>(state) else {
            return Err("it is not a state of the mechanism viewer".into());
        };
        if let Some(kind) = VIEWS.get(usize::from(state.view)) {
            self.camera = Camera::new(*kind, self.camera.centre, self.camera.extent);
        }
        if state.driven.iter().all(|v| v.is_finite()) {
            let _ = self.set_driven(&state.driven);
        }
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
        let _ = w.restore(&side);
        let Some(back) = w.state().and_then(|s| link::decode::<LinkState>(&s)) else {
            panic!("a changed viewer goes into the link")
        };
        assert_eq!(back.view, 2);
        assert!((back.driven[0] - 10.0).abs() < 1e-9 && (back.driven[1] + 20.0).abs() < 1e-9);
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
