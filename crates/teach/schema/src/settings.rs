//! A widget's settings as one typed struct, read from its checked
//! parameters and written back as a widget block.
//!
//! A widget declares `struct Settings` with one field per parameter of its
//! schema entry (serde names them; `Option` for a parameter with no
//! default), and reads it with [`Params::settings`]: every default, range
//! and allowed value stays in the schema. [`to_params`] writes settings
//! back as the `key: value` lines a lesson would write, so a link can carry
//! them and [`crate::validate`] can check them on the way back in.
//! Choices may be read into enums (a unit variant per allowed value).

use serde::Serialize;
use serde::de::DeserializeOwned;
use serde_json::{Map, Number, Value as Json};

use crate::{Params, Value};

impl Params {
    /// The settings struct `T`, every field from this widget's parameters.
    pub fn settings<T: DeserializeOwned>(&self) -> Result<T, String> {
        serde_json::from_value(self.object()).map_err(|e| self.misfit(&e))
    }

    /// Every parameter as one JSON object (the part of [`Params::settings`]
    /// that does not depend on the struct, kept out of its generic body so
    /// the lab's wasm holds it once rather than once per widget).
    fn object(&self) -> Json {
        let mut object = Map::new();
        for (name, value) in self.values() {
            object.insert(name.to_owned(), json(value));
        }
        Json::Object(object)
    }

    fn misfit(&self, e: &serde_json::Error) -> String {
        format!("widget `{}`: settings do not fit: {e}", self.widget)
    }
}

/// A checked value as JSON for serde.
fn json(value: &Value) -> Json {
    let number = |x: f64| Number::from_f64(x).map_or(Json::Null, Json::Number);
    match value {
        Value::Number(x) => number(*x),
        Value::Integer(n) => Json::from(*n),
        Value::YesNo(b) => Json::Bool(*b),
        Value::Choice(c) => Json::from(*c),
        Value::Text(t) => Json::from(t.as_str()),
        Value::Numbers(v) => Json::Array(v.iter().map(|x| number(*x)).collect()),
        Value::Groups(g) => Json::Array(
            g.iter()
                .map(|v| Json::Array(v.iter().map(|x| number(*x)).collect()))
                .collect(),
        ),
    }
}

/// `settings` of the widget `widget` as the parameter lines of a widget
/// block: `(key, value)` in field order, the values written as a lesson
/// writes them (numbers as Rust prints them, which read back exactly;
/// `yes`/`no`; lists with `,` and groups with `;`). Fields that are `None`
/// or equal to the schema's default are left out, as a lesson leaves them.
pub fn to_params<T: Serialize>(
    widget: &str,
    settings: &T,
) -> Result<Vec<(String, String)>, String> {
    let fields = serde_json::to_value(settings).map_err(|e| e.to_string())?;
    value_to_params(widget, fields)
}

/// [`to_params`] once the settings are JSON (not generic, so it is compiled
/// once for every widget).
fn value_to_params(widget: &str, fields: Json) -> Result<Vec<(String, String)>, String> {
    let schema = crate::find(widget).ok_or_else(|| format!("no widget `{widget}`"))?;
    let defaults = crate::validate(&kinolab_lessons::WidgetSpec {
        name: widget.to_owned(),
        params: Vec::new(),
        line: 0,
    })?;
    let Json::Object(fields) = fields else {
        return Err("settings must be a struct".into());
    };
    let mut out = Vec::with_capacity(fields.len());
    for (key, value) in fields {
        let Some(text) = text(&value).map_err(|e| format!("`{key}`: {e}"))? else {
            continue;
        };
        let default = schema
            .param(&key)
            .and_then(|p| crate::params::parse(p, &text).ok())
            .is_some_and(|v| defaults.get(&key) == Some(&v));
        if !default {
            out.push((key, text));
        }
    }
    Ok(out)
}

/// One value as a lesson writes it; `None` for a field that is not set.
fn text(value: &Json) -> Result<Option<String>, String> {
    let number = |v: &Json| match v {
        Json::Number(n) => Ok(n.to_string()),
        other => Err(format!("`{other}` is not a number")),
    };
    Ok(Some(match value {
        Json::Null => return Ok(None),
        Json::Bool(true) => "yes".to_owned(),
        Json::Bool(false) => "no".to_owned(),
        Json::Number(n) => n.to_string(),
        Json::String(s) => s.clone(),
        Json::Array(items) if items.iter().all(Json::is_array) && !items.is_empty() => items
            .iter()
            .map(|g| {
                g.as_array()
                    .map_or(Ok(Vec::new()), |g| g.iter().map(number).collect())
                    .map(|g: Vec<String>| g.join(","))
            })
            .collect::<Result<Vec<_>, _>>()?
            .join(";"),
        Json::Array(items) => items
            .iter()
            .map(number)
            .collect::<Result<Vec<_>, _>>()?
            .join(","),
        Json::Object(_) => return Err("a parameter cannot hold an object".into()),
    }))
}

#[cfg(test)]
mod tests {
    use serde::Deserialize;

    use crate::validate;

    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    #[serde(rename_all = "kebab-case")]
    enum Task {
        SpotUnstable,
        ReachWithin,
    }

    /// The controller playground's parameters, typed.
    #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
    struct Playground {
        gains: [f64; 3],
        start: Vec<f64>,
        seed: u64,
        #[serde(rename = "forward-only")]
        forward_only: bool,
        task: Option<Task>,
        sets: Vec<[f64; 3]>,
        plan: String,
    }

    use super::*;

    fn params(pairs: &[(&str, &str)]) -> Params {
        let spec = kinolab_lessons::WidgetSpec {
            name: "controller-playground".into(),
            params: pairs
                .iter()
                .map(|(k, v)| ((*k).to_owned(), (*v).to_owned()))
                .collect(),
            line: 1,
        };
        validate(&spec).unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn settings_take_the_schema_defaults_and_the_lesson_values() {
        let s: Playground = params(&[("gains", "3, 9, -2"), ("task", "spot-unstable")])
            .settings()
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(s.gains, [3.0, 9.0, -2.0]);
        assert_eq!(s.start, vec![-1.0, 0.5, 0.0], "the schema's default");
        assert_eq!(s.seed, 1);
        assert!(!s.forward_only);
        assert_eq!(s.task, Some(Task::SpotUnstable));
        assert_eq!(s.sets.len(), 4, "the schema's default");
        assert_eq!(s.plan, "line 1; arc 0.5 90; line 0.5");
    }

    /// Settings written as parameter lines and read back through the schema.
    fn round_trip(s: &Playground) -> (Vec<(String, String)>, Playground) {
        let lines = to_params("controller-playground", s).unwrap_or_else(|e| panic!("{e}"));
        let pairs: Vec<(&str, &str)> = lines
            .iter()
            .map(|(k, v)| (k.as_str(), v.as_str()))
            .collect();
        let back = params(&pairs).settings().unwrap_or_else(|e| panic!("{e}"));
        (lines, back)
    }

    #[test]
    fn settings_round_trip_through_parameter_lines_exactly() {
        let defaults: Playground = params(&[]).settings().unwrap_or_else(|e| panic!("{e}"));
        let s = Playground {
            gains: [0.1, 1.0 / 3.0, -1.5e-3],
            start: vec![-2.25, 0.0625, 91.0],
            seed: 42,
            forward_only: true,
            task: Some(Task::ReachWithin),
            ..defaults.clone()
        };
        let (lines, back) = round_trip(&s);
        assert_eq!(back, s);
        assert!(lines.contains(&("forward-only".into(), "yes".into())));
        assert!(
            !lines.iter().any(|(k, _)| k == "sets" || k == "plan"),
            "defaults are left out: {lines:?}"
        );
        let s = Playground {
            task: Some(Task::SpotUnstable),
            sets: vec![[1.0, 2.0, -1.0], [3.0, 4.0, -0.5]],
            ..defaults.clone()
        };
        let (lines, back) = round_trip(&s);
        assert_eq!(back, s);
        assert!(lines.contains(&("sets".into(), "1.0,2.0,-1.0;3.0,4.0,-0.5".into())));
        assert_eq!(round_trip(&defaults), (Vec::new(), defaults));
    }

    #[test]
    fn values_outside_the_schema_are_refused_by_name() {
        let spec = kinolab_lessons::WidgetSpec {
            name: "controller-playground".into(),
            params: vec![("gains".into(), "1e308, 8, -1.5".into())],
            line: 1,
        };
        let e = validate(&spec).unwrap_err();
        assert!(e.starts_with("parameter `gains` must be 3 numbers"), "{e}");
    }
}
