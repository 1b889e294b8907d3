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
use serde::{Deserialize, Serialize};

use crate::draw::canvas;
use crate::draw::labels::Labels;
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::theme;
use crate::widget::{LabWidget, Params};

/// The widget's name in the schema.
const NAME: &str = "morphology-builder";

/// What the lesson sets and a link carries: the schema's parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    mechanism: String,
    /// The transform's ends, by body number (`to`: the last when `None`).
    from: usize,
    to: Option<usize>,
    /// Pairs whose port is deleted, by joint number (none when `None`).
    dissolved: Option<Vec<f64>>,
    /// Whether the plugged-in closed forms answer.
    commands: bool,
}

impl Settings {
    /// The schema's settings for `mechanism`.
    fn fresh(mechanism: &str) -> Result<Self, String> {
        kinolab_schema::validate(&crate::registry::spec(NAME, &[("mechanism", mechanism)]))?
            .settings()
    }

    /// The deleted pairs' numbers.
    fn dissolved(&self) -> Vec<usize> {
        self.dissolved
            .iter()
            .flatten()
            .map(|j| *j as usize)
            .collect()
    }

    fn set_dissolved(&mut self, joints: &[usize]) {
        self.dissolved = (!joints.is_empty()).then(|| joints.iter().map(|j| *j as f64).collect());
    }

    /// The transform's last element: the one set, or `model`'s last.
    fn to(&self, model: &Model) -> usize {
        self.to
            .unwrap_or_else(|| model.bodies().len().saturating_sub(1))
    }

    /// Whether every number names a body or a pair of `model`; why not.
    fn fits(&self, model: &Model) -> Result<(), String> {
        let bodies = model.bodies().len();
        let joints = model.joints().len();
        if self.from >= bodies || self.to.is_some_and(|t| t >= bodies) {
            return Err(format!(
                "`{}` has bodies 0 to {}",
                self.mechanism,
                bodies.saturating_sub(1)
            ));
        }
        let whole = |j: &f64| j.fract() == 0.0 && (*j as usize) < joints;
        if !self.dissolved.iter().flatten().all(whole) {
            return Err(format!(
                "`{}` has pairs 0 to {}",
                self.mechanism,
                joints.saturating_sub(1)
            ));
        }
        Ok(())
    }
}

struct Morphology {
    settings: Settings,
    initial: Settings,
    model: Option<Model>,
    q: Vec<f64>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    let mut w = Morphology {
        initial: settings.clone(),
        settings,
        model: None,
        q: Vec::new(),
    };
    w.load();
    if let Some(model) = &w.model {
        w.settings.fits(model)?;
    }
    Ok(Box::new(w))
}

impl Morphology {
    fn load(&mut self) {
        self.model = kinolab_mechanism::catalogue::mechanism(&self.settings.mechanism).ok();
        self.q = self.model.as_ref().map_or_else(Vec::new, |m| {
            (0..m.dof())
                .map(|i| 0.3 * ((i % 3) as f64 - 1.0) + 0.2)
                .collect()
        });
    }

    /// The flat graph: every element at its depth in the tree, pairs as
    /// lines; a dissolved pair dashed, what hangs below it faded. Where it
    /// was drawn.
    fn graph(&self, ui: &mut egui::Ui, model: &Model, width: f32) -> egui::Rect {
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
        let dissolved = self.settings.dissolved();
        let cut = |b: usize| chain(model, b).iter().any(|j| dissolved.contains(j));
        let ink = ui.visuals().text_color();
        let faint = ui.visuals().weak_text_color();
        for (j, joint) in model.joints().iter().enumerate() {
            let (a, b) = (at(joint.parent), at(joint.child));
            if dissolved.contains(&j) {
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
        let chosen = [self.settings.from, self.settings.to(model)];
        // Names clear of the dots, the pairs' lines and the ports' squares.
        let mut labels = Labels::default();
        labels.within(rect);
        for b in 0..n {
            labels.reserve(egui::Rect::from_center_size(at(b), vec2(10.0, 10.0)));
        }
        for joint in model.joints() {
            labels.avoid_line(at(joint.parent), at(joint.child));
        }
        for f in model.frames() {
            labels.reserve(egui::Rect::from_center_size(
                at(f.body) + vec2(0.0, 9.0),
                vec2(6.0, 6.0),
            ));
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
                labels.add(at(b), name, ink).toward(vec2(0.0, -1.0));
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
        rect
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
                    let mut dissolved = self.settings.dissolved();
                    let gone = dissolved.contains(&j);
                    let label = if gone {
                        "restore the port"
                    } else {
                        "delete the port"
                    };
                    if ui.small_button(label).clicked() {
                        if gone {
                            dissolved.retain(|x| *x != j);
                        } else {
                            dissolved.push(j);
                        }
                        self.settings.set_dissolved(&dissolved);
                    }
                });
            }
        });
    }

    fn transform(&mut self, ui: &mut egui::Ui, model: &Model) {
        let names: Vec<String> = model.bodies().iter().map(|b| b.name.clone()).collect();
        let mut to = self.settings.to(model);
        ui.horizontal_wrapped(|ui| {
            for (label, pick) in [("from", &mut self.settings.from), ("to", &mut to)] {
                egui::ComboBox::from_label(label)
                    .selected_text(names.get(*pick).cloned().unwrap_or_default())
                    .show_ui(ui, |ui| {
                        for (i, n) in names.iter().enumerate() {
                            crate::widget::choose(ui, pick, i, n);
                        }
                    });
            }
        });
        if to != self.settings.to(model) {
            self.settings.to = Some(to);
        }
        match self.between(model) {
            Some(t) => ui.label(RichText::new(format!("T(from → to): {}", describe(&t))).strong()),
            None => ui.label(
                RichText::new("No transform: a dissolved pair lies on the path between them.")
                    .color(theme::error_color(ui)),
            ),
        };
        let commands = model.command_names();
        if let (false, Ok(tool)) = (commands.is_empty(), model.frame("tool")) {
            ui.checkbox(
                &mut self.settings.commands,
                format!("use the plugged-in commands ({})", commands.join(", ")),
            );
            let (pose, by) = if self.settings.commands {
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

impl Morphology {
    /// Frame "to" seen from frame "from", `None` when a dissolved pair
    /// lies between them.
    fn between(&self, model: &Model) -> Option<Pose> {
        let s = &self.settings;
        between(model, &self.q, s.from, s.to(model), &s.dissolved())
    }

    /// The mechanism's size, the pairs dissolved and the transform asked for.
    fn description(&self) -> String {
        let Some(model) = &self.model else {
            return format!("There is no mechanism named {}.", self.settings.mechanism);
        };
        let name = |b: usize| model.bodies().get(b).map_or("?", |x| x.name.as_str());
        let (from, to) = (self.settings.from, self.settings.to(model));
        let transform = match self.between(model) {
            Some(t) => format!("T({} → {}): {}", name(from), name(to), describe(&t)),
            None => format!(
                "No transform from {} to {}: a dissolved pair lies between them",
                name(from),
                name(to)
            ),
        };
        format!(
            "{}: {} elements, {} pairs, {} dissolved. {transform}.",
            model.name(),
            model.bodies().len(),
            model.joints().len(),
            self.settings.dissolved().len()
        )
    }
}

impl LabWidget for Morphology {
    fn describe(&self) -> Option<String> {
        Some(self.description())
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        let before = self.settings.mechanism.clone();
        egui::ComboBox::from_label("mechanism")
            .selected_text(&self.settings.mechanism)
            .show_ui(ui, |ui| {
                if let Some(kinolab_schema::Kind::Choice { options }) = kinolab_schema::find(NAME)
                    .and_then(|w| w.param("mechanism"))
                    .map(|p| &p.kind)
                {
                    for m in *options {
                        crate::widget::choose(
                            ui,
                            &mut self.settings.mechanism,
                            (*m).to_owned(),
                            *m,
                        );
                    }
                }
            });
        if self.settings.mechanism != before {
            // Another mechanism: its own numbers, as the schema sets them.
            if let Ok(fresh) = Settings::fresh(&self.settings.mechanism) {
                self.settings = fresh;
            }
            self.load();
        }
        let Some(model) = self.model.clone() else {
            crate::widget::error_box(ui, "No such mechanism", &self.settings.mechanism);
            return;
        };
        ui.label(RichText::new("grey dots: elements (bodies) · lines: pairs (joints) · green squares: named ports (frames)").small());
        let width = ui.available_width();
        let graph = if width >= 700.0 {
            ui.horizontal_top(|ui| {
                let graph = self.graph(ui, &model, width * 0.6);
                ui.vertical(|ui| self.hierarchy(ui, &model));
                graph
            })
            .inner
        } else {
            let graph = self.graph(ui, &model, width);
            self.hierarchy(ui, &model);
            graph
        };
        export::bar(
            ui,
            ui.scope_id().with("morphology-exports"),
            &[Export::Png {
                file: "kinolab-morphology.png",
                rect: graph,
            }],
        );
        self.transform(ui, &model);
        self.pairs(ui, &model);
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
        let (settings, _) = link::read::<Settings, ()>(NAME, state)?;
        // A link is written only when something changed: one holding the
        // lesson's own settings is not one of this widget's.
        if settings == self.initial {
            return Err("it holds nothing this widget would change".into());
        }
        let model = kinolab_mechanism::catalogue::mechanism(&settings.mechanism)
            .map_err(|e| e.to_string())?;
        settings.fits(&model)?;
        self.settings = settings;
        self.load();
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::{create, spec};

    fn widget(params: &[(&str, &str)]) -> Morphology {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        let settings: Settings = p.settings().unwrap_or_else(|e| panic!("{e}"));
        let mut w = Morphology {
            initial: settings.clone(),
            settings,
            model: None,
            q: Vec::new(),
        };
        w.load();
        w
    }

    #[test]
    fn the_learners_picks_travel_in_the_link() {
        let mut w = widget(&[]);
        w.settings.set_dissolved(&[1]);
        w.settings.to = Some(2);
        w.settings.commands = false;
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.settings, w.settings);
        assert_eq!(again.settings.dissolved(), [1]);
        // Numbers the mechanism does not have are refused.
        let mut far = widget(&[]);
        far.settings.set_dissolved(&[40]);
        let text = far.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert!(again.restore(&text).is_err());
        assert_eq!(again.settings, again.initial);
        assert!(create(&spec(NAME, &[("to", "50")])).is_err());
        assert!(
            create(&spec(
                NAME,
                &[("mechanism", "hexapod"), ("dissolved", "3,4")]
            ))
            .is_ok()
        );
    }
}
