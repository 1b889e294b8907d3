//! The stable equilibria of a field: the points a robot following it can
//! come to rest at.
//!
//! Newton's method on F(p) = 0 starts from every cell of a grid over the
//! box, each step held within one cell's size. Newton finds every kind of
//! equilibrium; a point is kept only where the field is differentiable and
//! its Jacobian has both eigenvalues in the left half-plane (trace < 0 and
//! determinant > 0), so saddles and sources are thrown away.

use kinolab_world::Rect;
use serde::Serialize;

use crate::{Field, FieldError, Mat2, Vec2};

/// A stable equilibrium.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Minimum {
    pub x: f64,
    pub y: f64,
    /// Within 1e-6 m of an attractive field's centre.
    pub goal: bool,
}

impl Minimum {
    pub fn at(&self) -> Vec2 {
        Vec2::new(self.x, self.y)
    }
}

/// How an equilibrium behaves, from its Jacobian.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    /// Both eigenvalues have negative real parts: nearby points flow in.
    Stable,
    /// Eigenvalues of opposite sign: in along one line, out along another.
    Saddle,
    /// Nearby points flow out (or the test cannot tell: a zero eigenvalue).
    Unstable,
}

/// Classify an equilibrium by its Jacobian.
pub fn classify(j: &Mat2) -> Kind {
    let (trace, det) = (j.trace(), j.determinant());
    let size = j.norm().max(1e-300);
    if det < -1e-12 * size * size {
        Kind::Saddle
    } else if trace < 0.0 && det > 1e-12 * size * size {
        Kind::Stable
    } else {
        Kind::Unstable
    }
}

/// The search's settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Search {
    /// Starts along each side of the box.
    pub starts_per_side: usize,
    /// Newton steps from each start.
    pub max_steps: usize,
}

impl Default for Search {
    fn default() -> Self {
        Self {
            starts_per_side: 40,
            max_steps: 40,
        }
    }
}

/// Minima closer than this are one minimum, m.
const SAME_POINT: f64 = 1e-6;

/// An equilibrium where the field is smooth, and its kind.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Equilibrium {
    pub x: f64,
    pub y: f64,
    pub kind: Kind,
}

/// Every equilibrium of `field` inside `area` where the field is smooth,
/// each once, sorted by x then y: stable ones, saddles and sources.
pub fn equilibria(
    field: &Field,
    area: &Rect,
    search: Search,
) -> Result<Vec<Equilibrium>, FieldError> {
    let area = area.checked("box")?;
    let n = search.starts_per_side.clamp(2, 400);
    let (dx, dy) = (area.width() / n as f64, area.height() / n as f64);
    let trust = dx.hypot(dy);
    let mut found: Vec<(Vec2, f64)> = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let start = Vec2::new(
                area.x_min + (i as f64 + 0.5) * dx,
                area.y_min + (j as f64 + 0.5) * dy,
            );
            let Some(p) = newton(field, start, trust, search.max_steps.min(500)) else {
                continue;
            };
            if !area.contains(p.x, p.y) || !field.smooth_at(p) {
                continue;
            }
            let residual = field.vector(p).norm();
            match found
                .iter_mut()
                .find(|(q, _)| (q - p).norm() < SAME_POINT * 10.0)
            {
                Some(same) if residual < same.1 => *same = (p, residual),
                Some(_) => {}
                None => found.push((p, residual)),
            }
        }
    }
    let found = kinolab_common::order::sorted_by(found, |(p, _)| [p.x, p.y]);
    Ok(found
        .into_iter()
        .map(|(p, _)| Equilibrium {
            x: p.x,
            y: p.y,
            kind: classify(&field.linearise(p).1),
        })
        .collect())
}

/// Every stable equilibrium of `field` inside `area`, each once, sorted by
/// x then y.
pub fn minima(field: &Field, area: &Rect, search: Search) -> Result<Vec<Minimum>, FieldError> {
    Ok(stable(field, &equilibria(field, area, search)?))
}

/// The stable ones among `equilibria`, as minima with their goal flags.
pub fn stable(field: &Field, equilibria: &[Equilibrium]) -> Vec<Minimum> {
    equilibria
        .iter()
        .filter(|e| e.kind == Kind::Stable)
        .map(|e| minimum(field, Vec2::new(e.x, e.y)))
        .collect()
}

fn minimum(field: &Field, p: Vec2) -> Minimum {
    let goal = field.primitives.iter().any(|q| {
        matches!(q.source, crate::Source::Attractive { centre } if (centre - p).norm() <= SAME_POINT)
    });
    Minimum {
        x: p.x,
        y: p.y,
        goal,
    }
}

/// Whether `p` is an equilibrium (F = 0 to rounding), the field is smooth
/// there, and the Jacobian makes it stable.
pub fn is_stable_minimum(field: &Field, p: Vec2) -> bool {
    let (f, j) = field.linearise(p);
    f.norm() <= 1e-9 * field.scale() && field.smooth_at(p) && classify(&j) == Kind::Stable
}

/// Newton's method from `start`, each step no longer than `trust`.
/// Returns where it settles, or `None` if it does not.
fn newton(field: &Field, start: Vec2, trust: f64, max_steps: usize) -> Option<Vec2> {
    let tolerance = 1e-13 * field.scale();
    let mut p = start;
    for _ in 0..max_steps {
        let (f, j) = field.linearise(p);
        if f.norm() <= tolerance {
            return Some(p);
        }
        let mut step = -(j.try_inverse()? * f);
        let length = step.norm();
        if !length.is_finite() {
            return None;
        }
        if length > trust {
            step *= trust / length;
        }
        p += step;
        if length < 1e-14 * (1.0 + p.norm()) {
            return Some(p);
        }
    }
    let (f, _) = field.linearise(p);
    (f.norm() <= 1e-9 * field.scale()).then_some(p)
}
