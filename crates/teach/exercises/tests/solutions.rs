#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! Every exercise has a model solution that passes every world, held-back
//! ones included, and two wrong solutions that fail for the reason a
//! teacher would give.

use kinolab_exercises::{Check, find};

fn solution(name: &str) -> String {
    let path = format!("{}/tests/solutions/{name}.rhai", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn check(id: &str, file: &str) -> Check {
    find(id).unwrap().check(&solution(file), true)
}

fn summary(c: &Check) -> String {
    let worlds: Vec<String> = c
        .worlds
        .iter()
        .map(|w| format!("{}: {:?} {:?}", w.name, w.reason, w.metrics))
        .collect();
    format!("{:?}\n{}", c.error, worlds.join("\n"))
}

/// The model passes everywhere.
fn passes(id: &str) {
    let c = check(id, id);
    assert!(c.passed, "{id}: {}", summary(&c));
    assert!(c.error.is_none());
    assert!(
        c.worlds.iter().any(|w| !w.visible),
        "{id} holds worlds back"
    );
    assert!(c.worlds.iter().any(|w| w.visible), "{id} shows some worlds");
}

/// `wrong` fails, and the first failing world's reason says `why`.
fn fails(id: &str, wrong: &str, why: &str) {
    let c = check(id, &format!("{id}.{wrong}"));
    assert!(!c.passed, "{id}.{wrong} should fail: {}", summary(&c));
    let reason = c
        .worlds
        .iter()
        .find_map(|w| w.reason.clone())
        .or_else(|| c.error.as_ref().map(|e| e.message.clone()))
        .unwrap();
    assert!(
        reason.contains(why),
        "{id}.{wrong}: `{reason}` lacks `{why}`\n{}",
        summary(&c)
    );
}

#[test]
fn park_at_the_goal() {
    passes("control-park");
    fails("control-park", "no-beta", "arrived facing");
    fails("control-park", "wrong-sign", "the loop is unstable");
}

#[test]
fn a_slow_loop() {
    passes("control-slow-loop");
    fails("control-slow-loop", "fast-gains", "arrived facing");
    fails(
        "control-slow-loop",
        "infinite",
        "is there a loop that never ends",
    );
}

#[test]
fn explore() {
    passes("behaviour-explore");
    fails("behaviour-explore", "straight", "touched an obstacle at");
    fails("behaviour-explore", "timid", "drove only");
}

#[test]
fn coordinate() {
    passes("behaviour-coordinate");
    fails("behaviour-coordinate", "go-only", "touched an obstacle at");
    fails("behaviour-coordinate", "bad-name", "(\"go\", \"avoid\")");
}

#[test]
fn pull() {
    passes("field-pull");
    fails("field-pull", "push", "not at the goal");
    fails("field-pull", "x-only", "stuck at (4.00");
}

#[test]
fn escape() {
    passes("field-escape");
    fails("field-escape", "nothing", "stuck at");
    fails("field-escape", "forward", "stuck at");
}

#[test]
fn walk() {
    passes("legs-walk");
    fails("legs-walk", "same-side", "fell at phase");
    fails("legs-walk", "shuffle", "never left the ground");
}

#[test]
fn careful() {
    passes("legs-careful");
    fails("legs-careful", "tripod", "the margin fell to");
    fails("legs-careful", "slow", "moved 1.");
}

#[test]
fn replan() {
    passes("sequencer-replan");
    fails("sequencer-replan", "once", "");
    fails("sequencer-replan", "shape", "must return #{ replan");
}

#[test]
fn every_world_of_every_exercise_is_built() {
    let counts: Vec<(&str, usize)> = kinolab_exercises::all()
        .iter()
        .map(|e| (e.id, (e.worlds)().len()))
        .collect();
    let expected = [
        ("control-park", 5),
        ("control-slow-loop", 3),
        ("behaviour-explore", 5),
        ("behaviour-coordinate", 5),
        ("field-pull", 5),
        ("field-escape", 5),
        ("legs-walk", 4),
        ("legs-careful", 3),
        ("sequencer-replan", 6),
    ];
    assert_eq!(counts, expected);
}

#[test]
fn the_same_script_grades_the_same_and_run_shows_only_the_visible_worlds() {
    for e in kinolab_exercises::all() {
        let model = solution(e.id);
        let all = e.check(&model, true);
        assert_eq!(all, e.check(&model, true), "{}", e.id);
        let visible = e.check(&model, false);
        let shown: Vec<&str> = visible.worlds.iter().map(|w| w.name.as_str()).collect();
        let expected: Vec<&str> = all
            .worlds
            .iter()
            .filter(|w| w.visible)
            .map(|w| w.name.as_str())
            .collect();
        assert_eq!(shown, expected, "{}", e.id);
        assert!(visible.worlds.len() < all.worlds.len(), "{}", e.id);
    }
}

#[test]
fn the_starter_compiles_and_does_not_pass() {
    for e in kinolab_exercises::all() {
        let c = e.check(e.starter, true);
        assert!(c.error.is_none(), "{}: {:?}", e.id, c.error);
        assert!(!c.passed, "{}: the starter alone passes", e.id);
    }
}

#[test]
fn a_syntax_error_runs_nothing_and_names_its_line() {
    let e = find("control-park").unwrap();
    let c = e.check("fn control(rho, alpha, beta) {\n    [rho, alpha\n}\n", true);
    assert!(!c.passed);
    assert!(c.worlds.is_empty());
    let error = c.error.unwrap();
    assert_eq!(error.line, Some(3), "{error:?}");
}
