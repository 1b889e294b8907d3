//! A formula read aloud: the words a screen reader says for it, made from
//! the formula's tree ("v equals r times omega"), never from its TeX.
//!
//! The wording follows how a teacher reads a formula to a class: letters by
//! name, operators as words, `x^2` as "x squared", `\dot x` as "x dot",
//! fractions as "a over b", with "the fraction … end fraction" around parts
//! of more than one word so the grouping stays audible.

use crate::tree::{AccentKind, Delimiter, Math, MatrixKind, OpKind};

/// The spoken form of `math`: words separated by single spaces.
pub fn spoken(math: &Math) -> String {
    let mut words = String::new();
    say(math, &mut words);
    words.split_whitespace().collect::<Vec<_>>().join(" ")
}

fn say(math: &Math, out: &mut String) {
    match math {
        Math::Row(items) => items.iter().for_each(|m| say(m, out)),
        Math::Group(inner) => say(inner, out),
        Math::Ident { text, .. } => {
            let mut chars = text.chars();
            match (chars.next(), chars.next()) {
                (Some(c), None) => word(out, &letter(c)),
                _ => word(out, text),
            }
        }
        Math::Number { text, .. } => word(out, text),
        Math::Symbol(s) => word(out, symbol(s)),
        Math::Op { text, kind } => word(out, &operator(text, *kind)),
        Math::Function(name) => word(out, function(name)),
        Math::Text(text) => word(out, text),
        Math::Space(_) => {}
        Math::Frac { num, den } => fraction(num, den, out),
        Math::Scripts { base, sub, sup } => scripts(base, sub.as_deref(), sup.as_deref(), out),
        Math::Sqrt { index, body } => root(index.as_deref(), body, out),
        Math::Accent { kind, body } => accent(*kind, body, out),
        Math::Fenced { open, close, body } => fenced(*open, *close, body, out),
        Math::Matrix { kind, rows } => matrix(*kind, rows, out),
    }
}

fn word(out: &mut String, w: &str) {
    out.push(' ');
    out.push_str(w);
}

/// The words of `math` alone, each subtree spoken once (a formula nested
/// deep is read in time linear in its size times its depth).
fn words_of(math: &Math) -> String {
    let mut words = String::new();
    say(math, &mut words);
    words
}

fn one_word(words: &str) -> bool {
    words.split_whitespace().count() <= 1
}

/// Already spoken `words` as a group: alone when one word, else between
/// `open` and `close`.
fn group_words(words: &str, open: &str, close: &str, out: &mut String) {
    if one_word(words) {
        out.push_str(words);
    } else {
        word(out, open);
        out.push_str(words);
        word(out, close);
    }
}

/// `math` as a group (see [`group_words`]).
fn grouped(math: &Math, open: &str, close: &str, out: &mut String) {
    group_words(&words_of(math), open, close, out);
}

fn fraction(num: &Math, den: &Math, out: &mut String) {
    let (num, den) = (words_of(num), words_of(den));
    let simple = one_word(&num) && one_word(&den);
    if !simple {
        word(out, "the fraction");
    }
    out.push_str(&num);
    word(out, "over");
    out.push_str(&den);
    if !simple {
        word(out, "end fraction");
    }
}

fn scripts(base: &Math, sub: Option<&Math>, sup: Option<&Math>, out: &mut String) {
    say(base, out);
    let sub = sub.map(words_of);
    let sup = sup.map(words_of);
    // A sum or an integral with limits: "the sum over i of", "the
    // integral from 0 to T of".
    if matches!(
        base,
        Math::Op {
            kind: OpKind::Large,
            ..
        }
    ) {
        match (&sub, &sup) {
            (Some(from), Some(to)) => {
                word(out, "from");
                out.push_str(from);
                word(out, "to");
                out.push_str(to);
            }
            (Some(over), None) | (None, Some(over)) => {
                word(out, "over");
                out.push_str(over);
            }
            (None, None) => {}
        }
        word(out, "of");
        return;
    }
    if let Some(sub) = &sub {
        word(out, "sub");
        group_words(sub, "", "end sub", out);
    }
    if let Some(sup) = &sup {
        let plain = sup.split_whitespace().collect::<Vec<_>>().join(" ");
        match plain.as_str() {
            "2" => word(out, "squared"),
            "3" => word(out, "cubed"),
            "T" => word(out, "transposed"),
            "minus 1" => word(out, "inverse"),
            "prime" => word(out, "prime"),
            _ => {
                word(out, "to the power");
                group_words(sup, "", "end power", out);
            }
        }
    }
}

fn root(index: Option<&Math>, body: &Math, out: &mut String) {
    match index.map(spoken).as_deref() {
        None => word(out, "the square root of"),
        Some("3") => word(out, "the cube root of"),
        Some(n) => {
            word(out, "the root of index");
            word(out, n);
            word(out, "of");
        }
    }
    grouped(body, "", "end root", out);
}

fn accent(kind: AccentKind, body: &Math, out: &mut String) {
    if kind == AccentKind::Vec {
        word(out, "vector");
        grouped(body, "", "end vector", out);
        return;
    }
    grouped(body, "", "", out);
    word(
        out,
        match kind {
            AccentKind::Dot => "dot",
            AccentKind::Ddot => "double dot",
            AccentKind::Hat => "hat",
            AccentKind::Bar => "bar",
            AccentKind::Tilde => "tilde",
            AccentKind::Vec => "",
        },
    );
}

fn fenced(open: Delimiter, close: Delimiter, body: &Math, out: &mut String) {
    match (open, close) {
        (Delimiter::Bar, Delimiter::Bar) => {
            word(out, "the absolute value of");
            grouped(body, "", "end absolute value", out);
        }
        (Delimiter::DoubleBar, Delimiter::DoubleBar) => {
            word(out, "the norm of");
            grouped(body, "", "end norm", out);
        }
        (Delimiter::LeftFloor, _) => {
            word(out, "the floor of");
            grouped(body, "", "end floor", out);
        }
        (Delimiter::LeftCeil, _) => {
            word(out, "the ceiling of");
            grouped(body, "", "end ceiling", out);
        }
        _ => {
            word(out, delimiter(open));
            say(body, out);
            word(out, delimiter(close));
        }
    }
}

fn delimiter(d: Delimiter) -> &'static str {
    match d {
        Delimiter::None => "",
        Delimiter::LeftParen | Delimiter::LeftBracket | Delimiter::LeftBrace => "open bracket",
        Delimiter::RightParen | Delimiter::RightBracket | Delimiter::RightBrace => "close bracket",
        Delimiter::Bar => "bar",
        Delimiter::DoubleBar => "double bar",
        Delimiter::LeftAngle => "open angle",
        Delimiter::RightAngle => "close angle",
        Delimiter::LeftFloor | Delimiter::RightFloor => "floor",
        Delimiter::LeftCeil | Delimiter::RightCeil => "ceiling",
    }
}

fn matrix(kind: MatrixKind, rows: &[Vec<Math>], out: &mut String) {
    let columns = rows.iter().map(Vec::len).max().unwrap_or(0);
    let what = if kind == MatrixKind::Plain {
        "an array"
    } else {
        "a matrix"
    };
    word(out, &format!("{what} of {} by {columns};", rows.len()));
    for (i, row) in rows.iter().enumerate() {
        word(out, &format!("row {}:", i + 1));
        for (j, cell) in row.iter().enumerate() {
            if j > 0 {
                word(out, ",");
            }
            say(cell, out);
        }
        word(out, ";");
    }
    word(out, "end matrix");
}

fn operator(text: &str, kind: OpKind) -> String {
    let w = match text {
        "+" => "plus",
        "-" | "−" => "minus",
        "·" | "×" | "*" => "times",
        "/" | "÷" => "divided by",
        "±" => "plus or minus",
        "∓" => "minus or plus",
        "=" => "equals",
        "≠" => "is not equal to",
        "≈" => "is approximately",
        "≡" => "is identical to",
        "<" => "is less than",
        ">" => "is greater than",
        "≤" => "is at most",
        "≥" => "is at least",
        "→" => "to",
        "←" => "from",
        "⇒" => "implies",
        "∈" => "in",
        "∑" => "the sum",
        "∏" => "the product",
        "∫" => "the integral",
        "∇" => "nabla",
        "(" | "[" | "{" => "open bracket",
        ")" | "]" | "}" => "close bracket",
        _ if kind == OpKind::Punct => return format!("{text} "),
        other => other,
    };
    w.to_owned()
}

fn function(name: &str) -> &str {
    match name {
        "sin" => "sine",
        "cos" => "cosine",
        "tan" => "tangent",
        "cot" => "cotangent",
        "ln" => "natural log",
        "exp" => "exponential",
        "atan2" => "a-tan-2",
        "rank" => "rank",
        "dim" => "dimension",
        "max" => "max",
        "min" => "min",
        other => other,
    }
}

fn symbol(s: &str) -> &str {
    match s {
        "∞" => "infinity",
        "∂" => "partial",
        "′" => "prime",
        "!" => "factorial",
        "|" => "bar",
        "°" => "degrees",
        "/" => "divided by",
        "…" | "⋯" => "and so on",
        other => other,
    }
}

/// A letter by its name: Greek letters spelled out ("θ" is "theta", "Ω"
/// "capital omega"), anything else as it is.
fn letter(c: char) -> String {
    const GREEK: &str = "alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu nu \
                         xi omicron pi rho final-sigma sigma tau upsilon phi chi psi omega";
    let lower = ('α'..='ω').position(|g| g == c);
    let upper = ('Α'..='Ω').position(|g| g == c);
    let name = |i: usize| GREEK.split_whitespace().nth(i).unwrap_or("");
    match (lower, upper, c) {
        (_, _, 'ϕ' | 'φ') => "phi".into(),
        (_, _, 'ϑ') => "theta".into(),
        (_, _, 'ϵ' | 'ε') => "epsilon".into(),
        (Some(i), _, _) => name(i).into(),
        (_, Some(i), _) => format!("capital {}", name(i)),
        _ => c.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse;

    fn read(tex: &str) -> String {
        spoken(&parse(tex).unwrap_or_else(|e| panic!("{tex}: {e}")))
    }

    #[test]
    fn formulas_of_the_lessons_read_as_a_teacher_reads_them() {
        for (tex, words) in [
            ("v = r \\cdot \\omega", "v equals r times omega"),
            ("v = r\\dot\\varphi", "v equals r phi dot"),
            (
                "x^2 + y^2 = d^2",
                "x squared plus y squared equals d squared",
            ),
            ("\\frac{a}{b}", "a over b"),
            (
                "\\omega = \\frac{v_R - v_L}{b}",
                "omega equals the fraction v sub R minus v sub L over b end fraction",
            ),
            (
                "\\sqrt{g / z_c}",
                "the square root of g divided by z sub c end root",
            ),
            ("\\Delta t \\le 0.1", "capital delta t is at most 0.1"),
            ("R^T", "R transposed"),
            ("J^{-1}", "J inverse"),
            ("\\theta_{k+1}", "theta sub k plus 1 end sub"),
            ("\\left| F \\right|", "the absolute value of F"),
            ("\\sin \\alpha", "sine alpha"),
            ("\\vec{F}", "vector F"),
            (
                "\\begin{bmatrix} a & b \\\\ c & d \\end{bmatrix}",
                "a matrix of 2 by 2; row 1: a , b ; row 2: c , d ; end matrix",
            ),
        ] {
            assert_eq!(read(tex), words, "{tex}");
        }
    }

    #[test]
    fn sums_and_integrals_read_their_limits() {
        assert_eq!(
            read("\\sum_i m_i g d_i"),
            "the sum over i of m sub i g d sub i"
        );
        assert_eq!(read("\\int_0^T v"), "the integral from 0 to T of v");
    }

    #[test]
    fn a_formula_nested_deep_is_read_in_time() {
        // Sixty nested roots and dots: each level is spoken once, not
        // twice per level (which would take 2^60 steps).
        let roots = format!("{}x{}", "\\sqrt{".repeat(60), "}".repeat(60));
        let words = read(&roots);
        assert_eq!(words.matches("the square root of").count(), 60);
        let dots = format!("{}x", "\\dot ".repeat(60));
        assert_eq!(read(&dots).matches("dot").count(), 60);
    }

    #[test]
    fn no_formula_reads_as_its_source() {
        // The spoken form never shows TeX: no backslash, brace or caret.
        for tex in [
            "\\frac{\\partial U}{\\partial x}",
            "\\sum_{i=1}^{n} w_i x_i",
            "e^{-\\lambda t}",
        ] {
            let words = read(tex);
            assert!(
                !words.contains(['\\', '{', '}', '^', '_']),
                "{tex}: {words}"
            );
            assert!(!words.is_empty());
        }
    }
}
