//! The arena's picture: the world, the robot, its rays, each behaviour's
//! arrow and the command; obstacles and the goal can be dragged.

use egui::{Sense, Stroke, vec2};
use kinolab_world::Vec2;

use super::{Arena, Shown};
use crate::behaviour::world_view::{color, draw_robot, draw_trail, draw_world};
use crate::draw::marks::arrow;
use crate::draw::{PlaneView, handle};

/// Screen points per m/s of an arrow.
const ARROW_SCALE: f32 = 110.0;

impl Arena {
    /// The world and the robot at the instant shown; returns where it is
    /// on screen.
    pub(super) fn canvas(&mut self, ui: &mut egui::Ui, width: f32) -> egui::Rect {
        let Some(setup) = self.setup.clone() else {
            return egui::Rect::NOTHING;
        };
        let b = setup.world.bounds;
        let height = (width * (b.height() / b.width()) as f32).clamp(200.0, 520.0);
        let (rect, _) = ui.allocate_exact_size(vec2(width, height), Sense::hover());
        let view = PlaneView::fit(rect.shrink(4.0), [b.x_min, b.y_min], [b.x_max, b.y_max]);
        let painter = ui.painter_at(rect);
        let ink = ui.visuals().text_color();
        let Some(player) = &mut self.player else {
            return rect;
        };
        let t = player.time();
        draw_world(ui, &painter, &view, &setup.world, t);
        let start = setup.world.start;
        let trail = std::iter::once([start.x, start.y])
            .chain(player.ticks_shown().iter().map(|r| [r.pose.x, r.pose.y]));
        draw_trail(&painter, &view, trail, ink.gamma_multiply(0.5));
        let run = player.state();
        let pose = run.runner.sim.pose;
        let radius = setup.body.radius();
        if let Some(r) = &run.last {
            let at = view.to_screen([pose.x, pose.y]);
            for ray in &r.rays {
                let a = pose.theta + ray.angle;
                let end = [pose.x + ray.range * a.cos(), pose.y + ray.range * a.sin()];
                let c = if ray.hit {
                    ink.gamma_multiply(0.45)
                } else {
                    ink.gamma_multiply(0.15)
                };
                painter.line_segment([at, view.to_screen(end)], Stroke::new(1.0, c));
            }
        }
        let body = in_control_color(run.last.as_ref().and_then(|r| r.in_control));
        draw_robot(&painter, &view, &pose, radius, body, ink);
        if let Some(r) = &run.last {
            arrows(&painter, &view, &pose, r, ink);
        }
        self.drag(ui, &view);
        self.legend(ui, rect);
        rect
    }

    /// Obstacles and the goal as handles; a drag restarts the run.
    fn drag(&mut self, ui: &mut egui::Ui, view: &PlaneView) {
        let Some(setup) = &self.setup else { return };
        let base = ui.scope_id().with("arena");
        let mut edit = None;
        for (i, o) in setup.world.obstacles.iter().enumerate() {
            if !o.is_static() || o.appear_at > 0.0 {
                continue;
            }
            let a = o.shape.anchor();
            let h = handle(
                ui,
                base.with(i),
                view.to_screen([a.x, a.y]),
                9.0,
                &format!("Obstacle {}", i + 1),
            );
            if let Some(to) = h.dragged_to(view, [a.x, a.y]) {
                edit = Some((Some(i), to));
            }
        }
        if let Some(g) = setup.world.goal {
            let h = handle(
                ui,
                base.with("goal"),
                view.to_screen([g.x, g.y]),
                10.0,
                "Goal",
            );
            if let Some(to) = h.dragged_to(view, [g.x, g.y]) {
                edit = Some((None, to));
            }
        }
        let Some((which, at)) = edit else { return };
        let at = setup.world.bounds.clamp(at[0], at[1]);
        let mut settings = self.settings.clone();
        match which {
            Some(i) => {
                settings.moved.retain(|m| m[0] as usize != i);
                settings.moved.push([i as f64, at[0], at[1]]);
            }
            None => settings.goal = Some(at),
        }
        // The run starts again; when the robot no longer fits at its
        // start, the move is undone.
        let playing = self.player.as_ref().is_some_and(|p| p.playing);
        self.change(settings);
        if let Some(player) = &mut self.player {
            player.playing = playing;
        }
    }

    fn legend(&self, ui: &egui::Ui, rect: egui::Rect) {
        let painter = ui.painter_at(rect);
        let font = egui::FontId::proportional(crate::theme::TITLE_SIZE);
        let names = self.names();
        let backdrop = egui::Rect::from_min_size(
            rect.left_top() + vec2(4.0, 4.0),
            vec2(110.0, 17.0 * (names.len() + 1) as f32 + 8.0),
        );
        painter.rect_filled(
            backdrop,
            4.0,
            ui.visuals().extreme_bg_color.gamma_multiply(0.85),
        );
        let mut y = rect.top() + 16.0;
        for (i, name) in names.iter().enumerate() {
            let at = egui::pos2(rect.left() + 10.0, y);
            painter.line_segment([at, at + vec2(18.0, 0.0)], Stroke::new(3.0, color(i)));
            painter.text(
                at + vec2(24.0, 0.0),
                egui::Align2::LEFT_CENTER,
                name,
                font.clone(),
                ui.visuals().text_color(),
            );
            y += 17.0;
        }
        let at = egui::pos2(rect.left() + 10.0, y);
        painter.line_segment(
            [at, at + vec2(18.0, 0.0)],
            Stroke::new(4.0, ui.visuals().text_color()),
        );
        painter.text(
            at + vec2(24.0, 0.0),
            egui::Align2::LEFT_CENTER,
            "command",
            font,
            ui.visuals().text_color(),
        );
    }
}

/// Each behaviour's arrow and the command's, from the robot.
fn arrows(
    painter: &egui::Painter,
    view: &PlaneView,
    pose: &kinolab_world::Pose,
    r: &Shown,
    ink: egui::Color32,
) {
    let at = view.to_screen([pose.x, pose.y]);
    let world_dir = |v: Vec2| {
        let (s, c) = pose.theta.sin_cos();
        vec2((c * v.x - s * v.y) as f32, -(s * v.x + c * v.y) as f32)
    };
    for (i, v) in r.vectors.iter().enumerate() {
        if let Some(v) = v {
            arrow(
                painter,
                at,
                world_dir(*v) * ARROW_SCALE,
                8.0,
                Stroke::new(2.0, color(i)),
            );
        }
    }
    let cmd = Vec2::new(r.command.vx, r.command.vy);
    arrow(
        painter,
        at,
        world_dir(cmd) * ARROW_SCALE,
        11.0,
        Stroke::new(4.0, ink),
    );
}

/// The robot takes the colour of the behaviour in control.
pub(super) fn in_control_color(in_control: Option<usize>) -> egui::Color32 {
    in_control.map_or(crate::theme::NEUTRAL, color)
}
