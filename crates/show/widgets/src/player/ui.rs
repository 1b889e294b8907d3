//! The player on screen: a row of buttons with the time, and a scrub bar
//! the widget may colour (who had control, bumps). Every button is a
//! button (Tab reaches it, a tap presses it); the scrub bar takes the
//! keyboard when focused: ← and → step a tick, Shift with them a second,
//! Home and End go to the ends, Space plays and pauses.

use egui::{Key, Painter, Rect, Sense, Stroke, pos2, vec2};
use kinolab_common::display::fixed;

use super::{Player, Simulation, Speed};
use crate::theme;

/// How a widget colours the scrub bar: the painter, the bar, where tick
/// `k` falls along it, and the ticks recorded.
pub type Paint<'a, T> = &'a mut dyn FnMut(&Painter, Rect, &dyn Fn(usize) -> f32, &[T]);

impl<S: Simulation> Player<S> {
    /// Run on as the wall clock says, at most `most` ticks this frame, and
    /// ask for the next frame while playing (paused when scrolled away).
    pub fn run(&mut self, ui: &egui::Ui, most: usize) {
        let seconds = f64::from(ui.input(|i| i.stable_dt).min(0.1));
        self.advance(seconds, most);
        if self.playing || self.catching_up() {
            crate::widget::animate(ui);
        }
    }

    /// Restart, a tick back, play or pause, a tick on, the speed, and the time.
    pub fn controls(&mut self, ui: &mut egui::Ui) {
        buttons(self, ui);
    }

    /// "t = 12.40 s", with how far the run has been recorded when the
    /// instant shown is earlier, and why it stopped.
    pub fn time_label(&self) -> String {
        Transport::time_label(self)
    }

    /// Decimals enough to tell one tick from the next (2 to 4).
    fn decimals(&self) -> usize {
        let dt = self.live.dt().max(1e-4);
        (-dt.log10()).ceil().clamp(2.0, 4.0) as usize
    }

    fn toggle(&mut self) {
        if self.playing {
            self.playing = false;
        } else {
            if self.at_end() && self.over() {
                self.cursor = 0;
            }
            self.playing = true;
        }
    }

    /// The scrub bar, `expected` ticks long (the run's length when known,
    /// else what is recorded), coloured by `paint`; `name` is what a
    /// screen reader calls it.
    pub fn timeline(
        &mut self,
        ui: &mut egui::Ui,
        name: &str,
        expected: usize,
        paint: Paint<'_, S::Tick>,
    ) {
        let total = expected.max(self.len()).max(1);
        let (painter, rect, response) = scrub_bar(ui, total, self.len());
        let x = |k: usize| rect.left() + rect.width() * k as f32 / total as f32;
        paint(&painter, rect, &x, self.ticks());
        scrub(self, ui, (&painter, rect, &response), total, name);
    }
}

/// The scrub bar's ground and its recorded part, `total` (at least 1)
/// ticks long.
fn scrub_bar(ui: &mut egui::Ui, total: usize, recorded: usize) -> (Painter, Rect, egui::Response) {
    let width = ui.available_width();
    let (rect, response) = ui.allocate_exact_size(vec2(width, 22.0), Sense::click_and_drag());
    let right = rect.left() + width * recorded as f32 / total as f32;
    let painter = ui.painter_at(rect.expand(3.0));
    painter.rect_filled(rect, 3.0, ui.visuals().extreme_bg_color);
    let done = egui::Rect::from_min_max(rect.min, pos2(right, rect.max.y));
    painter.rect_filled(done, 3.0, ui.visuals().widgets.inactive.bg_fill);
    (painter, rect, response)
}

/// The instant shown on the scrub bar, the focus ring, and what a click, a
/// drag or a key does there; `name` is what a screen reader calls the bar.
fn scrub(
    p: &mut dyn Transport,
    ui: &egui::Ui,
    (painter, rect, response): (&Painter, Rect, &egui::Response),
    total: usize,
    name: &str,
) {
    let cx = rect.left() + rect.width() * p.cursor() as f32 / total as f32;
    let ink = ui.visuals().text_color();
    painter.line_segment(
        [pos2(cx, rect.top() - 3.0), pos2(cx, rect.bottom() + 3.0)],
        Stroke::new(2.5, ink),
    );
    if response.has_focus() {
        let ring = Stroke::new(2.0, theme::accent(ui));
        painter.rect_stroke(rect, 3.0, ring, egui::StrokeKind::Outside);
    }
    if let Some(at) = response.interact_pointer_pos()
        && (response.clicked() || response.dragged())
    {
        response.request_focus();
        *p.playing() = false;
        let k = ((at.x - rect.left()) / rect.width() * total as f32)
            .round()
            .max(0.0) as usize;
        let len = p.len();
        p.seek(k.min(len));
    }
    keys(p, ui, response);
    let value = p.time();
    response.widget_info(|| {
        let mut info = egui::WidgetInfo::labeled(egui::Role::Slider, true, name);
        info.value = Some(value);
        info
    });
}

/// What the row of buttons and the scrub bar's keys ask of a player,
/// whatever it plays: drawn through this, the row is one piece of code for
/// every simulation rather than a copy per simulation in the lab's wasm.
trait Transport {
    fn restart(&mut self);
    fn step_back(&mut self) -> bool;
    fn step_forward(&mut self) -> bool;
    fn toggle(&mut self);
    fn playing(&mut self) -> &mut bool;
    fn speed(&mut self) -> &mut Speed;
    fn time_label(&self) -> String;
    fn cursor(&self) -> usize;
    fn len(&self) -> usize;
    fn seek(&mut self, k: usize);
    /// Ticks in a simulated second.
    fn per_second(&self) -> usize;
    fn time(&self) -> f64;
}

impl<S: Simulation> Transport for Player<S> {
    fn restart(&mut self) {
        Player::restart(self);
    }
    fn step_back(&mut self) -> bool {
        Player::step_back(self)
    }
    fn step_forward(&mut self) -> bool {
        Player::step_forward(self)
    }
    fn toggle(&mut self) {
        Player::toggle(self);
    }
    fn playing(&mut self) -> &mut bool {
        &mut self.playing
    }
    fn speed(&mut self) -> &mut Speed {
        &mut self.speed
    }
    fn time_label(&self) -> String {
        let recorded = (!self.at_end()).then(|| self.time_at(self.len()));
        let catching = self.catching.as_ref().map(|c| c.instant);
        time_words(
            self.time(),
            self.decimals(),
            catching,
            recorded,
            self.full(),
        )
    }
    fn cursor(&self) -> usize {
        Player::cursor(self)
    }
    fn len(&self) -> usize {
        Player::len(self)
    }
    fn seek(&mut self, k: usize) {
        Player::seek(self, k);
    }
    fn per_second(&self) -> usize {
        (1.0 / self.live.dt().max(1e-9)).round().max(1.0) as usize
    }
    fn time(&self) -> f64 {
        Player::time(self)
    }
}

/// The time shown, with the instant a link's replay runs on to, or how far
/// the run has been recorded, and whether the recording is full.
fn time_words(
    t: f64,
    decimals: usize,
    catching: Option<f64>,
    recorded: Option<f64>,
    full: bool,
) -> String {
    let mut text = format!("t = {} s", fixed(t, decimals));
    if let Some(instant) = catching {
        let target = fixed(instant, decimals.min(1));
        text += &format!(" (running on to the link's {target} s…)");
    } else if let Some(recorded) = recorded {
        let recorded = fixed(recorded, decimals.min(1));
        text += &format!(" (recorded to {recorded} s)");
    }
    if full {
        text += &format!("; the recording is full at {} ticks", super::MAX_TICKS);
    }
    text
}

fn buttons(p: &mut dyn Transport, ui: &mut egui::Ui) {
    ui.horizontal_wrapped(|ui| {
        if ui
            .button("Restart")
            .on_hover_text("Back to the start, and play")
            .clicked()
        {
            p.restart();
        }
        if ui
            .button("Back")
            .on_hover_text("One tick back (←)")
            .clicked()
        {
            p.step_back();
        }
        let label = if *p.playing() { "Pause" } else { "Play" };
        let play = ui.button(label).on_hover_text("Play or pause (Space)");
        crate::probe::publish(ui.ctx(), "player.play", play.rect.center());
        if play.clicked() {
            p.toggle();
        }
        if ui.button("Step").on_hover_text("One tick on (→)").clicked() {
            *p.playing() = false;
            p.step_forward();
        }
        for speed in Speed::ALL {
            let chosen = crate::widget::choose(ui, p.speed(), speed, speed.label())
                .on_hover_text("Playing speed against the clock");
            if crate::probe::enabled(ui.ctx()) {
                let name = format!("player.speed {}", speed.label());
                crate::probe::publish(ui.ctx(), &name, chosen.rect.center());
            }
        }
        ui.label(p.time_label());
    });
}

/// The keyboard on a focused scrub bar.
fn keys(p: &mut dyn Transport, ui: &egui::Ui, response: &egui::Response) {
    if !response.has_focus() {
        return;
    }
    ui.memory_mut(|m| {
        m.set_focus_lock_filter(
            response.id,
            egui::EventFilter {
                horizontal_arrows: true,
                ..Default::default()
            },
        );
    });
    let (left, right, home, end, space, shift) = ui.input(|i| {
        (
            i.key_pressed(Key::ArrowLeft),
            i.key_pressed(Key::ArrowRight),
            i.key_pressed(Key::Home),
            i.key_pressed(Key::End),
            i.key_pressed(Key::Space),
            i.modifiers.shift,
        )
    });
    let jump = if shift { p.per_second() } else { 1 };
    let target = if left {
        Some(p.cursor().saturating_sub(jump))
    } else if right {
        Some(p.cursor() + jump)
    } else if home {
        Some(0)
    } else if end {
        Some(p.len())
    } else {
        None
    };
    if let Some(k) = target {
        *p.playing() = false;
        p.seek(k);
    }
    if space {
        p.toggle();
    }
}
