//! The wheel workbench: place wheels on a chassis seen from above and watch
//! the constraint rows, rank, the three degrees, DOF and the ICR follow.

use egui::{Color32, RichText, Sense, Stroke, vec2};
use kinolab_lessons::WidgetSpec;
use kinolab_wheels::catalogue::{self, CATALOGUE};
use kinolab_wheels::challenge::{Goal, Verdict, check_disagreeing};
use kinolab_wheels::{Analysis, Chassis, Icr, Wheel, WheelKind, wrap};

use super::chassis_view::{self as draw, View};
use super::{LabWidget, known_params, shown};
use crate::theme;

/// Positions snap to this grid (metres) and angles to this step (degrees)
/// while dragging, so wheels can share an axle exactly.
const GRID: f64 = 0.05;
const ANGLE_STEP: f64 = 5.0;

/// Robot from a widget's `robot:` or `layout:` parameter.
pub(crate) fn robot_param(spec: &WidgetSpec, default: &str) -> Result<Chassis, String> {
    match (spec.param("layout"), spec.param("robot")) {
        (Some(_), Some(_)) => Err("Give either `robot` or `layout`, not both.".into()),
        (Some(code), None) => {
            Chassis::from_compact("Layout", code).map_err(|e| format!("Parameter `layout`: {e}."))
        }
        (None, id) => catalogue::robot(id.unwrap_or(default))
            .map_err(|e| format!("Parameter `robot`: {}.", e.message)),
    }
}

enum Task {
    None,
    Goal(Goal),
    FindDisagreeing {
        chosen: Vec<usize>,
        verdict: Option<Verdict>,
    },
}

struct Workbench {
    start: Chassis,
    chassis: Chassis,
    selected: Option<usize>,
    task: Task,
    /// Half the width of the drawing, metres.
    extent: f64,
    /// Unsnapped position of the wheel being dragged.
    drag: Option<[f64; 2]>,
    file_text: String,
    file_error: Option<String>,
    message: Option<String>,
}

pub(super) fn create(spec: &WidgetSpec) -> Result<Box<dyn LabWidget>, String> {
    known_params(
        spec,
        &[
            "robot",
            "layout",
            "goal-maneuverability",
            "max-steer-inputs",
            "goal-icr",
            "goal-mobility",
            "goal-dof",
            "find-disagreeing",
        ],
    )?;
    let chassis = robot_param(spec, "differential-drive")?;
    let count = |key: &str| -> Result<Option<usize>, String> {
        spec.param(key)
            .map(|t| {
                t.trim()
                    .parse::<usize>()
                    .ok()
                    .filter(|v| *v <= 3)
                    .ok_or_else(|| format!("Parameter `{key}` must be 0, 1, 2 or 3, found `{t}`."))
            })
            .transpose()
    };
    let mut goals = Vec::new();
    if let Some(target) = count("goal-maneuverability")? {
        goals.push(Goal::Maneuverability {
            target,
            max_steer_inputs: count("max-steer-inputs")?,
        });
    }
    if let Some(target) = count("goal-mobility")? {
        goals.push(Goal::Mobility { target });
    }
    if let Some(target) = count("goal-dof")? {
        goals.push(Goal::Dof { target });
    }
    if let Some(text) = spec.param("goal-icr") {
        let xy: Vec<f64> = text
            .split(',')
            .filter_map(|p| p.trim().parse::<f64>().ok())
            .filter(|v| v.is_finite())
            .collect();
        let [x, y] = xy[..] else {
            return Err(format!(
                "Parameter `goal-icr` must be two numbers `x, y`, found `{text}`."
            ));
        };
        goals.push(Goal::IcrAt {
            x,
            y,
            tolerance: 0.05,
        });
    }
    let disagree = match spec.param("find-disagreeing") {
        None | Some("no") => false,
        Some("yes") => true,
        Some(other) => {
            return Err(format!(
                "Parameter `find-disagreeing` must be yes or no, found `{other}`."
            ));
        }
    };
    if goals.len() + usize::from(disagree) > 1 {
        return Err("A workbench takes at most one challenge.".into());
    }
    let task = match (goals.pop(), disagree) {
        (Some(goal), _) => Task::Goal(goal),
        (None, true) => {
            if chassis.disagreement().is_none() {
                return Err("`find-disagreeing` needs a layout that cannot move.".into());
            }
            Task::FindDisagreeing {
                chosen: Vec::new(),
                verdict: None,
            }
        }
        (None, false) => Task::None,
    };
    Ok(Box::new(Workbench::new(chassis, task)))
}

/// How far the drawing must reach to show every wheel (and a goal ICR).
fn extent_for(chassis: &Chassis, task: &Task) -> f64 {
    let mut reach = chassis
        .wheels()
        .iter()
        .map(|w| w.l + w.radius)
        .fold(0.3, f64::max)
        * 1.5;
    if let Task::Goal(Goal::IcrAt { x, y, .. }) = task {
        reach = reach.max(x.hypot(*y) * 1.15);
    }
    reach.min(4.0)
}

fn snap(v: f64, step: f64) -> f64 {
    (v / step).round() * step
}

impl Workbench {
    fn new(chassis: Chassis, task: Task) -> Self {
        let extent = extent_for(&chassis, &task);
        let file_text = chassis.to_json();
        Self {
            start: chassis.clone(),
            chassis,
            selected: None,
            task,
            extent,
            drag: None,
            file_text,
            file_error: None,
            message: None,
        }
    }

    /// Replace the wheels if they make a valid chassis; say why not otherwise.
    fn try_set(&mut self, wheels: Vec<Wheel>) -> bool {
        match Chassis::new(self.chassis.name().to_owned(), wheels) {
            Ok(chassis) => {
                self.chassis = chassis;
                self.file_text = self.chassis.to_json();
                self.message = None;
                true
            }
            Err(e) => {
                self.message = Some(e.to_string());
                false
            }
        }
    }

    fn load(&mut self, chassis: Chassis) {
        self.extent = extent_for(&chassis, &self.task);
        self.chassis = chassis;
        self.file_text = self.chassis.to_json();
        self.selected = None;
        self.message = None;
        if let Task::FindDisagreeing { chosen, verdict } = &mut self.task {
            chosen.clear();
            *verdict = None;
        }
    }

    /// A free spot for a new wheel: on the grid, away from the others.
    fn free_spot(&self) -> [f64; 2] {
        let taken = |x: f64, y: f64| {
            self.chassis.wheels().iter().any(|w| {
                let [wx, wy] = w.position();
                (wx - x).hypot(wy - y) < 0.12
            })
        };
        for ring in 1..8 {
            let r = ring as f64 * 0.15;
            for k in 0..8 {
                let a = k as f64 * std::f64::consts::FRAC_PI_4;
                let (x, y) = (snap(r * a.cos(), GRID), snap(r * a.sin(), GRID));
                if !taken(x, y) {
                    return [x, y];
                }
            }
        }
        [0.0, 0.0]
    }

    fn add_wheel(&mut self, kind: WheelKind) {
        let [x, y] = self.free_spot();
        let mut wheels = self.chassis.wheels().to_vec();
        wheels.push(Wheel::at(kind, x, y, 0.0, 0.08));
        if self.try_set(wheels) {
            self.selected = Some(self.chassis.wheels().len() - 1);
        }
    }

    fn toolbar(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            let label = ui.label("Start from");
            let mut pick = None;
            let combo = egui::ComboBox::from_id_salt(ui.scope_id().with("robot"))
                .selected_text(self.chassis.name().to_owned())
                .width(210.0)
                .show_ui(ui, |ui| {
                    for entry in CATALOGUE {
                        if ui
                            .selectable_label(self.chassis.name() == entry.name, entry.name)
                            .on_hover_text(entry.summary)
                            .clicked()
                        {
                            pick = Some(entry.id);
                        }
                    }
                });
            combo.response.labelled_by(label.id);
            if let Some(id) = pick
                && let Ok(chassis) = catalogue::robot(id)
            {
                self.load(chassis);
            }
            if ui.button("Reset").clicked() {
                self.load(self.start.clone());
            }
            ui.separator();
            ui.label("Add");
            for (label, kind) in [
                ("fixed", WheelKind::Fixed),
                ("steered", WheelKind::Steered),
                ("castor", WheelKind::Castor { offset: 0.04 }),
                ("Swedish", WheelKind::Swedish { gamma: 0.0 }),
                ("ball", WheelKind::Spherical),
            ] {
                if ui.small_button(label).clicked() {
                    self.add_wheel(kind);
                }
            }
            if let Some(i) = self.selected
                && ui.small_button("Remove selected").clicked()
            {
                let mut wheels = self.chassis.wheels().to_vec();
                wheels.remove(i);
                if self.try_set(wheels) {
                    self.selected = None;
                }
            }
        });
    }

    fn canvas(&mut self, ui: &mut egui::Ui, analysis: &Analysis, size: egui::Vec2) {
        let (response, painter) = ui.allocate_painter(size, Sense::click());
        let rect = response.rect;
        painter.rect_filled(rect, 6.0, ui.visuals().extreme_bg_color);
        let view = View::robot_frame(rect, self.extent);
        let text = ui.visuals().text_color();
        let painter = painter.with_clip_rect(rect);
        draw::draw_grid(&painter, &view, rect, 0.1, text.gamma_multiply(0.06));
        draw::draw_frame(
            &painter,
            &view,
            text.gamma_multiply(0.5),
            self.extent * 0.25,
        );
        for (i, w) in self.chassis.wheels().iter().enumerate() {
            if w.kind.constrains_chassis() {
                draw::draw_zero_motion_line(
                    &painter,
                    &view,
                    w,
                    draw::wheel_color(i),
                    self.extent * 4.0,
                );
            }
        }
        let icr_color = theme::accent(ui);
        draw::draw_icr(&painter, &view, &analysis.icr, icr_color, rect);
        if let Task::Goal(Goal::IcrAt { x, y, .. }) = self.task {
            let at = view.robot([x, y]);
            painter.circle_stroke(at, 12.0, Stroke::new(1.5, theme::good_color(ui)));
            painter.text(
                at + vec2(14.0, 0.0),
                egui::Align2::LEFT_CENTER,
                "goal",
                egui::FontId::proportional(12.0),
                theme::good_color(ui),
            );
        }
        let chosen: Vec<usize> = match &self.task {
            Task::FindDisagreeing { chosen, .. } => chosen.clone(),
            _ => Vec::new(),
        };
        let base = ui.scope_id().with("wheel");
        let mut clicked = None;
        let mut new_wheels: Option<Vec<Wheel>> = None;
        let mut steer_to: Option<(usize, f64)> = None;
        for (i, w) in self.chassis.wheels().iter().enumerate() {
            let selected = self.selected == Some(i);
            draw::draw_wheel(&painter, &view, w, draw::wheel_color(i), selected);
            let at = view.robot(w.position());
            painter.text(
                at + vec2(0.0, -14.0 - w.radius as f32 * view.scale * 0.4),
                egui::Align2::CENTER_BOTTOM,
                (i + 1).to_string(),
                egui::FontId::proportional(13.0),
                text,
            );
            if chosen.contains(&i) {
                painter.circle_stroke(at, 16.0, Stroke::new(2.5, theme::warn_color(ui)));
            }
            let hit = egui::Rect::from_center_size(at, vec2(26.0, 26.0));
            let r = ui.interact(hit, base.with(i), Sense::click_and_drag());
            r.widget_info(|| {
                egui::WidgetInfo::labeled(
                    egui::Role::Button,
                    true,
                    format!("Wheel {} ({})", i + 1, w.kind.name()),
                )
            });
            if r.clicked() {
                clicked = Some(i);
            }
            if r.drag_started() {
                self.drag = Some(w.position());
                self.selected = Some(i);
            }
            if r.dragged()
                && let Some(raw) = &mut self.drag
            {
                let d = r.drag_delta();
                raw[0] += f64::from(d.x / view.scale);
                raw[1] -= f64::from(d.y / view.scale);
                let (x, y) = (snap(raw[0], GRID), snap(raw[1], GRID));
                let heading = w.alpha + w.beta;
                let mut moved = w.clone();
                moved.l = x.hypot(y);
                moved.alpha = if moved.l > 0.0 { y.atan2(x) } else { 0.0 };
                moved.beta = wrap(heading - moved.alpha);
                let mut wheels = self.chassis.wheels().to_vec();
                wheels[i] = moved;
                new_wheels = Some(wheels);
            }
            if r.drag_stopped() {
                self.drag = None;
            }
            // The selected wheel gets a knob to turn it.
            if selected {
                let t = w.rolling_direction();
                let reach = w.radius
                    + 0.06
                    + if let WheelKind::Castor { offset } = w.kind {
                        offset
                    } else {
                        0.0
                    };
                let p = w.position();
                let knob = view.robot([p[0] + reach * t[0], p[1] + reach * t[1]]);
                painter.line_segment([at, knob], Stroke::new(1.0, text.gamma_multiply(0.5)));
                painter.circle(
                    knob,
                    6.0,
                    theme::accent(ui),
                    Stroke::new(1.5, Color32::WHITE),
                );
                let kr = ui.interact(
                    egui::Rect::from_center_size(knob, vec2(18.0, 18.0)),
                    base.with(("knob", i)),
                    Sense::drag(),
                );
                kr.widget_info(|| {
                    egui::WidgetInfo::labeled(
                        egui::Role::Slider,
                        true,
                        format!("Turn wheel {}", i + 1),
                    )
                });
                if kr.dragged()
                    && let Some(pointer) = kr.interact_pointer_pos()
                {
                    let [qx, qy] = view.robot_point_at(pointer);
                    let heading = (qy - p[1]).atan2(qx - p[0]).to_degrees();
                    let heading = snap(heading, ANGLE_STEP).to_radians();
                    // Rolling along `heading` means α + β = heading + π/2.
                    let beta = wrap(heading + std::f64::consts::FRAC_PI_2 - w.alpha);
                    steer_to = Some((i, beta));
                }
            }
        }
        if let Some(wheels) = new_wheels {
            self.try_set(wheels);
        }
        if let Some((i, beta)) = steer_to {
            let w = &self.chassis.wheels()[i];
            if w.kind == WheelKind::Steered {
                match self.chassis.steer(i, beta) {
                    Ok(c) => {
                        self.chassis = c;
                        self.file_text = self.chassis.to_json();
                    }
                    Err(e) => self.message = Some(e.to_string()),
                }
            } else {
                let mut wheels = self.chassis.wheels().to_vec();
                wheels[i].beta = beta;
                self.try_set(wheels);
            }
        }
        if let Some(i) = clicked {
            if let Task::FindDisagreeing { chosen, verdict } = &mut self.task {
                if let Some(k) = chosen.iter().position(|c| *c == i) {
                    chosen.remove(k);
                } else {
                    chosen.push(i);
                }
                *verdict = None;
            }
            self.selected = Some(i);
        } else if response.clicked() {
            self.selected = None;
        }
        painter.text(
            rect.left_bottom() + vec2(8.0, -6.0),
            egui::Align2::LEFT_BOTTOM,
            "drag a wheel to move it; select it and drag the blue knob to turn it",
            egui::FontId::proportional(11.0),
            text.gamma_multiply(0.6),
        );
    }

    fn degrees_panel(&self, ui: &mut egui::Ui, a: &Analysis) {
        let strong = |ui: &mut egui::Ui, s: String| {
            ui.label(RichText::new(s).strong());
        };
        egui::Grid::new(ui.scope_id().with("degrees"))
            .num_columns(2)
            .spacing(vec2(14.0, 4.0))
            .show(ui, |ui| {
                ui.label("rank C1");
                strong(ui, a.rank_c1.to_string());
                ui.end_row();
                ui.label("mobility δm = 3 − rank C1");
                strong(ui, a.mobility.to_string());
                ui.end_row();
                ui.label(format!(
                    "steerability δs ({} input{})",
                    a.steering_inputs,
                    if a.steering_inputs == 1 { "" } else { "s" }
                ));
                strong(ui, a.steerability.to_string());
                ui.end_row();
                ui.label("maneuverability δM = δm + δs");
                strong(ui, a.maneuverability.to_string());
                ui.end_row();
                ui.label("DDOF (= δm)");
                strong(ui, a.ddof().to_string());
                ui.end_row();
                ui.label("DOF (Lie brackets)");
                strong(ui, a.dof.to_string());
                ui.end_row();
                ui.label("holonomic (DDOF = DOF)");
                strong(
                    ui,
                    if a.holonomic {
                        "yes".into()
                    } else {
                        "no".into()
                    },
                );
                ui.end_row();
            });
        let icr = match a.icr {
            Icr::Anywhere => "ICR: anywhere (no standard wheel objects).".to_owned(),
            Icr::Line { point, direction } => format!(
                "ICR: on the line through ({:.2}, {:.2}) along ({:.2}, {:.2}).",
                shown(point[0], 5e-3),
                shown(point[1], 5e-3),
                shown(direction[0], 5e-3),
                shown(direction[1], 5e-3)
            ),
            Icr::Point { x, y } => format!(
                "ICR: at ({:.2}, {:.2}) in the robot frame.",
                shown(x, 5e-3),
                shown(y, 5e-3)
            ),
            Icr::Infinity { direction } => format!(
                "ICR: at infinity. The robot can only translate, along ({:.2}, {:.2}).",
                shown(direction[0], 5e-3),
                shown(direction[1], 5e-3)
            ),
            Icr::None => {
                "ICR: none. The zero-motion lines share no point: the robot cannot move.".to_owned()
            }
        };
        ui.label(RichText::new(icr).color(theme::accent(ui)));
    }

    fn matrices(&self, ui: &mut egui::Ui) {
        let rows_for = self.chassis.c1_wheels();
        if rows_for.is_empty() {
            ui.label("No fixed or steered wheel: C1 and J1 have no rows, so nothing restricts the chassis.");
            return;
        }
        let mono = |s: String| RichText::new(s).monospace();
        egui::Grid::new(ui.scope_id().with("rows"))
            .num_columns(4)
            .striped(true)
            .spacing(vec2(12.0, 2.0))
            .show(ui, |ui| {
                ui.label(RichText::new("wheel").strong());
                ui.label(RichText::new("rolling row J1 (= r × spin)").strong());
                ui.label(RichText::new("r").strong());
                ui.label(RichText::new("sliding row C1 (= 0)").strong());
                ui.end_row();
                for &i in &rows_for {
                    let w = &self.chassis.wheels()[i];
                    let rows = w.rows();
                    let color = draw::wheel_color(i);
                    let mut label =
                        RichText::new(format!("{} {}", i + 1, w.kind.name())).color(color);
                    if self.selected == Some(i) {
                        label = label.strong().background_color(color.gamma_multiply(0.15));
                    }
                    ui.label(label);
                    let v = |r: kinolab_wheels::Vector3<f64>| {
                        let c = |x: f64| shown(x, 5e-4);
                        format!("[{:+.3} {:+.3} {:+.3}]", c(r.x), c(r.y), c(r.z))
                    };
                    ui.label(mono(v(rows.rolling)));
                    ui.label(mono(format!("{:.3}", w.radius)));
                    ui.label(mono(v(rows.sliding)));
                    ui.end_row();
                }
            });
    }

    fn selected_editor(&mut self, ui: &mut egui::Ui) {
        let Some(i) = self.selected else {
            ui.label(RichText::new("Click a wheel to edit its numbers.").small());
            return;
        };
        let Some(w) = self.chassis.wheels().get(i).cloned() else {
            self.selected = None;
            return;
        };
        let mut edited = w.clone();
        ui.label(
            RichText::new(format!("Wheel {} ({})", i + 1, w.kind.name()))
                .strong()
                .color(draw::wheel_color(i)),
        );
        let mut alpha = w.alpha.to_degrees();
        let mut beta = w.beta.to_degrees();
        egui::Grid::new(ui.scope_id().with("edit"))
            .num_columns(2)
            .show(ui, |ui| {
                ui.label("l (m)");
                ui.add(
                    egui::DragValue::new(&mut edited.l)
                        .speed(0.005)
                        .range(0.0..=3.0)
                        .max_decimals(3),
                );
                ui.end_row();
                ui.label("α (°)");
                ui.add(
                    egui::DragValue::new(&mut alpha)
                        .speed(0.5)
                        .range(-180.0..=180.0)
                        .max_decimals(2),
                );
                ui.end_row();
                ui.label("β (°)");
                ui.add(
                    egui::DragValue::new(&mut beta)
                        .speed(0.5)
                        .range(-180.0..=180.0)
                        .max_decimals(2),
                );
                ui.end_row();
                ui.label("r (m)");
                ui.add(
                    egui::DragValue::new(&mut edited.radius)
                        .speed(0.002)
                        .range(0.01..=1.0)
                        .max_decimals(3),
                );
                ui.end_row();
                match &mut edited.kind {
                    WheelKind::Castor { offset } => {
                        ui.label("d (m)");
                        ui.add(
                            egui::DragValue::new(offset)
                                .speed(0.002)
                                .range(0.005..=0.5)
                                .max_decimals(3),
                        );
                        ui.end_row();
                    }
                    WheelKind::Swedish { gamma } => {
                        let mut g = gamma.to_degrees();
                        ui.label("γ (°)");
                        ui.add(
                            egui::DragValue::new(&mut g)
                                .speed(0.5)
                                .range(-80.0..=80.0)
                                .max_decimals(1),
                        );
                        *gamma = g.to_radians();
                        ui.end_row();
                    }
                    _ => {}
                }
                if w.kind == WheelKind::Steered {
                    ui.label("steering group");
                    let mut group = edited.steer_group.clone().unwrap_or_default();
                    if ui
                        .add(
                            egui::TextEdit::singleline(&mut group)
                                .desired_width(90.0)
                                .hint_text("own input"),
                        )
                        .changed()
                    {
                        edited.steer_group =
                            (!group.trim().is_empty()).then(|| group.trim().to_owned());
                    }
                    ui.end_row();
                }
            });
        edited.alpha = alpha.to_radians();
        edited.beta = beta.to_radians();
        if edited != w {
            if edited.alpha == w.alpha
                && edited.beta != w.beta
                && w.kind == WheelKind::Steered
                && edited.l == w.l
            {
                if let Ok(c) = self.chassis.steer(i, edited.beta) {
                    self.chassis = c;
                    self.file_text = self.chassis.to_json();
                }
            } else {
                let mut wheels = self.chassis.wheels().to_vec();
                wheels[i] = edited;
                self.try_set(wheels);
            }
        }
    }

    fn task_ui(&mut self, ui: &mut egui::Ui) {
        let good = theme::good_color(ui);
        let warn = theme::warn_color(ui);
        match &mut self.task {
            Task::None => {}
            Task::Goal(goal) => {
                let verdict = goal.check(&self.chassis);
                ui.label(RichText::new(format!("Challenge: {}", goal.describe())).strong());
                let color = if verdict.met { good } else { warn };
                let mark = if verdict.met { "Solved. " } else { "" };
                ui.label(RichText::new(format!("{mark}{}", verdict.message)).color(color));
            }
            Task::FindDisagreeing { chosen, verdict } => {
                ui.label(RichText::new("Challenge: this layout cannot move. Click the wheels that disagree with the others, then check.").strong());
                ui.horizontal(|ui| {
                    let mut names: Vec<String> =
                        chosen.iter().map(|i| (i + 1).to_string()).collect();
                    names.sort();
                    ui.label(if names.is_empty() {
                        "No wheel marked.".to_owned()
                    } else {
                        format!("Marked: {}", names.join(", "))
                    });
                    if ui.button("Check").clicked() {
                        *verdict = Some(check_disagreeing(&self.chassis, chosen));
                    }
                });
                if let Some(v) = verdict {
                    ui.label(RichText::new(&v.message).color(if v.met { good } else { warn }));
                }
            }
        }
    }

    fn file_ui(&mut self, ui: &mut egui::Ui) {
        egui::CollapsingHeader::new("Robot file (save and load)")
            .id_salt(ui.scope_id().with("file"))
            .show(ui, |ui| {
                ui.label(RichText::new("The same JSON the command line reads: copy it to save the robot, paste one and load it.").small());
                ui.add(
                    egui::TextEdit::multiline(&mut self.file_text)
                        .code_editor()
                        .desired_rows(8)
                        .desired_width(f32::INFINITY),
                );
                ui.horizontal(|ui| {
                    if ui.button("Load this file").clicked() {
                        match Chassis::from_json(&self.file_text) {
                            Ok(c) => {
                                self.load(c);
                                self.file_error = None;
                            }
                            Err(e) => self.file_error = Some(e.to_string()),
                        }
                    }
                    if ui.button("Copy").clicked() {
                        ui.ctx().copy_text(self.file_text.clone());
                    }
                });
                if let Some(e) = &self.file_error {
                    ui.label(RichText::new(e).color(theme::warn_color(ui)));
                }
            });
    }
}

impl LabWidget for Workbench {
    fn ui(&mut self, ui: &mut egui::Ui) {
        self.toolbar(ui);
        let analysis = self.chassis.analyze();
        let wide = ui.available_width() > 760.0;
        let canvas_size = if wide {
            vec2(ui.available_width() * 0.56, 400.0)
        } else {
            vec2(ui.available_width(), 340.0)
        };
        if wide {
            ui.horizontal_top(|ui| {
                self.canvas(ui, &analysis, canvas_size);
                ui.vertical(|ui| {
                    self.degrees_panel(ui, &analysis);
                    ui.separator();
                    self.selected_editor(ui);
                });
            });
        } else {
            self.canvas(ui, &analysis, canvas_size);
            self.degrees_panel(ui, &analysis);
            self.selected_editor(ui);
        }
        if let Some(m) = &self.message {
            ui.label(RichText::new(m).color(theme::warn_color(ui)));
        }
        self.task_ui(ui);
        self.matrices(ui);
        self.file_ui(ui);
    }

    fn state(&self) -> Option<String> {
        (self.chassis != self.start).then(|| self.chassis.to_compact())
    }

    fn restore(&mut self, state: &str) {
        if let Ok(c) = Chassis::from_compact("Shared layout", state) {
            self.load(c);
        }
    }
}
