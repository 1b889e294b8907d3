//! Scripted surprises: what an open world does to a robot's plans. Each
//! is written as `kind:numbers[@number]`, as the command line takes them.

use kinolab_common::error::{finite, in_range};
use kinolab_world::obstacle::{Obstacle, Repeat, Script, Shape};
use kinolab_world::{FieldError, Light, Sensors, Vec2, World};
use serde::Serialize;

/// The radius of a walking person, m.
pub const PERSON_RADIUS: f64 = 0.25;

#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Surprise {
    /// A door closes: a wall from `from` to `to` appears at time `at`.
    Door {
        from: [f64; 2],
        to: [f64; 2],
        at: f64,
    },
    /// A person steps in at time `at`: walks from `from` to `to` at `speed`
    /// and stands there.
    Person {
        from: [f64; 2],
        to: [f64; 2],
        speed: f64,
        at: f64,
    },
    /// The map the robots are given lacks these obstacles.
    WrongMap { missing: Vec<usize> },
    /// The range sensors' noise, standard deviation in m.
    Noise { sd: f64 },
    /// The goal moves to `to` at time `at`.
    Goal { to: [f64; 2], at: f64 },
    /// A glass wall (light and range rays pass it), with a light on the goal.
    Glass { from: [f64; 2], to: [f64; 2] },
}

/// The widget's surprise ids: none, then the office's.
pub fn ids() -> impl Iterator<Item = &'static str> {
    std::iter::once("none").chain(OFFICE.iter().map(|(id, _)| *id))
}

/// Examples of every surprise in the office world, as written on the
/// command line; the widget's buttons use the same.
pub const OFFICE: [(&str, &str); 6] = [
    ("door", "door:5,1,5,2@6"),
    ("person", "person:6.3,5.6,6.3,2.0@0.6"),
    ("wrong-map", "wrong-map:3"),
    ("noise", "noise:0.15"),
    ("moved-goal", "goal:9,5@8"),
    ("glass", "glass:8.2,0,8.2,3.2"),
];

fn numbers(field: &str, text: &str, count: usize) -> Result<Vec<f64>, FieldError> {
    let values: Vec<f64> = text
        .split(',')
        .map(|t| t.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| {
            FieldError::new(
                field,
                format!("`{text}` should be {count} numbers separated by commas"),
            )
        })?;
    if values.len() != count {
        return Err(FieldError::new(
            field,
            format!("needs {count} numbers, got {}", values.len()),
        ));
    }
    // Coordinates must be numbers the lab can compute with; a single
    // number (a time, a noise, a speed) only needs to be finite here, since
    // its own range is checked where it is used and the message names it.
    for v in values.iter().filter(|v| count > 1 || !v.is_finite()) {
        finite(field, *v)?;
    }
    Ok(values)
}

/// `body@number`, split at the last `@`.
fn split_at(field: &str, text: &str) -> Result<(String, f64), FieldError> {
    let (body, at) = text.rsplit_once('@').ok_or_else(|| {
        FieldError::new(field, format!("`{text}` needs `@` and a number after it"))
    })?;
    let at = numbers(field, at, 1)?[0];
    Ok((body.to_owned(), at))
}

impl Surprise {
    /// Read `kind:…`; errors name `field`.
    pub fn parse(field: &str, spec: &str) -> Result<Self, FieldError> {
        let (kind, rest) = spec.split_once(':').ok_or_else(|| {
            FieldError::new(
                field,
                format!("`{spec}` should look like `kind:numbers`, e.g. `door:5,1,5,2@6`"),
            )
        })?;
        let pair = |v: &[f64], k: usize| [v[k], v[k + 1]];
        Ok(match kind {
            "door" => {
                let (body, at) = split_at(field, rest)?;
                let v = numbers(field, &body, 4)?;
                Surprise::Door {
                    from: pair(&v, 0),
                    to: pair(&v, 2),
                    at: in_range(field, at, 0.0, 3600.0)?,
                }
            }
            "person" => {
                // `…@SPEED` or `…@SPEED@T`: the time they step in, 0 when left out.
                let (body, last) = split_at(field, rest)?;
                let (body, speed, at) = match split_at(field, &body) {
                    Ok((body, speed)) => (body, speed, last),
                    Err(_) => (body, last, 0.0),
                };
                let v = numbers(field, &body, 4)?;
                Surprise::Person {
                    from: pair(&v, 0),
                    to: pair(&v, 2),
                    speed: in_range(field, speed, 0.01, 5.0)?,
                    at: in_range(field, at, 0.0, 3600.0)?,
                }
            }
            "wrong-map" => Surprise::WrongMap {
                missing: rest
                    .split(',')
                    .map(|t| t.trim().parse::<usize>())
                    .collect::<Result<_, _>>()
                    .map_err(|_| {
                        FieldError::new(
                            field,
                            format!("`{rest}` should be obstacle numbers separated by commas"),
                        )
                    })?,
            },
            "noise" => Surprise::Noise {
                sd: in_range(field, numbers(field, rest, 1)?[0], 0.0, 1.0)?,
            },
            "goal" => {
                let (body, at) = split_at(field, rest)?;
                let v = numbers(field, &body, 2)?;
                Surprise::Goal {
                    to: pair(&v, 0),
                    at: in_range(field, at, 0.0, 3600.0)?,
                }
            }
            "glass" => {
                let v = numbers(field, rest, 4)?;
                Surprise::Glass {
                    from: pair(&v, 0),
                    to: pair(&v, 2),
                }
            }
            other => {
                return Err(FieldError::new(
                    field,
                    format!(
                        "`{other}` is not a surprise: door, person, wrong-map, noise, goal or glass"
                    ),
                ));
            }
        })
    }

    /// The same surprise happening at `t` (a door closing, a person
    /// stepping in, the goal moving); the others have no time.
    pub fn at(self, t: f64) -> Self {
        match self {
            Surprise::Door { from, to, .. } => Surprise::Door { from, to, at: t },
            Surprise::Person {
                from, to, speed, ..
            } => Surprise::Person {
                from,
                to,
                speed,
                at: t,
            },
            Surprise::Goal { to, .. } => Surprise::Goal { to, at: t },
            other => other,
        }
    }

    /// The surprise as the command line writes it (`door:5,1,5,2@6`);
    /// [`Surprise::parse`] reads it back.
    pub fn spec(&self) -> String {
        let list = |v: &[f64]| {
            v.iter()
                .map(|x| x.to_string())
                .collect::<Vec<_>>()
                .join(",")
        };
        match self {
            Surprise::Door { from, to, at } => {
                format!("door:{}@{at}", list(&[from[0], from[1], to[0], to[1]]))
            }
            Surprise::Person {
                from,
                to,
                speed,
                at,
            } => format!(
                "person:{}@{speed}@{at}",
                list(&[from[0], from[1], to[0], to[1]])
            ),
            Surprise::WrongMap { missing } => format!(
                "wrong-map:{}",
                missing
                    .iter()
                    .map(usize::to_string)
                    .collect::<Vec<_>>()
                    .join(",")
            ),
            Surprise::Noise { sd } => format!("noise:{sd}"),
            Surprise::Goal { to, at } => format!("goal:{}@{at}", list(to)),
            Surprise::Glass { from, to } => {
                format!("glass:{}", list(&[from[0], from[1], to[0], to[1]]))
            }
        }
    }

    /// Check the surprise against `world`: points inside, obstacles that exist.
    pub fn check(&self, field: &str, world: &World) -> Result<(), FieldError> {
        let inside = |p: [f64; 2]| {
            if world.bounds.contains(p[0], p[1]) {
                Ok(())
            } else {
                Err(FieldError::new(
                    field,
                    format!("({}, {}) is outside the world", p[0], p[1]),
                ))
            }
        };
        match self {
            Surprise::Door { from, to, .. }
            | Surprise::Person { from, to, .. }
            | Surprise::Glass { from, to } => {
                inside(*from)?;
                inside(*to)
            }
            Surprise::Goal { to, .. } => inside(*to),
            Surprise::WrongMap { missing } => {
                match missing.iter().find(|&&k| k >= world.obstacles.len()) {
                    Some(k) => Err(FieldError::new(
                        field,
                        format!(
                            "the world has no obstacle {k} (it has {})",
                            world.obstacles.len()
                        ),
                    )),
                    None => Ok(()),
                }
            }
            Surprise::Noise { .. } => Ok(()),
        }
    }

    /// Put the surprise into the world and sensors (a moved goal is the
    /// arena's to script; a wrong map is the robots').
    pub fn apply(&self, world: &mut World, sensors: &mut Sensors) {
        let v = |p: [f64; 2]| Vec2::new(p[0], p[1]);
        match self {
            Surprise::Door { from, to, at } => world.obstacles.push(
                Obstacle::new(Shape::Wall {
                    from: v(*from),
                    to: v(*to),
                    thickness: 0.1,
                })
                .appearing_at(*at),
            ),
            Surprise::Person {
                from,
                to,
                speed,
                at,
            } => world.obstacles.push(
                Obstacle::new(Shape::Disc {
                    centre: v(*from),
                    radius: PERSON_RADIUS,
                })
                .moving(Script::new(vec![v(*from), v(*to)], *speed, Repeat::Once))
                .appearing_at(*at),
            ),
            Surprise::Glass { from, to } => {
                world.obstacles.push(
                    Obstacle::new(Shape::Wall {
                        from: v(*from),
                        to: v(*to),
                        thickness: 0.05,
                    })
                    .glazed(),
                );
                if let Some(g) = world.goal {
                    world.lights.push(Light {
                        x: g.x,
                        y: g.y,
                        intensity: 1.0,
                    });
                }
            }
            Surprise::Noise { sd } => {
                if let Some(r) = sensors.rays.as_mut() {
                    r.noise = *sd;
                }
            }
            Surprise::WrongMap { .. } | Surprise::Goal { .. } => {}
        }
    }
}
