//! How fast the number of leg-event sequences grows with the number of legs.

use egui::{RichText, Stroke, pos2, vec2};
use kinolab_common::display::group_digits;
use kinolab_locomotion::leg_events;

use crate::widget::{LabWidget, Params};
use crate::{link, theme};

const MAX_LEGS: u32 = 12;

struct LegEvents {
    legs: u32,
    initial: u32,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let legs = p.integer("legs").unwrap_or(2).clamp(1, i64::from(MAX_LEGS)) as u32;
    Ok(Box::new(LegEvents {
        legs,
        initial: legs,
    }))
}

impl LabWidget for LegEvents {
    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            let label = ui.label("Number of legs k:");
            ui.add(egui::Slider::new(&mut self.legs, 1..=MAX_LEGS))
                .labelled_by(label.id);
        });
        let count = leg_events(self.legs).unwrap_or(0);
        ui.label(
            RichText::new(format!(
                "N = (2·{} − 1)! = {}! = {} possible event sequences",
                self.legs,
                2 * self.legs - 1,
                group_digits(count)
            ))
            .size(theme::BODY_SIZE + 2.0)
            .strong(),
        );
        if self.legs > 1 {
            let previous = leg_events(self.legs - 1).unwrap_or(1).max(1);
            ui.label(format!(
                "Adding leg number {} multiplies the count by {}.",
                self.legs,
                group_digits(count / previous)
            ));
        }
        self.chart(ui);
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.legs, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(legs) = link::decode::<u32>(state) {
            self.legs = legs.clamp(1, MAX_LEGS);
        }
        Ok(())
    }
}

impl LegEvents {
    /// Bars of log₁₀ N for every k, the chosen one highlighted.
    fn chart(&mut self, ui: &mut egui::Ui) {
        let width = ui.available_width().min(640.0);
        let (response, painter) = ui.allocate_painter(vec2(width, 170.0), egui::Sense::click());
        let rect = response.rect.shrink2(vec2(30.0, 18.0));
        let max_log = (leg_events(MAX_LEGS).unwrap_or(1) as f64).log10() as f32;
        let bar_w = rect.width() / MAX_LEGS as f32;
        let text = ui.visuals().text_color();
        for k in 1..=MAX_LEGS {
            let log = (leg_events(k).unwrap_or(1) as f64).log10() as f32;
            let h = (log / max_log) * rect.height();
            let x = rect.left() + (k - 1) as f32 * bar_w;
            let bar = egui::Rect::from_min_max(
                pos2(x + 3.0, rect.bottom() - h.max(1.0)),
                pos2(x + bar_w - 3.0, rect.bottom()),
            );
            let color = if k == self.legs {
                theme::accent(ui)
            } else {
                ui.visuals().widgets.inactive.bg_fill
            };
            painter.rect_filled(bar, 2.0, color);
            painter.text(
                pos2(bar.center().x, rect.bottom() + 2.0),
                egui::Align2::CENTER_TOP,
                k.to_string(),
                egui::FontId::proportional(theme::SMALL_SIZE),
                text,
            );
        }
        painter.line_segment(
            [rect.left_bottom(), rect.right_bottom()],
            Stroke::new(1.0, text),
        );
        painter.text(
            rect.left_top() - vec2(26.0, 14.0),
            egui::Align2::LEFT_TOP,
            "log₁₀ N  (each step up is ×10)",
            egui::FontId::proportional(theme::SMALL_SIZE),
            ui.visuals().weak_text_color(),
        );
        if let Some(pos) = response.interact_pointer_pos()
            && response.clicked()
            && rect.x_range().contains(pos.x)
        {
            self.legs = (((pos.x - rect.left()) / bar_w) as u32 + 1).clamp(1, MAX_LEGS);
        }
    }
}
