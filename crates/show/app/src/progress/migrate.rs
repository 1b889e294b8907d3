//! Stored progress of every format the lab has written, read into today's,
//! and lessons that moved to a new address.
//!
//! Each change of format adds a reader for the old one here and a fixture
//! (`fixtures/vN.json`, a state that version really stored) to the tests.

use std::collections::{BTreeMap, BTreeSet};

use serde::Deserialize;

use super::{Millis, Progress, QuizRecord, VERSION, WidgetRecord};

/// A lesson that moved: a learner who opened it has opened its new home.
/// Its quiz answers and widget states stay under the old address (the
/// questions changed), where [`Progress::retired`] reports them.
#[derive(Debug)]
pub struct Moved {
    pub from: &'static str,
    pub to: &'static str,
}

/// Every lesson that has moved since the first release.
pub const MOVED: &[Moved] = &[
    // Round two split the automation unit's lesson on legs into the
    // legged-locomotion unit, which opens with its first half.
    Moved {
        from: "automation/legs-and-balance",
        to: "legged-locomotion/legs-and-wheels",
    },
];

/// Format 1: no times on quiz answers or widget states.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Version1 {
    #[allow(dead_code)]
    version: u32,
    visited: BTreeSet<String>,
    quizzes: BTreeMap<String, QuizRecord1>,
    dark: Option<bool>,
    #[serde(default)]
    widgets: BTreeMap<String, String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct QuizRecord1 {
    attempts: u32,
    correct: bool,
}

/// Records from before times were kept count as older than any new one.
const BEFORE_TIMES: Millis = 0;

impl From<Version1> for Progress {
    fn from(old: Version1) -> Self {
        let quiz = |r: QuizRecord1| QuizRecord {
            attempts: r.attempts,
            correct: r.correct,
            at: BEFORE_TIMES,
        };
        let widget = |state| WidgetRecord {
            state,
            at: BEFORE_TIMES,
        };
        // Inserted one by one: collecting into a map sorts, and would put
        // a sort per record type in the lab's wasm.
        let mut quizzes = BTreeMap::new();
        for (k, r) in old.quizzes {
            quizzes.insert(k, quiz(r));
        }
        let mut widgets = BTreeMap::new();
        for (k, s) in old.widgets {
            widgets.insert(k, widget(s));
        }
        Progress {
            version: VERSION,
            visited: old.visited,
            quizzes,
            dark: old.dark,
            dark_at: BEFORE_TIMES,
            widgets,
        }
    }
}

/// Progress from stored text of any format so far, with moved lessons
/// followed; why not, in words for the learner.
pub fn read(text: &str) -> Result<Progress, String> {
    // Read once as JSON, then as the format it names: one JSON reader in
    // the lab's wasm rather than one per format.
    let value = serde_json::from_str(text).map_err(|e| format!("not progress data: {e}"))?;
    read_value(value)
}

/// [`read`] for progress already read as JSON (a progress file holds it).
pub fn read_value(value: serde_json::Value) -> Result<Progress, String> {
    if !value.is_object() {
        return Err("not progress data: it is not a JSON object".to_owned());
    }
    let version = match value.get("version") {
        None | Some(serde_json::Value::Null) => None,
        Some(v) => Some(
            v.as_u64()
                .and_then(|v| u32::try_from(v).ok())
                .ok_or_else(|| format!("not progress data: version `{v}` is not a number"))?,
        ),
    };
    let mut progress = match version {
        Some(1) => Version1::deserialize(value).map(Progress::from),
        Some(VERSION) => Progress::deserialize(value),
        Some(newer) if newer > VERSION => {
            return Err(format!(
                "it was written by a newer Kinolab, format {newer}; this one reads up to {VERSION}"
            ));
        }
        Some(other) => return Err(format!("format {other} is not one Kinolab wrote")),
        None => return Err("it has no format version".to_owned()),
    }
    .map_err(|e| format!("format {}: {e}", version.unwrap_or_default()))?;
    follow_moves(&mut progress);
    Ok(progress)
}

/// A visit to a moved lesson counts for its new address.
fn follow_moves(progress: &mut Progress) {
    for moved in MOVED {
        if progress.visited.remove(moved.from) {
            progress.visited.insert(moved.to.to_owned());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What version 1 stored for a learner midway through the course (a
    /// visit to the lesson that later moved, quiz answers, widget states).
    const V1: &str = include_str!("fixtures/v1.json");
    const V2: &str = include_str!("fixtures/v2.json");

    #[test]
    fn version_1_keeps_every_record() {
        let p = read(V1).unwrap();
        assert_eq!(p.version, VERSION);
        assert!(p.visited.contains("wheeled-locomotion/wheel-kinds"));
        assert!(!p.visited.contains("automation/legs-and-balance"));
        assert!(p.visited.contains("legged-locomotion/legs-and-wheels"));
        let quiz = p.quizzes["wheeled-locomotion/wheel-kinds#0"];
        assert_eq!((quiz.attempts, quiz.correct, quiz.at), (2, true, 0));
        // The moved lesson's answers stay under its old address.
        assert!(p.quizzes.contains_key("automation/legs-and-balance#1"));
        assert_eq!(p.dark, Some(true));
        assert_eq!(
            p.widgets_of("motion-control/programming-the-robot").count(),
            1
        );
        // Read again in today's format, nothing changes.
        assert_eq!(read(&p.to_json()).unwrap(), p);
    }

    #[test]
    fn version_2_reads_as_it_was_written() {
        let p = read(V2).unwrap();
        assert_eq!(p.quizzes["behaviours/emergence#1"].at, 1_764_806_400_000);
        assert_eq!(
            p.widgets["wheeled-locomotion/icr-and-holonomy@w0"].state,
            ""
        );
        assert_eq!(p.to_json(), V2.trim());
    }

    #[test]
    fn moves_lead_from_a_lesson_gone_to_one_the_course_has() {
        let course = kinolab_lessons::bundled::course().unwrap();
        for moved in MOVED {
            assert!(course.lesson(moved.to).is_some(), "{}", moved.to);
            assert!(course.lesson(moved.from).is_none(), "{}", moved.from);
        }
    }

    #[test]
    fn other_formats_are_refused_with_a_reason() {
        assert!(
            read(r#"{"version":3}"#)
                .unwrap_err()
                .contains("newer Kinolab, format 3")
        );
        assert!(read(r#"{"version":0}"#).unwrap_err().contains("format 0"));
        assert!(
            read(r#"{"visited":[]}"#)
                .unwrap_err()
                .contains("no format version")
        );
        assert!(read("[1,2]").unwrap_err().starts_with("not progress data"));
        let broken = V1.replace("\"attempts\": 2", "\"attempts\": \"two\"");
        assert!(read(&broken).unwrap_err().starts_with("format 1:"));
    }
}
