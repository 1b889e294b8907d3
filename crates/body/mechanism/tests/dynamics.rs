#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! Mass, statics and dynamics: a pendulum in closed form, the identities
//! that tie the algorithms together (M symmetric positive definite, RNEA
//! at rest is gravity, RNEA − bias is M q̈, forward undoes inverse, gravity
//! torques are the potential's slope), an undamped arm's energy kept by
//! the integrator, and real robots' files against Pinocchio
//! (`tests/urdf/dynamics_goldens.py` made the goldens).

use kinolab_mechanism::dynamics::EARTH;
use kinolab_mechanism::dynamics::motion::Release;
use kinolab_mechanism::dynamics::statics::Load;
use kinolab_mechanism::{Inertial, JointKind, Model, ModelBuilder, Pose, catalogue, urdf};
use nalgebra::{DVector, Unit, Vector3};
use proptest::prelude::*;

/// One link of length `l` turning about y, its mass `m` at its far end
/// spread as a thin rod's (a centroidal moment `ic` about y and z).
fn pendulum(m: f64, l: f64, ic: f64) -> Model {
    let mut b = ModelBuilder::new("pendulum");
    let link = b.joint(
        "swing",
        JointKind::Revolute,
        0,
        Pose::identity(),
        Unit::new_normalize(Vector3::y()),
        0.0,
        Pose::identity(),
        None,
    );
    b.set_inertial(
        link,
        Inertial::new("swing", m, [l, 0.0, 0.0], [1e-6, 0.0, 0.0, ic, 0.0, ic]).unwrap(),
    );
    b.build().unwrap()
}

#[test]
fn a_pendulum_in_closed_form() {
    let (m, l, ic) = (2.0, 0.5, 0.04);
    let p = pendulum(m, l, ic);
    for q in [-1.2, -0.3, 0.0, 0.7, 2.5] {
        // The mass sits at (l cos q, 0, −l sin q): holding it takes
        // −m g l cos q about y (g = 9.81 down).
        let g = p.gravity(&[q], EARTH).unwrap()[0];
        assert!((g - (-m * 9.81 * l * q.cos())).abs() < 1e-12, "{q}: {g}");
        let mm = p.mass_matrix(&[q]).unwrap()[(0, 0)];
        assert!((mm - (ic + m * l * l)).abs() < 1e-12);
        // A pendulum's own swing: q'' = (τ − g) / M.
        let qdd = p.forward_dynamics(&[q], &[0.3], &[1.0], EARTH).unwrap()[0];
        assert!((qdd - (1.0 - g) / mm).abs() < 1e-12);
    }
    let (mass, com) = p.mass_and_centre(&[0.0]).unwrap();
    assert_eq!(mass, m);
    assert!((com[0] - l).abs() < 1e-12);
}

/// A state of `model` inside its limits, and rates, from seeds in [0, 1).
fn state(model: &Model, u: &[f64]) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let n = model.dof();
    let q = (0..n)
        .map(|i| {
            let [lo, hi] = model
                .variable_joint(i)
                .unwrap()
                .limits
                .unwrap_or([-3.0, 3.0]);
            lo + (hi - lo) * u[i % u.len()]
        })
        .collect();
    let qd = (0..n).map(|i| 2.0 * u[(i + 3) % u.len()] - 1.0).collect();
    let qdd = (0..n).map(|i| 2.0 * u[(i + 5) % u.len()] - 1.0).collect();
    (q, qd, qdd)
}

fn close(a: &[f64], b: &[f64], tol: f64) -> bool {
    let scale = b.iter().fold(1.0_f64, |m, x| m.max(x.abs()));
    a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol * scale)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn the_algorithms_agree_with_each_other(
        u in prop::collection::vec(0.0..1.0_f64, 8),
        arm in 0..2_usize,
    ) {
        let model = [catalogue::mechanism("puma560"), catalogue::mechanism("panda")][arm].clone().unwrap();
        let (q, qd, qdd) = state(&model, &u);
        let n = model.dof();
        let m = model.mass_matrix(&q).unwrap();
        prop_assert!((&m - m.transpose()).abs().max() < 1e-12);
        prop_assert!(m.clone().cholesky().is_some(), "M is positive definite");
        // At rest, the recursion is gravity alone.
        let g = model.gravity(&q, EARTH).unwrap();
        let rest = model.inverse_dynamics(&q, &vec![0.0; n], &vec![0.0; n], EARTH).unwrap();
        prop_assert!(close(&rest, &g, 1e-12));
        // τ − bias = M q̈.
        let tau = model.inverse_dynamics(&q, &qd, &qdd, EARTH).unwrap();
        let bias = model.inverse_dynamics(&q, &qd, &vec![0.0; n], EARTH).unwrap();
        let mqdd = &m * DVector::from_vec(qdd.clone());
        let diff: Vec<f64> = tau.iter().zip(&bias).map(|(a, b)| a - b).collect();
        prop_assert!(close(&diff, mqdd.as_slice(), 1e-10), "{diff:?} vs {mqdd}");
        // Forward undoes inverse.
        let back = model.forward_dynamics(&q, &qd, &tau, EARTH).unwrap();
        prop_assert!(close(&back, &qdd, 1e-8), "{back:?} vs {qdd:?}");
        // Gravity torques are the slope of the potential energy.
        let mut work = model.dynamics();
        for k in 0..n {
            let h = 1e-6;
            let (mut up, mut down) = (q.clone(), q.clone());
            up[k] += h;
            down[k] -= h;
            let slope = (model.energy(&mut work, &up, &vec![0.0; n], EARTH)
                - model.energy(&mut work, &down, &vec![0.0; n], EARTH)) / (2.0 * h);
            prop_assert!((slope - g[k]).abs() < 1e-6 * (1.0 + g[k].abs()), "joint {k}: {slope} vs {}", g[k]);
        }
    }
}

/// Two rods of 1 kg and 0.5 m hanging from each other, turning about y.
fn double_pendulum() -> Model {
    let mut b = ModelBuilder::new("double pendulum");
    let y = Unit::new_normalize(Vector3::y());
    let rod = |name: &str| {
        Inertial::new(
            name,
            1.0,
            [0.25, 0.0, 0.0],
            [1e-5, 0.0, 0.0, 0.0208, 0.0, 0.0208],
        )
        .unwrap()
    };
    let upper = b.joint(
        "upper",
        JointKind::Revolute,
        0,
        Pose::identity(),
        y,
        0.0,
        Pose::identity(),
        None,
    );
    b.set_inertial(upper, rod("upper"));
    let lower = b.joint(
        "lower",
        JointKind::Revolute,
        upper,
        Pose::translation(0.5, 0.0, 0.0),
        y,
        0.0,
        Pose::identity(),
        None,
    );
    b.set_inertial(lower, rod("lower"));
    b.build().unwrap()
}

#[test]
fn an_undamped_arm_keeps_its_energy_and_a_smaller_step_keeps_it_better() {
    let model = double_pendulum();
    let q = vec![0.3, -0.8];
    let drift = |dt: f64| {
        let release = Release {
            dt,
            steps: (1.0 / dt) as usize,
            damping: 0.0,
            gravity: EARTH,
        };
        let mut fall = model.release(&q, &[0.0; 2], release).unwrap();
        let mut worst: f64 = 0.0;
        while fall.step(&model).unwrap() {
            worst = worst.max(fall.drift());
        }
        (worst, fall.now.q.clone())
    };
    let (coarse, q1) = drift(2e-3);
    let (fine, _) = drift(1e-3);
    // Runge–Kutta: the error falls with the fourth power of the step.
    assert!(coarse < 1e-5, "{coarse}");
    assert!(fine < coarse / 8.0, "{fine} vs {coarse}");
    assert!((q1[1] - q[1]).abs() > 0.05, "the arm fell: {q1:?}");
    // With damping it loses energy.
    let release = Release {
        dt: 1e-3,
        steps: 1000,
        damping: 0.5,
        gravity: EARTH,
    };
    let mut fall = model.release(&q, &[0.0; 2], release).unwrap();
    while fall.step(&model).unwrap() {}
    assert!(fall.now.energy < fall.start_energy - 1.0);
}

#[test]
fn loads_and_springs_by_virtual_work() {
    // A straight arm held out along x, turning about y at its base: 1 kg
    // at 0.5 m, a 2 kg payload at the 1 m tool.
    let mut b = ModelBuilder::new("held out");
    let link = b.joint(
        "shoulder",
        JointKind::Revolute,
        0,
        Pose::identity(),
        Unit::new_normalize(Vector3::y()),
        0.0,
        Pose::identity(),
        None,
    );
    b.set_inertial(
        link,
        Inertial::new("shoulder", 1.0, [0.5, 0.0, 0.0], [0.0; 6]).unwrap(),
    );
    b.frame("tool", link, Pose::translation(1.0, 0.0, 0.0));
    let model = b.build().unwrap();
    let tool = model.frame("tool").unwrap();
    let weight = Load {
        frame: tool,
        force: [0.0, 0.0, -2.0 * 9.81],
        moment: [0.0; 3],
    };
    let held = model.hold(&[0.0], &[weight], EARTH).unwrap();
    // Turning about +y tips the arm down: holding it up takes a negative torque.
    assert!((held.gravity[0] + 0.5 * 9.81).abs() < 1e-12, "{held:?}");
    assert!((held.load[0] + 2.0 * 9.81).abs() < 1e-12, "{held:?}");
    // A spring of 1000 N·m/rad gives 0.02453 rad, and the tool sags.
    let sag = model.sag(&[0.0], &held.total, &[1000.0], &tool).unwrap();
    let give = held.total[0] / 1000.0;
    assert!((sag.deflection[0] - give).abs() < 1e-15);
    assert!(sag.sag[2] < -0.024 && sag.sag[2] > -0.025, "{sag:?}");
    assert!(sag.sag[0] < 0.0, "the tool swings in a little as it drops");
}

#[test]
fn real_robots_match_pinocchio() {
    for name in ["panda", "ur5", "solo12"] {
        let dir = env!("CARGO_MANIFEST_DIR");
        let text = std::fs::read_to_string(format!("{dir}/robots/{name}.urdf")).unwrap();
        let golden: serde_json::Value = serde_json::from_str(
            &std::fs::read_to_string(format!("{dir}/tests/urdf/{name}.dynamics.json")).unwrap(),
        )
        .unwrap();
        let robot = urdf::read(&text).unwrap();
        let order: Vec<&str> = robot.driven().collect();
        let want: Vec<&str> = golden["order"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_str().unwrap())
            .collect();
        assert_eq!(order, want, "{name}");
        let model = &robot.model;
        let mut work = model.dynamics();
        let numbers = |v: &serde_json::Value| -> Vec<f64> {
            v.as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect()
        };
        for s in golden["states"].as_array().unwrap() {
            let q = robot.state(&numbers(&s["q"])).unwrap();
            let qd = robot.rates("qd", &numbers(&s["qd"])).unwrap();
            let qdd = robot.rates("qdd", &numbers(&s["qdd"])).unwrap();
            let tau = robot.values(
                model
                    .inverse_dynamics_in(&mut work, &q, &qd, &qdd, EARTH)
                    .unwrap(),
            );
            assert!(
                close(&tau, &numbers(&s["tau"]), 1e-8),
                "{name} tau {tau:?}\n vs {}",
                s["tau"]
            );
            let g = robot.values(model.gravity_in(&mut work, &q, EARTH).unwrap());
            assert!(close(&g, &numbers(&s["gravity"]), 1e-8), "{name} g");
            let m = model.mass_matrix_in(&mut work, &q).unwrap().clone();
            let rows = s["mass_matrix"].as_array().unwrap();
            for (r, row) in rows.iter().enumerate() {
                let got: Vec<f64> = robot.values(
                    &(0..model.dof())
                        .map(|c| m[(robot_var(&robot, r), c)])
                        .collect::<Vec<_>>(),
                );
                assert!(
                    close(&got, &numbers(row), 1e-8),
                    "{name} M row {r}: {got:?} vs {row}"
                );
            }
            let tau = robot.rates("tau", &numbers(&s["forward_tau"])).unwrap();
            let qdd = robot.values(
                model
                    .forward_dynamics_in(&mut work, &q, &qd, &tau, EARTH)
                    .unwrap(),
            );
            assert!(
                close(&qdd, &numbers(&s["forward_qdd"]), 1e-8),
                "{name} forward {qdd:?} vs {}",
                s["forward_qdd"]
            );
        }
    }
}

/// The model variable of driven joint `r`.
fn robot_var(robot: &urdf::Robot, r: usize) -> usize {
    let name = robot.driven().nth(r).unwrap();
    robot.model.variable(name).unwrap()
}

#[test]
fn masses_survive_urdf_and_model_files_both_ways() {
    let puma = catalogue::mechanism("puma560").unwrap();
    let q = [0.2, -0.5, 0.9, 0.1, -0.3, 0.4];
    let from_urdf = urdf::read(&urdf::write(&puma).text).unwrap().model;
    let from_file =
        kinolab_mechanism::file::from_json(&kinolab_mechanism::file::to_json(&puma)).unwrap();
    for other in [&from_urdf, &from_file] {
        let (a, b) = (
            puma.gravity(&q, EARTH).unwrap(),
            other.gravity(&q, EARTH).unwrap(),
        );
        assert!(close(&b, &a, 1e-12), "{a:?} vs {b:?}");
        let diff = (puma.mass_matrix(&q).unwrap() - other.mass_matrix(&q).unwrap())
            .abs()
            .max();
        assert!(diff < 1e-12, "{diff}");
    }
    assert!((puma.mass_and_centre(&q).unwrap().0 - 23.45).abs() < 1e-9);
}

#[test]
fn a_model_files_masses_are_checked_and_name_their_body() {
    let file = |inertial: &str| {
        format!(
            r#"{{ "name": "one", "convention": "transforms", "joints": [
                {{ "name": "j", "type": "revolute", "axis": [0, 0, 1], "inertial": {inertial} }} ] }}"#
        )
    };
    let ok = kinolab_mechanism::file::from_json(&file(
        r#"{ "mass": 1.0, "com": [0.1, 0, 0], "inertia": [0.01, 0, 0, 0.01, 0, 0.01] }"#,
    ));
    assert_eq!(ok.unwrap().mass_and_centre(&[0.0]).unwrap().0, 1.0);
    for (bad, words) in [
        (r#"{ "mass": -1.0 }"#, "body `j`): mass"),
        (
            r#"{ "mass": 1.0, "inertia": [0.01, 0, 0, 0.01, 0, 0.05] }"#,
            "triangle inequality",
        ),
        (
            r#"{ "mass": 1.0, "inertia": [0.01, 0.02, 0, 0.01, 0, 0.01] }"#,
            "positive semi-definite",
        ),
    ] {
        let e = kinolab_mechanism::file::from_json(&file(bad))
            .unwrap_err()
            .to_string();
        assert!(e.contains("joints[0].inertial") && e.contains(words), "{e}");
    }
}

#[test]
fn real_files_read_as_ros_and_pinocchio_read_them() {
    let robot = |body: &str| {
        format!(
            "\n\n<?xml version=\"1.0\"?>\n<robot name=\"r\">\n<link name=\"base\"/><link name=\"a\">\n<inertial><mass value=\"1\"/><inertia ixx=\"0\" iyy=\"0\" izz=\"0.003\"/></inertial></link><link name=\"b\"/>\n{body}\n</robot>"
        )
    };
    let text = robot(
        "<joint name=\"j1\" type=\"revolute\"><parent link=\"base\"/><child link=\"a\"/><axis xyz=\"0 0 1\"/><limit lower=\"0\" upper=\"0\"/></joint>\n\
         <joint name=\"j2\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/><mimic joint=\"j1\"/></joint>",
    );
    let r = urdf::read(&text).unwrap();
    let notices = r.notices.join("\n");
    assert!(
        notices.contains("`j1`: equal lower and upper limits"),
        "{notices}"
    );
    assert!(
        notices.contains("`j2` mimics `j1`, but it does not move"),
        "{notices}"
    );
    assert!(
        notices.contains("link `a`: the inertia breaks the triangle inequality"),
        "{notices}"
    );
    assert_eq!(r.model.variable_joint(0).unwrap().limits, None);
    // A huge but finite limit is read as written.
    let huge = robot(
        "<joint name=\"j1\" type=\"prismatic\"><parent link=\"base\"/><child link=\"a\"/><limit lower=\"-1e+16\" upper=\"1e+16\"/></joint><joint name=\"j2\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint>",
    );
    assert_eq!(
        urdf::read(&huge)
            .unwrap()
            .model
            .variable_joint(0)
            .unwrap()
            .limits,
        Some([-1e16, 1e16])
    );
    // Line numbers still count from the file's first line.
    let broken = robot("<joint name=\"j1\" type=\"spinning\"/>");
    assert!(
        urdf::read(&broken)
            .unwrap_err()
            .to_string()
            .contains("(line 7)")
    );
}
