//! Draws a parsed lesson: headings, paragraphs with formulas, lists,
//! tables, code, images, quizzes and live widgets.

use std::collections::HashMap;

use egui::{Color32, RichText, Stroke};
use kinolab_lessons::{Align, Block, Inline, Quiz, Span, WidgetSpec};

use kinolab_formula::layout::{InlineMath, MathStyle, display_math};
use kinolab_widgets::theme;
use kinolab_widgets::widget::{LabWidget, error_box, sideways};

use crate::first_screen::FirstScreen;
use crate::images::ImageCache;
use crate::progress::Progress;
use crate::quiz_view::{QuizState, quiz_ui};
use crate::route::Page;

/// A live widget, or why it could not be made.
pub type WidgetSlot = Result<Box<dyn LabWidget>, String>;

/// Everything a lesson needs while it is drawn, beyond its blocks.
pub struct LessonState<'a> {
    /// The lesson's `unit/lesson` address; quiz and widget ids hang off it.
    pub address: &'a str,
    /// The lesson's file under `lessons/`; its images sit beside it.
    pub file: &'a str,
    pub quizzes: &'a mut HashMap<String, QuizState>,
    pub widgets: &'a mut HashMap<String, WidgetSlot>,
    /// Widget states from a link, by widget id, applied once.
    pub restore: &'a mut HashMap<String, String>,
    pub progress: &'a mut Progress,
    /// The time now, to date an answer.
    pub now: crate::progress::Millis,
    pub progress_changed: &'a mut bool,
    pub images: &'a mut ImageCache,
    /// Set when the learner follows a link to another page.
    pub navigate: &'a mut Option<Page>,
    /// Where the lab's first frame stops laying out the lesson.
    pub first_screen: &'a mut FirstScreen,
}

impl std::fmt::Debug for LessonState<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("LessonState")
            .field("address", &self.address)
            .finish_non_exhaustive()
    }
}

/// Draw `blocks`. Quizzes and widgets are numbered in order of appearance,
/// which gives them stable ids.
pub fn blocks_ui(ui: &mut egui::Ui, blocks: &[Block], state: &mut LessonState<'_>) {
    let mut quiz_no = 0;
    let mut widget_no = 0;
    for block in blocks {
        if state.first_screen.stop(ui) {
            break;
        }
        block_ui(ui, block, state, &mut quiz_no, &mut widget_no);
    }
}

fn block_ui(
    ui: &mut egui::Ui,
    block: &Block,
    state: &mut LessonState<'_>,
    quiz_no: &mut usize,
    widget_no: &mut usize,
) {
    match block {
        Block::Heading { level, text } => {
            ui.add_space(if *level <= 2 { 14.0 } else { 8.0 });
            let size = theme::heading_size(*level);
            let heading = ui.scope(|ui| inline_ui(ui, text, size, true, state.navigate));
            // A screen reader lists and jumps by headings.
            ui.ctx()
                .accesskit_node_builder(heading.response.id, |node| {
                    node.set_role(egui::accesskit::Role::Heading);
                    node.set_level(usize::from(*level));
                });
            ui.add_space(4.0);
        }
        Block::Paragraph(spans) => {
            inline_ui(ui, spans, theme::BODY_SIZE, false, state.navigate);
            ui.add_space(8.0);
        }
        Block::Math(math) => {
            let style = math_style(ui, theme::BODY_SIZE);
            sideways(ui, |ui| {
                display_math(ui, math, &style);
            });
            ui.add_space(8.0);
        }
        Block::List { start, items } => list_ui(ui, *start, items, state, quiz_no, widget_no),
        Block::Quote(blocks) => quote_ui(ui, blocks, state, quiz_no, widget_no),
        Block::Code { text, .. } => code_ui(ui, text),
        Block::Table {
            align,
            header,
            rows,
        } => {
            table_ui(ui, align, header, rows, state);
            ui.add_space(10.0);
        }
        Block::Rule => {
            ui.separator();
        }
        Block::Widget(spec) => {
            let id = format!("{}@w{}", state.address, *widget_no);
            *widget_no += 1;
            widget_ui(ui, &id, spec, state.widgets, state.restore);
            ui.add_space(10.0);
        }
        Block::Quiz(quiz) => quiz_block_ui(ui, quiz, state, quiz_no),
    }
    // Images sit inside paragraphs in Markdown; draw them after the text.
    if let Block::Paragraph(spans) = block {
        for span in spans {
            if let Span::Image { url, alt, .. } = span {
                state.images.show(ui, state.file, url, alt);
            }
        }
    }
}

fn list_ui(
    ui: &mut egui::Ui,
    start: Option<u64>,
    items: &[Vec<Block>],
    state: &mut LessonState<'_>,
    quiz_no: &mut usize,
    widget_no: &mut usize,
) {
    for (i, item) in items.iter().enumerate() {
        ui.horizontal_top(|ui| {
            let marker = match start {
                Some(n) => format!("{}.", n + i as u64),
                None => "•".to_owned(),
            };
            ui.add_sized(
                [22.0, theme::BODY_SIZE + 4.0],
                egui::Label::new(RichText::new(marker).size(theme::BODY_SIZE)),
            );
            ui.vertical(|ui| {
                for block in item {
                    block_ui(ui, block, state, quiz_no, widget_no);
                }
            });
        });
    }
    ui.add_space(6.0);
}

/// A block quote: indented, with an accent bar down its left side.
fn quote_ui(
    ui: &mut egui::Ui,
    blocks: &[Block],
    state: &mut LessonState<'_>,
    quiz_no: &mut usize,
    widget_no: &mut usize,
) {
    let margin = egui::Margin {
        left: 12,
        right: 8,
        top: 4,
        bottom: 4,
    };
    egui::Frame::new().inner_margin(margin).show(ui, |ui| {
        let top = ui.cursor().top();
        for block in blocks {
            block_ui(ui, block, state, quiz_no, widget_no);
        }
        let x = ui.min_rect().left() - 8.0;
        let y = egui::Rangef::new(top, ui.min_rect().bottom());
        ui.painter()
            .vline(x, y, Stroke::new(3.0, theme::accent(ui)));
    });
}

fn code_ui(ui: &mut egui::Ui, text: &str) {
    egui::Frame::new()
        .fill(ui.visuals().code_bg_color)
        .corner_radius(4.0)
        .inner_margin(8.0)
        .show(ui, |ui| {
            ui.set_width(ui.available_width());
            let text = RichText::new(text.trim_end()).monospace();
            ui.label(text.size(theme::CODE_SIZE));
        });
    ui.add_space(8.0);
}

/// A quiz, numbered within the lesson; a fresh verdict is saved to progress.
fn quiz_block_ui(ui: &mut egui::Ui, quiz: &Quiz, state: &mut LessonState<'_>, quiz_no: &mut usize) {
    let id = format!("{}#{}", state.address, *quiz_no);
    *quiz_no += 1;
    let quiz_state = state.quizzes.entry(id.clone()).or_default();
    if quiz_ui(ui, &id, quiz, quiz_state, state.navigate)
        && let Some(correct) = quiz_state.verdict
    {
        state.progress.record_answer(&id, correct, state.now);
        *state.progress_changed = true;
    }
    ui.add_space(12.0);
}

fn math_style(ui: &egui::Ui, size: f32) -> MathStyle {
    MathStyle {
        size,
        color: ui.visuals().text_color(),
    }
}

/// Draw one run of inline content, wrapping like a paragraph.
pub fn inline_ui(
    ui: &mut egui::Ui,
    spans: &Inline,
    size: f32,
    strong: bool,
    navigate: &mut Option<Page>,
) {
    ui.horizontal_wrapped(|ui| {
        ui.spacing_mut().item_spacing.x = 0.0;
        ui.spacing_mut().item_spacing.y = 2.0;
        for (i, span) in spans.iter().enumerate() {
            // A formula is laid out once, to measure it and to show it.
            let math = match span {
                Span::Math(math) => Some(InlineMath::new(ui, math, &math_style(ui, size))),
                _ => None,
            };
            keep_with_punctuation(ui, span, math.as_ref(), spans.get(i + 1), size);
            match span {
                Span::Text { text, style } => {
                    let text = no_space_at_row_start(ui, text, size);
                    let mut rich = RichText::new(text).size(size);
                    if strong || style.strong {
                        rich = rich.strong();
                    }
                    if style.emphasis {
                        rich = rich.italics();
                    }
                    if style.strikethrough {
                        rich = rich.strikethrough();
                    }
                    match &style.link {
                        Some(url) if url.starts_with("#/") => {
                            if ui.link(rich).clicked() {
                                *navigate = Some(Page::from_hash(url));
                            }
                        }
                        Some(url) => {
                            ui.hyperlink_to(rich, url);
                        }
                        None => {
                            ui.label(rich);
                        }
                    }
                    if style.emphasis {
                        italic_correction(ui, spans.get(i + 1), size);
                    }
                }
                Span::Code(code) => {
                    let label = egui::Label::new(RichText::new(code).code().size(theme::CODE_SIZE));
                    // A short piece of code (`push(o, x, y, d)`) never breaks.
                    if code.chars().count() <= SHORT_CODE {
                        ui.add(label.wrap_mode(egui::TextWrapMode::Extend));
                    } else {
                        ui.add(label);
                    }
                }
                Span::Math(_) => {
                    if let Some(math) = &math {
                        let visuals = ui.visuals();
                        let color = if strong {
                            visuals.strong_text_color()
                        } else {
                            visuals.text_color()
                        };
                        math.show(ui, color);
                    }
                }
                Span::Image { .. } => {}
                Span::LineBreak => ui.end_row(),
            }
        }
    });
}

/// Text that starts with a space (after an italic word, a formula, a
/// link) must not begin a row with it: when its first word does not fit
/// on this row, start the next one, without the space.
fn no_space_at_row_start<'t>(ui: &mut egui::Ui, text: &'t str, size: f32) -> &'t str {
    let trimmed = text.trim_start();
    if trimmed.len() == text.len() {
        return text;
    }
    let at_start = ui.cursor().min.x <= ui.max_rect().left() + 0.5;
    if at_start {
        return trimmed;
    }
    let first = &text
        [..text.len() - trimmed.len() + trimmed.find(char::is_whitespace).unwrap_or(trimmed.len())];
    let width = ui.ctx().fonts_mut(|f| {
        f.layout_no_wrap(
            first.to_owned(),
            egui::FontId::proportional(size),
            Color32::WHITE,
        )
        .size()
        .x
    });
    if width > ui.available_size_before_wrap().x {
        ui.end_row();
        return trimmed;
    }
    text
}

/// Start a new row before a formula, inline code or a link when the word
/// glued to its end (a comma, a full stop, "s") would not fit after it on
/// this row: the two then wrap together, and punctuation never begins a
/// line alone.
fn keep_with_punctuation(
    ui: &mut egui::Ui,
    span: &Span,
    math: Option<&InlineMath<'_>>,
    next: Option<&Span>,
    size: f32,
) {
    let Some(Span::Text { text, style }) = next else {
        return;
    };
    let glued = text.split(char::is_whitespace).next().unwrap_or_default();
    if glued.is_empty() || style.link.is_some() {
        return;
    }
    let width = |text: &str, font: egui::FontId| {
        ui.ctx().fonts_mut(|f| {
            f.layout_no_wrap(text.to_owned(), font, Color32::WHITE)
                .size()
                .x
        })
    };
    let atom = match span {
        Span::Code(code) => width(code, egui::FontId::monospace(theme::CODE_SIZE)),
        Span::Math(_) => math.map_or(0.0, |m| m.size().x),
        Span::Text { text, style } if style.link.is_some() => {
            width(text, egui::FontId::proportional(size))
        }
        _ => return,
    };
    // The glued word and the space after it (the text breaks after it),
    // with a point to spare for rounding.
    let tail = format!("{glued} ");
    let together = atom + width(&tail, egui::FontId::proportional(size)) + 1.0;
    let row = ui.max_rect().width();
    let left = ui.available_size_before_wrap().x;
    if together > left && together <= row && left < row - 1.0 {
        ui.end_row();
    }
}

/// egui slants italics by shifting each glyph's top a quarter of its height
/// to the right, so the last letter of an emphasised word leans over the
/// space after it ("away from" read as "awayfrom"). Type-setters add an
/// italic correction there: a little room before the upright text.
fn italic_correction(ui: &mut egui::Ui, next: Option<&Span>, size: f32) {
    let upright = match next {
        Some(Span::Text { style, .. }) => !style.emphasis,
        Some(Span::LineBreak) | None => false,
        Some(_) => true,
    };
    if upright {
        ui.add_space(size * 0.15);
    }
}

fn table_ui(
    ui: &mut egui::Ui,
    align: &[Align],
    header: &[Inline],
    rows: &[Vec<Inline>],
    state: &mut LessonState<'_>,
) {
    // Share the text column among the table's columns in proportion to
    // their longest cell, so the table never overflows and short columns
    // stay narrow.
    let columns = header
        .len()
        .max(rows.iter().map(Vec::len).max().unwrap_or(0))
        .max(1);
    let weight = |col: usize| {
        std::iter::once(header.get(col))
            .chain(rows.iter().map(|r| r.get(col)))
            .flatten()
            .map(|cell| kinolab_lessons::plain_text(cell).chars().count())
            .max()
            .unwrap_or(0)
            .clamp(6, 40) as f32
    };
    let weights: Vec<f32> = (0..columns).map(weight).collect();
    // No column is narrower than its widest word, formula or piece of
    // code, so nothing breaks or runs past its column.
    let size = theme::BODY_SIZE - 1.0;
    let longest_word = |col: usize| {
        std::iter::once(header.get(col))
            .chain(rows.iter().map(|r| r.get(col)))
            .flatten()
            .map(|cell| widest_atom(ui, cell, size))
            .fold(0.0f32, f32::max)
    };
    // Bold headers are a little wider than the measure.
    let least: Vec<f32> = (0..columns).map(|c| longest_word(c) * 1.08 + 4.0).collect();
    let gap = 16.0;
    // The frame's margins and stroke, and a point for egui's rounding of
    // each cell to whole pixels.
    let usable = ui.available_width() - 15.0 - gap * (columns as f32 - 1.0);
    let widths = column_widths(&weights, &least, usable);
    // A table that cannot fit even at its narrowest scrolls sideways.
    sideways(ui, |ui| {
        table_frame(ui, header, rows, align, &widths, gap, state)
    });
}

/// Inline code up to this many characters is kept on one line.
const SHORT_CODE: usize = 24;

/// The widest piece of `cell` that cannot wrap: a word, a word of code or
/// a whole formula, at text size `size`.
fn widest_atom(ui: &egui::Ui, cell: &Inline, size: f32) -> f32 {
    let words = |text: &str, font: egui::FontId| {
        text.split_whitespace()
            .map(|w| {
                ui.painter()
                    .layout_no_wrap(w.to_owned(), font.clone(), Color32::WHITE)
                    .size()
                    .x
            })
            .fold(0.0f32, f32::max)
    };
    cell.iter()
        .map(|span| match span {
            Span::Text { text, .. } => words(text, egui::FontId::proportional(size)),
            Span::Code(code) if code.chars().count() <= SHORT_CODE => {
                let font = egui::FontId::monospace(theme::CODE_SIZE);
                ui.painter()
                    .layout_no_wrap(code.clone(), font, Color32::WHITE)
                    .size()
                    .x
            }
            Span::Code(code) => words(code, egui::FontId::monospace(theme::CODE_SIZE)),
            Span::Math(math) => InlineMath::new(ui, math, &math_style(ui, size)).size().x,
            Span::Image { .. } | Span::LineBreak => 0.0,
        })
        .fold(0.0f32, f32::max)
}

/// Share `usable` points among columns in proportion to `weights`, none
/// narrower than its `least`; when even the least widths do not fit, the
/// columns get exactly those (and the table scrolls).
pub fn column_widths(weights: &[f32], least: &[f32], usable: f32) -> Vec<f32> {
    let mut widths: Vec<f32> = least.to_vec();
    let mut free: Vec<usize> = (0..weights.len()).collect();
    // Columns whose share is below their least width take that width; the
    // rest share what is left, repeated until every share suffices.
    for _ in 0..weights.len() {
        let fixed: f32 = (0..weights.len())
            .filter(|c| !free.contains(c))
            .map(|c| widths[c])
            .sum();
        let left = (usable - fixed).max(0.0);
        let total: f32 = free.iter().map(|&c| weights[c]).sum::<f32>().max(1e-6);
        let short: Vec<usize> = free
            .iter()
            .copied()
            .filter(|&c| left * weights[c] / total < least[c])
            .collect();
        if short.is_empty() {
            for &c in &free {
                widths[c] = left * weights[c] / total;
            }
            break;
        }
        free.retain(|c| !short.contains(c));
    }
    widths
}

fn table_frame(
    ui: &mut egui::Ui,
    header: &[Inline],
    rows: &[Vec<Inline>],
    align: &[Align],
    widths: &[f32],
    gap: f32,
    state: &mut LessonState<'_>,
) {
    egui::Frame::new()
        .stroke(Stroke::new(
            1.0,
            ui.visuals().widgets.noninteractive.bg_stroke.color,
        ))
        .corner_radius(4.0)
        .inner_margin(6.0)
        .show(ui, |ui| {
            ui.spacing_mut().item_spacing.y = 2.0;
            let all_rows = std::iter::once(header).chain(rows.iter().map(Vec::as_slice));
            for (index, row) in all_rows.enumerate() {
                // Rows are laid out in this frame, so a row is as tall as
                // its tallest cell; the stripe is painted behind afterwards.
                let stripe = ui.painter().add(egui::Shape::Noop);
                let response = ui
                    .horizontal_top(|ui| {
                        ui.spacing_mut().item_spacing.x = gap;
                        for (col, cell) in row.iter().enumerate() {
                            let width = widths.get(col).copied().unwrap_or(40.0);
                            cell_ui(ui, cell, align.get(col), width, index == 0, state);
                        }
                    })
                    .response;
                if index % 2 == 1 {
                    let fill = ui.visuals().faint_bg_color;
                    let rect = response.rect.expand2(egui::vec2(4.0, 1.0));
                    ui.painter()
                        .set(stripe, egui::Shape::rect_filled(rect, 2.0, fill));
                } else if index == 0 {
                    let y = response.rect.bottom() + 1.0;
                    let stroke = ui.visuals().widgets.noninteractive.bg_stroke;
                    ui.painter().hline(response.rect.x_range(), y, stroke);
                }
            }
        });
}

fn cell_ui(
    ui: &mut egui::Ui,
    cell: &Inline,
    align: Option<&Align>,
    width: f32,
    header: bool,
    state: &mut LessonState<'_>,
) {
    let layout = match align {
        Some(Align::Right) => egui::Layout::top_down(egui::Align::Max),
        Some(Align::Center) => egui::Layout::top_down(egui::Align::Center),
        _ => egui::Layout::top_down(egui::Align::Min),
    };
    ui.allocate_ui_with_layout(egui::vec2(width, 0.0), layout, |ui| {
        ui.set_width(width);
        inline_ui(ui, cell, theme::BODY_SIZE - 1.0, header, state.navigate);
    });
}

fn widget_ui(
    ui: &mut egui::Ui,
    id: &str,
    spec: &WidgetSpec,
    slots: &mut HashMap<String, WidgetSlot>,
    restore: &mut HashMap<String, String>,
) {
    let slot = slots
        .entry(id.to_owned())
        .or_insert_with(|| kinolab_widgets::registry::create(spec));
    if let (Ok(widget), Some(saved)) = (slot.as_mut(), restore.remove(id))
        && let Err(why) = widget.restore(&saved)
    {
        let notice = format!(
            "This link's settings for the widget could not be used ({why}); it starts as the lesson set it up."
        );
        ui.ctx().data_mut(|d| d.insert_temp(notice_id(id), notice));
    }
    widget_frame(ui, id, &spec.name, slot);
}

/// Where a widget's notice about its link is kept.
fn notice_id(widget: &str) -> egui::Id {
    egui::Id::unique(("kinolab-link-notice", widget))
}

/// A live widget in its frame, or the reason it cannot be shown.
pub fn widget_frame(ui: &mut egui::Ui, id: &str, name: &str, slot: &mut WidgetSlot) {
    egui::Frame::group(ui.style())
        .inner_margin(10.0)
        .corner_radius(6.0)
        .show(ui, |ui| {
            ui.set_width(ui.available_width());
            let notice: Option<String> = ui.ctx().data(|d| d.get_temp(notice_id(id)));
            if let Some(notice) = notice {
                ui.label(egui::RichText::new(notice).color(theme::error_color(ui)));
            }
            ui.push_id(id, |ui| match slot {
                Ok(widget) => {
                    let at = egui::Id::unique(("widget-rect", id));
                    let shown = kinolab_widgets::widget::animated_scope(ui, at, |ui| {
                        ui.scope(|ui| widget.ui(ui))
                    });
                    // Its state in words, for a screen reader (built only
                    // when one listens).
                    ui.ctx().accesskit_node_builder(shown.response.id, |node| {
                        if let Some(words) = widget.describe() {
                            node.set_role(egui::accesskit::Role::Group);
                            node.set_label(words);
                        }
                    });
                }
                Err(message) => error_box(ui, &format!("Widget `{name}` cannot be shown"), message),
            });
        });
}

#[cfg(test)]
mod tests {
    use super::column_widths;

    #[test]
    fn columns_share_the_width_by_weight_when_all_fit() {
        let w = column_widths(&[10.0, 30.0], &[20.0, 20.0], 400.0);
        assert!(
            (w[0] - 100.0).abs() < 1e-3 && (w[1] - 300.0).abs() < 1e-3,
            "{w:?}"
        );
    }

    #[test]
    fn a_short_column_keeps_its_longest_word_and_the_rest_share_what_is_left() {
        // Column 0's share (40) is below its longest word (90).
        let w = column_widths(&[6.0, 27.0, 27.0], &[90.0, 30.0, 30.0], 400.0);
        assert!((w[0] - 90.0).abs() < 1e-3, "{w:?}");
        assert!(
            (w[1] - 155.0).abs() < 1e-3 && (w[2] - 155.0).abs() < 1e-3,
            "{w:?}"
        );
        assert!((w.iter().sum::<f32>() - 400.0).abs() < 1e-3);
    }

    #[test]
    fn a_table_that_cannot_fit_gets_its_least_widths() {
        let w = column_widths(&[1.0, 1.0, 1.0], &[150.0, 150.0, 150.0], 300.0);
        assert_eq!(w, vec![150.0; 3]);
    }
}
