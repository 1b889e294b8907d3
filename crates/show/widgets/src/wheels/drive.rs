//! Drive a robot on the floor: set wheel spins (forward kinematics) or a
//! chassis twist (inverse kinematics) and watch the trail, the ICR and each
//! wheel's velocity.

use std::collections::VecDeque;

use egui::{Key, Painter, RichText, Sense, Stroke, vec2};
use kinolab_common::display::{fixed, signed};
use kinolab_wheels::{Chassis, Icr, Vector3, WheelKind, integrate, twist_icr};
use serde::{Deserialize, Serialize};

use super::chassis::{
    RobotView, contact_point, draw_frame, draw_icr, draw_wheel, wheel_color, wheel_rects,
};
use crate::draw::labels::Labels;
use crate::draw::{PlaneView, canvas, grid, placed, placed_dir};
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::theme;
use crate::widget::{LabWidget, Params, range};

/// The widget's name in the schema.
const NAME: &str = "wheel-drive";

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum Mode {
    /// Twist in, spins (and steering) out.
    Twist,
    /// Spins in, twist out.
    Wheels,
}

/// What the lesson sets and a link carries: the schema's parameters (the
/// robot, the mode, the twist, and the spins while the learner sets them).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    robot: Option<String>,
    layout: Option<String>,
    mode: Mode,
    forward: f64,
    sideways: f64,
    turn: f64,
    /// One per wheel, rad/s (a passive wheel's is ignored); `None` in
    /// twist mode.
    spins: Option<Vec<f64>>,
}

/// The links of the first format: the mode (wheels first), the twist and
/// the spins (`None` for passive wheels).
#[derive(Deserialize)]
struct Legacy {
    mode: LegacyMode,
    twist: [f64; 3],
    spins: Vec<Option<f64>>,
}

#[derive(Deserialize)]
enum LegacyMode {
    Wheels,
    Twist,
}

struct Drive {
    settings: Settings,
    initial: Settings,
    start: Chassis,
    /// The robot as it is steered now.
    chassis: Chassis,
    pose: [f64; 3],
    trail: VecDeque<[f64; 2]>,
    running: bool,
    /// The first frame has been drawn (a learner who asked for less motion
    /// starts with the drive paused).
    shown: bool,
    /// Seconds driven since the learner last changed anything.
    unattended: f64,
}

/// A drive left alone this long pauses itself, so a page at rest asks for
/// no frames (a phone's battery, a slow laptop's fan), s.
const REST_AFTER: f64 = 30.0;

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let chassis = kinolab_schema::robot_of(p)?;
    Ok(Box::new(Drive::new(chassis, p.settings()?)))
}

/// The robot that `settings` name, through the schema.
fn robot(settings: &Settings) -> Result<Chassis, String> {
    let spec = kinolab_lessons::WidgetSpec {
        name: NAME.to_owned(),
        params: kinolab_schema::settings::to_params(NAME, settings)?,
        line: 0,
    };
    kinolab_schema::robot_of(&kinolab_schema::validate(&spec)?)
}

/// Passive wheels (castors, balls) have no spin a learner can command.
fn driven(kind: WheelKind) -> bool {
    !matches!(kind, WheelKind::Castor { .. } | WheelKind::Spherical)
}

const TRAIL: usize = 1500;

impl Drive {
    fn new(chassis: Chassis, settings: Settings) -> Self {
        let mut drive = Self {
            start: chassis.clone(),
            chassis,
            initial: settings.clone(),
            settings,
            pose: [0.0, 0.0, 0.0],
            trail: VecDeque::new(),
            running: true,
            shown: false,
            unattended: 0.0,
        };
        if drive.settings.mode == Mode::Wheels && drive.settings.spins.is_none() {
            drive.spins_from_twist();
        }
        drive.initial = drive.settings.clone();
        drive
    }

    /// The commanded twist (forward, sideways, turn).
    fn twist(&self) -> [f64; 3] {
        let s = &self.settings;
        [s.forward, s.sideways, s.turn]
    }

    /// The commanded spins, `None` for passive wheels.
    fn spins(&self) -> Vec<Option<f64>> {
        let spins = self.settings.spins.clone().unwrap_or_default();
        self.chassis
            .wheels()
            .iter()
            .enumerate()
            .map(|(i, w)| driven(w.kind).then(|| spins.get(i).copied().unwrap_or(0.0)))
            .collect()
    }

    /// Start the wheels mode from the spins that produce the current twist
    /// (or the nearest feasible one).
    fn spins_from_twist(&mut self) {
        let twist = self.feasible_twist(Vector3::from(self.twist()));
        let span = range(NAME, "spins");
        let spins = match self.chassis.inverse(twist) {
            Ok(ik) => self
                .chassis
                .wheels()
                .iter()
                .zip(&ik.wheels)
                .map(|(w, c)| {
                    let spin = round2(c.spin).clamp(*span.start(), *span.end());
                    if driven(w.kind) { spin } else { 0.0 }
                })
                .collect(),
            Err(_) => vec![0.0; self.chassis.wheels().len()],
        };
        self.settings.spins = Some(spins);
    }

    /// The requested twist projected onto what the wheels allow now (or, in
    /// twist mode, after steering): the robot never slides.
    fn feasible_twist(&self, want: Vector3<f64>) -> Vector3<f64> {
        let reach = self.chassis.analyze().reachable;
        let mut allowed = Vector3::zeros();
        for b in reach.basis() {
            allowed += b * b.dot(&want);
        }
        allowed
    }

    /// The twist to drive with this frame, and a note when the request
    /// could not be met as asked; asking for a twist steers the wheels.
    fn current_twist(&mut self) -> (Vector3<f64>, Option<String>) {
        if self.settings.mode == Mode::Twist {
            self.steer();
        }
        self.resolved()
    }

    /// Steer the wheels as inverse kinematics says for the twist asked.
    fn steer(&mut self) {
        let Ok(ik) = self.chassis.inverse(Vector3::from(self.twist())) else {
            return;
        };
        if !ik.feasible {
            return;
        }
        for (i, c) in ik.wheels.iter().enumerate() {
            let w = &self.chassis.wheels()[i];
            if w.kind == WheelKind::Steered && (c.steer - w.beta).abs() > 1e-12 {
                let mut wheels = self.chassis.wheels().to_vec();
                wheels[i].beta = c.steer;
                if let Ok(next) = Chassis::new(self.chassis.name().to_owned(), wheels) {
                    self.chassis = next;
                }
            }
        }
    }

    /// The twist the settings drive with, and a note when the request
    /// cannot be met as asked (changing nothing).
    fn resolved(&self) -> (Vector3<f64>, Option<String>) {
        match self.settings.mode {
            Mode::Twist => {
                let want = Vector3::from(self.twist());
                match self.chassis.inverse(want) {
                    Ok(ik) if ik.feasible => (want, None),
                    Ok(ik) => {
                        let names: Vec<String> = ik
                            .violations
                            .iter()
                            .map(|v| match &v.group {
                                Some(g) => format!("the {g} linkage ({})", signed(v.residual, 2)),
                                None => format!(
                                    "wheel {} would slide at {} m/s",
                                    v.wheel + 1,
                                    signed(v.residual, 2)
                                ),
                            })
                            .collect();
                        (
                            Vector3::zeros(),
                            Some(format!(
                                "Not possible: {}. The robot waits; change the request.",
                                names.join(", ")
                            )),
                        )
                    }
                    Err(e) => (Vector3::zeros(), Some(e.to_string())),
                }
            }
            Mode::Wheels => match self.chassis.forward(&self.spins()) {
                Ok(fk) => {
                    let note = if !fk.consistent {
                        Some(format!(
                            "The spins disagree (residual {} m/s): real wheels would slip. The robot follows the best fit.",
                            fixed(fk.residual, 3)
                        ))
                    } else if !fk.determined {
                        Some("These spins do not pin the motion down; the robot takes the smallest motion that fits.".into())
                    } else {
                        None
                    };
                    (Vector3::from(fk.twist), note)
                }
                Err(e) => (Vector3::zeros(), Some(e.to_string())),
            },
        }
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            let before = self.settings.mode;
            let mode = &mut self.settings.mode;
            crate::widget::choose(ui, mode, Mode::Twist, "Set the twist (inverse)");
            crate::widget::choose(ui, mode, Mode::Wheels, "Set wheel spins (forward)");
            if before != self.settings.mode {
                match self.settings.mode {
                    Mode::Wheels => self.spins_from_twist(),
                    Mode::Twist => self.settings.spins = None,
                }
            }
            ui.separator();
            if ui
                .button(if self.running { "Pause" } else { "Run" })
                .clicked()
            {
                self.running = !self.running;
                self.unattended = 0.0;
            }
            if ui.button("Reset").clicked() {
                self.chassis = self.start.clone();
                self.pose = [0.0, 0.0, 0.0];
                self.trail.clear();
            }
            if ui.button("Stop").clicked() {
                let s = &mut self.settings;
                (s.forward, s.sideways, s.turn) = (0.0, 0.0, 0.0);
                for v in s.spins.iter_mut().flatten() {
                    *v = 0.0;
                }
            }
        });
        ui.vertical(|ui| match self.settings.mode {
            Mode::Twist => {
                let s = &mut self.settings;
                for (value, param, label) in [
                    (&mut s.forward, "forward", "forward (m/s)"),
                    (&mut s.sideways, "sideways", "sideways (m/s)"),
                    (&mut s.turn, "turn", "turn (rad/s)"),
                ] {
                    ui.add(
                        egui::Slider::new(value, range(NAME, param))
                            .text(label)
                            .fixed_decimals(2),
                    );
                }
            }
            Mode::Wheels => {
                let kinds: Vec<bool> = self
                    .chassis
                    .wheels()
                    .iter()
                    .map(|w| driven(w.kind))
                    .collect();
                let spins = self.settings.spins.get_or_insert_default();
                for (i, (s, driven)) in spins.iter_mut().zip(kinds).enumerate() {
                    if driven {
                        ui.add(
                            egui::Slider::new(s, range(NAME, "spins"))
                                .text(format!("wheel {} (rad/s)", i + 1))
                                .fixed_decimals(1),
                        );
                    }
                }
            }
        });
    }
}

fn round2(v: f64) -> f64 {
    (v * 100.0).round() / 100.0
}

impl Drive {
    /// Arrow keys drive while the floor has the pointer or the focus; Q
    /// and E slide sideways.
    fn keyboard(&mut self, ui: &egui::Ui, floor: &egui::Response) {
        if !(floor.hovered() || floor.has_focus()) || self.settings.mode != Mode::Twist {
            return;
        }
        // A held drive key is attention, even when the speed it pushes is
        // already at its limit and nothing changes.
        let driving = ui.input(|i| {
            [
                Key::ArrowUp,
                Key::ArrowDown,
                Key::ArrowLeft,
                Key::ArrowRight,
                Key::Q,
                Key::E,
            ]
            .into_iter()
            .any(|k| i.key_down(k))
        });
        if driving {
            // It wakes a drive that paused itself, not one the learner paused.
            self.running |= self.unattended > REST_AFTER;
            self.unattended = 0.0;
        }
        let s = &mut self.settings;
        ui.input(|i| {
            let step = 0.02;
            let keys = |up: Key, down: Key, by: f64| {
                f64::from(u8::from(i.key_down(up))) * by
                    - f64::from(u8::from(i.key_down(down))) * by
            };
            for (value, by, param) in [
                (
                    &mut s.forward,
                    keys(Key::ArrowUp, Key::ArrowDown, step),
                    "forward",
                ),
                (
                    &mut s.turn,
                    keys(Key::ArrowLeft, Key::ArrowRight, 2.0 * step),
                    "turn",
                ),
                (&mut s.sideways, keys(Key::Q, Key::E, step), "sideways"),
            ] {
                if by != 0.0 {
                    let span = range(NAME, param);
                    *value = (*value + by).clamp(*span.start(), *span.end());
                }
            }
        });
    }

    /// Move the robot by one frame's time and extend the trail.
    fn step(&mut self, ui: &egui::Ui, twist: Vector3<f64>) {
        if !self.running {
            return;
        }
        let dt = f64::from(ui.input(|i| i.stable_dt)).clamp(0.0, 0.05);
        self.unattended += dt;
        if self.unattended > REST_AFTER {
            self.running = false;
            return;
        }
        self.pose = integrate(self.pose, twist, dt);
        self.swing_castors(twist, dt);
        let here = [self.pose[0], self.pose[1]];
        let last = self.trail.back().copied();
        if last.is_none_or(|l| (l[0] - here[0]).hypot(l[1] - here[1]) > 0.01) {
            self.trail.push_back(here);
            if self.trail.len() > TRAIL {
                self.trail.pop_front();
            }
        }
        if twist.norm() > 0.0 {
            crate::widget::animate(ui);
        }
    }

    /// Castors are not steered by anyone: each swings at the rate that
    /// keeps it rolling without sliding, so over a turn it trails the
    /// motion, as the drawing and the "swings" readout both show.
    fn swing_castors(&mut self, twist: Vector3<f64>, dt: f64) {
        // A short castor swings fast (about speed / offset): small steps
        // keep its swing from overshooting.
        const STEP: f64 = 0.005;
        let steps = (dt / STEP).ceil().clamp(1.0, 10.0);
        for _ in 0..steps as usize {
            let Ok(ik) = self.chassis.inverse(twist) else {
                return;
            };
            let mut wheels = self.chassis.wheels().to_vec();
            let mut swung = false;
            for (w, c) in wheels.iter_mut().zip(&ik.wheels) {
                if matches!(w.kind, WheelKind::Castor { .. }) && c.steer_rate.is_finite() {
                    w.beta = kinolab_common::angle::wrap(w.beta + c.steer_rate * dt / steps);
                    swung |= c.steer_rate != 0.0;
                }
            }
            match Chassis::new(self.chassis.name().to_owned(), wheels) {
                Ok(next) if swung => self.chassis = next,
                _ => return,
            }
        }
    }

    /// The floor that follows the robot: grid, trail, robot, each wheel's
    /// contact-point velocity, the ICR.
    fn floor(&self, ui: &egui::Ui, painter: &Painter, rect: egui::Rect, twist: Vector3<f64>) {
        let extent = self
            .chassis
            .wheels()
            .iter()
            .map(|w| w.l + w.radius)
            .fold(0.3, f64::max)
            * 3.2;
        let view = RobotView {
            plane: PlaneView::centred(rect, [self.pose[0], self.pose[1]], extent),
            pose: self.pose,
        };
        let ink = ui.visuals().text_color();
        grid(painter, &view.plane, rect, 0.25, ink.gamma_multiply(0.08));
        let trail: Vec<egui::Pos2> = self
            .trail
            .iter()
            .map(|p| view.plane.to_screen(*p))
            .collect();
        if trail.len() > 1 {
            painter.add(egui::Shape::line(
                trail,
                Stroke::new(2.0, theme::accent(ui).gamma_multiply(0.6)),
            ));
        }
        let mut labels = Labels::default();
        draw_frame(
            painter,
            &mut labels,
            &view,
            ink.gamma_multiply(0.5),
            extent * 0.2,
        );
        for (i, w) in self.chassis.wheels().iter().enumerate() {
            draw_wheel(painter, &view, w, wheel_color(i), false);
            // Velocity of the contact point, drawn in the world, half scale.
            let c = contact_point(w);
            let u = [twist.x - twist.z * c[1], twist.y + twist.z * c[0]];
            let d = placed_dir(self.pose[2], [u[0] * 0.5, u[1] * 0.5]);
            let from_world = placed(self.pose, c);
            let from = view.plane.to_screen(from_world);
            let to = view
                .plane
                .to_screen([from_world[0] + d[0], from_world[1] + d[1]]);
            if (to - from).length() > 2.0 {
                painter.arrow(from, to - from, Stroke::new(2.0, wheel_color(i)));
            }
        }
        for r in wheel_rects(&view, self.chassis.wheels()) {
            labels.reserve(r);
        }
        draw_icr(
            painter,
            &mut labels,
            &view,
            &twist_icr(&twist),
            theme::accent(ui),
            rect,
        );
        labels.draw(painter, &egui::FontId::proportional(theme::LABEL_SIZE));
    }

    /// The twist, ICR and pose in words, and what each wheel does.
    /// The twist driven, its ICR and the pose, in words.
    fn motion_text(&self, twist: Vector3<f64>) -> String {
        let icr_text = match twist_icr(&twist) {
            Icr::Point { x, y } => format!(
                "ICR at ({}, {}) m in the robot frame",
                fixed(x, 2),
                fixed(y, 2)
            ),
            Icr::Infinity { .. } => "ICR at infinity: driving straight".to_owned(),
            _ => "standing still".to_owned(),
        };
        format!(
            "Twist (forward, sideways, turn) = ({} m/s, {} m/s, {} rad/s). {icr_text}. Pose x = {} m, y = {} m, θ = {}°.",
            fixed(twist.x, 2),
            fixed(twist.y, 2),
            fixed(twist.z, 2),
            fixed(self.pose[0], 2),
            fixed(self.pose[1], 2),
            fixed(kinolab_common::angle::wrap(self.pose[2]).to_degrees(), 0)
        )
    }

    fn readouts(&self, ui: &mut egui::Ui, twist: Vector3<f64>) {
        ui.label(self.motion_text(twist));
        if self.settings.mode == Mode::Twist
            && let Ok(ik) = self.chassis.inverse(twist)
        {
            let spins: Vec<String> = ik
                .wheels
                .iter()
                .enumerate()
                .map(|(i, c)| match self.chassis.wheels()[i].kind {
                    WheelKind::Steered => format!(
                        "{}: {} rad/s at β {}°",
                        i + 1,
                        fixed(c.spin, 1),
                        fixed(c.steer.to_degrees(), 0)
                    ),
                    WheelKind::Castor { .. } => format!(
                        "{}: {} rad/s, swings {}°/s",
                        i + 1,
                        fixed(c.spin, 1),
                        fixed(c.steer_rate.to_degrees(), 0)
                    ),
                    _ => format!("{}: {} rad/s", i + 1, fixed(c.spin, 1)),
                })
                .collect();
            ui.label(RichText::new(format!("Wheel spins. {}", spins.join("; "))).small());
        }
    }
}

impl LabWidget for Drive {
    /// The robot, how it is driven, the twist with its ICR and the pose,
    /// and why the request is not met when it is not.
    fn describe(&self) -> Option<String> {
        let (twist, note) = self.resolved();
        let how = match self.settings.mode {
            Mode::Twist => "driven by its twist",
            Mode::Wheels => "driven by its wheel spins",
        };
        let mut text = format!(
            "Robot {}, {how}{}. {}",
            self.chassis.name(),
            if self.running { "" } else { ", paused" },
            self.motion_text(twist)
        );
        if let Some(note) = note {
            text = format!("{text} {note}");
        }
        Some(text)
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        if !self.shown {
            self.shown = true;
            self.running = !theme::motion_reduced(ui.ctx());
        }
        let before = self.settings.clone();
        self.controls(ui);
        let width = ui.available_width().min(900.0);
        let (response, painter) = canvas(ui, vec2(width, 360.0), Sense::click());
        let rect = response.rect;
        if response.clicked() {
            response.request_focus();
        }
        self.keyboard(ui, &response);
        if self.settings != before {
            // A change wakes a drive that paused itself, not one the
            // learner paused.
            self.running |= self.unattended > REST_AFTER;
            self.unattended = 0.0;
        }
        let (twist, note) = self.current_twist();
        self.step(ui, twist);
        self.floor(ui, &painter, rect, twist);
        export::bar(
            ui,
            ui.scope_id().with("wheel-drive-exports"),
            &[Export::Png {
                file: "kinolab-wheel-drive.png",
                rect,
            }],
        );
        self.readouts(ui, twist);
        // One line kept for notes, so the layout does not jump.
        if !self.running && self.unattended > REST_AFTER {
            ui.label(format!(
                "Paused after {REST_AFTER:.0} s with nothing changed: press Run to drive on."
            ));
        } else {
            ui.label(RichText::new(note.unwrap_or_default()).color(theme::error_color(ui)));
        }
        ui.label(
            RichText::new(
                "Click the floor (or hover it) and use the arrow keys to drive; Q and E slide sideways.",
            )
            .small(),
        );
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
        let settings = match link::read::<Settings, ()>(NAME, state) {
            Ok((settings, _)) => settings,
            Err(why) => match link::decode::<Legacy>(state) {
                Some(old) => self.legacy(old),
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema's ranges too.
        let chassis = robot(&settings)?;
        *self = Drive {
            initial: self.initial.clone(),
            ..Drive::new(chassis, settings)
        };
        Ok(())
    }
}

impl Drive {
    /// An old link's command, with the lesson's robot.
    fn legacy(&self, old: Legacy) -> Settings {
        let [forward, sideways, turn] = old.twist;
        let mode = match old.mode {
            LegacyMode::Wheels => Mode::Wheels,
            LegacyMode::Twist => Mode::Twist,
        };
        Settings {
            mode,
            forward,
            sideways,
            turn,
            spins: (mode == Mode::Wheels)
                .then(|| old.spins.iter().map(|s| s.unwrap_or(0.0)).collect()),
            ..self.initial.clone()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn widget(params: &[(&str, &str)]) -> Drive {
        let p = kinolab_schema::validate(&crate::registry::spec(NAME, params))
            .unwrap_or_else(|e| panic!("{e}"));
        let chassis = kinolab_schema::robot_of(&p).unwrap_or_else(|e| panic!("{e}"));
        Drive::new(chassis, p.settings().unwrap_or_else(|e| panic!("{e}")))
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        // Wheels mode (the first variant), a twist, two driven wheels and a castor.
        let old = link::encode(&(
            0_u32,
            [0.2_f64, 0.0, -0.5],
            vec![Some(3.0_f64), Some(-1.5), None],
        ))
        .unwrap_or_default();
        let mut w = widget(&[]);
        assert_eq!(w.restore(&old), Ok(()));
        assert_eq!(w.settings.mode, Mode::Wheels);
        assert_eq!((w.settings.forward, w.settings.turn), (0.2, -0.5));
        assert_eq!(w.settings.spins, Some(vec![3.0, -1.5, 0.0]));
        assert_eq!(w.spins(), vec![Some(3.0), Some(-1.5), None]);
        // Out of the schema's range: refused, the lesson's settings kept.
        let bad =
            link::encode(&(1_u32, [5.0_f64, 0.0, 0.0], vec![None::<f64>; 3])).unwrap_or_default();
        let mut w = widget(&[("forward", "0.5")]);
        assert!(w.restore(&bad).is_err());
        assert_eq!(w.settings.forward, 0.5);
    }

    #[test]
    fn the_spins_travel_in_the_link() {
        let mut w = widget(&[("mode", "wheels")]);
        assert_eq!(w.state(), None);
        assert_eq!(w.settings.spins.as_ref().map(Vec::len), Some(3));
        if let Some(spins) = &mut w.settings.spins {
            spins[0] = 7.5;
        }
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.settings, w.settings);
    }

    /// The castor's angle and how fast it still swings, for `twist`.
    fn castor(d: &Drive, twist: Vector3<f64>) -> (f64, f64) {
        let i = d
            .chassis
            .wheels()
            .iter()
            .position(|w| matches!(w.kind, WheelKind::Castor { .. }))
            .expect("the differential drive has a castor");
        let ik = d.chassis.inverse(twist).expect("a valid twist");
        (d.chassis.wheels()[i].beta, ik.wheels[i].steer_rate)
    }

    #[test]
    fn a_castor_swings_round_to_trail_the_motion() {
        let chassis =
            kinolab_wheels::catalogue::robot("differential-drive").expect("in the catalogue");
        let p = kinolab_schema::validate(&crate::registry::spec(NAME, &[]))
            .unwrap_or_else(|e| panic!("{e}"));
        let mut d = Drive::new(chassis, p.settings().unwrap_or_else(|e| panic!("{e}")));
        let drive = |d: &mut Drive, twist: Vector3<f64>| {
            // A nudge off balance, as any real castor has, then 4 s.
            d.swing_castors(twist + Vector3::new(0.0, 0.0, 0.2), 0.05);
            for _ in 0..200 {
                d.swing_castors(twist, 0.02);
            }
        };
        for v in [0.3, -0.3] {
            let twist = Vector3::new(v, 0.0, 0.0);
            drive(&mut d, twist);
            let (trailing, rate) = castor(&d, twist);
            assert!(rate.abs() < 1e-3, "still swinging at {rate} rad/s");
            // Reverse: the castor leads now, and swings half a turn round.
            drive(&mut d, -twist);
            let (after, rate) = castor(&d, -twist);
            let turned = kinolab_common::angle::wrap(after - trailing).abs();
            assert!(
                (turned - std::f64::consts::PI).abs() < 0.01,
                "turned {turned} rad"
            );
            assert!(rate.abs() < 1e-3, "still swinging at {rate} rad/s");
        }
    }
}
