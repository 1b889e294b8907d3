//! What every widget is, and the small pieces widgets share.

use egui::{RichText, Stroke};
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

    /// Take back a [`LabWidget::state`] from a link. What cannot be used
    /// (damaged, out of range, from another widget) is refused with a line
    /// saying why; the widget then stays as the lesson set it up, and the
    /// lab shows the line as a notice. Nothing a link holds may panic.
    fn restore(&mut self, _state: &str) -> Result<(), String> {
        Ok(())
    }

    /// What the widget shows now, in a sentence or two a screen reader can
    /// read on demand (the wheel workbench: its wheels, degrees and ICR);
    /// `None` for a widget whose controls say it all.
    fn describe(&self) -> Option<String> {
        None
    }

    /// Show the instant `t` seconds into the run (a widget that simulates
    /// runs on as far as it needs to); nothing for a widget that does not.
    fn seek(&mut self, _t: f64) {}

    /// The run shown, as the command line reproduces it ("Save run"); `None`
    /// for a widget that simulates nothing.
    fn saved_run(&mut self) -> Option<SavedRun> {
        None
    }
}

/// A widget's run for the command line: the input file, the command that
/// reads it, and what the widget shows, as that command prints it.
#[derive(Debug, Clone, PartialEq)]
pub struct SavedRun {
    /// The file's name (`push.zmp.json`) and text.
    pub file: String,
    pub text: String,
    /// The command's arguments after `kinolab`, the file's name among them.
    pub args: Vec<String>,
    /// Where in the command's answer (a JSON pointer such as `/samples`)
    /// the widget's own numbers are, and those numbers, up to the instant
    /// it shows: the command must print exactly these.
    pub shows: Vec<(String, serde_json::Value)>,
}

impl SavedRun {
    /// The command as a learner would type it.
    pub fn command(&self) -> String {
        format!("kinolab {}", self.args.join(" "))
    }
}

/// The range a parameter of the widget `widget` allows (its schema's
/// `Number` or `Integer` kind, or each number of a `Numbers` or `Groups`
/// kind): sliders take it from here, so a range is written only in the
/// schema.
pub fn range(widget: &str, param: &str) -> std::ops::RangeInclusive<f64> {
    use kinolab_schema::Kind;
    match kinolab_schema::find(widget)
        .and_then(|w| w.param(param))
        .map(|p| &p.kind)
    {
        Some(
            Kind::Number { min, max }
            | Kind::Numbers { min, max, .. }
            | Kind::Groups { min, max, .. },
        ) => *min..=*max,
        Some(Kind::Integer { min, max }) => (*min as f64)..=(*max as f64),
        _ => 0.0..=1.0,
    }
}

/// Where, this frame, the widget being drawn keeps its animation flags.
fn animation_id() -> egui::Id {
    egui::Id::unique("kinolab-widget-animation")
}

/// Whether the widget being drawn was on screen, and whether it asked for
/// another frame while it was not.
#[derive(Clone, Copy, Default)]
struct Animation {
    off_screen: bool,
    wanted: bool,
}

/// Draw one widget, remembering where it was: a widget scrolled off screen
/// stops asking for frames (see [`animate`]) and starts again as soon as
/// any of it is back in view.
pub fn animated_scope<R>(
    ui: &mut egui::Ui,
    id: egui::Id,
    add: impl FnOnce(&mut egui::Ui) -> R,
) -> R {
    let last: Option<egui::Rect> = ui.ctx().data(|d| d.get_temp(id));
    let off_screen = last.is_some_and(|r| !ui.is_rect_visible(r));
    let flags = animation_id();
    ui.ctx().data_mut(|d| {
        d.insert_temp(
            flags,
            Animation {
                off_screen,
                wanted: false,
            },
        );
    });
    let inner = ui.scope(add);
    let rect = inner.response.rect;
    let animation: Animation = ui.ctx().data_mut(|d| {
        d.insert_temp(id, rect);
        d.remove_temp(flags).unwrap_or_default()
    });
    if animation.wanted && ui.is_rect_visible(rect) {
        // Scrolled back into view this frame: carry on.
        crate::widget::animate(ui);
    }
    inner.inner
}

/// Seconds since the last frame, for stepping an animation: at most 0.1 s,
/// so a stalled tab does not jump ahead.
pub fn frame_dt(ui: &egui::Ui) -> f64 {
    f64::from(ui.input(|i| i.stable_dt).min(0.1))
}

/// Ask for the next frame of a running animation, unless the widget is
/// scrolled out of view (then it pauses where it is).
pub fn animate(ui: &egui::Ui) {
    let flags = animation_id();
    let paused = ui.ctx().data_mut(|d| match d.get_temp::<Animation>(flags) {
        Some(a) if a.off_screen => {
            d.insert_temp(flags, Animation { wanted: true, ..a });
            true
        }
        _ => false,
    });
    if !paused {
        ui.ctx().request_repaint();
    }
}

/// Builds a widget from its checked parameters.
pub type Constructor = fn(&Params) -> Result<Box<dyn LabWidget>, String>;

/// A visible, readable error in place of content that could not be shown.
pub fn error_box(ui: &mut egui::Ui, title: &str, message: &str) {
    let red = theme::error_color(ui);
    egui::Frame::new()
        .fill(red.gamma_multiply(0.16))
        .stroke(Stroke::new(1.5, red))
        .corner_radius(6.0)
        .inner_margin(10.0)
        .show(ui, |ui| {
            ui.set_width(ui.available_width());
            ui.label(RichText::new(title).strong().color(red));
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
            theme::error_color(ui)
        };
        message_ui(ui, &feedback_text(f), color);
    }
}

/// A message from the core in `color`, its `backticked` names (ports,
/// services, behaviours) set in the code face without the backticks.
pub fn message_ui(ui: &mut egui::Ui, text: &str, color: egui::Color32) -> egui::Response {
    let body = egui::TextStyle::Body.resolve(ui.style());
    let code = egui::FontId::monospace(body.size * 0.95);
    let mut job = egui::text::LayoutJob::default();
    for (i, part) in text.split('`').enumerate() {
        let font = if i % 2 == 1 {
            code.clone()
        } else {
            body.clone()
        };
        job.append(part, 0.0, egui::TextFormat::simple(font, color));
    }
    job.wrap.max_width = ui.available_width();
    ui.label(job)
}

/// A feedback as one sentence or more: "Solved. " before a met goal's
/// message, the message's first letter a capital.
pub fn feedback_text(f: &Feedback) -> String {
    let sentence = sentence(f.message.trim());
    if f.met {
        format!("Solved. {sentence}")
    } else {
        sentence
    }
}

/// `text` as the start of a sentence: its first letter a capital (the core
/// writes its reasons in lower case, to be quoted mid-sentence too).
pub fn sentence(text: &str) -> String {
    let mut chars = text.chars();
    match chars.next() {
        Some(first) => first.to_uppercase().chain(chars).collect(),
        None => String::new(),
    }
}

/// Narrower than this, points, a widget stacks what it shows side by side.
pub const NARROW: f32 = 560.0;

/// One option of a choice, framed even when not chosen so that every
/// option reads as a button; the chosen one is highlighted.
pub fn choice(
    ui: &mut egui::Ui,
    selected: bool,
    text: impl Into<egui::WidgetText>,
) -> egui::Response {
    ui.add(egui::Button::selectable(selected, text).frame_when_inactive(true))
}

/// [`choice`] bound to `current`: a click sets it to `value`.
pub fn choose<T: PartialEq>(
    ui: &mut egui::Ui,
    current: &mut T,
    value: T,
    text: impl Into<egui::WidgetText>,
) -> egui::Response {
    let mut response = choice(ui, *current == value, text);
    if response.clicked() && *current != value {
        *current = value;
        response.mark_changed();
    }
    response
}

/// Whether `ui` is too narrow for a widget's panels side by side.
pub fn narrow(ui: &egui::Ui) -> bool {
    ui.available_width() < NARROW
}

/// `count` panels side by side on a wide column, one under the other on a
/// narrow one; `add(ui, i, width)` draws panel `i` at the width it gets.
pub fn panels(ui: &mut egui::Ui, count: usize, mut add: impl FnMut(&mut egui::Ui, usize, f32)) {
    if narrow(ui) || count < 2 {
        let width = ui.available_width();
        for i in 0..count {
            ui.vertical(|ui| add(ui, i, width));
        }
        return;
    }
    let gap = ui.spacing().item_spacing.x;
    let width = (ui.available_width() - gap * (count - 1) as f32) / count as f32;
    ui.horizontal_top(|ui| {
        for i in 0..count {
            ui.vertical(|ui| {
                ui.set_width(width);
                add(ui, i, width);
            });
        }
    });
}

/// A row of controls (sliders, buttons, choices): side by side, wrapping,
/// on a wide column; one under the other on a narrow one. (egui cannot
/// move a slider with its number and label to the next line on its own,
/// so a row of sliders would run off a phone's screen.)
pub fn control_row<R>(ui: &mut egui::Ui, add: impl FnOnce(&mut egui::Ui) -> R) -> R {
    if narrow(ui) {
        ui.vertical(add).inner
    } else {
        ui.horizontal_wrapped(add).inner
    }
}

/// `count` like controls (one slider per leg, say) in as many columns of
/// about `cell` points as the column has room for, row after row; one
/// under the other on a narrow column. ([`control_row`] cannot wrap them:
/// egui gives each slider the rest of the row.)
pub fn control_grid(
    ui: &mut egui::Ui,
    id: &str,
    count: usize,
    cell: f32,
    mut add: impl FnMut(&mut egui::Ui, usize),
) {
    let columns = ((ui.available_width() / cell.max(1.0)) as usize).clamp(1, count.max(1));
    egui::Grid::new(id).num_columns(columns).show(ui, |ui| {
        for i in 0..count {
            add(ui, i);
            if (i + 1) % columns == 0 {
                ui.end_row();
            }
        }
    });
}

/// Content that cannot get narrower (a grid of numbers, a wide formula)
/// scrolls sideways when the column is too narrow, instead of running off
/// the screen's edge. A solid scroll bar and a fade at the clipped edge say
/// there is more (a phone shows no hover bar), and the up-and-down part of
/// a drag that starts on it still scrolls the page.
pub fn sideways<R>(ui: &mut egui::Ui, add: impl FnOnce(&mut egui::Ui) -> R) -> R {
    let width = ui.available_width();
    let scroll = std::mem::replace(
        &mut ui.spacing_mut().scroll,
        egui::style::ScrollStyle::solid(),
    );
    // A page has several of these in one parent: each needs its own id.
    let out = egui::ScrollArea::horizontal()
        .id_salt(ui.next_auto_id())
        .max_width(width)
        .show(ui, |ui| {
            ui.spacing_mut().scroll = scroll;
            // Lay out for the column (centred content stays centred); only
            // what is wider than the column scrolls.
            ui.set_max_width(width);
            add(ui)
        });
    ui.spacing_mut().scroll = scroll;
    let hidden_left = out.state.clamped_offset().x > 0.5;
    let hidden_right =
        out.content_size.x - out.state.clamped_offset().x > out.inner_rect.width() + 0.5;
    if hidden_left || hidden_right {
        let over = out.content_size.x - out.inner_rect.width();
        ui.ctx().data_mut(|d| {
            // Kept for a check (see `take_scrolled_sideways`); bounded, as
            // nothing takes it in the lab.
            let seen = d.get_temp_mut_or_default::<Vec<f32>>(overflow_id());
            if seen.len() < 64 {
                seen.push(over);
            }
        });
    }
    let panel = ui.visuals().panel_fill;
    if hidden_left {
        edge_fade(ui.painter(), out.inner_rect, egui::Align::Min, panel);
    }
    if hidden_right {
        edge_fade(ui.painter(), out.inner_rect, egui::Align::Max, panel);
    }
    let dragged = ui
        .ctx()
        .read_response(out.id.with("area"))
        .is_some_and(|r| r.dragged());
    if dragged {
        let dy = ui.input(|i| i.pointer.delta().y);
        ui.scroll_with_delta_animation(egui::vec2(0.0, dy), egui::style::ScrollAnimation::none());
    }
    out.inner
}

fn overflow_id() -> egui::Id {
    egui::Id::unique("kinolab-sideways-overflow")
}

/// By how many points each [`sideways`] area drawn since the last call was
/// wider than its column (it scrolled): a page that should fit can check
/// that nothing had to scroll.
pub fn take_scrolled_sideways(ctx: &egui::Context) -> Vec<f32> {
    ctx.data_mut(|d| d.remove_temp::<Vec<f32>>(overflow_id()))
        .unwrap_or_default()
}

/// A band at one side of `rect` fading from clear to `color`: the sign
/// that content goes on beyond that edge.
fn edge_fade(painter: &egui::Painter, rect: egui::Rect, side: egui::Align, color: egui::Color32) {
    let band = 28.0_f32.min(rect.width() / 4.0);
    let (x_clear, x_solid) = match side {
        egui::Align::Min => (rect.left() + band, rect.left()),
        _ => (rect.right() - band, rect.right()),
    };
    let clear = egui::Color32::TRANSPARENT;
    let mut mesh = egui::Mesh::default();
    mesh.colored_vertex(egui::pos2(x_clear, rect.top()), clear);
    mesh.colored_vertex(egui::pos2(x_solid, rect.top()), color);
    mesh.colored_vertex(egui::pos2(x_clear, rect.bottom()), clear);
    mesh.colored_vertex(egui::pos2(x_solid, rect.bottom()), color);
    mesh.add_triangle(0, 1, 2);
    mesh.add_triangle(1, 2, 3);
    painter.add(mesh);
}

/// A status text whose length changes with what the learner does, in a
/// space at least `lines` lines tall, so that what follows it stays put.
pub fn status_text(ui: &mut egui::Ui, text: impl Into<egui::WidgetText>, lines: usize) {
    let row = ui.text_style_height(&egui::TextStyle::Body) + ui.spacing().item_spacing.y;
    let width = ui.available_width();
    ui.allocate_ui_with_layout(
        egui::vec2(width, 0.0),
        egui::Layout::top_down(egui::Align::Min),
        |ui| {
            ui.set_min_size(egui::vec2(
                width,
                row * lines as f32 - ui.spacing().item_spacing.y,
            ));
            ui.label(text);
        },
    );
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn backticked_names_lose_their_backticks_on_screen() {
        use egui_kittest::kittest::Queryable as _;
        // The lab's fonts take effect a frame after they are installed.
        let mut h = egui_kittest::Harness::new_ui_state(
            |ui, ready: &mut bool| {
                if *ready {
                    message_ui(ui, "`planner.map` is not connected", egui::Color32::RED);
                } else {
                    crate::theme::install(ui.ctx());
                    *ready = true;
                }
            },
            false,
        );
        h.run_steps(2);
        h.get_by_label("planner.map is not connected");
    }

    #[test]
    fn feedback_reads_as_sentences_with_solved_said_once() {
        let met = Feedback::met("the omni reached the goal.");
        assert_eq!(feedback_text(&met), "Solved. The omni reached the goal.");
        let not_yet = Feedback::not_yet("ändern: one slot");
        assert_eq!(feedback_text(&not_yet), "Ändern: one slot");
        assert_eq!(feedback_text(&Feedback::not_yet("  ")), "");
    }

    /// A page of text with a table wider than the screen in the middle.
    fn page_with_a_wide_table(ui: &mut egui::Ui) {
        egui::ScrollArea::vertical().show(ui, |ui| {
            for i in 0..12 {
                ui.label(format!("line {i} above"));
            }
            sideways(ui, |ui| {
                ui.add_sized([900.0, 80.0], egui::Label::new("a wide table"));
            });
            for i in 0..40 {
                ui.label(format!("line {i} below"));
            }
        });
    }

    #[test]
    fn a_drag_up_that_starts_on_a_wide_table_scrolls_the_page() {
        use egui_kittest::kittest::Queryable as _;
        let mut h = egui_kittest::Harness::builder()
            .with_size(egui::vec2(320.0, 400.0))
            .build_ui_state(
                |ui, ready: &mut bool| {
                    if *ready {
                        page_with_a_wide_table(ui);
                    } else {
                        crate::theme::install(ui.ctx());
                        *ready = true;
                    }
                },
                false,
            );
        h.run_steps(2);
        let table = h.get_by_label("a wide table").rect().center();
        let top = |h: &egui_kittest::Harness<'_, bool>| h.get_by_label("line 0 above").rect().top();
        let before = top(&h);
        // What a browser sends for a finger: touch events and the pointer
        // events egui makes of them.
        let finger = |h: &mut egui_kittest::Harness<'_, bool>, phase, pos| {
            h.event(egui::Event::Touch {
                device_id: egui::TouchDeviceId(1),
                id: egui::TouchId(1),
                phase,
                pos,
                force: None,
            });
            match phase {
                egui::TouchPhase::Move => h.event(egui::Event::PointerMoved(pos)),
                _ => {
                    h.event(egui::Event::PointerMoved(pos));
                    h.event(egui::Event::PointerButton {
                        pos,
                        button: egui::PointerButton::Primary,
                        pressed: phase == egui::TouchPhase::Start,
                        modifiers: egui::Modifiers::NONE,
                    });
                }
            }
            h.run_steps(1);
        };
        let press = egui::pos2(160.0, table.y);
        finger(&mut h, egui::TouchPhase::Start, press);
        for step in 1..=10 {
            let at = press + egui::vec2(-4.0 * step as f32, -15.0 * step as f32);
            finger(&mut h, egui::TouchPhase::Move, at);
        }
        let moved = top(&h) - before;
        assert!(
            moved < -120.0,
            "the page moved {moved} px for a 150 px drag up"
        );
    }
}
