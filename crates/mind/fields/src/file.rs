//! Field files, as the command-line contract writes them, and their
//! fields on one line, as a lesson (or a link) writes them.

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

/// A field's kind, as field files name it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Kind {
    Uniform,
    Attractive,
    Repulsive,
    Tangential,
    Perpendicular,
    /// A learner's: `field(x, y)` → `[fx, fy]`, in `source`.
    Script,
}

/// A field's profile, as field files name it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ProfileName {
    Constant,
    Linear,
    Exponential,
    Potential,
}

/// One entry of a field file's `fields`, as written (every number as the
/// file gives it, so a field written and read back is the same field).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Entry {
    pub kind: Option<Kind>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub x: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub y: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub direction_deg: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub from: Option<[f64; 2]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub to: Option<[f64; 2]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gain: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub profile: Option<ProfileName>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub range: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lambda: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spin: Option<Spin>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sense: Option<Sense>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub source: Option<String>,
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

    /// The primitive this entry makes, checked; errors name the field.
    pub fn primitive(&self) -> Result<Primitive, FieldError> {
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

    /// The entry a field file writes for `p`.
    pub fn from_primitive(p: &Primitive) -> Self {
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

/// A field file with these entries, pretty-printed: the same text the
/// command line reads.
pub fn write(name: &str, goal: Option<[f64; 2]>, entries: &[Entry]) -> String {
    let file = FieldFile {
        name: name.to_owned(),
        goal: goal.map(|[x, y]| Point { x, y }),
        fields: entries.to_vec(),
    };
    serde_json::to_string_pretty(&file).unwrap_or_default()
}

/// A field file's goal and entries, as written (not yet checked).
pub fn entries(text: &str) -> Result<(Option<[f64; 2]>, Vec<Entry>), FieldError> {
    let file: FieldFile = from_json(text)?;
    Ok((file.goal.map(|g| [g.x, g.y]), file.fields))
}

/// The keys of an entry on a line, in the order [`line`] writes them.
const KEYS: [&str; 12] = [
    "x",
    "y",
    "from",
    "to",
    "radius",
    "direction_deg",
    "gain",
    "profile",
    "lambda",
    "range",
    "spin",
    "sense",
];

/// Entries on one line: each its kind and then `key value` pairs with a
/// field file's keys (`from` and `to` as `x,y`), entries separated by `;`:
/// `attractive x 4 y 0 gain 1 profile linear range 1; uniform direction_deg 90 gain 0.2`.
pub fn line(entries: &[Entry]) -> String {
    entries
        .iter()
        .map(|e| {
            let json = serde_json::to_value(e).unwrap_or_default();
            let mut words = vec![word(json.get("kind"))];
            for key in KEYS {
                if let Some(value) = json.get(key) {
                    words.push(key.to_owned());
                    words.push(word(Some(value)));
                }
            }
            words.join(" ")
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// One value as a line writes it.
fn word(value: Option<&serde_json::Value>) -> String {
    match value {
        Some(serde_json::Value::String(s)) => s.clone(),
        Some(serde_json::Value::Array(xy)) => xy
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join(","),
        Some(v) => v.to_string(),
        None => String::new(),
    }
}

/// Read entries written by [`line`]; each is checked as a field file's
/// would be. Errors say which entry and what is wrong.
pub fn from_line(text: &str) -> Result<Vec<Entry>, String> {
    text.split(';')
        .filter(|e| !e.trim().is_empty())
        .enumerate()
        .map(|(i, e)| entry(e).map_err(|m| format!("has field {}: {m}", i + 1)))
        .collect()
}

/// One entry of a line, checked.
fn entry(text: &str) -> Result<Entry, String> {
    let mut words = text.split_whitespace();
    let mut object = serde_json::Map::new();
    let kind = words.next().unwrap_or_default();
    object.insert("kind".into(), kind.into());
    while let Some(key) = words.next() {
        if !KEYS.contains(&key) {
            return Err(format!("`{key}` is not one of {}", KEYS.join(", ")));
        }
        let value = words
            .next()
            .ok_or_else(|| format!("`{key}` has no value"))?;
        let number = |v: &str| {
            v.parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .and_then(serde_json::Number::from_f64)
                .ok_or_else(|| format!("`{key}` must be a number, found `{v}`"))
        };
        let json = match key {
            "profile" | "spin" | "sense" => serde_json::Value::from(value),
            "from" | "to" => {
                let xy: Vec<&str> = value.split(',').collect();
                let [x, y] = xy.as_slice() else {
                    return Err(format!("`{key}` must be x,y, found `{value}`"));
                };
                serde_json::json!([number(x)?, number(y)?])
            }
            _ => serde_json::Value::Number(number(value)?),
        };
        if object.insert(key.to_owned(), json).is_some() {
            return Err(format!("`{key}` is given twice"));
        }
    }
    let e: Entry = serde_json::from_value(serde_json::Value::Object(object))
        .map_err(|_| format!("`{text}` is not a field (a kind, then keys and values)"))?;
    e.primitive().map_err(|err| err.to_string())?;
    Ok(e)
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
    fn fields_on_a_line_read_back_as_written() {
        let file: FieldFile = serde_json::from_str(CONTRACT).unwrap();
        let text = line(&file.fields);
        assert!(
            text.starts_with("attractive x 4.0 y 0.0 gain 1.0 profile linear range 1.0; "),
            "{text}"
        );
        assert!(
            text.contains("perpendicular from 0.0,-1.0 to 5.0,-1.0"),
            "{text}"
        );
        let back = from_line(&text).unwrap();
        assert_eq!(back, file.fields);
        let again = write("goal-behind-a-rock", Some([4.0, 0.0]), &back);
        assert_eq!(
            Field::from_json(&again).unwrap(),
            Field::from_json(CONTRACT).unwrap()
        );
        for (bad, says) in [
            ("vortex x 1 y 1", "not a field"),
            ("attractive x 1 y", "has no value"),
            ("attractive x 1 x 2 y 0", "twice"),
            ("attractive x 1 y 0 colour red", "not one of"),
            ("repulsive x 1 y 0 radius -1 range 1", "radius"),
            ("perpendicular from 1 to 2,2", "x,y"),
            ("uniform direction_deg NaN", "number"),
        ] {
            let e = from_line(bad).unwrap_err();
            assert!(e.contains(says), "{bad}: {e}");
        }
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
