#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! Every widget against damaged links: truncated, wrong types, numbers out
//! of range, huge and NaN text, unknown keys, other widgets' states, the
//! old format. Each restore either works or says why, never panics, and
//! the widget still draws a frame.

use base64::Engine as _;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use kinolab_widgets::widget::LabWidget;

fn widget(name: &str) -> Box<dyn LabWidget> {
    kinolab_widgets::registry::create(&kinolab_widgets::registry::spec(name, &[])).unwrap()
}

/// A settings link holding these lines.
fn lines(text: &str) -> String {
    format!("b{}", URL_SAFE_NO_PAD.encode(text))
}

/// Damaged states for a widget whose first parameter is `key`.
fn damaged(key: &str) -> Vec<String> {
    let mut cases = vec![
        String::new(),
        "b".into(),
        "zzz".into(),
        "a!!!".into(),
        "b!!!!".into(),
        format!("b{}", "A".repeat(9000)),
        lines(&format!("{key}: 1e308\n")),
        lines(&format!("{key}: -1e308\n")),
        lines(&format!("{key}: NaN\n")),
        lines(&format!("{key}: [[[[[[[[[[\n")),
        lines(&format!("{key}: {}\n", "x".repeat(1 << 20))),
        lines("no-such-key: 1\n"),
        lines("not a setting line\n"),
        lines("@t: -5\n"),
        lines("@t: 99999\n"),
        lines("@events: {\"door\": [}\n"),
        lines("@events: [[1.0, {\"kind\": \"teleport\"}]]\n"),
    ];
    // Old-format states of other shapes.
    cases.push(format!("a{}", URL_SAFE_NO_PAD.encode([0xff_u8; 40])));
    cases.push(format!("a{}", URL_SAFE_NO_PAD.encode([1_u8, 2, 3])));
    cases
}

fn draw(widget: &mut Box<dyn LabWidget>) {
    let ctx = egui::Context::default();
    let mut out = ctx.run_ui(egui::RawInput::default(), |ui| widget.ui(ui));
    out.textures_delta.clear();
}

/// The cases every widget must refuse (the rest it may refuse, or use the
/// part that is valid).
const MUST_REFUSE: usize = 12;

#[test]
fn no_damaged_link_breaks_any_widget() {
    let mut accepted = Vec::new();
    for schema in kinolab_schema::widgets() {
        let first = schema.params.first().map_or("x", |p| p.name);
        for (i, state) in damaged(first).iter().enumerate() {
            let mut w = widget(schema.name);
            if w.restore(state).is_ok() && i < MUST_REFUSE {
                accepted.push(format!("{} case {i}", schema.name));
            }
            draw(&mut w);
        }
    }
    assert!(accepted.is_empty(), "accepted damaged links: {accepted:?}");
}

#[test]
fn a_link_of_another_widget_is_refused_or_harmless() {
    let names: Vec<&str> = kinolab_schema::widgets().map(|w| w.name).collect();
    for pair in names.windows(2) {
        let mut from = widget(pair[0]);
        draw(&mut from);
        let Some(state) = from.state() else { continue };
        let mut to = widget(pair[1]);
        let _ = to.restore(&state);
        draw(&mut to);
    }
}
