//! Graded exercises on fields, checked by the core.

use kinolab_common::Feedback;

use crate::descend::{Outcome, Steps, descend};
use crate::{Field, FieldError, Primitive, Vec2};

/// "Compute the vector at this point": right within 2 % of its length
/// (or 0.01 when it is short).
pub fn check_vector(field: &Field, at: Vec2, answer: [f64; 2]) -> Feedback {
    let f = field.vector(at);
    let miss = (Vec2::new(answer[0], answer[1]) - f).norm();
    let allowed = (0.02 * f.norm()).max(0.01);
    if !(answer[0].is_finite() && answer[1].is_finite()) {
        return Feedback::not_yet("Type two numbers: the x and y parts of the vector.");
    }
    Feedback::when(
        miss <= allowed,
        format!("Right: F = ({:.3}, {:.3}).", f.x, f.y),
        format!(
            "Not yet: your vector is {miss:.3} away from the field's. Add every primitive's push at the point, each with its profile."
        ),
    )
}

/// "Add one field so the robot escapes": `base` plus exactly one added
/// primitive must take a point robot from `start` to the goal.
pub fn check_escape(
    base: &Field,
    added: &[Primitive],
    start: Vec2,
) -> Result<Feedback, FieldError> {
    if added.len() != 1 {
        return Ok(Feedback::not_yet(format!(
            "Add exactly one field (you have added {}).",
            added.len()
        )));
    }
    let mut field = base.clone();
    field.primitives.extend_from_slice(added);
    let d = descend(&field, start, Steps::default())?;
    Ok(match d.outcome {
        Outcome::Reached => Feedback::met(format!(
            "The robot reaches the goal in {} steps.",
            d.steps()
        )),
        Outcome::Trapped => Feedback::not_yet(format!(
            "The robot still stops at ({:.2}, {:.2}): the new field must not cancel out where the old ones do.",
            d.end[0], d.end[1]
        )),
        Outcome::MaxSteps => {
            Feedback::not_yet("The robot wanders without arriving: a weaker added field may do.")
        }
    })
}

/// "Choose range and gain so the robot stops at least `clearance` from the
/// wall": the wall is primitive `wall` of `field`; the robot must come to
/// rest without ever getting closer.
pub fn check_stand_off(
    field: &Field,
    wall: usize,
    start: Vec2,
    clearance: f64,
) -> Result<Feedback, FieldError> {
    let Some(w) = field.primitives.get(wall) else {
        return Err(FieldError::new("wall", "no such primitive"));
    };
    let d = descend(field, start, Steps::default())?;
    let closest = d
        .path
        .iter()
        .map(|p| {
            let mut only = w.to_owned();
            only.gain = 1.0;
            distance_to(&only, Vec2::new(p[0], p[1]))
        })
        .fold(f64::INFINITY, f64::min);
    Ok(match d.outcome {
        Outcome::Trapped if closest >= clearance => Feedback::met(format!(
            "The robot stops {closest:.2} m from the wall, no closer than {clearance} m."
        )),
        Outcome::Trapped => Feedback::not_yet(format!(
            "The robot gets within {closest:.2} m of the wall: push harder or from farther away."
        )),
        _ => Feedback::not_yet(
            "The robot does not come to rest in front of the wall: the wall must push back.",
        ),
    })
}

/// The distance from `p` to a primitive's object (its segment or disc).
pub fn distance_to(p: &Primitive, q: Vec2) -> f64 {
    match p.source {
        crate::Source::Perpendicular { from, to, .. } => {
            let ab = to - from;
            let t = ((q - from).dot(&ab) / ab.norm_squared()).clamp(0.0, 1.0);
            (q - (from + ab * t)).norm()
        }
        crate::Source::Repulsive { centre, radius }
        | crate::Source::Tangential { centre, radius, .. } => {
            ((q - centre).norm() - radius).max(0.0)
        }
        crate::Source::Attractive { centre } => (q - centre).norm(),
        crate::Source::Uniform { .. } => f64::INFINITY,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::catalogue::preset;
    use crate::primitive::{Profile, Sense, Source};

    #[test]
    fn vectors_are_graded_against_the_core() {
        let field = preset("rock-on-the-axis").unwrap().field().unwrap();
        let at = Vec2::new(1.0, 0.5);
        let f = field.vector(at);
        assert!(check_vector(&field, at, [f.x, f.y]).met);
        assert!(check_vector(&field, at, [f.x * 1.01, f.y]).met);
        assert!(!check_vector(&field, at, [f.x + 0.2, f.y]).met);
        assert!(!check_vector(&field, at, [f64::NAN, 0.0]).met);
    }

    #[test]
    fn one_tangential_field_frees_the_u() {
        // A clockwise swirl round the U's middle lifts the robot over the
        // top arm before it can enter the mouth.
        let base = preset("u-shaped-wall").unwrap().field().unwrap();
        let start = Vec2::new(0.5, 0.3);
        let around = Primitive::new(
            Source::Tangential {
                centre: Vec2::new(3.0, 0.0),
                radius: 0.0,
                spin: crate::Spin::Cw,
            },
            3.0,
            Profile::Linear,
            Some(2.3),
        )
        .unwrap();
        assert!(check_escape(&base, &[around], start).unwrap().met);
        assert!(!check_escape(&base, &[], start).unwrap().met);
        let weak = Primitive {
            gain: 0.05,
            ..around
        };
        assert!(!check_escape(&base, &[weak], start).unwrap().met);
    }

    #[test]
    fn stand_off_needs_range_and_gain() {
        let wall = |gain: f64, range: f64| {
            Field::new(
                "wall",
                Some(Vec2::new(5.0, 0.0)),
                vec![
                    Primitive::new(
                        Source::Attractive {
                            centre: Vec2::new(5.0, 0.0),
                        },
                        1.0,
                        Profile::Constant,
                        None,
                    )
                    .unwrap(),
                    Primitive::new(
                        Source::Perpendicular {
                            from: Vec2::new(3.0, -3.0),
                            to: Vec2::new(3.0, 3.0),
                            sense: Sense::Away,
                        },
                        gain,
                        Profile::Linear,
                        Some(range),
                    )
                    .unwrap(),
                ],
            )
        };
        let start = Vec2::new(0.0, 0.0);
        // Rest where 1 = m (1 − d/D): d = D (1 − 1/m). m = 2, D = 1: 0.5 m.
        assert!(check_stand_off(&wall(2.0, 1.0), 1, start, 0.3).unwrap().met);
        // m = 2, D = 0.5: 0.25 m, too close.
        assert!(!check_stand_off(&wall(2.0, 0.5), 1, start, 0.3).unwrap().met);
        // m = 0.8 never outweighs the pull: the robot goes through.
        assert!(!check_stand_off(&wall(0.8, 1.0), 1, start, 0.3).unwrap().met);
    }
}
