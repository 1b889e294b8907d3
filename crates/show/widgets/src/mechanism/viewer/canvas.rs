//! The viewer's drawing: obstacles, bodies as capsules, the skeleton,
//! frames, loop constraints and the end effector; the ring at the end is a
//! named handle to drag (or move with the arrow keys), and dragging
//! anywhere else turns or pans the camera.

use egui::{Painter, Rect, Sense, Stroke, vec2};
use kinolab_mechanism::exercise::Task;
use kinolab_mechanism::{Collisions, Obstacle, Part, Placement, Plane, Pose, Vector3};

use super::{Exercise, Viewer, bounds};
use crate::draw::scene3d::{ViewKind, draw_capsule, draw_frame};
use crate::draw::{canvas_3d, corner_text, handle, marks};
use crate::theme;

/// Radius of the target ring, points: big enough to grab with a finger.
const RING: f32 = 13.0;

impl Viewer {
    /// The drawing; the area it took.
    pub(super) fn canvas(&mut self, ui: &mut egui::Ui) -> Rect {
        let size = vec2(ui.available_width().min(760.0), 380.0);
        let (response, painter) = canvas_3d(ui, size, Sense::click_and_drag(), &self.camera);
        let rect = response.rect;
        let target_held = self.target_handle(ui, rect);
        if !target_held {
            self.camera.handle(ui, &response, true);
        }
        let Ok(placed) = self.model.place(&self.q) else {
            return rect;
        };
        let collisions = (self.shapes || !self.obstacles.is_empty())
            .then(|| {
                self.model
                    .collisions(&self.q, self.plane(), &self.obstacles)
                    .ok()
            })
            .flatten();
        self.draw_obstacles(ui, &painter, rect, collisions.as_ref());
        self.draw_bodies(ui, &painter, rect, &placed, collisions.as_ref());
        self.draw_frames(&painter, rect, &placed);
        self.draw_marks(ui, &painter, rect);
        self.captions(ui, &painter, rect, collisions.as_ref());
        rect
    }

    /// The ring at the end effector (or at the dragged target): drag it and
    /// inverse kinematics follows. True while the learner holds it.
    fn target_handle(&mut self, ui: &mut egui::Ui, rect: Rect) -> bool {
        let Some(at) = self.target.or_else(|| self.end_position()) else {
            return false;
        };
        if !self.drag {
            return false;
        }
        let (screen, _) = self.camera.project(rect, &at);
        let name = self.end.as_ref().map_or("tool", |(n, _)| n.as_str());
        let h = handle(
            ui,
            ui.scope_id().with("target"),
            screen,
            RING,
            &format!("Target for the {name}"),
        );
        if h.dragged() {
            let mut t = at + self.camera.unproject_delta(rect, h.moved);
            if self.flat {
                t.z = 0.0;
            }
            self.target = Some(t);
            self.follow(t);
        }
        h.held()
    }

    /// Obstacles live in the view's plane; touched ones turn red.
    fn draw_obstacles(
        &self,
        ui: &egui::Ui,
        painter: &Painter,
        rect: Rect,
        collisions: Option<&Collisions>,
    ) {
        let plane = self.plane();
        for (i, o) in self.obstacles.iter().enumerate() {
            let Obstacle::Circle { center, radius } = o else {
                continue;
            };
            let p = match plane {
                Plane::Plan => Vector3::new(center[0], center[1], 0.0),
                Plane::Side => Vector3::new(center[0], 0.0, center[1]),
            };
            let (c, _) = self.camera.project(rect, &p);
            let touched =
                collisions.is_some_and(|c| c.pairs.iter().any(|(_, y)| *y == Part::Obstacle(i)));
            let color = if touched {
                theme::error_color(ui)
            } else {
                ui.visuals().weak_text_color()
            };
            let r = *radius as f32 * self.camera.scale(rect);
            painter.circle(c, r, color.gamma_multiply(0.15), Stroke::new(1.5, color));
        }
    }

    /// Bodies as their capsules (faint as silhouettes, stronger with the
    /// shapes on, colliding ones red), then the skeleton: parent origin →
    /// joint → child origin.
    fn draw_bodies(
        &self,
        ui: &egui::Ui,
        painter: &Painter,
        rect: Rect,
        placed: &Placement,
        collisions: Option<&Collisions>,
    ) {
        let ink = ui.visuals().text_color();
        let (accent, bad) = (theme::accent(ui), theme::error_color(ui));
        let hit = |b: usize| {
            collisions.is_some_and(|c| {
                c.pairs
                    .iter()
                    .any(|(x, y)| *x == Part::Body(b) || *y == Part::Body(b))
            })
        };
        for s in self.model.shapes() {
            let at = &placed.bodies[s.body];
            let a = at.rotation * s.a + at.translation.vector;
            let b = at.rotation * s.b + at.translation.vector;
            let fill = match (self.shapes, hit(s.body)) {
                (true, true) => bad.gamma_multiply(0.45),
                (true, false) => accent.gamma_multiply(0.22),
                (false, _) => ink.gamma_multiply(0.14),
            };
            draw_capsule(painter, &self.camera, rect, &a, &b, s.radius, fill);
        }
        for (j, joint) in self.model.joints().iter().enumerate() {
            if joint.parent == 0 && !joint.kind.moves() {
                continue; // a body bolted to the world: no link to draw
            }
            let selected = self.selected == Some(joint.child);
            let color = if selected {
                accent
            } else {
                ink.gamma_multiply(0.85)
            };
            let stroke = Stroke::new(if selected { 4.0 } else { 2.5 }, color);
            let project = |p: &Pose| self.camera.project(rect, &p.translation.vector).0;
            let (pf, pa, pt) = (
                project(&placed.bodies[joint.parent]),
                project(&placed.joints[j]),
                project(&placed.bodies[joint.child]),
            );
            painter.line_segment([pf, pa], stroke);
            painter.line_segment([pa, pt], stroke);
            if joint.kind.moves() {
                painter.circle(
                    pa,
                    4.0,
                    ui.visuals().extreme_bg_color,
                    Stroke::new(1.5, color),
                );
            }
        }
        // Ports: a thin line from each body's origin to its named frames.
        for f in self.model.frames() {
            let body = &placed.bodies[f.body];
            let (pb, _) = self.camera.project(rect, &body.translation.vector);
            let (pf, _) = self
                .camera
                .project(rect, &(body * f.offset).translation.vector);
            painter.line_segment([pb, pf], Stroke::new(1.5, ink.gamma_multiply(0.55)));
        }
    }

    /// The world frame and the frame of every moving body.
    fn draw_frames(&self, painter: &Painter, rect: Rect, placed: &Placement) {
        if !self.frames {
            return;
        }
        let length = self.camera.extent * 0.12;
        draw_frame(
            painter,
            &self.camera,
            rect,
            &Pose::identity(),
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
                draw_frame(painter, &self.camera, rect, pose, length, 1.0, 1.5);
            }
        }
    }

    /// The reach circle on the floor, loop constraints, the end effector,
    /// the target and an exercise's goal.
    fn draw_marks(&self, ui: &egui::Ui, painter: &Painter, rect: Rect) {
        let accent = theme::accent(ui);
        if self.flat && self.model.loops().is_empty() {
            // The outer edge of the workspace, drawn on the floor so it
            // turns with the view.
            let r = bounds::reach(&self.model);
            let ring: Vec<egui::Pos2> = (0..=72)
                .map(|k| {
                    let a = f64::from(k) * std::f64::consts::TAU / 72.0;
                    self.camera
                        .project(rect, &Vector3::new(r * a.cos(), r * a.sin(), 0.0))
                        .0
                })
                .collect();
            painter.add(egui::Shape::line(
                ring,
                Stroke::new(1.0, accent.gamma_multiply(0.3)),
            ));
        }
        for l in self.model.loops() {
            if let (Ok(a), Ok(b)) = (
                self.model.pose(&self.q, &l.a),
                self.model.pose(&self.q, &l.b),
            ) {
                let (pa, _) = self.camera.project(rect, &a.translation.vector);
                let (pb, _) = self.camera.project(rect, &b.translation.vector);
                painter.circle_stroke(pb, 6.0, Stroke::new(1.5, accent));
                painter.line_segment([pa, pb], Stroke::new(1.0, theme::error_color(ui)));
            }
        }
        if let Some(end) = self.end_position() {
            let (p, _) = self.camera.project(rect, &end);
            painter.circle_filled(p, 5.0, accent);
            if let Some(t) = self.target {
                let (pt, _) = self.camera.project(rect, &t);
                painter.line_segment([p, pt], Stroke::new(1.0, accent.gamma_multiply(0.6)));
                painter.circle_stroke(pt, RING, Stroke::new(2.0, accent));
            } else if self.drag {
                painter.circle_stroke(p, RING, Stroke::new(1.5, accent.gamma_multiply(0.7)));
            }
        }
        if let Some(Exercise {
            task: Task::Reach { target, .. },
            ..
        }) = &self.exercise
        {
            let (p, _) = self.camera.project(rect, target);
            marks::cross(painter, p, 7.0, Stroke::new(2.0, theme::good_color(ui)));
        }
    }

    /// How to use the view, and which pairs collide.
    fn captions(
        &self,
        ui: &egui::Ui,
        painter: &Painter,
        rect: Rect,
        collisions: Option<&Collisions>,
    ) {
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
        let font = egui::FontId::proportional(theme::LABEL_SIZE);
        painter.text(
            rect.left_bottom() + vec2(8.0, -8.0),
            egui::Align2::LEFT_BOTTOM,
            hint,
            font,
            ui.visuals().weak_text_color(),
        );
        if let Some(c) = collisions
            && !c.pairs.is_empty()
        {
            let names: Vec<String> = c
                .pairs
                .iter()
                .map(|(a, b)| format!("{} – {}", self.part_name(a), self.part_name(b)))
                .collect();
            let text = format!("Colliding: {}", names.join(", "));
            corner_text(painter, rect, 0, text, theme::error_color(ui));
        }
    }
}
