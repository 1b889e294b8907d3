//! Technology churn: the same application designed stably and naively, as
//! class graphs side by side; replace an industrial object and the classes
//! whose code must change light up, counted by the core.

use egui::{Align2, FontId, Pos2, RichText, Sense, Stroke, pos2, vec2};
use kinolab_design::churn::{Design, Layer, SWAPS, naive, stable};

use crate::draw::canvas;
use crate::theme;
use crate::widget::{LabWidget, Params};

struct Churn {
    swap: Option<&'static str>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let swap = p
        .choice("swap")
        .and_then(|s| SWAPS.iter().find(|(io, _)| *io == s).map(|(io, _)| *io));
    Ok(Box::new(Churn { swap }))
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

fn draw(ui: &mut egui::Ui, design: &Design, edited: &[&str], swapped: Option<&str>, width: f32) {
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

impl LabWidget for Churn {
    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.label("Replace:");
            for (io, what) in SWAPS {
                if ui
                    .selectable_label(self.swap == Some(io), io)
                    .on_hover_text(what)
                    .clicked()
                {
                    self.swap = Some(io);
                }
            }
        });
        ui.label(
            RichText::new(
                "blue: business logic · green: business objects · orange: industrial objects",
            )
            .small(),
        );
        let designs = [stable(), naive()];
        let wide = ui.available_width() >= 700.0;
        let width = if wide {
            ui.available_width() / 2.0 - 8.0
        } else {
            ui.available_width()
        };
        let show = |ui: &mut egui::Ui, d: &Design| {
            ui.vertical(|ui| {
                let edited = self
                    .swap
                    .and_then(|io| d.churn(io).ok())
                    .unwrap_or_default();
                let title = match self.swap {
                    Some(io) => format!(
                        "{} design: replacing {io} edits {} class{}: {}",
                        d.name,
                        edited.len(),
                        if edited.len() == 1 { "" } else { "es" },
                        edited.join(", ")
                    ),
                    None => format!("{} design", d.name),
                };
                ui.set_width(width);
                ui.label(RichText::new(title).strong());
                draw(ui, d, &edited, self.swap, width);
            });
        };
        if wide {
            ui.horizontal_top(|ui| {
                for d in &designs {
                    show(ui, d);
                }
            });
        } else {
            for d in &designs {
                show(ui, d);
            }
        }
    }
}
