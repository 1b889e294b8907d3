//! The viewer's panels: joint sliders grouped by sub-mechanism, the
//! read-outs, the model tree, the model file and the exercise; and the
//! inverse kinematics that follows a dragged target.

use egui::{RichText, vec2};
use kinolab_common::Feedback;
use kinolab_common::display::fixed;
use kinolab_mechanism::exercise::{Task, conditioning};
use kinolab_mechanism::{Goal, JointKind, Options, Part, Plane, Target, Vector3, file, urdf};

use super::{Viewer, from_shown, to_shown};
use crate::draw::scene3d::ViewKind;
use crate::export::request_save;
use crate::open;
use crate::theme;
use crate::widget::feedback_ui;

impl Viewer {
    pub(super) fn plane(&self) -> Plane {
        match self.camera.kind {
            ViewKind::Side => Plane::Side,
            _ => Plane::Plan,
        }
    }

    pub(super) fn end_position(&self) -> Option<Vector3<f64>> {
        let (_, f) = self.end.as_ref()?;
        self.model
            .pose(&self.q, f)
            .ok()
            .map(|p| p.translation.vector)
    }

    /// Follow the dragged target with inverse kinematics from where the
    /// mechanism is now (a few restarts keep it quick enough per frame).
    pub(super) fn follow(&mut self, target: Vector3<f64>) {
        let Some((_, f)) = &self.end else { return };
        let options = Options {
            max_iterations: 60,
            restarts: 3,
            ..Options::default()
        };
        match self.model.solve(
            &[Goal::new(*f, Target::Position(target))],
            &self.q,
            &options,
        ) {
            Ok(s) => {
                self.q = s.q;
                self.model.apply_couplings(&mut self.q);
                self.ik_note = (!s.converged).then(|| {
                    format!(
                        "Out of reach: the closest the {} gets is {:.0} mm from the target.",
                        self.end.as_ref().map_or("tool", |(n, _)| n.as_str()),
                        s.position_error * 1000.0
                    )
                });
            }
            Err(e) => self.ik_note = Some(e.to_string()),
        }
    }

    /// One joint's row: a slider for a driven joint, its value and why
    /// it moves for a follower or a loop joint. True when it changed.
    fn slider_row(&mut self, ui: &mut egui::Ui, v: usize, label: &str) -> bool {
        let mut changed = false;
        let Some(joint) = self.model.variable_joint(v).cloned() else {
            return false;
        };
        let prismatic = joint.kind == JointKind::Prismatic;
        let unit = if prismatic { " m" } else { "°" };
        let name = ui.label(label);
        if self.driven.contains(&v) {
            let [lo, hi] = joint.limits.unwrap_or(if prismatic {
                [-1.0, 1.0]
            } else {
                [-std::f64::consts::PI, std::f64::consts::PI]
            });
            let mut shown = to_shown(&self.model, v, self.q[v]);
            let range = to_shown(&self.model, v, lo)..=to_shown(&self.model, v, hi);
            let slider = egui::Slider::new(&mut shown, range)
                .suffix(unit)
                .fixed_decimals(if prismatic { 2 } else { 0 });
            if ui.add(slider).labelled_by(name.id).changed() {
                self.q[v] = from_shown(&self.model, v, shown);
                changed = true;
            }
        } else {
            let why = match self.model.couplings().iter().find(|c| c.follower == v) {
                Some(c) => format!(
                    "follows {} × {:+}",
                    self.model
                        .variable_joint(c.leader)
                        .map_or("?", |j| j.name.as_str()),
                    c.ratio
                ),
                None => "moves to keep the loop closed".into(),
            };
            let value = fixed(to_shown(&self.model, v, self.q[v]), 1);
            // Wraps inside its grid cell: the reason can be long.
            ui.add(
                egui::Label::new(RichText::new(format!("{value}{unit}  ({why})")).italics()).wrap(),
            );
        }
        ui.end_row();
        changed
    }

    pub(super) fn sliders(&mut self, ui: &mut egui::Ui) {
        let mut changed = false;
        // Joints grouped by the top-level sub-mechanism they belong to.
        let top: Vec<(String, Vec<usize>)> = self
            .model
            .groups()
            .iter()
            .filter(|g| g.parent.is_none())
            .map(|g| {
                let vars = (0..self.model.dof())
                    .filter(|&v| {
                        self.model
                            .variable_joint(v)
                            .is_some_and(|j| g.bodies.contains(&j.child))
                    })
                    .collect();
                (g.name.clone(), vars)
            })
            .collect();
        let grouped: Vec<usize> = top.iter().flat_map(|(_, v)| v.iter().copied()).collect();
        let loose: Vec<usize> = (0..self.model.dof())
            .filter(|v| !grouped.contains(v))
            .collect();
        let fold = self.model.dof() > 8 && !top.is_empty();
        let grid = |ui: &mut egui::Ui, salt: usize, rows: &mut dyn FnMut(&mut egui::Ui)| {
            egui::Grid::new(ui.scope_id().with(("joints", salt)))
                .num_columns(2)
                .spacing(vec2(12.0, 2.0))
                .show(ui, |ui| rows(ui));
        };
        if fold {
            // Many joints: one foldable section per sub-mechanism.
            grid(ui, usize::MAX, &mut |ui| {
                for &v in &loose {
                    let name = self
                        .model
                        .variable_joint(v)
                        .map_or(String::new(), |j| j.name.clone());
                    changed |= self.slider_row(ui, v, &name);
                }
            });
            for (k, (name, vars)) in top.iter().enumerate() {
                egui::CollapsingHeader::new(format!("{name} ({} joints)", vars.len()))
                    .id_salt(("joint-group", k))
                    .default_open(k == 0)
                    .show(ui, |ui| {
                        grid(ui, k, &mut |ui| {
                            for &v in vars {
                                let full = self
                                    .model
                                    .variable_joint(v)
                                    .map_or(String::new(), |j| j.name.clone());
                                let short = full
                                    .strip_prefix(&format!("{name}/"))
                                    .unwrap_or(&full)
                                    .to_string();
                                changed |= self.slider_row(ui, v, &short);
                            }
                        });
                    });
            }
        } else {
            grid(ui, 0, &mut |ui| {
                for &v in loose.iter().chain(&grouped) {
                    let name = self
                        .model
                        .variable_joint(v)
                        .map_or(String::new(), |j| j.name.clone());
                    changed |= self.slider_row(ui, v, &name);
                }
            });
        }
        self.home_note(ui);
        if changed {
            self.settle();
            self.target = None;
            self.ik_note = None;
        }
    }

    /// Joints whose range excludes 0 start at their nearest limit, not at
    /// 0: say so, so that a home pose such as the Panda's q4 = −4° is no
    /// surprise.
    fn home_note(&self, ui: &mut egui::Ui) {
        let notes: Vec<String> = self
            .driven
            .iter()
            .filter_map(|&v| {
                let j = self.model.variable_joint(v)?;
                let [lo, hi] = j.limits?;
                if lo <= 0.0 && 0.0 <= hi {
                    return None;
                }
                let unit = if j.kind == JointKind::Prismatic {
                    " m"
                } else {
                    "°"
                };
                let shown = |x: f64| truthful(to_shown(&self.model, v, x));
                let home = if lo > 0.0 { lo } else { hi };
                Some(format!(
                    "{} starts at {}{unit}: its range, {}{unit} to {}{unit}, does not include 0.",
                    j.name,
                    shown(home),
                    shown(lo),
                    shown(hi)
                ))
            })
            .collect();
        for note in notes {
            ui.label(RichText::new(note).small());
        }
    }

    pub(super) fn part_name(&self, p: &Part) -> String {
        match *p {
            Part::Body(b) => self
                .model
                .bodies()
                .get(b)
                .map_or_else(String::new, |x| x.name.clone()),
            Part::Obstacle(i) => format!("obstacle {}", i + 1),
        }
    }

    /// Where the end frame is, in words.
    pub(super) fn end_text(&self) -> Option<String> {
        let (p, (name, _)) = (self.end_position()?, self.end.as_ref()?);
        Some(format!(
            "{name} at ({}, {}, {}) m",
            fixed(p.x, 3),
            fixed(p.y, 3),
            fixed(p.z, 3)
        ))
    }

    /// The mechanism, the joints driven (the first few) and where its end
    /// frame is.
    pub(super) fn description(&self) -> String {
        const MOST: usize = 6;
        let joints: Vec<String> = self
            .driven
            .iter()
            .take(MOST)
            .filter_map(|&v| {
                let j = self.model.variable_joint(v)?;
                let (unit, digits) = match j.kind {
                    JointKind::Prismatic => (" m", 3),
                    _ => ("°", 1),
                };
                let value = to_shown(&self.model, v, self.q[v]);
                Some(format!("{} {}{unit}", j.name, fixed(value, digits)))
            })
            .collect();
        let more = self.driven.len().saturating_sub(MOST);
        let more = if more > 0 {
            format!(" and {more} more")
        } else {
            String::new()
        };
        let end = self
            .end_text()
            .map_or(String::new(), |t| format!(" The {t}."));
        format!(
            "{}: {}{more}.{end}",
            self.model.name(),
            if joints.is_empty() {
                "no joint to drive".to_owned()
            } else {
                joints.join(", ")
            }
        )
    }

    pub(super) fn readout(&self, ui: &mut egui::Ui) {
        let mut lines = Vec::new();
        if let (Some(text), Some((name, f))) = (self.end_text(), &self.end) {
            lines.push(text);
            let spotting = matches!(
                self.exercise.as_ref().map(|e| &e.task),
                Some(Task::SpotSingular { .. })
            );
            if name == "tool"
                && !spotting
                && let Ok(c) = conditioning(&self.model, &self.q, f)
            {
                let how = if c < 1e-6 {
                    "singular: a direction of motion is lost"
                } else if c < 0.05 {
                    "close to a singularity"
                } else {
                    "well away from singularities"
                };
                lines.push(format!("Jacobian conditioning {} ({how})", fixed(c, 3)));
            }
        }
        if let Some(c) = self
            .model
            .loops()
            .first()
            .and(self.model.closure(&self.q).ok())
        {
            lines.push(format!("loop closed to {:.1e} m", c.gap));
        }
        ui.label(RichText::new(lines.join(" · ")).monospace().small());
        for note in [&self.ik_note, &self.closure_note].into_iter().flatten() {
            ui.label(RichText::new(note).color(theme::error_color(ui)));
        }
    }

    pub(super) fn tree_ui(&mut self, ui: &mut egui::Ui) {
        egui::CollapsingHeader::new("Model tree")
            .default_open(self.tree)
            .show(ui, |ui| {
                let model = &self.model;
                let joint_of = |b: usize| model.joints().iter().find(|j| j.child == b);
                let mut select = None;
                let mut body_line = |ui: &mut egui::Ui, b: usize, selected: Option<usize>| {
                    let name = &model.bodies()[b].name;
                    let how = joint_of(b).map_or(String::new(), |j| {
                        format!(
                            " — {:?} joint from {}",
                            j.kind,
                            model.bodies()[j.parent].name
                        )
                        .to_lowercase()
                    });
                    if crate::widget::choice(ui, selected == Some(b), format!("{name}{how}"))
                        .clicked()
                    {
                        select = Some(b);
                    }
                };
                let grouped: Vec<usize> = model
                    .groups()
                    .iter()
                    .flat_map(|g| g.bodies.iter().copied())
                    .collect();
                ui.label(
                    RichText::new(format!(
                        "{} — {} joint variables",
                        model.name(),
                        model.dof()
                    ))
                    .strong(),
                );
                for b in 1..model.bodies().len() {
                    if !grouped.contains(&b) {
                        body_line(ui, b, self.selected);
                    }
                }
                for (gi, g) in model
                    .groups()
                    .iter()
                    .enumerate()
                    .filter(|(_, g)| g.parent.is_none())
                {
                    egui::CollapsingHeader::new(format!("mechanism {}", g.name))
                        .id_salt(("group", gi))
                        .show(ui, |ui| {
                            let nested: Vec<usize> = model
                                .groups()
                                .iter()
                                .filter(|c| c.parent == Some(gi))
                                .flat_map(|c| c.bodies.iter().copied())
                                .collect();
                            for &b in &g.bodies {
                                if !nested.contains(&b) {
                                    body_line(ui, b, self.selected);
                                }
                            }
                        });
                }
                for c in model.couplings() {
                    let n = |v: usize| model.variable_joint(v).map_or("?", |j| j.name.as_str());
                    let offset = if c.offset == 0.0 {
                        String::new()
                    } else {
                        format!(" {:+}", c.offset)
                    };
                    ui.label(format!(
                        "coupling: {} = {} × {}{offset}",
                        n(c.follower),
                        c.ratio,
                        n(c.leader)
                    ));
                }
                for l in model.loops() {
                    ui.label(format!("loop: {}", l.name));
                }
                for s in model.command_names() {
                    ui.label(format!("specialised solver: {s}"));
                }
                if let Some(b) = select {
                    self.selected = if self.selected == Some(b) {
                        None
                    } else {
                        Some(b)
                    };
                }
            });
    }

    pub(super) fn file_ui(&mut self, ui: &mut egui::Ui) {
        let id = ui.scope_id().with("mechanism-file");
        if let Some(file) = open::take_delivered(ui.ctx(), id) {
            self.open_file(&file.name, &file.text());
        }
        egui::CollapsingHeader::new("Model file: JSON or URDF").show(ui, |ui| {
            ui.horizontal_wrapped(|ui| {
                if ui
                    .button("Open a file…")
                    .on_hover_text("A URDF (.urdf) or a Kinolab model file (.model.json); dropping one on the page opens it too.")
                    .clicked()
                {
                    open::request_pick(ui.ctx(), id, ".urdf,.xml,.json");
                }
                if ui.button("Open the text below").clicked() {
                    let text = self.file_text.clone();
                    self.open_file("the pasted text", &text);
                }
                if ui.button("Save model file").clicked() {
                    self.save(ui.ctx(), false);
                }
                if ui
                    .button("Save as URDF")
                    .on_hover_text("For ROS, MoveIt, Pinocchio and Drake.")
                    .clicked()
                {
                    self.save(ui.ctx(), true);
                }
            });
            ui.add(
                egui::TextEdit::multiline(&mut self.file_text)
                    .hint_text("paste a model file (JSON) or a URDF here")
                    .desired_rows(4)
                    .code_editor(),
            );
            if let Some(n) = &self.file_note {
                ui.add(egui::Label::new(RichText::new(n).small()).wrap());
            }
        });
    }

    /// Ask the host to save the model as a Kinolab file or as URDF.
    fn save(&mut self, ctx: &egui::Context, as_urdf: bool) {
        let stem = self.model.name().to_lowercase().replace(' ', "-");
        let (name, mime, text, notices) = if as_urdf {
            let written = urdf::write(&self.model);
            (
                format!("{stem}.urdf"),
                "application/xml",
                written.text,
                written.notices,
            )
        } else {
            let text = file::to_json(&self.model);
            (
                format!("{stem}.model.json"),
                "application/json",
                text,
                Vec::new(),
            )
        };
        request_save(ctx, &name, mime, text.into_bytes());
        let mut note = format!("Saved {name}.");
        for n in notices {
            note.push_str(&format!(" Note: {n}."));
        }
        self.file_note = Some(note);
    }

    pub(super) fn exercise_ui(&mut self, ui: &mut egui::Ui) {
        let mut load = None;
        let Some(ex) = &mut self.exercise else { return };
        ui.group(|ui| {
            ui.label(RichText::new(format!("Exercise: {}", ex.task.describe())).strong());
            if let Task::SpotSingular { sets, .. } = &ex.task {
                for (i, (q, mark)) in sets.iter().zip(ex.marks.iter_mut()).enumerate() {
                    ui.horizontal(|ui| {
                        let shown: Vec<String> = self
                            .driven
                            .iter()
                            .map(|&v| fixed(to_shown(&self.model, v, q[v]), 0))
                            .collect();
                        let text = format!("configuration {}: ({})", i + 1, shown.join(", "));
                        if ui.checkbox(mark, text).changed() {
                            ex.feedback = None;
                        }
                        if ui.small_button("show").clicked() {
                            load = Some(q.clone());
                        }
                    });
                }
            }
            if ui.button("Check").clicked() {
                let result = match &ex.task {
                    Task::SpotSingular { .. } => ex.task.check_marks(&self.model, &ex.marks),
                    _ => ex.task.check_state(&self.model, &self.q),
                };
                ex.feedback = Some(Feedback::from(result));
            }
            feedback_ui(ui, ex.feedback.as_ref());
        });
        if let Some(q) = load {
            self.q = q;
            self.target = None;
        }
    }
}

/// `x` with as few decimals as keep it true: a limit of 0.0087 rad is
/// "0.5°", never "0°", so that "its range does not include 0" reads right.
fn truthful(x: f64) -> String {
    let nonzero = |text: &String| text.chars().any(|c| c.is_ascii_digit() && c != '0');
    (0..=4)
        .map(|decimals| fixed(x, decimals))
        .find(|text| x == 0.0 || nonzero(text))
        .unwrap_or_else(|| fixed(x, 4))
}

#[cfg(test)]
mod truthful_tests {
    #[test]
    fn a_small_limit_is_never_printed_as_zero() {
        assert_eq!(super::truthful(0.4986), "0.5");
        assert_eq!(super::truthful(164.0), "164");
        assert_eq!(super::truthful(-0.04), "-0.04");
        assert_eq!(super::truthful(0.0), "0");
    }
}
