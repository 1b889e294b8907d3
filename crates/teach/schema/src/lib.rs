//! What a lesson may embed, as data.
//!
//! Every widget is a [`WidgetSchema`]: a name, a one-line summary and its
//! [`Param`]s, each with a [`Kind`] (type and range or allowed values), a
//! default written the way a lesson writes it, and a line of help. The
//! lesson checker ([`check_course`]), the command line, the JS API, the
//! widget gallery and the widgets' own constructors all read this one
//! catalogue ([`widgets`]), so a lesson that names an unknown widget or
//! gives a parameter a bad value is rejected everywhere with the same
//! message, naming the file and line.

mod catalogue;
mod check;
mod params;
pub mod settings;

pub use catalogue::{robot_of, widgets};
pub use check::{check_course, check_lesson};
pub use params::{Params, Value};

use serde::Serialize;

/// A check across a widget's parameters; the error completes "widget `x`: …".
pub type Rules = fn(&Params) -> Result<(), String>;

/// One widget a lesson can embed.
#[derive(Debug, Serialize)]
pub struct WidgetSchema {
    pub name: &'static str,
    /// What a learner does with it, in one line.
    pub summary: &'static str,
    pub params: &'static [Param],
    /// Rules that involve several parameters (or the core's models), run
    /// after each parameter is checked on its own.
    #[serde(skip)]
    pub rules: Option<Rules>,
}

/// One `key: value` line a widget block may have.
#[derive(Debug, Serialize)]
pub struct Param {
    pub name: &'static str,
    pub kind: Kind,
    /// The value when the lesson leaves the line out, as a lesson writes it;
    /// `None` when leaving it out means something of its own (no task, say).
    pub default: Option<&'static str>,
    pub help: &'static str,
}

/// The type of a parameter and what values it takes.
#[derive(Debug, Serialize)]
#[serde(tag = "type", rename_all = "snake_case")]
pub enum Kind {
    /// A number within `[min, max]`.
    Number { min: f64, max: f64 },
    /// A whole number within `[min, max]`.
    Integer { min: i64, max: i64 },
    /// `yes` or `no`.
    YesNo,
    /// One of a fixed list of words.
    Choice { options: &'static [&'static str] },
    /// Numbers separated by commas: from `min_count` to `max_count` of
    /// them, each within `[min, max]`.
    Numbers {
        min_count: usize,
        max_count: usize,
        min: f64,
        max: f64,
    },
    /// Groups of `size` numbers (any size when 0) separated by `;`, at
    /// least `min_groups` of them.
    Groups {
        size: usize,
        min_groups: usize,
        min: f64,
        max: f64,
    },
    /// An id from one of the core's catalogues.
    Catalogue { of: Catalogue },
    /// Text in a small language of its own (a plan, a wheel layout),
    /// checked by the core crate that reads it.
    Text {
        example: &'static str,
        #[serde(skip)]
        check: fn(&str) -> Result<(), String>,
    },
}

/// The core's catalogues a parameter can pick from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Catalogue {
    /// Wheeled robots (`kinolab robots`).
    Robots,
    /// Mechanisms (`catalogue:<id>` model files).
    Mechanisms,
    /// Example worlds for behaviours (`kinolab run` accepts their ids).
    Worlds,
    /// Classic potential fields and their failures.
    Fields,
    /// Graded code exercises (`kinolab script exercises`).
    Exercises,
}

impl Catalogue {
    /// Every id, in catalogue order.
    pub fn ids(self) -> Vec<&'static str> {
        match self {
            Catalogue::Robots => kinolab_wheels::catalogue::CATALOGUE
                .iter()
                .map(|e| e.id)
                .collect(),
            Catalogue::Mechanisms => kinolab_mechanism::catalogue::CATALOGUE
                .iter()
                .map(|(id, _, _)| *id)
                .collect(),
            Catalogue::Worlds => kinolab_world::catalogue::WORLDS
                .iter()
                .map(|(id, _)| *id)
                .collect(),
            Catalogue::Fields => kinolab_fields::catalogue::PRESETS
                .iter()
                .map(|p| p.id)
                .collect(),
            Catalogue::Exercises => kinolab_exercises::all().iter().map(|e| e.id).collect(),
        }
    }
}

impl WidgetSchema {
    /// The parameter called `name`.
    pub fn param(&self, name: &str) -> Option<&'static Param> {
        self.params.iter().find(|p| p.name == name)
    }
}

/// The widget called `name`.
pub fn find(name: &str) -> Option<&'static WidgetSchema> {
    widgets().find(|w| w.name == name)
}

/// Check a widget block on its own: its name, every parameter and the
/// widget's rules. The message does not name the file; the lesson checker
/// adds that.
pub fn validate(spec: &kinolab_lessons::WidgetSpec) -> Result<Params, String> {
    let Some(schema) = find(&spec.name) else {
        let known: Vec<&str> = widgets().map(|w| w.name).collect();
        return Err(format!(
            "there is no widget named `{}` (known widgets: {})",
            spec.name,
            known.join(", ")
        ));
    };
    let params = Params::read(schema, spec)?;
    if let Some(rules) = schema.rules {
        rules(&params).map_err(|e| format!("widget `{}`: {e}", schema.name))?;
    }
    Ok(params)
}

#[cfg(test)]
mod tests {
    use super::*;
    use kinolab_lessons::WidgetSpec;

    fn spec(name: &str, params: &[(&str, &str)]) -> WidgetSpec {
        WidgetSpec {
            name: name.into(),
            params: params
                .iter()
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect(),
            line: 12,
        }
    }

    #[test]
    fn every_widget_accepts_its_defaults_and_names_are_unique() {
        for w in widgets() {
            let p = validate(&spec(w.name, &[])).unwrap_or_else(|e| panic!("{}: {e}", w.name));
            for param in w.params {
                assert_eq!(
                    p.get(param.name).is_some(),
                    param.default.is_some(),
                    "{}",
                    param.name
                );
            }
            assert_eq!(widgets().filter(|o| o.name == w.name).count(), 1);
        }
    }

    #[test]
    fn bad_widgets_and_values_are_named() {
        let e = validate(&spec("flux-capacitor", &[])).unwrap_err();
        assert!(
            e.starts_with("there is no widget named `flux-capacitor`"),
            "{e}"
        );
        assert!(e.contains("support-polygon"), "{e}");
        assert_eq!(
            validate(&spec("leg-events", &[("legs", "many")])).unwrap_err(),
            "parameter `legs` must be a whole number from 1 to 12, found `many`"
        );
        assert_eq!(
            validate(&spec("leg-events", &[("legs", "13")])).unwrap_err(),
            "parameter `legs` must be a whole number from 1 to 12, found `13`"
        );
        let e = validate(&spec("support-polygon", &[("colour", "red")])).unwrap_err();
        assert!(
            e.contains("has no parameter `colour` (it takes: legs, feet, lifted, com)"),
            "{e}"
        );
        let e = validate(&spec("wheel-drive", &[("mode", "fly")])).unwrap_err();
        assert_eq!(
            e,
            "parameter `mode` must be one of twist, wheels, found `fly`"
        );
        let e = validate(&spec("wheel-drive", &[("robot", "hovercraft")])).unwrap_err();
        assert!(
            e.starts_with("parameter `robot` must be one of unicycle,"),
            "{e}"
        );
        let e = validate(&spec(
            "wheel-drive",
            &[("robot", "tricycle"), ("layout", "f,0,0,0.2,0.1")],
        ))
        .unwrap_err();
        assert!(e.contains("not both"), "{e}");
        let e = validate(&spec("controller-playground", &[("plan", "line 1; fly 2")])).unwrap_err();
        assert!(e.contains("segments[1]"), "{e}");
        let e = validate(&spec("controller-playground", &[("gains", "3, 8")])).unwrap_err();
        assert!(e.contains("must be 3 numbers"), "{e}");
        let e = validate(&spec(
            "mechanism-viewer",
            &[("model", "puma560"), ("q", "10, 20")],
        ))
        .unwrap_err();
        assert!(e.contains("`q` needs 6 values"), "{e}");
        let e = validate(&spec("dh-link", &[("row", "3, 0, 0, 0")])).unwrap_err();
        assert!(e.contains("within ±2 m"), "{e}");
        let e = validate(&spec("leg-events", &[("legs", "3"), ("legs", "4")])).unwrap_err();
        assert_eq!(e, "parameter `legs` is given twice");
    }

    #[test]
    fn given_values_are_typed() {
        let p = validate(&spec(
            "controller-playground",
            &[
                ("gains", "3, 9, -2"),
                ("task", "spot-unstable"),
                ("sets", "1,2,-1;3,4,-1"),
            ],
        ))
        .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(p.numbers("gains"), Some(&[3.0, 9.0, -2.0][..]));
        assert_eq!(p.numbers("start"), Some(&[-1.0, 0.5, 0.0][..]), "default");
        assert_eq!(p.choice("task"), Some("spot-unstable"));
        assert_eq!(p.groups("sets").map(<[_]>::len), Some(2));
        assert_eq!(p.integer("seed"), Some(1));
        assert!(!p.yes("forward-only"));
        assert!(p.given("gains") && !p.given("start"));
    }
}
