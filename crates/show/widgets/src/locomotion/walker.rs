//! The hexapod walker: the lab's hexapod model carried through a gait by
//! per-leg inverse kinematics. The 3D view shows the legs, the support
//! polygon of the feet on the ground and the centre of mass above it; a
//! plot follows one leg's joint angles through the cycle.

use egui::{RichText, Sense, Stroke, vec2};
use egui_plot::{Plot, PlotPoints};
use kinolab_common::display::fixed;
use kinolab_locomotion::walker::{Step, Walker};
use kinolab_mechanism::Vector3;
use serde::{Deserialize, Serialize};

use crate::draw::plot::{REFERENCE, series_legend, series_lines};
use crate::draw::scene3d::{Camera, ViewKind, draw_capsule};
use crate::draw::{canvas_3d, corner_text};
use crate::widget::{LabWidget, Params};

/// The plotted joints of the left front leg, in the model's order.
const JOINTS: [&str; 3] = ["coxa", "femur", "tibia"];
use crate::{link, theme};

use kinolab_locomotion::HEXAPOD_IDS as GAITS;
/// Instants per cycle in the joint plot.
const PLOT_SAMPLES: usize = 60;

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Setup {
    gait: String,
    stride: f64,
    lift: f64,
    /// Cycles per second.
    rate: f64,
}

struct HexapodWalker {
    setup: Setup,
    initial: Setup,
    walker: Option<Walker>,
    /// The cycle sampled for the plot, and the set-up it was made for.
    cycle: Option<(Setup, Vec<Step>)>,
    step: Option<Step>,
    tau: f64,
    playing: bool,
    camera: Camera,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let setup = Setup {
        gait: p.choice("gait").unwrap_or("hexapod-tripod").to_owned(),
        stride: p.number("stride").unwrap_or(0.06),
        lift: 0.03,
        rate: 0.5,
    };
    let mut w = HexapodWalker {
        initial: setup.clone(),
        setup,
        walker: None,
        cycle: None,
        step: None,
        tau: 0.0,
        playing: true,
        camera: Camera::new(ViewKind::Orbit, [0.0, 0.0, 0.08], 0.3),
    };
    w.rebuild();
    Ok(Box::new(w))
}

impl HexapodWalker {
    fn rebuild(&mut self) {
        self.walker = kinolab_locomotion::named(&self.setup.gait).and_then(|mut g| {
            g.stride = self.setup.stride;
            Walker::new(g, self.setup.lift).ok()
        });
        self.step = None;
    }

    /// Move to `tau`, starting the IK from the last instant's joints.
    fn advance(&mut self, tau: f64) {
        let Some(w) = &self.walker else { return };
        let seed = self
            .step
            .as_ref()
            .map_or_else(|| w.model.zero_state(), |s| s.q.clone());
        self.step = w.step(tau, &seed).ok();
        self.tau = tau;
    }

    fn cycle(&mut self) -> Option<&[Step]> {
        let fresh = matches!(&self.cycle, Some((s, _)) if *s == self.setup);
        if !fresh {
            let w = self.walker.as_ref()?;
            let mut q = w.model.zero_state();
            let mut steps = Vec::with_capacity(PLOT_SAMPLES + 1);
            for k in 0..=PLOT_SAMPLES {
                let s = w.step(k as f64 / PLOT_SAMPLES as f64, &q).ok()?;
                q = s.q.clone();
                steps.push(s);
            }
            self.cycle = Some((self.setup.clone(), steps));
        }
        self.cycle.as_ref().map(|(_, s)| s.as_slice())
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        let before = self.setup.clone();
        ui.horizontal_wrapped(|ui| {
            for g in GAITS {
                let label = g.trim_start_matches("hexapod-");
                ui.selectable_value(&mut self.setup.gait, g.to_owned(), label);
            }
            let label = if self.playing { "Pause" } else { "Play" };
            if ui.button(label).clicked() {
                self.playing = !self.playing;
            }
        });
        ui.add(
            egui::Slider::new(&mut self.setup.stride, 0.0..=0.3)
                .step_by(0.005)
                .text("stride L (m)"),
        );
        ui.add(
            egui::Slider::new(&mut self.setup.lift, 0.0..=0.06)
                .step_by(0.005)
                .text("foot lift (m)"),
        );
        ui.add(egui::Slider::new(&mut self.setup.rate, 0.1..=1.5).text("cycles per second"));
        let mut tau = self.tau;
        if ui
            .add(egui::Slider::new(&mut tau, 0.0..=1.0).text("τ (cycle)"))
            .changed()
        {
            self.playing = false;
            self.advance(tau);
        }
        if self.setup != before {
            self.rebuild();
            self.advance(self.tau);
        }
    }

    fn scene(&mut self, ui: &mut egui::Ui) {
        let size = vec2(ui.available_width().min(760.0), 340.0);
        let (response, painter) = canvas_3d(ui, size, Sense::click_and_drag(), &self.camera);
        let rect = response.rect;
        self.camera.handle(ui, &response, true);
        let (Some(w), Some(step)) = (&self.walker, &self.step) else {
            return;
        };
        let cam = &self.camera;
        // The support polygon: the stance feet on the ground.
        let stance: Vec<[f64; 2]> = (0..6)
            .filter(|&i| w.gait.in_stance(i, step.tau))
            .map(|i| [step.targets[i][0], step.targets[i][1]])
            .collect();
        let hull = kinolab_locomotion::convex_hull(&stance);
        let margin = kinolab_locomotion::static_stability([0.0, 0.0], &stance)
            .ok()
            .map(|s| s.margin);
        let good = margin.is_some_and(|m| m > 0.0);
        let color = if good {
            theme::good_color(ui)
        } else {
            theme::error_color(ui)
        };
        let pts: Vec<egui::Pos2> = hull
            .iter()
            .map(|p| cam.project(rect, &Vector3::new(p[0], p[1], 0.0)).0)
            .collect();
        if pts.len() >= 3 {
            painter.add(egui::Shape::convex_polygon(
                pts,
                color.gamma_multiply(0.2),
                Stroke::new(1.5, color),
            ));
        } else if pts.len() == 2 {
            painter.line_segment([pts[0], pts[1]], Stroke::new(2.0, color));
        }
        let (com, _) = cam.project(rect, &Vector3::zeros());
        painter.circle_filled(com, 5.0, color);
        let Ok(placed) = w.model.place(&step.q) else {
            return;
        };
        let ink = ui.visuals().text_color();
        for s in w.model.shapes() {
            let at = &placed.bodies[s.body];
            let a = at.rotation * s.a + at.translation.vector;
            let b = at.rotation * s.b + at.translation.vector;
            draw_capsule(
                &painter,
                cam,
                rect,
                &a,
                &b,
                s.radius,
                ink.gamma_multiply(0.3),
            );
        }
        for (i, t) in step.targets.iter().enumerate() {
            let (p, _) = cam.project(rect, &Vector3::from(*t));
            let missed = step.errors[i] > kinolab_locomotion::walker::REACHED;
            let c = if missed {
                theme::error_color(ui)
            } else {
                theme::accent(ui)
            };
            painter.circle_stroke(p, 4.0, Stroke::new(1.5, c));
        }
        let text = match margin {
            Some(m) => format!(
                "stance feet {}; static margin S = {} m",
                stance.len(),
                fixed(m, 3)
            ),
            None => "no foot on the ground".to_owned(),
        };
        corner_text(&painter, rect, 0, text, ink);
        if !step.unreachable.is_empty() {
            let text = format!("out of reach: {}", step.unreachable.join(", "));
            corner_text(&painter, rect, 1, text, theme::error_color(ui));
        }
    }

    fn plot(&mut self, ui: &mut egui::Ui) {
        let tau = self.tau;
        let Some(cycle) = self.cycle() else { return };
        // The left-front leg's three joints (the first three variables).
        let series = |k: usize| -> PlotPoints<'static> {
            cycle
                .iter()
                .enumerate()
                .map(|(n, s)| {
                    let tau = n as f64 / PLOT_SAMPLES as f64;
                    [tau, s.q.get(k).copied().unwrap_or(0.0).to_degrees()]
                })
                .collect()
        };
        Plot::new(ui.scope_id().with("walker-joints"))
            .height(160.0)
            .x_axis_label("τ (cycle)")
            .y_axis_label("left front leg (°)")
            .allow_scroll(false)
            .show(ui, |plot| {
                let values = (0..JOINTS.len()).map(series);
                series_lines(plot, JOINTS.into_iter().zip(values).collect(), Some(tau));
            });
        series_legend(ui, &JOINTS, &[("now", REFERENCE)]);
    }
}

impl LabWidget for HexapodWalker {
    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        if self.step.is_none() {
            self.advance(self.tau);
        }
        self.scene(ui);
        ui.label(RichText::new("Drag to turn the view. Rings: where each foot should be (red when the leg cannot reach it); the polygon: the stance feet; the dot: the centre of mass.").small());
        self.plot(ui);
        if self.playing {
            let dt = crate::widget::frame_dt(ui);
            self.advance((self.tau + dt * self.setup.rate).rem_euclid(1.0));
            crate::widget::animate(ui);
        }
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.setup, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(s) = link::decode::<Setup>(state)
            && GAITS.contains(&s.gait.as_str())
            && (0.0..=0.3).contains(&s.stride)
            && (0.0..=0.06).contains(&s.lift)
            && (0.1..=1.5).contains(&s.rate)
        {
            self.setup = s;
            self.rebuild();
        }
        Ok(())
    }
}
