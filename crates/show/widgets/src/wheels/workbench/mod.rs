//! The wheel workbench: place wheels on a chassis seen from above and watch
//! the constraint rows, rank, the three degrees, DOF and the ICR follow.
//!
//! - this file: the state, the constructor, the layout and the link;
//! - [`canvas`]: the drawing, and dragging and turning wheels;
//! - [`panels`]: the degrees, the rows, the wheel editor, the challenge
//!   and the robot file.

mod canvas;
mod panels;

use egui::{RichText, vec2};
use kinolab_common::Feedback;
use kinolab_wheels::challenge::Goal;
use kinolab_wheels::{Chassis, Wheel, WheelKind};
use serde::{Deserialize, Serialize};

use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::theme;
use crate::widget::{LabWidget, Params};

/// The widget's name in the schema.
const NAME: &str = "wheel-workbench";

/// Positions snap to this grid (metres) and angles to this step (degrees)
/// while dragging, so wheels can share an axle exactly.
const GRID: f64 = 0.05;
const ANGLE_STEP: f64 = 5.0;
/// How close to the goal ICR counts, m.
const ICR_TOLERANCE: f64 = 0.05;

/// What the lesson sets and a link carries: the schema's parameters. A
/// layout the learner changed travels as `layout` (or `robot`, when it is
/// a catalogue robot as it stands).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
struct Settings {
    robot: Option<String>,
    layout: Option<String>,
    goal_maneuverability: Option<usize>,
    max_steer_inputs: Option<usize>,
    goal_icr: Option<[f64; 2]>,
    goal_mobility: Option<usize>,
    goal_dof: Option<usize>,
    find_disagreeing: bool,
    /// The wheels picked in the challenge, by number from 1.
    chosen: Option<Vec<f64>>,
}

impl Settings {
    fn task(&self) -> Task {
        if let Some(target) = self.goal_maneuverability {
            Task::Goal(Goal::Maneuverability {
                target,
                max_steer_inputs: self.max_steer_inputs,
            })
        } else if let Some(target) = self.goal_mobility {
            Task::Goal(Goal::Mobility { target })
        } else if let Some(target) = self.goal_dof {
            Task::Goal(Goal::Dof { target })
        } else if let Some([x, y]) = self.goal_icr {
            Task::Goal(Goal::IcrAt {
                x,
                y,
                tolerance: ICR_TOLERANCE,
            })
        } else if self.find_disagreeing {
            let chosen = self.chosen.clone().unwrap_or_default();
            Task::FindDisagreeing {
                chosen: chosen
                    .iter()
                    .map(|n| (*n as usize).saturating_sub(1))
                    .collect(),
                feedback: None,
            }
        } else {
            Task::None
        }
    }
}

enum Task {
    None,
    Goal(Goal),
    FindDisagreeing {
        chosen: Vec<usize>,
        feedback: Option<Feedback>,
    },
}

pub(super) struct Workbench {
    /// What the lesson set up.
    initial: Settings,
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

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let chassis = kinolab_schema::robot_of(p)?;
    Ok(Box::new(Workbench::new(chassis, p.settings()?)))
}

/// The robot that `settings` name, through the schema (which checks them).
fn robot(settings: &Settings) -> Result<Chassis, String> {
    let spec = kinolab_lessons::WidgetSpec {
        name: NAME.to_owned(),
        params: kinolab_schema::settings::to_params(NAME, settings)?,
        line: 0,
    };
    kinolab_schema::robot_of(&kinolab_schema::validate(&spec)?)
}

/// How far the drawing must reach to show every wheel, the point where
/// their zero-motion lines meet, and a goal ICR.
fn extent_for(chassis: &Chassis, task: &Task) -> f64 {
    let mut reach = chassis
        .wheels()
        .iter()
        .map(|w| w.l + w.radius)
        .fold(0.3, f64::max)
        * 1.5;
    if let kinolab_wheels::Icr::Point { x, y } = chassis.analyze().icr {
        reach = reach.max(x.hypot(y) * 1.15);
    }
    if let Task::Goal(Goal::IcrAt { x, y, .. }) = task {
        reach = reach.max(x.hypot(*y) * 1.15);
    }
    reach.min(4.0)
}

impl Workbench {
    fn new(chassis: Chassis, settings: Settings) -> Self {
        let task = settings.task();
        let extent = extent_for(&chassis, &task);
        let file_text = chassis.to_json();
        Self {
            initial: settings,
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
                self.set(chassis);
                true
            }
            Err(e) => {
                self.message = Some(e.to_string());
                false
            }
        }
    }

    /// Take a changed chassis; a challenge's old verdict no longer holds.
    fn set(&mut self, chassis: Chassis) {
        self.chassis = chassis;
        self.file_text = self.chassis.to_json();
        self.message = None;
        if let Task::FindDisagreeing { feedback, .. } = &mut self.task {
            *feedback = None;
        }
    }

    fn load(&mut self, chassis: Chassis) {
        self.extent = extent_for(&chassis, &self.task);
        self.set(chassis);
        self.selected = None;
        if let Task::FindDisagreeing { chosen, .. } = &mut self.task {
            chosen.clear();
        }
    }

    /// Steer wheel `i` to `beta`: through its linkage for a steered wheel,
    /// directly otherwise.
    fn steer(&mut self, i: usize, beta: f64) {
        if self.chassis.wheels()[i].kind == WheelKind::Steered {
            match self.chassis.steer(i, beta) {
                Ok(c) => self.set(c),
                Err(e) => self.message = Some(e.to_string()),
            }
        } else {
            let mut wheels = self.chassis.wheels().to_vec();
            wheels[i].beta = beta;
            self.try_set(wheels);
        }
    }
}

impl LabWidget for Workbench {
    fn describe(&self) -> Option<String> {
        Some(self.description())
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.toolbar(ui);
        let analysis = self.chassis.analyze();
        let wide = ui.available_width() > 760.0;
        let canvas_size = if wide {
            vec2(ui.available_width() * 0.56, 400.0)
        } else {
            vec2(ui.available_width(), 340.0)
        };
        let mut drawing = egui::Rect::NOTHING;
        if wide {
            ui.horizontal_top(|ui| {
                drawing = self.canvas(ui, &analysis, canvas_size);
                ui.vertical(|ui| {
                    self.degrees_panel(ui, &analysis);
                    ui.separator();
                    self.selected_editor(ui);
                });
            });
        } else {
            drawing = self.canvas(ui, &analysis, canvas_size);
            self.degrees_panel(ui, &analysis);
            self.selected_editor(ui);
        }
        // One line kept for messages, so the layout does not jump.
        let message = self.message.clone().unwrap_or_default();
        ui.label(RichText::new(message).color(theme::error_color(ui)));
        export::bar(
            ui,
            ui.scope_id().with("workbench-exports"),
            &[Export::Png {
                file: "kinolab-wheel-layout.png",
                rect: drawing,
            }],
        );
        self.task_ui(ui);
        self.matrices(ui);
        self.file_ui(ui);
    }

    fn state(&self) -> Option<String> {
        link::write(
            NAME,
            &self.settings(),
            &self.initial,
            &Moment::<()>::default(),
        )
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let settings = match link::read::<Settings, ()>(NAME, state) {
            Ok((settings, _)) => settings,
            Err(why) => match link::decode::<LinkLayout>(state).and_then(LinkLayout::chassis) {
                Some(chassis) => Settings {
                    robot: None,
                    layout: Some(chassis.to_compact()),
                    ..self.initial.clone()
                },
                None => return Err(why),
            },
        };
        let chassis = robot(&settings)?;
        let lesson = (self.initial.clone(), self.start.clone());
        *self = Workbench::new(chassis, settings);
        (self.initial, self.start) = lesson;
        Ok(())
    }
}

impl Workbench {
    /// The settings as the learner has them now.
    fn settings(&self) -> Settings {
        let mut settings = self.initial.clone();
        if self.chassis != self.start {
            let compact = self.chassis.to_compact();
            let robot = kinolab_wheels::catalogue::CATALOGUE.iter().find(|e| {
                kinolab_wheels::catalogue::robot(e.id).is_ok_and(|c| c.to_compact() == compact)
            });
            (settings.robot, settings.layout) = match robot {
                Some(e) => (Some(e.id.to_owned()), None),
                None => (None, Some(compact)),
            };
        }
        if let Task::FindDisagreeing { chosen, .. } = &self.task {
            let mut numbers: Vec<f64> = chosen.iter().map(|i| (i + 1) as f64).collect();
            numbers.sort_by(f64::total_cmp);
            settings.chosen = (!numbers.is_empty()).then_some(numbers);
        }
        settings
    }
}

/// A layout as the first format of links carries it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct LinkLayout {
    name: String,
    wheels: Vec<LinkWheel>,
}

/// One wheel: its kind (0 fixed, 1 steered, 2 castor with `extra` its
/// offset, 3 Swedish with `extra` its roller angle, 4 ball), placement and
/// steering group.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct LinkWheel {
    kind: u8,
    alpha: f64,
    beta: f64,
    l: f64,
    radius: f64,
    extra: f64,
    group: Option<String>,
}

impl LinkLayout {
    #[cfg(test)]
    fn of(chassis: &Chassis) -> Self {
        let wheels = chassis
            .wheels()
            .iter()
            .map(|w| {
                let (kind, extra) = match w.kind {
                    WheelKind::Fixed => (0, 0.0),
                    WheelKind::Steered => (1, 0.0),
                    WheelKind::Castor { offset } => (2, offset),
                    WheelKind::Swedish { gamma } => (3, gamma),
                    WheelKind::Spherical => (4, 0.0),
                };
                LinkWheel {
                    kind,
                    alpha: w.alpha,
                    beta: w.beta,
                    l: w.l,
                    radius: w.radius,
                    extra,
                    group: w.steer_group.clone(),
                }
            })
            .collect();
        Self {
            name: chassis.name().to_owned(),
            wheels,
        }
    }

    /// The chassis, if the link describes a valid one.
    fn chassis(self) -> Option<Chassis> {
        let wheels = self
            .wheels
            .into_iter()
            .map(|w| {
                let kind = match w.kind {
                    0 => WheelKind::Fixed,
                    1 => WheelKind::Steered,
                    2 => WheelKind::Castor { offset: w.extra },
                    3 => WheelKind::Swedish { gamma: w.extra },
                    4 => WheelKind::Spherical,
                    _ => return None,
                };
                Some(Wheel {
                    kind,
                    alpha: w.alpha,
                    beta: w.beta,
                    l: w.l,
                    radius: w.radius,
                    steer_group: w.group,
                })
            })
            .collect::<Option<Vec<_>>>()?;
        Chassis::new(self.name, wheels).ok()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::spec;

    fn widget(params: &[(&str, &str)]) -> Workbench {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        let chassis = kinolab_schema::robot_of(&p).unwrap_or_else(|e| panic!("{e}"));
        Workbench::new(chassis, p.settings().unwrap_or_else(|e| panic!("{e}")))
    }

    #[test]
    fn every_catalogue_layout_survives_a_link() {
        for entry in kinolab_wheels::catalogue::CATALOGUE {
            let Ok(chassis) = kinolab_wheels::catalogue::robot(entry.id) else {
                panic!("{}", entry.id)
            };
            let text = link::encode(&LinkLayout::of(&chassis)).unwrap_or_default();
            let back = link::decode::<LinkLayout>(&text).and_then(LinkLayout::chassis);
            assert_eq!(back.as_ref(), Some(&chassis), "{}", entry.id);
            // Picked from the toolbar, it travels by its id.
            let mut w = widget(&[("layout", "f,90,0,0.3,0.1;o,-90,0,0.3,0.05")]);
            w.load(chassis.clone());
            let mut again = widget(&[]);
            assert_eq!(
                again.restore(&w.state().unwrap_or_default()),
                Ok(()),
                "{}",
                entry.id
            );
            assert_eq!(
                again.chassis.to_compact(),
                chassis.to_compact(),
                "{}",
                entry.id
            );
        }
        assert!(
            link::decode::<LinkLayout>("a_broken")
                .and_then(LinkLayout::chassis)
                .is_none()
        );
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        let Ok(tricycle) = kinolab_wheels::catalogue::robot("tricycle") else {
            panic!("the tricycle is in the catalogue")
        };
        let old = link::encode(&LinkLayout::of(&tricycle)).unwrap_or_default();
        let mut w = widget(&[]);
        assert_eq!(w.restore(&old), Ok(()));
        assert_eq!(w.chassis.to_compact(), tricycle.to_compact());
        // A wheel with a radius the core refuses: refused, the lesson's kept.
        let mut broken = LinkLayout::of(&tricycle);
        broken.wheels[0].radius = -1.0;
        let mut w = widget(&[("robot", "three-swedish")]);
        assert!(
            w.restore(&link::encode(&broken).unwrap_or_default())
                .is_err()
        );
        assert_eq!(w.chassis.name(), w.start.name());
    }

    #[test]
    fn an_edited_layout_and_the_picks_travel_in_the_link() {
        let stuck = "f,45,45,0.5,0.1;f,-45,135,0.5,0.1;f,135,-45,0.5,0.1;f,-135,-135,0.5,0.1;f,0,20,0.5,0.1";
        let mut w = widget(&[("layout", stuck), ("find-disagreeing", "yes")]);
        assert_eq!(w.state(), None);
        w.select(Some(4), false);
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[("layout", stuck), ("find-disagreeing", "yes")]);
        assert_eq!(again.restore(&text), Ok(()));
        assert!(matches!(&again.task, Task::FindDisagreeing { chosen, .. } if chosen == &[4]));
        // A moved wheel travels as a layout.
        let mut w = widget(&[]);
        let mut wheels = w.chassis.wheels().to_vec();
        wheels[2].l = 0.4;
        assert!(w.try_set(wheels));
        let mut again = widget(&[]);
        assert_eq!(again.restore(&w.state().unwrap_or_default()), Ok(()));
        assert_eq!(again.chassis.to_compact(), w.chassis.to_compact());
    }
}
