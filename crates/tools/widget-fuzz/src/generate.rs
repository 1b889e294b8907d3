//! Link states for a widget: valid ones from its schema, then damaged in
//! every way a link can be (see [`Damage`]).

use base64::Engine as _;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use kinolab_common::SplitMix64;
use kinolab_schema::{Kind, Param, WidgetSchema};

/// The lab's deterministic random source with the picks cases need: the
/// same seed, the same cases, on every machine.
#[derive(Debug, Clone)]
pub struct Rng(SplitMix64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(SplitMix64::new(seed))
    }

    fn next(&mut self) -> u64 {
        self.0.next_u64()
    }

    /// A whole number below `n` (0 when `n` is 0).
    pub fn below(&mut self, n: usize) -> usize {
        if n == 0 {
            0
        } else {
            (self.next() % n as u64) as usize
        }
    }

    /// A number in `[lo, hi]`.
    pub fn between(&mut self, lo: f64, hi: f64) -> f64 {
        self.0.range(lo, hi)
    }

    pub fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }
}

/// How a case's state was made.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Damage {
    /// Valid settings (and an instant) the schema accepts.
    Valid,
    /// One setting given a hostile value: huge, negative, NaN text, a 1 MB
    /// string, deep nesting.
    HostileValue,
    /// A setting the widget does not have.
    UnknownKey,
    /// The instant or the events line damaged.
    HostileMoment,
    /// The link text cut short.
    Truncated,
    /// Characters of the link text altered.
    Altered,
    /// The first link format (postcard) with random bytes.
    OldFormat,
    /// Text that is no link at all.
    Garbage,
}

pub const DAMAGES: [Damage; 8] = [
    Damage::Valid,
    Damage::HostileValue,
    Damage::UnknownKey,
    Damage::HostileMoment,
    Damage::Truncated,
    Damage::Altered,
    Damage::OldFormat,
    Damage::Garbage,
];

/// Values no setting should take quietly.
const HOSTILE: &[&str] = &[
    "1e308",
    "-1e308",
    "1e309",
    "NaN",
    "nan",
    "inf",
    "-inf",
    "-0",
    "-1",
    "99999999999999999999999",
    "-99999999999999999999",
    "0x10",
    "",
    " ",
    "yes",
    "1,2,3",
    "1;2;3",
    "[[[]]]",
    "{\"a\":1}",
    "\u{0}",
    "é∇→",
    "1e-320",
];

/// A valid value for `param`.
fn valid_value(rng: &mut Rng, param: &Param) -> Option<String> {
    Some(match &param.kind {
        Kind::Number { min, max } => format!("{}", rng.between(*min, *max)),
        Kind::Integer { min, max } => {
            let span = (max - min).clamp(0, 1_000_000) as usize;
            format!("{}", min + rng.below(span + 1) as i64)
        }
        Kind::YesNo => (*rng.pick(&["yes", "no"])).to_owned(),
        Kind::Choice { options } => (*rng.pick(options)).to_owned(),
        Kind::Numbers {
            min_count,
            max_count,
            min,
            max,
        } => {
            let count = min_count + rng.below(max_count.saturating_sub(*min_count).min(8) + 1);
            let values: Vec<String> = (0..count)
                .map(|_| format!("{}", rng.between(*min, *max)))
                .collect();
            values.join(",")
        }
        Kind::Groups {
            size,
            min_groups,
            min,
            max,
        } => {
            let size = if *size == 0 { 1 + rng.below(3) } else { *size };
            let groups: Vec<String> = (0..min_groups + rng.below(3))
                .map(|_| {
                    let g: Vec<String> = (0..size)
                        .map(|_| format!("{}", rng.between(*min, *max)))
                        .collect();
                    g.join(",")
                })
                .collect();
            groups.join(";")
        }
        Kind::Catalogue { of } => (*rng.pick(&of.ids())).to_owned(),
        Kind::Text { example, .. } => (*example).to_owned(),
    })
}

/// A hostile value: from the list, or made to size.
fn hostile_value(rng: &mut Rng) -> String {
    match rng.below(4) {
        0 => "x".repeat(1 << 20),
        1 => format!("{}{}", "[".repeat(10_000), "]".repeat(10_000)),
        _ => (*rng.pick(HOSTILE)).to_owned(),
    }
}

/// The settings lines of a valid state (some of the widget's parameters).
fn valid_lines(rng: &mut Rng, schema: &WidgetSchema) -> Vec<(String, String)> {
    let mut lines = Vec::new();
    for p in schema.params {
        if rng.below(2) == 0
            && let Some(v) = valid_value(rng, p)
        {
            lines.push((p.name.to_owned(), v));
        }
    }
    lines
}

/// Lines as a settings link (`b` and URL-safe base64).
pub fn link(lines: &[(String, String)]) -> String {
    let text: String = lines.iter().map(|(k, v)| format!("{k}: {v}\n")).collect();
    let mut out = String::from("b");
    URL_SAFE_NO_PAD.encode_string(text.as_bytes(), &mut out);
    out
}

/// A state for `schema`'s widget, made as `damage` says.
pub fn state(rng: &mut Rng, schema: &WidgetSchema, damage: Damage) -> String {
    let mut lines = valid_lines(rng, schema);
    if rng.below(2) == 0 {
        lines.push(("@t".into(), format!("{:.2}", rng.between(0.0, 30.0))));
    }
    match damage {
        Damage::Valid => {}
        Damage::HostileValue => {
            if let Some(p) = (!schema.params.is_empty()).then(|| rng.pick(schema.params)) {
                lines.push((p.name.to_owned(), hostile_value(rng)));
            }
        }
        Damage::UnknownKey => lines.push((
            rng.pick(&["speed", "zz", "@x", "", "__proto__"])
                .to_string(),
            "1".into(),
        )),
        Damage::HostileMoment => {
            let (key, value) = match rng.below(3) {
                0 => ("@t", hostile_value(rng)),
                1 => ("@t", (*rng.pick(&["3600", "3599.99", "1e6"])).to_owned()),
                _ => (
                    "@events",
                    rng.pick(&[
                        "[{\"t\":1}]",
                        "[[[[[[[[[[]]]]]]]]]]",
                        "{}",
                        "null",
                        "[1e400]",
                    ])
                    .to_string(),
                ),
            };
            lines.push((key.into(), value));
        }
        Damage::Truncated => {
            let whole = link(&lines);
            let cut = rng.below(whole.len());
            return whole[..cut].to_owned();
        }
        Damage::Altered => {
            let mut bytes = link(&lines).into_bytes();
            for _ in 0..1 + rng.below(3) {
                let i = rng.below(bytes.len());
                if let Some(b) = bytes.get_mut(i) {
                    *b = *rng.pick(b"AZaz09-_=+/%.");
                }
            }
            return String::from_utf8_lossy(&bytes).into_owned();
        }
        Damage::OldFormat => {
            let bytes: Vec<u8> = (0..rng.below(64)).map(|_| rng.next() as u8).collect();
            return format!("a{}", URL_SAFE_NO_PAD.encode(bytes));
        }
        Damage::Garbage => {
            return (*rng.pick(&["", "b", "a", "%%%", "bAAAA", "🙂", "b====", "z123"])).to_owned();
        }
    }
    link(&lines)
}
