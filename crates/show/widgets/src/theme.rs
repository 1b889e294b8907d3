//! Sizes and colours shared by every page, for light and dark themes.

use egui::{Color32, FontFamily, FontId, Stroke, TextStyle};

/// Lesson text, and text a widget writes in the page's own font size.
pub const BODY_SIZE: f32 = 16.0;
/// Code blocks and inline code.
pub const CODE_SIZE: f32 = 14.0;
/// Button text, and the shell's menu toggle.
pub const BUTTON_SIZE: f32 = 15.0;
/// Prominent lines on a canvas: a title, a read-out or verdict, a legend's
/// names, the main labels of a large drawing.
pub const TITLE_SIZE: f32 = 13.0;
/// Labels placed on a drawing (points, bodies, marks, names in boxes), and
/// `.small()` captions under a widget.
pub const LABEL_SIZE: f32 = 12.0;
/// Secondary text: hints, axis names, names in tight places, legend rows.
pub const SMALL_SIZE: f32 = 11.0;
/// Tick numbers and time stamps, the smallest text the lab draws.
pub const TINY_SIZE: f32 = 10.5;

/// Heading sizes by Markdown level.
pub fn heading_size(level: u8) -> f32 {
    match level {
        1 => 28.0,
        2 => 22.0,
        3 => 19.0,
        _ => 17.0,
    }
}

/// An opaque colour ([`Color32::from_rgb`], short for the tables here).
const fn rgb(r: u8, g: u8, b: u8) -> Color32 {
    Color32::from_rgb(r, g, b)
}

/// Of a `[dark, light]` pair, the colour that suits the theme of `ui`.
fn by_theme(ui: &egui::Ui, [dark, light]: [Color32; 2]) -> Color32 {
    if ui.visuals().dark_mode { dark } else { light }
}

/// The lab's accent colour, readable on either background: what is chosen,
/// what the learner drives, the start of a path.
pub fn accent(ui: &egui::Ui) -> Color32 {
    by_theme(ui, [rgb(110, 170, 255), rgb(30, 100, 200)])
}

/// Success: a goal met, a right answer, a foot that holds, and goals
/// themselves.
pub fn good_color(ui: &egui::Ui) -> Color32 {
    by_theme(ui, [rgb(90, 200, 120), rgb(25, 120, 50)])
}

/// Errors, refusals and failures: a wrong answer, a fall, a lost or refused
/// message, a notice that something was reset, what a change breaks.
pub fn error_color(ui: &egui::Ui) -> Color32 {
    by_theme(ui, [rgb(255, 120, 100), rgb(190, 50, 40)])
}

/// Solid grey matter: walls, obstacles, plain bodies; also a control's
/// outline at rest. At least 3:1 against the page in either theme.
pub fn solid_color(ui: &egui::Ui) -> Color32 {
    solid(ui.visuals().dark_mode)
}

/// [`solid_color`] for the dark theme or the light one.
fn solid(dark: bool) -> Color32 {
    Color32::from_gray(if dark { 150 } else { 110 })
}

/// A robot drawn as the one mover of its picture (the field sandbox's
/// unicycle, the ant on the beach).
pub fn robot_color(ui: &egui::Ui) -> Color32 {
    by_theme(ui, [rgb(230, 170, 60), rgb(190, 110, 0)])
}

/// The ant beach's sand.
pub fn sand_color(ui: &egui::Ui) -> Color32 {
    by_theme(ui, [rgb(90, 80, 60), rgb(236, 222, 190)])
}

/// A pebble on the sand: dark where it is big enough to turn the ant aside.
pub fn pebble_color(matters: bool) -> Color32 {
    Color32::from_gray(if matters { 105 } else { 175 })
}

// Named hues: mid-tones that read as marks on either background, the same
// in both themes. The domain colours below are made of them.

/// Orange: "send" messages, the reactive architecture, industrial objects.
pub const ORANGE: Color32 = rgb(230, 120, 40);
/// Blue: "query" messages, the hierarchical architecture, business logic,
/// a frame's z axis.
pub const BLUE: Color32 = rgb(70, 140, 230);
/// Green: "push-newest" messages, the hybrid architecture, business
/// objects, named frames, a frame's y axis, the frog.
pub const GREEN: Color32 = rgb(60, 170, 90);
/// Teal: "push-timed" messages.
pub const TEAL: Color32 = rgb(40, 160, 160);
/// Magenta: "event" messages.
pub const MAGENTA: Color32 = rgb(200, 70, 170);
/// Gold: "wiring" messages.
pub const GOLD: Color32 = rgb(170, 140, 40);
/// Purple: the palette's sixth colour, a second trap.
pub const PURPLE: Color32 = rgb(120, 110, 220);
/// Red as a hue, not a verdict: a frame's x axis, a trap, the frog's tongue.
pub const RED: Color32 = rgb(220, 60, 60);
/// Yellow: a light, and a basin where the robot wanders.
pub const YELLOW: Color32 = rgb(250, 200, 40);

/// Nothing in particular: reference marks in plots, no behaviour in
/// control, an unknown message pattern, a basin where the robot stalls.
pub const NEUTRAL: Color32 = Color32::GRAY;

/// Glass: an obstacle light and range sensors see through (a bumper finds it).
pub const GLASS: Color32 = rgb(120, 190, 230);

/// Dims the page behind an open drawer.
pub const SCRIM: Color32 = Color32::from_black_alpha(110);

/// A frame's x, y and z axes.
pub const AXIS_COLORS: [Color32; 3] = [RED, GREEN, BLUE];

/// The architectures hierarchical, reactive and hybrid, and the sensing
/// routes that stand for them (global, local, hybrid).
pub const ARCHITECTURE_COLORS: [Color32; 3] = [BLUE, ORANGE, GREEN];

/// One colour per trap (local minimum) of a potential field.
pub const TRAP_COLORS: [Color32; 4] = [RED, PURPLE, ORANGE, MAGENTA];

/// The colour of a component-lab message pattern; neutral for any other.
pub fn pattern_color(pattern: &str) -> Color32 {
    match pattern {
        "send" => ORANGE,
        "query" => BLUE,
        "push-newest" => GREEN,
        "push-timed" => TEAL,
        "event" => MAGENTA,
        "wiring" => GOLD,
        _ => NEUTRAL,
    }
}

const PALETTE: [Color32; 6] = [ORANGE, BLUE, GREEN, MAGENTA, GOLD, PURPLE];

/// How many distinct colours [`palette`] cycles through.
pub const PALETTE_LEN: usize = PALETTE.len();

/// The `i`-th of a cycle of distinct colours, readable on both themes: one
/// per wheel, per plotted series, per leg, per behaviour.
pub fn palette(i: usize) -> Color32 {
    PALETTE[i % PALETTE_LEN]
}

/// Fonts and text styles for the lab; call once, before the first frame
/// that draws text.
pub fn install(ctx: &egui::Context) {
    install_fonts(ctx);
    apply_text_styles(ctx);
    outline_controls(ctx);
    readable_text(ctx);
}

/// The learner asked for less motion (the system's "reduce motion", the
/// browser's `prefers-reduced-motion`): egui's own animations (menus
/// opening, scrolling to a place) end at once, and nothing starts moving by
/// itself (the wheel drive waits for Run).
pub fn reduce_motion(ctx: &egui::Context) {
    for theme in [egui::Theme::Dark, egui::Theme::Light] {
        ctx.style_mut_of(theme, |style| style.animation_time = 0.0);
    }
    ctx.data_mut(|d| d.insert_temp(reduce_motion_id(), true));
}

/// Whether [`reduce_motion`] was asked for.
pub fn motion_reduced(ctx: &egui::Context) -> bool {
    ctx.data(|d| d.get_temp::<bool>(reduce_motion_id()))
        .unwrap_or(false)
}

fn reduce_motion_id() -> egui::Id {
    egui::Id::unique("kinolab-reduce-motion")
}

/// WCAG's minimum contrast for text (1.4.3, level AA).
pub const TEXT_CONTRAST: f32 = 4.5;

/// egui's faint text on the dark page (2.3:1) and its links on the light
/// one (2.8:1) are too pale to read comfortably: every text colour reaches
/// at least 4.5:1. On the dark page the body text is lifted too (egui's
/// grey is 5.1:1), so that faint text can stay fainter than it and still
/// pass.
fn readable_text(ctx: &egui::Context) {
    ctx.style_mut_of(egui::Theme::Dark, |style| {
        let body = &mut style.visuals.widgets.noninteractive.fg_stroke.color;
        *body = Color32::from_gray(200);
        style.visuals.weak_text_color = Some(Color32::from_gray(140));
    });
    ctx.style_mut_of(egui::Theme::Light, |style| {
        style.visuals.hyperlink_color = rgb(30, 100, 200);
        style.visuals.weak_text_color = Some(Color32::from_gray(100));
    });
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

/// Unselected radio buttons and checkboxes are egui's faint grey blobs in
/// the light theme: give every control at rest a visible outline, in both
/// themes, so "not chosen" is as clear as "chosen".
fn outline_controls(ctx: &egui::Context) {
    for theme in [egui::Theme::Dark, egui::Theme::Light] {
        ctx.style_mut_of(theme, |style| {
            let dark = style.visuals.dark_mode;
            style.visuals.widgets.inactive.bg_stroke = Stroke::new(1.0, solid(dark));
        });
    }
}

/// `top` (premultiplied, as egui keeps colours) blended over an opaque
/// `bottom`.
fn over(top: Color32, bottom: Color32) -> Color32 {
    let keep = 1.0 - f32::from(top.a()) / 255.0;
    let mix = |t: u8, b: u8| (f32::from(t) + f32::from(b) * keep).round().min(255.0) as u8;
    Color32::from_rgb(
        mix(top.r(), bottom.r()),
        mix(top.g(), bottom.g()),
        mix(top.b(), bottom.b()),
    )
}

/// The contrast ratio of `a` drawn over `b`, 1 to 21 (WCAG 2's
/// definition); a translucent `a` is first blended over `b`.
pub fn contrast(a: Color32, b: Color32) -> f32 {
    let a = over(a, b);
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
                    FontId::new(BUTTON_SIZE, FontFamily::Proportional),
                ),
                (
                    TextStyle::Small,
                    FontId::new(LABEL_SIZE, FontFamily::Proportional),
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Every theme-dependent colour a learner must see stands out 3:1 from
    /// the page and from a canvas, in both themes.
    #[test]
    fn theme_colors_stand_out_in_both_themes() {
        let ctx = egui::Context::default();
        for theme in [egui::Theme::Dark, egui::Theme::Light] {
            ctx.set_theme(theme);
            let output = ctx.run_ui(egui::RawInput::default(), |ui| {
                let visuals = ui.visuals().clone();
                assert_eq!(visuals.dark_mode, theme == egui::Theme::Dark);
                let colors = [
                    ("accent", accent(ui)),
                    ("good", good_color(ui)),
                    ("error", error_color(ui)),
                    ("solid", solid_color(ui)),
                    ("robot", robot_color(ui)),
                ];
                for (name, c) in colors {
                    for background in [visuals.panel_fill, visuals.extreme_bg_color] {
                        let ratio = contrast(c, background);
                        assert!(
                            ratio >= CONTROL_CONTRAST,
                            "{theme:?}: {name} has contrast {ratio:.2} against {background:?}"
                        );
                    }
                }
            });
            output.drop_without_applying_deltas();
        }
    }
}

#[cfg(test)]
mod text_contrast {
    use super::*;

    /// Text a learner reads (body, faint hints, feedback in its colours,
    /// links) keeps 4.5:1 against the page, a window and a canvas, in
    /// both themes.
    #[test]
    fn text_meets_aa_in_both_themes() {
        let ctx = egui::Context::default();
        install(&ctx);
        for theme in [egui::Theme::Dark, egui::Theme::Light] {
            ctx.set_theme(theme);
            let output = ctx.run_ui(egui::RawInput::default(), |ui| {
                let v = ui.visuals().clone();
                let texts = [
                    ("text", v.text_color()),
                    ("weak text", v.weak_text_color()),
                    ("strong text", v.strong_text_color()),
                    ("link", v.hyperlink_color),
                    ("good", good_color(ui)),
                    ("error", error_color(ui)),
                ];
                for (name, c) in texts {
                    for background in [v.panel_fill, v.window_fill, v.extreme_bg_color] {
                        let ratio = contrast(c, background);
                        assert!(
                            ratio >= TEXT_CONTRAST,
                            "{theme:?}: {name} {c:?} has contrast {ratio:.2} against {background:?}"
                        );
                    }
                }
            });
            output.drop_without_applying_deltas();
        }
    }
}
