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

/// Every exercise's model (which passes), the solutions a learner might
/// plausibly get wrong, and the degenerate solutions of its hook (a
/// constant command, one that reads nothing, a huge or tiny field, a plan
/// every tick, feet that never really step), each failing for the reason a
/// teacher would give. A file `ID.NAME.rhai` is checked against `ID`.
const CASES: &[(&str, &[(&str, &str)])] = &[
    (
        "control-park",
        &[
            (
                "textbook",
                "asked for 3.35 m/s at t = 0.00 s; the limit is 0.5 m/s",
            ),
            ("no-beta", "arrived facing"),
            ("wrong-sign", "not at the goal"),
            ("constant", "not at the goal"),
        ],
    ),
    (
        "control-slow-loop",
        &[
            ("fast-gains", "arrived facing 14° off"),
            ("timid", "not at the goal after 15 s"),
            ("infinite", "is there a loop that never ends"),
        ],
    ),
    (
        "arm-hold",
        &[
            (
                "pd",
                "joint 1 was 18.8° below its target in the last second",
            ),
            ("wrong-sign", "below its target"),
            (
                "stiff",
                "asked joint 1 for 3490.7 N·m at t = 0.00 s; the motors give at most 100 N·m",
            ),
            ("constant", "below its target"),
            ("no-payload", "joint 2 was 7.9° below its target"),
        ],
    ),
    (
        "behaviour-explore",
        &[
            ("straight", "touched an obstacle at"),
            ("timid", "stood still from 0.0 s"),
            ("circling", "covered only"),
            ("wide-circle", ""),
            ("shuttle", "covered only"),
            ("stops", "stood still from 21.8 s"),
        ],
    ),
    (
        "behaviour-coordinate",
        &[
            ("seek-only", "touched an obstacle at"),
            ("bad-name", "(\"seek\", \"avoid\")"),
            ("avoid-only", "not at the goal"),
            ("constant", ""),
        ],
    ),
    (
        "field-pull",
        &[
            ("push", "not at the goal"),
            ("x-only", "stuck at (4.00"),
            ("huge", "ran into an obstacle"),
            ("tiny", "stuck at"),
            ("constant", ""),
        ],
    ),
    (
        "field-escape",
        &[
            ("nothing", "stuck at"),
            ("forward", ""),
            ("stronger", "ran into an obstacle"),
        ],
    ),
    (
        "legs-walk",
        &[
            ("same-side", "fell at phase"),
            ("shuffle", "never left the ground"),
            ("blink", "was in the air for only"),
            ("scuff", "swung without lifting"),
        ],
    ),
    (
        "legs-careful",
        &[
            ("tripod", "3 feet were in the air"),
            ("short-tripod", "3 feet were in the air"),
            ("slow", "the body moved 1.2 cm a cycle"),
        ],
    ),
    (
        "sequencer-replan",
        &[
            ("once", "not at the goal"),
            ("shape", "must return #{ replan"),
            ("every-tick", "planned"),
            ("timer", "planned"),
        ],
    ),
];

fn check_all(id: &str) {
    passes(id);
    let (_, wrongs) = CASES.iter().find(|(i, _)| *i == id).unwrap();
    for (wrong, why) in *wrongs {
        fails(id, wrong, why);
    }
}

#[test]
fn park_under_a_speed_limit() {
    check_all("control-park");
}

#[test]
fn a_slow_loop() {
    check_all("control-slow-loop");
}

#[test]
fn hold_an_arm() {
    check_all("arm-hold");
}

#[test]
fn explore() {
    check_all("behaviour-explore");
}

#[test]
fn coordinate() {
    check_all("behaviour-coordinate");
}

#[test]
fn pull() {
    check_all("field-pull");
}

#[test]
fn escape() {
    check_all("field-escape");
}

#[test]
fn walk() {
    check_all("legs-walk");
}

#[test]
fn careful() {
    check_all("legs-careful");
}

#[test]
fn replan() {
    check_all("sequencer-replan");
    // The hints' own way, comparing the goals with `!=`, is a model too.
    let c = check("sequencer-replan", "sequencer-replan.unequal");
    assert!(c.passed, "{}", summary(&c));
}

#[test]
fn every_solution_file_is_checked() {
    let dir = format!("{}/tests/solutions", env!("CARGO_MANIFEST_DIR"));
    for entry in std::fs::read_dir(&dir).unwrap() {
        let name = entry.unwrap().file_name().into_string().unwrap();
        let stem = name.trim_end_matches(".rhai");
        let known = CASES.iter().any(|(id, wrongs)| {
            stem == *id || wrongs.iter().any(|(w, _)| stem == format!("{id}.{w}"))
        });
        assert!(
            known || stem == "sequencer-replan.unequal",
            "{name} is not checked"
        );
    }
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
        ("arm-hold", 5),
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
