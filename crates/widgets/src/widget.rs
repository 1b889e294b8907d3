//! What every widget is, and the small pieces widgets share.

use egui::{Color32, RichText, Stroke};
use kinolab_common::Feedback;

pub use kinolab_schema::Params;

use crate::theme;

/// A widget living inside a lesson.
pub trait LabWidget {
    fn ui(&mut self, ui: &mut egui::Ui);

    /// What a link must carry to reproduce this widget as the learner left
    /// it (see [`crate::link`]), or `None` while it is as the lesson set it up.
    fn state(&self) -> Option<String> {
        None
    }

    /// Take back a [`LabWidget::state`] from a link; ignore what does not
    /// decode (a damaged link never breaks the widget).
    fn restore(&mut self, _state: &str) {}
}

/// Builds a widget from its checked parameters.
pub type Constructor = fn(&Params) -> Result<Box<dyn LabWidget>, String>;

/// A visible, readable error in place of content that could not be shown.
pub fn error_box(ui: &mut egui::Ui, title: &str, message: &str) {
    egui::Frame::new()
        .fill(Color32::from_rgba_unmultiplied(200, 40, 40, 40))
        .stroke(Stroke::new(1.5, Color32::from_rgb(200, 50, 50)))
        .corner_radius(6.0)
        .inner_margin(10.0)
        .show(ui, |ui| {
            ui.set_width(ui.available_width());
            ui.label(
                RichText::new(title)
                    .strong()
                    .color(Color32::from_rgb(220, 60, 60)),
            );
            ui.label(message);
        });
}

/// An exercise's feedback, coloured by whether the goal is met; nothing
/// before the first check.
pub fn feedback_ui(ui: &mut egui::Ui, feedback: Option<&Feedback>) {
    if let Some(f) = feedback {
        let color = if f.met {
            theme::good_color(ui)
        } else {
            theme::warn_color(ui)
        };
        let prefix = if f.met { "Solved. " } else { "" };
        ui.label(RichText::new(format!("{prefix}{}", f.message)).color(color));
    }
}

/// A parameter with a default in its schema.
pub fn number(p: &Params, name: &str) -> f64 {
    p.number(name).unwrap_or_default()
}

/// Three numbers `[a, b, c]` (a pose or gains), from a parameter with a default.
pub fn triple(p: &Params, name: &str) -> [f64; 3] {
    match p.numbers(name) {
        Some([a, b, c]) => [*a, *b, *c],
        _ => [0.0; 3],
    }
}
