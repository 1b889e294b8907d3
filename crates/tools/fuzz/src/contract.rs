//! The verdict on one call: did the command keep its contract?

use std::time::Duration;

use serde_json::Value;

use crate::case::{Case, Sink};

/// What a call left behind.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// The exit status; `None` when a signal ended it.
    pub status: Option<i32>,
    pub stdout: Vec<u8>,
    pub stderr: Vec<u8>,
    pub elapsed: Duration,
    /// Killed after the time limit.
    pub timed_out: bool,
}

/// The classes of the reliability table.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Verdict {
    /// Exit 0 and one JSON document with finite, meaningful numbers.
    Answer,
    /// Exit 2 and one escaped line naming what is wrong.
    Refused,
    /// The answer could not be written (a full disk, a closed pipe), said
    /// in one line.
    WriteFailed,
    /// A panic, a signal, an unexpected status or memory exhausted.
    Crash(String),
    /// Still running at the time limit.
    Hang,
    /// Exit 0 with something that is not an answer.
    Nonsense(String),
    /// An error that is not one short escaped line.
    BadError(String),
}

impl Verdict {
    /// The column of the table.
    pub fn class(&self) -> &'static str {
        match self {
            Verdict::Answer => "answer",
            Verdict::Refused => "refused",
            Verdict::WriteFailed => "write failed",
            Verdict::Crash(_) => "crash",
            Verdict::Hang => "hang",
            Verdict::Nonsense(_) => "nonsense",
            Verdict::BadError(_) => "bad error",
        }
    }

    /// Whether the contract was kept.
    pub fn kept(&self) -> bool {
        matches!(
            self,
            Verdict::Answer | Verdict::Refused | Verdict::WriteFailed
        )
    }
}

/// Keys whose value may be `null` in an answer: "none" in the contract's
/// sense (no time to goal, no ICR, no path), never a number that overflowed.
pub const NULLABLE: [&str; 23] = [
    "behaviour",
    // A joint without limits; a widget parameter with no default; a
    // straight drive's turn radius; a top-level group of bodies; a foot
    // that held.
    "left_foot_at",
    "limits",
    "parent",
    "default",
    "radius",
    "margin",
    "min_margin",
    "group",
    "control",
    "time_to_goal",
    "slowest_time_to_goal",
    "icr",
    "cost",
    "wheels",
    "time",
    "model_age_mean",
    "model_age_max",
    // A mechanism with no two bodies far enough apart to measure.
    "clearance",
    // A graded world that passed has no reason; a script that ran
    // cleanly no error (whose line, column and time may be unknown).
    "reason",
    "error",
    "error_kind",
    "first_failure",
];

/// Keys whose objects may hold nulls: a learner's script error, where the
/// line or the time is not always known.
const NULLS_INSIDE: [&str; 1] = ["error"];

/// The longest error line, in characters.
pub const MAX_ERROR_CHARS: usize = 420;

/// Judge `outcome` of `case`.
pub fn judge(case: &Case, outcome: &Outcome) -> Verdict {
    if outcome.timed_out {
        return Verdict::Hang;
    }
    let stderr = String::from_utf8_lossy(&outcome.stderr);
    if stderr.contains("panicked") || stderr.contains("RUST_BACKTRACE") {
        return Verdict::Crash(first_line(&stderr));
    }
    match outcome.status {
        None => Verdict::Crash(format!(
            "killed by a signal; stderr: {}",
            first_line(&stderr)
        )),
        Some(0) => answer(case, outcome),
        Some(2) => error_line(outcome).map_or(Verdict::Refused, Verdict::BadError),
        Some(3) if case.sink != Sink::File => {
            error_line(outcome).map_or(Verdict::WriteFailed, Verdict::BadError)
        }
        Some(code) => Verdict::Crash(format!("exit status {code}: {}", first_line(&stderr))),
    }
}

fn first_line(text: &str) -> String {
    let line = text.lines().find(|l| !l.trim().is_empty()).unwrap_or("");
    line.chars().take(200).collect()
}

/// What is wrong with the error output, if anything.
fn error_line(outcome: &Outcome) -> Option<String> {
    if !outcome.stdout.is_empty() {
        return Some("printed on stdout as well as failing".into());
    }
    let Ok(text) = std::str::from_utf8(&outcome.stderr) else {
        return Some("stderr is not UTF-8".into());
    };
    let Some(line) = text.strip_suffix('\n') else {
        return Some("stderr does not end with a newline".into());
    };
    if line.contains('\n') {
        return Some(format!("{} lines on stderr", line.lines().count()));
    }
    if !line.starts_with("kinolab: ") || line.len() <= "kinolab: ".len() {
        return Some(format!("not a `kinolab: ` message: {}", first_line(line)));
    }
    if line.chars().any(char::is_control) {
        return Some("a control character in the message".into());
    }
    if line.chars().count() > MAX_ERROR_CHARS {
        return Some(format!("{} characters long", line.chars().count()));
    }
    None
}

/// Exit 0: one JSON document, nothing on stderr, no number hidden as null.
fn answer(case: &Case, outcome: &Outcome) -> Verdict {
    match case.sink {
        Sink::File => {}
        // The answer may have gone into the pipe before its reader left.
        Sink::Closed => return Verdict::Answer,
        Sink::Full => {
            return Verdict::Nonsense("exit 0 although the answer could not be written".into());
        }
    }
    if !outcome.stderr.is_empty() {
        return Verdict::Nonsense(format!(
            "exit 0 with stderr: {}",
            first_line(&String::from_utf8_lossy(&outcome.stderr))
        ));
    }
    let Ok(text) = std::str::from_utf8(&outcome.stdout) else {
        return Verdict::Nonsense("stdout is not UTF-8".into());
    };
    if case.args.iter().any(|a| a == "--csv") {
        return csv(text);
    }
    let Some(line) = text.strip_suffix('\n').filter(|l| !l.contains('\n')) else {
        return Verdict::Nonsense("stdout is not exactly one line".into());
    };
    let value: Value = match serde_json::from_str(line) {
        Ok(v) => v,
        Err(e) => return Verdict::Nonsense(format!("stdout is not JSON: {e}")),
    };
    if let Some(path) = hidden_number(&value, "") {
        return Verdict::Nonsense(format!("`{path}` is null"));
    }
    if let Some(why) = false_convergence(&value) {
        return Verdict::Nonsense(why);
    }
    Verdict::Answer
}

/// A CSV answer: a header, then records of as many fields, each ended
/// by a new line (one inside quotes belongs to its field).
fn csv(text: &str) -> Verdict {
    let mut records: Vec<usize> = Vec::new();
    let (mut fields, mut quoted) = (1, false);
    for c in text.chars() {
        match c {
            '"' => quoted = !quoted,
            ',' if !quoted => fields += 1,
            '\n' if !quoted => {
                records.push(fields);
                fields = 1;
            }
            _ => {}
        }
    }
    if quoted || fields != 1 || !text.ends_with('\n') {
        return Verdict::Nonsense("the CSV's last record is not ended".into());
    }
    match records.split_first() {
        None => Verdict::Nonsense("an empty CSV".into()),
        Some((header, rows)) => match rows.iter().position(|n| n != header) {
            Some(i) => Verdict::Nonsense(format!("CSV row {} has not {header} fields", i + 1)),
            None => Verdict::Answer,
        },
    }
}

/// The path of a `null` where a number belongs (any key outside
/// [`NULLABLE`]).
fn hidden_number(value: &Value, path: &str) -> Option<String> {
    match value {
        Value::Object(map) => map.iter().find_map(|(k, v)| {
            let here = format!("{path}.{k}");
            if v.is_null() && !NULLABLE.contains(&k.as_str()) {
                Some(here)
            } else if NULLS_INSIDE.contains(&k.as_str()) {
                None
            } else {
                hidden_number(v, &here)
            }
        }),
        Value::Array(items) => items.iter().enumerate().find_map(|(i, v)| {
            let here = format!("{path}[{i}]");
            if v.is_null() {
                Some(here)
            } else {
                hidden_number(v, &here)
            }
        }),
        _ => None,
    }
}

/// `converged: true` with errors that say otherwise.
fn false_convergence(value: &Value) -> Option<String> {
    if value.get("converged") != Some(&Value::Bool(true)) {
        return None;
    }
    for key in ["position_error", "rotation_error"] {
        match value.get(key).and_then(Value::as_f64) {
            Some(e) if e <= 1e-3 => {}
            other => return Some(format!("converged with {key} {other:?}")),
        }
    }
    None
}

/// What a regression case also expects, if it is not met.
pub fn unmet(case: &Case, outcome: &Outcome) -> Option<String> {
    let e = &case.expect;
    if let Some(code) = e.exit
        && outcome.status != Some(code)
    {
        return Some(format!("exit {:?}, expected {code}", outcome.status));
    }
    let stderr = String::from_utf8_lossy(&outcome.stderr);
    let stdout = String::from_utf8_lossy(&outcome.stdout);
    if let Some(piece) = e
        .stderr_contains
        .iter()
        .find(|p| !stderr.contains(p.as_str()))
    {
        return Some(format!("stderr lacks `{piece}`: {}", first_line(&stderr)));
    }
    if let Some(piece) = e.stderr_lacks.iter().find(|p| stderr.contains(p.as_str())) {
        return Some(format!("stderr has `{piece}`: {}", first_line(&stderr)));
    }
    if let Some(piece) = e
        .stdout_contains
        .iter()
        .find(|p| !stdout.contains(p.as_str()))
    {
        return Some(format!("stdout lacks `{piece}`"));
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn outcome(status: Option<i32>, stdout: &str, stderr: &str) -> Outcome {
        Outcome {
            status,
            stdout: stdout.into(),
            stderr: stderr.into(),
            elapsed: Duration::ZERO,
            timed_out: false,
        }
    }

    #[test]
    fn every_class_is_recognised() {
        let case = Case::new("fk", vec![]);
        let judge = |o: &Outcome| judge(&case, o);
        assert_eq!(judge(&outcome(Some(0), "{\"a\":1}\n", "")), Verdict::Answer);
        assert_eq!(
            judge(&outcome(
                Some(2),
                "",
                "kinolab: x.json: a: must be finite\n"
            )),
            Verdict::Refused
        );
        assert_eq!(
            judge(&outcome(Some(0), "{\"x\":null}\n", "")).class(),
            "nonsense"
        );
        assert_eq!(
            judge(&outcome(Some(0), "{\"icr\":null}\n", "")),
            Verdict::Answer
        );
        assert_eq!(
            judge(&outcome(Some(0), "[1,null]\n", "")).class(),
            "nonsense"
        );
        assert_eq!(
            judge(&outcome(
                Some(0),
                "{\"converged\":true,\"position_error\":0}\n",
                ""
            ))
            .class(),
            "nonsense"
        );
        assert_eq!(
            judge(&outcome(Some(2), "", "kinolab: a\nb\n")).class(),
            "bad error"
        );
        assert_eq!(judge(&outcome(Some(2), "", "oops\n")).class(), "bad error");
        assert_eq!(
            judge(&outcome(Some(134), "", "thread 'main' panicked at x\n")).class(),
            "crash"
        );
        assert_eq!(judge(&outcome(None, "", "")).class(), "crash");
        let mut hung = outcome(None, "", "");
        hung.timed_out = true;
        assert_eq!(judge(&hung), Verdict::Hang);
    }
}
