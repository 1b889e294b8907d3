#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! `checkLesson` (and `kinolab lessons`) fed hostile lesson text: real
//! lessons cut anywhere, with hostile pieces spliced in (deep nesting,
//! unclosed fences and formulas, huge lines, control characters, widget
//! and quiz blocks gone wrong). Every answer is a summary or one short
//! line saying what is wrong, in bounded time; nothing panics.

use std::time::{Duration, Instant};

use kinolab_api::teach::CheckLesson;
use kinolab_api::{NoFiles, answer};
use proptest::prelude::*;

const LESSONS: [&str; 3] = [
    include_str!("../../../../lessons/02-wheeled-locomotion/05-icr-and-holonomy.md"),
    include_str!("../../../../lessons/03-motion-control/03-programming-the-robot.md"),
    include_str!("../../../../lessons/07-legged-locomotion/02-balance.md"),
];

/// Pieces no lesson should contain.
fn hostile() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("> ".repeat(5_000)),
        Just(format!("{}x", "- ".repeat(5_000))),
        Just("```widget\nname: wheel-workbench\n".to_owned()),
        Just("```quiz\nkind: single\n".to_owned()),
        Just("$\\frac{\\frac{\\frac{".repeat(2_000)),
        Just("$$".to_owned()),
        Just("\u{0}\u{1b}[2J\r".to_owned()),
        Just("x".repeat(1 << 20)),
        Just("[".repeat(10_000)),
        Just("---\ntitle: [\n---\n".to_owned()),
        Just("```widget\nname: no-such-widget\nspeed: 1e308\n```\n".to_owned()),
        Just("| a |\n|---|\n".repeat(2_000)),
        Just("![](../../../../etc/passwd)".to_owned()),
    ]
}

fn check(markdown: &str) {
    let operation = CheckLesson {
        file: "hostile.md".to_owned(),
        markdown: markdown.to_owned(),
    };
    let started = Instant::now();
    let result = answer(&operation, &mut NoFiles);
    let took = started.elapsed();
    // Debug builds are ten times slower than the lab; this still catches
    // anything that grows faster than the text.
    assert!(took < Duration::from_secs(10), "took {took:?}");
    if let Err(e) = result {
        let line = kinolab_common::error::one_line(&e.message);
        assert!(
            !line.contains('\n') && line.chars().count() <= 401,
            "{line}"
        );
        assert!(!line.is_empty());
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn hostile_lesson_text_gets_an_answer_never_a_panic(
        which in 0..LESSONS.len(),
        cut in 0.0..1.0f64,
        at in 0.0..1.0f64,
        piece in hostile(),
    ) {
        let lesson = LESSONS[which];
        let boundary = |f: f64| {
            let mut k = (lesson.len() as f64 * f) as usize;
            while !lesson.is_char_boundary(k) {
                k -= 1;
            }
            k
        };
        let (end, splice) = (boundary(cut), boundary(at * cut));
        let text = format!("{}{piece}{}", &lesson[..splice], &lesson[splice..end]);
        check(&text);
    }
}

#[test]
fn the_real_lessons_pass() {
    for lesson in LESSONS {
        let operation = CheckLesson {
            file: "lesson.md".to_owned(),
            markdown: lesson.to_owned(),
        };
        assert!(answer(&operation, &mut NoFiles).is_ok());
    }
}
