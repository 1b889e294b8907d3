//! Field files, as the command-line contract writes them.

use kinolab_common::error::from_json;
use serde::{Deserialize, Serialize};

use crate::primitive::{Primitive, Profile, Sense, Source, Spin};
use crate::{Field, FieldError, Vec2};

#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a field file (an object with `fields`)"
)]
struct FieldFile {
    #[serde(default)]
    name: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    goal: Option<Point>,
    fields: Vec<Entry>,
}

#[derive(Debug, Clone, Copy, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Point {
    x: f64,
    y: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
enum Kind {
    Uniform,
    Attractive,
    Repulsive,
    Tangential,
    Perpendicular,
    /// A learner's: `field(x, y)` → `[fx, fy]`, in `source`.
    Script,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
enum ProfileName {
    Constant,
    Linear,
    Exponential,
    Potential,
}

#[derive(Debug, Clone, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct Entry {
    kind: Option<Kind>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    x: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    y: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    radius: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    direction_deg: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    from: Option<[f64; 2]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    to: Option<[f64; 2]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    gain: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    profile: Option<ProfileName>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    range: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    lambda: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    spin: Option<Spin>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    sense: Option<Sense>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    source: Option<String>,
}

/// A script entry read as a built-in primitive.
fn not_built_in() -> FieldError {
    FieldError::new("kind", "a script is not a built-in primitive")
}

impl Entry {
    /// The fields that are set, by name.
    fn set(&self) -> [(&'static str, bool); 8] {
        [
            ("x", self.x.is_some()),
            ("y", self.y.is_some()),
            ("radius", self.radius.is_some()),
            ("direction_deg", self.direction_deg.is_some()),
            ("from", self.from.is_some()),
            ("to", self.to.is_some()),
            ("spin", self.spin.is_some()),
            ("sense", self.sense.is_some()),
        ]
    }

    /// A learner's primitive: only `source` may be set.
    fn custom(&self) -> Result<crate::custom::Custom, FieldError> {
        if let Some((field, _)) = self.set().iter().find(|(_, on)| *on) {
            return Err(FieldError::new(
                *field,
                "a script field takes only `source`",
            ));
        }
        let source = self
            .source
            .as_deref()
            .ok_or_else(|| FieldError::new("source", "missing: a script field needs its code"))?;
        crate::custom::Custom::new(source).map_err(|e| FieldError::new("source", e.to_string()))
    }

    fn primitive(&self) -> Result<Primitive, FieldError> {
        if self.source.is_some() {
            return Err(FieldError::new("source", "only a `script` field has code"));
        }
        let kind = self
            .kind
            .ok_or_else(|| FieldError::new("kind", "missing: every field needs a kind"))?;
        let allowed: &[&str] = match kind {
            Kind::Script => return Err(not_built_in()),
            Kind::Uniform => &["direction_deg"],
            Kind::Attractive => &["x", "y"],
            Kind::Repulsive => &["x", "y", "radius"],
            Kind::Tangential => &["x", "y", "radius", "spin"],
            Kind::Perpendicular => &["from", "to", "sense"],
        };
        let name = format!("{kind:?}").to_lowercase();
        if let Some((field, _)) = self
            .set()
            .iter()
            .find(|(f, on)| *on && !allowed.contains(f))
        {
            return Err(FieldError::new(
                *field,
                format!("does not apply to a {name} field"),
            ));
        }
        if self.lambda.is_some() && self.profile != Some(ProfileName::Exponential) {
            return Err(FieldError::new(
                "lambda",
                "only the `exponential` profile takes a decay length",
            ));
        }
        let need = |v: Option<f64>, field: &str| {
            v.ok_or_else(|| FieldError::new(field, format!("missing: a {name} field needs it")))
        };
        let point = |v: Option<[f64; 2]>, field: &str| -> Result<Vec2, FieldError> {
            let [x, y] = v.ok_or_else(|| {
                FieldError::new(field, format!("missing: a {name} field needs it"))
            })?;
            Ok(Vec2::new(x, y))
        };
        let source = match kind {
            Kind::Script => return Err(not_built_in()),
            Kind::Uniform => Source::Uniform {
                direction: need(self.direction_deg, "direction_deg")?.to_radians(),
            },
            Kind::Attractive => Source::Attractive {
                centre: Vec2::new(need(self.x, "x")?, need(self.y, "y")?),
            },
            Kind::Repulsive => Source::Repulsive {
                centre: Vec2::new(need(self.x, "x")?, need(self.y, "y")?),
                radius: self.radius.unwrap_or(0.0),
            },
            Kind::Tangential => Source::Tangential {
                centre: Vec2::new(need(self.x, "x")?, need(self.y, "y")?),
                radius: self.radius.unwrap_or(0.0),
                spin: self.spin.unwrap_or(Spin::Ccw),
            },
            Kind::Perpendicular => Source::Perpendicular {
                from: point(self.from, "from")?,
                to: point(self.to, "to")?,
                sense: self.sense.unwrap_or(Sense::Away),
            },
        };
        let profile = match self.profile.unwrap_or(ProfileName::Constant) {
            ProfileName::Constant => Profile::Constant,
            ProfileName::Linear => Profile::Linear,
            ProfileName::Potential => Profile::Potential,
            ProfileName::Exponential => Profile::Exponential {
                lambda: need(self.lambda, "lambda")?,
            },
        };
        Primitive::new(source, self.gain.unwrap_or(1.0), profile, self.range)
    }

    fn from_primitive(p: &Primitive) -> Self {
        let mut e = Entry {
            gain: Some(p.gain),
            range: p.range,
            profile: Some(match p.profile {
                Profile::Constant => ProfileName::Constant,
                Profile::Linear => ProfileName::Linear,
                Profile::Exponential { .. } => ProfileName::Exponential,
                Profile::Potential => ProfileName::Potential,
            }),
            lambda: match p.profile {
                Profile::Exponential { lambda } => Some(lambda),
                _ => None,
            },
            ..Entry::default()
        };
        let at = |e: &mut Entry, c: Vec2| {
            e.x = Some(c.x);
            e.y = Some(c.y);
        };
        match p.source {
            Source::Uniform { direction } => {
                e.kind = Some(Kind::Uniform);
                e.direction_deg = Some(direction.to_degrees());
                e.range = None;
            }
            Source::Attractive { centre } => {
                e.kind = Some(Kind::Attractive);
                at(&mut e, centre);
            }
            Source::Repulsive { centre, radius } => {
                e.kind = Some(Kind::Repulsive);
                at(&mut e, centre);
                e.radius = Some(radius);
            }
            Source::Tangential {
                centre,
                radius,
                spin,
            } => {
                e.kind = Some(Kind::Tangential);
                at(&mut e, centre);
                e.radius = Some(radius);
                e.spin = Some(spin);
            }
            Source::Perpendicular { from, to, sense } => {
                e.kind = Some(Kind::Perpendicular);
                e.from = Some([from.x, from.y]);
                e.to = Some([to.x, to.y]);
                e.sense = Some(sense);
            }
        }
        e
    }
}

impl Field {
    /// Read a field file. Errors name the JSON path of the bad field.
    pub fn from_json(text: &str) -> Result<Self, FieldError> {
        let file: FieldFile = from_json(text)?;
        let mut primitives = Vec::new();
        let mut custom = Vec::new();
        for (i, e) in file.fields.iter().enumerate() {
            let within = |err: FieldError| err.within(&format!("fields[{i}]"));
            if e.kind == Some(Kind::Script) {
                custom.push(e.custom().map_err(within)?);
            } else {
                primitives.push(e.primitive().map_err(within)?);
            }
        }
        let goal = match file.goal {
            Some(g) => {
                kinolab_common::error::finite("goal.x", g.x)?;
                kinolab_common::error::finite("goal.y", g.y)?;
                Some(Vec2::new(g.x, g.y))
            }
            None => None,
        };
        Ok(Field {
            custom,
            ..Field::new(file.name, goal, primitives)
        })
    }

    /// The field file for this field, pretty-printed.
    pub fn to_json(&self) -> String {
        let file = FieldFile {
            name: self.name.clone(),
            goal: self.goal.map(|g| Point { x: g.x, y: g.y }),
            fields: self
                .primitives
                .iter()
                .map(Entry::from_primitive)
                .chain(self.custom.iter().map(|c| Entry {
                    kind: Some(Kind::Script),
                    source: Some(c.source.clone()),
                    ..Entry::default()
                }))
                .collect(),
        };
        serde_json::to_string_pretty(&file).unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    pub(crate) const CONTRACT: &str = r#"{
      "name": "goal-behind-a-rock",
      "goal": { "x": 4.0, "y": 0.0 },
      "fields": [
        { "kind": "attractive", "x": 4.0, "y": 0.0, "gain": 1.0, "profile": "linear", "range": 1.0 },
        { "kind": "repulsive", "x": 2.0, "y": 0.0, "radius": 0.3, "gain": 2.0, "profile": "linear", "range": 1.0 },
        { "kind": "tangential", "x": 2.0, "y": 0.0, "radius": 0.3, "gain": 0.5, "profile": "exponential", "lambda": 0.4, "range": 2.0, "spin": "ccw" },
        { "kind": "uniform", "direction_deg": 90, "gain": 0.2 },
        { "kind": "perpendicular", "from": [0.0, -1.0], "to": [5.0, -1.0], "gain": 1.0, "profile": "linear", "range": 0.5, "sense": "away" }
      ]
    }"#;

    #[test]
    fn the_contract_example_reads_and_round_trips() {
        let f = Field::from_json(CONTRACT).unwrap();
        assert_eq!(f.primitives.len(), 5);
        assert_eq!(f.goal, Some(Vec2::new(4.0, 0.0)));
        assert_eq!(Field::from_json(&f.to_json()).unwrap(), f);
    }

    #[test]
    fn bad_fields_name_the_field() {
        let cases = [
            (
                r#"{"fields": [{"kind": "repulsive", "x": 0, "y": 0, "gain": 1, "profile": "linear"}]}"#,
                "fields[0].range",
            ),
            (
                r#"{"fields": [{"kind": "repulsive", "x": 0, "y": 0, "gain": 1, "profile": "linear", "range": -1}]}"#,
                "fields[0].range",
            ),
            (
                r#"{"fields": [{"kind": "repulsive", "x": 0, "y": 0, "radius": -0.1, "profile": "constant", "range": 1}]}"#,
                "fields[0].radius",
            ),
            (
                r#"{"fields": [{"kind": "tangential", "x": 0, "y": 0, "profile": "exponential", "range": 1}]}"#,
                "fields[0].lambda",
            ),
            (
                r#"{"fields": [{"kind": "tangential", "x": 0, "y": 0, "profile": "potential", "range": 1}]}"#,
                "fields[0].profile",
            ),
            (
                r#"{"fields": [{"kind": "attractive", "x": 0, "y": 0, "profile": "linear"}]}"#,
                "fields[0].range",
            ),
            (
                r#"{"fields": [{"kind": "attractive", "x": 0, "y": 0, "gain": -2}]}"#,
                "fields[0].gain",
            ),
            (
                r#"{"fields": [{"kind": "uniform", "direction_deg": 0, "spin": "cw"}]}"#,
                "fields[0].spin",
            ),
            (
                r#"{"fields": [{"kind": "uniform"}]}"#,
                "fields[0].direction_deg",
            ),
            (
                r#"{"fields": [{"kind": "perpendicular", "from": [1, 1], "to": [1, 1], "range": 1}]}"#,
                "fields[0].to",
            ),
            (r#"{"fields": [{"kind": "vortex"}]}"#, "fields[0].kind"),
            (
                r#"{"fields": [{"kind": "attractive", "x": 0, "y": 0, "colour": "red"}]}"#,
                "fields[0].colour",
            ),
            (r#"{"goal": {"x": 1}, "fields": []}"#, "goal"),
        ];
        for (text, field) in cases {
            let e = Field::from_json(text).unwrap_err();
            assert!(e.field.starts_with(field), "{text}: {e}");
        }
    }
}
