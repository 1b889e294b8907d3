//! Technology churn: the same application designed stably and naively, as
//! class graphs side by side; replace an industrial object and the classes
//! whose code must change light up, counted by the core.

use egui::{Align2, FontId, Pos2, RichText, Sense, Stroke, pos2, vec2};
use kinolab_design::churn::{Design, Layer, SWAPS, naive, stable};
use serde::{Deserialize, Serialize};

use crate::draw::canvas;
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::theme;
use crate::widget::{LabWidget, Params};

/// The widget's name in the schema.
const NAME: &str = "technology-churn";

/// What the lesson sets and a link carries: the schema's parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    /// The industrial object replaced (none yet when `None`).
    swap: Option<String>,
}

struct Churn {
    settings: Settings,
    initial: Settings,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    Ok(Box::new(Churn {
        initial: settings.clone(),
        settings,
    }))
}

impl Settings {
    /// The object replaced, as the core names it.
    fn swap(&self) -> Option<&'static str> {
        let swap = self.swap.as_deref()?;
        SWAPS.iter().map(|(io, _)| *io).find(|io| *io == swap)
    }
}

/// Where each class sits: logic on top, business objects in the middle,
/// industrial objects at the bottom.
fn positions(design: &Design, rect: egui::Rect) -> Vec<(&'static str, Pos2)> {
    let rows = [Layer::Logic, Layer::Bo, Layer::Io];
    let mut out = Vec::new();
    for (r, layer) in rows.iter().enumerate() {
        let names: Vec<&'static str> = design
            .classes
            .iter()
            .filter(|c| c.layer == *layer)
            .map(|c| c.name)
            .collect();
        for (i, name) in names.iter().enumerate() {
            let x = rect.left() + rect.width() * (i as f32 + 0.5) / names.len().max(1) as f32;
            let y = rect.top() + 22.0 + r as f32 * (rect.height() - 80.0) / 2.0;
            out.push((*name, pos2(x, y)));
        }
    }
    out
}

/// One design's class graph; where it was drawn.
fn draw(
    ui: &mut egui::Ui,
    design: &Design,
    edited: &[&str],
    swapped: Option<&str>,
    width: f32,
) -> egui::Rect {
    let (response, painter) = canvas(ui, vec2(width, 230.0), Sense::hover());
    let rect = response.rect;
    let at = positions(design, rect.shrink2(vec2(6.0, 6.0)));
    let pos = |name: &str| at.iter().find(|(n, _)| *n == name).map(|(_, p)| *p);
    let faint = ui.visuals().weak_text_color();
    for (user, used) in &design.uses {
        if let (Some(a), Some(b)) = (pos(user), pos(used)) {
            let hot = Some(*used) == swapped && edited.contains(user);
            let stroke = if hot {
                Stroke::new(2.0, theme::error_color(ui))
            } else {
                Stroke::new(1.0, faint)
            };
            painter.add(egui::Shape::line(link_line(a, b), stroke));
        }
    }
    let ink = ui.visuals().text_color();
    for c in &design.classes {
        let Some(p) = pos(c.name) else { continue };
        let fill = match c.layer {
            Layer::Logic => theme::BLUE.gamma_multiply(0.25),
            Layer::Bo => theme::GREEN.gamma_multiply(0.3),
            Layer::Io => theme::ORANGE.gamma_multiply(0.3),
        };
        let font = FontId::proportional(theme::SMALL_SIZE);
        let size = painter
            .layout_no_wrap(c.name.to_owned(), font.clone(), ink)
            .size()
            + vec2(10.0, 6.0);
        let r = egui::Rect::from_center_size(p, size);
        let outline = if edited.contains(&c.name) || Some(c.name) == swapped {
            Stroke::new(2.5, theme::error_color(ui))
        } else {
            Stroke::new(1.0, faint)
        };
        // An opaque box, so no line runs through a name.
        painter.rect_filled(r, 4.0, ui.visuals().extreme_bg_color);
        painter.rect(r, 4.0, fill, outline, egui::StrokeKind::Inside);
        painter.text(p, Align2::CENTER_CENTER, c.name, font, ink);
    }
    rect
}

/// A use drawn from box edge to box edge; between two classes in one row,
/// an arc that dips below the row instead of a line through its names.
fn link_line(a: Pos2, b: Pos2) -> Vec<Pos2> {
    if (a.y - b.y).abs() < 1.0 {
        let dip = 12.0 + (b.x - a.x).abs() * 0.08;
        (0..=16)
            .map(|k| {
                let t = k as f32 / 16.0;
                pos2(a.x + (b.x - a.x) * t, a.y + 9.0 + dip * 4.0 * t * (1.0 - t))
            })
            .collect()
    } else {
        let (top, bottom) = if a.y < b.y { (a, b) } else { (b, a) };
        vec![top + vec2(0.0, 9.0), bottom - vec2(0.0, 9.0)]
    }
}

/// The classes replacing `swap` edits in design `d`.
fn edited(d: &Design, swap: Option<&str>) -> Vec<&'static str> {
    swap.and_then(|io| d.churn(io).ok()).unwrap_or_default()
}

/// A design's title: what replacing `swap` costs in it.
fn title(d: &Design, swap: Option<&str>, edited: &[&str]) -> String {
    match swap {
        Some(io) => format!(
            "{} design: replacing {io} edits {} class{}: {}",
            d.name,
            edited.len(),
            if edited.len() == 1 { "" } else { "es" },
            edited.join(", ")
        ),
        None => format!("{} design", d.name),
    }
}

impl Churn {
    /// The two designs side by side (one under the other when narrow);
    /// where they were drawn.
    fn designs(&self, ui: &mut egui::Ui) -> egui::Rect {
        let designs = [stable(), naive()];
        let wide = ui.available_width() >= 700.0;
        let width = if wide {
            ui.available_width() / 2.0 - 8.0
        } else {
            ui.available_width()
        };
        let swap = self.settings.swap();
        let show = |ui: &mut egui::Ui, d: &Design| {
            ui.vertical(|ui| {
                let edited = edited(d, swap);
                ui.set_width(width);
                ui.label(RichText::new(title(d, swap, &edited)).strong());
                draw(ui, d, &edited, swap, width);
            })
            .response
            .rect
        };
        if wide {
            ui.horizontal_top(|ui| {
                let a = show(ui, &designs[0]);
                a.union(show(ui, &designs[1]))
            })
            .inner
        } else {
            let a = show(ui, &designs[0]);
            a.union(show(ui, &designs[1]))
        }
    }
}

impl LabWidget for Churn {
    /// What the replacement chosen costs in each design.
    fn describe(&self) -> Option<String> {
        let swap = self.settings.swap();
        if swap.is_none() {
            return Some(
                "The stable and the naive design side by side; nothing is replaced yet: pick a device to replace.".to_owned(),
            );
        }
        let titles: Vec<String> = [stable(), naive()]
            .iter()
            .map(|d| title(d, swap, &edited(d, swap)))
            .collect();
        Some(format!("The {}.", titles.join(". The ")))
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.label("Replace:");
            for (io, what) in SWAPS {
                if crate::widget::choice(ui, self.settings.swap() == Some(io), io)
                    .on_hover_text(what)
                    .clicked()
                {
                    self.settings.swap = Some(io.to_owned());
                }
            }
        });
        ui.label(
            RichText::new(
                "blue: business logic · green: business objects · orange: industrial objects",
            )
            .small(),
        );
        let shown = self.designs(ui);
        export::bar(
            ui,
            ui.scope_id().with("churn-exports"),
            &[Export::Png {
                file: "kinolab-technology-churn.png",
                rect: shown,
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
        let (settings, _) = link::read::<Settings, ()>(NAME, state)?;
        // A link is written only when something changed: one holding the
        // lesson's own settings is not one of this widget's.
        if settings == self.initial {
            return Err("it holds nothing this widget would change".into());
        }
        self.settings = settings;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::spec;

    #[test]
    fn the_object_replaced_travels_in_the_link() {
        let settings = |params: &[(&str, &str)]| -> Settings {
            kinolab_schema::validate(&spec(NAME, params))
                .and_then(|p| p.settings())
                .unwrap_or_else(|e| panic!("{e}"))
        };
        let lesson = settings(&[]);
        let mut w = Churn {
            initial: lesson.clone(),
            settings: lesson.clone(),
        };
        assert_eq!(w.state(), None);
        w.settings.swap = Some("RosTopics".into());
        let text = w.state().unwrap_or_default();
        let mut again = Churn {
            initial: lesson.clone(),
            settings: lesson,
        };
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.settings.swap(), Some("RosTopics"));
        assert!(again.restore("b").is_err(), "nothing to change");
        for (io, _) in SWAPS {
            assert_eq!(settings(&[("swap", io)]).swap(), Some(io));
        }
    }
}
