//! Forward and inverse kinematics against golden values, each other and
//! finite differences.

use std::f64::consts::FRAC_PI_2;

use kinolab_mechanism::catalogue::{mechanism, puma560_rows};
use kinolab_mechanism::dh::{Convention, DhRow, chain};
use kinolab_mechanism::{FieldError, FrameRef, Goal, Model, Options, Pose, Target};

fn tool(m: &Model) -> FrameRef {
    m.frame("tool").unwrap_or_else(|e| panic!("{e}"))
}

fn close(a: &Pose, b: &Pose, tol: f64) -> bool {
    (a.translation.vector - b.translation.vector).norm() < tol
        && a.rotation.angle_to(&b.rotation) < tol
}

mod support;

#[test]
fn puma_golden_poses() -> Result<(), FieldError> {
    let puma = mechanism("puma560")?;
    let d1 = 0.6718;
    let at = |q: &[f64]| puma.pose(q, &tool(&puma));
    let zero = at(&[0.0; 6])?;
    let want = nalgebra::Vector3::new(0.4521, -0.15005, 0.4318 + d1);
    assert!(
        (zero.translation.vector - want).norm() < 1e-12,
        "{}",
        zero.translation.vector
    );
    assert!(zero.rotation.angle() < 1e-12);
    let bent = at(&[0.0, FRAC_PI_2, -FRAC_PI_2, 0.0, 0.0, 0.0])?;
    let want = nalgebra::Vector3::new(0.0203, -0.15005, 0.8636 + d1);
    assert!(
        (bent.translation.vector - want).norm() < 1e-12,
        "{}",
        bent.translation.vector
    );
    Ok(())
}

#[test]
fn standard_and_modified_dh_describe_the_same_arm() -> Result<(), FieldError> {
    // Modified row i takes (a, α) of standard row i − 1; the last link's
    // (a, α) becomes the tool transform.
    let standard = puma560_rows();
    let mut modified: Vec<DhRow> = Vec::new();
    for (i, r) in standard.iter().enumerate() {
        let (a, alpha) = if i == 0 {
            (0.0, 0.0)
        } else {
            (standard[i - 1].a, standard[i - 1].alpha)
        };
        modified.push(DhRow {
            a,
            alpha,
            ..r.clone()
        });
    }
    let last = &standard[standard.len() - 1];
    let tool_pose =
        Pose::translation(last.a, 0.0, 0.0) * Pose::rotation(nalgebra::Vector3::x() * last.alpha);
    let s = chain(
        "std",
        Convention::StandardDh,
        &standard,
        Pose::identity(),
        Pose::identity(),
    )?;
    let m = chain(
        "mdh",
        Convention::ModifiedDh,
        &modified,
        Pose::identity(),
        tool_pose,
    )?;
    for q in support::sample(&support::states(&s), 200) {
        assert!(
            close(&s.pose(&q, &tool(&s))?, &m.pose(&q, &tool(&m))?, 1e-12),
            "{q:?}"
        );
    }
    Ok(())
}

#[test]
fn jacobian_matches_finite_differences() -> Result<(), FieldError> {
    for id in ["puma560", "stanford", "panda", "planar-3r"] {
        let model = mechanism(id)?;
        let frame = tool(&model);
        for q in support::sample(&support::states(&model), 20) {
            let jac = model.jacobian(&q, &frame)?;
            let h = 1e-6;
            for v in 0..model.dof() {
                let (mut qp, mut qm) = (q.clone(), q.clone());
                qp[v] += h;
                qm[v] -= h;
                let (p, m) = (model.pose(&qp, &frame)?, model.pose(&qm, &frame)?);
                let linear = (p.translation.vector - m.translation.vector) / (2.0 * h);
                let angular = (p.rotation * m.rotation.inverse()).scaled_axis() / (2.0 * h);
                for k in 0..3 {
                    assert!((jac[(k, v)] - linear[k]).abs() < 1e-6, "{id} column {v}");
                    assert!(
                        (jac[(k + 3, v)] - angular[k]).abs() < 1e-6,
                        "{id} column {v}"
                    );
                }
            }
        }
    }
    Ok(())
}

fn round_trips(id: &str, count: usize) -> Result<(usize, usize), FieldError> {
    let model = mechanism(id)?;
    let frame = tool(&model);
    let seed = model.zero_state();
    let mut ok = 0;
    for q in support::sample(&support::states(&model), count) {
        let target = model.pose(&q, &frame)?;
        let options = Options {
            position_tolerance: 1e-6,
            rotation_tolerance: 1e-6,
            ..Options::default()
        };
        let s = model.solve(&[Goal::new(frame, Target::Pose(target))], &seed, &options)?;
        let reached = model.pose(&s.q, &frame)?;
        let inside = s.q.iter().enumerate().all(|(i, v)| {
            model
                .variable_joint(i)
                .and_then(|j| j.limits)
                .is_none_or(|[lo, hi]| (lo..=hi).contains(v))
        });
        assert!(inside, "{id}: a solution outside the limits");
        if s.converged {
            assert!(close(&reached, &target, 1e-6), "{id}: converged but off");
            ok += 1;
        }
    }
    Ok((ok, count))
}

/// Random poses within the limits, solved from the zero pose to 1e-6 m
/// and 1e-6 rad: at least 99.9 % must converge (10 000 each for the Puma
/// and the Panda, as the issue asks). The few misses lie next to the elbow
/// singularity, where the steps shrink slowly.
#[test]
fn ik_round_trips_converge() -> Result<(), FieldError> {
    for (id, n, bar) in [
        ("puma560", 10_000, 0.999),
        ("panda", 10_000, 0.999),
        ("stanford", 1000, 0.999),
    ] {
        let (ok, count) = round_trips(id, n)?;
        assert!(ok as f64 >= bar * count as f64, "{id}: {ok} of {count}");
    }
    Ok(())
}

#[test]
fn unreachable_targets_stop_with_the_closest_pose() -> Result<(), FieldError> {
    let arm = mechanism("planar-2r")?;
    let frame = tool(&arm);
    let far = nalgebra::Vector3::new(3.0, 0.0, 0.0);
    let s = arm.solve(
        &[Goal::new(frame, Target::Position(far))],
        &[0.3, 0.3],
        &Options::default(),
    )?;
    assert!(!s.converged);
    // The closest the 1 m + 0.8 m arm gets is 1.8 m out, 1.2 m short.
    // Fully stretched is a singular pose, so the last micrometres come slowly.
    assert!(
        (s.position_error - 1.2).abs() < 1e-4,
        "{}",
        s.position_error
    );
    let o = Options::default();
    // Every attempt, plus one longer polish of the best.
    assert!(s.iterations <= o.max_iterations * (o.restarts + 5));
    // A six-joint arm asked for a pose twice its reach gives up as fast:
    // attempts that stop improving end after a few iterations each.
    let puma = mechanism("puma560")?;
    let s = puma.solve(
        &[Goal::new(
            tool(&puma),
            Target::Pose(Pose::translation(2.0, 0.0, 0.7)),
        )],
        &puma.zero_state(),
        &o,
    )?;
    assert!(!s.converged && s.position_error > 1.0);
    assert!(s.iterations < 20 * (o.restarts + 1), "{}", s.iterations);
    Ok(())
}

#[test]
fn bad_states_and_frames_are_named() -> Result<(), FieldError> {
    let puma = mechanism("puma560")?;
    assert!(
        puma.pose(&[0.0; 5], &tool(&puma))
            .is_err_and(|e| e.field == "q")
    );
    assert!(
        puma.pose(&[0.0, f64::NAN, 0.0, 0.0, 0.0, 0.0], &tool(&puma))
            .is_err_and(|e| e.field == "q[1]")
    );
    assert!(
        puma.frame("gripper")
            .is_err_and(|e| e.message.contains("q3"))
    );
    assert!(mechanism("robby").is_err_and(|e| e.message.contains("puma560")));
    Ok(())
}

/// The Jacobian the long way: every joint's axis frame from the full
/// placement (origin, motion and post transform, one product each), the
/// columns from the textbook formula.
fn jacobian_from_placement(m: &Model, q: &[f64], frame: &FrameRef) -> nalgebra::DMatrix<f64> {
    let placed = m.place(q).unwrap_or_else(|e| panic!("{e}"));
    let p = (placed.bodies[frame.body] * frame.offset)
        .translation
        .vector;
    let mut jac = nalgebra::DMatrix::zeros(6, m.dof());
    // The joints above the frame's body, found by walking up from it.
    let mut body = frame.body;
    while let Some((i, joint)) = m.joints().iter().enumerate().find(|(_, j)| j.child == body) {
        let variable =
            (0..m.dof()).find(|&v| m.variable_joint(v).is_some_and(|j| std::ptr::eq(j, joint)));
        if let Some(v) = variable {
            let axis_frame = placed.joints[i];
            let z = axis_frame.rotation * joint.axis.into_inner();
            let (linear, angular) = match joint.kind {
                kinolab_mechanism::JointKind::Prismatic => (z, nalgebra::Vector3::zeros()),
                _ => (z.cross(&(p - axis_frame.translation.vector)), z),
            };
            for k in 0..3 {
                jac[(k, v)] += linear[k];
                jac[(3 + k, v)] += angular[k];
            }
        }
        body = joint.parent;
    }
    jac
}

/// The prepared walks (fixed products merged, turns specialised to their
/// axis) give what the full placement gives, to 1e-12, for every frame of
/// every catalogue mechanism at seeded random states.
#[test]
fn prepared_walks_match_the_full_placement() -> Result<(), FieldError> {
    let mut work = None;
    for (id, _, _) in kinolab_mechanism::catalogue::CATALOGUE {
        let m = mechanism(id)?;
        let uncoupled = m.couplings().is_empty();
        let w = work.insert(m.workspace());
        for q in support::sample(&support::states(&m), 20) {
            let placed = m.place(&q)?;
            for f in m.frames() {
                let frame = m.frame(&f.name)?;
                let want = placed.bodies[frame.body] * frame.offset;
                let got = m.pose_generic(&q, &frame)?;
                assert!(
                    close(&got, &want, 1e-12),
                    "{id} {}: {got} vs {want}",
                    f.name
                );
                if uncoupled {
                    let fast = m.jacobian_in(w, &q, &frame)?;
                    let slow = jacobian_from_placement(&m, &q, &frame);
                    assert!((fast - &slow).amax() < 1e-12, "{id} {}", f.name);
                }
            }
        }
    }
    Ok(())
}

#[test]
fn an_arm_seen_from_the_side_is_its_joints_then_its_tool() -> Result<(), FieldError> {
    use kinolab_mechanism::Plane;
    let arm = mechanism("vertical-2r")?;
    let level = arm.chain_in_plane(&[0.0, 0.0], &tool(&arm), Plane::Side)?;
    let want = [[0.0, 0.0], [0.5, 0.0], [0.9, 0.0]];
    assert_eq!(level.len(), want.len(), "{level:?}");
    for (got, want) in level.iter().zip(want) {
        assert!(
            (got[0] - want[0]).abs() < 1e-12 && (got[1] - want[1]).abs() < 1e-12,
            "{level:?}"
        );
    }
    // Up at the shoulder and bent back at the elbow: the tool is where FK puts it.
    let q = [FRAC_PI_2, -FRAC_PI_2];
    let bent = arm.chain_in_plane(&q, &tool(&arm), Plane::Side)?;
    let end = arm.pose(&q, &tool(&arm))?.translation.vector;
    let last = bent.last().copied().unwrap_or_default();
    assert!((last[0] - end.x).abs() < 1e-12 && (last[1] - end.z).abs() < 1e-12);
    assert!(
        (last[0] - 0.4).abs() < 1e-12 && (last[1] - 0.5).abs() < 1e-12,
        "{bent:?}"
    );
    Ok(())
}
