//! The behaviour library. Each behaviour has a releaser (when it is
//! active) and maps percepts, and any state it keeps, to a [`Response`].
//! Vectors are in the robot's frame: x ahead, y to the left; their length
//! is a speed in m/s.

use kinolab_common::angle::wrap;
use kinolab_common::random::unit_hash;
use kinolab_common::trig;
use kinolab_world::sensors::Percepts;
use serde::{Deserialize, Serialize};

use crate::braitenberg::Wiring;
use crate::script::ScriptCall;
use crate::{FieldError, Response, Vec2};

/// Which side a wall is followed on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Side {
    Left,
    Right,
}

impl Side {
    /// +1 for left, −1 for right.
    pub fn sign(self) -> f64 {
        match self {
            Side::Left => 1.0,
            Side::Right => -1.0,
        }
    }
}

/// A behaviour and its parameters, as run files write it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Behaviour {
    /// When something ahead is nearer than `range`: towards the most open
    /// direction, slower the nearer; back off when a bumper is pressed.
    Avoid { range: f64, gain: f64 },
    /// Towards the goal, slowing within `slow_within` of it.
    GoToGoal {
        gain: f64,
        #[serde(default = "default_slow")]
        slow_within: f64,
    },
    /// A heading that changes by up to `turn_deg` every `every` seconds.
    Wander {
        gain: f64,
        #[serde(default = "default_turn")]
        turn_deg: f64,
        #[serde(default = "default_every")]
        every: f64,
        #[serde(default)]
        seed: u64,
    },
    /// Along a wall on one `side`, `distance` from it.
    FollowWall {
        side: Side,
        distance: f64,
        gain: f64,
    },
    /// Along a corridor, midway between its walls (up to `width` apart).
    Corridor { width: f64, gain: f64 },
    /// Towards the brighter side.
    SeekLight {
        gain: f64,
        #[serde(default = "default_threshold")]
        threshold: f64,
    },
    /// Away from the light.
    Flee {
        gain: f64,
        #[serde(default = "default_threshold")]
        threshold: f64,
    },
    /// Within `within` of the goal: creep in and stop on it.
    Dock { within: f64, speed: f64 },
    /// Light sensors wired to the wheels.
    Braitenberg(Wiring),
    /// A learner's behaviour: `behave(p)` (see [`crate::script`]).
    Script { source: String },
}

fn default_slow() -> f64 {
    0.5
}
fn default_turn() -> f64 {
    60.0
}
fn default_every() -> f64 {
    2.0
}
fn default_threshold() -> f64 {
    0.01
}

/// A behaviour with the name coordinators and timelines know it by, and
/// the state it keeps between steps.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Named {
    pub name: String,
    #[serde(flatten)]
    pub behaviour: Behaviour,
    /// Wander's interval and heading (odometry frame, rad).
    #[serde(skip)]
    wander: Option<(u64, f64)>,
    /// A script behaviour compiled (with its notes), what its last call
    /// returned and printed, and the error that stopped it.
    #[serde(skip)]
    script: Option<kinolab_script::Script>,
    #[serde(skip)]
    pub call: Option<ScriptCall>,
    #[serde(skip)]
    pub failed: Option<kinolab_script::ScriptError>,
}

/// Closer than this to the goal, going to it is done, m.
pub const AT_GOAL: f64 = 0.05;

impl Named {
    pub fn new(name: impl Into<String>, behaviour: Behaviour) -> Self {
        Self {
            name: name.into(),
            behaviour,
            wander: None,
            script: None,
            call: None,
            failed: None,
        }
    }

    /// Check the parameters; errors name the field.
    pub fn check(&self) -> Result<(), FieldError> {
        use kinolab_common::error::{in_range, non_negative, positive};
        if self.name.trim().is_empty() {
            return Err(FieldError::new("name", "every behaviour needs a name"));
        }
        match &self.behaviour {
            Behaviour::Avoid { range, gain } => {
                positive("range", *range)?;
                non_negative("gain", *gain)?;
            }
            Behaviour::GoToGoal { gain, slow_within } => {
                non_negative("gain", *gain)?;
                positive("slow_within", *slow_within)?;
            }
            Behaviour::Wander {
                gain,
                turn_deg,
                every,
                ..
            } => {
                non_negative("gain", *gain)?;
                in_range("turn_deg", *turn_deg, 0.0, 180.0)?;
                in_range("every", *every, 0.05, 3600.0)?;
            }
            Behaviour::FollowWall { distance, gain, .. } => {
                positive("distance", *distance)?;
                non_negative("gain", *gain)?;
            }
            Behaviour::Corridor { width, gain } => {
                positive("width", *width)?;
                non_negative("gain", *gain)?;
            }
            Behaviour::SeekLight { gain, threshold } | Behaviour::Flee { gain, threshold } => {
                non_negative("gain", *gain)?;
                non_negative("threshold", *threshold)?;
            }
            Behaviour::Dock { within, speed } => {
                positive("within", *within)?;
                positive("speed", *speed)?;
            }
            Behaviour::Braitenberg(w) => w.check()?,
            Behaviour::Script { source } => {
                kinolab_script::Script::compile(source, crate::script::BEHAVE)
                    .map_err(|e| FieldError::new("source", e.to_string()))?;
            }
        }
        Ok(())
    }

    /// Forget any state (a run starting again): a script starts afresh,
    /// its notes empty.
    pub fn reset(&mut self) {
        self.wander = None;
        self.call = None;
        self.failed = None;
        self.script = match &self.behaviour {
            Behaviour::Script { source } => {
                match kinolab_script::Script::compile(source, crate::script::BEHAVE) {
                    Ok(s) => Some(s),
                    Err(e) => {
                        self.failed = Some(e);
                        None
                    }
                }
            }
            _ => None,
        };
    }

    /// A script behaviour's answer, keeping the call (or the error).
    fn scripted(&mut self, p: &Percepts) -> Option<Response> {
        let script = self.script.as_mut()?;
        match crate::script::behave(script, &self.name, p) {
            Ok((response, call)) => {
                self.call = Some(call);
                response
            }
            Err(e) => {
                self.failed = Some(e);
                None
            }
        }
    }

    /// Wander's heading now: a random walk that turns by up to `turn`
    /// each interval, every turn drawn from the seed and the interval's
    /// number, so a replay wanders the same way.
    fn wander_heading(&mut self, p: &Percepts, seed: u64, every: f64, turn: f64) -> f64 {
        let now = (p.time / every).floor().max(0.0) as u64;
        let change = |n: u64| (2.0 * unit_hash(seed, n, 0) - 1.0) * turn;
        let (mut at, mut heading) = *self
            .wander
            .get_or_insert((now, p.odometry.theta + change(now)));
        // Catch up on any intervals since the last call (at most 1000).
        while at < now && now - at <= 1000 {
            at += 1;
            heading += change(at);
        }
        self.wander = Some((now, heading));
        heading
    }

    /// The response to `p`, or `None` when the releaser is off.
    pub fn respond(&mut self, p: &Percepts) -> Option<Response> {
        match self.behaviour.clone() {
            Behaviour::Avoid { range, gain } => avoid(p, range, gain),
            Behaviour::GoToGoal { gain, slow_within } => {
                let g = p.goal.filter(|g| g.distance > AT_GOAL)?;
                let speed = gain * (g.distance / slow_within).min(1.0);
                Some(Response::Vector(polar(g.bearing, speed)))
            }
            Behaviour::Wander {
                gain,
                turn_deg,
                every,
                seed,
            } => {
                let heading = self.wander_heading(p, seed, every, turn_deg.to_radians());
                Some(Response::Vector(polar(
                    wrap(heading - p.odometry.theta),
                    gain,
                )))
            }
            Behaviour::FollowWall {
                side,
                distance,
                gain,
            } => follow_wall(p, side, distance, gain),
            Behaviour::Corridor { width, gain } => corridor(p, width, gain),
            Behaviour::SeekLight { gain, threshold } => {
                light_bearing(p, threshold).map(|b| Response::Vector(polar(b, gain)))
            }
            Behaviour::Flee { gain, threshold } => light_bearing(p, threshold)
                .map(|b| Response::Vector(polar(wrap(b + std::f64::consts::PI), gain))),
            Behaviour::Dock { within, speed } => {
                let g = p.goal.filter(|g| g.distance <= within)?;
                if g.distance <= AT_GOAL {
                    return Some(Response::Twist { v: 0.0, omega: 0.0 });
                }
                let v = speed.min(g.distance) * trig::cos(g.bearing).max(0.0);
                Some(Response::Twist {
                    v,
                    omega: 2.0 * g.bearing,
                })
            }
            Behaviour::Braitenberg(w) => Some(Response::Wheels(w.wheels(p.light))),
            Behaviour::Script { .. } => self.scripted(p),
        }
    }
}

/// A vector of length `length` at `angle` (robot frame).
fn polar(angle: f64, length: f64) -> Vec2 {
    Vec2::new(trig::cos(angle), trig::sin(angle)) * length
}

/// Something this far either side of the nose (rad, 60°) releases avoid;
/// rays up to 100° either side are looked at for a way out.
const RELEASE: f64 = 1.047;
const AHEAD: f64 = 1.745;

/// Avoid: when something within 60° of the nose is nearer than `range`,
/// head for the most open direction, slower and pushed away from the
/// nearest obstacle the closer it is; when a bumper is pressed, back off
/// turning away from it.
fn avoid(p: &Percepts, range: f64, gain: f64) -> Option<Response> {
    let [front, left, _, right] = p.bumpers;
    if front || left || right {
        let away = if left && !right { -1.5 } else { 1.5 };
        return Some(Response::Twist {
            v: -0.5 * gain,
            omega: away,
        });
    }
    let ahead: Vec<&kinolab_world::sensors::RayReading> =
        p.rays.iter().filter(|r| r.angle.abs() <= AHEAD).collect();
    let near = |r: &&&kinolab_world::sensors::RayReading| r.hit && r.range < range;
    ahead
        .iter()
        .filter(near)
        .find(|r| r.angle.abs() <= RELEASE)?;
    let nearest = ahead
        .iter()
        .filter(near)
        .min_by(|a, b| a.range.total_cmp(&b.range))?;
    // A direction is as open as the shortest of its ray and its two
    // neighbours (the robot is wider than a ray); prefer the straighter of
    // two alike.
    let (open, _) = (0..ahead.len())
        .map(|i| {
            let lo = i.saturating_sub(1);
            let hi = (i + 1).min(ahead.len() - 1);
            let free = ahead[lo..=hi]
                .iter()
                .map(|r| r.range)
                .fold(f64::INFINITY, f64::min);
            (
                ahead[i].angle,
                free.min(2.0 * range) - 0.15 * ahead[i].angle.abs(),
            )
        })
        .max_by(|a, b| a.1.total_cmp(&b.1))?;
    // Head for the open direction, slower and pushed away from the nearest
    // obstacle the closer it is.
    let closeness = (range - nearest.range) / range;
    let v = polar(open, gain * (1.0 - 0.6 * closeness)) - polar(nearest.angle, gain * closeness);
    Some(Response::Vector(v))
}

fn follow_wall(p: &Percepts, side: Side, distance: f64, gain: f64) -> Option<Response> {
    let s = side.sign();
    // The nearest reading on the wall's side (between 20° and 160°).
    let nearest = p
        .rays
        .iter()
        .filter(|r| r.hit && s * r.angle > 20f64.to_radians() && s * r.angle < 160f64.to_radians())
        .min_by(|a, b| a.range.total_cmp(&b.range))
        .filter(|r| r.range < 2.5 * distance)?;
    // Along the wall (the wall on our `side`), closing the distance error;
    // turn away from a wall ahead.
    let along = polar(nearest.angle - s * std::f64::consts::FRAC_PI_2, 1.0);
    let towards =
        polar(nearest.angle, 1.0) * ((nearest.range - distance) / distance).clamp(-1.0, 1.0);
    let mut v = along + towards;
    if let Some(ahead) = p.nearest_within(0.0, 25f64.to_radians())
        && ahead < 1.5 * distance
    {
        v += polar(-s * std::f64::consts::FRAC_PI_2, 1.0) * (1.5 * distance - ahead) / distance;
    }
    Some(Response::Vector(v.try_normalize(1e-12)? * gain))
}

fn corridor(p: &Percepts, width: f64, gain: f64) -> Option<Response> {
    let side = |sign: f64| p.nearest_within(sign * std::f64::consts::FRAC_PI_2, 30f64.to_radians());
    let (left, right) = (side(1.0)?, side(-1.0)?);
    if left + right > width {
        return None;
    }
    // Sideways towards the roomier side, in proportion to the imbalance.
    let lateral = (left - right) / width;
    Some(Response::Vector(Vec2::new(1.0, lateral).normalize() * gain))
}

/// The light's bearing from the two sensors: 0 when they read the same,
/// up to ±90° when one reads everything.
fn light_bearing(p: &Percepts, threshold: f64) -> Option<f64> {
    let [l, r] = p.light;
    if l + r <= threshold {
        return None;
    }
    Some(((l - r) / (l + r)) * std::f64::consts::FRAC_PI_2)
}
