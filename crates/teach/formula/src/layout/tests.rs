//! Geometry of typeset formulas, measured with egui's own fonts.

use egui::epaint::text::FontsView;
use egui::{Color32, vec2};

use super::ui::{TextLine, inline_placement};
use super::*;
use crate::parse;

const STYLE: MathStyle = MathStyle {
    size: 16.0,
    color: Color32::WHITE,
};

/// A context with the lab's fonts installed (they take effect at the
/// start of the next pass, so one empty pass runs first).
fn lab_context() -> egui::Context {
    let ctx = egui::Context::default();
    ctx.set_fonts(super::fonts::definitions());
    ctx.run_ui(egui::RawInput::default(), |_| {})
        .drop_without_applying_deltas();
    ctx
}

/// Runs `f` inside an egui pass with the lab's fonts installed.
fn with_fonts<R>(f: impl FnOnce(&mut FontsView<'_>) -> R) -> R {
    let ctx = lab_context();
    let mut f = Some(f);
    let mut result = None;
    let output = ctx.run_ui(egui::RawInput::default(), |ui| {
        if let Some(f) = f.take() {
            result = Some(ui.ctx().fonts_mut(f));
        }
    });
    output.drop_without_applying_deltas();
    result.expect("the pass ran")
}

fn layout(src: &str, mode: MathMode) -> MathBox {
    let math = parse(src).expect("test formula parses");
    with_fonts(|fonts| layout_math(fonts, &math, &STYLE, mode))
}

fn inline(src: &str) -> MathBox {
    layout(src, MathMode::Inline)
}

fn count_text(b: &MathBox) -> usize {
    b.paints
        .iter()
        .filter(|p| matches!(p, Paint::Text { .. }))
        .count()
}

#[test]
fn atoms_have_ink_metrics() {
    let x = inline("x");
    assert!(x.width > 0.0);
    assert!(
        x.ascent > 0.3 * STYLE.size && x.ascent < 0.8 * STYLE.size,
        "{x:?}"
    );
    assert!(x.descent < 0.1 * STYLE.size);
    let y = inline("y");
    assert!(y.descent > 0.1 * STYLE.size, "y has a descender: {y:?}");
    let b = inline("b");
    assert!(b.ascent > x.ascent);
}

#[test]
fn fraction_is_taller_than_its_parts() {
    let num = inline("a+b");
    let fraction = inline("\\frac{a+b}{c}");
    assert!(fraction.height() > num.height() + inline("c").height());
    assert!(fraction.ascent > num.ascent, "numerator is raised");
    assert!(
        fraction.descent > 0.3 * STYLE.size,
        "denominator is lowered"
    );
    assert!(fraction.width >= num.width * FRACTION_SCALE);
    assert!(fraction.paints.iter().any(|p| matches!(p, Paint::Rule(_))));
    // Display fractions keep full size.
    let display = layout("\\frac{a+b}{c}", MathMode::Display);
    assert!(display.width > fraction.width);
    assert!(display.height() > fraction.height());
}

#[test]
fn fraction_bar_sits_on_the_axis() {
    let fraction = inline("\\frac{1}{2}");
    let plus = inline("+");
    let Some(Paint::Rule(rule)) = fraction.paints.iter().find(|p| matches!(p, Paint::Rule(_)))
    else {
        panic!("no fraction bar");
    };
    let plus_middle = (plus.descent - plus.ascent) / 2.0;
    assert!(
        (rule.center().y - plus_middle).abs() < 1.5,
        "{rule:?} vs {plus_middle}"
    );
}

#[test]
fn superscripts_rise_and_subscripts_drop() {
    let x = inline("x");
    let squared = inline("x^2");
    assert!(squared.ascent > x.ascent + 0.2 * STYLE.size, "{squared:?}");
    assert!(squared.width > x.width);
    let indexed = inline("x_i");
    assert!(
        indexed.descent > x.descent + 0.1 * STYLE.size,
        "{indexed:?}"
    );
    assert!(indexed.ascent < squared.ascent);
    let both = inline("x_i^2");
    assert!(both.ascent >= squared.ascent - 0.5 && both.descent >= indexed.descent - 0.5);
    // Scripts are smaller than their base.
    let two = inline("2");
    let script_two = squared.width - x.width;
    assert!(script_two < two.width);
}

#[test]
fn display_sums_take_limits_above_and_below() {
    let inline_sum = inline("\\sum_{i=1}^n x_i");
    let display_sum = layout("\\sum_{i=1}^n x_i", MathMode::Display);
    assert!(display_sum.height() > inline_sum.height() * 1.3);
    let display_sum_alone = layout("\\sum", MathMode::Display);
    let with_limits = layout("\\sum_{i=1}^{n}", MathMode::Display);
    // Limits stack: the box is no wider than its widest part plus a little.
    assert!(with_limits.width < display_sum_alone.width + inline("i=1").width);
}

#[test]
fn matrices_grow_with_their_cells() {
    let cell = inline("a");
    let one = inline("\\begin{bmatrix} a \\end{bmatrix}");
    let two = inline("\\begin{bmatrix} a & b \\\\ c & d \\end{bmatrix}");
    assert!(one.width > cell.width, "brackets add width");
    assert!(two.width > one.width + cell.width);
    assert!(two.height() > one.height() + cell.height());
    let lines = two
        .paints
        .iter()
        .filter(|p| matches!(p, Paint::Line { .. }))
        .count();
    assert_eq!(lines, 2, "two drawn brackets");
    assert_eq!(count_text(&two), 4);
    // A plain matrix draws no delimiters and is narrower.
    let plain = inline("\\begin{matrix} a & b \\\\ c & d \\end{matrix}");
    assert!(plain.width < two.width);
    assert!(!plain.paints.iter().any(|p| matches!(p, Paint::Line { .. })));
}

#[test]
fn fences_stretch_to_their_body() {
    let small = inline("\\left( x \\right)");
    let tall = inline("\\left( \\frac{a}{b} \\right)");
    assert!(tall.height() > small.height());
    let frac = inline("\\frac{a}{b}");
    assert!(tall.ascent >= frac.ascent && tall.descent >= frac.descent);
    assert!(inline("\\left. x \\right|").width < small.width);
}

#[test]
fn radicals_and_accents_add_height() {
    let x = inline("x");
    let root = inline("\\sqrt{x}");
    assert!(root.width > x.width && root.ascent > x.ascent);
    let cube = inline("\\sqrt[3]{x}");
    assert!(cube.width >= root.width);
    for accent in ["\\dot", "\\ddot", "\\hat", "\\bar", "\\vec", "\\tilde"] {
        let accented = inline(&format!("{accent}{{x}}"));
        assert!(
            accented.ascent > x.ascent + 0.1 * STYLE.size,
            "{accent}: {accented:?}"
        );
        assert!((accented.descent - x.descent).abs() < 0.01, "{accent}");
    }
    let wide = inline("\\overline{ABC}");
    assert!(wide.width >= inline("ABC").width);
}

#[test]
fn operators_get_space_but_signs_do_not() {
    let a = inline("a");
    let b = inline("b");
    let sum = inline("a+b");
    let plus = inline("+");
    let tight = a.width + plus.width + b.width;
    assert!(
        sum.width > tight + 0.3 * STYLE.size,
        "medium spaces around +"
    );
    let equation = inline("a=b");
    let equals = inline("=");
    assert!(equation.width > a.width + equals.width + b.width + 0.4 * STYLE.size);
    // A leading minus is a sign.
    let negative = inline("-b");
    let minus = inline("-");
    assert!((negative.width - (minus.width + b.width)).abs() < 0.01);
    // No medium space in scripts.
    assert_eq!(
        resolve_classes(&[], None),
        Vec::<Option<Class>>::new(),
        "empty rows are fine"
    );
    assert_eq!(space_between(Class::Ord, Class::Bin, true), 0.0);
    assert_eq!(space_between(Class::Op, Class::Ord, true), 3.0);
}

#[test]
fn bold_and_fallback_glyphs_render_as_text() {
    let bold = inline("\\mathbf{v}");
    let plain = inline("v");
    assert!(bold.width > plain.width);
    // Letters the default fonts lack are replaced, not dropped.
    for src in [
        "\\epsilon",
        "\\vartheta",
        "\\phi",
        "\\perp",
        "\\parallel",
        "\\mathbb{R}",
        "\\to",
    ] {
        let b = inline(src);
        assert!(b.width > 0.0 && b.ascent > 0.0, "{src}: {b:?}");
    }
    let dots = inline("\\cdots");
    assert_eq!(count_text(&dots), 0, "dots are drawn");
    assert!(dots.width > 0.5 * STYLE.size);
}

#[test]
fn inline_placement_keeps_the_text_baseline() {
    let line = TextLine {
        ascent: 13.0,
        row_height: 18.0,
    };
    let small = MathBox {
        width: 10.0,
        ascent: 8.0,
        descent: 2.0,
        paints: Vec::new(),
    };
    let placed = inline_placement(&small, line);
    assert_eq!(placed.size, vec2(10.0, 18.0));
    assert_eq!(placed.baseline, 13.0);
    // A tall formula grows on both sides of the row's middle.
    let tall = MathBox {
        ascent: 20.0,
        descent: 10.0,
        ..small
    };
    let placed = inline_placement(&tall, line);
    assert!(placed.baseline >= tall.ascent);
    assert!(placed.size.y - placed.baseline >= tall.descent);
    let middle_offset = placed.baseline - placed.size.y / 2.0;
    assert!((middle_offset - (line.ascent - line.row_height / 2.0)).abs() < 1e-4);
}

#[test]
fn widgets_allocate_their_layout() {
    let math = parse("v = r\\dot\\varphi + \\frac{1}{2} \\begin{pmatrix} a \\\\ b \\end{pmatrix}")
        .expect("parses");
    let ctx = lab_context();
    let mut rects = Vec::new();
    let output = ctx.run_ui(egui::RawInput::default(), |ui| {
        ui.horizontal_wrapped(|ui| {
            ui.label("speed");
            rects.push(math_widget(ui, &math, &STYLE).rect);
        });
        rects.push(display_math(ui, &math, &STYLE).rect);
    });
    output.drop_without_applying_deltas();
    let expected = with_fonts(|fonts| layout_math(fonts, &math, &STYLE, MathMode::Inline));
    let [inline_rect, display_rect] = rects[..] else {
        panic!("two widgets: {rects:?}");
    };
    assert!(
        (inline_rect.width() - expected.width).abs() < 0.1,
        "{inline_rect:?} vs {}",
        expected.width
    );
    assert!(inline_rect.height() >= expected.height());
    assert!(display_rect.width() >= inline_rect.width());
    assert!(display_rect.height() > inline_rect.height());
}

#[test]
fn baseline_matches_labels_in_a_sized_row() {
    let math = parse("\\frac{a}{b} + x^2").expect("parses");
    let ctx = lab_context();
    let mut rects = Vec::new();
    let output = ctx.run_ui(egui::RawInput::default(), |ui| {
        ui.horizontal_wrapped(|ui| {
            ui.set_row_height(InlineMath::new(ui, &math, &STYLE).size().y);
            rects.push(ui.label(egui::RichText::new("x").size(STYLE.size)).rect);
            rects.push(math_widget(ui, &math, &STYLE).rect);
            rects.push(ui.label(egui::RichText::new("y").size(STYLE.size)).rect);
        });
    });
    output.drop_without_applying_deltas();
    let [before, formula, after] = rects[..] else {
        panic!("three widgets: {rects:?}");
    };
    // Labels and formula are centred on one line, so baselines agree.
    assert!(
        (before.center().y - formula.center().y).abs() < 0.5,
        "{rects:?}"
    );
    assert!(
        (after.center().y - formula.center().y).abs() < 0.5,
        "{rects:?}"
    );
    assert!(formula.height() > before.height());
}

#[test]
fn primes_are_drawn_after_their_base() {
    let f = inline("f");
    let prime = inline("f'");
    let double = inline("f''");
    assert!(prime.width > f.width && double.width > prime.width);
    assert!(prime.ascent >= f.ascent);
    assert_eq!(count_text(&prime), 1);
}

#[test]
fn every_construct_lays_out_finitely() {
    let sources = [
        "",
        "x",
        "\\alpha\\beta\\Gamma",
        "f'(x) = \\lim_{h \\to 0} \\frac{f(x+h)-f(x)}{h}",
        "\\sqrt[3]{\\frac{a}{b}}",
        "\\left\\{ x \\right\\} \\left\\langle y \\right\\rangle \\left\\lfloor z \\right\\rceil",
        "\\left\\| v \\right\\|",
        "\\begin{cases} 1 & x > 0 \\\\ 0 & \\text{otherwise} \\end{cases}",
        "\\begin{aligned} a &= b \\\\ c &= d + e \\end{aligned}",
        "\\begin{vmatrix} a & b \\\\ c & d \\end{vmatrix} \\begin{Vmatrix} a \\end{Vmatrix}",
        "\\begin{bmatrix}\\end{bmatrix}",
        "R^\\top \\mathbf{x}_{i}^{2} \\int_0^1 x\\,dx \\quad \\dots \\ldots \\vdots \\ddots",
        "a\\!b~c\\;d",
        "^2",
    ];
    for src in sources {
        for mode in [MathMode::Inline, MathMode::Display] {
            let b = layout(src, mode);
            assert!(
                b.width.is_finite() && b.ascent.is_finite() && b.descent.is_finite(),
                "{src}: {b:?}"
            );
            assert!(
                b.width >= 0.0 && b.ascent >= 0.0 && b.descent >= 0.0,
                "{src}"
            );
        }
    }
}

#[test]
fn odd_sizes_do_not_break_layout() {
    let math = parse("\\frac{x}{y}").expect("parses");
    for size in [f32::NAN, -3.0, 0.0, 1e9] {
        let style = MathStyle { size, ..STYLE };
        let b = with_fonts(|fonts| layout_math(fonts, &math, &style, MathMode::Inline));
        assert!(b.height().is_finite() && b.width.is_finite(), "{size}");
    }
}
