//! What the learner sets in the playground (the schema's parameters, typed
//! once), the run files they make, and the runs those files give; how the
//! first format of links is read.

use kinolab_common::angle::wrap;
use kinolab_control::batch::{PREVIEW_DT, PREVIEW_DURATION, batch, circle_starts};
use kinolab_control::file::{RunSpec, from_json};
use kinolab_control::{Direction, Driver, Gains, Plan, Pose, Segment, Trajectory};
use serde::{Deserialize, Serialize};
use serde_json::{Value, json};

use super::Comparison;

/// The tab a playground shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub(super) enum View {
    Run,
    Many,
    OpenVsClosed,
    Gains,
}

/// A graded exercise.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub(super) enum TaskKind {
    ReachWithin,
    SpotUnstable,
}

/// Everything a lesson sets and a learner can change, and what a link
/// carries: the schema's parameters. Poses are `x, y, heading_deg`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub(super) struct Settings {
    pub view: View,
    pub start: [f64; 3],
    pub goal: [f64; 3],
    pub gains: [f64; 3],
    pub direction: Direction,
    pub slip: f64,
    pub push: f64,
    pub seed: u64,
    /// Hz; 0 = continuous.
    pub control_rate: f64,
    /// rad/s; 0 = unlimited.
    pub max_wheel_speed: f64,
    pub plan: String,
    /// Many starts: how many on the circle, and their heading (°).
    pub starts: usize,
    pub start_heading: f64,
    pub task: Option<TaskKind>,
    pub time_limit: f64,
    pub forward_only: bool,
    pub sets: Vec<[f64; 3]>,
    /// The gain sets marked unstable, by number from 1.
    pub marked: Option<Vec<f64>>,
}

/// Simulation step of the playground's runs, s, and a sample every so
/// many steps (a sample every 10 ms).
const DT: f64 = 0.001;
const OUTPUT_EVERY: usize = 10;
/// Seconds a run from start to goal lasts.
const DURATION: f64 = 10.0;

/// A pose `x, y, heading_deg` as the core's pose.
pub(super) fn pose([x, y, heading]: [f64; 3]) -> Pose {
    Pose::new(x, y, heading.to_radians())
}

fn pose_file([x, y, heading]: [f64; 3]) -> Value {
    json!({ "x": x, "y": y, "theta_deg": heading })
}

fn text(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// A run file as the command line writes it.
pub(super) fn pretty(file: &Value) -> Result<String, String> {
    serde_json::to_string_pretty(file).map_err(text)
}

/// The run a file describes, as `kinolab simulate` reads it.
pub(super) fn spec(file: &Value) -> Result<RunSpec, String> {
    from_json(&file.to_string()).map_err(text)
}

impl Settings {
    pub fn gains(&self) -> Result<Gains, String> {
        Gains::new(self.gains[0], self.gains[1], self.gains[2]).map_err(text)
    }

    /// Slip and pushes, the control rate and the wheel limit, as a run
    /// file gives them (a push of 0.1 m/s comes with up to 0.2 rad/s of
    /// twist).
    fn effects(&self, file: &mut Value) {
        if self.slip > 0.0 || self.push > 0.0 {
            file["noise"] = json!({
                "seed": self.seed,
                "slip": self.slip,
                "push_speed": self.push,
                "push_turn_deg": (2.0 * self.push).to_degrees(),
            });
        }
        if self.control_rate > 0.0 {
            file["control_rate"] = json!(self.control_rate);
        }
        if self.max_wheel_speed > 0.0 {
            file["max_wheel_speed"] = json!(self.max_wheel_speed);
        }
    }

    /// The polar controller from `start` to `goal` for `duration` s with
    /// every setting applied, as a run file.
    fn polar_file(&self, start: [f64; 3], goal: [f64; 3], duration: f64) -> Value {
        let [k_rho, k_alpha, k_beta] = self.gains;
        let mut file = json!({
            "controller": {
                "kind": "polar",
                "k_rho": k_rho,
                "k_alpha": k_alpha,
                "k_beta": k_beta,
                "direction": self.direction,
            },
            "start": pose_file(start),
            "goal": pose_file(goal),
            "dt": DT,
            "duration": duration,
            "output_every": OUTPUT_EVERY,
        });
        self.effects(&mut file);
        file
    }

    /// The one run, start to goal (`kinolab simulate` reads it).
    pub fn run_file(&self) -> Value {
        self.polar_file(self.start, self.goal, DURATION)
    }

    /// One run from start to goal.
    pub fn run(&self) -> Result<Trajectory, String> {
        spec(&self.run_file())?.run.simulate().map_err(text)
    }

    /// The plan played open loop, as a run file, and how long the
    /// comparison lasts.
    pub fn open_file(&self) -> Result<(Value, f64), String> {
        let segments = Segment::parse_list(&self.plan).map_err(text)?;
        let plan = Plan::new(
            pose(self.start),
            &segments,
            kinolab_control::Limits::default(),
        )
        .map_err(text)?;
        let segments: Vec<Value> = segments
            .iter()
            .map(|segment| match *segment {
                Segment::Line { length } => json!({ "kind": "line", "length": length }),
                Segment::Arc { radius, angle } => {
                    json!({ "kind": "arc", "radius": radius, "angle_deg": angle.to_degrees() })
                }
                Segment::Turn { angle } => {
                    json!({ "kind": "turn", "angle_deg": angle.to_degrees() })
                }
            })
            .collect();
        let duration = (plan.duration() + 1.0).max(DURATION);
        let mut file = json!({
            "controller": { "kind": "open_loop", "segments": segments },
            "start": pose_file(self.start),
            "dt": DT,
            "duration": duration,
            "output_every": OUTPUT_EVERY,
        });
        self.effects(&mut file);
        // The run file's limits are the plan's defaults; control rate and
        // wheel limit belong to the controller.
        if let Some(map) = file.as_object_mut() {
            map.remove("control_rate");
            map.remove("max_wheel_speed");
        }
        Ok((file, duration))
    }

    /// The plan played open loop, and the controller driving to its end,
    /// under the same slip and pushes.
    pub fn compare(&self) -> Result<Comparison, String> {
        let (open_file, duration) = self.open_file()?;
        let open_spec = spec(&open_file)?;
        let Driver::OpenLoop(plan) = open_spec.run.driver.clone() else {
            return Err("the plan is not an open-loop run".into());
        };
        let end = plan.end();
        let goal = [end.x, end.y, wrap(end.theta).to_degrees()];
        let closed = spec(&self.polar_file(self.start, goal, duration))?;
        let open = open_spec.run.simulate().map_err(text)?;
        let closed = closed.run.simulate().map_err(text)?;
        Ok((plan, open, closed))
    }

    /// Quick runs from starts on a 1 m circle around the goal, as the run
    /// file that `kinolab batch` reads with these starts (its own start is
    /// replaced by the circle's).
    pub fn many_file(&self) -> Value {
        let mut file = self.polar_file(self.goal, self.goal, PREVIEW_DURATION);
        file["dt"] = json!(PREVIEW_DT);
        file["output_every"] = json!(1);
        file
    }

    /// The arguments after `kinolab` for the many starts, the file named `file`.
    pub fn many_args(&self, file: &str) -> Vec<String> {
        vec![
            "batch".into(),
            file.into(),
            "--count".into(),
            self.starts.to_string(),
            "--heading-deg".into(),
            self.start_heading.to_string(),
        ]
    }

    /// Quick runs from starts on a 1 m circle around the goal.
    pub fn many(&self) -> Result<Vec<Trajectory>, String> {
        let run = spec(&self.many_file())?.run;
        let starts = circle_starts(&run.goal, 1.0, self.starts, self.start_heading.to_radians())
            .map_err(text)?;
        batch(&run, &starts).map_err(text)
    }
}

/// The settings as the first format of links carried them (angles in
/// radians, the tab and the direction by index).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(super) struct Legacy {
    tab: u8,
    start: [f64; 3],
    goal: [f64; 3],
    gains: [f64; 3],
    direction: u8,
    slip: f64,
    push: f64,
    seed: u64,
    control_rate: f64,
    max_wheel_speed: f64,
    plan: String,
    many_count: u16,
    many_heading_deg: f64,
}

const VIEWS: [View; 4] = [View::Run, View::Many, View::OpenVsClosed, View::Gains];
const DIRECTIONS: [Direction; 3] = [Direction::Auto, Direction::Forward, Direction::Backward];

impl Legacy {
    /// The settings an old link gives, on top of the lesson's `base`
    /// (the schema checks them afterwards).
    pub fn settings(self, base: &Settings) -> Option<Settings> {
        let degrees = |[x, y, theta]: [f64; 3]| [x, y, theta.to_degrees()];
        Some(Settings {
            view: *VIEWS.get(usize::from(self.tab))?,
            start: degrees(self.start),
            goal: degrees(self.goal),
            gains: self.gains,
            direction: *DIRECTIONS.get(usize::from(self.direction))?,
            slip: self.slip,
            push: self.push,
            seed: self.seed,
            control_rate: self.control_rate,
            max_wheel_speed: self.max_wheel_speed,
            plan: self.plan,
            starts: usize::from(self.many_count),
            start_heading: self.many_heading_deg,
            ..base.clone()
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::link;
    use crate::registry::spec as block;

    fn defaults() -> Settings {
        let p = kinolab_schema::validate(&block("controller-playground", &[]))
            .unwrap_or_else(|e| panic!("{e}"));
        p.settings().unwrap_or_else(|e| panic!("{e}"))
    }

    fn legacy() -> Legacy {
        Legacy {
            tab: 2,
            start: [-1.25, 0.5, 0.5],
            goal: [0.3, -0.2, -1.0],
            gains: [2.5, 9.0, -2.0],
            direction: 1,
            slip: 0.1,
            push: 0.05,
            seed: 42,
            control_rate: 20.0,
            max_wheel_speed: 15.0,
            plan: "line 1; arc 0.5 90".into(),
            many_count: 36,
            many_heading_deg: 45.0,
        }
    }

    #[test]
    fn the_first_format_of_links_reads_into_settings() {
        let text = link::encode(&legacy()).unwrap_or_default();
        let back = link::decode::<Legacy>(&text).and_then(|l| l.settings(&defaults()));
        let Some(s) = back else {
            panic!("an old link reads")
        };
        assert_eq!(s.view, View::OpenVsClosed);
        assert_eq!(s.start[2], 0.5_f64.to_degrees());
        assert_eq!(
            (s.direction, s.starts, s.seed),
            (Direction::Forward, 36, 42)
        );
        assert_eq!(link::check("controller-playground", &s), Ok(()));
        let mut bad = legacy();
        bad.direction = 7;
        assert!(bad.settings(&defaults()).is_none());
    }

    #[test]
    fn the_run_file_gives_the_run_the_widget_shows() {
        let mut s = defaults();
        s.slip = 0.1;
        s.control_rate = 50.0;
        let Ok(spec) = spec(&s.run_file()) else {
            panic!("the run file reads")
        };
        assert_eq!(spec.run.output_every, OUTPUT_EVERY);
        assert!(spec.run.noise.is_some() && spec.run.control_rate == Some(50.0));
        let Ok((plan, open, closed)) = s.compare() else {
            panic!("the comparison runs")
        };
        assert!(plan.duration() > 0.0);
        assert_eq!(open.samples.len(), closed.samples.len());
        assert_eq!(s.many().map(|r| r.len()), Ok(s.starts));
    }
}
