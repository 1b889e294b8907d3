//! The workbench's drawing: grid, frame, zero-motion lines, the ICR, the
//! wheels; dragging a wheel moves it, the knob of the selected wheel
//! turns it, a click selects (or, in the challenge, marks) it.

use egui::{Color32, Painter, Pos2, Sense, Stroke, vec2};
use kinolab_common::angle::{snap, wrap};
use kinolab_wheels::challenge::Goal;
use kinolab_wheels::{Analysis, Wheel, WheelKind};

use super::{ANGLE_STEP, GRID, Task, Workbench};
use crate::draw::labels::Labels;
use crate::draw::{canvas, grid, handle};
use crate::theme;
use crate::wheels::chassis::{
    RobotView, draw_frame, draw_icr, draw_wheel, draw_zero_motion_line, wheel_color, wheel_rects,
};

impl Workbench {
    /// The drawing; the area it took.
    pub(super) fn canvas(
        &mut self,
        ui: &mut egui::Ui,
        analysis: &Analysis,
        size: egui::Vec2,
    ) -> egui::Rect {
        let (response, painter) = canvas(ui, size, Sense::click());
        let rect = response.rect;
        let view = RobotView::robot_frame(rect, self.extent);
        let mut labels = Labels::default();
        let hint = painter.text(
            rect.left_bottom() + vec2(8.0, -6.0),
            egui::Align2::LEFT_BOTTOM,
            "drag a wheel to move it; select it and drag the blue knob to turn it",
            egui::FontId::proportional(theme::SMALL_SIZE),
            ui.visuals().weak_text_color(),
        );
        labels.reserve(hint);
        for r in wheel_rects(&view, self.chassis.wheels()) {
            labels.reserve(r);
        }
        self.draw_scene(ui, &painter, &mut labels, &view, analysis);
        let clicked = self.wheel_handles(ui, &painter, &mut labels, &view);
        self.select(clicked, response.clicked());
        labels.draw(&painter, &egui::FontId::proportional(theme::LABEL_SIZE));
        rect
    }

    /// Everything under the wheels: grid, frame, zero-motion lines, ICR, goal.
    fn draw_scene(
        &self,
        ui: &egui::Ui,
        painter: &Painter,
        labels: &mut Labels,
        view: &RobotView,
        analysis: &Analysis,
    ) {
        let ink = ui.visuals().text_color();
        grid(
            painter,
            &view.plane,
            painter.clip_rect(),
            0.1,
            ink.gamma_multiply(0.06),
        );
        draw_frame(
            painter,
            labels,
            view,
            ink.gamma_multiply(0.5),
            self.extent * 0.25,
        );
        for (i, w) in self.chassis.wheels().iter().enumerate() {
            if w.kind.constrains_chassis() {
                let reach = self.extent * 4.0;
                draw_zero_motion_line(painter, labels, view, w, wheel_color(i), reach);
            }
        }
        draw_icr(
            painter,
            labels,
            view,
            &analysis.icr,
            theme::accent(ui),
            painter.clip_rect(),
        );
        if let Task::Goal(Goal::IcrAt { x, y, .. }) = self.task {
            let at = view.robot([x, y]);
            let good = theme::good_color(ui);
            painter.circle_stroke(at, 12.0, Stroke::new(1.5, good));
            labels.reserve(egui::Rect::from_center_size(at, vec2(26.0, 26.0)));
            labels
                .add(at, "goal", good)
                .toward(vec2(1.0, 0.0))
                .beyond(12.0);
        }
    }

    /// Draw each wheel and make it a handle; returns the wheel clicked, if any.
    fn wheel_handles(
        &mut self,
        ui: &mut egui::Ui,
        painter: &Painter,
        labels: &mut Labels,
        view: &RobotView,
    ) -> Option<usize> {
        let chosen: Vec<usize> = match &self.task {
            Task::FindDisagreeing { chosen, .. } => chosen.clone(),
            _ => Vec::new(),
        };
        let base = ui.scope_id().with("wheel");
        let mut clicked = None;
        for i in 0..self.chassis.wheels().len() {
            let w = self.chassis.wheels()[i].clone();
            let selected = self.selected == Some(i);
            draw_wheel(painter, view, &w, wheel_color(i), selected);
            let at = view.robot(w.position());
            // The number goes above the wheel when that is free.
            let label_at = at + vec2(0.0, -8.0 - w.radius as f32 * view.scale() * 0.4);
            let ink = ui.visuals().text_color();
            labels
                .add(label_at, (i + 1).to_string(), ink)
                .toward(vec2(0.0, -1.0));
            if chosen.contains(&i) {
                painter.circle_stroke(at, 16.0, Stroke::new(2.5, theme::error_color(ui)));
            }
            let h = handle(
                ui,
                base.with(i),
                at,
                13.0,
                &format!("Wheel {} ({})", i + 1, w.kind.name()),
            );
            if h.clicked() {
                clicked = Some(i);
            }
            if h.response.drag_started() {
                self.drag = Some(w.position());
                self.selected = Some(i);
            }
            if h.dragged() {
                self.move_wheel(i, &w, view, h.moved);
            }
            if h.response.drag_stopped() {
                self.drag = None;
            }
            if selected {
                self.steering_knob(ui, painter, view, i, &w, at);
            }
        }
        clicked
    }

    /// Move wheel `i` by a screen displacement, snapped to the grid, keeping
    /// its heading in the chassis.
    fn move_wheel(&mut self, i: usize, w: &Wheel, view: &RobotView, by: egui::Vec2) {
        let raw = self.drag.get_or_insert(w.position());
        raw[0] += f64::from(by.x / view.scale());
        raw[1] -= f64::from(by.y / view.scale());
        let (x, y) = (snap(raw[0], GRID), snap(raw[1], GRID));
        let heading = w.alpha + w.beta;
        let mut moved = w.clone();
        moved.l = x.hypot(y);
        moved.alpha = if moved.l > 0.0 { y.atan2(x) } else { 0.0 };
        moved.beta = wrap(heading - moved.alpha);
        let mut wheels = self.chassis.wheels().to_vec();
        wheels[i] = moved;
        self.try_set(wheels);
    }

    /// The selected wheel's knob: drag it to turn the wheel (in 5° steps).
    fn steering_knob(
        &mut self,
        ui: &mut egui::Ui,
        painter: &Painter,
        view: &RobotView,
        i: usize,
        w: &Wheel,
        at: Pos2,
    ) {
        let t = w.rolling_direction();
        let offset = if let WheelKind::Castor { offset } = w.kind {
            offset
        } else {
            0.0
        };
        let reach = w.radius + 0.06 + offset;
        let p = w.position();
        let knob = view.robot([p[0] + reach * t[0], p[1] + reach * t[1]]);
        painter.line_segment([at, knob], Stroke::new(1.0, ui.visuals().weak_text_color()));
        painter.circle(
            knob,
            6.0,
            theme::accent(ui),
            Stroke::new(1.5, Color32::WHITE),
        );
        let h = handle(
            ui,
            ui.scope_id().with(("knob", i)),
            knob,
            9.0,
            &format!("Turn wheel {}", i + 1),
        );
        if h.dragged() {
            // The pointer itself while dragging (small moves must add up),
            // the knob nudged by the arrow keys otherwise.
            let to = h.response.interact_pointer_pos().unwrap_or(knob + h.moved);
            let [qx, qy] = view.robot_point_at(to);
            let heading = snap((qy - p[1]).atan2(qx - p[0]).to_degrees(), ANGLE_STEP).to_radians();
            // Rolling along `heading` means α + β = heading + π/2.
            self.steer(i, wrap(heading + std::f64::consts::FRAC_PI_2 - w.alpha));
        }
    }

    /// A click on a wheel selects it (and marks it in the challenge); a
    /// click on empty ground clears the selection.
    pub(super) fn select(&mut self, clicked: Option<usize>, ground_clicked: bool) {
        if let Some(i) = clicked {
            if let Task::FindDisagreeing { chosen, feedback } = &mut self.task {
                if let Some(k) = chosen.iter().position(|c| *c == i) {
                    chosen.remove(k);
                } else {
                    chosen.push(i);
                }
                *feedback = None;
            }
            self.selected = Some(i);
        } else if ground_clicked {
            self.selected = None;
        }
    }
}
