//! Sizes and colours shared by every page, for light and dark themes.

use egui::{Color32, FontFamily, FontId, Stroke, TextStyle};

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

/// The `i`-th of a cycle of distinct colours, readable on both themes: one
/// per wheel, per plotted series, per leg.
pub fn palette(i: usize) -> Color32 {
    const PALETTE: [Color32; 6] = [
        Color32::from_rgb(230, 120, 40),
        Color32::from_rgb(60, 150, 220),
        Color32::from_rgb(90, 170, 80),
        Color32::from_rgb(200, 80, 160),
        Color32::from_rgb(170, 140, 40),
        Color32::from_rgb(120, 110, 220),
    ];
    PALETTE[i % PALETTE.len()]
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
    outline_controls(ctx);
}

/// Set up for fingers: labels are not selectable, so a drag that starts on
/// text scrolls the page (egui does this itself, but only once it has seen
/// a touch event, which comes after the first press).
pub fn touch_first(ctx: &egui::Context) {
    ctx.all_styles_mut(|style| style.interaction.selectable_labels = false);
}

/// WCAG's minimum contrast for the parts of a control a learner must see
/// (1.4.11, non-text contrast).
pub const CONTROL_CONTRAST: f32 = 3.0;

/// The outline of a control at rest (a radio button, a checkbox, a button),
/// dark enough against the page to see without hovering.
fn control_outline(dark: bool) -> Color32 {
    if dark {
        Color32::from_gray(150)
    } else {
        Color32::from_gray(110)
    }
}

/// Unselected radio buttons and checkboxes are egui's faint grey blobs in
/// the light theme: give every control at rest a visible outline, in both
/// themes, so "not chosen" is as clear as "chosen".
fn outline_controls(ctx: &egui::Context) {
    for theme in [egui::Theme::Dark, egui::Theme::Light] {
        ctx.style_mut_of(theme, |style| {
            let dark = style.visuals.dark_mode;
            style.visuals.widgets.inactive.bg_stroke = Stroke::new(1.0, control_outline(dark));
        });
    }
}

/// The contrast ratio of two colours, 1 to 21 (WCAG 2's definition).
pub fn contrast(a: Color32, b: Color32) -> f32 {
    fn channel(c: u8) -> f32 {
        let c = f32::from(c) / 255.0;
        if c <= 0.04045 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    }
    let luminance =
        |c: Color32| 0.2126 * channel(c.r()) + 0.7152 * channel(c.g()) + 0.0722 * channel(c.b());
    let (la, lb) = (luminance(a), luminance(b));
    (la.max(lb) + 0.05) / (la.min(lb) + 0.05)
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
