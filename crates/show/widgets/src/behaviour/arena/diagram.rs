//! The coordinator's own picture, lit by the step shown: the sum's parts,
//! subsumption's layers with their nodes, the vote over candidate arcs,
//! the sequencer's states.

use egui::{Align2, Color32, FontId, RichText, Sense, Stroke, pos2, vec2};
use kinolab_behaviours::coordinate::sequencer::{Sequencer, Trigger};
use kinolab_behaviours::coordinate::subsumption::{NodeKind, Subsumption};
use kinolab_behaviours::coordinate::{Coordinator, Trace};
use kinolab_common::display::fixed;

use super::{Arena, Shown, sets};
use crate::theme;

impl Arena {
    pub(super) fn diagram(&mut self, ui: &mut egui::Ui) {
        ui.set_min_width(250.0);
        if self.task.is_none() {
            ui.label(RichText::new("Coordination").strong());
            ui.horizontal_wrapped(|ui| {
                for c in sets::COORDINATORS {
                    if crate::widget::choice(ui, self.settings.coordinator == c, c.name()).clicked()
                        && self.settings.coordinator != c
                    {
                        let mut settings = self.settings.clone();
                        settings.coordinator = c;
                        self.change(settings);
                    }
                }
            });
            if self.settings.coordinator == sets::CoordinatorKind::Subsumption {
                self.top_node_choice(ui);
            }
        }
        let names = self.names();
        let Some(coordinator) = self.setup.as_ref().map(|s| s.coordinator.clone()) else {
            return;
        };
        let record = self.shown().and_then(|r| r.last.clone());
        let record = record.as_ref();
        match &coordinator {
            Coordinator::Sum { gains } => {
                ui.label(
                    "Vector summation: every active behaviour's arrow, times its gain, added.",
                );
                for (i, (name, color)) in names.iter().zip(self.colors()).enumerate() {
                    let gain = gains.get(name).copied().unwrap_or(1.0);
                    let size = record
                        .and_then(|r| r.vectors[i])
                        .map_or("off".to_owned(), |v| format!("{} m/s", fixed(v.norm(), 2)));
                    ui.label(RichText::new(format!("■ {name}: gain {gain}, {size}")).color(color));
                }
            }
            Coordinator::Subsumption(s) => subsumption(ui, s, &names, &self.colors(), record),
            Coordinator::Voting(_) => votes(ui, record),
            Coordinator::Sequencer(s) => states(ui, s, record),
            Coordinator::Script { .. } => {
                let chose = match record.map(|r| &r.trace) {
                    Some(Trace::Script { chose: Some(name) }) => format!("chose `{name}`"),
                    Some(Trace::Script { chose: None }) => "drove itself".to_owned(),
                    _ => "has not run yet".to_owned(),
                };
                let text = format!("Your coordinator {chose}.");
                crate::widget::message_ui(ui, &text, ui.visuals().text_color());
            }
        }
    }
}

impl Arena {
    /// Whether avoid's node replaces the message below it or silences it.
    fn top_node_choice(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.label("avoid's node:");
            for (kind, name) in [
                (NodeKind::Suppress, "suppress"),
                (NodeKind::Inhibit, "inhibit"),
            ] {
                let chosen = self.settings.top_node == kind;
                if crate::widget::choice(ui, chosen, name).clicked() && !chosen {
                    let mut settings = self.settings.clone();
                    settings.top_node = kind;
                    self.change(settings);
                }
            }
        });
    }
}

/// Layers stacked (the highest on top), each with its wire running right;
/// level 0's wire reaches the motors. Nodes sit on the wires they act on
/// and light up while they act.
fn subsumption(
    ui: &mut egui::Ui,
    s: &Subsumption,
    names: &[String],
    colors: &[Color32],
    record: Option<&Shown>,
) {
    let acting = match record.map(|r| &r.trace) {
        Some(Trace::Subsumption { acting }) => acting.clone(),
        _ => vec![false; s.nodes.len()],
    };
    let rows = s.layers.len();
    let (rect, _) = ui.allocate_exact_size(vec2(260.0, 36.0 * rows as f32 + 24.0), Sense::hover());
    let painter = ui.painter_at(rect);
    let ink = ui.visuals().text_color();
    let accent = theme::accent(ui);
    let font = FontId::proportional(theme::TITLE_SIZE);
    let y = |level: usize| rect.top() + 18.0 + 36.0 * (rows - 1 - level) as f32;
    let box_right = rect.left() + 90.0;
    let motor_x = rect.right() - 40.0;
    for (level, name) in s.layers.iter().enumerate() {
        let i = names.iter().position(|n| n == name).unwrap_or(0);
        let color = colors.get(i).copied().unwrap_or(theme::NEUTRAL);
        let b = egui::Rect::from_min_max(
            pos2(rect.left() + 4.0, y(level) - 12.0),
            pos2(box_right, y(level) + 12.0),
        );
        let lit = record.is_some_and(|r| r.vectors.get(i).is_some_and(Option::is_some));
        painter.rect(
            b,
            4.0,
            color.gamma_multiply(if lit { 0.5 } else { 0.15 }),
            Stroke::new(1.0, color),
            egui::StrokeKind::Middle,
        );
        painter.text(
            b.center(),
            Align2::CENTER_CENTER,
            format!("{level}: {name}"),
            font.clone(),
            ink,
        );
        let end = if level == 0 { motor_x } else { motor_x - 30.0 };
        painter.line_segment(
            [pos2(box_right, y(level)), pos2(end, y(level))],
            Stroke::new(1.5, ink.gamma_multiply(0.6)),
        );
    }
    painter.text(
        pos2(motor_x + 4.0, y(0)),
        Align2::LEFT_CENTER,
        "motors",
        font.clone(),
        ink,
    );
    for (k, node) in s.nodes.iter().enumerate() {
        let level = |n: &str| s.layers.iter().position(|l| l == n).unwrap_or(0);
        let (by, on) = (level(&node.by), level(&node.on));
        let x = box_right + 30.0 + 34.0 * k as f32;
        let at = pos2(x, y(on));
        painter.line_segment(
            [pos2(x, y(by)), at],
            Stroke::new(1.5, ink.gamma_multiply(0.6)),
        );
        let lit = acting.get(k).copied().unwrap_or(false);
        let fill = if lit {
            accent
        } else {
            ui.visuals().extreme_bg_color
        };
        painter.circle(at, 10.0, fill, Stroke::new(1.5, accent));
        let letter = if node.node == NodeKind::Suppress {
            "S"
        } else {
            "I"
        };
        painter.text(
            at,
            Align2::CENTER_CENTER,
            letter,
            font.clone(),
            if lit { Color32::WHITE } else { ink },
        );
    }
    ui.label(
        RichText::new("S: suppress (replaces the wire's message) · I: inhibit (silences it)")
            .small(),
    );
}

/// A bar per candidate arc, hard right to hard left; the winner in accent.
fn votes(ui: &mut egui::Ui, record: Option<&Shown>) {
    ui.label("Voting: each behaviour votes on every arc; the highest total wins.");
    let (rect, _) = ui.allocate_exact_size(vec2(260.0, 120.0), Sense::hover());
    let painter = ui.painter_at(rect);
    let ink = ui.visuals().text_color();
    let mid = rect.center().y;
    painter.line_segment(
        [pos2(rect.left(), mid), pos2(rect.right(), mid)],
        Stroke::new(1.0, ink.gamma_multiply(0.4)),
    );
    let Some(Trace::Voting { totals, winner, .. }) = record.map(|r| &r.trace) else {
        return;
    };
    let top = totals.iter().fold(1e-9f64, |m, t| m.max(t.abs()));
    let w = rect.width() / totals.len() as f32;
    for (k, t) in totals.iter().enumerate() {
        let h = (t / top) as f32 * (rect.height() / 2.0 - 14.0);
        let x = rect.left() + w * k as f32;
        let bar = egui::Rect::from_two_pos(pos2(x + 1.0, mid), pos2(x + w - 1.0, mid - h));
        let c = if *winner == Some(k) {
            theme::accent(ui)
        } else {
            ink.gamma_multiply(0.35)
        };
        painter.rect_filled(bar, 1.0, c);
    }
    let font = FontId::proportional(theme::LABEL_SIZE);
    painter.text(
        rect.left_bottom(),
        Align2::LEFT_BOTTOM,
        "hard right",
        font.clone(),
        ink,
    );
    painter.text(
        rect.right_bottom(),
        Align2::RIGHT_BOTTOM,
        "hard left",
        font,
        ink,
    );
}

/// The states in a row, the current one lit, and the transitions.
fn states(ui: &mut egui::Ui, s: &Sequencer, record: Option<&Shown>) {
    let current = match record.map(|r| &r.trace) {
        Some(Trace::Sequencer { state }) => state.clone(),
        _ => s.start.clone(),
    };
    ui.horizontal_wrapped(|ui| {
        for st in &s.states {
            let lit = st.name == current;
            let text = RichText::new(format!(" {} ", st.name)).strong();
            let text = if lit {
                text.background_color(theme::accent(ui))
                    .color(Color32::WHITE)
            } else {
                text
            };
            ui.label(text)
                .on_hover_text(format!("active: {}", st.behaviours.join(", ")));
        }
    });
    for t in &s.transitions {
        ui.label(
            RichText::new(format!(
                "{} → {} when {}",
                t.from,
                t.to,
                trigger_text(&t.when)
            ))
            .small(),
        );
    }
}

fn trigger_text(t: &Trigger) -> String {
    match t {
        Trigger::Bump => "a bumper is pressed".into(),
        Trigger::GoalWithin { distance } => format!("the goal is within {distance} m"),
        Trigger::LightAbove { level } => format!("the light reads above {level}"),
        Trigger::LightBelow { level } => format!("the light reads below {level}"),
        Trigger::ObstacleAhead { distance } => format!("something is within {distance} m ahead"),
        Trigger::ClearAhead { distance } => format!("the way ahead is clear for {distance} m"),
        Trigger::After { seconds } => format!("{seconds} s have passed"),
    }
}
