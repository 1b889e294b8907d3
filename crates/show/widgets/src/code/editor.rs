//! The code editor: line numbers, the lab's colours for the language
//! (keywords, numbers, strings, comments), and the line of an error marked
//! with its message underneath.

use std::sync::Arc;

use egui::text::{LayoutJob, TextFormat};
use egui::{Color32, FontId, RichText};
use kinolab_script::ScriptError;

use crate::theme;

/// The words the language reserves.
const KEYWORDS: [&str; 16] = [
    "fn", "let", "const", "if", "else", "while", "loop", "for", "in", "do", "until", "return",
    "break", "continue", "true", "false",
];

/// Colours for each kind of token.
struct Palette {
    plain: Color32,
    keyword: Color32,
    number: Color32,
    text: Color32,
    comment: Color32,
}

fn palette(ui: &egui::Ui) -> Palette {
    let dark = ui.visuals().dark_mode;
    Palette {
        plain: ui.visuals().text_color(),
        keyword: if dark {
            theme::PURPLE.gamma_multiply(1.4)
        } else {
            theme::PURPLE
        },
        number: if dark {
            theme::TEAL.gamma_multiply(1.3)
        } else {
            theme::TEAL
        },
        text: if dark {
            theme::GOLD.gamma_multiply(1.4)
        } else {
            theme::GOLD
        },
        comment: ui.visuals().weak_text_color(),
    }
}

/// `code` coloured token by token.
pub(super) fn highlight(ui: &egui::Ui, code: &str) -> LayoutJob {
    let p = palette(ui);
    let font = FontId::monospace(theme::CODE_SIZE);
    let mut job = LayoutJob::default();
    let mut rest = code;
    while !rest.is_empty() {
        let (len, color) = token(rest, &p);
        let (piece, after) = rest.split_at(len);
        job.append(piece, 0.0, TextFormat::simple(font.clone(), color));
        rest = after;
    }
    job
}

/// The length in bytes of the token `s` starts with, and its colour.
fn token(s: &str, p: &Palette) -> (usize, Color32) {
    let first = s.chars().next().unwrap_or(' ');
    let upto = |stop: &dyn Fn(char) -> bool| s.find(stop).unwrap_or(s.len());
    if s.starts_with("//") {
        return (upto(&|c| c == '\n'), p.comment);
    }
    if first == '"' {
        let end = s[1..].find('"').map_or(s.len(), |i| i + 2);
        return (end, p.text);
    }
    if first.is_ascii_digit() {
        return (
            upto(&|c: char| !(c.is_ascii_alphanumeric() || c == '.' || c == '_')),
            p.number,
        );
    }
    if first.is_alphabetic() || first == '_' {
        let len = upto(&|c: char| !(c.is_alphanumeric() || c == '_'));
        let color = if KEYWORDS.contains(&&s[..len]) {
            p.keyword
        } else {
            p.plain
        };
        return (len, color);
    }
    (first.len_utf8(), p.plain)
}

/// The editor for `code`, numbered, with `error`'s line marked; whether
/// the code changed.
pub(super) fn editor(ui: &mut egui::Ui, code: &mut String, error: Option<&ScriptError>) -> bool {
    let lines = code.lines().count().max(1) + usize::from(code.ends_with('\n'));
    let marked = error.and_then(|e| e.line);
    let bad = theme::error_color(ui);
    let mut changed = false;
    egui::ScrollArea::both()
        .id_salt("code-editor")
        .max_height(360.0)
        // Inside a lesson's own scrolling the editor would otherwise shrink
        // to a few lines: keep room for a short function at a glance.
        .min_scrolled_height(240.0)
        .show(ui, |ui| {
            ui.horizontal_top(|ui| {
                ui.spacing_mut().item_spacing.x = 6.0;
                numbers(ui, lines, marked, bad);
                let mut layouter = |ui: &egui::Ui, text: &dyn egui::TextBuffer, _wrap: f32| {
                    let job = highlight(ui, text.as_str());
                    ui.fonts_mut(|f| f.layout_job(job))
                };
                let edit = egui::TextEdit::multiline(code)
                    .code_editor()
                    .desired_width(f32::INFINITY)
                    .desired_rows(12)
                    .layouter(&mut layouter)
                    .id_salt("code-text");
                let response = ui.add(edit);
                response.widget_info(|| {
                    egui::WidgetInfo::labeled(egui::Role::MultilineTextInput, true, "Your code")
                });
                changed = response.changed();
            });
        });
    if let Some(e) = error {
        ui.label(
            RichText::new(error_line(e))
                .color(bad)
                .size(theme::LABEL_SIZE),
        );
    }
    changed
}

/// The error as the learner reads it under the editor.
pub(super) fn error_line(e: &ScriptError) -> String {
    match (e.line, e.column) {
        (Some(l), Some(c)) => format!("Line {l}, column {c}: {}", e.message),
        (Some(l), None) => format!("Line {l}: {}", e.message),
        _ => e.message.clone(),
    }
}

/// The line numbers beside the code, the error's line in `bad`.
fn numbers(ui: &mut egui::Ui, lines: usize, marked: Option<usize>, bad: Color32) {
    let font = FontId::monospace(theme::CODE_SIZE);
    let weak = ui.visuals().weak_text_color();
    let mut job = LayoutJob::default();
    for n in 1..=lines {
        let (color, mark) = if Some(n) == marked {
            (bad, "→")
        } else {
            (weak, " ")
        };
        let text = if n == lines {
            format!("{mark}{n:>3}")
        } else {
            format!("{mark}{n:>3}\n")
        };
        job.append(&text, 0.0, TextFormat::simple(font.clone(), color));
    }
    let galley: Arc<egui::Galley> = ui.fonts_mut(|f| f.layout_job(job));
    // The text edit's frame pads its text by its margin: match it.
    ui.add_space(0.0);
    ui.vertical(|ui| {
        ui.add_space(ui.spacing().button_padding.y.max(2.0) + 2.0);
        ui.label(galley);
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(code: &str) -> Vec<(String, &'static str)> {
        let p = Palette {
            plain: Color32::WHITE,
            keyword: Color32::RED,
            number: Color32::GREEN,
            text: Color32::BLUE,
            comment: Color32::GRAY,
        };
        let name = |c: Color32| match c {
            c if c == Color32::RED => "keyword",
            c if c == Color32::GREEN => "number",
            c if c == Color32::BLUE => "text",
            c if c == Color32::GRAY => "comment",
            _ => "plain",
        };
        let mut out = Vec::new();
        let mut rest = code;
        while !rest.is_empty() {
            let (len, color) = token(rest, &p);
            let (piece, after) = rest.split_at(len);
            if !piece.trim().is_empty() {
                out.push((piece.to_owned(), name(color)));
            }
            rest = after;
        }
        out
    }

    #[test]
    fn tokens_get_their_colours() {
        let got = kinds("fn f(x) { let k = 3.5; print(\"hi\"); } // done");
        let find = |t: &str| got.iter().find(|(p, _)| p == t).map(|(_, k)| *k);
        assert_eq!(find("fn"), Some("keyword"));
        assert_eq!(find("let"), Some("keyword"));
        assert_eq!(find("3.5"), Some("number"));
        assert_eq!(find("\"hi\""), Some("text"));
        assert_eq!(find("// done"), Some("comment"));
        assert_eq!(find("print"), Some("plain"));
        // Every byte is covered once, even odd text.
        let odd = "é\"unclosed";
        assert_eq!(
            kinds(odd)
                .iter()
                .map(|(p, _)| p.as_str())
                .collect::<String>(),
            odd
        );
    }
}
