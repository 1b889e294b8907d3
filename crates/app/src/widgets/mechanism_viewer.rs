//! The mechanism viewer: any catalogue mechanism (or a loaded model file)
//! in 3D, from above or from the side. A slider per joint the learner
//! drives; followers and loop joints move by themselves. Drag the target
//! and inverse kinematics follows; bounding shapes light up where they
//! collide; the model tree lists mechanisms, bodies and joints.

use egui::{RichText, Sense, Stroke, vec2};
use kinolab_lessons::WidgetSpec;
use kinolab_mechanism::exercise::{Task, Verdict, conditioning};
use kinolab_mechanism::{
    FrameRef, Goal, JointKind, Model, Obstacle, Options, Part, Plane, Target, Vector3, catalogue,
    file,
};

use super::scene3d::{Camera, ViewKind, draw_capsule, draw_frame, draw_grid};
use super::{LabWidget, known_params, number_list, yes_no_param};
use crate::theme;

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
    verdict: Option<Verdict>,
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
    dragging_target: bool,
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

fn obstacles_param(text: &str) -> Result<Vec<Obstacle>, String> {
    text.split(';')
        .filter(|t| !t.trim().is_empty())
        .map(|t| match number_list("obstacles", t)?.as_slice() {
            [x, y, r] if *r > 0.0 => Ok(Obstacle::Circle {
                center: [*x, *y],
                radius: *r,
            }),
            _ => Err(format!(
                "Parameter `obstacles` takes `x, y, radius` groups separated by `;`, found `{}`.",
                t.trim()
            )),
        })
        .collect()
}

pub(super) fn create(spec: &WidgetSpec) -> Result<Box<dyn LabWidget>, String> {
    known_params(
        spec,
        &[
            "model",
            "view",
            "q",
            "frames",
            "shapes",
            "obstacles",
            "drag",
            "tree",
            "task",
            "target",
            "tolerance",
            "sets",
        ],
    )?;
    let id = spec.param("model").unwrap_or("planar-2r");
    let model =
        catalogue::mechanism(id).map_err(|e| format!("Parameter `model`: {}", e.message))?;
    let kind = match spec.param("view") {
        None if planar(id) => ViewKind::Plan,
        None if id == "rocker-bogie" => ViewKind::Side,
        None => ViewKind::Orbit,
        Some(v) => ViewKind::parse(v)
            .ok_or_else(|| format!("Parameter `view` must be 3d, plan or side, found `{v}`."))?,
    };
    let mut viewer = Viewer::new(model, kind);
    viewer.flat = planar(id);
    if viewer.flat {
        let (centre, extent) = bounds(&viewer.model, &viewer.q, true);
        viewer.camera = Camera::new(kind, centre, extent);
    }
    if let Some(text) = spec.param("q") {
        let values = number_list("q", text)?;
        viewer
            .set_driven(&values)
            .map_err(|e| format!("Parameter `q`: {e}"))?;
    }
    viewer.initial_q = viewer.q.clone();
    viewer.frames = yes_no_param(spec, "frames", true)?;
    viewer.shapes = yes_no_param(spec, "shapes", false)?;
    viewer.drag = yes_no_param(spec, "drag", true)?;
    viewer.tree = yes_no_param(spec, "tree", false)?;
    if let Some(text) = spec.param("obstacles") {
        viewer.obstacles = obstacles_param(text)?;
    }
    let end_name = viewer
        .end
        .as_ref()
        .map(|(n, _)| n.clone())
        .unwrap_or_else(|| "tool".into());
    viewer.exercise = match spec.param("task") {
        None => None,
        Some("reach") => {
            let t = number_list(
                "target",
                spec.param("target")
                    .ok_or("Task `reach` needs `target: x, y` or `target: x, y, z`.")?,
            )?;
            let target = match t.as_slice() {
                [x, y] => Vector3::new(*x, *y, 0.0),
                [x, y, z] => Vector3::new(*x, *y, *z),
                _ => return Err("Parameter `target` takes two or three numbers.".into()),
            };
            let tolerance = match spec.param("tolerance") {
                None => 0.01,
                Some(t) => t
                    .parse::<f64>()
                    .ok()
                    .filter(|v| *v > 0.0 && *v < 1.0)
                    .ok_or("Parameter `tolerance` must be a distance in metres between 0 and 1.")?,
            };
            viewer.drag = false;
            Some(Task::Reach {
                frame: end_name,
                target,
                tolerance,
            })
        }
        Some("spot-singular") => {
            let text = spec
                .param("sets")
                .ok_or("Task `spot-singular` needs `sets: q1, q2; q1, q2; …`.")?;
            let mut sets = Vec::new();
            for group in text.split(';') {
                let values = number_list("sets", group)?;
                let mut probe = Viewer::new(viewer.model.clone(), kind);
                probe
                    .set_driven(&values)
                    .map_err(|e| format!("Parameter `sets`: {e}"))?;
                sets.push(probe.q);
            }
            Some(Task::SpotSingular {
                frame: end_name,
                sets,
            })
        }
        Some(other) => {
            return Err(format!(
                "Parameter `task` must be reach or spot-singular, found `{other}`."
            ));
        }
    }
    .map(|task| {
        let marks = match &task {
            Task::SpotSingular { sets, .. } => vec![false; sets.len()],
            _ => Vec::new(),
        };
        Exercise {
            task,
            marks,
            verdict: None,
        }
    });
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
        let (centre, extent) = bounds(&model, &q, false);
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
            dragging_target: false,
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

    fn plane(&self) -> Plane {
        match self.camera.kind {
            ViewKind::Side => Plane::Side,
            _ => Plane::Plan,
        }
    }

    fn end_position(&self) -> Option<Vector3<f64>> {
        let (_, f) = self.end.as_ref()?;
        self.model
            .pose(&self.q, f)
            .ok()
            .map(|p| p.translation.vector)
    }

    /// Follow the dragged target with inverse kinematics from where the
    /// mechanism is now (a few restarts keep it quick enough per frame).
    fn follow(&mut self, target: Vector3<f64>) {
        let Some((_, f)) = &self.end else { return };
        let options = Options {
            max_iterations: 60,
            restarts: 3,
            ..Options::default()
        };
        match self.model.solve(
            &[Goal::new(*f, Target::Position(target))],
            &self.q,
            &options,
        ) {
            Ok(s) => {
                self.q = s.q;
                self.model.apply_couplings(&mut self.q);
                self.ik_note = (!s.converged).then(|| {
                    format!(
                        "Out of reach: the closest the {} gets is {:.0} mm from the target.",
                        self.end.as_ref().map_or("tool", |(n, _)| n.as_str()),
                        s.position_error * 1000.0
                    )
                });
            }
            Err(e) => self.ik_note = Some(e.to_string()),
        }
    }

    /// One joint's row: a slider for a driven joint, its value and why
    /// it moves for a follower or a loop joint. True when it changed.
    fn slider_row(&mut self, ui: &mut egui::Ui, v: usize, label: &str) -> bool {
        let mut changed = false;
        let Some(joint) = self.model.variable_joint(v).cloned() else {
            return false;
        };
        let prismatic = joint.kind == JointKind::Prismatic;
        let unit = if prismatic { " m" } else { "°" };
        ui.label(label);
        if self.driven.contains(&v) {
            let [lo, hi] = joint.limits.unwrap_or(if prismatic {
                [-1.0, 1.0]
            } else {
                [-std::f64::consts::PI, std::f64::consts::PI]
            });
            let mut shown = to_shown(&self.model, v, self.q[v]);
            let range = to_shown(&self.model, v, lo)..=to_shown(&self.model, v, hi);
            let slider = egui::Slider::new(&mut shown, range)
                .suffix(unit)
                .fixed_decimals(if prismatic { 2 } else { 0 });
            if ui.add(slider).changed() {
                self.q[v] = from_shown(&self.model, v, shown);
                changed = true;
            }
        } else {
            let why = match self.model.couplings().iter().find(|c| c.follower == v) {
                Some(c) => format!(
                    "follows {} × {:+}",
                    self.model
                        .variable_joint(c.leader)
                        .map_or("?", |j| j.name.as_str()),
                    c.ratio
                ),
                None => "moves to keep the loop closed".into(),
            };
            ui.label(
                RichText::new(format!(
                    "{:.1}{unit}  ({why})",
                    to_shown(&self.model, v, self.q[v])
                ))
                .italics(),
            );
        }
        ui.end_row();
        changed
    }

    fn sliders(&mut self, ui: &mut egui::Ui) {
        let mut changed = false;
        // Joints grouped by the top-level sub-mechanism they belong to.
        let top: Vec<(String, Vec<usize>)> = self
            .model
            .groups()
            .iter()
            .filter(|g| g.parent.is_none())
            .map(|g| {
                let vars = (0..self.model.dof())
                    .filter(|&v| {
                        self.model
                            .variable_joint(v)
                            .is_some_and(|j| g.bodies.contains(&j.child))
                    })
                    .collect();
                (g.name.clone(), vars)
            })
            .collect();
        let grouped: Vec<usize> = top.iter().flat_map(|(_, v)| v.iter().copied()).collect();
        let loose: Vec<usize> = (0..self.model.dof())
            .filter(|v| !grouped.contains(v))
            .collect();
        let fold = self.model.dof() > 8 && !top.is_empty();
        let grid = |ui: &mut egui::Ui, salt: usize, rows: &mut dyn FnMut(&mut egui::Ui)| {
            egui::Grid::new(ui.scope_id().with(("joints", salt)))
                .num_columns(2)
                .spacing(vec2(12.0, 2.0))
                .show(ui, |ui| rows(ui));
        };
        if fold {
            // Many joints: one foldable section per sub-mechanism.
            grid(ui, usize::MAX, &mut |ui| {
                for &v in &loose {
                    let name = self
                        .model
                        .variable_joint(v)
                        .map_or(String::new(), |j| j.name.clone());
                    changed |= self.slider_row(ui, v, &name);
                }
            });
            for (k, (name, vars)) in top.iter().enumerate() {
                egui::CollapsingHeader::new(format!("{name} ({} joints)", vars.len()))
                    .id_salt(("joint-group", k))
                    .default_open(k == 0)
                    .show(ui, |ui| {
                        grid(ui, k, &mut |ui| {
                            for &v in vars {
                                let full = self
                                    .model
                                    .variable_joint(v)
                                    .map_or(String::new(), |j| j.name.clone());
                                let short = full
                                    .strip_prefix(&format!("{name}/"))
                                    .unwrap_or(&full)
                                    .to_string();
                                changed |= self.slider_row(ui, v, &short);
                            }
                        });
                    });
            }
        } else {
            grid(ui, 0, &mut |ui| {
                for &v in loose.iter().chain(&grouped) {
                    let name = self
                        .model
                        .variable_joint(v)
                        .map_or(String::new(), |j| j.name.clone());
                    changed |= self.slider_row(ui, v, &name);
                }
            });
        }
        if changed {
            self.settle();
            self.target = None;
            self.ik_note = None;
        }
    }

    fn canvas(&mut self, ui: &mut egui::Ui) {
        let size = vec2(ui.available_width().min(760.0), 380.0);
        let (response, painter) = ui.allocate_painter(size, Sense::click_and_drag());
        let rect = response.rect;
        painter.rect_filled(rect, 6.0, ui.visuals().extreme_bg_color);
        let text = ui.visuals().text_color();
        let accent = theme::accent(ui);
        let warn = theme::warn_color(ui);
        draw_grid(&painter, &self.camera, rect, text.gamma_multiply(0.08));

        // Drag: the target handle if the press starts on it, else the camera.
        let handle = self.target.or_else(|| self.end_position());
        if response.drag_started() {
            self.dragging_target = self.drag
                && handle
                    .zip(response.interact_pointer_pos())
                    .is_some_and(|(h, p)| {
                        let (s, _) = self.camera.project(rect, &h);
                        s.distance(p) < 16.0
                    });
        }
        if self.dragging_target && response.dragged_by(egui::PointerButton::Primary) {
            if let Some(h) = handle {
                let mut t = h + self.camera.unproject_delta(rect, response.drag_delta());
                if self.flat {
                    t.z = 0.0;
                }
                self.target = Some(t);
                self.follow(t);
            }
        } else {
            self.camera.handle(ui, &response, true);
        }
        if response.drag_stopped() {
            self.dragging_target = false;
        }

        let Ok(placed) = self.model.place(&self.q) else {
            return;
        };
        let plane = self.plane();
        let collisions = if self.shapes || !self.obstacles.is_empty() {
            self.model.collisions(&self.q, plane, &self.obstacles).ok()
        } else {
            None
        };
        let hit = |b: usize| {
            collisions.as_ref().is_some_and(|c| {
                c.pairs
                    .iter()
                    .any(|(x, y)| *x == Part::Body(b) || *y == Part::Body(b))
            })
        };
        // Obstacles live in the view's plane.
        for (i, o) in self.obstacles.iter().enumerate() {
            if let Obstacle::Circle { center, radius } = o {
                let p = match plane {
                    Plane::Plan => Vector3::new(center[0], center[1], 0.0),
                    Plane::Side => Vector3::new(center[0], 0.0, center[1]),
                };
                let (c, _) = self.camera.project(rect, &p);
                let touched = collisions
                    .as_ref()
                    .is_some_and(|c| c.pairs.iter().any(|(_, y)| *y == Part::Obstacle(i)));
                let colour = if touched {
                    warn
                } else {
                    text.gamma_multiply(0.5)
                };
                painter.circle(
                    c,
                    *radius as f32 * self.camera.scale(rect),
                    colour.gamma_multiply(0.15),
                    Stroke::new(1.5, colour),
                );
            }
        }
        // Bodies as their capsules: faint as silhouettes, stronger when the
        // learner asks for the bounding shapes (colliding ones in red).
        for s in self.model.shapes() {
            let at = &placed.bodies[s.body];
            let a = at.rotation * s.a + at.translation.vector;
            let b = at.rotation * s.b + at.translation.vector;
            let fill = match (self.shapes, hit(s.body)) {
                (true, true) => warn.gamma_multiply(0.45),
                (true, false) => accent.gamma_multiply(0.22),
                (false, _) => text.gamma_multiply(0.14),
            };
            draw_capsule(&painter, &self.camera, rect, &a, &b, s.radius, fill);
        }
        // The skeleton: parent origin → joint → child origin.
        for (j, joint) in self.model.joints().iter().enumerate() {
            if joint.parent == 0 && !joint.kind.moves() {
                // A body bolted to the world: no link to draw.
                continue;
            }
            let from = placed.bodies[joint.parent].translation.vector;
            let at = placed.joints[j].translation.vector;
            let to = placed.bodies[joint.child].translation.vector;
            let selected = self.selected == Some(joint.child);
            let colour = if selected {
                accent
            } else {
                text.gamma_multiply(0.85)
            };
            let width = if selected { 4.0 } else { 2.5 };
            let (pf, _) = self.camera.project(rect, &from);
            let (pa, _) = self.camera.project(rect, &at);
            let (pt, _) = self.camera.project(rect, &to);
            painter.line_segment([pf, pa], Stroke::new(width, colour));
            painter.line_segment([pa, pt], Stroke::new(width, colour));
            if joint.kind.moves() {
                painter.circle(
                    pa,
                    4.0,
                    ui.visuals().extreme_bg_color,
                    Stroke::new(1.5, colour),
                );
            }
        }
        // Ports: a thin line from each body's origin to its named frames.
        for f in self.model.frames() {
            let body = &placed.bodies[f.body];
            let at = body * f.offset;
            let (pb, _) = self.camera.project(rect, &body.translation.vector);
            let (pf, _) = self.camera.project(rect, &at.translation.vector);
            painter.line_segment([pb, pf], Stroke::new(1.5, text.gamma_multiply(0.55)));
        }
        if self.flat && self.model.loops().is_empty() {
            // The outer edge of the workspace: full stretch.
            let (o, _) = self.camera.project(rect, &Vector3::zeros());
            let r = reach(&self.model) as f32 * self.camera.scale(rect);
            painter.circle_stroke(o, r, Stroke::new(1.0, accent.gamma_multiply(0.3)));
        }
        if self.frames {
            let length = self.camera.extent * 0.12;
            draw_frame(
                &painter,
                &self.camera,
                rect,
                &kinolab_mechanism::Pose::identity(),
                length * 1.5,
                0.6,
                1.5,
            );
            for (b, pose) in placed.bodies.iter().enumerate().skip(1) {
                let moving = self
                    .model
                    .joints()
                    .iter()
                    .any(|j| j.child == b && j.kind.moves());
                if moving || self.selected == Some(b) {
                    draw_frame(&painter, &self.camera, rect, pose, length, 1.0, 1.5);
                }
            }
        }
        // Loop constraints: the two frames that must meet.
        for l in self.model.loops() {
            if let (Ok(a), Ok(b)) = (
                self.model.pose(&self.q, &l.a),
                self.model.pose(&self.q, &l.b),
            ) {
                let (pa, _) = self.camera.project(rect, &a.translation.vector);
                let (pb, _) = self.camera.project(rect, &b.translation.vector);
                painter.circle_stroke(pb, 6.0, Stroke::new(1.5, accent));
                painter.line_segment([pa, pb], Stroke::new(1.0, warn));
            }
        }
        // The end effector and the target the learner drags.
        if let Some(end) = self.end_position() {
            let (p, _) = self.camera.project(rect, &end);
            painter.circle_filled(p, 5.0, accent);
            if let Some(t) = self.target {
                let (pt, _) = self.camera.project(rect, &t);
                painter.line_segment([p, pt], Stroke::new(1.0, accent.gamma_multiply(0.6)));
                painter.circle_stroke(pt, 9.0, Stroke::new(2.0, accent));
            } else if self.drag {
                painter.circle_stroke(p, 9.0, Stroke::new(1.5, accent.gamma_multiply(0.7)));
            }
        }
        if let Some(Exercise {
            task: Task::Reach { target, .. },
            ..
        }) = &self.exercise
        {
            let (p, _) = self.camera.project(rect, target);
            let s = Stroke::new(2.0, theme::good_color(ui));
            painter.line_segment([p - vec2(7.0, 7.0), p + vec2(7.0, 7.0)], s);
            painter.line_segment([p - vec2(7.0, -7.0), p + vec2(7.0, -7.0)], s);
        }
        let hint = match (self.camera.kind, self.drag && self.end.is_some()) {
            (ViewKind::Orbit, true) => {
                "drag the ring to move the end; drag elsewhere to turn the view (Shift to pan)"
            }
            (ViewKind::Orbit, false) => {
                "drag to turn the view (Shift to pan), Ctrl + wheel to zoom"
            }
            (_, true) => "drag the ring to move the end; drag elsewhere to pan",
            (_, false) => "drag to pan, Ctrl + wheel to zoom",
        };
        painter.text(
            rect.left_bottom() + vec2(8.0, -8.0),
            egui::Align2::LEFT_BOTTOM,
            hint,
            egui::FontId::proportional(12.0),
            text.gamma_multiply(0.6),
        );
        if let Some(c) = &collisions
            && !c.pairs.is_empty()
        {
            let names: Vec<String> = c
                .pairs
                .iter()
                .map(|(a, b)| format!("{} – {}", self.part_name(a), self.part_name(b)))
                .collect();
            painter.text(
                rect.left_top() + vec2(8.0, 8.0),
                egui::Align2::LEFT_TOP,
                format!("Colliding: {}", names.join(", ")),
                egui::FontId::proportional(13.0),
                warn,
            );
        }
    }

    fn part_name(&self, p: &Part) -> String {
        match *p {
            Part::Body(b) => self
                .model
                .bodies()
                .get(b)
                .map_or_else(String::new, |x| x.name.clone()),
            Part::Obstacle(i) => format!("obstacle {}", i + 1),
        }
    }

    fn readout(&self, ui: &mut egui::Ui) {
        let mut lines = Vec::new();
        if let (Some(p), Some((name, f))) = (self.end_position(), &self.end) {
            lines.push(format!("{name} at ({:.3}, {:.3}, {:.3}) m", p.x, p.y, p.z));
            let spotting = matches!(
                self.exercise.as_ref().map(|e| &e.task),
                Some(Task::SpotSingular { .. })
            );
            if name == "tool"
                && !spotting
                && let Ok(c) = conditioning(&self.model, &self.q, f)
            {
                let how = if c < 1e-6 {
                    "singular: a direction of motion is lost"
                } else if c < 0.05 {
                    "close to a singularity"
                } else {
                    "well away from singularities"
                };
                lines.push(format!("Jacobian conditioning {c:.3} ({how})"));
            }
        }
        if let Some(c) = self
            .model
            .loops()
            .first()
            .and(self.model.closure(&self.q).ok())
        {
            lines.push(format!("loop closed to {:.1e} m", c.gap));
        }
        ui.label(RichText::new(lines.join(" · ")).monospace().small());
        for note in [&self.ik_note, &self.closure_note].into_iter().flatten() {
            ui.label(RichText::new(note).color(theme::warn_color(ui)));
        }
    }

    fn tree_ui(&mut self, ui: &mut egui::Ui) {
        egui::CollapsingHeader::new("Model tree")
            .default_open(self.tree)
            .show(ui, |ui| {
                let model = &self.model;
                let joint_of = |b: usize| model.joints().iter().find(|j| j.child == b);
                let mut select = None;
                let mut body_line = |ui: &mut egui::Ui, b: usize, selected: Option<usize>| {
                    let name = &model.bodies()[b].name;
                    let how = joint_of(b).map_or(String::new(), |j| {
                        format!(
                            " — {:?} joint from {}",
                            j.kind,
                            model.bodies()[j.parent].name
                        )
                        .to_lowercase()
                    });
                    if ui
                        .selectable_label(selected == Some(b), format!("{name}{how}"))
                        .clicked()
                    {
                        select = Some(b);
                    }
                };
                let grouped: Vec<usize> = model
                    .groups()
                    .iter()
                    .flat_map(|g| g.bodies.iter().copied())
                    .collect();
                ui.label(
                    RichText::new(format!(
                        "{} — {} joint variables",
                        model.name(),
                        model.dof()
                    ))
                    .strong(),
                );
                for b in 1..model.bodies().len() {
                    if !grouped.contains(&b) {
                        body_line(ui, b, self.selected);
                    }
                }
                for (gi, g) in model
                    .groups()
                    .iter()
                    .enumerate()
                    .filter(|(_, g)| g.parent.is_none())
                {
                    egui::CollapsingHeader::new(format!("mechanism {}", g.name))
                        .id_salt(("group", gi))
                        .show(ui, |ui| {
                            let nested: Vec<usize> = model
                                .groups()
                                .iter()
                                .filter(|c| c.parent == Some(gi))
                                .flat_map(|c| c.bodies.iter().copied())
                                .collect();
                            for &b in &g.bodies {
                                if !nested.contains(&b) {
                                    body_line(ui, b, self.selected);
                                }
                            }
                        });
                }
                for c in model.couplings() {
                    let n = |v: usize| model.variable_joint(v).map_or("?", |j| j.name.as_str());
                    let offset = if c.offset == 0.0 {
                        String::new()
                    } else {
                        format!(" {:+}", c.offset)
                    };
                    ui.label(format!(
                        "coupling: {} = {} × {}{offset}",
                        n(c.follower),
                        c.ratio,
                        n(c.leader)
                    ));
                }
                for l in model.loops() {
                    ui.label(format!("loop: {}", l.name));
                }
                for s in model.command_names() {
                    ui.label(format!("specialised solver: {s}"));
                }
                if let Some(b) = select {
                    self.selected = if self.selected == Some(b) {
                        None
                    } else {
                        Some(b)
                    };
                }
            });
    }

    fn file_ui(&mut self, ui: &mut egui::Ui) {
        egui::CollapsingHeader::new("Model file").show(ui, |ui| {
            ui.horizontal(|ui| {
                if ui.button("Save model file").clicked() {
                    let text = file::to_json(&self.model);
                    let name = format!(
                        "{}.model.json",
                        self.model.name().to_lowercase().replace(' ', "-")
                    );
                    self.file_note = Some(
                        crate::export::save(&name, "application/json", text.as_bytes())
                            .unwrap_or_else(|e| e),
                    );
                }
                if ui.button("Load from the text below").clicked() {
                    match file::from_json(&self.file_text) {
                        Ok(m) => {
                            let name = m.name().to_string();
                            self.replace_model(m);
                            self.file_note = Some(format!("Loaded {name}."));
                        }
                        Err(e) => self.file_note = Some(format!("Not loaded: {e}")),
                    }
                }
            });
            ui.add(
                egui::TextEdit::multiline(&mut self.file_text)
                    .hint_text("paste a model file (JSON) here")
                    .desired_rows(4)
                    .code_editor(),
            );
            if let Some(n) = &self.file_note {
                ui.label(RichText::new(n).small());
            }
        });
    }

    fn exercise_ui(&mut self, ui: &mut egui::Ui) {
        let mut load = None;
        let Some(ex) = &mut self.exercise else { return };
        ui.group(|ui| {
            ui.label(RichText::new(format!("Exercise: {}", ex.task.describe())).strong());
            if let Task::SpotSingular { sets, .. } = &ex.task {
                for (i, (q, mark)) in sets.iter().zip(ex.marks.iter_mut()).enumerate() {
                    ui.horizontal(|ui| {
                        let shown: Vec<String> = self
                            .driven
                            .iter()
                            .map(|&v| format!("{:.0}", to_shown(&self.model, v, q[v])))
                            .collect();
                        ui.checkbox(
                            mark,
                            format!("configuration {}: ({})", i + 1, shown.join(", ")),
                        );
                        if ui.small_button("show").clicked() {
                            load = Some(q.clone());
                        }
                    });
                }
            }
            if ui.button("Check").clicked() {
                let result = match &ex.task {
                    Task::SpotSingular { .. } => ex.task.check_marks(&self.model, &ex.marks),
                    _ => ex.task.check_state(&self.model, &self.q),
                };
                ex.verdict = Some(result.unwrap_or_else(|e| Verdict {
                    met: false,
                    message: e.to_string(),
                }));
            }
            if let Some(v) = &ex.verdict {
                let colour = if v.met {
                    theme::good_color(ui)
                } else {
                    theme::warn_color(ui)
                };
                ui.label(RichText::new(&v.message).color(colour));
            }
        });
        if let Some(q) = load {
            self.q = q;
            self.target = None;
        }
    }
}

/// How far each body can be from the world origin along its chain, at
/// most: the sum of the fixed offsets above it (joint travel aside).
fn chain_lengths(model: &Model) -> Vec<f64> {
    let mut length = vec![0.0; model.bodies().len()];
    for j in model.joints() {
        length[j.child] = length[j.parent]
            + j.origin.translation.vector.norm()
            + j.post.translation.vector.norm();
    }
    length
}

/// The longest reach of the mechanism, to its named frames included.
fn reach(model: &Model) -> f64 {
    let length = chain_lengths(model);
    let frames = model
        .frames()
        .iter()
        .map(|f| length[f.body] + f.offset.translation.vector.norm());
    length.iter().copied().chain(frames).fold(0.0, f64::max)
}

/// The centre and half-size of the scene, for the camera. A flat arm is
/// centred on its base with its whole reach in view; anything else on the
/// box around its bodies, frames and shapes.
fn bounds(model: &Model, q: &[f64], flat: bool) -> ([f64; 3], f64) {
    let reach = reach(model).max(0.1);
    let closed = !model.loops().is_empty();
    if flat && !closed {
        return ([0.0; 3], reach * 1.1);
    }
    let Ok(placed) = model.place(q) else {
        return ([0.0; 3], reach);
    };
    let mut lo = Vector3::repeat(f64::INFINITY);
    let mut hi = Vector3::repeat(f64::NEG_INFINITY);
    let mut grow = |p: &Vector3<f64>, r: f64| {
        lo = lo.inf(&p.add_scalar(-r));
        hi = hi.sup(&p.add_scalar(r));
    };
    for p in placed.bodies.iter().chain(&placed.joints) {
        grow(&p.translation.vector, 0.0);
    }
    for f in model.frames() {
        let at = placed.bodies[f.body] * f.offset;
        grow(&at.translation.vector, 0.0);
    }
    for s in model.shapes() {
        let at = &placed.bodies[s.body];
        grow(&(at.rotation * s.a + at.translation.vector), s.radius);
        grow(&(at.rotation * s.b + at.translation.vector), s.radius);
    }
    let centre = (lo + hi) / 2.0;
    let half = (hi - lo).max() / 2.0;
    // A closed chain never stretches out: its box is a better guide.
    let extent = if closed {
        half * 1.6
    } else {
        (half * 1.25).max(reach * 0.45)
    };
    ([centre.x, centre.y, centre.z], extent.max(0.1))
}

impl LabWidget for Viewer {
    fn ui(&mut self, ui: &mut egui::Ui) {
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
            if self
                .exercise
                .as_ref()
                .is_none_or(|e| !matches!(e.task, Task::Reach { .. }))
                && self.end.is_some()
            {
                ui.checkbox(&mut self.drag, "drag target");
            }
            if ui.button("home").clicked() {
                self.q = self.initial_q.clone();
                self.target = None;
                self.ik_note = None;
            }
        });
        self.canvas(ui);
        self.readout(ui);
        self.sliders(ui);
        self.exercise_ui(ui);
        self.tree_ui(ui);
        self.file_ui(ui);
    }

    fn state(&self) -> Option<String> {
        let changed = self.q != self.initial_q || self.camera.kind != self.initial_kind;
        changed.then(|| {
            let values: Vec<String> = self
                .driven
                .iter()
                .map(|&v| format!("{:.3}", to_shown(&self.model, v, self.q[v])))
                .collect();
            format!("{}~{}", self.camera.kind.key(), values.join(","))
        })
    }

    fn restore(&mut self, state: &str) {
        let Some((kind, values)) = state.split_once('~') else {
            return;
        };
        if let Some(kind) = ViewKind::parse(kind) {
            self.camera = Camera::new(kind, self.camera.centre, self.camera.extent);
        }
        if let Ok(values) = number_list("q", values) {
            let _ = self.set_driven(&values);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(params: &[(&str, &str)]) -> WidgetSpec {
        super::super::test_spec("mechanism-viewer", params)
    }

    #[test]
    fn every_catalogue_mechanism_opens() {
        for (id, _, _) in catalogue::CATALOGUE {
            assert!(create(&spec(&[("model", id)])).is_ok(), "{id}");
        }
    }

    #[test]
    fn joint_values_and_links_round_trip() {
        let Ok(mut w) = create(&spec(&[("model", "planar-2r"), ("q", "30, 45")])) else {
            panic!()
        };
        assert_eq!(w.state(), None);
        w.restore("side~10.000,-20.000");
        assert_eq!(w.state().as_deref(), Some("side~10.000,-20.000"));
    }

    #[test]
    fn bad_parameters_say_what_is_wrong() {
        let message = |p: &[(&str, &str)]| match create(&spec(p)) {
            Err(e) => e,
            Ok(_) => panic!("accepted {p:?}"),
        };
        assert!(message(&[("model", "warp-drive")]).contains("no built-in mechanism"));
        assert!(message(&[("q", "1, 2, 3")]).contains("takes 2 values"));
        assert!(message(&[("view", "sideways")]).contains("3d, plan or side"));
        assert!(message(&[("task", "reach")]).contains("needs `target"));
        assert!(message(&[("obstacles", "1, 2")]).contains("x, y, radius"));
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
