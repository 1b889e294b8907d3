//! The gains: sliders, the stability sentence, real-world effects, and the
//! (k_α, k_β) plane with the stable regions and the conditions.

use egui::{RichText, Stroke};
use egui_plot::{Plot, PlotUi, Points, Polygon};
use kinolab_common::angle::snap;
use kinolab_common::display::fixed;
use kinolab_control::{Direction, Gains};

use super::{NAME, Playground};
use crate::theme;
use crate::widget::range;

fn slider(
    ui: &mut egui::Ui,
    value: &mut f64,
    range: std::ops::RangeInclusive<f64>,
    text: &str,
    decimals: usize,
) -> egui::Response {
    ui.add(
        egui::Slider::new(value, range)
            .text(text)
            .step_by(10f64.powi(-(decimals as i32)))
            .fixed_decimals(decimals),
    )
}

fn direction_name(d: Direction) -> &'static str {
    match d {
        Direction::Auto => "auto",
        Direction::Forward => "forward",
        Direction::Backward => "backward",
    }
}

/// The plane's right and bottom edges.
const A_MAX: f64 = 20.0;
const B_MIN: f64 = -10.0;

/// The gain sliders' spans: the textbook's neighbourhood, well inside the
/// schema's ±100 (a lesson or a link may set gains beyond them).
const SPANS: [(f64, f64); 3] = [(-2.0, 10.0), (-5.0, A_MAX), (B_MIN, 5.0)];

impl Playground {
    pub(super) fn gain_sliders(&mut self, ui: &mut egui::Ui) {
        crate::widget::control_row(ui, |ui| {
            let g = &mut self.set.gains;
            for ((value, (low, high)), name) in g.iter_mut().zip(SPANS).zip(["k_ρ", "k_α", "k_β"])
            {
                slider(ui, value, low..=high, name, 1);
            }
            // Labelled, so a screen reader names it too.
            egui::ComboBox::new(ui.scope_id().with("direction"), "driving direction")
                .selected_text(direction_name(self.set.direction))
                .show_ui(ui, |ui| {
                    for d in [Direction::Auto, Direction::Forward, Direction::Backward] {
                        crate::widget::choose(ui, &mut self.set.direction, d, direction_name(d));
                    }
                });
        });
    }

    pub(super) fn stability_line(&self, ui: &mut egui::Ui) {
        let (text, color) = match self.set.gains() {
            Ok(g) => {
                let s = g.stability();
                let color = if s.strongly_stable {
                    theme::good_color(ui)
                } else if s.locally_stable {
                    theme::accent(ui)
                } else {
                    theme::error_color(ui)
                };
                (s.explanation, color)
            }
            Err(e) => (e, theme::error_color(ui)),
        };
        // Two lines kept whatever the verdict, so the plot below never moves.
        crate::widget::status_text(ui, RichText::new(text).color(color), 2);
    }

    pub(super) fn effects(&mut self, ui: &mut egui::Ui) {
        let s = &mut self.set;
        let open = s.slip > 0.0 || s.push > 0.0 || s.control_rate > 0.0 || s.max_wheel_speed > 0.0;
        egui::CollapsingHeader::new("Real-world effects")
            .id_salt(ui.scope_id().with("effects"))
            .default_open(open)
            .show(ui, |ui| {
                crate::widget::control_row(ui, |ui| {
                    slider(ui, &mut s.slip, range(NAME, "slip"), "slip", 2);
                    slider(ui, &mut s.push, range(NAME, "push"), "push (m/s)", 2);
                    let seeds = range(NAME, "seed");
                    ui.add(
                        egui::DragValue::new(&mut s.seed)
                            .range(*seeds.start() as u64..=*seeds.end() as u64)
                            .prefix("seed "),
                    );
                    if ui.button("new seed").clicked() {
                        s.seed = kinolab_common::random::hash(s.seed, 0, 0) % 1_000_000;
                    }
                });
                crate::widget::control_row(ui, |ui| {
                    let rate = range(NAME, "control-rate");
                    ui.add(
                        egui::Slider::new(&mut s.control_rate, rate)
                            .text("control rate (Hz)")
                            .logarithmic(true)
                            .fixed_decimals(0),
                    )
                    .on_hover_text("0 means the controller acts continuously");
                    let limit = range(NAME, "max-wheel-speed");
                    slider(ui, &mut s.max_wheel_speed, limit, "wheel limit (rad/s)", 0)
                        .on_hover_text("0 means the wheels have no speed limit");
                });
            });
    }

    pub(super) fn gains_tab(&mut self, ui: &mut egui::Ui) {
        let Ok(g) = self.set.gains() else { return };
        let width = ui.available_width().min(900.0);
        let mut picked = None;
        let (good, accent) = (theme::good_color(ui), theme::accent(ui));
        let top = ui.cursor().min;
        Plot::new(ui.scope_id().with("gain-plane"))
            .width(width)
            .height(300.0)
            .x_axis_label("k_α")
            .y_axis_label("k_β")
            .allow_drag(false)
            .allow_zoom(false)
            .allow_scroll(false)
            .allow_boxed_zoom(false)
            .allow_double_click_reset(false)
            .include_x(-2.0)
            .include_x(A_MAX)
            .include_y(B_MIN)
            .include_y(4.0)
            .show(ui, |plot| {
                regions(plot, g.k_rho, good);
                plot.points(
                    Points::new("your gains", vec![[g.k_alpha, g.k_beta]])
                        .radius(6.0)
                        .color(accent),
                );
                let response = plot.response();
                if (response.clicked() || response.dragged())
                    && let Some(p) = plot.pointer_coordinate()
                {
                    picked = Some([snap(p.x, 0.1), snap(p.y, 0.1)]);
                }
            });
        crate::draw::plot::legend(
            ui,
            &[
                ("locally stable", good.gamma_multiply(0.5)),
                ("strongly stable", good),
                ("your gains", accent),
            ],
        );
        let area = egui::Rect::from_min_max(top, egui::pos2(top.x + width, ui.cursor().min.y));
        super::export::picture_export(ui, area, "kinolab-gain-plane.png");
        if let Some([a, b]) = picked {
            self.set.gains[1] = a.clamp(SPANS[1].0, SPANS[1].1);
            self.set.gains[2] = b.clamp(SPANS[2].0, SPANS[2].1);
        }
        ui.label(
            RichText::new(format!(
                "The plane at k_ρ = {}. Click or drag in it to pick k_α and k_β, or set them with their sliders above (the arrow keys move a focused slider).",
                fixed(g.k_rho, 1)
            ))
            .small(),
        );
        conditions(ui, &g);
    }
}

/// The locally and strongly stable regions for this k_ρ.
fn regions(plot: &mut PlotUi<'_>, k_rho: f64, good: egui::Color32) {
    if k_rho <= 0.0 {
        return;
    }
    let local = vec![[k_rho, 0.0], [A_MAX, 0.0], [A_MAX, B_MIN], [k_rho, B_MIN]];
    plot.polygon(
        Polygon::new("locally stable", local)
            .fill_color(good.gamma_multiply(0.3))
            .stroke(Stroke::new(1.0, good.gamma_multiply(0.5))),
    );
    // Strong: k_β > (3/5)(2 k_ρ / π − k_α), inside the local region.
    let line = |a: f64| 0.6 * (2.0 * k_rho / std::f64::consts::PI - a);
    let steps = 40;
    let mut strong: Vec<[f64; 2]> = (0..=steps)
        .map(|i| {
            let a = k_rho + (A_MAX - k_rho) * f64::from(i) / f64::from(steps);
            [a, line(a).clamp(B_MIN, 0.0)]
        })
        .collect();
    strong.push([A_MAX, 0.0]);
    strong.push([k_rho, 0.0]);
    plot.polygon(
        Polygon::new("strongly stable", strong)
            .fill_color(good.gamma_multiply(0.6))
            .stroke(Stroke::new(1.0, good)),
    );
}

/// Each condition with its value, and the eigenvalues.
fn conditions(ui: &mut egui::Ui, g: &Gains) {
    let s = g.stability();
    egui::Grid::new(ui.scope_id().with("conditions"))
        .striped(true)
        .show(ui, |ui| {
            for c in &s.conditions {
                let (mark, color) = if c.holds {
                    ("holds", theme::good_color(ui))
                } else {
                    ("fails", theme::error_color(ui))
                };
                ui.label(RichText::new(mark).color(color));
                crate::draw::labels::formula(ui, &tex(c.expression));
                ui.label(fixed(c.value, 3));
                ui.end_row();
            }
        });
    let eig: Vec<String> = s
        .eigenvalues
        .iter()
        .map(|[re, im]| {
            if fixed(*im, 3) == "0.000" {
                fixed(*re, 3)
            } else {
                let sign = if *im < 0.0 { "−" } else { "+" };
                format!("{} {sign} {}i", fixed(*re, 3), fixed(im.abs(), 3))
            }
        })
        .collect();
    ui.label(format!(
        "Eigenvalues of the linearised loop: {}.",
        eig.join(", ")
    ));
}

/// The core's condition (plain text such as `k_alpha - k_rho > 0`) as TeX,
/// so it is typeset the way the lesson writes it.
fn tex(expression: &str) -> String {
    [
        ("k_alpha", "k_\\alpha"),
        ("k_beta", "k_\\beta"),
        ("k_rho", "k_\\rho"),
        ("5/3", "\\frac{5}{3}"),
        ("2/pi", "\\frac{2}{\\pi}"),
    ]
    .iter()
    .fold(expression.to_owned(), |text, (plain, tex)| {
        text.replace(plain, tex)
    })
}

#[cfg(test)]
mod tests {
    #[test]
    fn every_condition_reads_as_a_formula() {
        let g = kinolab_control::TEXTBOOK_GAINS;
        for c in g.stability().conditions {
            let tex = super::tex(c.expression);
            assert!(
                !["k_a", "k_b", "k_r", "/"].iter().any(|p| tex.contains(p)),
                "{tex}"
            );
            kinolab_formula::parse(&tex).unwrap_or_else(|e| panic!("{tex}: {e}"));
        }
        assert_eq!(
            super::tex("k_alpha + 5/3 k_beta - 2/pi k_rho > 0"),
            "k_\\alpha + \\frac{5}{3} k_\\beta - \\frac{2}{\\pi} k_\\rho > 0"
        );
    }
}
