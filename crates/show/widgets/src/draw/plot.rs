//! The plots' one rule for legends: a legend sits in a row under its plot,
//! never on it, so it cannot cover the ends of curves or the "now" marker.
//! Each series takes its colour from [`series_color`], so the plot and its
//! legend row agree.

use egui::{Color32, RichText, Stroke, vec2};

/// The colour of a plot's `k`-th series (the lab's palette, so a leg or a
/// wheel keeps its colour from drawing to plot).
pub fn series_color(k: usize) -> Color32 {
    crate::theme::palette(k)
}

/// An axis mark as a plain number, at most three decimals, no trailing
/// zeros (`0.25`, `-0.5`, `1`): for axes whose grid steps are not powers
/// of ten.
pub fn axis_number(mark: egui_plot::GridMark, _range: &std::ops::RangeInclusive<f64>) -> String {
    let text = format!("{:.3}", mark.value);
    let text = text.trim_end_matches('0').trim_end_matches('.');
    match text {
        "-0" => "0".to_owned(),
        other => other.to_owned(),
    }
}

/// The colour of reference marks (a "now" line, a fixed level).
pub const REFERENCE: Color32 = crate::theme::NEUTRAL;

/// A legend row: a short stroke in each entry's colour, then its name;
/// wraps on a narrow column.
pub fn legend(ui: &mut egui::Ui, entries: &[(&str, Color32)]) {
    ui.horizontal_wrapped(|ui| {
        for (name, color) in entries {
            let (rect, _) = ui.allocate_exact_size(vec2(18.0, 12.0), egui::Sense::hover());
            ui.painter().line_segment(
                [rect.left_center(), rect.right_center()],
                Stroke::new(2.5, *color),
            );
            ui.label(RichText::new(*name).small());
            ui.add_space(6.0);
        }
    });
}

/// Each named series as a line in its palette colour (the `k`-th gets
/// [`series_color`]`(k)`), and a grey "now" marker when `now` is given.
pub fn series_lines(
    plot: &mut egui_plot::PlotUi<'_>,
    series: Vec<(&str, egui_plot::PlotPoints<'static>)>,
    now: Option<f64>,
) {
    for (k, (name, points)) in series.into_iter().enumerate() {
        plot.line(
            egui_plot::Line::new(name, points)
                .width(2.0)
                .color(series_color(k)),
        );
    }
    if let Some(t) = now {
        plot.vline(egui_plot::VLine::new("now", t).color(REFERENCE));
    }
}

/// The legend row for series drawn by [`series_lines`] under `names`,
/// then `extra` entries (reference marks).
pub fn series_legend(ui: &mut egui::Ui, names: &[&str], extra: &[(&str, Color32)]) {
    let entries: Vec<(&str, Color32)> = names
        .iter()
        .enumerate()
        .map(|(k, name)| (*name, series_color(k)))
        .chain(extra.iter().copied())
        .collect();
    legend(ui, &entries);
}
