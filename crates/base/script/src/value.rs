//! Values between the lab and a script: numbers, lists of numbers and
//! maps in, checked shapes out.

use rhai::{Dynamic, Map};

use crate::error::{ScriptError, When};
use crate::script::Signature;

/// A number as a script sees it.
pub fn number(x: f64) -> Dynamic {
    Dynamic::from_float(x)
}

/// A list of numbers.
pub fn numbers(xs: &[f64]) -> Dynamic {
    Dynamic::from_array(xs.iter().map(|x| number(*x)).collect())
}

/// A map from names to values.
pub fn map<'a>(entries: impl IntoIterator<Item = (&'a str, Dynamic)>) -> Dynamic {
    // Inserted one by one: collecting would sort, and put a sort in the
    // lab's wasm for every caller's iterator.
    let mut map = Map::new();
    for (k, v) in entries {
        map.insert(k.into(), v);
    }
    remember(&map);
    Dynamic::from_map(map)
}

/// `value` as a float (an integer counts), if it is a number.
pub fn float(value: &Dynamic) -> Option<f64> {
    value
        .as_float()
        .ok()
        .or_else(|| value.as_int().ok().map(|n| n as f64))
}

/// `value` as text, if it is a string.
pub fn text(value: &Dynamic) -> Option<String> {
    value.is_string().then(|| value.to_string())
}

/// `value` as `N` finite numbers (`names` says what each one is), or why
/// not: the wrong shape, or a number that is not finite.
pub fn finite<const N: usize>(
    value: &Dynamic,
    names: [&str; N],
    signature: Signature,
    at: impl Into<When>,
) -> Result<[f64; N], ScriptError> {
    let at = at.into();
    let wanted = format!("[{}], {} numbers", names.join(", "), N);
    let shape = || ScriptError::shape(signature, &wanted, &describe(value), at);
    let items = value.as_array_ref().map_err(|_| shape())?;
    if items.len() != N {
        return Err(shape());
    }
    let mut out = [0.0; N];
    for (k, item) in items.iter().enumerate() {
        let x = float(item).ok_or_else(shape)?;
        if !x.is_finite() {
            return Err(ScriptError::not_finite(signature, names[k], x, at));
        }
        out[k] = x;
    }
    Ok(out)
}

/// A value as the stepper shows it: short, one line.
pub fn describe(value: &Dynamic) -> String {
    let text = written(value, 240);
    if text.chars().count() > 120 {
        format!("{}…", text.chars().take(119).collect::<String>())
    } else {
        text
    }
}

/// Lists and maps deeper than this are written `[…]` and `#{…}`.
const WRITTEN_DEPTH: usize = 16;

/// `value` as text, the way Rhai writes it (`[1, "x"]`, `#{"a": 2.5}`),
/// but at most [`WRITTEN_DEPTH`] levels deep and about `max` bytes long:
/// printing a list nested a thousand deep must neither overflow the stack
/// nor take a moment.
pub fn written(value: &Dynamic, max: usize) -> String {
    let mut out = String::new();
    write(&mut out, value, WRITTEN_DEPTH, false, max);
    out
}

/// A list as [`written`] writes it.
pub fn written_list(items: &[Dynamic], max: usize) -> String {
    let mut out = String::new();
    write_list(&mut out, items, WRITTEN_DEPTH, max);
    out
}

/// A map as [`written`] writes it.
pub fn written_map(map: &Map, max: usize) -> String {
    let mut out = String::new();
    write_map(&mut out, map, WRITTEN_DEPTH, max);
    out
}

fn write_list(out: &mut String, items: &[Dynamic], depth: usize, max: usize) {
    let items: Vec<(Option<String>, &Dynamic)> = items.iter().map(|x| (None, x)).collect();
    write_all(out, ("[", "]"), &items, depth, max);
}

fn write_map(out: &mut String, map: &Map, depth: usize, max: usize) {
    let entries: Vec<(Option<String>, &Dynamic)> = map
        .iter()
        .map(|(k, x)| (Some(format!("{:?}: ", k.as_str())), x))
        .collect();
    write_all(out, ("#{", "}"), &entries, depth, max);
}

fn write(out: &mut String, v: &Dynamic, depth: usize, quoted: bool, max: usize) {
    if let Ok(items) = v.as_array_ref() {
        write_list(out, &items, depth, max);
    } else if let Ok(map) = v.as_map_ref() {
        write_map(out, &map, depth, max);
    } else if quoted && v.is_string() {
        out.push_str(&format!("{:?}", v.to_string()));
    } else {
        out.push_str(&v.to_string());
    }
}

fn write_all(
    out: &mut String,
    (open, close): (&str, &str),
    items: &[(Option<String>, &Dynamic)],
    depth: usize,
    max: usize,
) {
    out.push_str(open);
    if depth == 0 && !items.is_empty() {
        out.push('…');
    } else {
        for (i, (key, item)) in items.iter().enumerate() {
            if out.len() > max {
                out.push('…');
                break;
            }
            if i > 0 {
                out.push_str(", ");
            }
            out.push_str(key.as_deref().unwrap_or(""));
            write(out, item, depth.saturating_sub(1), true, max);
        }
    }
    out.push_str(close);
}

/// How deep lists and maps sit inside `value` (a number is 0, `[1]` is 1,
/// `[[1]]` is 2), counted no further than `limit + 1`, so a value nested
/// thousands deep costs no more than one nested `limit` deep.
pub fn nesting(value: &Dynamic, limit: usize) -> usize {
    if limit == 0 {
        return usize::from(value.is_array() || value.is_map());
    }
    let inner = |items: &mut dyn Iterator<Item = &Dynamic>| {
        items.map(|v| nesting(v, limit - 1)).max().unwrap_or(0)
    };
    if let Ok(a) = value.as_array_ref() {
        1 + inner(&mut a.iter())
    } else if let Ok(m) = value.as_map_ref() {
        1 + inner(&mut m.values())
    } else {
        0
    }
}

/// Drop `value` a level at a time, so that lists nested deep are freed
/// without a call per level (which could overflow the stack).
pub fn dispose(value: Dynamic) {
    let mut pending = vec![value];
    while let Some(v) = pending.pop() {
        if v.is_array() {
            if let Ok(items) = v.into_array() {
                pending.extend(items);
            }
        } else if v.is_map()
            && let Some(m) = v.try_cast::<Map>()
        {
            pending.extend(m.into_values());
        }
    }
}

thread_local! {
    /// The key sets of the maps the lab hands to scripts (`p`, a ray, a
    /// leg, the sequencer's state): reading a key that such a map does not
    /// have is a mistake worth naming, while a learner's own map (`this`)
    /// answers `()` for a key not yet set.
    static SHAPES: std::cell::RefCell<Vec<Vec<String>>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// The most key sets remembered (the lab hands out a dozen).
const MAX_SHAPES: usize = 64;

fn keys_of(map: &Map) -> Vec<String> {
    map.keys().map(|k| k.to_string()).collect()
}

fn remember(map: &Map) {
    let keys = keys_of(map);
    SHAPES.with(|s| {
        let mut shapes = s.borrow_mut();
        if shapes.len() < MAX_SHAPES && !shapes.contains(&keys) {
            shapes.push(keys);
        }
    });
}

/// Whether `map` has the keys of a map the lab hands out.
pub(crate) fn from_the_lab(map: &Map) -> bool {
    let keys = keys_of(map);
    SHAPES.with(|s| s.borrow().contains(&keys))
}

/// The keys of `map`, comma-separated (for a missing property's error).
pub(crate) fn key_list(map: &Map) -> String {
    keys_of(map).join(",")
}
