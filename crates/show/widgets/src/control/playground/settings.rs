//! What the learner sets in the playground, the runs it gives, and how it
//! travels in a link.

use kinolab_common::angle::wrap;
use kinolab_control::batch::{batch, circle_starts, preview};
use kinolab_control::{
    Direction, Driver, Gains, Limits, Noise, Plan, Pose, Run, Segment, Trajectory,
};
use serde::{Deserialize, Serialize};

use super::{Comparison, TABS, Tab};

/// Everything a learner can change; a change invalidates the cached runs.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Settings {
    pub start: Pose,
    pub goal: Pose,
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
    pub many_count: usize,
    pub many_heading_deg: f64,
}

fn text(e: impl std::fmt::Display) -> String {
    e.to_string()
}

impl Settings {
    pub fn gains(&self) -> Result<Gains, String> {
        Gains::new(self.gains[0], self.gains[1], self.gains[2]).map_err(text)
    }

    fn noise(&self) -> Option<Noise> {
        (self.slip > 0.0 || self.push > 0.0).then_some(Noise {
            seed: self.seed,
            slip: self.slip,
            push_speed: self.push,
            // A push of 0.1 m/s comes with up to 0.2 rad/s of twist.
            push_turn: 2.0 * self.push,
        })
    }

    /// The polar controller from `start` to `goal` with every setting applied.
    fn polar_run(&self, start: Pose, goal: Pose) -> Result<Run, String> {
        let gains = self.gains()?;
        let mut run = Run::polar(start, goal, gains).map_err(text)?;
        run.driver = Driver::Polar {
            gains,
            direction: self.direction,
        };
        run.output_every = 10;
        run.noise = self.noise();
        run.control_rate = (self.control_rate > 0.0).then_some(self.control_rate);
        run.max_wheel_speed = (self.max_wheel_speed > 0.0).then_some(self.max_wheel_speed);
        Ok(run)
    }

    /// One run from start to goal.
    pub fn run(&self) -> Result<Trajectory, String> {
        self.polar_run(self.start, self.goal)?
            .simulate()
            .map_err(text)
    }

    pub fn plan(&self) -> Result<Plan, String> {
        let segments: Vec<Segment> = Segment::parse_list(&self.plan).map_err(text)?;
        Plan::new(self.start, &segments, Limits::default()).map_err(text)
    }

    /// The plan played open loop, and the controller driving to its end,
    /// under the same slip and pushes.
    pub fn compare(&self) -> Result<Comparison, String> {
        let plan = self.plan()?;
        let duration = (plan.duration() + 1.0).max(10.0);
        let mut open = Run::open_loop(plan.clone()).map_err(text)?;
        open.duration = duration;
        open.output_every = 10;
        open.noise = self.noise();
        let mut closed = self.polar_run(self.start, plan.end())?;
        closed.duration = duration;
        let open = open.simulate().map_err(text)?;
        let closed = closed.simulate().map_err(text)?;
        Ok((plan, open, closed))
    }

    /// Quick runs from starts on a 1 m circle around the goal.
    pub fn many(&self) -> Result<Vec<Trajectory>, String> {
        let run = preview(&self.polar_run(self.goal, self.goal)?);
        let starts = circle_starts(
            &self.goal,
            1.0,
            self.many_count,
            self.many_heading_deg.to_radians(),
        )
        .map_err(text)?;
        batch(&run, &starts).map_err(text)
    }
}

/// The settings as a link carries them (angles in radians, the tab by index).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(super) struct LinkState {
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

const DIRECTIONS: [Direction; 3] = [Direction::Auto, Direction::Forward, Direction::Backward];

impl LinkState {
    pub fn of(s: &Settings, tab: Tab) -> Self {
        let pose = |p: &Pose| [p.x, p.y, wrap(p.theta)];
        Self {
            tab: TABS.iter().position(|(t, _, _)| *t == tab).unwrap_or(0) as u8,
            start: pose(&s.start),
            goal: pose(&s.goal),
            gains: s.gains,
            direction: DIRECTIONS
                .iter()
                .position(|d| *d == s.direction)
                .unwrap_or(0) as u8,
            slip: s.slip,
            push: s.push,
            seed: s.seed,
            control_rate: s.control_rate,
            max_wheel_speed: s.max_wheel_speed,
            plan: s.plan.clone(),
            many_count: s.many_count.min(100) as u16,
            many_heading_deg: s.many_heading_deg,
        }
    }

    /// The settings, if every value is one the widget could have made.
    pub fn settings(self) -> Option<(Settings, Tab)> {
        let numbers = [self.start, self.goal, self.gains]
            .iter()
            .flatten()
            .chain([
                &self.slip,
                &self.push,
                &self.control_rate,
                &self.max_wheel_speed,
                &self.many_heading_deg,
            ])
            .all(|v| v.is_finite());
        if !numbers || self.plan.len() > 2000 || Segment::parse_list(&self.plan).is_err() {
            return None;
        }
        let pose = |p: [f64; 3]| Pose::new(p[0].clamp(-5.0, 5.0), p[1].clamp(-5.0, 5.0), p[2]);
        let settings = Settings {
            start: pose(self.start),
            goal: pose(self.goal),
            gains: self.gains.map(|g| g.clamp(-100.0, 100.0)),
            direction: *DIRECTIONS.get(usize::from(self.direction))?,
            slip: self.slip.clamp(0.0, 0.5),
            push: self.push.clamp(0.0, 0.2),
            seed: self.seed,
            control_rate: self.control_rate.clamp(0.0, 1000.0),
            max_wheel_speed: self.max_wheel_speed.clamp(0.0, 100.0),
            plan: self.plan,
            many_count: usize::from(self.many_count).clamp(4, 100),
            many_heading_deg: self.many_heading_deg.clamp(-180.0, 180.0),
        };
        Some((settings, TABS.get(usize::from(self.tab))?.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::link;

    fn sample() -> Settings {
        Settings {
            start: Pose::new(-1.25, 0.5, 0.5),
            goal: Pose::new(0.3, -0.2, -1.0),
            gains: [2.5, 9.0, -2.0],
            direction: Direction::Forward,
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
    fn settings_round_trip_through_the_link() {
        let text = link::encode(&LinkState::of(&sample(), Tab::OpenVsClosed)).unwrap_or_default();
        let back = link::decode::<LinkState>(&text).and_then(LinkState::settings);
        assert_eq!(back, Some((sample(), Tab::OpenVsClosed)));
    }

    #[test]
    fn damaged_or_impossible_states_are_refused() {
        let mut bad = LinkState::of(&sample(), Tab::Run);
        bad.plan = "jump 3".into();
        assert!(bad.clone().settings().is_none());
        bad.plan = "line 1".into();
        bad.gains[0] = f64::NAN;
        assert!(bad.clone().settings().is_none());
        bad.gains[0] = 3.0;
        bad.direction = 7;
        assert!(bad.settings().is_none());
    }
}
