//! What the learner has done, kept between visits (browser storage on the
//! web, a file natively), merged across tabs and computers.
//!
//! - [`merge`]: two records of progress become one by the rule the README
//!   states (a visited lesson stays visited, an answered quiz stays
//!   answered, the latest attempt wins per item);
//! - [`migrate`]: stored progress of every earlier format, and lessons that
//!   moved or were retired;
//! - [`file`]: the progress file a learner takes to another computer.

pub mod file;
pub mod merge;
pub mod migrate;

use std::collections::{BTreeMap, BTreeSet};

use serde::{Deserialize, Serialize};

/// The storage key progress is kept under.
pub const STORAGE_KEY: &str = "kinolab.progress";

/// Where stored progress that could not be read is set aside, so that a
/// later version (or a person) can still recover it.
pub const UNREADABLE_KEY: &str = "kinolab.progress.unreadable";

/// The format version. Every earlier one has a migration in [`migrate`].
pub const VERSION: u32 = 2;

/// Milliseconds since 1970 (the browser's `Date.now()`): when an attempt
/// or a change was made, so that the latest one wins in a merge.
pub type Millis = u64;

/// The learner's record of one quiz.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct QuizRecord {
    pub attempts: u32,
    /// Whether the latest answer was right.
    pub correct: bool,
    /// When the latest answer was given.
    pub at: Millis,
}

/// A widget the learner changed: its state as its link holds it (empty
/// when put back to its defaults) and when.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WidgetRecord {
    pub state: String,
    pub at: Millis,
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
    /// When the theme was last chosen.
    #[serde(default)]
    pub dark_at: Millis,
    /// Each widget the learner changed, by widget id (`unit/lesson@wN`):
    /// the code they wrote, the run they were at.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub widgets: BTreeMap<String, WidgetRecord>,
}

impl Default for Progress {
    fn default() -> Self {
        Self {
            version: VERSION,
            visited: BTreeSet::new(),
            quizzes: BTreeMap::new(),
            dark: None,
            dark_at: 0,
            widgets: BTreeMap::new(),
        }
    }
}

/// Something to tell the learner about their stored progress.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ResetNotice(pub String);

impl Progress {
    /// Restore progress from its stored text, migrating earlier formats.
    /// Nothing stored gives a fresh start; unreadable data also gives a
    /// fresh start, plus a notice (the host sets the text aside under
    /// [`UNREADABLE_KEY`]).
    pub fn restore(stored: Option<&str>) -> (Progress, Option<ResetNotice>) {
        let Some(text) = stored else {
            return (Progress::default(), None);
        };
        match migrate::read(text) {
            Ok(p) => (p, None),
            Err(why) => (
                Progress::default(),
                Some(ResetNotice(format!(
                    "Your saved progress could not be read ({why}), so the lab starts afresh; the old copy is kept aside in this browser."
                ))),
            ),
        }
    }

    /// The text to store.
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).unwrap_or_default()
    }

    /// Record an answer to quiz `id`, given at `at`.
    pub fn record_answer(&mut self, id: &str, correct: bool, at: Millis) {
        let record = self.quizzes.entry(id.to_owned()).or_insert(QuizRecord {
            attempts: 0,
            correct: false,
            at,
        });
        record.attempts = record.attempts.saturating_add(1);
        record.correct = correct;
        record.at = at;
    }

    /// Keep widget `id`'s state (`None`: back to its defaults), changed at
    /// `at`; whether anything changed.
    pub fn keep_widget(&mut self, id: &str, state: Option<&str>, at: Millis) -> bool {
        let state = state.unwrap_or_default();
        match self.widgets.get(id) {
            Some(kept) if kept.state == state => false,
            None if state.is_empty() => false,
            _ => {
                let record = WidgetRecord {
                    state: state.to_owned(),
                    at,
                };
                self.widgets.insert(id.to_owned(), record);
                true
            }
        }
    }

    /// The widget states kept for the lesson at `address`, by widget id
    /// (those put back to their defaults left out).
    pub fn widgets_of<'a>(&'a self, address: &str) -> impl Iterator<Item = (&'a str, &'a str)> {
        let prefix = format!("{address}@w");
        self.widgets
            .range(prefix.clone()..)
            .take_while(move |(id, _)| id.starts_with(&prefix))
            .filter(|(_, kept)| !kept.state.is_empty())
            .map(|(id, kept)| (id.as_str(), kept.state.as_str()))
    }

    /// Choose the theme (`None`: follow the system) at `at`.
    pub fn choose_theme(&mut self, dark: Option<bool>, at: Millis) {
        self.dark = dark;
        self.dark_at = at;
    }

    /// Lessons this progress has records for that `known` (the course's
    /// addresses) does not have: kept, never dropped, and reported.
    pub fn retired(&self, known: &BTreeSet<String>) -> BTreeSet<String> {
        let lesson_of =
            |id: &str| -> String { id.split(['#', '@']).next().unwrap_or_default().to_owned() };
        self.visited
            .iter()
            .cloned()
            .chain(self.quizzes.keys().map(|id| lesson_of(id)))
            .chain(self.widgets.keys().map(|id| lesson_of(id)))
            .filter(|address| !known.contains(address))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip() {
        let mut p = Progress::default();
        p.visited.insert("a/b".into());
        p.record_answer("a/b#0", false, 10);
        p.record_answer("a/b#0", true, 20);
        p.choose_theme(Some(true), 30);
        assert!(p.keep_widget("a/b@w0", Some("x=1"), 40));
        assert!(!p.keep_widget("a/b@w0", Some("x=1"), 50), "no change");
        let (back, notice) = Progress::restore(Some(&p.to_json()));
        assert_eq!(back, p);
        assert_eq!(notice, None);
        assert_eq!(
            back.quizzes["a/b#0"],
            QuizRecord {
                attempts: 2,
                correct: true,
                at: 20,
            }
        );
        assert_eq!(
            back.widgets_of("a/b").collect::<Vec<_>>(),
            [("a/b@w0", "x=1")]
        );
    }

    #[test]
    fn a_widget_put_back_keeps_a_dated_blank() {
        let mut p = Progress::default();
        assert!(!p.keep_widget("a/b@w0", None, 1), "nothing to forget");
        assert!(p.keep_widget("a/b@w0", Some("x=1"), 2));
        assert!(p.keep_widget("a/b@w0", None, 3));
        // The blank is kept, so a merge with an older copy cannot bring
        // the old state back.
        assert_eq!(p.widgets["a/b@w0"].at, 3);
        assert_eq!(p.widgets_of("a/b").count(), 0);
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
            r#"{"version":2,"visited":[],"quizzes":{},"dark":null,"extra":1}"#,
        ));
        assert!(notice.is_some(), "unknown fields are not silently kept");
        assert_eq!(Progress::restore(None), (Progress::default(), None));
    }

    #[test]
    fn records_of_lessons_the_course_lacks_are_reported_not_dropped() {
        let mut p = Progress::default();
        p.visited.insert("a/b".into());
        p.record_answer("gone/quiz#1", true, 1);
        p.keep_widget("old/widget@w2", Some("s"), 1);
        let known = BTreeSet::from(["a/b".to_owned()]);
        let retired: Vec<String> = p.retired(&known).into_iter().collect();
        assert_eq!(retired, ["gone/quiz", "old/widget"]);
        assert_eq!(p.quizzes.len(), 1);
    }
}
