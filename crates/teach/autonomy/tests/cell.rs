#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
use kinolab_autonomy::PickCell;

#[test]
fn a_closed_world_never_fails_the_scripted_robot() {
    let cell = PickCell::new(0.0, 0.01, 0.002).unwrap();
    assert_eq!(cell.scripted_success(), 1.0);
    assert!(cell.run(500, 1).iter().all(|t| t.scripted_grasped));
}

#[test]
fn closed_forms_for_uniform_discs() {
    let cell = PickCell::new(0.02, 0.01, 0.005).unwrap();
    assert!((cell.scripted_success() - 0.25).abs() < 1e-15);
    assert_eq!(cell.sensing_success(), 1.0);
    let noisy = PickCell::new(0.02, 0.01, 0.04).unwrap();
    assert!((noisy.sensing_success() - 0.0625).abs() < 1e-15);
}

#[test]
fn simulated_rates_converge_to_the_closed_forms() {
    let cell = PickCell::new(0.03, 0.01, 0.015).unwrap();
    let n = 40_000;
    let trials = cell.run(n, 42);
    let rate = |f: fn(&kinolab_autonomy::PickTrial) -> bool| {
        trials.iter().filter(|t| f(t)).count() as f64 / n as f64
    };
    for (simulated, exact) in [
        (rate(|t| t.scripted_grasped), cell.scripted_success()),
        (rate(|t| t.sensing_grasped), cell.sensing_success()),
    ] {
        let sigma = (exact * (1.0 - exact) / n as f64).sqrt();
        assert!(
            (simulated - exact).abs() < 4.0 * sigma,
            "{simulated} vs {exact}"
        );
    }
    for t in &trials {
        assert!(t.part[0].hypot(t.part[1]) <= 0.03 + 1e-15);
    }
}

#[test]
fn the_same_seed_gives_the_same_parts() {
    let cell = PickCell::new(0.05, 0.01, 0.002).unwrap();
    assert_eq!(cell.run(50, 7), cell.run(50, 7));
    assert_ne!(cell.run(50, 7), cell.run(50, 8));
}

#[test]
fn bad_parameters_name_the_field() {
    assert_eq!(
        PickCell::new(-1.0, 0.01, 0.0).unwrap_err().field,
        "placement_error"
    );
    assert_eq!(
        PickCell::new(0.0, f64::NAN, 0.0).unwrap_err().field,
        "gripper_tolerance"
    );
    assert_eq!(
        PickCell::new(0.0, 0.0, f64::INFINITY)
            .unwrap_err()
            .to_string(),
        "sensor_error: must be a finite number, got inf"
    );
}
