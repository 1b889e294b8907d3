//! The graded exercises of the Mechanisms unit, checked by the core.

use kinolab_mechanism::catalogue::mechanism;
use kinolab_mechanism::dh::Convention;
use kinolab_mechanism::exercise::{SINGULAR, Task, conditioning};
use kinolab_mechanism::{FieldError, Vector3};

#[test]
fn reach_is_met_within_the_tolerance_only() -> Result<(), FieldError> {
    let arm = mechanism("planar-2r")?;
    let task = Task::Reach {
        frame: "tool".into(),
        target: Vector3::new(1.2, 0.6, 0.0),
        tolerance: 0.01,
    };
    // One of the two exact answers (elbow down): q2 = −acos(c2).
    let c2 = (1.2f64 * 1.2 + 0.6 * 0.6 - 1.0 - 0.64) / 1.6;
    let q2 = -c2.acos();
    let q1 = 0.6f64.atan2(1.2) - (0.8 * q2.sin()).atan2(1.0 + 0.8 * q2.cos());
    assert!(task.check_state(&arm, &[q1, q2])?.met);
    let off = task.check_state(&arm, &[q1 + 0.05, q2])?;
    assert!(
        !off.met && off.message.starts_with("Not yet"),
        "{}",
        off.message
    );
    Ok(())
}

#[test]
fn singular_configurations_of_the_two_link_arm() -> Result<(), FieldError> {
    let arm = mechanism("planar-2r")?;
    let tool = arm.frame("tool")?;
    let deg = |a: f64, b: f64| [a.to_radians(), b.to_radians()];
    // Stretched (q2 = 0) and folded as far as the limits allow.
    assert!(conditioning(&arm, &deg(30.0, 0.0), &tool)? < SINGULAR);
    assert!(conditioning(&arm, &deg(40.0, 90.0), &tool)? > 0.1);
    // The lesson's sets: the first and third are singular.
    let sets: Vec<Vec<f64>> = [
        (30.0, 0.0),
        (40.0, 90.0),
        (150.0, 0.0),
        (90.0, -45.0),
        (-60.0, 120.0),
    ]
    .iter()
    .map(|&(a, b)| deg(a, b).to_vec())
    .collect();
    let task = Task::SpotSingular {
        frame: "tool".into(),
        sets,
    };
    assert!(
        task.check_marks(&arm, &[true, false, true, false, false])?
            .met
    );
    let wrong = task.check_marks(&arm, &[true, true, false, false, false])?;
    assert!(!wrong.met);
    assert!(
        wrong.message.contains("2 is not") && wrong.message.contains("3 is singular"),
        "{}",
        wrong.message
    );
    // The Puma's wrist: singular whenever q5 = 0.
    let puma = mechanism("puma560")?;
    let ptool = puma.frame("tool")?;
    assert!(conditioning(&puma, &[0.3, -0.5, 0.8, 0.2, 0.0, -0.4], &ptool)? < SINGULAR);
    assert!(conditioning(&puma, &[0.3, -0.5, 0.8, 0.2, 0.6, -0.4], &ptool)? > 1e-3);
    Ok(())
}

#[test]
fn a_dh_row_counts_when_its_frame_matches() -> Result<(), FieldError> {
    let r = f64::to_radians;
    let task = Task::DhRow {
        convention: Convention::StandardDh,
        target: [0.3, r(-90.0), 0.4, r(45.0)],
    };
    assert!(task.check_row([0.3, r(-90.0), 0.4, r(45.0)])?.met);
    // θ = 45° + 360° is the same frame.
    assert!(task.check_row([0.3, r(-90.0), 0.4, r(405.0)])?.met);
    let twisted = task.check_row([0.3, r(90.0), 0.4, r(45.0)])?;
    assert!(
        !twisted.met && twisted.message.contains("axes are turned 180°"),
        "{}",
        twisted.message
    );
    let short = task.check_row([0.2, r(-90.0), 0.4, r(45.0)])?;
    assert!(
        !short.met && short.message.contains("origin is 100 mm off"),
        "{}",
        short.message
    );
    Ok(())
}
