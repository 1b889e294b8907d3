//! Static stability, hands on: drag the feet and the centre of mass of a
//! walker seen from above; click a foot to lift or lower it.

use egui::{Color32, Pos2, RichText, Sense, Shape, Stroke, pos2, vec2};
use kinolab_lessons::WidgetSpec;
use kinolab_locomotion::{Point, static_stability};

use super::{LabWidget, known_params, number_param};
use crate::theme;

/// Half-extent of the visible ground, metres.
const VIEW_HALF_WIDTH: f64 = 0.5;
const VIEW_HALF_HEIGHT: f64 = 0.32;

struct Foot {
    at: Point,
    on_ground: bool,
}

struct SupportPolygon {
    legs: usize,
    feet: Vec<Foot>,
    com: Point,
}

pub(super) fn create(spec: &WidgetSpec) -> Result<Box<dyn LabWidget>, String> {
    known_params(spec, &["legs"])?;
    let legs = number_param(spec, "legs", 4.0, 3.0..=8.0)? as usize;
    Ok(Box::new(SupportPolygon::new(legs)))
}

impl SupportPolygon {
    fn new(legs: usize) -> Self {
        // Feet spread evenly on an ellipse around the body, starting front-right.
        let feet = (0..legs)
            .map(|i| {
                let angle = std::f64::consts::TAU * (i as f64 + 0.5) / legs as f64;
                Foot {
                    at: [0.3 * angle.cos(), 0.2 * angle.sin()],
                    on_ground: true,
                }
            })
            .collect();
        Self {
            legs,
            feet,
            com: [0.0, 0.0],
        }
    }
}

/// Maps ground metres to screen points (y up on the ground, down on screen).
struct View {
    centre: Pos2,
    scale: f32,
}

impl View {
    fn to_screen(&self, p: Point) -> Pos2 {
        pos2(
            self.centre.x + p[0] as f32 * self.scale,
            self.centre.y - p[1] as f32 * self.scale,
        )
    }

    fn to_ground(&self, delta: egui::Vec2) -> Point {
        [
            f64::from(delta.x / self.scale),
            f64::from(-delta.y / self.scale),
        ]
    }

    fn clamp(p: Point) -> Point {
        [
            p[0].clamp(-VIEW_HALF_WIDTH, VIEW_HALF_WIDTH),
            p[1].clamp(-VIEW_HALF_HEIGHT, VIEW_HALF_HEIGHT),
        ]
    }
}

/// A draggable handle; returns its response.
fn handle(ui: &mut egui::Ui, id: egui::Id, at: Pos2, label: String) -> egui::Response {
    let rect = egui::Rect::from_center_size(at, vec2(24.0, 24.0));
    let response = ui.interact(rect, id, Sense::click_and_drag());
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Button, true, label.clone()));
    response.on_hover_cursor(egui::CursorIcon::Grab)
}

impl LabWidget for SupportPolygon {
    fn ui(&mut self, ui: &mut egui::Ui) {
        let width = ui.available_width().min(720.0);
        let height = 320.0;
        let (response, painter) = ui.allocate_painter(vec2(width, height), Sense::hover());
        let rect = response.rect;
        let view = View {
            centre: rect.center(),
            scale: (rect.width() / (2.0 * VIEW_HALF_WIDTH as f32))
                .min(rect.height() / (2.0 * VIEW_HALF_HEIGHT as f32)),
        };
        painter.rect_filled(rect, 6.0, ui.visuals().extreme_bg_color);

        let grounded: Vec<Point> = self
            .feet
            .iter()
            .filter(|f| f.on_ground)
            .map(|f| f.at)
            .collect();
        let verdict = static_stability(self.com, &grounded);
        let text_color = ui.visuals().text_color();
        let good = theme::good_color(ui);
        let bad = theme::warn_color(ui);

        // The support polygon and the margin.
        if let Ok(s) = &verdict {
            let color = if s.stable { good } else { bad };
            let corners: Vec<Pos2> = s.polygon.iter().map(|&p| view.to_screen(p)).collect();
            if corners.len() >= 3 {
                painter.add(Shape::convex_polygon(
                    corners,
                    color.gamma_multiply(0.18),
                    Stroke::new(2.0, color),
                ));
            } else if corners.len() == 2 {
                painter.line_segment([corners[0], corners[1]], Stroke::new(2.0, color));
            }
            painter.line_segment(
                [view.to_screen(self.com), view.to_screen(s.nearest)],
                Stroke::new(1.5, color),
            );
        }

        // Body outline, for orientation: the front is to the right.
        let body = egui::Rect::from_center_size(
            view.to_screen([0.0, 0.0]),
            vec2(0.36 * view.scale, 0.2 * view.scale),
        );
        painter.rect_stroke(
            body,
            8.0,
            Stroke::new(1.0, text_color.gamma_multiply(0.4)),
            egui::StrokeKind::Middle,
        );
        painter.text(
            rect.right_top() + vec2(-10.0, 10.0),
            egui::Align2::RIGHT_TOP,
            "seen from above, front to the right →",
            egui::FontId::proportional(11.0),
            text_color.gamma_multiply(0.6),
        );

        // Feet: drag to move, click to lift or lower.
        let base_id = ui.scope_id().with("feet");
        for (i, foot) in self.feet.iter_mut().enumerate() {
            let at = view.to_screen(foot.at);
            let state = if foot.on_ground {
                "on the ground"
            } else {
                "lifted"
            };
            let r = handle(ui, base_id.with(i), at, format!("Foot {} ({state})", i + 1));
            if r.dragged() {
                let d = view.to_ground(r.drag_delta());
                foot.at = View::clamp([foot.at[0] + d[0], foot.at[1] + d[1]]);
            } else if r.clicked() {
                foot.on_ground = !foot.on_ground;
            }
            let stroke = Stroke::new(2.0, text_color);
            if foot.on_ground {
                painter.circle(at, 9.0, text_color.gamma_multiply(0.8), stroke);
            } else {
                painter.circle_stroke(at, 9.0, Stroke::new(2.0, text_color.gamma_multiply(0.5)));
                painter.circle_stroke(at, 13.0, Stroke::new(1.0, text_color.gamma_multiply(0.3)));
            }
            painter.text(
                at + vec2(0.0, -16.0),
                egui::Align2::CENTER_BOTTOM,
                (i + 1).to_string(),
                egui::FontId::proportional(12.0),
                text_color,
            );
        }

        // Centre of mass.
        let com_at = view.to_screen(self.com);
        let r = handle(
            ui,
            ui.scope_id().with("com"),
            com_at,
            "Centre of mass".to_owned(),
        );
        if r.dragged() {
            let d = view.to_ground(r.drag_delta());
            self.com = View::clamp([self.com[0] + d[0], self.com[1] + d[1]]);
        }
        let com_color = theme::accent(ui);
        painter.circle(com_at, 8.0, com_color, Stroke::new(1.5, Color32::WHITE));
        painter.line_segment(
            [com_at - vec2(5.0, 0.0), com_at + vec2(5.0, 0.0)],
            Stroke::new(1.5, Color32::WHITE),
        );
        painter.line_segment(
            [com_at - vec2(0.0, 5.0), com_at + vec2(0.0, 5.0)],
            Stroke::new(1.5, Color32::WHITE),
        );

        // The verdict in words.
        let lifted = self.feet.iter().filter(|f| !f.on_ground).count();
        match verdict {
            Ok(s) if s.stable => {
                ui.label(
                    RichText::new(format!(
                        "Statically stable: stability margin {:.1} cm",
                        s.margin * 100.0
                    ))
                    .strong()
                    .color(good),
                );
            }
            Ok(s) if s.polygon.len() < 3 => {
                ui.label(
                    RichText::new("Not statically stable: the feet on the ground enclose no area.")
                        .strong()
                        .color(bad),
                );
            }
            Ok(s) if s.margin == 0.0 => {
                ui.label(
                    RichText::new(
                        "On the edge: the centre of mass lies on the polygon's border (margin 0).",
                    )
                    .strong()
                    .color(bad),
                );
            }
            Ok(s) => {
                ui.label(
                    RichText::new(format!(
                        "Tips over: the centre of mass is {:.1} cm outside the support polygon",
                        -s.margin * 100.0
                    ))
                    .strong()
                    .color(bad),
                );
            }
            Err(_) => {
                ui.label(
                    RichText::new("No foot is on the ground: the walker falls.")
                        .strong()
                        .color(bad),
                );
            }
        }
        ui.horizontal(|ui| {
            ui.label(RichText::new(format!("{} of {} feet lifted. Drag a foot or the blue centre of mass; click a foot to lift or lower it.", lifted, self.feet.len())).small());
            if ui.button("Reset stance").clicked() {
                *self = SupportPolygon::new(self.legs);
            }
        });
    }
}
