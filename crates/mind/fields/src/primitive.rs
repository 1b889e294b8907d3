//! The five field primitives and their magnitude profiles.
//!
//! A primitive pushes with F(p) = m · g(d) · u(p): a gain m, a profile g of
//! the distance d to its object, and a unit direction u. Each primitive also
//! gives its exact Jacobian ∂F/∂p, which the minima search needs.

use kinolab_common::trig;
use serde::{Deserialize, Serialize};

use crate::{FieldError, Mat2, Vec2};

/// Which way a tangential field turns around its centre.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Spin {
    /// Counter-clockwise: u is the outward direction turned +90°.
    Ccw,
    Cw,
}

/// Whether a perpendicular field pushes away from its segment or pulls.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Sense {
    Away,
    Toward,
}

/// What a primitive is anchored to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Source {
    /// The same push everywhere, towards `direction` (rad).
    Uniform { direction: f64 },
    /// Towards a point.
    Attractive { centre: Vec2 },
    /// Away from a disc.
    Repulsive { centre: Vec2, radius: f64 },
    /// Around a disc.
    Tangential {
        centre: Vec2,
        radius: f64,
        spin: Spin,
    },
    /// Square to a segment.
    Perpendicular { from: Vec2, to: Vec2, sense: Sense },
}

impl Source {
    pub fn kind(&self) -> &'static str {
        match self {
            Source::Uniform { .. } => "uniform",
            Source::Attractive { .. } => "attractive",
            Source::Repulsive { .. } => "repulsive",
            Source::Tangential { .. } => "tangential",
            Source::Perpendicular { .. } => "perpendicular",
        }
    }
}

/// How the magnitude varies with the distance d (range D).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Profile {
    /// 1 within the range.
    Constant,
    /// 1 − d/D (strongest at contact); for attractive fields min(1, d/D).
    Linear,
    /// e^(−d/λ).
    Exponential { lambda: f64 },
    /// The gradient of a potential: d for attractive fields (F = m (c − p)),
    /// Khatib's (1/d − 1/D)/d² for repulsive ones.
    Potential,
}

impl Profile {
    pub fn name(&self) -> &'static str {
        match self {
            Profile::Constant => "constant",
            Profile::Linear => "linear",
            Profile::Exponential { .. } => "exponential",
            Profile::Potential => "potential",
        }
    }
}

/// A repulsive potential is capped this close to its obstacle, m, so the
/// field stays finite.
pub const POTENTIAL_FLOOR: f64 = 1e-6;

/// Closer than this to a centre or a segment, the direction is undefined, m.
const SINGULAR: f64 = 1e-12;

/// One primitive: its source, gain, profile and range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Primitive {
    pub source: Source,
    pub gain: f64,
    pub profile: Profile,
    /// D: beyond it the primitive is 0 (except attractive `linear`, and
    /// uniform fields, which ignore it). `None`: no limit.
    pub range: Option<f64>,
}

/// The value and slope of a profile at one distance.
#[derive(Debug, Clone, Copy)]
struct Magnitude {
    g: f64,
    slope: f64,
}

const ZERO: Magnitude = Magnitude { g: 0.0, slope: 0.0 };

impl Primitive {
    /// A checked primitive; errors name the field as a field file spells it.
    pub fn new(
        source: Source,
        gain: f64,
        profile: Profile,
        range: Option<f64>,
    ) -> Result<Self, FieldError> {
        let p = Self {
            source,
            gain,
            profile,
            range,
        };
        p.check()?;
        Ok(p)
    }

    fn check(&self) -> Result<(), FieldError> {
        use kinolab_common::error::{finite, non_negative, positive};
        non_negative("gain", self.gain)?;
        let kind = self.source.kind();
        let allowed = match (self.source, self.profile) {
            (Source::Uniform { .. }, Profile::Constant) => true,
            (Source::Uniform { .. }, _) => false,
            (Source::Attractive { .. }, Profile::Exponential { .. }) => false,
            (Source::Tangential { .. } | Source::Perpendicular { .. }, Profile::Potential) => false,
            _ => true,
        };
        if !allowed {
            return Err(FieldError::new(
                "profile",
                format!("`{}` does not apply to a {kind} field", self.profile.name()),
            ));
        }
        if let Profile::Exponential { lambda } = self.profile {
            positive("lambda", lambda)?;
        }
        let needs_range = match self.source {
            Source::Uniform { .. } => false,
            Source::Attractive { .. } => self.profile == Profile::Linear,
            _ => true,
        };
        match self.range {
            Some(d) => {
                positive("range", d)?;
            }
            None if needs_range => {
                return Err(FieldError::new(
                    "range",
                    format!(
                        "missing: a {kind} field with the `{}` profile needs it",
                        self.profile.name()
                    ),
                ));
            }
            None => {}
        }
        match self.source {
            Source::Uniform { direction } => {
                finite("direction_deg", direction)?;
            }
            Source::Attractive { centre } => check_point("x", centre)?,
            Source::Repulsive { centre, radius } | Source::Tangential { centre, radius, .. } => {
                check_point("x", centre)?;
                non_negative("radius", radius)?;
            }
            Source::Perpendicular { from, to, .. } => {
                check_point("from", from)?;
                check_point("to", to)?;
                if (to - from).norm() < 1e-9 {
                    return Err(FieldError::new(
                        "to",
                        "the segment has no length: `from` and `to` are the same point",
                    ));
                }
            }
        }
        Ok(())
    }

    /// The profile g and its slope dg/dd at distance `d`.
    fn magnitude(&self, d: f64) -> Magnitude {
        let beyond = self.range.is_some_and(|range| d > range);
        let range = self.range.unwrap_or(f64::INFINITY);
        match (self.source, self.profile) {
            (Source::Uniform { .. }, _) => Magnitude { g: 1.0, slope: 0.0 },
            (Source::Attractive { .. }, Profile::Linear) if d < range => Magnitude {
                g: d / range,
                slope: 1.0 / range,
            },
            (Source::Attractive { .. }, Profile::Linear) => Magnitude { g: 1.0, slope: 0.0 },
            _ if beyond => ZERO,
            (_, Profile::Constant) => Magnitude { g: 1.0, slope: 0.0 },
            (Source::Attractive { .. }, Profile::Potential) => Magnitude { g: d, slope: 1.0 },
            (_, Profile::Potential) => {
                let floor = d < POTENTIAL_FLOOR;
                let d = d.max(POTENTIAL_FLOOR);
                Magnitude {
                    g: (1.0 / d - 1.0 / range) / (d * d),
                    slope: if floor {
                        0.0
                    } else {
                        -3.0 / d.powi(4) + 2.0 / (range * d.powi(3))
                    },
                }
            }
            (_, Profile::Linear) => Magnitude {
                g: 1.0 - d / range,
                slope: -1.0 / range,
            },
            (_, Profile::Exponential { lambda }) => {
                let g = (-d / lambda).exp();
                Magnitude {
                    g,
                    slope: -g / lambda,
                }
            }
        }
    }

    /// F(p).
    pub fn vector(&self, p: Vec2) -> Vec2 {
        self.linearise(p).0
    }

    /// F(p) and its Jacobian ∂F/∂p.
    pub fn linearise(&self, p: Vec2) -> (Vec2, Mat2) {
        let m = self.gain;
        match self.source {
            Source::Uniform { direction } => (
                Vec2::new(trig::cos(direction), trig::sin(direction)) * m,
                Mat2::zeros(),
            ),
            Source::Attractive { centre } => self.attract(p, centre),
            Source::Repulsive { centre, radius } => {
                self.around(p, centre, radius, Mat2::identity())
            }
            Source::Tangential {
                centre,
                radius,
                spin,
            } => {
                let turn = match spin {
                    Spin::Ccw => Mat2::new(0.0, -1.0, 1.0, 0.0),
                    Spin::Cw => Mat2::new(0.0, 1.0, -1.0, 0.0),
                };
                self.around(p, centre, radius, turn)
            }
            Source::Perpendicular { from, to, sense } => {
                let sign = if sense == Sense::Away { 1.0 } else { -1.0 };
                let (f, j) = self.segment(p, from, to);
                (f * sign, j * sign)
            }
        }
    }

    /// Attraction: written out in full, as the `linear` and `potential`
    /// profiles are smooth right through the centre.
    fn attract(&self, p: Vec2, centre: Vec2) -> (Vec2, Mat2) {
        let m = self.gain;
        let w = centre - p;
        let d = w.norm();
        let beyond = self.range.is_some_and(|r| d > r);
        match (self.profile, self.range) {
            // F = m (c − p) / D inside the range: smooth through the centre.
            (Profile::Linear, Some(r)) if d < r => {
                return (w * (m / r), Mat2::identity() * (-m / r));
            }
            // F = m (c − p): the gradient of ½ m d².
            (Profile::Potential, _) if !beyond => return (w * m, Mat2::identity() * -m),
            _ => {}
        }
        let mag = self.magnitude(d);
        if d < SINGULAR || mag.g == 0.0 {
            return (Vec2::zeros(), Mat2::zeros());
        }
        let u = w / d;
        let across = (Mat2::identity() - u * u.transpose()) / d;
        // u = (c − p)/d, so ∂u/∂p = −(I − u uᵀ)/d and ∂d/∂p = −uᵀ.
        (
            u * (m * mag.g),
            (u * u.transpose() * (-mag.slope) - across * mag.g) * m,
        )
    }

    /// Repulsive (`turn` = I) and tangential (`turn` a quarter turn) fields
    /// around a disc.
    fn around(&self, p: Vec2, centre: Vec2, radius: f64, turn: Mat2) -> (Vec2, Mat2) {
        let w = p - centre;
        let r = w.norm();
        if r < SINGULAR {
            return (Vec2::zeros(), Mat2::zeros());
        }
        let out = w / r;
        let d = (r - radius).max(0.0);
        let mag = self.magnitude(d);
        if mag.g == 0.0 && mag.slope == 0.0 {
            return (Vec2::zeros(), Mat2::zeros());
        }
        let grad_d = if r > radius { out } else { Vec2::zeros() };
        let d_out = (Mat2::identity() - out * out.transpose()) / r;
        let u = turn * out;
        let j = (u * grad_d.transpose() * mag.slope + turn * d_out * mag.g) * self.gain;
        (u * (self.gain * mag.g), j)
    }

    /// Away from the nearest point of a segment.
    fn segment(&self, p: Vec2, a: Vec2, b: Vec2) -> (Vec2, Mat2) {
        let ab = b - a;
        let t = ((p - a).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
        let w = p - (a + ab * t);
        let d = w.norm();
        if d < SINGULAR {
            return (Vec2::zeros(), Mat2::zeros());
        }
        let u = w / d;
        let mag = self.magnitude(d);
        // Beside the segment u is fixed (the normal); past an end it turns
        // like a point's.
        let du = if t > 0.0 && t < 1.0 {
            Mat2::zeros()
        } else {
            (Mat2::identity() - u * u.transpose()) / d
        };
        let j = (u * u.transpose() * mag.slope + du * mag.g) * self.gain;
        (u * (self.gain * mag.g), j)
    }

    /// Whether the field is differentiable at `p`: not at a centre where the
    /// direction jumps, nor on a segment, a range's edge, or the rim of a
    /// disc where the distance stops changing.
    pub fn smooth_at(&self, p: Vec2, tolerance: f64) -> bool {
        let edge = |d: f64| self.range.is_some_and(|r| (d - r).abs() <= tolerance);
        match self.source {
            Source::Uniform { .. } => true,
            Source::Attractive { centre } => {
                let d = (p - centre).norm();
                let centre_ok =
                    matches!(self.profile, Profile::Linear | Profile::Potential) || d > tolerance;
                centre_ok && !edge(d)
            }
            Source::Repulsive { centre, radius } | Source::Tangential { centre, radius, .. } => {
                let r = (p - centre).norm();
                let rim = radius > 0.0
                    && self.profile != Profile::Constant
                    && (r - radius).abs() <= tolerance;
                r > tolerance && !rim && !edge((r - radius).max(0.0))
            }
            Source::Perpendicular { from, to, .. } => {
                let ab = to - from;
                let t = ((p - from).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
                let d = (p - (from + ab * t)).norm();
                d > tolerance && !edge(d)
            }
        }
    }

    /// The primitive's anchor point, for drawing (the segment's midpoint).
    pub fn anchor(&self) -> Option<Vec2> {
        match self.source {
            Source::Uniform { .. } => None,
            Source::Attractive { centre }
            | Source::Repulsive { centre, .. }
            | Source::Tangential { centre, .. } => Some(centre),
            Source::Perpendicular { from, to, .. } => Some((from + to) / 2.0),
        }
    }
}

fn check_point(field: &str, p: Vec2) -> Result<(), FieldError> {
    let (fx, fy) = match field {
        "x" => ("x".to_owned(), "y".to_owned()),
        other => (format!("{other}[0]"), format!("{other}[1]")),
    };
    kinolab_common::error::finite(fx, p.x)?;
    kinolab_common::error::finite(fy, p.y)?;
    Ok(())
}
