//! The arena's picture: the world, the robot, its rays, each behaviour's
//! arrow and the command; obstacles and the goal can be dragged.

use egui::{Sense, Stroke, vec2};
use kinolab_world::Vec2;

use super::{Arena, Shown};
use crate::behaviour::world_view::{draw_robot, draw_trail, draw_world};
use crate::draw::marks::arrow;
use crate::draw::{PlaneView, handle};

/// Screen points per m/s of an arrow.
const ARROW_SCALE: f32 = 110.0;

impl Arena {
    /// The world and the robot at the instant shown, with its legend
    /// underneath; returns where the drawing is on screen.
    pub(super) fn canvas(&mut self, ui: &mut egui::Ui, width: f32) -> egui::Rect {
        ui.vertical(|ui| {
            let rect = self.scene(ui, width);
            self.legend(ui);
            rect
        })
        .inner
    }

    fn scene(&mut self, ui: &mut egui::Ui, width: f32) -> egui::Rect {
        let Some(setup) = self.setup.clone() else {
            return egui::Rect::NOTHING;
        };
        let b = setup.world.bounds;
        let height = (width * (b.height() / b.width()) as f32).clamp(200.0, 520.0);
        let (rect, _) = ui.allocate_exact_size(vec2(width, height), Sense::hover());
        let view = PlaneView::fit(rect.shrink(4.0), [b.x_min, b.y_min], [b.x_max, b.y_max]);
        let painter = ui.painter_at(rect);
        let ink = ui.visuals().text_color();
        let colors = self.colors();
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
        let body = in_control_color(&colors, run.last.as_ref().and_then(|r| r.in_control));
        draw_robot(&painter, &view, &pose, radius, body, ink);
        if let Some(r) = &run.last {
            arrows(&painter, &view, &pose, r, &colors, ink);
        }
        self.drag(ui, &view);
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

    /// Under the drawing, never on it: each behaviour's colour, and the
    /// command's.
    fn legend(&self, ui: &mut egui::Ui) {
        let names = self.names();
        let colors = self.colors();
        let mut entries: Vec<(&str, egui::Color32)> =
            names.iter().map(String::as_str).zip(colors).collect();
        entries.push(("command", ui.visuals().text_color()));
        crate::draw::plot::legend(ui, &entries);
    }
}

/// Each behaviour's arrow and the command's, from the robot.
fn arrows(
    painter: &egui::Painter,
    view: &PlaneView,
    pose: &kinolab_world::Pose,
    r: &Shown,
    colors: &[egui::Color32],
    ink: egui::Color32,
) {
    let at = view.to_screen([pose.x, pose.y]);
    let world_dir = |v: Vec2| {
        let (s, c) = pose.theta.sin_cos();
        vec2((c * v.x - s * v.y) as f32, -(s * v.x + c * v.y) as f32)
    };
    for (v, &color) in r.vectors.iter().zip(colors) {
        if let Some(v) = v {
            arrow(
                painter,
                at,
                world_dir(*v) * ARROW_SCALE,
                8.0,
                Stroke::new(2.0, color),
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
pub(super) fn in_control_color(
    colors: &[egui::Color32],
    in_control: Option<usize>,
) -> egui::Color32 {
    in_control
        .and_then(|i| colors.get(i).copied())
        .unwrap_or(crate::theme::NEUTRAL)
}
