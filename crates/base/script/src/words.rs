//! Rhai's errors retold for someone writing their first functions: what
//! went wrong in the words of the lesson, and what to type instead.

use rhai::{EvalAltResult, LexError, ParseError, ParseErrorType, Position};

/// A syntax error's message and the place to show it.
pub(crate) fn syntax(e: &ParseError, source: &str) -> (String, Position) {
    let at = e.position();
    let (what, at) = match e.err_type() {
        ParseErrorType::MissingToken(token, _) if token == ";" => (
            "a `;` is missing at the end of this line: every statement but the last one in a block ends with `;`".to_owned(),
            end_of_previous(source, at).unwrap_or(at),
        ),
        ParseErrorType::BadInput(LexError::UnexpectedInput(text)) => (unexpected(text), at),
        other => (other.to_string(), at),
    };
    (
        format!("{what}: the code cannot run until this is fixed"),
        at,
    )
}

/// Where the last character before `at` is, one column after it: the
/// place a missing `;` belongs (Rhai notices it at the next token).
fn end_of_previous(source: &str, at: Position) -> Option<Position> {
    let (line, column) = (at.line()?, at.position()?);
    let lines: Vec<&str> = source.lines().collect();
    let current = lines.get(line - 1)?;
    // The part of the error's line before the token Rhai stopped at.
    let before: String = current.chars().take(column.saturating_sub(1)).collect();
    if !before.trim().is_empty() {
        return Some(place(line, before.trim_end().chars().count() + 1));
    }
    (1..line).rev().find_map(|l| {
        let text = code_part(lines[l - 1]).trim_end();
        (!text.is_empty()).then(|| place(l, text.chars().count() + 1))
    })
}

/// A position from a line and column (Rhai keeps them as `u16`).
fn place(line: usize, column: usize) -> Position {
    let fit = |n: usize| u16::try_from(n).unwrap_or(u16::MAX);
    Position::new(fit(line), fit(column))
}

/// A line without its `//` comment (a `//` inside a string is rare in
/// a learner's function and only moves the place shown).
fn code_part(line: &str) -> &str {
    line.find("//").map_or(line, |i| &line[..i])
}

/// A character the language does not read outside strings and comments.
fn unexpected(text: &str) -> String {
    let c = text.chars().next().unwrap_or(' ');
    match lookalike(c) {
        Some((name, instead)) => {
            format!("`{c}` ({name}) is not understood here: type {instead} instead")
        }
        None if !c.is_ascii() => format!(
            "`{c}` (U+{:04X}) is not understood outside strings and comments: names use the letters a to z, digits and `_`",
            c as u32
        ),
        None => format!("`{c}` is not understood here"),
    }
}

/// Characters that word processors, slides and formulas put in code, and
/// what to type in their place.
fn lookalike(c: char) -> Option<(&'static str, &'static str)> {
    let pair = match c {
        '\u{2212}' => ("a minus sign from a formula", "the ASCII `-`"),
        '\u{2013}' | '\u{2014}' => ("a dash, as word processors make it", "the ASCII `-`"),
        '\u{00d7}' | '\u{22c5}' | '\u{00b7}' => ("a multiplication sign", "`*`"),
        '\u{00f7}' => ("a division sign", "`/`"),
        '\u{2264}' => ("less than or equal", "`<=`"),
        '\u{2265}' => ("greater than or equal", "`>=`"),
        '\u{2260}' => ("not equal", "`!=`"),
        '\u{2018}' | '\u{2019}' | '\u{201c}' | '\u{201d}' => {
            ("a curly quote", "the straight quote `\"`")
        }
        '\u{00a0}' | '\u{2009}' | '\u{202f}' => ("a non-breaking space", "an ordinary space"),
        _ => return greek(c),
    };
    Some(pair)
}

/// A Greek letter and the name to write for it.
fn greek(c: char) -> Option<(&'static str, &'static str)> {
    Some(match c {
        'α' => ("the Greek letter alpha", "`alpha`"),
        'β' => ("the Greek letter beta", "`beta`"),
        'γ' => ("the Greek letter gamma", "`gamma`"),
        'δ' | 'Δ' => ("the Greek letter delta", "`delta`"),
        'ε' => ("the Greek letter epsilon", "`epsilon`"),
        'θ' => ("the Greek letter theta", "`theta`"),
        'λ' => ("the Greek letter lambda", "`lambda`"),
        'μ' => ("the Greek letter mu", "`mu`"),
        'π' => ("the Greek letter pi", "`PI()`"),
        'ρ' => ("the Greek letter rho", "`rho`"),
        'σ' => ("the Greek letter sigma", "`sigma`"),
        'τ' => ("the Greek letter tau", "`tau`"),
        'φ' | 'ϕ' => ("the Greek letter phi", "`phi`"),
        'ψ' => ("the Greek letter psi", "`psi`"),
        'ω' | 'Ω' => ("the Greek letter omega", "`omega`"),
        _ => return None,
    })
}

/// Functions that take decimal numbers only.
const DECIMAL: &[&str] = &[
    "sin",
    "cos",
    "tan",
    "atan",
    "atan2",
    "asin",
    "acos",
    "sqrt",
    "exp",
    "ln",
    "log10",
    "log",
    "hypot",
    "floor",
    "ceiling",
    "round",
    "int",
    "fraction",
    "is_nan",
    "is_finite",
    "is_infinite",
    "to_degrees",
    "to_radians",
];

/// A run-time error in the learner's words, when there are better ones
/// than Rhai's.
pub(crate) fn runtime(e: &EvalAltResult, source: &str) -> Option<String> {
    match e {
        EvalAltResult::ErrorFunctionNotFound(signature, at) => {
            Some(function_not_found(signature, source, *at))
        }
        EvalAltResult::ErrorVariableNotFound(name, _) => Some(format!(
            "there is no variable `{name}` here: give it a value first with `let {name} = …;` (a function sees only its parameters, `this` and the variables it makes itself)"
        )),
        EvalAltResult::ErrorPropertyNotFound(encoded, at) => Some(property(encoded, source, *at)),
        EvalAltResult::ErrorArrayBounds(len, index, _) => Some(match len {
            0 => format!("asked for item {index} of an empty list"),
            n => format!(
                "asked for item {index} of a list of {n}: items are numbered from 0 to {}",
                n - 1
            ),
        }),
        EvalAltResult::ErrorMismatchDataType(wanted, got, _) => {
            Some(format!("expected {} here, not {}", kind(wanted), kind(got)))
        }
        EvalAltResult::ErrorRuntime(value, _) => Some(format!(
            "your code threw `{}`",
            crate::value::describe(value)
        )),
        _ => None,
    }
}

/// A type as the lessons name it.
fn kind(rhai: &str) -> String {
    let name = rhai.trim();
    match name {
        "i64" | "INT" => "a whole number".into(),
        "f64" | "FLOAT" | "decimal" => "a decimal number".into(),
        "bool" => "true or false".into(),
        "string" | "ImmutableString" | "&str | ImmutableString | String" => "text".into(),
        "char" => "a character".into(),
        "array" | "Array" => "a list".into(),
        "map" | "Map" => "a map".into(),
        "()" => "`()` (nothing)".into(),
        other => format!("`{other}`"),
    }
}

/// "sqrt (i64)": a function, or an operator, not found for those types.
fn function_not_found(signature: &str, source: &str, at: Position) -> String {
    let (name, args) = match signature.split_once(" (") {
        Some((name, rest)) => (name.trim(), rest.trim_end_matches(')')),
        None => (signature.trim(), ""),
    };
    let types: Vec<&str> = args
        .split(',')
        .map(str::trim)
        .filter(|a| !a.is_empty())
        .collect();
    let given = types
        .iter()
        .map(|t| kind(t))
        .collect::<Vec<_>>()
        .join(" and ");
    if types.contains(&"()") {
        return format!(
            "`{name}` was given {given}: `()` is what a map key that is not set, or a function that answers nothing, gives"
        );
    }
    if DECIMAL.contains(&name) && types.contains(&"i64") {
        let call = call_text(source, at, name);
        let fixed = call.as_deref().map(decimal_literals);
        return match (call, fixed) {
            (Some(call), Some(fixed)) if fixed != call => {
                format!("`{name}` takes a decimal number: write `{fixed}`")
            }
            _ => format!(
                "`{name}` takes a decimal number, and was given a whole number: write `9.0` rather than `9`, or convert with `to_float(…)`"
            ),
        };
    }
    if name.chars().all(|c| c.is_alphanumeric() || c == '_') {
        format!("there is no function `{name}` that takes {given}")
    } else {
        format!("`{name}` cannot be used with {given}")
    }
}

/// The text of the call of `name` at `at`: `sqrt(9)`, up to its closing
/// bracket on the same line.
fn call_text(source: &str, at: Position, name: &str) -> Option<String> {
    let line = source.lines().nth(at.line()?.checked_sub(1)?)?;
    let from: String = line
        .chars()
        .skip(at.position()?.saturating_sub(1))
        .collect();
    let start = from.find(name)?;
    let rest = &from[start..];
    let mut depth = 0usize;
    for (i, c) in rest.char_indices() {
        match c {
            '(' => depth += 1,
            ')' if depth == 1 => return Some(rest[..=i].to_owned()),
            ')' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    None
}

/// `text` with every whole-number literal written as a decimal: `9` → `9.0`.
fn decimal_literals(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let starts = c.is_ascii_digit()
            && !(i > 0 && (chars[i - 1].is_alphanumeric() || matches!(chars[i - 1], '_' | '.')));
        if !starts {
            out.push(c);
            i += 1;
            continue;
        }
        let mut j = i;
        while j < chars.len() && chars[j].is_ascii_digit() {
            j += 1;
        }
        out.extend(&chars[i..j]);
        let whole = chars
            .get(j)
            .is_none_or(|n| !(n.is_alphanumeric() || matches!(n, '.' | '_')));
        if whole {
            out.push_str(".0");
        }
        i = j;
    }
    out
}

/// The separator in a missing property's error between the property and
/// the keys its map has (see [`crate::value`]).
pub(crate) const KEYS: char = '\u{1f}';

/// "`p` has no `bumper`; it has …".
fn property(encoded: &str, source: &str, at: Position) -> String {
    let (name, keys) = encoded.split_once(KEYS).unwrap_or((encoded, ""));
    let keys: Vec<String> = keys
        .split(',')
        .filter(|k| !k.is_empty())
        .map(|k| format!("`{k}`"))
        .collect();
    let owner = owner(source, at).map_or("this map".to_owned(), |o| format!("`{o}`"));
    format!("{owner} has no `{name}`; it has {}", keys.join(", "))
}

/// The expression before `.name` at `at`: `p`, `p.bumpers`, `r`.
fn owner(source: &str, at: Position) -> Option<String> {
    let line = source.lines().nth(at.line()?.checked_sub(1)?)?;
    let chars: Vec<char> = line.chars().collect();
    let mut end = at.position()?.checked_sub(1)?.min(chars.len());
    // Back over the property's name and its dot.
    while end > 0 && (chars[end - 1].is_alphanumeric() || chars[end - 1] == '_') {
        end -= 1;
    }
    if end == 0 || chars[end - 1] != '.' {
        return None;
    }
    end -= 1;
    let mut start = end;
    while start > 0
        && (chars[start - 1].is_alphanumeric() || matches!(chars[start - 1], '_' | '.' | '[' | ']'))
    {
        start -= 1;
    }
    let text: String = chars[start..end].iter().collect();
    (!text.is_empty()).then_some(text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn whole_numbers_in_a_call_become_decimals() {
        assert_eq!(decimal_literals("sqrt(9)"), "sqrt(9.0)");
        assert_eq!(decimal_literals("atan2(1, x2)"), "atan2(1.0, x2)");
        assert_eq!(decimal_literals("hypot(1.5, 20)"), "hypot(1.5, 20.0)");
        assert_eq!(decimal_literals("log(1e3)"), "log(1e3)");
    }

    #[test]
    fn the_owner_of_a_property_is_read_back_from_the_line() {
        let source = "fn f(p) {\n  let b = p.bumpers.frnt;\n}";
        // Rhai places the error at the property's name.
        assert_eq!(owner(source, place(2, 21)).as_deref(), Some("p.bumpers"));
        assert_eq!(owner(source, place(2, 13)).as_deref(), Some("p"));
    }
}
