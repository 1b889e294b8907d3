//! The morphology builder: the lab's own mechanism model read as the
//! AnyMorphology pattern. Elements (bodies) and pairs (joints) as a flat
//! graph beside the mechanism hierarchy; delete the port a pair hangs on
//! and the pair dissolves; pick two elements for the transform between
//! them through the ports; switch the plugged-in closed forms off and the
//! generic tree walk answers instead.

use egui::{FontId, RichText, Sense, Stroke, pos2, vec2};
use kinolab_common::display::fixed;
use kinolab_design::morphology::{between, chain};
use kinolab_mechanism::{Model, Pose};

use crate::draw::canvas;
use crate::draw::labels::Labels;
use crate::theme;
use crate::widget::{LabWidget, Params};

const MECHANISMS: [&str; 3] = ["planar-3r", "rover-arm", "hexapod"];

struct Morphology {
    id: String,
    model: Option<Model>,
    q: Vec<f64>,
    dissolved: Vec<usize>,
    from: usize,
    to: usize,
    commands: bool,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let mut w = Morphology {
        id: p.choice("mechanism").unwrap_or("planar-3r").to_owned(),
        model: None,
        q: Vec::new(),
        dissolved: Vec::new(),
        from: 0,
        to: 0,
        commands: true,
    };
    w.load();
    Ok(Box::new(w))
}

impl Morphology {
    fn load(&mut self) {
        self.model = kinolab_mechanism::catalogue::mechanism(&self.id).ok();
        self.q = self.model.as_ref().map_or_else(Vec::new, |m| {
            (0..m.dof())
                .map(|i| 0.3 * ((i % 3) as f64 - 1.0) + 0.2)
                .collect()
        });
        self.dissolved.clear();
        self.from = 0;
        self.to = self
            .model
            .as_ref()
            .map_or(0, |m| m.bodies().len().saturating_sub(1));
    }

    /// The flat graph: every element at its depth in the tree, pairs as
    /// lines; a dissolved pair dashed, what hangs below it faded.
    fn graph(&self, ui: &mut egui::Ui, model: &Model, width: f32) {
        let n = model.bodies().len();
        let depth: Vec<usize> = (0..n).map(|b| chain(model, b).len()).collect();
        let max_depth = depth.iter().copied().max().unwrap_or(0);
        let mut rows = vec![0usize; max_depth + 1];
        let mut slot = vec![0usize; n];
        for b in 0..n {
            slot[b] = rows[depth[b]];
            rows[depth[b]] += 1;
        }
        let tallest = rows.iter().copied().max().unwrap_or(1).max(1);
        let height = (tallest as f32 * 22.0 + 20.0).clamp(140.0, 420.0);
        let (response, painter) = canvas(ui, vec2(width, height), Sense::hover());
        let rect = response.rect;
        let at = |b: usize| {
            let x = rect.left()
                + 40.0
                + (rect.width() - 80.0) * depth[b] as f32 / max_depth.max(1) as f32;
            let y = rect.top()
                + 14.0
                + (rect.height() - 28.0) * (slot[b] as f32 + 0.5) / rows[depth[b]].max(1) as f32;
            pos2(x, y)
        };
        let cut = |b: usize| chain(model, b).iter().any(|j| self.dissolved.contains(j));
        let ink = ui.visuals().text_color();
        let faint = ui.visuals().weak_text_color();
        for (j, joint) in model.joints().iter().enumerate() {
            let (a, b) = (at(joint.parent), at(joint.child));
            if self.dissolved.contains(&j) {
                painter.add(egui::Shape::dashed_line(
                    &[a, b],
                    Stroke::new(1.5, theme::error_color(ui)),
                    4.0,
                    4.0,
                ));
            } else {
                painter.line_segment(
                    [a, b],
                    Stroke::new(1.2, if cut(joint.child) { faint } else { ink }),
                );
            }
        }
        let chosen = [self.from, self.to];
        let mut labels = Labels::default();
        for b in 0..n {
            labels.reserve(egui::Rect::from_center_size(at(b), vec2(10.0, 10.0)));
        }
        for b in 0..n {
            let color = if chosen.contains(&b) {
                theme::accent(ui)
            } else if cut(b) {
                faint
            } else {
                theme::solid_color(ui)
            };
            painter.circle_filled(at(b), 5.0, color);
            if n <= 14 || chosen.contains(&b) {
                let name = model.bodies()[b].name.as_str();
                labels.add(at(b), name, ink).toward(vec2(1.0, 0.0));
            }
        }
        labels.draw(&painter, &FontId::proportional(theme::SMALL_SIZE));
        for f in model.frames() {
            let p = at(f.body) + vec2(0.0, 9.0);
            painter.rect_filled(
                egui::Rect::from_center_size(p, vec2(5.0, 5.0)),
                1.0,
                theme::GREEN,
            );
        }
    }

    /// The hierarchy: the mechanism, its sub-mechanisms, their elements.
    fn hierarchy(&self, ui: &mut egui::Ui, model: &Model) {
        ui.label(RichText::new(format!("{} (mechanism)", model.name())).strong());
        let groups = model.groups();
        if groups.is_empty() {
            ui.label(format!(
                "  {} elements, {} pairs, no sub-mechanisms",
                model.bodies().len(),
                model.joints().len()
            ));
        }
        for g in groups {
            let depth = std::iter::successors(g.parent, |&p| groups.get(p).and_then(|x| x.parent))
                .count()
                + 1;
            let names: Vec<&str> = g
                .bodies
                .iter()
                .filter_map(|&b| model.bodies().get(b))
                .map(|b| b.name.as_str())
                .collect();
            ui.label(format!(
                "{}{} (mechanism): {}",
                "  ".repeat(depth),
                g.name,
                names.join(", ")
            ));
        }
    }

    fn pairs(&mut self, ui: &mut egui::Ui, model: &Model) {
        egui::CollapsingHeader::new("Pairs: delete the port a pair hangs on").show(ui, |ui| {
            for (j, joint) in model.joints().iter().enumerate() {
                ui.horizontal_wrapped(|ui| {
                    let name = |b: usize| model.bodies().get(b).map_or("?", |x| x.name.as_str());
                    ui.label(format!(
                        "{}: {:?}, {} → {}",
                        joint.name,
                        joint.kind,
                        name(joint.parent),
                        name(joint.child)
                    ));
                    let gone = self.dissolved.contains(&j);
                    let label = if gone {
                        "restore the port"
                    } else {
                        "delete the port"
                    };
                    if ui.small_button(label).clicked() {
                        if gone {
                            self.dissolved.retain(|x| *x != j);
                        } else {
                            self.dissolved.push(j);
                        }
                    }
                });
            }
        });
    }

    fn transform(&mut self, ui: &mut egui::Ui, model: &Model) {
        let names: Vec<String> = model.bodies().iter().map(|b| b.name.clone()).collect();
        ui.horizontal_wrapped(|ui| {
            for (label, pick) in [("from", &mut self.from), ("to", &mut self.to)] {
                egui::ComboBox::from_label(label)
                    .selected_text(names.get(*pick).cloned().unwrap_or_default())
                    .show_ui(ui, |ui| {
                        for (i, n) in names.iter().enumerate() {
                            ui.selectable_value(pick, i, n);
                        }
                    });
            }
        });
        match between(model, &self.q, self.from, self.to, &self.dissolved) {
            Some(t) => ui.label(RichText::new(format!("T(from → to): {}", describe(&t))).strong()),
            None => ui.label(
                RichText::new("No transform: a dissolved pair lies on the path between them.")
                    .color(theme::error_color(ui)),
            ),
        };
        let commands = model.command_names();
        if let (false, Ok(tool)) = (commands.is_empty(), model.frame("tool")) {
            ui.checkbox(
                &mut self.commands,
                format!("use the plugged-in commands ({})", commands.join(", ")),
            );
            let (pose, by) = if self.commands {
                (model.pose(&self.q, &tool), commands[0])
            } else {
                (model.pose_generic(&self.q, &tool), "the generic tree walk")
            };
            if let Ok(p) = pose {
                ui.label(format!("tool: {} — computed by {by}", describe(&p)));
            }
        }
    }
}

/// A pose in words: where, and how far turned.
fn describe(t: &Pose) -> String {
    let v = t.translation.vector;
    format!(
        "({}, {}, {}) m, turned {}°",
        fixed(v.x, 3),
        fixed(v.y, 3),
        fixed(v.z, 3),
        fixed(t.rotation.angle().to_degrees(), 1)
    )
}

impl LabWidget for Morphology {
    fn ui(&mut self, ui: &mut egui::Ui) {
        let before = self.id.clone();
        egui::ComboBox::from_label("mechanism")
            .selected_text(&self.id)
            .show_ui(ui, |ui| {
                for m in MECHANISMS {
                    ui.selectable_value(&mut self.id, m.to_owned(), m);
                }
            });
        if self.id != before {
            self.load();
        }
        let Some(model) = self.model.clone() else {
            crate::widget::error_box(ui, "No such mechanism", &self.id);
            return;
        };
        ui.label(RichText::new("grey dots: elements (bodies) · lines: pairs (joints) · green squares: named ports (frames)").small());
        let width = ui.available_width();
        if width >= 700.0 {
            ui.horizontal_top(|ui| {
                self.graph(ui, &model, width * 0.6);
                ui.vertical(|ui| self.hierarchy(ui, &model));
            });
        } else {
            self.graph(ui, &model, width);
            self.hierarchy(ui, &model);
        }
        self.transform(ui, &model);
        self.pairs(ui, &model);
    }
}
