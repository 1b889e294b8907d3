//! How fast the number of leg-event sequences grows with the number of legs.

use egui::{RichText, Stroke, pos2, vec2};
use kinolab_common::display::group_digits;
use kinolab_locomotion::leg_events;
use serde::{Deserialize, Serialize};

use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::theme;
use crate::widget::{LabWidget, Params, range};

/// The widget's name in the schema.
const NAME: &str = "leg-events";

/// What the lesson sets and a link carries: the schema's parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    legs: u32,
}

struct LegEvents {
    settings: Settings,
    initial: Settings,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    Ok(Box::new(LegEvents {
        initial: settings.clone(),
        settings,
    }))
}

/// The most legs the slider and the chart go to (the schema's).
fn max_legs() -> u32 {
    *range(NAME, "legs").end() as u32
}

/// The count for `k` legs, as the widget prints it.
fn count_text(k: u32) -> String {
    format!(
        "N = (2·{} − 1)! = {}! = {} possible event sequences",
        k,
        2 * k - 1,
        group_digits(leg_events(k).unwrap_or(0))
    )
}

impl LabWidget for LegEvents {
    /// The number of legs and the count it gives.
    fn describe(&self) -> Option<String> {
        let k = self.settings.legs;
        Some(format!(
            "{k} leg{}: {}.",
            if k == 1 { "" } else { "s" },
            count_text(k)
        ))
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        let legs = range(NAME, "legs");
        let legs = (*legs.start() as u32)..=(*legs.end() as u32);
        ui.horizontal(|ui| {
            let label = ui.label("Number of legs k:");
            ui.add(egui::Slider::new(&mut self.settings.legs, legs))
                .labelled_by(label.id);
        });
        let k = self.settings.legs;
        let count = leg_events(k).unwrap_or(0);
        ui.label(
            RichText::new(count_text(k))
                .size(theme::BODY_SIZE + 2.0)
                .strong(),
        );
        if k > 1 {
            let previous = leg_events(k - 1).unwrap_or(1).max(1);
            ui.label(format!(
                "Adding leg number {} multiplies the count by {}.",
                k,
                group_digits(count / previous)
            ));
        }
        let chart = self.chart(ui);
        let csv = || chart_csv(max_legs());
        export::bar(
            ui,
            ui.scope_id().with("leg-events-exports"),
            &[
                Export::Png {
                    file: "kinolab-leg-events.png",
                    rect: chart,
                },
                Export::Csv {
                    file: "kinolab-leg-events.csv",
                    make: &csv,
                },
            ],
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
            // The first format: the number of legs alone.
            Err(why) => match link::decode::<u32>(state) {
                Some(legs) => Settings { legs },
                None => return Err(why),
            },
        };
        link::check(NAME, &settings)?;
        self.settings = settings;
        Ok(())
    }
}

/// The chart's numbers: k, N exactly, and log₁₀ N.
fn chart_csv(max: u32) -> String {
    let mut out = String::from("k,N,log10 N\n");
    for k in 1..=max {
        let n = leg_events(k).unwrap_or(0);
        out += &format!("{k},{n},{}\n", (n as f64).log10());
    }
    out
}

impl LegEvents {
    /// Bars of log₁₀ N for every k, the chosen one highlighted; the area
    /// it drew.
    fn chart(&mut self, ui: &mut egui::Ui) -> egui::Rect {
        let max = max_legs();
        let width = ui.available_width().min(640.0);
        let (response, painter) = ui.allocate_painter(vec2(width, 170.0), egui::Sense::click());
        let rect = response.rect.shrink2(vec2(30.0, 18.0));
        let max_log = (leg_events(max).unwrap_or(1) as f64).log10() as f32;
        let bar_w = rect.width() / max as f32;
        let text = ui.visuals().text_color();
        for k in 1..=max {
            let log = (leg_events(k).unwrap_or(1) as f64).log10() as f32;
            let h = (log / max_log) * rect.height();
            let x = rect.left() + (k - 1) as f32 * bar_w;
            let bar = egui::Rect::from_min_max(
                pos2(x + 3.0, rect.bottom() - h.max(1.0)),
                pos2(x + bar_w - 3.0, rect.bottom()),
            );
            let color = if k == self.settings.legs {
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
            self.settings.legs = (((pos.x - rect.left()) / bar_w) as u32 + 1).clamp(1, max);
        }
        response.rect
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::spec;

    fn widget(params: &[(&str, &str)]) -> LegEvents {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        let settings: Settings = p.settings().unwrap_or_else(|e| panic!("{e}"));
        LegEvents {
            initial: settings.clone(),
            settings,
        }
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        let old = link::encode(&6_u32).unwrap_or_default();
        let mut w = widget(&[]);
        assert_eq!(w.restore(&old), Ok(()));
        assert_eq!(w.settings.legs, 6);
        // Out of the schema's range: refused, the lesson's settings kept.
        let bad = link::encode(&40_u32).unwrap_or_default();
        let mut w = widget(&[("legs", "3")]);
        assert!(w.restore(&bad).is_err());
        assert_eq!(w.settings.legs, 3);
    }

    #[test]
    fn settings_travel_in_the_link() {
        let mut w = widget(&[]);
        assert_eq!(w.state(), None);
        w.settings.legs = 9;
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.settings, w.settings);
        assert_eq!(chart_csv(12).lines().count(), 13);
    }
}
