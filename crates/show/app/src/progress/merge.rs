//! Two records of one learner's progress made one: another tab's, or the
//! file from another computer.
//!
//! The rule, per item: a lesson once opened stays opened; a quiz once
//! answered stays answered, with the larger count of attempts and the
//! verdict of the latest one; a widget's state and the theme are the most
//! recently changed. Ties go to the larger value, so merging is the same
//! in either order and merging twice changes nothing.

use super::{Progress, QuizRecord, WidgetRecord};

/// What a merge took from the other side, for the learner to read.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Added {
    pub lessons: usize,
    pub answers: usize,
    pub widgets: usize,
}

impl Added {
    pub fn is_empty(&self) -> bool {
        *self == Added::default()
    }

    /// "2 lessons, 1 quiz answer and 3 widget states", or "nothing new".
    pub fn describe(&self) -> String {
        let count = |n: usize, one: &str, many: &str| match n {
            0 => None,
            1 => Some(format!("1 {one}")),
            n => Some(format!("{n} {many}")),
        };
        let parts: Vec<String> = [
            count(self.lessons, "lesson opened", "lessons opened"),
            count(self.answers, "quiz answer", "quiz answers"),
            count(self.widgets, "widget state", "widget states"),
        ]
        .into_iter()
        .flatten()
        .collect();
        match parts.as_slice() {
            [] => "nothing new".to_owned(),
            [one] => one.clone(),
            [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
        }
    }
}

fn quiz_key(r: &QuizRecord) -> (u64, bool) {
    (r.at, r.correct)
}

fn widget_key(r: &WidgetRecord) -> (u64, &str) {
    (r.at, r.state.as_str())
}

impl Progress {
    /// Take into this progress what `other` knows that it does not.
    pub fn merge(&mut self, other: &Progress) -> Added {
        let mut added = Added::default();
        for address in &other.visited {
            if self.visited.insert(address.clone()) {
                added.lessons += 1;
            }
        }
        for (id, theirs) in &other.quizzes {
            let attempts = theirs.attempts;
            match self.quizzes.get_mut(id) {
                None => {
                    self.quizzes.insert(id.clone(), *theirs);
                    added.answers += 1;
                }
                Some(ours) => {
                    if quiz_key(theirs) > quiz_key(ours) {
                        (ours.correct, ours.at) = (theirs.correct, theirs.at);
                        added.answers += 1;
                    }
                    ours.attempts = ours.attempts.max(attempts);
                }
            }
        }
        for (id, theirs) in &other.widgets {
            let newer = self
                .widgets
                .get(id)
                .is_none_or(|ours| widget_key(theirs) > widget_key(ours));
            if newer {
                self.widgets.insert(id.clone(), theirs.clone());
                added.widgets += 1;
            }
        }
        if (other.dark_at, other.dark) > (self.dark_at, self.dark) {
            (self.dark, self.dark_at) = (other.dark, other.dark_at);
        }
        added
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn progress() -> impl Strategy<Value = Progress> {
        let ids = || prop::sample::select(vec!["a/b", "a/c", "d/e"]);
        let answer = (ids(), 0..3usize, 1..4u32, any::<bool>(), 0..5u64);
        let widget = (
            ids(),
            0..2usize,
            prop::sample::select(vec!["", "x=1", "x=2"]),
            0..5u64,
        );
        (
            prop::collection::vec(ids(), 0..3),
            prop::collection::vec(answer, 0..5),
            prop::collection::vec(widget, 0..4),
            prop::option::of(any::<bool>()),
            0..5u64,
        )
            .prop_map(|(visited, answers, widgets, dark, dark_at)| {
                let mut p = Progress::default();
                p.visited.extend(visited.into_iter().map(str::to_owned));
                for (lesson, n, attempts, correct, at) in answers {
                    let record = QuizRecord {
                        attempts,
                        correct,
                        at,
                    };
                    p.quizzes.insert(format!("{lesson}#{n}"), record);
                }
                for (lesson, n, state, at) in widgets {
                    let record = WidgetRecord {
                        state: state.to_owned(),
                        at,
                    };
                    p.widgets.insert(format!("{lesson}@w{n}"), record);
                }
                p.choose_theme(dark, dark_at);
                p
            })
    }

    fn merged(a: &Progress, b: &Progress) -> Progress {
        let mut m = a.clone();
        m.merge(b);
        m
    }

    proptest! {
        #[test]
        fn merging_is_order_free_and_idempotent(a in progress(), b in progress(), c in progress()) {
            prop_assert_eq!(merged(&a, &b), merged(&b, &a));
            prop_assert_eq!(merged(&merged(&a, &b), &c), merged(&a, &merged(&b, &c)));
            prop_assert_eq!(merged(&a, &a), a.clone());
            let mut twice = merged(&a, &b);
            prop_assert!(twice.merge(&b).is_empty(), "a second merge adds nothing");
        }

        #[test]
        fn nothing_done_is_undone(a in progress(), b in progress()) {
            let m = merged(&a, &b);
            prop_assert!(a.visited.is_subset(&m.visited) && b.visited.is_subset(&m.visited));
            for (id, r) in a.quizzes.iter().chain(&b.quizzes) {
                let kept = m.quizzes[id];
                prop_assert!(kept.at >= r.at && kept.attempts >= r.attempts);
            }
            for (id, r) in a.widgets.iter().chain(&b.widgets) {
                prop_assert!(m.widgets[id].at >= r.at);
            }
        }
    }

    #[test]
    fn the_latest_attempt_wins_and_attempts_are_kept() {
        let mut tab1 = Progress::default();
        tab1.record_answer("u/l#0", false, 100);
        tab1.record_answer("u/l#0", false, 110);
        let mut tab2 = Progress::default();
        tab2.record_answer("u/l#0", true, 120);
        tab2.visited.insert("u/l".into());
        tab2.keep_widget("u/l@w0", Some("k=2"), 130);
        let added = tab1.merge(&tab2);
        assert_eq!(
            tab1.quizzes["u/l#0"],
            QuizRecord {
                attempts: 2,
                correct: true,
                at: 120
            }
        );
        assert_eq!(
            added,
            Added {
                lessons: 1,
                answers: 1,
                widgets: 1
            }
        );
        assert_eq!(
            added.describe(),
            "1 lesson opened, 1 quiz answer and 1 widget state"
        );
        // A widget put back to its defaults later is not revived by an
        // older copy.
        tab1.keep_widget("u/l@w0", None, 140);
        assert!(tab1.merge(&tab2).is_empty());
        assert_eq!(tab1.widgets_of("u/l").count(), 0);
        assert_eq!(Added::default().describe(), "nothing new");
        let two = Added {
            lessons: 2,
            answers: 0,
            widgets: 3,
        };
        assert_eq!(two.describe(), "2 lessons opened and 3 widget states");
    }
}
