//! Writing the one JSON document, or the one error line.
//!
//! The document is bounded ([`MAX_OUTPUT_BYTES`]) so no option can make
//! the tool write gigabytes; a closed pipe or a full disk is reported in
//! one line, never as a panic.

use std::io::Write;
use std::process::ExitCode;

use kinolab_common::error::one_line;
use serde_json::Value;

/// The largest document any command prints.
pub(crate) const MAX_OUTPUT_BYTES: usize = 32 * 1024 * 1024;

/// Exit status for bad input (the contract's "non-zero").
const BAD_INPUT: u8 = 2;
/// Exit status when the answer could not be written.
const CANNOT_WRITE: u8 = 3;

/// Print `value` as one line of JSON on stdout.
pub(crate) fn print(value: &Value) -> ExitCode {
    print_text(&format!("{value}\n"))
}

/// Print `text` (ending in a new line) on stdout.
pub(crate) fn print_text(text: &str) -> ExitCode {
    if text.len() > MAX_OUTPUT_BYTES {
        return fail(&format!(
            "the answer would be {:.0} MB, above the output bound of {} MB; ask for less \
             (fewer points, starts or samples, or no paths)",
            text.len() as f64 / 1e6,
            MAX_OUTPUT_BYTES / (1024 * 1024)
        ));
    }
    let mut out = std::io::stdout().lock();
    match write!(out, "{text}").and_then(|()| out.flush()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            say(&format!("cannot write the answer: {e}"));
            ExitCode::from(CANNOT_WRITE)
        }
    }
}

/// Report bad input: one line on stderr, exit status 2.
pub(crate) fn fail(message: &str) -> ExitCode {
    say(message);
    ExitCode::from(BAD_INPUT)
}

/// A remark beside the answer: one line on stderr.
pub(crate) fn note(message: &str) {
    say(&format!("note: {message}"));
}

/// One line on stderr; if even that cannot be written there is no one to tell.
fn say(message: &str) {
    let _ = writeln!(std::io::stderr().lock(), "kinolab: {}", one_line(message));
}
