//! Holding still: an arm in a vertical plane, seen from the side, with the
//! torque each joint must give to hold it there as a bar that changes as
//! the learner drags the pose; a payload at the tool and its weight drawn;
//! each bar split into what the arm's own weight asks and what the payload
//! asks; the pose that holds the same tool point with the least torque;
//! and, with springy joints, how far the tool sags (drawn larger on
//! request, the true millimetres printed).

use egui::{Color32, Pos2, RichText, Sense, Stroke, vec2};
use kinolab_common::display::fixed;
use kinolab_mechanism::dynamics::EARTH;
use kinolab_mechanism::dynamics::statics::{Held, Load, Sag};
use kinolab_mechanism::{FrameRef, Model, Plane};
use serde::{Deserialize, Serialize};

use crate::draw::PlaneView;
use crate::link::{self, Moment};
use crate::theme;
use crate::widget::{LabWidget, Params};

/// The widget's name in the schema.
const NAME: &str = "arm-statics";

/// What the lesson sets and a link carries.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    model: String,
    /// The joints, degrees (0 is level, up is positive).
    q: Option<Vec<f64>>,
    /// kg at the tool.
    payload: f64,
    /// N·m/rad at every joint; no springs when left out.
    stiffness: Option<f64>,
    /// Draw the sag larger than it is.
    exaggerate: bool,
}

struct Holding {
    settings: Settings,
    initial: Settings,
    model: Model,
    tool: FrameRef,
    /// The link lengths, from the shoulder out, m.
    lengths: Vec<f64>,
    /// The handle being dragged, if any.
    dragging: Option<usize>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    Ok(Box::new(Holding::new(p.settings()?)?))
}

impl Holding {
    fn new(mut settings: Settings) -> Result<Self, String> {
        let model =
            kinolab_mechanism::catalogue::mechanism(&settings.model).map_err(|e| e.to_string())?;
        let tool = model.frame("tool").map_err(|e| e.to_string())?;
        let zero = vec![0.0; model.dof()];
        let lengths = points(&model, &tool, &zero)
            .windows(2)
            .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
            .filter(|l| *l > 1e-9)
            .collect();
        let q = settings.q.get_or_insert_with(|| vec![0.0; model.dof()]);
        q.resize(model.dof(), 0.0);
        Ok(Holding {
            initial: settings.clone(),
            settings,
            model,
            tool,
            lengths,
            dragging: None,
        })
    }

    fn q(&self) -> Vec<f64> {
        self.settings
            .q
            .iter()
            .flatten()
            .map(|d| d.to_radians())
            .collect()
    }

    fn set_q(&mut self, q: &[f64]) {
        self.settings.q = Some(
            q.iter()
                .map(|r| (r.to_degrees() * 10.0).round() / 10.0)
                .collect(),
        );
    }

    /// The torques that hold the arm at `q` with its payload.
    fn held(&self, q: &[f64]) -> Option<Held> {
        let weight = Load {
            frame: self.tool,
            force: [0.0, 0.0, -self.settings.payload * 9.81],
            moment: [0.0; 3],
        };
        self.model.hold(q, &[weight], EARTH).ok()
    }

    fn sag(&self, q: &[f64], held: &Held) -> Option<Sag> {
        let k = self.settings.stiffness?;
        self.model
            .sag(q, &held.total, &vec![k; self.model.dof()], &self.tool)
            .ok()
    }

    /// Of the poses that put the tool where it is now, the one whose
    /// torques are smallest (their sum of squares).
    fn least_torque(&self) -> Option<Vec<f64>> {
        let q = self.q();
        let tool = *points(&self.model, &self.tool, &q).last()?;
        let cost = |q: &[f64]| {
            self.held(q)
                .map(|h| h.total.iter().map(|t| t * t).sum::<f64>())
        };
        planar_poses(&self.lengths, tool)
            .into_iter()
            .filter_map(|q| Some((cost(&q)?, q)))
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .map(|(_, q)| q)
    }

    fn description(&self) -> String {
        let q = self.q();
        let Some(held) = self.held(&q) else {
            return "The arm cannot be held in this pose.".into();
        };
        let joints: Vec<String> = held
            .total
            .iter()
            .enumerate()
            .map(|(i, t)| format!("{} {} N·m", joint_name(i), fixed(*t, 1)))
            .collect();
        let sag = self.sag(&q, &held).map_or(String::new(), |s| {
            format!(" The tool sags {} mm.", fixed(norm(s.sag) * 1000.0, 1))
        });
        format!(
            "Holding the arm with {} kg at the tool takes {}.{sag}",
            fixed(self.settings.payload, 1),
            joints.join(", ")
        )
    }
}

fn norm(v: [f64; 3]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

fn joint_name(i: usize) -> &'static str {
    ["shoulder", "elbow", "wrist"]
        .get(i)
        .copied()
        .unwrap_or("joint")
}

/// The shoulder, each joint after it and the tool, from the side (x, z).
fn points(model: &Model, tool: &FrameRef, q: &[f64]) -> Vec<[f64; 2]> {
    model
        .chain_in_plane(q, tool, Plane::Side)
        .unwrap_or_default()
}

/// Joint angles of a planar chain of `lengths` whose end is at `tool`:
/// both elbows of a two-link chain; for three links, both elbows for the
/// last link at every degree round.
fn planar_poses(lengths: &[f64], tool: [f64; 2]) -> Vec<Vec<f64>> {
    let two = |l1: f64, l2: f64, p: [f64; 2]| -> Vec<[f64; 2]> {
        let d2 = p[0] * p[0] + p[1] * p[1];
        let c = (d2 - l1 * l1 - l2 * l2) / (2.0 * l1 * l2);
        if !(-1.0..=1.0).contains(&c) {
            return Vec::new();
        }
        [c.acos(), -c.acos()]
            .iter()
            .map(|&q2| {
                let q1 = p[1].atan2(p[0]) - (l2 * q2.sin()).atan2(l1 + l2 * q2.cos());
                [q1, q2]
            })
            .collect()
    };
    match lengths {
        [l1, l2] => two(*l1, *l2, tool)
            .into_iter()
            .map(|q| q.to_vec())
            .collect(),
        [l1, l2, l3] => (0..360)
            .flat_map(|deg| {
                let phi = f64::from(deg).to_radians();
                let wrist = [tool[0] - l3 * phi.cos(), tool[1] - l3 * phi.sin()];
                two(*l1, *l2, wrist)
                    .into_iter()
                    .map(move |[a, b]| vec![a, b, kinolab_common::angle::wrap(phi - a - b)])
            })
            .collect(),
        _ => Vec::new(),
    }
}

/// A factor that makes a sag of `sag` m show as about a seventh of the
/// reach on an
/// arm that reaches `reach` m: 1, 2, 5, 10, 20, …
fn exaggeration(sag: f64, reach: f64) -> f64 {
    let wanted = 0.15 * reach / sag.max(1e-9);
    let mut factor = 1.0;
    for step in [2.0, 2.5, 2.0].iter().cycle().take(30) {
        if factor * step > wanted {
            break;
        }
        factor *= step;
    }
    factor
}

impl Holding {
    /// The arm from the side: its links, a handle at each link's end to
    /// turn it, the payload's weight, and the sagged arm.
    fn scene(&mut self, ui: &mut egui::Ui, width: f32) {
        let reach: f64 = self.lengths.iter().sum::<f64>() + 0.15;
        let (response, painter) = ui.allocate_painter(
            vec2(width, (width * 0.75).clamp(220.0, 420.0)),
            Sense::click_and_drag(),
        );
        let rect = response.rect;
        painter.rect_filled(rect, 4.0, ui.visuals().extreme_bg_color);
        let view = PlaneView::fit(rect.shrink(12.0), [-reach, -reach], [reach, reach]);
        let ink = ui.visuals().text_color();
        let weak = ui.visuals().weak_text_color();
        painter.line_segment(
            [view.to_screen([-reach, 0.0]), view.to_screen([reach, 0.0])],
            Stroke::new(1.0, weak),
        );
        let q = self.q();
        let pts = points(&self.model, &self.tool, &q);
        let held = self.held(&q);
        chain(
            &painter,
            &view,
            &pts,
            Stroke::new(8.0, theme::accent(ui)),
            ink,
        );
        if let (Some(held), true) = (&held, self.settings.stiffness.is_some()) {
            self.draw_sag(&painter, &view, &q, held, reach);
        }
        if let Some(tool) = pts.last() {
            let at = view.to_screen(*tool);
            let m = self.settings.payload;
            if m > 0.0 {
                let size = 6.0 + 3.0 * m.sqrt() as f32;
                painter.rect_filled(
                    egui::Rect::from_center_size(
                        at + vec2(0.0, size),
                        vec2(2.0 * size, 2.0 * size),
                    ),
                    2.0,
                    theme::GOLD,
                );
                let arrow = vec2(0.0, 18.0 + 8.0 * m.sqrt() as f32);
                crate::draw::marks::arrow(
                    &painter,
                    at + vec2(0.0, 2.0 * size + 2.0),
                    arrow,
                    6.0,
                    Stroke::new(2.0, theme::RED),
                );
                painter.text(
                    at + vec2(10.0, 2.0 * size + 10.0),
                    egui::Align2::LEFT_TOP,
                    format!("{} N", fixed(m * 9.81, 1)),
                    egui::FontId::proportional(13.0),
                    theme::RED,
                );
            }
        }
        // Handles: the end of each link turns its joint.
        let handles: Vec<Pos2> = pts.iter().skip(1).map(|p| view.to_screen(*p)).collect();
        for h in &handles {
            painter.circle_filled(*h, 6.0, ink);
        }
        if response.drag_started()
            && let Some(at) = response.interact_pointer_pos()
        {
            self.dragging = handles
                .iter()
                .enumerate()
                .map(|(i, h)| (i, h.distance(at)))
                .filter(|(_, d)| *d < 24.0)
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .map(|(i, _)| i);
        }
        if response.drag_stopped() {
            self.dragging = None;
        }
        if let (Some(i), Some(at)) = (self.dragging, response.interact_pointer_pos())
            && i < q.len()
        {
            let joint = pts[i];
            let [x, z] = view.to_world(at);
            let absolute = (z - joint[1]).atan2(x - joint[0]);
            let before: f64 = q[..i].iter().sum();
            let mut moved = q.clone();
            moved[i] = kinolab_common::angle::wrap(absolute - before);
            self.set_q(&moved);
        }
    }

    /// The arm as its springy joints let it sag (dashed, larger than life
    /// on request), and how far the tool really goes.
    fn draw_sag(
        &self,
        painter: &egui::Painter,
        view: &PlaneView,
        q: &[f64],
        held: &Held,
        reach: f64,
    ) {
        let Some(sag) = self.sag(q, held) else { return };
        let factor = if self.settings.exaggerate {
            exaggeration(norm(sag.sag), reach)
        } else {
            1.0
        };
        let given: Vec<f64> = q
            .iter()
            .zip(&sag.deflection)
            .map(|(q, d)| q - factor * d)
            .collect();
        let sagged = points(&self.model, &self.tool, &given);
        let color = theme::ORANGE;
        for w in sagged.windows(2) {
            let (a, b) = (view.to_screen(w[0]), view.to_screen(w[1]));
            painter.add(egui::Shape::dashed_line(
                &[a, b],
                Stroke::new(2.0, color),
                6.0,
                4.0,
            ));
        }
        if let Some(s) = sagged.last() {
            let text = if factor > 1.0 {
                format!(
                    "sag {} mm, drawn ×{}",
                    fixed(norm(sag.sag) * 1000.0, 1),
                    factor
                )
            } else {
                format!("sag {} mm", fixed(norm(sag.sag) * 1000.0, 1))
            };
            // Below and to the left of the tool: the weight's label is on its right.
            painter.text(
                view.to_screen(*s) + vec2(-14.0, 10.0),
                egui::Align2::RIGHT_TOP,
                text,
                egui::FontId::proportional(13.0),
                color,
            );
        }
    }

    /// Each joint's torque as a bar: the arm's own weight, then the
    /// payload's, in N·m.
    fn bars(&self, ui: &mut egui::Ui, width: f32) {
        let q = self.q();
        let Some(held) = self.held(&q) else { return };
        let biggest = held
            .gravity
            .iter()
            .zip(&held.load)
            .map(|(g, l)| g.abs() + l.abs())
            .fold(1.0, f64::max);
        let scale = f64::from(width - 20.0) / 2.0 / biggest;
        let all: f64 = held.total.iter().map(|t| t.abs()).sum::<f64>().max(1e-9);
        for (i, ((g, l), t)) in held
            .gravity
            .iter()
            .zip(&held.load)
            .zip(&held.total)
            .enumerate()
        {
            let share = 100.0 * t.abs() / all;
            ui.label(format!(
                "{}: {} N·m ({}% of all the torque)",
                joint_name(i),
                fixed(*t, 1),
                fixed(share, 0)
            ));
            let (rect, _) = ui.allocate_exact_size(vec2(width - 20.0, 14.0), Sense::hover());
            let p = ui.painter();
            let mid = rect.center().x;
            p.line_segment(
                [egui::pos2(mid, rect.top()), egui::pos2(mid, rect.bottom())],
                Stroke::new(1.0, ui.visuals().weak_text_color()),
            );
            let segment = |from: f64, by: f64, color: Color32| {
                let (a, b) = (
                    mid + (from * scale) as f32,
                    mid + ((from + by) * scale) as f32,
                );
                p.rect_filled(
                    egui::Rect::from_x_y_ranges(a.min(b)..=a.max(b), rect.y_range()),
                    1.0,
                    color,
                );
            };
            segment(0.0, *g, theme::BLUE);
            segment(*g, *l, theme::GOLD);
        }
        ui.label(
            RichText::new("blue: the arm's own weight; gold: the payload; right of the line lifts")
                .size(theme::LABEL_SIZE)
                .weak(),
        );
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        let n = self.model.dof();
        let mut q = self.settings.q.clone().unwrap_or_default();
        crate::widget::control_row(ui, |ui| {
            for (i, v) in q.iter_mut().enumerate().take(n) {
                ui.add(
                    egui::Slider::new(v, -180.0..=180.0)
                        .suffix("°")
                        .text(joint_name(i)),
                );
            }
        });
        self.settings.q = Some(q);
        crate::widget::control_row(ui, |ui| {
            ui.add(
                egui::Slider::new(
                    &mut self.settings.payload,
                    crate::widget::range(NAME, "payload"),
                )
                .suffix(" kg")
                .text("payload"),
            );
            let mut springs = self.settings.stiffness.is_some();
            if ui.checkbox(&mut springs, "springy joints").changed() {
                self.settings.stiffness = springs.then_some(2000.0);
            }
            if let Some(k) = &mut self.settings.stiffness {
                ui.add(
                    egui::Slider::new(k, crate::widget::range(NAME, "stiffness"))
                        .logarithmic(true)
                        .suffix(" N·m/rad")
                        .text("stiffness"),
                );
                ui.checkbox(&mut self.settings.exaggerate, "draw the sag larger");
            }
            if ui.button("Least torque for this tool point").on_hover_text("Of the poses that put the tool where it is, take the one whose joints work least").clicked()
                && let Some(best) = self.least_torque()
            {
                self.set_q(&best);
            }
        });
    }
}

/// A chain of links from the side, with a ring at each joint.
fn chain(
    painter: &egui::Painter,
    view: &PlaneView,
    pts: &[[f64; 2]],
    stroke: Stroke,
    ink: Color32,
) {
    for w in pts.windows(2) {
        painter.line_segment([view.to_screen(w[0]), view.to_screen(w[1])], stroke);
    }
    for p in pts.iter().take(pts.len().saturating_sub(1)) {
        painter.circle_stroke(
            view.to_screen(*p),
            stroke.width * 0.7,
            Stroke::new(2.0, ink),
        );
    }
}

impl LabWidget for Holding {
    fn describe(&self) -> Option<String> {
        Some(self.description())
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        crate::widget::panels(ui, 2, |ui, i, width| {
            if i == 0 {
                self.scene(ui, width);
            } else {
                self.bars(ui, width);
            }
        });
        crate::widget::status_text(ui, self.description(), 2);
    }

    fn state(&self) -> Option<String> {
        link::write(
            NAME,
            &self.settings,
            &self.initial,
            &Moment::<()>::default(),
        )
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let (settings, _): (Settings, Moment<()>) = link::read(NAME, state)?;
        let initial = self.initial.clone();
        *self = Holding::new(settings)?;
        self.initial = initial;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    fn holding(model: &str, payload: f64) -> Holding {
        Holding::new(Settings {
            model: model.into(),
            q: Some(vec![30.0, -20.0, 10.0]),
            payload,
            stiffness: Some(2000.0),
            exaggerate: true,
        })
        .unwrap()
    }

    #[test]
    fn the_least_torque_pose_keeps_the_tool_and_needs_less() {
        for model in ["vertical-2r", "vertical-3r"] {
            let h = holding(model, 2.0);
            let q = h.q();
            let best = h.least_torque().unwrap();
            let (before, after) = (
                points(&h.model, &h.tool, &q),
                points(&h.model, &h.tool, &best),
            );
            let (a, b) = (before.last().unwrap(), after.last().unwrap());
            assert!(
                (a[0] - b[0]).hypot(a[1] - b[1]) < 1e-9,
                "{model}: the tool stays"
            );
            let cost = |q: &[f64]| h.held(q).unwrap().total.iter().map(|t| t * t).sum::<f64>();
            assert!(cost(&best) <= cost(&q) + 1e-9, "{model}");
        }
    }

    #[test]
    fn a_heavier_payload_asks_more_of_every_joint_and_sags_further() {
        let (light, heavy) = (holding("vertical-3r", 0.0), holding("vertical-3r", 3.0));
        let q = light.q();
        let (l, h) = (light.held(&q).unwrap(), heavy.held(&q).unwrap());
        for (a, b) in l.total.iter().zip(&h.total) {
            assert!(b.abs() > a.abs(), "{a} vs {b}");
        }
        let (sl, sh) = (light.sag(&q, &l).unwrap(), heavy.sag(&q, &h).unwrap());
        assert!(norm(sh.sag) > norm(sl.sag));
        assert!(sh.sag[1].abs() < 1e-12, "it sags in its own plane");
        assert_eq!(exaggeration(0.001, 1.0), 100.0);
    }
}
