//! The controller playground: the polar go-to-pose controller on a
//! differential drive. Drag start and goal, set gains, see the path, the
//! robot, and ρ, α, β, v, ω over time; many starts at once; open loop
//! against closed loop under the same slip; the stability region.
//!
//! - this file: the state, the constructor, the tabs and the link;
//! - [`settings`]: what the learner sets, and the runs it gives;
//! - [`floor`]: the floor with its draggable poses;
//! - [`tabs`]: one run, many starts, open against closed loop;
//! - [`gains`]: the gain sliders, the gain plane and the conditions;
//! - [`export`]: plots, CSV and PNG;
//! - [`exercise`]: the graded tasks.

mod exercise;
mod export;
mod floor;
mod gains;
mod settings;
mod tabs;

use kinolab_common::Feedback;
use kinolab_control::exercise::Task;
use kinolab_control::{Direction, Plan, Pose, Trajectory};

use crate::draw::PlaneView;
use crate::link;
use crate::widget::{LabWidget, Params, triple};
use settings::{LinkState, Settings};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Tab {
    Run,
    Many,
    OpenVsClosed,
    Gains,
}

const TABS: [(Tab, &str, &str); 4] = [
    (Tab::Run, "run", "One run"),
    (Tab::Many, "many", "Many starts"),
    (Tab::OpenVsClosed, "open-vs-closed", "Open vs closed loop"),
    (Tab::Gains, "gains", "Gain region"),
];

/// What the learner is asked to do, and how it went.
struct Exercise {
    task: Task,
    marks: Vec<bool>,
    feedback: Option<Feedback>,
}

/// The open-vs-closed comparison: the plan, then open and closed runs.
type Comparison = (Plan, Trajectory, Trajectory);

struct Playground {
    tab: Tab,
    set: Settings,
    initial: Settings,
    initial_tab: Tab,
    computed: Option<Settings>,
    run: Option<Result<Trajectory, String>>,
    many: Option<Result<Vec<Trajectory>, String>>,
    compare: Option<Result<Comparison, String>>,
    /// Playback time, s, and whether it advances.
    cursor: f64,
    playing: bool,
    /// The view kept while the learner drags on the floor, so it does not
    /// slide away under the pointer.
    frozen: Option<PlaneView>,
    exercise: Option<Exercise>,
    /// A requested capture of the plots.
    capture: Option<export::Capture>,
    status: Option<String>,
}

fn pose_of(p: &Params, name: &str) -> Pose {
    let [x, y, heading] = triple(p, name);
    Pose::new(x, y, heading.to_radians())
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let tab = TABS
        .iter()
        .find(|(_, key, _)| Some(*key) == p.choice("view"))
        .map_or(Tab::Run, |(t, _, _)| *t);
    let set = Settings {
        start: pose_of(p, "start"),
        goal: pose_of(p, "goal"),
        gains: triple(p, "gains"),
        direction: match p.choice("direction") {
            Some("forward") => Direction::Forward,
            Some("backward") => Direction::Backward,
            _ => Direction::Auto,
        },
        slip: p.number("slip").unwrap_or_default(),
        push: p.number("push").unwrap_or_default(),
        seed: p.integer("seed").unwrap_or(1).max(0) as u64,
        control_rate: p.number("control-rate").unwrap_or_default(),
        max_wheel_speed: p.number("max-wheel-speed").unwrap_or_default(),
        plan: p.text("plan").unwrap_or("line 1").to_owned(),
        many_count: 24,
        many_heading_deg: 0.0,
    };
    let exercise = exercise::from_params(p, &set)?;
    Ok(Box::new(Playground {
        tab,
        initial: set.clone(),
        initial_tab: tab,
        set,
        computed: None,
        run: None,
        many: None,
        compare: None,
        cursor: 0.0,
        playing: true,
        frozen: None,
        exercise,
        capture: None,
        status: None,
    }))
}

impl Playground {
    /// Recompute what the visible tab shows, once per change.
    fn refresh(&mut self) {
        if self.computed.as_ref() != Some(&self.set) {
            self.computed = Some(self.set.clone());
            self.run = None;
            self.many = None;
            self.compare = None;
            if let Some(ex) = &mut self.exercise {
                ex.feedback = None;
            }
        }
        match self.tab {
            Tab::Run if self.run.is_none() => self.run = Some(self.set.run()),
            Tab::Many if self.many.is_none() => self.many = Some(self.set.many()),
            Tab::OpenVsClosed if self.compare.is_none() => self.compare = Some(self.set.compare()),
            _ => {}
        }
    }

    fn tab_bar(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            for (tab, _, label) in TABS {
                if ui.selectable_label(self.tab == tab, label).clicked() && self.tab != tab {
                    self.tab = tab;
                    self.cursor = 0.0;
                    self.playing = true;
                }
            }
        });
    }
}

impl LabWidget for Playground {
    fn ui(&mut self, ui: &mut egui::Ui) {
        self.finish_capture(ui);
        self.tab_bar(ui);
        self.gain_sliders(ui);
        self.stability_line(ui);
        self.effects(ui);
        let before = self.set.clone();
        self.refresh();
        match self.tab {
            Tab::Run => self.run_tab(ui),
            Tab::Many => self.many_tab(ui),
            Tab::OpenVsClosed => self.compare_tab(ui),
            Tab::Gains => self.gains_tab(ui),
        }
        self.exercise_ui(ui);
        if self.set != before {
            crate::widget::animate(ui);
        }
    }

    fn state(&self) -> Option<String> {
        (self.set != self.initial || self.tab != self.initial_tab)
            .then(|| link::encode(&LinkState::of(&self.set, self.tab)))
            .flatten()
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some((set, tab)) = link::decode::<LinkState>(state).and_then(LinkState::settings) {
            self.set = set;
            self.tab = tab;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::{create as build, spec};

    #[test]
    fn lesson_parameters_reach_the_settings() {
        let block = spec(
            "controller-playground",
            &[
                ("view", "many"),
                ("gains", "3, 9, -2"),
                ("slip", "0.1"),
                ("start", "-1, 0.5, 90"),
            ],
        );
        assert!(build(&block).is_ok());
        let Ok(p) = kinolab_schema::validate(&block) else {
            panic!()
        };
        let s = pose_of(&p, "start");
        assert!((s.theta - std::f64::consts::FRAC_PI_2).abs() < 1e-15 && s.x == -1.0);
        for (k, v) in [
            ("view", "sideways"),
            ("plan", "jump 2"),
            ("task", "dance"),
            ("slip", "2"),
            ("start", "1,2"),
        ] {
            assert!(
                build(&spec("controller-playground", &[(k, v)])).is_err(),
                "{k}: {v}"
            );
        }
    }
}
