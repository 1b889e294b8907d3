//! Graded tasks, checked by the core.

use kinolab_common::Feedback;

use crate::ant::{Beach, DEFAULT_PEBBLES, walk};
use crate::slots::outcome;

/// "Find a body size of at most 100 whose path on this beach is within
/// 1 % of straight."
pub fn nearly_straight(seed: u64, size: f64) -> Feedback {
    let beach = match Beach::new(seed, DEFAULT_PEBBLES) {
        Ok(b) => b,
        Err(e) => return Feedback::not_yet(e.to_string()),
    };
    match walk(&beach, size) {
        Err(e) => Feedback::not_yet(e.to_string()),
        Ok(_) if size > 100.0 => Feedback::not_yet(format!(
            "Size {size:.0} is over 100: find a smaller body whose path is nearly straight."
        )),
        Ok(w) if w.tortuosity <= 1.01 => Feedback::met(format!(
            "At size {size:.0} the path is {:.3} times the straight line, with {} pebbles that matter.",
            w.tortuosity, w.obstacles
        )),
        Ok(w) => Feedback::not_yet(format!(
            "At size {size:.0} the path is {:.3} times the straight line: {} pebbles still matter.",
            w.tortuosity, w.obstacles
        )),
    }
}

/// "The car fails in the maze: change exactly one slot, keep the world,
/// and reach the goal."
pub fn fix_the_car(body: &'static str, behaviours: &'static str, world: &'static str) -> Feedback {
    if world != "maze" {
        return Feedback::not_yet("Keep the world: the task is to get through the maze.");
    }
    let changed = usize::from(body != "car") + usize::from(behaviours != "go-and-avoid");
    if changed != 1 {
        return Feedback::not_yet(format!(
            "Change exactly one slot (you changed {changed}): that is how you learn which one the failure belongs to."
        ));
    }
    match outcome(body, behaviours, world) {
        Ok((o, _)) if o.reached => Feedback::met(format!(
            "The {body} with {behaviours} reached the goal in {:.1} s: the failure belonged to the body (embodiment).",
            o.time.unwrap_or_default()
        )),
        Ok((o, _)) => Feedback::not_yet(format!("Still no: {}.", o.why)),
        Err(e) => Feedback::not_yet(e.to_string()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tasks_grade_right_and_wrong() {
        assert!(nearly_straight(1, 300.0).message.contains("over 100"));
        assert!(!nearly_straight(1, 1.0).met);
        let sizes: Vec<f64> = (1..=100).map(f64::from).collect();
        let first = sizes.iter().find(|s| nearly_straight(1, **s).met).copied();
        assert!(first.is_some_and(|s| s > 1.0), "{first:?}");
        assert!(fix_the_car("omni", "go-and-avoid", "maze").met);
        assert!(!fix_the_car("car", "wander-when-stuck", "maze").met);
        assert!(
            fix_the_car("omni", "wander-when-stuck", "maze")
                .message
                .contains("exactly one")
        );
        assert!(
            fix_the_car("omni", "go-and-avoid", "open")
                .message
                .contains("Keep the world")
        );
    }
}
