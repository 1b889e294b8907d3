//! Mechanisms built from parts: mounting, coupling, closed loops, relative
//! goals, specialised solvers and collision queries.

mod support;

use std::f64::consts::PI;

use kinolab_mechanism::catalogue::mechanism;
use kinolab_mechanism::{
    FieldError, FrameRef, Goal, Model, Obstacle, Options, Part, Plane, Pose, Target, Vector3,
};
use proptest::prelude::*;

fn frame(m: &Model, name: &str) -> FrameRef {
    m.frame(name).unwrap_or_else(|e| panic!("{e}"))
}

fn position(m: &Model, q: &[f64], name: &str) -> Vector3<f64> {
    m.pose(q, &frame(m, name))
        .unwrap_or_else(|e| panic!("{e}"))
        .translation
        .vector
}

#[test]
fn the_rocker_bogie_differential_holds_through_inverse_kinematics() -> Result<(), FieldError> {
    let rover = mechanism("rocker-bogie")?;
    assert_eq!(rover.dof(), 4);
    let left = rover.variable("left-rocker").unwrap_or(usize::MAX);
    let right = rover.variable("right-rocker").unwrap_or(usize::MAX);
    assert!(rover.is_follower(right) && !rover.is_follower(left));
    // Lift the left front wheel onto a rock: IK must turn the left rocker,
    // and the right rocker must turn the other way by the same angle.
    let q0 = rover.zero_state();
    let wheel = frame(&rover, "left-front-wheel");
    let start = position(&rover, &q0, "left-front-wheel");
    // Where the wheel is with the left rocker at 0.15 rad: a point the
    // solver must reach by turning that rocker alone.
    let mut probe = q0.clone();
    probe[left] = -0.15;
    rover.apply_couplings(&mut probe);
    let lifted = position(&rover, &probe, "left-front-wheel");
    let s = rover.solve(
        &[Goal::new(wheel, Target::Position(lifted))],
        &q0,
        &Options::default(),
    )?;
    assert!(s.converged, "{s:?}");
    assert!((s.q[left] + 0.15).abs() < 1e-6, "{:?}", s.q);
    assert!((s.q[right] + s.q[left]).abs() < 1e-12, "{:?}", s.q);
    // The right front wheel went down as the left went up.
    let dz_left = position(&rover, &s.q, "left-front-wheel").z - start.z;
    let dz_right = position(&rover, &s.q, "right-front-wheel").z
        - position(&rover, &q0, "right-front-wheel").z;
    assert!(dz_left > 0.04 && dz_right < -0.04, "{dz_left} {dz_right}");
    Ok(())
}

#[test]
fn the_coupled_jacobian_is_the_derivative_along_the_leader() -> Result<(), FieldError> {
    let rover = mechanism("rocker-bogie")?;
    let left = rover.variable("left-rocker").unwrap_or(usize::MAX);
    let mut q = rover.zero_state();
    q[left] = 0.2;
    rover.apply_couplings(&mut q);
    let f = frame(&rover, "right-middle-wheel");
    let jac = rover.jacobian(&q, &f)?;
    let h = 1e-6;
    let mut plus = q.clone();
    plus[left] += h;
    rover.apply_couplings(&mut plus);
    let mut minus = q.clone();
    minus[left] -= h;
    rover.apply_couplings(&mut minus);
    let fd = (rover.pose(&plus, &f)?.translation.vector
        - rover.pose(&minus, &f)?.translation.vector)
        / (2.0 * h);
    for k in 0..3 {
        assert!(
            (jac[(k, left)] - fd[k]).abs() < 1e-8,
            "{k}: {} vs {}",
            jac[(k, left)],
            fd[k]
        );
    }
    Ok(())
}

/// The rocker angle of a four-bar from the crank angle, by intersecting
/// two circles (the closed form the loop solver is checked against).
fn rocker_tip_closed_form(crank_angle: f64) -> [f64; 2] {
    let (a, b, c, d) = (0.2, 0.6, 0.5, 0.6);
    let bx = a * crank_angle.cos();
    let by = a * crank_angle.sin();
    // C is on the circle of radius b about B and radius c about D = (d, 0).
    let (dx, dy) = (d - bx, -by);
    let dist = (dx * dx + dy * dy).sqrt();
    let along = (b * b - c * c + dist * dist) / (2.0 * dist);
    let h = (b * b - along * along).max(0.0).sqrt();
    // The branch with C above the line B–D (the assembled one).
    let (ux, uy) = (dx / dist, dy / dist);
    [bx + along * ux - h * uy, by + along * uy + h * ux]
}

#[test]
fn the_four_bar_stays_closed_all_the_way_round() -> Result<(), FieldError> {
    let linkage = mechanism("four-bar")?;
    let crank = linkage.variable("crank").unwrap_or(usize::MAX);
    assert!(linkage.closure(&linkage.zero_state())?.closed);
    assert!(linkage.is_driven(crank));
    assert!(!linkage.is_driven(linkage.variable("rocker").unwrap_or(0)));
    let mut q = linkage.zero_state();
    for step in 0..=72 {
        let angle = step as f64 * 5.0_f64.to_radians();
        q[crank] = angle;
        let closure = linkage.close_loops(&mut q)?;
        assert!(closure.closed, "crank {angle}: gap {}", closure.gap);
        assert!((q[crank] - angle).abs() < 1e-15, "the crank must not move");
        // The coupler's far end (the rocker's joint) is where two circles meet.
        let c = position(&linkage, &q, "rocker");
        let want = rocker_tip_closed_form(angle);
        assert!(
            (c.x - want[0]).abs() < 1e-8 && (c.y - want[1]).abs() < 1e-8,
            "crank {angle}: {c} vs {want:?}"
        );
    }
    Ok(())
}

#[test]
fn a_hexapod_is_one_leg_mounted_six_times() -> Result<(), FieldError> {
    let hexapod = mechanism("hexapod")?;
    assert_eq!(hexapod.dof(), 18);
    let legs: Vec<&str> = hexapod
        .groups()
        .iter()
        .filter(|g| g.parent.is_none())
        .map(|g| g.name.as_str())
        .collect();
    assert_eq!(legs.len(), 6, "{legs:?}");
    let q = hexapod.zero_state();
    for name in legs {
        // Every foot stands on the ground, 0.15 m out from its hip.
        let foot = position(&hexapod, &q, &format!("{name}/foot"));
        let hip = position(&hexapod, &q, &format!("{name}-mount"));
        assert!(foot.z.abs() < 1e-12, "{name}: {foot}");
        let reach = ((foot.x - hip.x).powi(2) + (foot.y - hip.y).powi(2)).sqrt();
        assert!((reach - 0.15).abs() < 1e-12, "{name}: {reach}");
    }
    Ok(())
}

#[test]
fn a_goal_relative_to_a_moving_frame() -> Result<(), FieldError> {
    let robot = mechanism("rover-arm")?;
    assert_eq!(robot.dof(), 6);
    let names: Vec<&str> = robot.groups().iter().map(|g| g.name.as_str()).collect();
    assert_eq!(names, ["rover", "arm"]);
    let gripper = frame(&robot, "arm/gripper");
    let chassis = frame(&robot, "rover/chassis");
    // Drive the rover somewhere, then put the gripper 0.6 m ahead of and
    // 0.3 m above the chassis centre: only the arm can do that.
    let mut seed = robot.zero_state();
    seed[0] = 1.5;
    seed[1] = -0.7;
    seed[2] = 0.9;
    let want = Vector3::new(0.6, 0.0, 0.3);
    let s = robot.solve(
        &[Goal::relative(gripper, Target::Position(want), chassis)],
        &seed,
        &Options::default(),
    )?;
    assert!(s.converged, "{s:?}");
    let got = robot.relative(&s.q, &chassis, &gripper)?.translation.vector;
    assert!((got - want).norm() < 1e-7, "{got}");
    // A relative goal also accepts whole poses.
    let target = Pose::translation(0.5, 0.1, 0.35);
    let s = robot.solve(
        &[
            Goal::relative(
                gripper,
                Target::Position(target.translation.vector),
                chassis,
            ),
            Goal::new(chassis, Target::Position(Vector3::new(2.0, 1.0, 0.2))),
        ],
        &robot.zero_state(),
        &Options::default(),
    )?;
    assert!(s.converged, "{s:?}");
    let base = robot.pose(&s.q, &chassis)?.translation.vector;
    assert!((base - Vector3::new(2.0, 1.0, 0.2)).norm() < 1e-7);
    Ok(())
}

#[test]
fn closed_form_planar_solvers_agree_with_the_generic_one() -> Result<(), FieldError> {
    let two = mechanism("planar-2r")?;
    let three = mechanism("planar-3r")?;
    assert_eq!(
        two.command_names(),
        ["closed-form planar FK", "analytic 2R"]
    );
    assert_eq!(
        three.command_names(),
        ["closed-form planar FK", "analytic 3R"]
    );
    // The closed-form FK against the tree walk, over random states.
    for q in support::sample(&proptest::collection::vec(-PI..PI, 3), 200) {
        for (arm, q) in [(&two, &q[..2]), (&three, &q[..])] {
            let f = frame(arm, "tool");
            let a = arm.pose(q, &f)?;
            let b = arm.pose_generic(q, &f)?;
            assert!((a.translation.vector - b.translation.vector).norm() < 1e-12);
            assert!(a.rotation.angle_to(&b.rotation) < 1e-12);
        }
    }
    let options = Options::default();
    let mut exact = 0;
    let targets = (0.0f64..2.0, 0.0..2.0 * PI, -PI..PI);
    for (r, a, phi) in support::sample(&targets, 300) {
        let p = Vector3::new(r * a.cos(), r * a.sin(), 0.0);
        let goal = [Goal::new(frame(&two, "tool"), Target::Position(p))];
        let special = two.solve(&goal, &[0.1, 0.1], &options)?;
        let generic = two.solve_generic(&goal, &[0.1, 0.1], &options)?;
        // Same verdict on reachability; both really reach when they say so.
        assert_eq!(special.converged, generic.converged, "{p}");
        if special.converged {
            assert!((position(&two, &special.q, "tool") - p).norm() < 1e-9);
            exact += usize::from(special.iterations == 0);
        }
        let pose = Pose::from_parts(
            nalgebra::Translation3::new(p.x, p.y, 0.0),
            nalgebra::UnitQuaternion::from_axis_angle(&Vector3::z_axis(), phi),
        );
        let goal = [Goal::new(frame(&three, "tool"), Target::Pose(pose))];
        let special = three.solve(&goal, &[0.1, 0.1, 0.1], &options)?;
        let generic = three.solve_generic(&goal, &[0.1, 0.1, 0.1], &options)?;
        assert_eq!(special.converged, generic.converged, "{p} {phi}");
        if special.converged {
            let reached = three.pose(&special.q, &frame(&three, "tool"))?;
            assert!((reached.translation.vector - p).norm() < 1e-9);
            assert!(reached.rotation.angle_to(&pose.rotation) < 1e-9);
        }
    }
    // Most targets are reachable and go through the closed form.
    assert!(exact > 200, "{exact}");
    Ok(())
}

#[test]
fn collision_finds_a_folded_arm_and_an_obstacle() -> Result<(), FieldError> {
    let arm = mechanism("planar-3r")?;
    let (l1, l3) = (
        arm.bodies().iter().position(|b| b.name == "q1"),
        arm.bodies().iter().position(|b| b.name == "q3"),
    );
    let (Some(l1), Some(l3)) = (l1, l3) else {
        panic!("no links");
    };
    // Straight: nothing touches.
    let straight = arm.collisions(&[0.0, 0.0, 0.0], Plane::Plan, &[])?;
    assert!(straight.pairs.is_empty());
    // Folded back on itself: the hand lies on the first link.
    let folded = arm.collisions(
        &[0.0, 170f64.to_radians(), 30f64.to_radians()],
        Plane::Plan,
        &[],
    )?;
    assert!(
        folded.pairs.contains(&(Part::Body(l1), Part::Body(l3))),
        "{folded:?}"
    );
    // A post in the way of the straight arm.
    let post = [Obstacle::Circle {
        center: [1.5, 0.1],
        radius: 0.1,
    }];
    let hit = arm.collisions(&[0.0, 0.0, 0.0], Plane::Plan, &post)?;
    assert_eq!(hit.pairs.len(), 1, "{hit:?}");
    let (gap, _, _) = arm
        .clearance(
            &[0.0, 0.0, 0.0],
            Plane::Plan,
            &[Obstacle::Circle {
                center: [1.0, 0.5],
                radius: 0.2,
            }],
        )?
        .unwrap_or((f64::NAN, Part::Obstacle(0), Part::Obstacle(0)));
    // The link capsule (radius 0.05) is 0.5 m below the post's centre; the
    // two outer links are further apart (0.8 m less two radii).
    assert!((gap - (0.5 - 0.2 - 0.05)).abs() < 1e-9, "{gap}");
    Ok(())
}

#[test]
fn bad_obstacles_and_couplings_name_the_field() {
    let arm = mechanism("planar-2r").unwrap_or_else(|e| panic!("{e}"));
    let Err(e) = arm.collisions(
        &[0.0, 0.0],
        Plane::Plan,
        &[Obstacle::Circle {
            center: [0.0, f64::NAN],
            radius: 1.0,
        }],
    ) else {
        panic!("accepted NaN");
    };
    assert_eq!(e.field, "obstacles[0]");
    let mut b = kinolab_mechanism::ModelBuilder::new("bad");
    b.joint(
        "a",
        kinolab_mechanism::JointKind::Revolute,
        0,
        Pose::identity(),
        Vector3::z_axis(),
        0.0,
        Pose::identity(),
        None,
    );
    b.couple("a", "nope", 1.0, 0.0);
    let Err(e) = b.build() else {
        panic!("accepted")
    };
    assert_eq!(e.field, "couplings[0].leader");
    assert!(e.message.contains("nope"));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]

    /// The tree search finds exactly the pairs that testing every capsule
    /// pair finds, for random states and random obstacles.
    #[test]
    fn tree_search_matches_brute_force(
        which in 0usize..4,
        unit in proptest::collection::vec(0.0f64..1.0, 64),
        obstacles in proptest::collection::vec((-1.5f64..1.5, -1.5f64..1.5, 0.02f64..0.4, any::<bool>()), 0..4),
        side in any::<bool>(),
    ) {
        let id = ["planar-3r", "hexapod", "rover-arm", "rocker-bogie"][which];
        let m = mechanism(id).unwrap_or_else(|e| panic!("{e}"));
        // Each joint somewhere within its limits, couplings applied.
        let mut q: Vec<f64> = (0..m.dof())
            .map(|i| {
                let [lo, hi] = m.variable_joint(i).and_then(|j| j.limits).unwrap_or([-PI, PI]);
                lo + unit[i] * (hi - lo)
            })
            .collect();
        m.apply_couplings(&mut q);
        let plane = if side { Plane::Side } else { Plane::Plan };
        let obstacles: Vec<Obstacle> = obstacles
            .iter()
            .map(|&(x, y, r, round)| if round {
                Obstacle::Circle { center: [x, y], radius: r }
            } else {
                Obstacle::Rect { center: [x, y], half: [r, 0.5 * r] }
            })
            .collect();
        let fast = m.collisions(&q, plane, &obstacles).unwrap_or_else(|e| panic!("{e}"));
        let slow = m.collisions_brute_force(&q, plane, &obstacles).unwrap_or_else(|e| panic!("{e}"));
        prop_assert_eq!(&fast.pairs, &slow.pairs, "{} {:?}", id, q);
        prop_assert!(fast.fine_tests <= slow.fine_tests);
        // The pruned clearance finds the same smallest gap.
        let near = m.clearance(&q, plane, &obstacles).unwrap_or_else(|e| panic!("{e}"));
        let all = m.clearance_brute_force(&q, plane, &obstacles).unwrap_or_else(|e| panic!("{e}"));
        prop_assert_eq!(near.is_some(), all.is_some());
        if let (Some((a, _, _)), Some((b, _, _))) = (near, all) {
            prop_assert!((a - b).abs() < 1e-12, "{} vs {}", a, b);
        }
    }
}

#[test]
fn the_tree_skips_most_capsule_pairs_of_a_hexapod() -> Result<(), FieldError> {
    let hexapod = mechanism("hexapod")?;
    let q = hexapod.zero_state();
    let fast = hexapod.collisions(&q, Plane::Plan, &[])?;
    let slow = hexapod.collisions_brute_force(&q, Plane::Plan, &[])?;
    assert!(fast.pairs.is_empty() && slow.pairs.is_empty());
    assert!(
        fast.fine_tests * 4 < slow.fine_tests,
        "{} of {}",
        fast.fine_tests,
        slow.fine_tests
    );
    Ok(())
}
