//! Sizes and colours shared by every page, for light and dark themes.

use egui::{Color32, FontFamily, FontId, TextStyle};

pub const BODY_SIZE: f32 = 16.0;
pub const CODE_SIZE: f32 = 14.0;

/// Heading sizes by Markdown level.
pub fn heading_size(level: u8) -> f32 {
    match level {
        1 => 28.0,
        2 => 22.0,
        3 => 19.0,
        _ => 17.0,
    }
}

/// The lab's accent colour, readable on either background.
pub fn accent(ui: &egui::Ui) -> Color32 {
    if ui.visuals().dark_mode {
        Color32::from_rgb(110, 170, 255)
    } else {
        Color32::from_rgb(30, 100, 200)
    }
}

pub fn good_color(ui: &egui::Ui) -> Color32 {
    if ui.visuals().dark_mode {
        Color32::from_rgb(90, 200, 120)
    } else {
        Color32::from_rgb(30, 140, 60)
    }
}

pub fn warn_color(ui: &egui::Ui) -> Color32 {
    if ui.visuals().dark_mode {
        Color32::from_rgb(255, 120, 100)
    } else {
        Color32::from_rgb(190, 50, 40)
    }
}

/// Fonts and text styles for the lab; call once, before the first frame
/// that draws text.
pub fn install(ctx: &egui::Context) {
    install_fonts(ctx);
    apply_text_styles(ctx);
}

/// The lab's two fonts, cut down to what it draws (the formula crate owns
/// them: formulas are set against their metrics).
fn install_fonts(ctx: &egui::Context) {
    ctx.set_fonts(kinolab_formula::layout::fonts::definitions());
}

/// Larger, more readable text than egui's defaults.
fn apply_text_styles(ctx: &egui::Context) {
    for theme in [egui::Theme::Dark, egui::Theme::Light] {
        ctx.style_mut_of(theme, |style| {
            style.text_styles = [
                (
                    TextStyle::Heading,
                    FontId::new(24.0, FontFamily::Proportional),
                ),
                (
                    TextStyle::Body,
                    FontId::new(BODY_SIZE, FontFamily::Proportional),
                ),
                (
                    TextStyle::Button,
                    FontId::new(15.0, FontFamily::Proportional),
                ),
                (
                    TextStyle::Small,
                    FontId::new(12.5, FontFamily::Proportional),
                ),
                (
                    TextStyle::Monospace,
                    FontId::new(CODE_SIZE, FontFamily::Monospace),
                ),
            ]
            .into();
            style.spacing.item_spacing = egui::vec2(8.0, 6.0);
            style.spacing.button_padding = egui::vec2(8.0, 4.0);
        });
    }
}
