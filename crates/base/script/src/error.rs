//! What went wrong in a learner's script, in a learner's words: what, on
//! which line and column, at what simulated time, and what to look at.

use std::fmt;

use kinolab_common::display::fixed;
use rhai::{EvalAltResult, ParseError, Position};

use crate::sandbox::{LIMITS, stop};
use crate::script::Signature;

/// The kind of problem, for tests and for the stepper's colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ErrorKind {
    /// The code does not parse.
    Syntax,
    /// The function the lab calls is missing or takes other parameters.
    Missing,
    /// Too many operations in one call: a loop that never ends.
    Endless,
    /// Too many operations over the whole run: far more work each call
    /// than the job needs.
    TooSlow,
    /// Functions calling functions too deep: recursion that never stops.
    TooDeep,
    /// A string, array or map grown past its bound.
    TooLarge,
    /// The function returned something of the wrong shape.
    Shape,
    /// The function returned NaN or an infinity.
    NotFinite,
    /// Any other run-time error (an unknown variable, a wrong type, …).
    Runtime,
}

/// A problem with a learner's script (as reports write it: `kind`,
/// `message`, `line`, `column`, `t`).
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ScriptError {
    pub kind: ErrorKind,
    /// What happened, in a sentence (with the time when it ran).
    pub message: String,
    /// Where, 1-based, when known.
    pub line: Option<usize>,
    pub column: Option<usize>,
    /// The simulated time of the call, s (`None` before anything ran).
    pub t: Option<f64>,
}

impl fmt::Display for ScriptError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.line, self.column) {
            (Some(l), Some(c)) => write!(f, "line {l}, column {c}: {}", self.message),
            (Some(l), None) => write!(f, "line {l}: {}", self.message),
            _ => write!(f, "{}", self.message),
        }
    }
}

impl std::error::Error for ScriptError {}

fn at(position: Position) -> (Option<usize>, Option<usize>) {
    (position.line(), position.position())
}

/// When (or where) a function was called: at a simulated time, or at a
/// point of the plane (a potential field is asked at points, not times).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum When {
    Time(f64),
    Point(f64, f64),
    /// A phase of a cycle, 0 to 1.
    Phase(f64),
}

impl From<f64> for When {
    fn from(t: f64) -> Self {
        When::Time(t)
    }
}

impl When {
    /// " at t = 3.20 s", " at (1.20, 0.50)".
    fn words(self) -> String {
        match self {
            When::Time(t) => format!(" at t = {} s", fixed(t, 2)),
            When::Point(x, y) => format!(" at ({}, {})", fixed(x, 2), fixed(y, 2)),
            When::Phase(tau) => format!(" at phase {}", fixed(tau, 3)),
        }
    }

    fn time(self) -> Option<f64> {
        match self {
            When::Time(t) => Some(t),
            When::Point(..) | When::Phase(..) => None,
        }
    }
}

impl ScriptError {
    fn new(kind: ErrorKind, message: String, position: Position, t: Option<f64>) -> Self {
        let (line, column) = at(position);
        Self {
            kind,
            message,
            line,
            column,
            t,
        }
    }

    /// The same error, placed at `position` (when it is known).
    pub(crate) fn at(mut self, position: Position) -> Self {
        if !position.is_none() {
            (self.line, self.column) = at(position);
        }
        self
    }

    pub(crate) fn too_long(len: usize, max: usize) -> Self {
        let message = format!("the code is {len} bytes long; the lab takes at most {max}");
        Self::new(ErrorKind::Syntax, message, Position::NONE, None)
    }

    /// The code does not parse.
    pub(crate) fn syntax(e: &ParseError, source: &str) -> Self {
        let (message, at) = crate::words::syntax(e, source);
        Self::new(ErrorKind::Syntax, message, at, None)
    }

    /// The function is missing, or found with `found` parameter counts.
    pub(crate) fn missing(signature: Signature, found: &[usize]) -> Self {
        let wanted = signature.text();
        let message = match found.first() {
            None => format!(
                "the lab calls `{wanted}`, and your code has no function `{}`",
                signature.name
            ),
            Some(n) => format!(
                "`{}` takes {} parameters ({wanted}); yours takes {n}",
                signature.name,
                signature.params.len()
            ),
        };
        Self::new(ErrorKind::Missing, message, Position::NONE, None)
    }

    /// The function returned `got` where `wanted` (a description) belongs.
    pub fn shape(signature: Signature, wanted: &str, got: &str, at: impl Into<When>) -> Self {
        let at = at.into();
        let message = format!(
            "`{}` must return {wanted};{} it returned `{got}`",
            signature.name,
            at.words()
        );
        Self::new(ErrorKind::Shape, message, Position::NONE, at.time())
    }

    /// The function returned a number that is not finite, for `what`.
    pub fn not_finite(signature: Signature, what: &str, value: f64, at: impl Into<When>) -> Self {
        let at = at.into();
        let message = format!(
            "`{}` returned {value} for {what}{}: a division by zero, or the square root of a negative number?",
            signature.name,
            at.words()
        );
        Self::new(ErrorKind::NotFinite, message, Position::NONE, at.time())
    }

    /// An error while the function ran (`source` is its code).
    pub(crate) fn run(e: &EvalAltResult, at: When, signature: Signature, source: &str) -> Self {
        let inner = e.unwrap_inner();
        // An operation count stops wherever it is; then the function's call.
        let position = match inner.position() {
            p if p.is_none() => e.position(),
            p => p,
        };
        let when = at.words();
        let (kind, message) = match inner {
            EvalAltResult::ErrorTerminated(token, _) => stopped(&token.to_string(), &when),
            EvalAltResult::ErrorTooManyOperations(_) => stopped(stop::CALL_STEPS, &when),
            EvalAltResult::ErrorStackOverflow(_) => (
                ErrorKind::TooDeep,
                format!(
                    "functions called functions more than {} deep{when}: does a function call itself and never stop?",
                    LIMITS.call_depth
                ),
            ),
            EvalAltResult::ErrorDataTooLarge(what, _) => {
                (ErrorKind::TooLarge, too_large(what, &when))
            }
            other => (
                ErrorKind::Runtime,
                format!(
                    "in `{}`{when}: {}",
                    signature.name,
                    crate::words::runtime(other, source).unwrap_or_else(|| plain(other))
                ),
            ),
        };
        Self::new(kind, message, position, at.time())
    }

    /// The function answered, or kept in `this`, lists inside lists
    /// deeper than the sandbox allows.
    pub(crate) fn nested(signature: Signature, what: &str, at: When) -> Self {
        let message = format!(
            "`{}` {what} lists or maps inside each other more than {} deep{}: does something wrap itself every call?",
            signature.name,
            LIMITS.nesting,
            at.words()
        );
        Self::new(ErrorKind::TooLarge, message, Position::NONE, at.time())
    }
}

/// Why the sandbox stopped a call (see [`stop`]), in words.
fn stopped(token: &str, when: &str) -> (ErrorKind, String) {
    match token {
        stop::RUN_STEPS => (
            ErrorKind::TooSlow,
            format!(
                "your function has done more than {} steps in all{when}: does it do far more work each time than the job needs?",
                group(LIMITS.run_operations)
            ),
        ),
        stop::CALL_TIME => (
            ErrorKind::Endless,
            format!(
                "your function ran for more than {} s in one call{when}: is there a loop that never ends, or a list that grows each time round?",
                LIMITS.call_seconds
            ),
        ),
        stop::RUN_TIME => (
            ErrorKind::TooSlow,
            format!(
                "your function has run for more than {} s in all{when}: does it do far more work each time than the job needs?",
                LIMITS.run_seconds
            ),
        ),
        _ => (
            ErrorKind::Endless,
            format!(
                "your function did more than {} steps{when}: is there a loop that never ends?",
                group(LIMITS.operations)
            ),
        ),
    }
}

/// A string, list or map grown past its bound.
fn too_large(what: &str, when: &str) -> String {
    let thing = if what.contains("string") {
        format!(
            "a string longer than {} characters",
            group(LIMITS.string as u64)
        )
    } else if what.contains("map") {
        format!(
            "a map of more than {} entries (counting the entries of maps inside it)",
            group(LIMITS.map as u64)
        )
    } else {
        format!(
            "a list of more than {} items (counting the items of lists inside it)",
            group(LIMITS.array as u64)
        )
    };
    format!("your function made {thing}{when}: does something grow every time round a loop?")
}

/// Rhai's own message without its position (the error carries that).
fn plain(e: &EvalAltResult) -> String {
    let text = e.to_string();
    match text.rfind(" (line ") {
        Some(i) if text.ends_with(')') => text[..i].to_owned(),
        _ => text,
    }
}

/// 100000 as "100 000".
fn group(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(' ');
        }
        out.push(c);
    }
    out
}
