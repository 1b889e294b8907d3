//! Picture tests: formulas typeset and drawn, compared with the PNGs in
//! `tests/snapshots/` (rendered on the CPU, so the same on every machine).
//! After an intended change, run with `UPDATE_SNAPSHOTS=true` and look at
//! the new pictures before committing them.

use egui::Color32;
use kinolab_formula::layout::{MathStyle, display_math};

/// Draw `formula` displayed on a white card and compare it with the snapshot `name`.
fn picture(name: &str, formula: &str) {
    let math = kinolab_formula::parse(formula).unwrap_or_else(|e| panic!("{formula}: {e}"));
    let mut harness = kinolab_picture::harness()
        .with_size(egui::vec2(360.0, 120.0))
        .build_ui(move |ui| {
            ui.ctx()
                .set_fonts(kinolab_formula::layout::fonts::definitions());
            ui.ctx().set_visuals(egui::Visuals::light());
            egui::Frame::new().fill(Color32::WHITE).show(ui, |ui| {
                ui.set_min_size(ui.available_size());
                let style = MathStyle {
                    size: 22.0,
                    color: Color32::BLACK,
                };
                display_math(ui, &math, &style);
            });
        });
    harness.run();
    harness.snapshot(name);
}

#[test]
fn a_fraction_sits_on_the_math_axis() {
    picture(
        "fraction",
        r"v = \frac{V_R + V_L}{2},\; \omega = \frac{V_R - V_L}{W}",
    );
}

#[test]
fn scripts_and_primes_shrink_and_stack() {
    picture(
        "scripts",
        r"x_{ij}^{2} + e^{-d/\lambda} + f'(x) + \sum_{i=1}^{n} w_i",
    );
}

#[test]
fn roots_stretch_over_their_contents() {
    picture(
        "roots",
        r"\rho = \sqrt{\Delta x^2 + \Delta y^2} + \sqrt{\frac{1}{2}}",
    );
}

#[test]
fn matrices_get_brackets_as_tall_as_their_rows() {
    picture(
        "matrix",
        r"R(\theta) = \begin{bmatrix} \cos\theta & \sin\theta & 0 \\ -\sin\theta & \cos\theta & 0 \\ 0 & 0 & 1 \end{bmatrix}",
    );
}

#[test]
fn fences_grow_with_what_they_enclose() {
    picture(
        "fences",
        r"\left( \frac{a}{b} \right) \cdot \left\{ x \right\} + \left| \frac{1}{d} - \frac{1}{D} \right|",
    );
}
