//! World files: the contract's format (bounds, robot radius, circles,
//! polygons, walls) extended with a start pose, a goal, lights, and
//! obstacles that move along a path or appear at a time.

use kinolab_common::error::{from_json, non_negative, positive};
use serde::{Deserialize, Serialize};

use crate::obstacle::{Obstacle, Repeat, Script, Shape};
use crate::world::{Light, World};
use crate::{FieldError, Pose, Rect, Vec2};

#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a world file (an object with `bounds`)"
)]
struct WorldFile {
    #[serde(default)]
    name: String,
    bounds: [f64; 4],
    #[serde(default = "default_radius")]
    robot_radius: f64,
    #[serde(default)]
    obstacles: Vec<ObstacleEntry>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    start: Option<StartEntry>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    goal: Option<PointEntry>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    lights: Vec<Light>,
}

fn default_radius() -> f64 {
    0.2
}

#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct StartEntry {
    x: f64,
    y: f64,
    #[serde(default)]
    theta_deg: f64,
}

#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct PointEntry {
    x: f64,
    y: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
enum KindName {
    Circle,
    Polygon,
    Wall,
}

#[derive(Debug, Clone, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct ObstacleEntry {
    kind: Option<KindName>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    x: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    y: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    radius: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    points: Option<Vec<[f64; 2]>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    from: Option<[f64; 2]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    to: Option<[f64; 2]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    thickness: Option<f64>,
    /// Waypoints the obstacle's anchor moves through after its start place.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    path: Option<Vec<[f64; 2]>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    speed: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    repeat: Option<Repeat>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    appear_at: Option<f64>,
    /// Glass: seen through by light and range sensors.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    glass: Option<bool>,
}

fn point(field: &str, q: [f64; 2]) -> Result<Vec2, FieldError> {
    for (i, v) in q.iter().enumerate() {
        kinolab_common::error::finite_at(*v, || format!("{field}[{i}]"))?;
    }
    Ok(Vec2::new(q[0], q[1]))
}

fn needs<T>(value: Option<T>, field: String, kind: &str) -> Result<T, FieldError> {
    value.ok_or_else(|| FieldError::new(field, format!("missing: a {kind} needs it")))
}

fn unused<T>(value: &Option<T>, field: String, kind: &str) -> Result<(), FieldError> {
    match value {
        Some(_) => Err(FieldError::new(
            field,
            format!("does not apply to a {kind}"),
        )),
        None => Ok(()),
    }
}

/// Twice the signed area of a polygon (positive when counter-clockwise).
fn twice_area(points: &[Vec2]) -> f64 {
    let n = points.len();
    (0..n).map(|i| points[i].perp(&points[(i + 1) % n])).sum()
}

impl ObstacleEntry {
    /// Refuse shape fields that do not belong to `kind`.
    fn only(&self, at: &str, kind: &str, allowed: &[&str]) -> Result<(), FieldError> {
        let set = [
            ("x", self.x.is_some()),
            ("y", self.y.is_some()),
            ("radius", self.radius.is_some()),
            ("points", self.points.is_some()),
            ("from", self.from.is_some()),
            ("to", self.to.is_some()),
            ("thickness", self.thickness.is_some()),
        ];
        match set.iter().find(|(name, on)| *on && !allowed.contains(name)) {
            Some((name, _)) => Err(FieldError::new(
                format!("{at}.{name}"),
                format!("does not apply to a {kind}"),
            )),
            None => Ok(()),
        }
    }

    fn shape(&self, at: &str) -> Result<Shape, FieldError> {
        let f = |name: &str| format!("{at}.{name}");
        let kind = needs(self.kind, f("kind"), "obstacle")?;
        match kind {
            KindName::Circle => {
                self.only(at, "circle", &["x", "y", "radius"])?;
                let x = kinolab_common::error::finite(f("x"), needs(self.x, f("x"), "circle")?)?;
                let y = kinolab_common::error::finite(f("y"), needs(self.y, f("y"), "circle")?)?;
                let radius = positive(f("radius"), needs(self.radius, f("radius"), "circle")?)?;
                Ok(Shape::Disc {
                    centre: Vec2::new(x, y),
                    radius,
                })
            }
            KindName::Polygon => {
                self.only(at, "polygon", &["points"])?;
                let raw = needs(self.points.as_ref(), f("points"), "polygon")?;
                if raw.len() < 3 {
                    return Err(FieldError::new(
                        f("points"),
                        format!("a polygon needs at least three points, got {}", raw.len()),
                    ));
                }
                let points = raw
                    .iter()
                    .enumerate()
                    .map(|(i, q)| point(&format!("{at}.points[{i}]"), *q))
                    .collect::<Result<Vec<_>, _>>()?;
                if twice_area(&points).abs() < 1e-12 {
                    return Err(FieldError::new(
                        f("points"),
                        "the polygon has no area (its points are in a line)",
                    ));
                }
                Ok(Shape::Polygon { points })
            }
            KindName::Wall => {
                self.only(at, "wall", &["from", "to", "thickness"])?;
                let from = point(&f("from"), needs(self.from, f("from"), "wall")?)?;
                let to = point(&f("to"), needs(self.to, f("to"), "wall")?)?;
                let thickness = non_negative(f("thickness"), self.thickness.unwrap_or(0.0))?;
                Ok(Shape::Wall {
                    from,
                    to,
                    thickness,
                })
            }
        }
    }

    fn obstacle(&self, at: &str) -> Result<Obstacle, FieldError> {
        let f = |name: &str| format!("{at}.{name}");
        let shape = self.shape(at)?;
        let mut o = Obstacle::new(shape.clone());
        if let Some(path) = &self.path {
            let mut points = vec![shape.anchor()];
            for (i, q) in path.iter().enumerate() {
                points.push(point(&format!("{at}.path[{i}]"), *q)?);
            }
            let speed = positive(
                f("speed"),
                needs(self.speed, f("speed"), "moving obstacle")?,
            )?;
            o = o.moving(Script::new(points, speed, self.repeat.unwrap_or_default()));
        } else {
            unused(
                &self.speed,
                f("speed"),
                "standing obstacle (give it a `path`)",
            )?;
            unused(
                &self.repeat,
                f("repeat"),
                "standing obstacle (give it a `path`)",
            )?;
        }
        if let Some(t) = self.appear_at {
            o = o.appearing_at(non_negative(f("appear_at"), t)?);
        }
        if self.glass == Some(true) {
            o = o.glazed();
        }
        Ok(o)
    }

    fn from_obstacle(o: &Obstacle) -> Self {
        let mut e = match &o.shape {
            Shape::Disc { centre, radius } => Self {
                kind: Some(KindName::Circle),
                x: Some(centre.x),
                y: Some(centre.y),
                radius: Some(*radius),
                ..Self::default()
            },
            Shape::Polygon { points } => Self {
                kind: Some(KindName::Polygon),
                points: Some(points.iter().map(|q| [q.x, q.y]).collect()),
                ..Self::default()
            },
            Shape::Wall {
                from,
                to,
                thickness,
            } => Self {
                kind: Some(KindName::Wall),
                from: Some([from.x, from.y]),
                to: Some([to.x, to.y]),
                thickness: Some(*thickness),
                ..Self::default()
            },
        };
        if let Some(s) = &o.script {
            e.path = Some(s.points.iter().skip(1).map(|q| [q.x, q.y]).collect());
            e.speed = Some(s.speed);
            e.repeat = Some(s.repeat);
        }
        if o.appear_at > 0.0 {
            e.appear_at = Some(o.appear_at);
        }
        e.glass = o.glass.then_some(true);
        e
    }
}

impl World {
    /// Read a world file. Errors name the JSON path of the bad field.
    pub fn from_json(text: &str) -> Result<Self, FieldError> {
        let file: WorldFile = from_json(text)?;
        World::from_file(file)
    }

    /// Read a world given as an already-parsed JSON value (a run file's
    /// `world`).
    pub fn from_value(value: serde_json::Value) -> Result<Self, FieldError> {
        World::from_json(&value.to_string())
    }

    fn from_file(file: WorldFile) -> Result<Self, FieldError> {
        let bounds = Rect::new("bounds", file.bounds)?;
        let robot_radius = non_negative("robot_radius", file.robot_radius)?;
        let obstacles = file
            .obstacles
            .iter()
            .enumerate()
            .map(|(i, e)| e.obstacle(&format!("obstacles[{i}]")))
            .collect::<Result<Vec<_>, _>>()?;
        let inside = |field: &str, x: f64, y: f64| -> Result<Vec2, FieldError> {
            let q = point(field, [x, y])?;
            if bounds.contains(q.x, q.y) {
                Ok(q)
            } else {
                Err(FieldError::new(
                    field,
                    format!("({x}, {y}) is outside the bounds"),
                ))
            }
        };
        let mut world = World::empty(file.name, bounds);
        world.robot_radius = robot_radius;
        world.obstacles = obstacles;
        if let Some(s) = file.start {
            let q = inside("start", s.x, s.y)?;
            let theta = kinolab_common::error::finite("start.theta_deg", s.theta_deg)?.to_radians();
            world.start = Pose::new(q.x, q.y, theta);
        }
        if let Some(g) = file.goal {
            world.goal = Some(inside("goal", g.x, g.y)?);
        }
        for (i, l) in file.lights.iter().enumerate() {
            inside(&format!("lights[{i}]"), l.x, l.y)?;
            non_negative(format!("lights[{i}].intensity"), l.intensity)?;
        }
        world.lights = file.lights;
        Ok(world)
    }

    /// The world file for this world, pretty-printed.
    pub fn to_json(&self) -> String {
        let file = WorldFile {
            name: self.name.clone(),
            bounds: self.bounds.into(),
            robot_radius: self.robot_radius,
            obstacles: self
                .obstacles
                .iter()
                .map(ObstacleEntry::from_obstacle)
                .collect(),
            start: Some(StartEntry {
                x: self.start.x,
                y: self.start.y,
                theta_deg: self.start.theta.to_degrees(),
            }),
            goal: self.goal.map(|g| PointEntry { x: g.x, y: g.y }),
            lights: self.lights.clone(),
        };
        serde_json::to_string_pretty(&file).unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TWO_ROOMS: &str = r#"{
      "name": "two-rooms",
      "bounds": [0.0, 0.0, 10.0, 6.0],
      "robot_radius": 0.2,
      "obstacles": [
        { "kind": "circle", "x": 3.0, "y": 3.0, "radius": 0.5 },
        { "kind": "polygon", "points": [[5, 0], [5.2, 0], [5.2, 4], [5, 4]] },
        { "kind": "wall", "from": [7, 2], "to": [7, 6], "thickness": 0.1 }
      ]
    }"#;

    #[test]
    fn the_contract_example_reads_and_round_trips() {
        let w = World::from_json(TWO_ROOMS).unwrap();
        assert_eq!(w.obstacles.len(), 3);
        assert_eq!(w.robot_radius, 0.2);
        let again = World::from_json(&w.to_json()).unwrap();
        assert_eq!(again, w);
    }

    #[test]
    fn moving_obstacles_read_and_round_trip() {
        let text = r#"{ "bounds": [0, 0, 5, 5], "start": {"x": 1, "y": 1, "theta_deg": 90},
            "goal": {"x": 4, "y": 4}, "lights": [{"x": 2, "y": 2, "intensity": 3}],
            "obstacles": [{ "kind": "circle", "x": 1, "y": 3, "radius": 0.2,
                            "path": [[4, 3]], "speed": 0.5, "repeat": "loop", "appear_at": 2 },
                          { "kind": "wall", "from": [3, 0], "to": [3, 2], "glass": true }] }"#;
        let w = World::from_json(text).unwrap();
        assert!((w.start.theta - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
        assert!(!w.obstacles[0].present(1.0));
        assert!((w.obstacles[0].offset(4.0).x - 1.0).abs() < 1e-12);
        assert_eq!(World::from_json(&w.to_json()).unwrap(), w);
    }

    #[test]
    fn bad_worlds_name_the_field() {
        let cases = [
            (
                r#"{"bounds": [0, 0, 1, 1], "obstacles": [{"kind": "circle", "x": 0, "y": 0, "radius": -1}]}"#,
                "obstacles[0].radius",
            ),
            (
                r#"{"bounds": [0, 0, 1, 1], "obstacles": [{"kind": "polygon", "points": [[0, 0], [1, 1]]}]}"#,
                "obstacles[0].points",
            ),
            (
                r#"{"bounds": [0, 0, 1, 1], "obstacles": [{"kind": "polygon", "points": [[0, 0], [1, 1], [2, 2]]}]}"#,
                "obstacles[0].points",
            ),
            (
                r#"{"bounds": [0, 0, 1, 1], "obstacles": [{"kind": "wall", "from": [0, 0]}]}"#,
                "obstacles[0].to",
            ),
            (
                r#"{"bounds": [0, 0, 1, 1], "obstacles": [{"kind": "wall", "from": [0, 0], "to": [1, 0], "radius": 1}]}"#,
                "obstacles[0].radius",
            ),
            (
                r#"{"bounds": [0, 0, 1, 1], "obstacles": [{"kind": "circle", "x": 0, "y": 0, "radius": 1, "path": [[1, 1]]}]}"#,
                "obstacles[0].speed",
            ),
            (
                r#"{"bounds": [0, 0, 1, 1], "obstacles": [{"kind": "circle", "x": 0, "y": 0, "radius": 1, "colour": 1}]}"#,
                "obstacles[0].colour",
            ),
            (r#"{"bounds": [1, 0, 0, 1]}"#, "bounds"),
            (
                r#"{"bounds": [0, 0, 1, 1], "goal": {"x": 2, "y": 0}}"#,
                "goal",
            ),
            (
                r#"{"bounds": [0, 0, 1, 1], "robot_radius": -0.1}"#,
                "robot_radius",
            ),
            (
                r#"{"bounds": [0, 0, 1, 1], "lights": [{"x": 0.5, "y": 0.5, "intensity": -1}]}"#,
                "lights[0].intensity",
            ),
        ];
        for (text, field) in cases {
            let e = World::from_json(text).unwrap_err();
            assert!(e.field.starts_with(field), "{text}: {e}");
        }
    }
}
