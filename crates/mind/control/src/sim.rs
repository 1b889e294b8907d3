//! The simulator: a unicycle (differential-drive) robot under a driver —
//! the polar controller or an open-loop plan — integrated with classic
//! fourth-order Runge–Kutta.
//!
//! The controller is part of the dynamics: it is evaluated at every RK4
//! stage, so the closed loop is integrated as one continuous system and the
//! error shrinks like dt⁴ (halving dt = 1e-3 moves no sample by more than
//! 1e-6; a test checks it). In sampled-data mode the controller instead
//! runs at a fixed rate and its command is held in between, like a real
//! control loop.
//!
//! Everything is integrated in the goal's frame (the controller's natural
//! one) and turned back into world coordinates for the samples.

use kinolab_common::trig;
use kinolab_wheels::{Chassis, Vector3, WheelKind};
use serde::Serialize;

use crate::error::{FieldError, finite, positive};
use crate::noise::{NOISE_INTERVAL, Noise};
use crate::plan::Plan;
use crate::polar::{Direction, Gains, Polar};
use kinolab_common::angle::{wrap, wrap_near};

use crate::law::{self, Law, LawCall};
use crate::pose::Pose;

/// What decides (v, ω).
#[derive(Debug, Clone, PartialEq)]
pub enum Driver {
    /// The polar go-to-pose controller, closed loop.
    Polar { gains: Gains, direction: Direction },
    /// A timetable of commands, open loop.
    OpenLoop(Plan),
    /// A learner's law, run at the control rate.
    Script(Law),
}

/// When the goal counts as reached.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Tolerance {
    /// m
    pub position: f64,
    /// rad
    pub heading: f64,
}

impl Default for Tolerance {
    /// 1 mm and 0.1°.
    fn default() -> Self {
        Self {
            position: 1e-3,
            heading: 0.1f64.to_radians(),
        }
    }
}

/// How (v, ω) becomes wheel spins, for saturation, slip and the peak wheel
/// speed: spin_i = a_i v + b_i ω for each driven (fixed or Swedish) wheel.
#[derive(Debug, Clone, PartialEq)]
pub struct DriveModel {
    pub robot: String,
    /// Index in the robot's wheel list of each driven wheel.
    pub driven: Vec<usize>,
    /// (a_i, b_i) per driven wheel, rad/s per m/s and per rad/s.
    pub gains: Vec<[f64; 2]>,
}

impl DriveModel {
    /// The drive of a robot that moves like a unicycle: driving straight
    /// and turning on the spot must both be admissible, and the motors are
    /// its fixed and Swedish wheels (castors and spheres just follow).
    pub fn new(chassis: &Chassis) -> Result<Self, FieldError> {
        let name = chassis.name().to_string();
        if let Some(i) = chassis
            .wheels()
            .iter()
            .position(|w| w.kind == WheelKind::Steered)
        {
            return Err(FieldError::new(
                format!("robot.wheels[{i}]"),
                format!(
                    "`{name}` has a steered wheel; the unicycle simulation needs a robot driven by fixed or Swedish wheels, such as differential-drive"
                ),
            ));
        }
        let straight = chassis.inverse(Vector3::new(1.0, 0.0, 0.0))?;
        let spin = chassis.inverse(Vector3::new(0.0, 0.0, 1.0))?;
        if !straight.feasible || !spin.feasible {
            return Err(FieldError::new(
                "robot",
                format!(
                    "`{name}` cannot both drive straight ahead and turn on the spot, as the unicycle model needs"
                ),
            ));
        }
        let driven: Vec<usize> = chassis
            .wheels()
            .iter()
            .enumerate()
            .filter(|(_, w)| matches!(w.kind, WheelKind::Fixed | WheelKind::Swedish { .. }))
            .map(|(i, _)| i)
            .collect();
        if driven.is_empty() {
            return Err(FieldError::new(
                "robot",
                format!("`{name}` has no driven (fixed or Swedish) wheel"),
            ));
        }
        let gains: Vec<[f64; 2]> = driven
            .iter()
            .map(|&i| [straight.wheels[i].spin, spin.wheels[i].spin])
            .collect();
        Ok(Self {
            robot: name,
            driven,
            gains,
        })
    }

    /// The largest |spin| of the driven wheels for (v, ω), rad/s.
    #[inline]
    pub fn peak(&self, v: f64, omega: f64) -> f64 {
        self.gains
            .iter()
            .fold(0.0, |m: f64, [a, b]| m.max((a * v + b * omega).abs()))
    }

    /// Scale (v, ω) down together, keeping the path's curvature, until no
    /// wheel spins faster than `max`.
    #[inline]
    pub fn saturate(&self, v: f64, omega: f64, max: f64) -> (f64, f64) {
        let peak = self.peak(v, omega);
        if peak > max {
            let k = max / peak;
            (v * k, omega * k)
        } else {
            (v, omega)
        }
    }
}

/// One simulation: who drives, from where to where, and how it is integrated.
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    pub start: Pose,
    pub goal: Pose,
    pub driver: Driver,
    /// Integration step, s.
    pub dt: f64,
    /// Simulated time, s.
    pub duration: f64,
    /// Keep every n-th step as a sample.
    pub output_every: usize,
    pub drive: DriveModel,
    /// Wheel-speed limit, rad/s.
    pub max_wheel_speed: Option<f64>,
    /// Sampled-data controller rate, Hz (`None`: evaluated continuously).
    pub control_rate: Option<f64>,
    pub noise: Option<Noise>,
    pub tolerance: Tolerance,
}

/// Most integration steps one run may take (about a second of computing).
pub const MAX_STEPS: usize = 5_000_000;
/// Most samples one run may return.
pub const MAX_SAMPLES: usize = 200_000;

/// The robot at one moment.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Sample {
    pub t: f64,
    /// World frame.
    pub pose: Pose,
    /// Commanded speed, m/s, and turn rate, rad/s (after saturation).
    pub v: f64,
    pub omega: f64,
    /// The goal as the robot sees it (forward angles, or backward ones when
    /// the controller drives rear first).
    pub polar: Polar,
    /// Fastest driven wheel, rad/s.
    pub wheel_speed: f64,
}

/// A finished run and its metrics.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Trajectory {
    pub samples: Vec<Sample>,
    /// Within the tolerance of the goal at the end, having settled there.
    pub reached: bool,
    /// When it entered the tolerance for the last time (and stayed), s.
    pub time_to_goal: Option<f64>,
    pub final_pose: Pose,
    /// Distance from the goal at the end, m.
    pub final_position_error: f64,
    /// Heading error at the end, rad, (−π, π].
    pub final_heading_error: f64,
    /// Distance driven, m.
    pub path_length: f64,
    /// Fastest any driven wheel turned, rad/s.
    pub peak_wheel_speed: f64,
    /// Whether the controller drove rear first.
    pub backward: bool,
    /// Set when the run was stopped because its state ran away.
    pub diverged: Option<Divergence>,
    /// A learner's law: every call, and the error that stopped the run.
    #[serde(skip)]
    pub calls: Vec<LawCall>,
    #[serde(skip)]
    pub error: Option<kinolab_script::ScriptError>,
}

/// A run stopped early because it ran away: unstable gains, or a time step
/// too coarse for them.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Divergence {
    /// When it was stopped, s.
    pub t: f64,
    /// Why, in words.
    pub reason: String,
}

/// A closed-loop run has run away once it is farther than this from the
/// goal, m, or ten times as far as it started, whichever is farther. (An
/// open-loop plan cannot run away: it only stops being finite.)
pub const RUNAWAY_DISTANCE: f64 = 100.0;

/// How far from the goal a closed-loop run starting `start_distance` away
/// may go before it counts as run away; `None` for an open-loop run.
fn runaway_bound(driver: &Driver, start_distance: f64) -> Option<f64> {
    match driver {
        Driver::Polar { .. } | Driver::Script(_) => {
            Some(RUNAWAY_DISTANCE.max(10.0 * start_distance))
        }
        Driver::OpenLoop(_) => None,
    }
}

/// Why the step from `t` to state `next` (wheels at `wheel_speed`) means
/// the run has run away, if it does.
fn runaway(next: &[f64; 3], wheel_speed: f64, t: f64, bound: Option<f64>) -> Option<Divergence> {
    let distance = next[0].hypot(next[1]);
    let what = if !(next.iter().all(|v| v.is_finite()) && wheel_speed.is_finite()) {
        "the state stopped being a finite number".to_owned()
    } else if let Some(bound) = bound.filter(|b| distance > *b) {
        format!("the distance to the goal grew past {bound:.0} m")
    } else {
        return None;
    };
    Some(Divergence {
        t,
        reason: format!(
            "diverged after {t:.2} s: {what}; the loop is unstable with these gains, \
             or dt is too large for them"
        ),
    })
}

impl Run {
    /// The polar controller with the contract's defaults: dt = 1 ms, 10 s,
    /// a sample every 100 steps, the catalogue's differential drive.
    pub fn polar(start: Pose, goal: Pose, gains: Gains) -> Result<Self, FieldError> {
        Ok(Self {
            start,
            goal,
            driver: Driver::Polar {
                gains,
                direction: Direction::Auto,
            },
            dt: 1e-3,
            duration: 10.0,
            output_every: 100,
            drive: default_drive()?,
            max_wheel_speed: None,
            control_rate: None,
            noise: None,
            tolerance: Tolerance::default(),
        })
    }

    /// An open-loop run of `plan`; the goal is where the plan ends.
    pub fn open_loop(plan: Plan) -> Result<Self, FieldError> {
        let goal = plan.end();
        let start = plan.start;
        let duration = (plan.duration() + 1.0).max(1.0);
        Ok(Self {
            driver: Driver::OpenLoop(plan),
            duration,
            ..Self::polar(start, goal, crate::polar::TEXTBOOK_GAINS)?
        })
    }

    /// Check the run; its number of steps.
    pub(crate) fn check(&self) -> Result<usize, FieldError> {
        for (field, pose) in [("start", &self.start), ("goal", &self.goal)] {
            let named = |name: &str| format!("{field}.{name}");
            finite(named("x"), pose.x)?;
            finite(named("y"), pose.y)?;
            finite(named("theta_deg"), pose.theta.to_degrees())?;
        }
        positive("dt", self.dt)?;
        positive("duration", self.duration)?;
        if self.output_every == 0 {
            return Err(FieldError::new("output_every", "must be at least 1"));
        }
        let steps = (self.duration / self.dt - 1e-9).ceil().max(1.0);
        if steps > MAX_STEPS as f64 {
            return Err(FieldError::new(
                "dt",
                format!(
                    "duration / dt = {steps:.0} steps; at most {MAX_STEPS} (raise dt or shorten the run)"
                ),
            ));
        }
        let steps = steps as usize;
        if steps / self.output_every > MAX_SAMPLES {
            return Err(FieldError::new(
                "output_every",
                format!(
                    "would keep {} samples; at most {MAX_SAMPLES}",
                    steps / self.output_every
                ),
            ));
        }
        if let Some(max) = self.max_wheel_speed {
            positive("max_wheel_speed", max)?;
        }
        if let Some(rate) = self.control_rate {
            positive("control_rate", rate)?;
            if 1.0 / rate < self.dt * (1.0 - 1e-9) {
                return Err(FieldError::new(
                    "control_rate",
                    format!(
                        "{rate} Hz is faster than the integration step (1/dt = {} Hz)",
                        1.0 / self.dt
                    ),
                ));
            }
        }
        if let Driver::Polar { gains, .. } = &self.driver {
            Gains::new(gains.k_rho, gains.k_alpha, gains.k_beta)
                .map_err(|e| FieldError::new(format!("controller.{}", e.field), e.message))?;
        }
        if let Some(noise) = &self.noise {
            noise.check()?;
        }
        Ok(steps)
    }

    /// Integrate the run.
    pub fn simulate(&self) -> Result<Trajectory, FieldError> {
        let steps = self.check()?;
        let start = self.start.relative_to(&self.goal);
        let direction = match &self.driver {
            Driver::Polar { direction, .. } => Some(*direction),
            Driver::Script(law) => Some(law.direction),
            Driver::OpenLoop(_) => None,
        };
        let backward = match direction {
            Some(Direction::Auto) => !Polar::forward(&start).goal_in_front(),
            Some(Direction::Backward) => true,
            Some(Direction::Forward) | None => false,
        };
        let mut system = System {
            run: self,
            backward,
            held: None,
            slip: [0.0; 2],
            push: [0.0; 3],
            disturbed: self.noise.is_some(),
            law: match &self.driver {
                Driver::Script(law) => Some(law.script.clone()),
                _ => None,
            },
            calls: Vec::new(),
            error: None,
        };
        let (sg, cg) = trig::sin_cos(self.goal.theta);
        let control_every = self
            .control_rate()
            .map(|rate| ((1.0 / rate) / self.dt).round().max(1.0) as usize);

        let mut s = [start.x, start.y, wrap(start.theta)];
        let mut samples = Vec::with_capacity(steps / self.output_every + 2);
        let mut time_to_goal = None;
        let mut path_length = 0.0;
        let mut peak_wheel_speed: f64 = 0.0;
        let mut noise_interval = u64::MAX;
        let mut diverged = None;
        let bound = runaway_bound(&self.driver, start.x.hypot(start.y));
        for k in 0..=steps {
            let t = (k as f64 * self.dt).min(self.duration);
            // Reached means arrived and stayed: the time it last entered
            // the tolerance, if it is still inside at the end.
            if !self.within_tolerance(&s) {
                time_to_goal = None;
            } else if time_to_goal.is_none() {
                time_to_goal = Some(t);
            }
            if let Some(noise) = &self.noise {
                let interval = (t / NOISE_INTERVAL) as u64;
                if interval != noise_interval {
                    noise_interval = interval;
                    system.slip = noise.slip_of(interval);
                    let [px, py, pw] = noise.push(interval);
                    // World push seen in the goal frame.
                    system.push = [cg * px + sg * py, -sg * px + cg * py, pw];
                }
            }
            if let Some(every) = control_every
                && k % every == 0
            {
                // A controller tick: compute afresh, then hold.
                system.held = None;
                system.held = Some(system.tick(&s, t));
                if system.error.is_some() {
                    break;
                }
            }
            let (v, omega) = system.command(&s, t);
            let wheel_speed = self.drive.peak(v, omega);
            peak_wheel_speed = peak_wheel_speed.max(wheel_speed);
            if k % self.output_every == 0 || k == steps {
                samples.push(Sample {
                    t,
                    pose: Pose::new(s[0], s[1], s[2]).from_frame(&self.goal),
                    v,
                    omega,
                    polar: system.polar(&s),
                    wheel_speed,
                });
            }
            if k == steps {
                break;
            }
            let h = (self.duration - t).min(self.dt);
            // The command at the step's start is the first stage's: reuse it.
            let next = system.rk4(&s, t, h, (v, omega));
            diverged = runaway(&next, wheel_speed, t + h, bound);
            if diverged.is_some() {
                break;
            }
            let (dx, dy) = (next[0] - s[0], next[1] - s[1]);
            path_length += (dx * dx + dy * dy).sqrt();
            s = [next[0], next[1], wrap_near(next[2])];
        }
        let final_pose = Pose::new(s[0], s[1], s[2]).from_frame(&self.goal);
        Ok(Trajectory {
            samples,
            reached: time_to_goal.is_some(),
            time_to_goal,
            final_pose,
            final_position_error: s[0].hypot(s[1]),
            final_heading_error: wrap(s[2]),
            path_length,
            peak_wheel_speed,
            backward,
            diverged,
            calls: system.calls,
            error: system.error,
        })
    }

    /// The rate the controller runs at: the run's, or a script's default.
    fn control_rate(&self) -> Option<f64> {
        match (&self.driver, self.control_rate) {
            (Driver::Script(_), None) => Some(law::DEFAULT_RATE.min(1.0 / self.dt)),
            (_, rate) => rate,
        }
    }

    fn within_tolerance(&self, s: &[f64; 3]) -> bool {
        // θ stays wrapped between steps, so the cheap wrap is enough.
        s[0] * s[0] + s[1] * s[1] <= self.tolerance.position * self.tolerance.position
            && wrap_near(s[2]).abs() <= self.tolerance.heading
    }
}

fn default_drive() -> Result<DriveModel, FieldError> {
    DriveModel::new(&kinolab_wheels::catalogue::robot("differential-drive")?)
}

/// The closed (or open) loop as a right-hand side for the integrator.
struct System<'a> {
    run: &'a Run,
    backward: bool,
    /// The sampled-data controller's held command.
    held: Option<(f64, f64)>,
    /// This noise interval's slip (of v, of ω) and push (goal frame).
    slip: [f64; 2],
    push: [f64; 3],
    /// Whether the run has noise (slip and push), or both stay zero.
    disturbed: bool,
    /// A learner's law (with its notes), its calls, and what stopped it.
    law: Option<kinolab_script::Script>,
    calls: Vec<LawCall>,
    error: Option<kinolab_script::ScriptError>,
}

impl System<'_> {
    #[inline(always)]
    fn polar(&self, s: &[f64; 3]) -> Polar {
        Polar::near(s[0], s[1], s[2], self.backward)
    }

    /// A controller tick: the command in state `s` at `t`, calling a
    /// learner's law (and keeping the call) when there is one.
    fn tick(&mut self, s: &[f64; 3], t: f64) -> (f64, f64) {
        let Some(script) = self.law.as_mut() else {
            return self.command(s, t);
        };
        match law::command(script, &Polar::near(s[0], s[1], s[2], self.backward), t) {
            Ok(call) => {
                let command = self.saturated(call.v, call.omega);
                self.calls.push(call);
                command
            }
            Err(e) => {
                self.error = Some(e);
                (0.0, 0.0)
            }
        }
    }

    /// (v, ω) within the wheels' limit, when the run sets one.
    #[inline(always)]
    fn saturated(&self, v: f64, omega: f64) -> (f64, f64) {
        match self.run.max_wheel_speed {
            Some(max) => self.run.drive.saturate(v, omega, max),
            None => (v, omega),
        }
    }

    /// The commanded (v, ω) in state `s` at time `t`, after saturation.
    #[inline(always)]
    fn command(&self, s: &[f64; 3], t: f64) -> (f64, f64) {
        if let Some(held) = self.held {
            return held;
        }
        let (v, omega) = match &self.run.driver {
            Driver::Polar { gains, .. } => gains.command(&self.polar(s)),
            Driver::OpenLoop(plan) => plan.command(t),
            // Only ever held: the law runs at its ticks.
            Driver::Script(_) => (0.0, 0.0),
        };
        self.saturated(v, omega)
    }

    /// d/dt of the unicycle's state z = (x, y, θ, cos θ, sin θ), with slip
    /// and push. Carrying cos θ and sin θ along (ċ = −θ̇ sin θ,
    /// ṡ = θ̇ cos θ) spares a sine and a cosine at every stage.
    #[inline]
    fn rate(&self, z: &[f64; 5], t: f64) -> [f64; 5] {
        self.rate_with(z, self.command(&[z[0], z[1], z[2]], t))
    }

    /// [`System::rate`] for an already computed command.
    #[inline]
    fn rate_with(&self, z: &[f64; 5], (v, omega): (f64, f64)) -> [f64; 5] {
        if !self.disturbed {
            // Without noise: the same numbers, four operations shorter.
            return [v * z[3], v * z[4], omega, -omega * z[4], omega * z[3]];
        }
        let (v, omega) = (v * (1.0 - self.slip[0]), omega * (1.0 - self.slip[1]));
        let turn = omega + self.push[2];
        [
            v * z[3] + self.push[0],
            v * z[4] + self.push[1],
            turn,
            -turn * z[4],
            turn * z[3],
        ]
    }

    /// One classic Runge–Kutta step of length h from pose `s` (x, y, θ),
    /// where the command is `first`. The cosine and sine start exact from θ
    /// at every step, so they never drift; the step stays fourth-order.
    #[inline]
    fn rk4(&self, s: &[f64; 3], t: f64, h: f64, first: (f64, f64)) -> [f64; 3] {
        let (sn, cs) = trig::sin_cos(s[2]);
        let z = [s[0], s[1], s[2], cs, sn];
        let at = |k: &[f64; 5], f: f64| -> [f64; 5] { std::array::from_fn(|i| z[i] + f * k[i]) };
        let k1 = self.rate_with(&z, first);
        let k2 = self.rate(&at(&k1, h / 2.0), t + h / 2.0);
        let k3 = self.rate(&at(&k2, h / 2.0), t + h / 2.0);
        let k4 = self.rate(&at(&k3, h), t + h);
        std::array::from_fn(|i| z[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
    }
}
