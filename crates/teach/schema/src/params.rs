//! A widget block's parameters, checked against its schema and typed.

use kinolab_lessons::WidgetSpec;

use crate::{Kind, Param, WidgetSchema};

/// A checked parameter value.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    Number(f64),
    Integer(i64),
    YesNo(bool),
    Choice(&'static str),
    Numbers(Vec<f64>),
    Groups(Vec<Vec<f64>>),
    Text(String),
}

/// Every parameter of one widget block: the lesson's value, or the
/// schema's default, or nothing; each already checked.
#[derive(Debug, Clone, PartialEq)]
pub struct Params {
    pub widget: &'static str,
    values: Vec<(&'static str, Option<Value>, bool)>,
}

impl Params {
    /// Check `spec` against `schema`: unknown and repeated keys, and each
    /// value against its kind; absent ones take their default.
    pub(crate) fn read(schema: &'static WidgetSchema, spec: &WidgetSpec) -> Result<Self, String> {
        for (i, (key, _)) in spec.params.iter().enumerate() {
            if schema.param(key).is_none() {
                let known: Vec<&str> = schema.params.iter().map(|p| p.name).collect();
                return Err(format!(
                    "widget `{}` has no parameter `{key}` (it takes: {})",
                    schema.name,
                    if known.is_empty() {
                        "none".to_owned()
                    } else {
                        known.join(", ")
                    }
                ));
            }
            if spec.params[..i].iter().any(|(k, _)| k == key) {
                return Err(format!("parameter `{key}` is given twice"));
            }
        }
        let mut values = Vec::with_capacity(schema.params.len());
        for param in schema.params {
            let given = spec.param(param.name);
            let value = match given.or(param.default) {
                Some(text) => Some(parse(param, text).map_err(|e| {
                    if given.is_some() {
                        format!("parameter `{}` {e}, found `{text}`", param.name)
                    } else {
                        format!("the default of `{}` is wrong: {e}", param.name)
                    }
                })?),
                None => None,
            };
            values.push((param.name, value, given.is_some()));
        }
        Ok(Self {
            widget: schema.name,
            values,
        })
    }

    /// The checked value of `name` (given or default), if any.
    pub fn get(&self, name: &str) -> Option<&Value> {
        self.values
            .iter()
            .find(|(n, _, _)| *n == name)
            .and_then(|(_, v, _)| v.as_ref())
    }

    /// Every parameter that has a value (given or default), by name.
    pub fn values(&self) -> impl Iterator<Item = (&'static str, &Value)> {
        self.values
            .iter()
            .filter_map(|(name, value, _)| value.as_ref().map(|v| (*name, v)))
    }

    /// Whether the lesson wrote this parameter itself.
    pub fn given(&self, name: &str) -> bool {
        self.values.iter().any(|(n, _, given)| *n == name && *given)
    }

    pub fn number(&self, name: &str) -> Option<f64> {
        match self.get(name)? {
            Value::Number(v) => Some(*v),
            Value::Integer(v) => Some(*v as f64),
            _ => None,
        }
    }

    pub fn integer(&self, name: &str) -> Option<i64> {
        match self.get(name)? {
            Value::Integer(v) => Some(*v),
            _ => None,
        }
    }

    /// `yes` → true; `no` or absent → false.
    pub fn yes(&self, name: &str) -> bool {
        matches!(self.get(name), Some(Value::YesNo(true)))
    }

    pub fn choice(&self, name: &str) -> Option<&'static str> {
        match self.get(name)? {
            Value::Choice(v) => Some(v),
            _ => None,
        }
    }

    pub fn numbers(&self, name: &str) -> Option<&[f64]> {
        match self.get(name)? {
            Value::Numbers(v) => Some(v),
            _ => None,
        }
    }

    pub fn groups(&self, name: &str) -> Option<&[Vec<f64>]> {
        match self.get(name)? {
            Value::Groups(v) => Some(v),
            _ => None,
        }
    }

    pub fn text(&self, name: &str) -> Option<&str> {
        match self.get(name)? {
            Value::Text(v) => Some(v),
            _ => None,
        }
    }
}

/// One value checked against its kind; the error completes "parameter
/// `x` …".
pub(crate) fn parse(param: &Param, text: &str) -> Result<Value, String> {
    let text = text.trim();
    match &param.kind {
        Kind::Number { min, max } => match number(text) {
            Some(v) if (*min..=*max).contains(&v) => Ok(Value::Number(v)),
            _ => Err(format!("must be a number from {min} to {max}")),
        },
        Kind::Integer { min, max } => match text.parse::<i64>() {
            Ok(v) if (*min..=*max).contains(&v) => Ok(Value::Integer(v)),
            _ => Err(format!("must be a whole number from {min} to {max}")),
        },
        Kind::YesNo => match text {
            "yes" => Ok(Value::YesNo(true)),
            "no" => Ok(Value::YesNo(false)),
            _ => Err("must be yes or no".into()),
        },
        Kind::Choice { options } => options
            .iter()
            .find(|o| **o == text)
            .map(|o| Value::Choice(o))
            .ok_or_else(|| format!("must be one of {}", options.join(", "))),
        Kind::Numbers {
            min_count,
            max_count,
            min,
            max,
        } => numbers(text, *min_count, *max_count, *min, *max).map(Value::Numbers),
        Kind::Groups {
            size,
            min_groups,
            min,
            max,
        } => {
            let groups: Vec<Vec<f64>> = text
                .split(';')
                .filter(|g| !g.trim().is_empty())
                .map(|g| match size {
                    0 => numbers(g, 1, 64, *min, *max),
                    n => numbers(g, *n, *n, *min, *max),
                })
                .collect::<Result<_, _>>()
                .map_err(|e| format!("takes groups separated by `;`, each of which {e}"))?;
            if groups.len() < *min_groups {
                return Err(format!(
                    "needs at least {min_groups} groups separated by `;`"
                ));
            }
            Ok(Value::Groups(groups))
        }
        Kind::Catalogue { of } => of
            .ids()
            .into_iter()
            .find(|id| *id == text)
            .map(Value::Choice)
            .ok_or_else(|| format!("must be one of {}", of.ids().join(", "))),
        Kind::Text { check, .. } => check(text).map(|()| Value::Text(text.to_owned())),
    }
}

fn number(text: &str) -> Option<f64> {
    text.trim().parse::<f64>().ok().filter(|v| v.is_finite())
}

/// `count` numbers separated by commas, each within `[min, max]`.
fn numbers(
    text: &str,
    min_count: usize,
    max_count: usize,
    min: f64,
    max: f64,
) -> Result<Vec<f64>, String> {
    let count = if min_count == max_count {
        format!("{min_count}")
    } else {
        format!("{min_count} to {max_count}")
    };
    let what = format!("must be {count} numbers from {min} to {max} separated by commas");
    let values: Vec<f64> = text
        .split(',')
        .map(number)
        .collect::<Option<_>>()
        .ok_or_else(|| what.clone())?;
    if values.len() < min_count || values.len() > max_count {
        return Err(what);
    }
    if values.iter().any(|v| !(min..=max).contains(v)) {
        return Err(what);
    }
    Ok(values)
}
