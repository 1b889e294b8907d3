//! Robot bodies: a differential drive, whose wheels come from the wheels
//! crate, and a holonomic point robot. A body turns a requested twist into
//! one it can actually drive.

use kinolab_common::error::{from_json, positive};
use kinolab_wheels::{Chassis, Vector3, Wheel, WheelKind};
use nalgebra::Matrix2;
use serde::{Deserialize, Serialize};

use crate::FieldError;

/// A robot-frame twist: forward speed `vx`, sideways speed `vy` (m/s) and
/// turn rate `omega` (rad/s).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Command {
    pub vx: f64,
    pub vy: f64,
    pub omega: f64,
}

impl Command {
    pub const STOP: Command = Command {
        vx: 0.0,
        vy: 0.0,
        omega: 0.0,
    };

    /// Forward speed and turn rate, as a unicycle is driven.
    pub fn unicycle(v: f64, omega: f64) -> Self {
        Self {
            vx: v,
            vy: 0.0,
            omega,
        }
    }

    pub fn speed(&self) -> f64 {
        self.vx.hypot(self.vy)
    }

    fn is_finite(&self) -> bool {
        self.vx.is_finite() && self.vy.is_finite() && self.omega.is_finite()
    }
}

/// Two driven wheels on one axle, as the wheels crate models them: wheel
/// speeds to chassis twist and back.
#[derive(Debug, Clone, PartialEq)]
pub struct DiffDrive {
    /// Distance between the wheels, m.
    pub track: f64,
    pub wheel_radius: f64,
    /// The fastest either wheel turns, rad/s.
    pub max_wheel_speed: f64,
    /// The body's radius for collisions, m.
    pub radius: f64,
    /// A car-like limit: it cannot turn tighter than this radius (m), so
    /// it cannot turn on the spot; 0 for a plain differential drive.
    pub min_turn_radius: f64,
    /// (v, ω) → (left, right) wheel speeds, forward-positive.
    to_wheels: Matrix2<f64>,
    to_twist: Matrix2<f64>,
}

impl DiffDrive {
    pub fn new(
        track: f64,
        wheel_radius: f64,
        max_wheel_speed: f64,
        radius: f64,
    ) -> Result<Self, FieldError> {
        let track = positive("track", track)?;
        let wheel_radius = positive("wheel_radius", wheel_radius)?;
        let max_wheel_speed = positive("max_wheel_speed", max_wheel_speed)?;
        let radius = body_radius(radius)?;
        let half = track / 2.0;
        let half_pi = std::f64::consts::FRAC_PI_2;
        let chassis = Chassis::new(
            "differential drive",
            vec![
                Wheel::new(WheelKind::Fixed, half_pi, 0.0, half, wheel_radius),
                Wheel::new(
                    WheelKind::Fixed,
                    -half_pi,
                    std::f64::consts::PI,
                    half,
                    wheel_radius,
                ),
            ],
        )?;
        // Each column: the wheel spins for a unit forward speed, then for a
        // unit turn rate. The signs make "forward" positive on both wheels.
        let spins = |v: f64, w: f64| -> Result<[f64; 2], FieldError> {
            let s = chassis.inverse(Vector3::new(v, 0.0, w))?;
            Ok([s.wheels[0].spin, s.wheels[1].spin])
        };
        let forward = spins(1.0, 0.0)?;
        let turning = spins(0.0, 1.0)?;
        let sign = [forward[0].signum(), forward[1].signum()];
        let to_wheels = Matrix2::new(
            forward[0] * sign[0],
            turning[0] * sign[0],
            forward[1] * sign[1],
            turning[1] * sign[1],
        );
        let to_twist = to_wheels
            .try_inverse()
            .ok_or_else(|| FieldError::new("track", "the wheels cannot turn the robot"))?;
        Ok(Self {
            track,
            wheel_radius,
            max_wheel_speed,
            radius,
            min_turn_radius: 0.0,
            to_wheels,
            to_twist,
        })
    }

    /// The same drive steered like a car: no turn tighter than `radius` m.
    pub fn car_like(mut self, radius: f64) -> Result<Self, FieldError> {
        self.min_turn_radius = positive("min_turn_radius", radius)?;
        Ok(self)
    }

    /// Left and right wheel speeds (rad/s, forward-positive) for (v, ω).
    pub fn wheel_speeds(&self, v: f64, omega: f64) -> [f64; 2] {
        let w = self.to_wheels * nalgebra::Vector2::new(v, omega);
        [w.x, w.y]
    }

    /// The twist (v, ω) that wheel speeds drive.
    pub fn twist(&self, left: f64, right: f64) -> [f64; 2] {
        let t = self.to_twist * nalgebra::Vector2::new(left, right);
        [t.x, t.y]
    }

    /// Wheel speeds clipped to the limit, both scaled by the same factor
    /// so the robot keeps its curvature.
    pub fn limit_wheels(&self, wheels: [f64; 2]) -> [f64; 2] {
        let fastest = wheels[0].abs().max(wheels[1].abs());
        if fastest > self.max_wheel_speed {
            let k = self.max_wheel_speed / fastest;
            [wheels[0] * k, wheels[1] * k]
        } else {
            wheels
        }
    }

    /// The fastest straight-line speed, m/s.
    pub fn max_speed(&self) -> f64 {
        self.max_wheel_speed * self.wheel_radius
    }
}

/// A holonomic point robot: any direction, any time, up to a speed.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PointRobot {
    pub max_speed: f64,
    /// The fastest it turns to face where it goes, rad/s.
    pub max_turn: f64,
    pub radius: f64,
}

fn body_radius(radius: f64) -> Result<f64, FieldError> {
    let radius = positive("radius", radius)?;
    if radius < 0.01 {
        return Err(FieldError::new(
            "radius",
            format!("must be at least 0.01 m, got {radius}"),
        ));
    }
    Ok(radius)
}

/// A robot's body.
#[derive(Debug, Clone, PartialEq)]
pub enum Body {
    Differential(DiffDrive),
    Point(PointRobot),
}

impl Body {
    pub fn radius(&self) -> f64 {
        match self {
            Body::Differential(d) => d.radius,
            Body::Point(p) => p.radius,
        }
    }

    pub fn max_speed(&self) -> f64 {
        match self {
            Body::Differential(d) => d.max_speed(),
            Body::Point(p) => p.max_speed,
        }
    }

    /// Whether it can move sideways.
    pub fn holonomic(&self) -> bool {
        matches!(self, Body::Point(_))
    }

    /// The twist the body actually drives when `command` is asked: no
    /// sideways motion for a differential drive, and every limit kept.
    /// A command that is not finite stops the robot.
    pub fn limit(&self, command: Command) -> Command {
        if !command.is_finite() {
            return Command::STOP;
        }
        match self {
            Body::Differential(d) => {
                let wheels = d.limit_wheels(d.wheel_speeds(command.vx, command.omega));
                let [v, omega] = d.twist(wheels[0], wheels[1]);
                if d.min_turn_radius > 0.0 {
                    let tightest = v.abs() / d.min_turn_radius;
                    Command::unicycle(v, omega.clamp(-tightest, tightest))
                } else {
                    Command::unicycle(v, omega)
                }
            }
            Body::Point(p) => {
                let speed = command.speed();
                let k = if speed > p.max_speed {
                    p.max_speed / speed
                } else {
                    1.0
                };
                Command {
                    vx: command.vx * k,
                    vy: command.vy * k,
                    omega: command.omega.clamp(-p.max_turn, p.max_turn),
                }
            }
        }
    }

    /// Read a body from its file form (a run file's `robot`).
    pub fn from_value(value: serde_json::Value) -> Result<Self, FieldError> {
        let entry: BodyEntry = from_json(&value.to_string())?;
        entry.body()
    }

    /// The file form of this body.
    pub fn to_value(&self) -> serde_json::Value {
        let entry = match self {
            Body::Differential(d) => BodyEntry::Differential {
                track: d.track,
                wheel_radius: d.wheel_radius,
                max_wheel_speed: d.max_wheel_speed,
                radius: d.radius,
            },
            Body::Point(p) => BodyEntry::Point {
                max_speed: p.max_speed,
                max_turn_deg: p.max_turn.to_degrees(),
                radius: p.radius,
            },
        };
        serde_json::to_value(entry).unwrap_or_default()
    }
}

impl Default for Body {
    /// A small differential robot: 30 cm track, 5 cm wheels, 0.5 m/s.
    fn default() -> Self {
        match DiffDrive::new(0.3, 0.05, 10.0, 0.18) {
            Ok(d) => Body::Differential(d),
            Err(_) => Body::Point(PointRobot {
                max_speed: 0.5,
                max_turn: 4.0,
                radius: 0.18,
            }),
        }
    }
}

#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase", deny_unknown_fields)]
enum BodyEntry {
    Differential {
        track: f64,
        wheel_radius: f64,
        max_wheel_speed: f64,
        radius: f64,
    },
    Point {
        max_speed: f64,
        #[serde(default = "default_turn")]
        max_turn_deg: f64,
        radius: f64,
    },
}

fn default_turn() -> f64 {
    360.0
}

impl BodyEntry {
    fn body(&self) -> Result<Body, FieldError> {
        Ok(match *self {
            BodyEntry::Differential {
                track,
                wheel_radius,
                max_wheel_speed,
                radius,
            } => Body::Differential(DiffDrive::new(
                track,
                wheel_radius,
                max_wheel_speed,
                radius,
            )?),
            BodyEntry::Point {
                max_speed,
                max_turn_deg,
                radius,
            } => Body::Point(PointRobot {
                max_speed: positive("max_speed", max_speed)?,
                max_turn: positive("max_turn_deg", max_turn_deg)?.to_radians(),
                radius: body_radius(radius)?,
            }),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_wheels_crate_agrees_with_the_closed_form() {
        let d = DiffDrive::new(0.3, 0.05, 10.0, 0.18).unwrap();
        // v = r (ω_R + ω_L) / 2, ω = r (ω_R − ω_L) / b.
        let [l, r] = d.wheel_speeds(0.4, 1.0);
        assert!((0.05 * (r + l) / 2.0 - 0.4).abs() < 1e-12);
        assert!((0.05 * (r - l) / 0.3 - 1.0).abs() < 1e-12);
        let [v, w] = d.twist(l, r);
        assert!((v - 0.4).abs() < 1e-12 && (w - 1.0).abs() < 1e-12);
    }

    #[test]
    fn limits_keep_the_curvature() {
        let body = Body::Differential(DiffDrive::new(0.3, 0.05, 10.0, 0.18).unwrap());
        let c = body.limit(Command {
            vx: 2.0,
            vy: 0.3,
            omega: 4.0,
        });
        assert_eq!(c.vy, 0.0, "no sideways motion");
        assert!((c.omega / c.vx - 2.0).abs() < 1e-12, "curvature kept");
        assert!(c.vx < 0.5);
        assert_eq!(
            body.limit(Command {
                vx: f64::NAN,
                vy: 0.0,
                omega: 0.0
            }),
            Command::STOP
        );
        let point = Body::Point(PointRobot {
            max_speed: 1.0,
            max_turn: 2.0,
            radius: 0.1,
        });
        let c = point.limit(Command {
            vx: 3.0,
            vy: 4.0,
            omega: -9.0,
        });
        assert!((c.speed() - 1.0).abs() < 1e-12 && (c.vy / c.vx - 4.0 / 3.0).abs() < 1e-12);
        assert_eq!(c.omega, -2.0);
    }

    #[test]
    fn bodies_read_and_name_bad_fields() {
        let v = serde_json::json!({"kind": "differential", "track": 0.3, "wheel_radius": 0.05, "max_wheel_speed": 10, "radius": 0.18});
        let b = Body::from_value(v).unwrap();
        assert!((b.max_speed() - 0.5).abs() < 1e-12);
        assert_eq!(Body::from_value(b.to_value()).unwrap(), b);
        let e =
            Body::from_value(serde_json::json!({"kind": "point", "max_speed": -1, "radius": 0.1}))
                .unwrap_err();
        assert_eq!(e.field, "max_speed");
        let e =
            Body::from_value(serde_json::json!({"kind": "point", "max_speed": 1, "radius": 0.001}))
                .unwrap_err();
        assert_eq!(e.field, "radius");
        let e = Body::from_value(serde_json::json!({"kind": "tank"})).unwrap_err();
        assert!(e.message.contains("tank"), "{e}");
    }
}
