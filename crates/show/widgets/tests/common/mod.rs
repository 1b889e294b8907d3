//! What the widget tests share: a widget in a kittest harness, driven
//! as a learner drives it, and the time its player shows.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use kinolab_widgets::widget::LabWidget;

/// Frames a quarter of a second apart (kittest's own step).
#[allow(dead_code)] // not every test binary steps this way
pub const KITTEST_STEP: f32 = 0.25;

/// The widget `name`, as a lesson block with `params` builds it.
pub fn widget(name: &str, params: &[(&str, &str)]) -> Box<dyn LabWidget> {
    kinolab_widgets::registry::create(&kinolab_widgets::registry::spec(name, params)).unwrap()
}

pub struct Host {
    pub widget: Box<dyn LabWidget>,
    ready: bool,
}

/// `widget` on a tall page, each frame `step_dt` seconds after the last.
pub fn harness(widget: Box<dyn LabWidget>, step_dt: f32) -> Harness<'static, Host> {
    Harness::builder()
        .with_size(egui::vec2(1200.0, 3000.0))
        .with_step_dt(step_dt)
        .build_ui_state(
            |ui, host: &mut Host| {
                if host.ready {
                    host.widget.ui(ui);
                } else {
                    kinolab_widgets::theme::install(ui.ctx());
                    host.ready = true;
                }
            },
            Host {
                widget,
                ready: false,
            },
        )
}

/// The time the player shows, read from its label.
#[allow(dead_code)] // not every test binary has a player
pub fn shown_time(h: &Harness<'_, Host>) -> f64 {
    use egui_kittest::kittest::NodeT as _;
    let label = h
        .get_all(egui_kittest::kittest::by())
        .filter_map(|n| n.accesskit_node().value())
        .find(|l| l.starts_with("t = "))
        .expect("the player's time");
    let text = label.trim_start_matches("t = ");
    text.split(' ').next().unwrap().parse().unwrap()
}
