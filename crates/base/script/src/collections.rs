//! What a script may do with its lists and maps: the few functions the
//! lab's exercises need, registered one by one.
//!
//! Rhai's own array and map packages bring sixty-odd functions (sorts,
//! splices, closures over items) that no robot's code here calls and that
//! cost the lab's page about 0.1 MB of wasm. The ones kept are the ones a
//! learner reaches for: size, add and take, look up, and `in`.
//!
//! Rhai counts each of these calls as one operation, but looking through
//! or copying a list takes time in proportion to its length: each such
//! call charges its length to the call's budget, so ten searches of a
//! long list a call cost what they take.

use std::rc::Rc;

use rhai::{Array, Dynamic, Engine, EvalAltResult, ImmutableString, Map, Position};

use crate::sandbox::{Budget, LIMITS};

type Done<T> = Result<T, Box<EvalAltResult>>;

/// Register the list and map functions on `e`, and `for x in list`,
/// charging their work to `budget`.
pub(crate) fn register(e: &mut Engine, budget: &Rc<Budget>) {
    lists(e);
    searches(e, budget);
    maps(e, budget);
    let mut iterable = rhai::Module::new();
    iterable.set_iterable::<Array>();
    e.register_global_module(iterable.into());
}

fn lists(e: &mut Engine) {
    e.register_fn("len", |a: &mut Array| a.len() as i64)
        .register_fn("is_empty", |a: &mut Array| a.is_empty())
        .register_fn("push", |a: &mut Array, x: Dynamic| a.push(x))
        .register_fn("pop", |a: &mut Array| a.pop().unwrap_or(Dynamic::UNIT))
        .register_fn("shift", |a: &mut Array| shift(a))
        .register_fn("insert", insert)
        .register_fn("remove", remove)
        .register_fn("clear", |a: &mut Array| a.clear())
        .register_fn("pad", pad)
        .register_fn("len", |s: &mut ImmutableString| s.chars().count() as i64)
        .register_fn("is_empty", |s: &mut ImmutableString| s.is_empty());
}

/// The functions whose work grows with a list's length.
fn searches(e: &mut Engine, budget: &Rc<Budget>) {
    let b = budget.clone();
    e.register_fn("contains", move |a: &mut Array, x: Dynamic| {
        b.charge(a.len());
        a.iter().any(|y| same(y, &x))
    });
    let b = budget.clone();
    e.register_fn("index_of", move |a: &mut Array, x: Dynamic| {
        b.charge(a.len());
        a.iter().position(|y| same(y, &x)).map_or(-1, |i| i as i64)
    });
    let b = budget.clone();
    e.register_fn("+", move |a: Array, b2: Array| {
        b.charge(a.len() + b2.len());
        [a, b2].concat()
    });
    let b = budget.clone();
    e.register_fn("append", move |a: &mut Array, more: Array| {
        b.charge(more.len());
        a.extend(more)
    });
    let b = budget.clone();
    e.register_fn("==", move |a: &mut Array, other: Array| {
        b.charge(a.len());
        equal(a, &other)
    });
    let b = budget.clone();
    e.register_fn("!=", move |a: &mut Array, other: Array| {
        b.charge(a.len());
        !equal(a, &other)
    });
}

fn maps(e: &mut Engine, budget: &Rc<Budget>) {
    e.register_fn("len", |m: &mut Map| m.len() as i64)
        .register_fn("is_empty", |m: &mut Map| m.is_empty())
        .register_fn("contains", |m: &mut Map, k: ImmutableString| {
            m.contains_key(k.as_str())
        })
        .register_fn("remove", |m: &mut Map, k: ImmutableString| {
            m.remove(k.as_str()).unwrap_or(Dynamic::UNIT)
        })
        .register_fn("clear", |m: &mut Map| m.clear());
    let b = budget.clone();
    e.register_fn("keys", move |m: &mut Map| -> Array {
        b.charge(m.len());
        m.keys()
            .map(|k| ImmutableString::from(k.as_str()).into())
            .collect()
    });
    let b = budget.clone();
    e.register_fn("values", move |m: &mut Map| -> Array {
        b.charge(m.len());
        m.values().cloned().collect()
    });
}

/// The first item, taken out (`()` when the list is empty).
fn shift(a: &mut Array) -> Dynamic {
    if a.is_empty() {
        Dynamic::UNIT
    } else {
        a.remove(0)
    }
}

/// Where `at` points in a list of `len` items: counted from the end when
/// negative, as Rhai's indexing does.
fn place(len: usize, at: i64) -> Option<usize> {
    let at = if at < 0 { len as i64 + at } else { at };
    usize::try_from(at).ok().filter(|i| *i <= len)
}

fn insert(a: &mut Array, at: i64, x: Dynamic) {
    let i = place(a.len(), at).unwrap_or(if at < 0 { 0 } else { a.len() });
    a.insert(i, x);
}

fn remove(a: &mut Array, at: i64) -> Dynamic {
    match place(a.len(), at) {
        Some(i) if i < a.len() => a.remove(i),
        _ => Dynamic::UNIT,
    }
}

/// Grow the list to `len` items with copies of `x`, refusing before it
/// allocates what the sandbox would refuse anyway.
fn pad(a: &mut Array, len: i64, x: Dynamic) -> Done<()> {
    let len = usize::try_from(len).unwrap_or(0);
    if len > LIMITS.array {
        let what = "Size of array".to_owned();
        return Err(EvalAltResult::ErrorDataTooLarge(what, Position::NONE).into());
    }
    if len > a.len() {
        a.resize(len, x);
    }
    Ok(())
}

fn equal(a: &[Dynamic], b: &[Dynamic]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| same(x, y))
}

/// Two values alike: numbers by value (an integer equals the same
/// float), text, truth values, `()`, and lists item by item.
fn same(x: &Dynamic, y: &Dynamic) -> bool {
    if let (Some(a), Some(b)) = (crate::value::float(x), crate::value::float(y)) {
        return a == b;
    }
    if let (Ok(a), Ok(b)) = (x.as_immutable_string_ref(), y.as_immutable_string_ref()) {
        return *a == *b;
    }
    if let (Ok(a), Ok(b)) = (x.as_bool(), y.as_bool()) {
        return a == b;
    }
    if let (Ok(a), Ok(b)) = (x.as_array_ref(), y.as_array_ref()) {
        return equal(&a, &b);
    }
    x.is_unit() && y.is_unit()
}
