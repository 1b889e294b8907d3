//! Open-loop plans: a path of lines, arcs and turns on the spot, each driven
//! with a trapezoidal speed profile (accelerate, cruise, brake to rest).
//!
//! A plan is a timetable of (v, ω): it says what to command at every
//! instant and where the robot *should* be. Nothing in it looks at where the
//! robot actually is, which is the whole point of the lesson.

use kinolab_common::trig;
use serde::{Deserialize, Serialize};

use crate::error::{FieldError, finite, positive};
use crate::pose::Pose;

/// One piece of path, relative to where the previous one ended.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase", deny_unknown_fields)]
pub enum Segment {
    /// Straight ahead by `length` metres (negative: reverse).
    Line { length: f64 },
    /// Along a circle of `radius` metres through `angle` radians (positive
    /// turns left, negative right).
    Arc { radius: f64, angle: f64 },
    /// Rotate on the spot by `angle` radians (positive: counter-clockwise).
    Turn { angle: f64 },
}

/// Speed and acceleration limits for the profiles.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Limits {
    /// m/s
    pub max_speed: f64,
    /// m/s²
    pub max_accel: f64,
    /// rad/s
    pub max_turn_rate: f64,
    /// rad/s²
    pub max_turn_accel: f64,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            max_speed: 0.5,
            max_accel: 1.0,
            max_turn_rate: std::f64::consts::FRAC_PI_2,
            max_turn_accel: std::f64::consts::PI,
        }
    }
}

/// A trapezoidal profile over a distance: ramp up at `accel`, cruise at
/// `peak`, ramp down; a triangle when the distance is too short to reach
/// the top speed.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Profile {
    pub distance: f64,
    pub peak: f64,
    pub accel: f64,
    /// Duration of each ramp, s.
    pub ramp: f64,
    /// Duration at the peak speed, s.
    pub cruise: f64,
}

impl Profile {
    /// The fastest rest-to-rest profile over `distance` ≥ 0 within the limits.
    pub fn new(distance: f64, max_speed: f64, max_accel: f64) -> Self {
        let full_ramps = max_speed * max_speed / max_accel;
        let (peak, cruise) = if distance >= full_ramps {
            (max_speed, (distance - full_ramps) / max_speed)
        } else {
            ((distance * max_accel).sqrt(), 0.0)
        };
        Self {
            distance,
            peak,
            accel: max_accel,
            ramp: peak / max_accel,
            cruise,
        }
    }

    pub fn duration(&self) -> f64 {
        2.0 * self.ramp + self.cruise
    }

    /// Speed at time `t` into the profile (0 outside it).
    pub fn speed(&self, t: f64) -> f64 {
        if t <= 0.0 || t >= self.duration() {
            0.0
        } else if t < self.ramp {
            self.accel * t
        } else if t <= self.ramp + self.cruise {
            self.peak
        } else {
            self.accel * (self.duration() - t)
        }
    }

    /// Distance covered by time `t`.
    pub fn covered(&self, t: f64) -> f64 {
        let total = self.duration();
        if t <= 0.0 {
            0.0
        } else if t >= total {
            self.distance
        } else if t < self.ramp {
            0.5 * self.accel * t * t
        } else if t <= self.ramp + self.cruise {
            0.5 * self.peak * self.ramp + self.peak * (t - self.ramp)
        } else {
            let left = total - t;
            self.distance - 0.5 * self.accel * left * left
        }
    }
}

/// One segment scheduled in time.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Scheduled {
    pub segment: Segment,
    pub profile: Profile,
    /// When it starts, s.
    pub t0: f64,
    /// Where it starts (nominally), world frame.
    pub from: Pose,
}

/// A whole plan: segments one after another, each from rest to rest.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Plan {
    pub start: Pose,
    pub limits: Limits,
    pub pieces: Vec<Scheduled>,
}

/// The most segments a plan may have.
pub const MAX_SEGMENTS: usize = 64;

impl Segment {
    /// (profile distance, v per unit profile speed, ω per unit profile speed).
    fn scales(&self) -> (f64, f64, f64) {
        match *self {
            Segment::Line { length } => (length.abs(), length.signum(), 0.0),
            Segment::Arc { radius, angle } => (radius * angle.abs(), 1.0, angle.signum() / radius),
            Segment::Turn { angle } => (angle.abs(), 0.0, angle.signum()),
        }
    }

    /// The pose after covering `s` of this segment's profile distance.
    fn advance(&self, from: &Pose, s: f64) -> Pose {
        let (_, v, w) = self.scales();
        let turn = w * s;
        let along = v * s;
        // The exact arc (a line when turn = 0), with a sinc form near 0.
        let half = turn / 2.0;
        let sinc = if half.abs() < 1e-6 {
            1.0 - half * half / 6.0
        } else {
            trig::sin(half) / half
        };
        let (sm, cm) = trig::sin_cos(from.theta + half);
        Pose::new(
            from.x + along * sinc * cm,
            from.y + along * sinc * sm,
            from.theta + turn,
        )
    }

    fn check(&self, i: usize) -> Result<(), FieldError> {
        let field = |name: &str| format!("segments[{i}].{name}");
        match *self {
            Segment::Line { length } => {
                finite(field("length"), length)?;
            }
            Segment::Arc { radius, angle } => {
                positive(field("radius"), radius)?;
                finite(field("angle"), angle)?;
            }
            Segment::Turn { angle } => {
                finite(field("angle"), angle)?;
            }
        }
        Ok(())
    }
}

impl Segment {
    /// Segments written the short way people type them:
    /// `line 1; arc 0.5 90; turn -90` (metres and degrees; a negative
    /// length drives backwards, a negative angle turns right).
    pub fn parse_list(text: &str) -> Result<Vec<Segment>, FieldError> {
        let mut out = Vec::new();
        for (i, part) in text
            .split(';')
            .map(str::trim)
            .filter(|p| !p.is_empty())
            .enumerate()
        {
            out.push(Self::parse_one(part).ok_or_else(|| {
                FieldError::new(
                    format!("segments[{i}]"),
                    format!(
                        "`{part}`: write `line METRES`, `arc RADIUS DEGREES` (radius > 0) or `turn DEGREES`"
                    ),
                )
            })?);
        }
        if out.is_empty() {
            return Err(FieldError::new(
                "segments",
                "the plan is empty: add a segment such as `line 1`",
            ));
        }
        if out.len() > MAX_SEGMENTS {
            return Err(FieldError::new(
                "segments",
                format!("at most {MAX_SEGMENTS} segments, got {}", out.len()),
            ));
        }
        Ok(out)
    }

    fn parse_one(part: &str) -> Option<Segment> {
        let mut words = part.split_whitespace();
        let kind = words.next()?;
        let nums: Vec<f64> = words
            .map(|w| w.parse::<f64>().ok().filter(|x| x.is_finite()))
            .collect::<Option<_>>()?;
        match (kind, nums.as_slice()) {
            ("line", [length]) => Some(Segment::Line { length: *length }),
            ("arc", [radius, deg]) if *radius > 0.0 => Some(Segment::Arc {
                radius: *radius,
                angle: deg.to_radians(),
            }),
            ("turn", [deg]) => Some(Segment::Turn {
                angle: deg.to_radians(),
            }),
            _ => None,
        }
    }
}

impl Limits {
    fn check(&self) -> Result<(), FieldError> {
        positive("limits.max_speed", self.max_speed)?;
        positive("limits.max_accel", self.max_accel)?;
        positive("limits.max_turn_rate", self.max_turn_rate)?;
        positive("limits.max_turn_accel", self.max_turn_accel)?;
        Ok(())
    }
}

impl Plan {
    /// Schedule `segments` from `start` within `limits`.
    pub fn new(start: Pose, segments: &[Segment], limits: Limits) -> Result<Self, FieldError> {
        limits.check()?;
        for (name, v) in [
            ("start.x", start.x),
            ("start.y", start.y),
            ("start.theta", start.theta),
        ] {
            finite(name, v)?;
        }
        if segments.len() > MAX_SEGMENTS {
            return Err(FieldError::new(
                "segments",
                format!("at most {MAX_SEGMENTS} segments, got {}", segments.len()),
            ));
        }
        let mut pieces = Vec::with_capacity(segments.len());
        let (mut t0, mut from) = (0.0, start);
        for (i, segment) in segments.iter().enumerate() {
            segment.check(i)?;
            let (distance, v, w) = segment.scales();
            // The profile variable is distance along the path (or angle for a
            // turn); its limits are whichever of v and ω binds first.
            let bound = |linear: f64, angular: f64| match (v != 0.0, w != 0.0) {
                (true, true) => linear.min(angular / w.abs()),
                (true, false) => linear,
                _ => angular,
            };
            let profile = Profile::new(
                distance,
                bound(limits.max_speed, limits.max_turn_rate),
                bound(limits.max_accel, limits.max_turn_accel),
            );
            pieces.push(Scheduled {
                segment: *segment,
                profile,
                t0,
                from,
            });
            t0 += profile.duration();
            from = segment.advance(&from, distance);
        }
        Ok(Self {
            start,
            limits,
            pieces,
        })
    }

    /// Total time, s.
    pub fn duration(&self) -> f64 {
        self.pieces
            .last()
            .map_or(0.0, |p| p.t0 + p.profile.duration())
    }

    /// Where the plan ends, world frame.
    pub fn end(&self) -> Pose {
        self.pieces.last().map_or(self.start, |p| {
            p.segment.advance(&p.from, p.profile.distance)
        })
    }

    fn piece_at(&self, t: f64) -> Option<&Scheduled> {
        let i = self.pieces.partition_point(|p| p.t0 <= t);
        i.checked_sub(1).and_then(|i| self.pieces.get(i))
    }

    /// The commanded (v, ω) at time `t` (zero before and after the plan).
    #[inline]
    pub fn command(&self, t: f64) -> (f64, f64) {
        match self.piece_at(t) {
            Some(p) => {
                let (_, v, w) = p.segment.scales();
                let speed = p.profile.speed(t - p.t0);
                (v * speed, w * speed)
            }
            None => (0.0, 0.0),
        }
    }

    /// Where the robot should be at time `t` if nothing slipped.
    pub fn nominal(&self, t: f64) -> Pose {
        match self.piece_at(t) {
            Some(p) => p.segment.advance(&p.from, p.profile.covered(t - p.t0)),
            None => self.start,
        }
    }
}

impl Plan {
    /// What each wheel of `chassis` must do at time `t` to follow the plan:
    /// the robot's inverse kinematics for the twist (v, 0, ω).
    pub fn wheel_commands(
        &self,
        chassis: &kinolab_wheels::Chassis,
        t: f64,
    ) -> Result<kinolab_wheels::InverseSolution, kinolab_common::FieldError> {
        let (v, omega) = self.command(t);
        chassis.inverse(kinolab_wheels::Vector3::new(v, 0.0, omega))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{FRAC_PI_2, PI};

    #[test]
    fn short_plans_parse_and_name_the_bad_segment() {
        let segs = Segment::parse_list("line 1; arc 0.5 90;turn -45 ").unwrap_or_default();
        assert_eq!(
            segs,
            vec![
                Segment::Line { length: 1.0 },
                Segment::Arc {
                    radius: 0.5,
                    angle: FRAC_PI_2
                },
                Segment::Turn { angle: -PI / 4.0 }
            ]
        );
        let e = Segment::parse_list("line 1; arc -0.5 90").unwrap_err();
        assert_eq!(e.field, "segments[1]");
        assert!(e.message.starts_with("`arc -0.5 90`"), "{e}");
        assert!(Segment::parse_list("jump 3").is_err());
        assert!(Segment::parse_list("line").is_err());
        assert_eq!(Segment::parse_list(" ; ").unwrap_err().field, "segments");
        let long = vec!["line 1"; MAX_SEGMENTS + 1].join(";");
        assert!(Segment::parse_list(&long).is_err());
    }

    #[test]
    fn trapezoid_and_triangle() {
        // 2 m at ≤ 0.5 m/s, 1 m/s²: ramps of 0.5 s covering 0.25 m in all,
        // cruise 1.75 m in 3.5 s.
        let p = Profile::new(2.0, 0.5, 1.0);
        assert!((p.duration() - 4.5).abs() < 1e-12);
        assert!((p.covered(p.duration()) - 2.0).abs() < 1e-12);
        assert!(
            (p.covered(2.25) - 1.0).abs() < 1e-12,
            "half way at half time"
        );
        assert_eq!(p.speed(1.0), 0.5);
        // 0.16 m is too short to reach 0.5 m/s: peak √(0.16·1) = 0.4.
        let t = Profile::new(0.16, 0.5, 1.0);
        assert!((t.peak - 0.4).abs() < 1e-12 && t.cruise == 0.0);
        assert!((t.duration() - 0.8).abs() < 1e-12);
        assert!((t.covered(0.4) - 0.08).abs() < 1e-12);
    }

    #[test]
    fn a_square_closes_on_itself() {
        let mut segs = Vec::new();
        for _ in 0..4 {
            segs.push(Segment::Line { length: 1.0 });
            segs.push(Segment::Turn { angle: FRAC_PI_2 });
        }
        let plan =
            Plan::new(Pose::default(), &segs, Limits::default()).unwrap_or_else(|e| panic!("{e}"));
        let end = plan.end();
        assert!(end.x.abs() < 1e-12 && end.y.abs() < 1e-12);
        assert!((end.theta - 2.0 * PI).abs() < 1e-12);
        // Each line: 1 m at 0.5 m/s, 1 m/s² → 2.5 s; each turn: π/2 at π/2
        // rad/s, π rad/s² → 1.5 s.
        assert!((plan.duration() - 16.0).abs() < 1e-12);
    }

    #[test]
    fn an_arc_respects_the_turn_rate_and_ends_on_the_circle() {
        // Radius 2: ω = v/2 ≤ π/2 never binds below 0.5 m/s; radius 0.1 it does.
        let limits = Limits::default();
        let wide = Plan::new(
            Pose::default(),
            &[Segment::Arc {
                radius: 2.0,
                angle: PI,
            }],
            limits,
        )
        .unwrap_or_else(|e| panic!("{e}"));
        assert!((wide.pieces[0].profile.peak - 0.5).abs() < 1e-12);
        let end = wide.end();
        assert!(
            end.x.abs() < 1e-12 && (end.y - 4.0).abs() < 1e-12 && (end.theta - PI).abs() < 1e-12
        );
        let tight = Plan::new(
            Pose::default(),
            &[Segment::Arc {
                radius: 0.1,
                angle: -PI,
            }],
            limits,
        )
        .unwrap_or_else(|e| panic!("{e}"));
        let peak = tight.pieces[0].profile.peak;
        assert!((peak - 0.1 * FRAC_PI_2).abs() < 1e-12);
        let mid = tight.pieces[0].profile.duration() / 2.0;
        let (v, w) = tight.command(mid);
        assert!((w + v / 0.1).abs() < 1e-12, "ω = −v/R on a right turn");
        assert!((tight.end().y + 0.2).abs() < 1e-12);
    }

    #[test]
    fn nominal_pose_is_the_integral_of_the_commands() {
        let plan = Plan::new(
            Pose::new(0.5, -0.2, 0.3),
            &[
                Segment::Line { length: 0.6 },
                Segment::Arc {
                    radius: 0.4,
                    angle: 1.2,
                },
                Segment::Line { length: -0.3 },
            ],
            Limits::default(),
        )
        .unwrap_or_else(|e| panic!("{e}"));
        // Midpoint-rule integration of (v, ω) lands on the nominal pose.
        let dt = 1e-4;
        let mut p = plan.start;
        let steps = (plan.duration() / dt).ceil() as usize;
        for k in 0..steps {
            let t = (k as f64 + 0.5) * dt;
            let (v, w) = plan.command(t);
            let mid = p.theta + w * dt / 2.0;
            p = Pose::new(
                p.x + v * dt * mid.cos(),
                p.y + v * dt * mid.sin(),
                p.theta + w * dt,
            );
        }
        let end = plan.end();
        assert!(
            p.distance(&end) < 1e-6 && (p.theta - end.theta).abs() < 1e-6,
            "{p:?} vs {end:?}"
        );
    }

    #[test]
    fn bad_segments_name_their_field() {
        let e = Plan::new(
            Pose::default(),
            &[
                Segment::Line { length: 1.0 },
                Segment::Arc {
                    radius: -1.0,
                    angle: 1.0,
                },
            ],
            Limits::default(),
        );
        assert!(e.is_err_and(|e| e.field == "segments[1].radius"));
        let limits = Limits {
            max_accel: 0.0,
            ..Limits::default()
        };
        assert!(
            Plan::new(Pose::default(), &[], limits).is_err_and(|e| e.field == "limits.max_accel")
        );
    }
}
