//! Blend or choose: a frog and two flies. Drag the flies; the frog on the
//! left adds the two pulls, the frog on the right lets the nearer fly win.

use egui::{RichText, Sense, Stroke, vec2};
use kinolab_behaviours::frog::{Combine, FLY_RADIUS, strike};
use kinolab_world::Vec2;
use serde::{Deserialize, Serialize};

use crate::draw::{PlaneView, canvas, corner_text, handle};
use crate::widget::{LabWidget, Params};
use crate::{link, theme};

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Flies {
    at: [[f64; 2]; 2],
}

struct Frog {
    flies: Flies,
    initial: Flies,
}

/// The frog sits at the bottom middle of a 1 m × 0.7 m pond.
const FROG: [f64; 2] = [0.0, 0.0];
const POND: ([f64; 2], [f64; 2]) = ([-0.5, -0.08], [0.5, 0.62]);

pub fn create(_: &Params) -> Result<Box<dyn LabWidget>, String> {
    let flies = Flies {
        at: [[-0.3, 0.4], [0.32, 0.42]],
    };
    Ok(Box::new(Frog {
        initial: flies.clone(),
        flies,
    }))
}

impl Frog {
    fn scene(&mut self, ui: &mut egui::Ui, how: Combine, width: f32, id: &str) {
        let (response, painter) = canvas(ui, vec2(width, width * 0.7), Sense::hover());
        let rect = response.rect;
        let view = PlaneView::fit(rect.shrink(6.0), POND.0, POND.1);
        let ink = ui.visuals().text_color();
        let flies: Vec<Vec2> = self
            .flies
            .at
            .iter()
            .map(|f| Vec2::new(f[0], f[1]))
            .collect();
        let frog = Vec2::new(FROG[0], FROG[1]);
        let s = strike(frog, &flies, how);
        let at = view.to_screen(FROG);
        painter.circle(at, 16.0, theme::GREEN, Stroke::new(1.5, ink));
        for (i, f) in flies.iter().enumerate() {
            let p = view.to_screen([f.x, f.y]);
            let caught = s.is_some_and(|s| s.caught == Some(i));
            let color = if caught { theme::good_color(ui) } else { ink };
            painter.circle_stroke(
                p,
                view.length(FLY_RADIUS),
                Stroke::new(1.0, color.gamma_multiply(0.5)),
            );
            painter.circle_filled(p, 5.0, color);
            for side in [-1.0, 1.0] {
                painter.circle_stroke(p + vec2(side * 6.0, -4.0), 4.0, Stroke::new(1.0, color));
            }
            // The fly's pull on the frog: a unit arrow towards it.
            let pull = (f - frog).normalize();
            let along = vec2(pull.x as f32, -pull.y as f32) * view.length(0.15);
            crate::draw::marks::arrow(
                &painter,
                at,
                along,
                6.0,
                Stroke::new(1.5, ink.gamma_multiply(0.6)),
            );
        }
        if let Some(s) = s {
            let tip = [
                FROG[0] + s.direction[0] * s.reach,
                FROG[1] + s.direction[1] * s.reach,
            ];
            painter.line_segment([at, view.to_screen(tip)], Stroke::new(4.0, theme::RED));
        }
        let base = ui.scope_id().with(id);
        for i in 0..2 {
            let f = self.flies.at[i];
            let h = handle(
                ui,
                base.with(i),
                view.to_screen(f),
                10.0,
                &format!("Fly {}", i + 1),
            );
            if let Some([x, y]) = h.dragged_to(&view, f) {
                self.flies.at[i] = [x.clamp(POND.0[0], POND.1[0]), y.clamp(0.1, POND.1[1])];
            }
        }
        let verdict = match (how, s.and_then(|s| s.caught)) {
            (Combine::Blend, None) => {
                "Blend: the pulls add up to a gap between the flies. Missed.".to_owned()
            }
            (Combine::Blend, Some(i)) => format!("Blend: caught fly {}.", i + 1),
            (Combine::Choose, Some(i)) => {
                format!("Choose: the nearer fly wins; caught fly {}.", i + 1)
            }
            (Combine::Choose, None) => "Choose: missed.".to_owned(),
        };
        corner_text(&painter, rect, 0, verdict, ink);
    }
}

impl LabWidget for Frog {
    fn ui(&mut self, ui: &mut egui::Ui) {
        let wide = ui.available_width() >= 560.0;
        let w = if wide {
            (ui.available_width() - 12.0) / 2.0
        } else {
            ui.available_width()
        };
        if wide {
            ui.horizontal_top(|ui| {
                self.scene(ui, Combine::Blend, w, "blend");
                self.scene(ui, Combine::Choose, w, "choose");
            });
        } else {
            self.scene(ui, Combine::Blend, w, "blend");
            self.scene(ui, Combine::Choose, w, "choose");
        }
        ui.label(
            RichText::new(
                "Drag either fly (in either pond). Thin arrows: each fly's pull; red: the tongue.",
            )
            .small(),
        );
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.flies, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(f) = link::decode::<Flies>(state)
            && f.at.iter().flatten().all(|v| v.is_finite())
        {
            self.flies = f;
        }
        Ok(())
    }
}
