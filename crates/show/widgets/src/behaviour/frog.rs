//! Blend or choose: a frog and two flies. Drag the flies; the frog on the
//! left adds the two pulls, the frog on the right lets the nearer fly win.

use egui::{RichText, Sense, Stroke, vec2};
use kinolab_behaviours::frog::{Combine, FLY_RADIUS, strike};
use kinolab_world::Vec2;
use serde::{Deserialize, Serialize};

use crate::draw::{PlaneView, canvas, corner_text, handle};
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::theme;
use crate::widget::{LabWidget, Params};

/// The widget's name in the schema.
const NAME: &str = "blend-or-choose";

/// What the lesson sets and a link carries: where the flies are.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    flies: [[f64; 2]; 2],
}

/// The links of the first format: the flies.
#[derive(Deserialize)]
struct Legacy {
    at: [[f64; 2]; 2],
}

struct Frog {
    settings: Settings,
    initial: Settings,
}

/// The frog sits at the bottom middle of a 1 m × 0.7 m pond.
const FROG: [f64; 2] = [0.0, 0.0];
const POND: ([f64; 2], [f64; 2]) = ([-0.5, -0.08], [0.5, 0.62]);

/// Flies stay this far above the frog, m.
const LOWEST_FLY: f64 = 0.1;

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    Ok(Box::new(Frog {
        initial: settings.clone(),
        settings,
    }))
}

/// What a way of combining the pulls does with the flies: `caught`, the
/// fly the tongue hits.
fn verdict(how: Combine, caught: Option<usize>) -> String {
    match (how, caught) {
        (Combine::Blend, None) => {
            "Blend: the pulls add up to a gap between the flies. Missed.".to_owned()
        }
        (Combine::Blend, Some(i)) => format!("Blend: caught fly {}.", i + 1),
        (Combine::Choose, Some(i)) => {
            format!("Choose: the nearer fly wins; caught fly {}.", i + 1)
        }
        (Combine::Choose, None) => "Choose: missed.".to_owned(),
    }
}

impl Frog {
    /// The flies where the learner put them.
    fn flies(&self) -> Vec<Vec2> {
        self.settings
            .flies
            .iter()
            .map(|f| Vec2::new(f[0], f[1]))
            .collect()
    }

    /// One pond; returns where it is on screen.
    fn scene(&mut self, ui: &mut egui::Ui, how: Combine, width: f32, id: &str) -> egui::Rect {
        let (response, painter) = canvas(ui, vec2(width, width * 0.7), Sense::hover());
        let rect = response.rect;
        let view = PlaneView::fit(rect.shrink(6.0), POND.0, POND.1);
        let ink = ui.visuals().text_color();
        let flies = self.flies();
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
            let f = self.settings.flies[i];
            let h = handle(
                ui,
                base.with(i),
                view.to_screen(f),
                10.0,
                &format!("Fly {}", i + 1),
            );
            if let Some([x, y]) = h.dragged_to(&view, f) {
                self.settings.flies[i] = [
                    x.clamp(POND.0[0], POND.1[0]),
                    y.clamp(LOWEST_FLY, POND.1[1]),
                ];
            }
        }
        corner_text(
            &painter,
            rect,
            0,
            verdict(how, s.and_then(|s| s.caught)),
            ink,
        );
        rect
    }
}

impl LabWidget for Frog {
    /// Where the flies are, and what blending and choosing each do.
    fn describe(&self) -> Option<String> {
        use kinolab_common::display::fixed;
        let flies = self.flies();
        let at: Vec<String> = flies
            .iter()
            .enumerate()
            .map(|(i, f)| format!("fly {} at ({}, {}) m", i + 1, fixed(f.x, 2), fixed(f.y, 2)))
            .collect();
        let frog = Vec2::new(FROG[0], FROG[1]);
        let verdicts: Vec<String> = [Combine::Blend, Combine::Choose]
            .into_iter()
            .map(|how| verdict(how, strike(frog, &flies, how).and_then(|s| s.caught)))
            .collect();
        Some(format!(
            "The frog sits at (0, 0) m, the middle of the pond's bank; {}. {}",
            at.join(", "),
            verdicts.join(" ")
        ))
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        let wide = ui.available_width() >= 560.0;
        let w = if wide {
            (ui.available_width() - 12.0) / 2.0
        } else {
            ui.available_width()
        };
        let ponds = if wide {
            ui.horizontal_top(|ui| {
                let a = self.scene(ui, Combine::Blend, w, "blend");
                a.union(self.scene(ui, Combine::Choose, w, "choose"))
            })
            .inner
        } else {
            let a = self.scene(ui, Combine::Blend, w, "blend");
            a.union(self.scene(ui, Combine::Choose, w, "choose"))
        };
        ui.label(
            RichText::new(
                "Drag either fly (in either pond). Thin arrows: each fly's pull; red: the tongue.",
            )
            .small(),
        );
        export::bar(
            ui,
            ui.scope_id().with("frog-exports"),
            &[Export::Png {
                file: "kinolab-blend-or-choose.png",
                rect: ponds,
            }],
        );
    }

    fn state(&self) -> Option<String> {
        link::write(
            NAME,
            &self.settings,
            &self.initial,
            &Moment::<()>::default(),
        )
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let settings = match link::read::<Settings, ()>(NAME, state) {
            Ok((settings, _)) => settings,
            Err(why) => match link::decode::<Legacy>(state) {
                Some(old) => Settings { flies: old.at },
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema's ranges too.
        link::check(NAME, &settings)?;
        self.settings = settings;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::{create, spec};

    fn frog(params: &[(&str, &str)]) -> Frog {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        let settings: Settings = p.settings().unwrap_or_else(|e| panic!("{e}"));
        Frog {
            initial: settings.clone(),
            settings,
        }
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        let old = link::encode(&((-0.2_f64, 0.3_f64), (0.25_f64, 0.5_f64))).unwrap_or_default();
        let mut w = frog(&[]);
        assert_eq!(w.restore(&old), Ok(()));
        assert_eq!(w.settings.flies, [[-0.2, 0.3], [0.25, 0.5]]);
        // Off the pond: refused, the lesson's flies kept.
        let bad = link::encode(&((-0.2_f64, 0.3_f64), (4.0_f64, 0.5_f64))).unwrap_or_default();
        let mut w = frog(&[("flies", "0.1, 0.2; 0.3, 0.4")]);
        assert!(w.restore(&bad).is_err());
        assert_eq!(w.settings.flies, [[0.1, 0.2], [0.3, 0.4]]);
        assert!(create(&spec(NAME, &[])).is_ok());
    }

    #[test]
    fn moved_flies_travel_in_the_link() {
        let mut w = frog(&[]);
        assert_eq!(w.state(), None, "as the lesson set it");
        w.settings.flies[1] = [0.05, 0.6];
        let text = w.state().unwrap_or_default();
        let mut again = frog(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.settings, w.settings);
    }
}
