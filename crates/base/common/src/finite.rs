//! Finding the first number in a report that is not finite.
//!
//! JSON has no NaN or infinity: `serde_json` silently writes `null` for
//! them, so a computation that overflowed would print `"x": null` and look
//! like an answer. [`first_non_finite`] walks any serializable report the
//! way a serializer would and returns the path of the first such number
//! (`final_pose.x`, `matrix[2][3]`), so the caller can refuse to print it.

use std::fmt;

use serde::ser::{self, Serialize};

/// The path of the first NaN or infinite number inside `value`, if any.
pub fn first_non_finite(value: &impl Serialize) -> Option<String> {
    let mut walker = Walker { path: Vec::new() };
    match value.serialize(&mut walker) {
        Ok(()) => None,
        Err(Found(path)) => Some(path),
    }
}

/// The path where a non-finite number was found.
#[derive(Debug)]
struct Found(String);

impl fmt::Display for Found {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "not finite at {}", self.0)
    }
}

impl std::error::Error for Found {}

impl ser::Error for Found {
    fn custom<T: fmt::Display>(msg: T) -> Self {
        Found(msg.to_string())
    }
}

/// One step of a path: a field name or an index.
enum Step {
    Key(String),
    Index(usize),
}

struct Walker {
    path: Vec<Step>,
}

impl Walker {
    fn found(&self) -> Found {
        let mut text = String::new();
        for step in &self.path {
            match step {
                Step::Key(k) if text.is_empty() => text.push_str(k),
                Step::Key(k) => {
                    text.push('.');
                    text.push_str(k);
                }
                Step::Index(i) => text.push_str(&format!("[{i}]")),
            }
        }
        Found(if text.is_empty() {
            "the result".into()
        } else {
            text
        })
    }

    fn number(&self, x: f64) -> Result<(), Found> {
        if x.is_finite() {
            Ok(())
        } else {
            Err(self.found())
        }
    }

    /// Walk `value` one step further down the path.
    fn at<T: Serialize + ?Sized>(&mut self, step: Step, value: &T) -> Result<(), Found> {
        self.path.push(step);
        let result = value.serialize(&mut *self);
        self.path.pop();
        result
    }
}

/// A compound value being walked: counts its items for their indices.
struct Compound<'a> {
    walker: &'a mut Walker,
    next: usize,
}

impl Compound<'_> {
    fn item<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Found> {
        let i = self.next;
        self.next += 1;
        self.walker.at(Step::Index(i), value)
    }

    fn field<T: Serialize + ?Sized>(&mut self, key: &str, value: &T) -> Result<(), Found> {
        self.walker.at(Step::Key(key.to_owned()), value)
    }
}

macro_rules! fine {
    ($($name:ident: $ty:ty),*) => {
        $(fn $name(self, _: $ty) -> Result<(), Found> { Ok(()) })*
    };
}

impl<'a> ser::Serializer for &'a mut Walker {
    type Ok = ();
    type Error = Found;
    type SerializeSeq = Compound<'a>;
    type SerializeTuple = Compound<'a>;
    type SerializeTupleStruct = Compound<'a>;
    type SerializeTupleVariant = Compound<'a>;
    type SerializeMap = Compound<'a>;
    type SerializeStruct = Compound<'a>;
    type SerializeStructVariant = Compound<'a>;

    fine!(serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
          serialize_i64: i64, serialize_u8: u8, serialize_u16: u16, serialize_u32: u32,
          serialize_u64: u64, serialize_char: char, serialize_str: &str, serialize_bytes: &[u8],
          serialize_unit_struct: &'static str);

    fn serialize_f32(self, v: f32) -> Result<(), Found> {
        self.number(f64::from(v))
    }
    fn serialize_f64(self, v: f64) -> Result<(), Found> {
        self.number(v)
    }
    fn serialize_none(self) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_some<T: Serialize + ?Sized>(self, value: &T) -> Result<(), Found> {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_newtype_struct<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        value: &T,
    ) -> Result<(), Found> {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: Serialize + ?Sized>(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
        value: &T,
    ) -> Result<(), Found> {
        self.at(Step::Key(variant.to_owned()), value)
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Compound<'a>, Found> {
        Ok(Compound {
            walker: self,
            next: 0,
        })
    }
    fn serialize_tuple(self, _: usize) -> Result<Compound<'a>, Found> {
        self.serialize_seq(None)
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, Found> {
        self.serialize_seq(None)
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, Found> {
        self.serialize_seq(None)
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Compound<'a>, Found> {
        self.serialize_seq(None)
    }
    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Compound<'a>, Found> {
        self.serialize_seq(None)
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Compound<'a>, Found> {
        self.serialize_seq(None)
    }
}

/// Sequences of every kind: each item walked at its index.
macro_rules! items {
    ($($trait:ident :: $method:ident),*) => {$(
        impl ser::$trait for Compound<'_> {
            type Ok = ();
            type Error = Found;
            fn $method<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Found> {
                self.item(value)
            }
            fn end(self) -> Result<(), Found> {
                Ok(())
            }
        }
    )*};
}

items!(
    SerializeSeq::serialize_element,
    SerializeTuple::serialize_element,
    SerializeTupleStruct::serialize_field,
    SerializeTupleVariant::serialize_field
);

impl ser::SerializeMap for Compound<'_> {
    type Ok = ();
    type Error = Found;
    fn serialize_key<T: Serialize + ?Sized>(&mut self, _: &T) -> Result<(), Found> {
        Ok(())
    }
    fn serialize_value<T: Serialize + ?Sized>(&mut self, value: &T) -> Result<(), Found> {
        self.item(value)
    }
    fn serialize_entry<K: Serialize + ?Sized, V: Serialize + ?Sized>(
        &mut self,
        key: &K,
        value: &V,
    ) -> Result<(), Found> {
        match serde_json::to_value(key) {
            Ok(serde_json::Value::String(k)) => self.field(&k, value),
            _ => self.item(value),
        }
    }
    fn end(self) -> Result<(), Found> {
        Ok(())
    }
}

/// Structs of both kinds: each field walked under its name.
macro_rules! fields {
    ($($trait:ident),*) => {$(
        impl ser::$trait for Compound<'_> {
            type Ok = ();
            type Error = Found;
            fn serialize_field<T: Serialize + ?Sized>(
                &mut self,
                key: &'static str,
                value: &T,
            ) -> Result<(), Found> {
                self.field(key, value)
            }
            fn end(self) -> Result<(), Found> {
                Ok(())
            }
        }
    )*};
}

fields!(SerializeStruct, SerializeStructVariant);

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;

    #[derive(serde::Serialize)]
    struct Pose {
        x: f64,
        y: f32,
    }

    #[derive(serde::Serialize)]
    struct Report {
        name: &'static str,
        poses: Vec<Pose>,
        extra: Option<f64>,
        named: BTreeMap<String, [f64; 2]>,
    }

    fn report(bad_x: f64, bad_named: f64) -> Report {
        Report {
            name: "r",
            poses: vec![Pose { x: 1.0, y: 2.0 }, Pose { x: bad_x, y: 0.0 }],
            extra: None,
            named: BTreeMap::from([("wheel".to_owned(), [0.0, bad_named])]),
        }
    }

    #[test]
    fn finite_reports_pass_and_the_first_bad_number_is_named() {
        assert_eq!(first_non_finite(&report(3.0, 4.0)), None);
        assert_eq!(
            first_non_finite(&report(f64::NAN, 4.0)).as_deref(),
            Some("poses[1].x")
        );
        assert_eq!(
            first_non_finite(&report(0.0, f64::NEG_INFINITY)).as_deref(),
            Some("named.wheel[1]")
        );
        assert_eq!(
            first_non_finite(&f64::INFINITY).as_deref(),
            Some("the result")
        );
        assert_eq!(
            first_non_finite(&Pose {
                x: 0.0,
                y: f32::NAN
            })
            .as_deref(),
            Some("y")
        );
    }
}
