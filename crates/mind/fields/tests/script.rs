#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! A learner's primitive joins the field's sum: the same vectors as the
//! built-in it imitates, equilibria found through it, descents run
//! through it, and an error reported in the learner's words.

use kinolab_fields::Field;
use kinolab_fields::descend::{Outcome, Steps};
use kinolab_fields::report::{descent, minima_in, vectors};

fn file(fields: &str) -> String {
    format!(r#"{{ "name": "mine", "fields": [{fields}] }}"#)
}

fn script(source: &str) -> String {
    serde_json::json!({ "kind": "script", "source": source }).to_string()
}

/// An attractive field of gain 1 with a constant profile, towards (4, 0).
const PULL: &str = "fn field(x, y) { let dx = 4.0 - x; let dy = 0.0 - y; let d = sqrt(dx * dx + dy * dy); if d < 1e-12 { return [0.0, 0.0]; } [dx / d * 1.0, dy / d * 1.0] }";

#[test]
fn a_script_primitive_gives_the_built_in_vectors() {
    let built_in = Field::from_json(&file(
        r#"{ "kind": "attractive", "x": 4, "y": 0, "gain": 1, "profile": "constant" }"#,
    ))
    .unwrap();
    let learner = Field::from_json(&file(&script(PULL))).unwrap();
    let points = [[0.0, 0.0], [1.0, 2.5], [-3.0, -1.0], [3.9, 0.2]];
    let (a, b) = (
        vectors(&built_in, &points).unwrap(),
        vectors(&learner, &points).unwrap(),
    );
    for (u, v) in a.vectors.iter().zip(&b.vectors) {
        assert!(
            (u[0] - v[0]).abs() < 1e-12 && (u[1] - v[1]).abs() < 1e-12,
            "{u:?} {v:?}"
        );
    }
}

#[test]
fn equilibria_and_descents_run_through_a_script() {
    // A spring to (2, 1) plus the built-in push of a uniform field east.
    let spring = script("fn field(x, y) { [2.0 - x, 1.0 - y] }");
    let f = Field::from_json(&file(&format!(
        r#"{spring}, {{ "kind": "uniform", "direction_deg": 0, "gain": 0.5 }}"#
    )))
    .unwrap();
    let m = minima_in(&f, [-1.0, -2.0, 6.0, 4.0]).unwrap();
    assert_eq!(m.minima.len(), 1);
    // 2 − x + 0.5 = 0 and 1 − y = 0.
    assert!(
        (m.minima[0].x - 2.5).abs() < 1e-6 && (m.minima[0].y - 1.0).abs() < 1e-6,
        "{m:?}"
    );
    let d = descent(
        &f,
        [0.0, -1.0],
        Steps {
            step: 0.01,
            max_steps: 2000,
        },
    )
    .unwrap();
    assert_eq!(d.outcome, Outcome::Trapped);
    assert!(
        (d.end[0] - 2.5).abs() < 0.02 && (d.end[1] - 1.0).abs() < 0.02,
        "{:?}",
        d.end
    );
    // The file writes the script back and reads it the same.
    let again = Field::from_json(&f.to_json()).unwrap();
    assert_eq!(again, f);
}

#[test]
fn a_failing_script_is_reported_with_the_point() {
    let f = Field::from_json(&file(&script("fn field(x, y) { [1.0 / x, 0.0] }"))).unwrap();
    let e = vectors(&f, &[[1.0, 0.0], [0.0, 0.5]]).unwrap_err();
    assert!(
        e.message.contains("returned inf for fx at (0.00, 0.50)"),
        "{e}"
    );
    let e = Field::from_json(&file(&script("fn field(x) { [x, 0.0] }"))).unwrap_err();
    assert_eq!(e.field, "fields[0].source");
}
