//! The code panel: a graded exercise's editor, its runs and the stepper.

use crate::{Catalogue, Kind, WidgetSchema};

use super::param;

fn check_code(text: &str) -> Result<(), String> {
    kinolab_exercises::packed::unpack(text).map(|_| ())
}

/// The longest note kept of a run that did not finish.
const MAX_NOTE: usize = 200;

fn check_note(text: &str) -> Result<(), String> {
    if text.chars().count() > MAX_NOTE {
        return Err(format!("at most {MAX_NOTE} characters"));
    }
    if text.chars().any(char::is_control) {
        return Err("one line of text, please".into());
    }
    Ok(())
}

pub(crate) static WIDGETS: &[WidgetSchema] = &[WidgetSchema {
    name: "code",
    summary: "write the robot's code for a graded exercise, run it on the worlds shown, step through what your function saw and answered, and submit",
    params: &[
        param(
            "exercise",
            Kind::Catalogue {
                of: Catalogue::Exercises,
            },
            Some("control-park"),
            "the graded exercise (`kinolab script exercises` lists them)",
        ),
        param(
            "code",
            Kind::Text {
                example: "S8tTSM7PKynKz9EoysjXUUjMKchI1FFISi1J1FSoVohGCMYq1AIA",
                check: check_code,
            },
            None,
            "the learner's code, deflated and in URL-safe base64 (the starter when not given)",
        ),
        param(
            "world",
            Kind::Integer { min: 1, max: 12 },
            Some("1"),
            "the world the stepper shows, counting from the first",
        ),
        param(
            "hints",
            Kind::Integer { min: 0, max: 10 },
            Some("0"),
            "hints unlocked by failed submissions",
        ),
        param(
            "ended",
            Kind::Text {
                example: "the run took far too long and was ended",
                check: check_note,
            },
            None,
            "why the last run did not finish, when it ended what ran it: the lesson reopens with this notice",
        ),
    ],
    rules: None,
}];
