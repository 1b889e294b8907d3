//! Static stability, hands on: drag the feet and the centre of mass of a
//! walker seen from above; click a foot to lift or lower it.

use egui::{Color32, Painter, Pos2, Rect, RichText, Sense, Stroke, vec2};
use kinolab_common::display::fixed;
use kinolab_locomotion::{Point, Stability, static_stability};
use serde::{Deserialize, Serialize};

use super::{draw_foot, draw_support};
use crate::draw::labels::Labels;
use crate::draw::{PlaneView, canvas, handle, marks};
use crate::widget::{LabWidget, Params};
use crate::{link, theme};

/// Half-extent of the visible ground, metres.
const VIEW_HALF_WIDTH: f64 = 0.5;
const VIEW_HALF_HEIGHT: f64 = 0.32;

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Foot {
    at: Point,
    on_ground: bool,
}

/// Everything the learner can change, and what a link carries.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Stance {
    feet: Vec<Foot>,
    com: Point,
}

struct SupportPolygon {
    stance: Stance,
    initial: Stance,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let legs = p.integer("legs").unwrap_or(4).clamp(3, 8) as usize;
    let stance = Stance::new(legs);
    Ok(Box::new(SupportPolygon {
        initial: stance.clone(),
        stance,
    }))
}

impl Stance {
    /// Feet spread evenly on an ellipse around the body, starting front-left.
    fn new(legs: usize) -> Self {
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
            feet,
            com: [0.0, 0.0],
        }
    }

    fn grounded(&self) -> Vec<Point> {
        self.feet
            .iter()
            .filter(|f| f.on_ground)
            .map(|f| f.at)
            .collect()
    }
}

fn clamp(p: Point) -> Point {
    [
        p[0].clamp(-VIEW_HALF_WIDTH, VIEW_HALF_WIDTH),
        p[1].clamp(-VIEW_HALF_HEIGHT, VIEW_HALF_HEIGHT),
    ]
}

/// A point moved by a screen displacement, kept on the visible ground.
fn moved(view: &PlaneView, p: Point, by: egui::Vec2) -> Point {
    let d = view.delta_to_world(by);
    clamp([p[0] + d[0], p[1] + d[1]])
}

impl SupportPolygon {
    /// The feet and the centre of mass as handles: drag to move, click a
    /// foot to lift or lower it.
    fn input(&mut self, ui: &mut egui::Ui, view: &PlaneView) {
        let base = ui.scope_id().with("feet");
        for (i, foot) in self.stance.feet.iter_mut().enumerate() {
            let state = if foot.on_ground {
                "on the ground"
            } else {
                "lifted"
            };
            let label = format!("Foot {} ({state})", i + 1);
            let h = handle(ui, base.with(i), view.to_screen(foot.at), 12.0, &label);
            if h.dragged() {
                foot.at = moved(view, foot.at, h.moved);
            } else if h.clicked() {
                foot.on_ground = !foot.on_ground;
            }
        }
        let com_at = view.to_screen(self.stance.com);
        let h = handle(
            ui,
            ui.scope_id().with("com"),
            com_at,
            12.0,
            "Centre of mass",
        );
        if h.dragged() {
            self.stance.com = moved(view, self.stance.com, h.moved);
        }
    }

    fn draw(
        &self,
        ui: &egui::Ui,
        painter: &Painter,
        view: &PlaneView,
        verdict: Option<&Stability>,
    ) {
        let ink = ui.visuals().text_color();
        let mut labels = Labels::default();
        if let Some(s) = verdict {
            let color = verdict_color(ui, s);
            draw_support(painter, &mut labels, view, s, self.stance.com, color);
        }
        let com = view.to_screen(self.stance.com);
        labels.reserve(Rect::from_center_size(com, vec2(20.0, 20.0)));
        self.draw_feet(painter, &mut labels, view, ink);
        draw_com(painter, com, theme::accent(ui));
        labels.draw(painter, &egui::FontId::proportional(theme::LABEL_SIZE));
    }

    fn draw_feet(&self, painter: &Painter, labels: &mut Labels, view: &PlaneView, ink: Color32) {
        for (i, foot) in self.stance.feet.iter().enumerate() {
            let out = egui::Vec2::new(foot.at[0] as f32, -foot.at[1] as f32);
            let at = view.to_screen(foot.at);
            let name = (i + 1).to_string();
            draw_foot(painter, labels, at, foot.on_ground, out, &name, ink);
        }
    }
}

fn draw_com(painter: &Painter, at: Pos2, color: Color32) {
    painter.circle(at, 8.0, color, Stroke::new(1.5, Color32::WHITE));
    marks::plus(painter, at, 5.0, Stroke::new(1.5, Color32::WHITE));
}

fn verdict_color(ui: &egui::Ui, s: &Stability) -> Color32 {
    if s.stable {
        theme::good_color(ui)
    } else {
        theme::error_color(ui)
    }
}

/// The verdict in words, the margin to the millimetre.
fn verdict_text(verdict: Option<&Stability>) -> String {
    let Some(s) = verdict else {
        return "No foot is on the ground: the walker falls.".into();
    };
    let cm = fixed(s.margin * 100.0, 1);
    if s.polygon.len() < 3 {
        "Not statically stable: the feet on the ground enclose no area.".into()
    } else if s.stable {
        format!("Statically stable: stability margin {cm} cm")
    } else if cm == "0.0" {
        "On the edge: the centre of mass lies on the polygon's border (margin 0).".into()
    } else {
        format!(
            "Tips over: the centre of mass is {} cm outside the support polygon",
            fixed(-s.margin * 100.0, 1)
        )
    }
}

impl LabWidget for SupportPolygon {
    fn ui(&mut self, ui: &mut egui::Ui) {
        let width = ui.available_width().min(720.0);
        let (response, painter) = canvas(ui, vec2(width, 320.0), Sense::hover());
        let rect = response.rect;
        let view = PlaneView::fit(
            rect,
            [-VIEW_HALF_WIDTH, -VIEW_HALF_HEIGHT],
            [VIEW_HALF_WIDTH, VIEW_HALF_HEIGHT],
        );
        self.input(ui, &view);
        let verdict = static_stability(self.stance.com, &self.stance.grounded()).ok();
        self.draw(ui, &painter, &view, verdict.as_ref());
        painter.text(
            rect.right_top() + vec2(-10.0, 10.0),
            egui::Align2::RIGHT_TOP,
            "seen from above, front to the right →",
            egui::FontId::proportional(theme::SMALL_SIZE),
            ui.visuals().weak_text_color(),
        );
        let color = verdict
            .as_ref()
            .map_or(theme::error_color(ui), |s| verdict_color(ui, s));
        ui.label(
            RichText::new(verdict_text(verdict.as_ref()))
                .strong()
                .color(color),
        );
        let lifted = self.stance.feet.iter().filter(|f| !f.on_ground).count();
        ui.horizontal_wrapped(|ui| {
            ui.label(RichText::new(format!("{lifted} of {} feet lifted. Drag a foot or the blue centre of mass; click a foot to lift or lower it.", self.stance.feet.len())).small());
            if ui.button("Reset stance").clicked() {
                self.stance = self.initial.clone();
            }
        });
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.stance, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(stance) = link::decode::<Stance>(state)
            && stance.feet.len() == self.initial.feet.len()
            && stance
                .feet
                .iter()
                .all(|f| f.at.iter().all(|c| c.is_finite()))
            && stance.com.iter().all(|c| c.is_finite())
        {
            self.stance = Stance {
                feet: stance
                    .feet
                    .into_iter()
                    .map(|f| Foot {
                        at: clamp(f.at),
                        ..f
                    })
                    .collect(),
                com: clamp(stance.com),
            };
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_verdict_never_reads_minus_zero() {
        let square = [[-0.1, -0.1], [0.1, -0.1], [0.1, 0.1], [-0.1, 0.1]];
        let edge = static_stability([0.1 - 1e-17, 0.0], &square).ok();
        let text = verdict_text(edge.as_ref());
        assert!(!text.contains("-0.0"), "{text}");
        let inside = static_stability([0.0, 0.0], &square).ok();
        assert_eq!(
            verdict_text(inside.as_ref()),
            "Statically stable: stability margin 10.0 cm"
        );
        let outside = static_stability([0.15, 0.0], &square).ok();
        assert_eq!(
            verdict_text(outside.as_ref()),
            "Tips over: the centre of mass is 5.0 cm outside the support polygon"
        );
    }
}
