//! What the learner has done, kept between visits (browser storage on the
//! web, a file natively).

use std::collections::{BTreeMap, BTreeSet};

use serde::{Deserialize, Serialize};

/// The storage key progress is kept under.
pub const STORAGE_KEY: &str = "kinolab.progress";

/// The format version; stored data of another version is reset.
pub const VERSION: u32 = 1;

/// The learner's record of one quiz.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct QuizRecord {
    pub attempts: u32,
    /// Whether the latest answer was right.
    pub correct: bool,
}

/// Everything remembered about the learner.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Progress {
    pub version: u32,
    /// Addresses of lessons opened at least once.
    pub visited: BTreeSet<String>,
    /// Quiz records by quiz id (`unit/lesson#n`).
    pub quizzes: BTreeMap<String, QuizRecord>,
    /// The chosen theme; `None` follows the system.
    pub dark: Option<bool>,
    /// Each widget the learner changed, as its link holds it, by widget id
    /// (`unit/lesson@wN`): the code they wrote, the run they were at.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub widgets: BTreeMap<String, String>,
}

impl Default for Progress {
    fn default() -> Self {
        Self {
            version: VERSION,
            visited: BTreeSet::new(),
            quizzes: BTreeMap::new(),
            dark: None,
            widgets: BTreeMap::new(),
        }
    }
}

/// Why stored progress was thrown away.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ResetNotice(pub String);

impl Progress {
    /// Restore progress from its stored text. Nothing stored gives a fresh
    /// start; unreadable or foreign data also gives a fresh start, plus a
    /// notice to show the learner.
    pub fn restore(stored: Option<&str>) -> (Progress, Option<ResetNotice>) {
        let Some(text) = stored else {
            return (Progress::default(), None);
        };
        match serde_json::from_str::<Progress>(text) {
            Ok(p) if p.version == VERSION => (p, None),
            Ok(p) => (
                Progress::default(),
                Some(ResetNotice(format!(
                    "Your saved progress was written by another version of Kinolab (format {}), so it has been reset.",
                    p.version
                ))),
            ),
            Err(e) => (
                Progress::default(),
                Some(ResetNotice(format!(
                    "Your saved progress could not be read ({e}), so it has been reset."
                ))),
            ),
        }
    }

    /// The text to store.
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).unwrap_or_default()
    }

    /// Record an answer to quiz `id`.
    pub fn record_answer(&mut self, id: &str, correct: bool) {
        let record = self.quizzes.entry(id.to_owned()).or_insert(QuizRecord {
            attempts: 0,
            correct: false,
        });
        record.attempts += 1;
        record.correct = correct;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip() {
        let mut p = Progress::default();
        p.visited.insert("a/b".into());
        p.record_answer("a/b#0", false);
        p.record_answer("a/b#0", true);
        p.dark = Some(true);
        let (back, notice) = Progress::restore(Some(&p.to_json()));
        assert_eq!(back, p);
        assert_eq!(notice, None);
        assert_eq!(
            back.quizzes["a/b#0"],
            QuizRecord {
                attempts: 2,
                correct: true
            }
        );
    }

    #[test]
    fn corrupted_state_resets_with_a_notice() {
        let (p, notice) = Progress::restore(Some("{not json"));
        assert_eq!(p, Progress::default());
        assert!(
            notice
                .unwrap()
                .0
                .starts_with("Your saved progress could not be read")
        );
        let (_, notice) = Progress::restore(Some(
            r#"{"version":99,"visited":[],"quizzes":{},"dark":null}"#,
        ));
        assert!(notice.unwrap().0.contains("format 99"));
        let (_, notice) = Progress::restore(Some(
            r#"{"version":1,"visited":[],"quizzes":{},"dark":null,"extra":1}"#,
        ));
        assert!(notice.is_some(), "unknown fields are not silently kept");
        assert_eq!(Progress::restore(None), (Progress::default(), None));
    }
}
