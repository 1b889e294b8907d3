//! What `kinolab field` prints, and the JS API returns, as typed reports.

use kinolab_world::Rect;
use serde::Serialize;

use crate::descend::{Descent, Steps, descend};
use crate::minima::{Minimum, Search, minima};
use crate::{Field, FieldError, Vec2};

/// `--at`: one vector per point, in order.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Vectors {
    pub vectors: Vec<[f64; 2]>,
}

/// `--minima`: every stable equilibrium in the box.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Minima {
    pub minima: Vec<Minimum>,
}

/// A learner's primitive that failed while the report was made.
fn script_ok(field: &Field) -> Result<(), FieldError> {
    match field.failed() {
        Some(e) => Err(FieldError::new(
            "fields",
            format!("your `field(x, y)`: {e}"),
        )),
        None => Ok(()),
    }
}

/// The field's vector at each point.
pub fn vectors(field: &Field, points: &[[f64; 2]]) -> Result<Vectors, FieldError> {
    let mut vectors = Vec::with_capacity(points.len());
    for (i, [x, y]) in points.iter().enumerate() {
        kinolab_common::error::finite_at(*x, || format!("at[{i}]"))?;
        kinolab_common::error::finite_at(*y, || format!("at[{i}]"))?;
        let f = field.vector(Vec2::new(*x, *y));
        vectors.push([f.x, f.y]);
    }
    script_ok(field)?;
    Ok(Vectors { vectors })
}

/// The stable equilibria in `area` ([x_min, y_min, x_max, y_max]).
pub fn minima_in(field: &Field, area: [f64; 4]) -> Result<Minima, FieldError> {
    let area = Rect::new("box", area)?;
    let minima = minima(field, &area, Search::default())?;
    script_ok(field)?;
    Ok(Minima { minima })
}

/// A point robot's descent from `start`.
pub fn descent(field: &Field, start: [f64; 2], steps: Steps) -> Result<Descent, FieldError> {
    let descent = descend(field, Vec2::new(start[0], start[1]), steps)?;
    script_ok(field)?;
    Ok(descent)
}
