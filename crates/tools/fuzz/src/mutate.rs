//! Structured damage: to JSON trees (a number made extreme, a key dropped
//! or invented, a value of the wrong type, deep nesting, huge arrays,
//! strings with newlines), to text (cut, spliced, a byte flipped) and to
//! option values (extreme, malformed, the wrong count).

use kinolab_common::SplitMix64;
use serde_json::{Map, Value, json};

/// A small random toolbox over one seeded generator.
#[derive(Debug, Clone)]
pub struct Dice(SplitMix64);

impl Dice {
    pub fn new(seed: u64) -> Self {
        Self(SplitMix64::new(seed))
    }

    /// A number from 0 to `n` − 1 (0 when `n` is 0).
    pub fn below(&mut self, n: usize) -> usize {
        if n == 0 {
            0
        } else {
            (self.0.next_u64() % n as u64) as usize
        }
    }

    /// True with probability `p`.
    pub fn chance(&mut self, p: f64) -> bool {
        self.0.unit() < p
    }

    pub fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }

    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        self.0.range(lo, hi)
    }

    /// A number a person might write, or one at the edge of what a float
    /// can hold.
    pub fn number(&mut self) -> f64 {
        const EDGES: [f64; 16] = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            1e-12,
            5e-324,
            2.2e-308,
            1e6,
            1e6 + 1.0,
            -1e6,
            1e9,
            1e160,
            -1e160,
            1e308,
            -1.7e308,
            0.5,
        ];
        match self.below(12) {
            0 => *self.pick(&EDGES),
            1..=4 => self.range(-10.0, 10.0),
            5 => self.range(-1000.0, 1000.0),
            _ => (self.range(-3.0, 3.0) * 100.0).round() / 100.0,
        }
    }

    /// A string that tests an error message: newlines, quotes, a long run,
    /// other scripts, control characters.
    pub fn nasty_string(&mut self) -> String {
        match self.below(8) {
            0 => "fixed\nkinolab: fake second line".into(),
            1 => "x".repeat(self.below(5000) + 100),
            2 => "ἄνθρωπος \u{202e}gnol".into(),
            3 => "tab\there\r\u{7}bell".into(),
            4 => "`backticks` and \"quotes\"".into(),
            5 => String::new(),
            6 => "catalogue:".into(),
            _ => "?".into(),
        }
    }

    /// A text for a numeric option: usually numbers, sometimes not.
    pub fn numbers_text(&mut self, count: usize) -> String {
        let n = match self.below(16) {
            0 => self.below(6),
            1 => count + 1,
            2 if count > 0 => count - 1,
            _ => count,
        };
        let mut parts: Vec<String> = (0..n).map(|_| format_number(self.number())).collect();
        if self.chance(0.08) && !parts.is_empty() {
            let i = self.below(parts.len());
            parts[i] = self
                .pick(&[
                    "NaN", "inf", "-inf", "1e999", "abc", "", " ", "1,5", "0x10", "--",
                ])
                .to_string();
        }
        parts.join(",")
    }
}

/// A number as an option or file writes it (integers without `.0`).
pub fn format_number(x: f64) -> String {
    if x == x.trunc() && x.abs() < 1e15 {
        format!("{}", x as i64)
    } else {
        format!("{x:e}")
    }
}

/// Paths to every value in a tree: keys and indices.
fn paths(value: &Value, prefix: &mut Vec<Step>, out: &mut Vec<Vec<Step>>) {
    out.push(prefix.clone());
    match value {
        Value::Object(map) => {
            for (k, v) in map {
                prefix.push(Step::Key(k.clone()));
                paths(v, prefix, out);
                prefix.pop();
            }
        }
        Value::Array(items) => {
            for (i, v) in items.iter().enumerate().take(64) {
                prefix.push(Step::Index(i));
                paths(v, prefix, out);
                prefix.pop();
            }
        }
        _ => {}
    }
}

#[derive(Debug, Clone)]
enum Step {
    Key(String),
    Index(usize),
}

fn at<'a>(value: &'a Value, path: &[Step]) -> Option<&'a Value> {
    let mut v = value;
    for step in path {
        v = match step {
            Step::Key(k) => v.get(k.as_str())?,
            Step::Index(i) => v.get(*i)?,
        };
    }
    Some(v)
}

fn at_mut<'a>(value: &'a mut Value, path: &[Step]) -> Option<&'a mut Value> {
    let mut v = value;
    for step in path {
        v = match step {
            Step::Key(k) => v.get_mut(k.as_str())?,
            Step::Index(i) => v.get_mut(*i)?,
        };
    }
    Some(v)
}

/// Damage one value somewhere in `tree`, `count` times.
pub fn mutate_tree(dice: &mut Dice, tree: &mut Value, count: usize) {
    for _ in 0..count {
        let mut all = Vec::new();
        paths(tree, &mut Vec::new(), &mut all);
        let path = dice.pick(&all).clone();
        // Numbers are the most interesting: aim at them half the time.
        let numbers: Vec<&Vec<Step>> = all
            .iter()
            .filter(|p| at(tree, p).is_some_and(Value::is_number))
            .collect();
        let path = if !numbers.is_empty() && dice.chance(0.5) {
            (*dice.pick(&numbers)).clone()
        } else {
            path
        };
        let parent_is_object = matches!(path.last(), Some(Step::Key(_)));
        let Some(target) = at_mut(tree, &path) else {
            continue;
        };
        change(dice, target);
        if parent_is_object && dice.chance(0.05) {
            drop_key(tree, &path);
        }
    }
}

fn drop_key(tree: &mut Value, path: &[Step]) {
    let Some((Step::Key(k), parent)) = path.split_last() else {
        return;
    };
    if let Some(Value::Object(map)) = at_mut(tree, parent) {
        map.remove(k);
    }
}

fn change(dice: &mut Dice, target: &mut Value) {
    *target = match dice.below(14) {
        0..=4 => json!(dice.number()),
        5 => json!(dice.nasty_string()),
        6 => Value::Null,
        7 => json!(dice.chance(0.5)),
        8 => json!([]),
        9 => {
            let mut map = Map::new();
            map.insert(dice.nasty_string(), json!(1));
            Value::Object(map)
        }
        10 => deep(dice.below(200) + 1),
        11 => match target.clone() {
            Value::Array(items) if !items.is_empty() => {
                let n = dice.pick(&[0usize, 1, 100, 5000]).to_owned();
                Value::Array(items.iter().cycle().take(n).cloned().collect())
            }
            Value::Object(mut map) => {
                map.insert(dice.nasty_string(), json!(dice.number()));
                Value::Object(map)
            }
            other => other,
        },
        12 => json!(dice.number().round() as i64),
        _ => json!(format_number(dice.number())),
    };
}

/// `[[[…1…]]]`, `depth` deep.
fn deep(depth: usize) -> Value {
    let mut v = json!(1);
    for _ in 0..depth {
        v = json!([v]);
    }
    v
}

/// Text damage: cut, spliced, a byte changed, a BOM, a duplicated key.
pub fn damage_text(dice: &mut Dice, text: &str) -> Vec<u8> {
    let mut bytes = text.as_bytes().to_vec();
    match dice.below(8) {
        0 => bytes.truncate(dice.below(bytes.len() + 1)),
        1 => {
            let i = dice.below(bytes.len() + 1);
            const JUNK: [&[u8]; 7] = [b"}", b",", b"\n", b"\"", b"{\"a\":", b"\xff\xfe", b"\0"];
            let junk = *dice.pick(&JUNK);
            bytes.splice(i..i, junk.iter().copied());
        }
        2 if !bytes.is_empty() => {
            let i = dice.below(bytes.len());
            bytes[i] = dice.below(256) as u8;
        }
        3 => bytes.splice(0..0, [0xef, 0xbb, 0xbf]).for_each(drop),
        4 => {
            // A key written twice.
            if let Some(i) = text.find("\":") {
                let start = text[..i].rfind('"').unwrap_or(0);
                let pair = format!("{}: 0, ", &text[start..=i]);
                bytes.splice(start..start, pair.bytes()).for_each(drop);
            }
        }
        5 => bytes = b"[".repeat(dice.below(100_000) + 1),
        6 => bytes.clear(),
        _ => bytes.extend_from_slice(b"\n{}"),
    }
    bytes
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_seed_damages_the_same_way() {
        let tree = json!({"a": [1.0, 2.0, {"b": 3.0}], "c": "x"});
        let run = |seed| {
            let mut t = tree.clone();
            mutate_tree(&mut Dice::new(seed), &mut t, 3);
            t
        };
        assert_eq!(run(7), run(7));
        assert!((0..20).any(|s| run(s) != tree));
        assert_eq!(format_number(3.0), "3");
        assert_eq!(format_number(1e160), "1e160");
    }
}
