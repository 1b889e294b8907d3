//! A quiz card: the question, the answer controls, a Check button, and the
//! verdict with its explanation once answered.

use egui::{RichText, Stroke};
use kinolab_lessons::{Answer, Inline, Quiz, QuizKind};

use crate::lesson_view::inline_ui;
use crate::route::Page;
use kinolab_widgets::theme;

/// What the learner has entered so far, and the last verdict.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct QuizState {
    pub choice: Option<usize>,
    pub ticks: Vec<bool>,
    pub typed: String,
    /// Sorting: the bin picked for each item.
    pub sorted: Vec<Option<usize>>,
    /// `Some(true)` right, `Some(false)` wrong, `None` not checked yet.
    pub verdict: Option<bool>,
    /// A problem with the input (such as text that is not a number).
    pub input_error: Option<String>,
}

/// Parse what was typed into a numeric answer, accepting a decimal comma
/// and thin separators (`39 916 800`, `0,5`).
pub fn parse_typed_number(text: &str) -> Option<f64> {
    let cleaned: String = text
        .trim()
        .chars()
        .filter(|c| !c.is_whitespace() && *c != '_' && *c != '\u{2009}')
        .map(|c| if c == ',' { '.' } else { c })
        .collect();
    cleaned.parse::<f64>().ok().filter(|v| v.is_finite())
}

/// Draw the quiz; returns true when the learner pressed Check with a
/// well-formed answer this frame (the verdict is then in `state`).
pub fn quiz_ui(
    ui: &mut egui::Ui,
    id: &str,
    quiz: &Quiz,
    state: &mut QuizState,
    navigate: &mut Option<Page>,
) -> bool {
    let mut checked = false;
    let accent = theme::accent(ui);
    egui::Frame::new()
        .stroke(Stroke::new(1.5, accent.gamma_multiply(0.7)))
        .fill(accent.gamma_multiply(0.06))
        .corner_radius(8.0)
        .inner_margin(12.0)
        .show(ui, |ui| {
            ui.set_width(ui.available_width());
            ui.push_id(id, |ui| {
                ui.label(RichText::new("Check yourself").small().color(accent));
                inline_ui(ui, &quiz.question, theme::BODY_SIZE, true, navigate);
                ui.add_space(4.0);
                let answer = answer_controls(ui, quiz, state, navigate);
                ui.add_space(4.0);
                ui.horizontal(|ui| {
                    let button = ui.button(RichText::new("Check answer").size(theme::BODY_SIZE));
                    if button.clicked() {
                        match answer {
                            Some(answer) => {
                                state.input_error = None;
                                state.verdict = quiz.check(&answer).ok();
                                checked = state.verdict.is_some();
                            }
                            None => {
                                state.verdict = None;
                                state.input_error = Some(match quiz.kind {
                                    QuizKind::Numeric { .. } => {
                                        "Type a number first, such as 120 or 0.5.".to_owned()
                                    }
                                    QuizKind::Sort { .. } => {
                                        "Put every item in a bin first.".to_owned()
                                    }
                                    _ => "Choose an answer first.".to_owned(),
                                });
                            }
                        }
                    }
                    if let Some(error) = &state.input_error {
                        ui.label(RichText::new(error).color(theme::error_color(ui)));
                    }
                });
                if let Some(right) = state.verdict {
                    ui.add_space(6.0);
                    let (text, color) = if right {
                        ("Right.", theme::good_color(ui))
                    } else {
                        (
                            "Not quite. Read why, then try again.",
                            theme::error_color(ui),
                        )
                    };
                    ui.label(
                        RichText::new(text)
                            .strong()
                            .size(theme::BODY_SIZE)
                            .color(color),
                    );
                    sort_feedback(ui, quiz, state, navigate);
                    inline_ui(ui, &quiz.explain, theme::BODY_SIZE, false, navigate);
                }
            });
        });
    checked
}

/// The controls for the quiz's kind; returns the answer entered, if any.
fn answer_controls(
    ui: &mut egui::Ui,
    quiz: &Quiz,
    state: &mut QuizState,
    navigate: &mut Option<Page>,
) -> Option<Answer> {
    match &quiz.kind {
        QuizKind::Single { options, .. } => {
            for (i, option) in options.iter().enumerate() {
                let selected = state.choice == Some(i);
                let clicked = option_control(ui, option, selected, false, navigate);
                if clicked {
                    state.choice = Some(i);
                    state.verdict = None;
                }
            }
            state.choice.map(Answer::Single)
        }
        QuizKind::Multiple { options, .. } => {
            state.ticks.resize(options.len(), false);
            ui.label(RichText::new("Tick every right answer.").italics());
            for (i, option) in options.iter().enumerate() {
                let ticked = state.ticks[i];
                let clicked = option_control(ui, option, ticked, true, navigate);
                if clicked {
                    state.ticks[i] = !ticked;
                    state.verdict = None;
                }
            }
            Some(Answer::Multiple(state.ticks.clone()))
        }
        QuizKind::Numeric { unit, .. } => {
            ui.horizontal_wrapped(|ui| {
                let label = ui.label(RichText::new("Your answer:").size(theme::BODY_SIZE));
                let edit = egui::TextEdit::singleline(&mut state.typed)
                    .hint_text("a number")
                    .desired_width(140.0);
                let response = ui.add(edit).labelled_by(label.id);
                if response.changed() {
                    state.verdict = None;
                }
                if let Some(unit) = unit {
                    ui.label(unit);
                }
            });
            parse_typed_number(&state.typed).map(Answer::Numeric)
        }
        QuizKind::Sort { bins, items } => {
            state.sorted.resize(items.len(), None);
            ui.label(RichText::new("Put each item in its bin.").italics());
            // The bins before each item's text, lined up down the list; when
            // they take most of the row (a phone, many or long bins) the
            // item's text comes first, its bins under it, and a rule
            // between items says which bins belong to which.
            let bins_width: f32 = bins
                .iter()
                .map(|bin| {
                    let font = egui::FontId::proportional(theme::BODY_SIZE);
                    let text = ui
                        .painter()
                        .layout_no_wrap(bin.clone(), font, egui::Color32::WHITE);
                    text.size().x
                        + 2.0 * ui.spacing().button_padding.x
                        + ui.spacing().item_spacing.x
                })
                .sum();
            let stacked = bins_width > 0.55 * ui.available_width();
            for (i, item) in items.iter().enumerate() {
                if stacked {
                    if i > 0 {
                        ui.separator();
                    }
                    inline_ui(ui, &item.text, theme::BODY_SIZE, false, navigate);
                }
                ui.horizontal_wrapped(|ui| {
                    for (b, bin) in bins.iter().enumerate() {
                        let on = state.sorted[i] == Some(b);
                        let text = RichText::new(bin).size(theme::BODY_SIZE);
                        if kinolab_widgets::widget::choice(ui, on, text).clicked() {
                            state.sorted[i] = Some(b);
                            state.verdict = None;
                        }
                    }
                    if !stacked {
                        ui.add_space(6.0);
                        inline_ui(ui, &item.text, theme::BODY_SIZE, false, navigate);
                    }
                });
            }
            state
                .sorted
                .iter()
                .copied()
                .collect::<Option<Vec<usize>>>()
                .map(Answer::Sort)
        }
    }
}

/// After a sorting question is checked: each item, right or where it
/// belongs, with its reason.
fn sort_feedback(ui: &mut egui::Ui, quiz: &Quiz, state: &QuizState, navigate: &mut Option<Page>) {
    let QuizKind::Sort { bins, items } = &quiz.kind else {
        return;
    };
    let Some(picks) = state.sorted.iter().copied().collect::<Option<Vec<usize>>>() else {
        return;
    };
    let Ok(marks) = quiz.sort_marks(&Answer::Sort(picks)) else {
        return;
    };
    // The verdict and the item on one line, the reason under them across
    // the column's whole width (beside them it would get only what is
    // left of the line, and break inside its words).
    for (i, (item, right)) in items.iter().zip(marks).enumerate() {
        ui.horizontal_wrapped(|ui| {
            let (text, color) = if right {
                ("right:".to_owned(), theme::good_color(ui))
            } else {
                (
                    format!("belongs in {}:", bins[item.bin]),
                    theme::error_color(ui),
                )
            };
            ui.label(RichText::new(text).color(color).size(theme::BODY_SIZE));
            inline_ui(ui, &item.text, theme::BODY_SIZE, false, navigate);
        });
        if let Some(why) = &item.why {
            ui.indent(("sort-why", i), |ui| {
                inline_ui(ui, why, theme::BODY_SIZE, false, navigate);
            });
        }
        ui.add_space(4.0);
    }
}

/// One option: a radio button or checkbox, then the option's text set like
/// any lesson text (so options with and without formulas line up and share
/// one colour); a click anywhere on the row picks it. Returns true if clicked.
fn option_control(
    ui: &mut egui::Ui,
    option: &Inline,
    on: bool,
    checkbox: bool,
    navigate: &mut Option<Page>,
) -> bool {
    let row = ui.horizontal(|ui| {
        let response = if checkbox {
            let mut value = on;
            ui.checkbox(&mut value, "")
        } else {
            ui.radio(on, "")
        };
        // The control has no text of its own: name it for screen readers.
        let role = if checkbox {
            egui::Role::CheckBox
        } else {
            egui::Role::RadioButton
        };
        let name = kinolab_lessons::plain_text(option);
        response.widget_info(|| egui::WidgetInfo::selected(role, true, on, name.clone()));
        ui.vertical(|ui| inline_ui(ui, option, theme::BODY_SIZE, false, navigate));
        response.clicked()
    });
    // Clickable, not a second tab stop: the keyboard reaches the option
    // through its radio button or check box.
    let text = row.response.interact(egui::Sense::CLICK);
    if text.hovered() {
        ui.ctx().set_cursor_icon(egui::CursorIcon::PointingHand);
    }
    row.inner || text.clicked()
}
