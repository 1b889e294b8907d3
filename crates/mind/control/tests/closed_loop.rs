//! The closed loop against the textbook's behaviour and the reference sheet.

use kinolab_common::angle::wrap;
use kinolab_control::batch::{batch, circle_starts};
use kinolab_control::{
    Direction, Driver, FieldError, Gains, Limits, Noise, Plan, Pose, Run, Segment, TEXTBOOK_GAINS,
    Trajectory,
};
use proptest::prelude::*;
use std::f64::consts::PI;

fn sim(run: &Run) -> Trajectory {
    run.simulate().unwrap_or_else(|e| panic!("{e}"))
}

fn reached_exactly(t: &Trajectory, goal: &Pose) -> bool {
    t.final_pose.distance(goal) <= 1e-3
        && t.final_pose.heading_error(goal).abs() <= 0.1f64.to_radians()
}

#[test]
fn every_start_on_the_unit_circle_reaches_the_goal() -> Result<(), FieldError> {
    for goal in [Pose::default(), Pose::new(2.0, -1.0, 2.0)] {
        for heading in [0.0, goal.theta, 2.5] {
            let starts = circle_starts(&goal, 1.0, 48, heading)?;
            let run = Run::polar(goal, goal, TEXTBOOK_GAINS)?;
            for (start, t) in starts.iter().zip(batch(&run, &starts)?) {
                assert!(t.reached, "from {start:?}");
                assert!(
                    reached_exactly(&t, &goal),
                    "from {start:?}: ended at {:?}",
                    t.final_pose
                );
                assert!(t.time_to_goal.is_some_and(|s| s < 10.0));
                assert!(
                    t.samples
                        .iter()
                        .all(|s| s.pose.x.is_finite() && s.v.is_finite())
                );
            }
        }
    }
    Ok(())
}

#[test]
fn the_contract_example_matches_its_sample_shape() -> Result<(), FieldError> {
    let t = sim(&Run::polar(
        Pose::new(-1.0, 0.5, 0.0),
        Pose::default(),
        TEXTBOOK_GAINS,
    )?);
    // 10 s at 1 ms, a sample every 100 steps: t = 0, 0.1, ..., 10.
    assert_eq!(t.samples.len(), 101);
    assert!((t.samples[100].t - 10.0).abs() < 1e-12);
    let first = &t.samples[0];
    // v = k_ρ ρ = 3 √1.25; ω = k_α α + k_β β with β = −α.
    let alpha = (-0.5f64).atan2(1.0);
    assert!((first.v - 3.0 * 1.25f64.sqrt()).abs() < 1e-12);
    assert!((first.omega - (8.0 * alpha + 1.5 * alpha)).abs() < 1e-12);
    assert!(t.reached && !t.backward);
    Ok(())
}

#[test]
fn on_the_straight_line_rho_decays_exponentially() -> Result<(), FieldError> {
    // α = β = 0 stays 0: ρ̇ = −k_ρ ρ, so ρ(t) = ρ₀ e^{−k_ρ t}.
    for k_rho in [0.5, 3.0] {
        let gains = Gains::new(k_rho, 8.0, -1.5)?;
        let mut run = Run::polar(Pose::new(-2.0, 0.0, 0.0), Pose::default(), gains)?;
        run.output_every = 10;
        let t = sim(&run);
        for s in &t.samples {
            let exact = 2.0 * (-k_rho * s.t).exp();
            assert!(
                (s.polar.rho - exact).abs() <= 1e-10 * exact.max(1e-3),
                "t = {}: {} vs {exact}",
                s.t,
                s.polar.rho
            );
            assert!(s.polar.alpha == 0.0 && s.polar.beta == 0.0 && s.pose.y == 0.0);
        }
    }
    Ok(())
}

#[test]
fn halving_dt_moves_no_sample_by_more_than_a_micrometre() -> Result<(), FieldError> {
    let goal = Pose::new(0.3, 0.2, 0.4);
    for start in [
        Pose::new(-1.0, 0.5, 0.0),
        Pose::new(1.0, 0.8, 1.0),
        Pose::new(0.2, -1.5, -2.0),
    ] {
        let coarse = Run::polar(start, goal, TEXTBOOK_GAINS)?;
        let fine = Run {
            dt: 5e-4,
            output_every: 200,
            ..coarse.clone()
        };
        let (a, b) = (sim(&coarse), sim(&fine));
        assert_eq!(a.samples.len(), b.samples.len());
        let mut worst: f64 = 0.0;
        for (p, q) in a.samples.iter().zip(&b.samples) {
            assert!((p.t - q.t).abs() < 1e-12);
            worst = worst
                .max(p.pose.distance(&q.pose))
                .max(wrap(p.pose.theta - q.pose.theta).abs());
        }
        assert!(worst < 1e-6, "{start:?}: {worst}");
        // And RK4 is doing its job: far below the bound, not just under it.
        assert!(worst < 1e-9, "{start:?}: {worst}");
    }
    Ok(())
}

#[test]
fn gains_outside_the_region_do_not_reach() -> Result<(), FieldError> {
    let start = Pose::new(-1.0, 0.5, 0.0);
    for (g, why) in [
        ((3.0, 8.0, 1.5), "k_beta > 0"),
        ((3.0, 2.0, -1.5), "k_alpha < k_rho"),
        ((-1.0, 8.0, -1.5), "k_rho < 0"),
    ] {
        let gains = Gains::new(g.0, g.1, g.2)?;
        assert!(!gains.stability().locally_stable);
        let t = sim(&Run::polar(start, Pose::default(), gains)?);
        assert!(!t.reached, "{why}");
        assert!(t.final_position_error.is_finite(), "{why}");
    }
    // Locally stable but not strongly: still converges.
    let weak = Gains::new(3.0, 4.0, -1.5)?;
    assert!(weak.stability().locally_stable && !weak.stability().strongly_stable);
    let mut run = Run::polar(start, Pose::default(), weak)?;
    run.duration = 20.0;
    assert!(sim(&run).reached);
    Ok(())
}

#[test]
fn starting_at_or_next_to_the_goal_gives_numbers() -> Result<(), FieldError> {
    for start in [
        Pose::default(),
        Pose::new(1e-12, -1e-12, 0.0),
        Pose::new(1e-9, 0.0, 0.5),
        Pose::new(0.0, 0.0, 3.0),
    ] {
        let t = sim(&Run::polar(start, Pose::default(), TEXTBOOK_GAINS)?);
        for s in &t.samples {
            for x in [
                s.pose.x,
                s.pose.y,
                s.pose.theta,
                s.v,
                s.omega,
                s.polar.rho,
                s.polar.alpha,
                s.polar.beta,
            ] {
                assert!(x.is_finite(), "{start:?}: {s:?}");
            }
        }
        assert!(t.final_pose.distance(&Pose::default()) < 1e-3, "{start:?}");
    }
    let at_goal = sim(&Run::polar(
        Pose::default(),
        Pose::default(),
        TEXTBOOK_GAINS,
    )?);
    assert_eq!(at_goal.time_to_goal, Some(0.0));
    assert_eq!(at_goal.path_length, 0.0);
    Ok(())
}

#[test]
fn goals_behind_are_reached_rear_first() -> Result<(), FieldError> {
    let mut run = Run::polar(Pose::new(1.0, 0.3, 0.0), Pose::default(), TEXTBOOK_GAINS)?;
    let t = sim(&run);
    assert!(t.backward && t.reached && reached_exactly(&t, &Pose::default()));
    assert!(t.samples.iter().all(|s| s.v <= 0.0));
    // Forced forward from the same start: it turns around, takes longer.
    run.driver = Driver::Polar {
        gains: TEXTBOOK_GAINS,
        direction: Direction::Forward,
    };
    let f = sim(&run);
    assert!(!f.backward && f.samples.iter().all(|s| s.v >= 0.0));
    assert!(f.path_length > t.path_length);
    Ok(())
}

#[test]
fn saturation_never_exceeds_the_limit_and_keeps_the_curvature() -> Result<(), FieldError> {
    let mut run = Run::polar(Pose::new(-2.0, 1.0, 0.5), Pose::default(), TEXTBOOK_GAINS)?;
    let free = sim(&run);
    let limit = 0.4 * free.peak_wheel_speed;
    run.max_wheel_speed = Some(limit);
    run.duration = 30.0;
    let t = sim(&run);
    assert!(
        t.peak_wheel_speed <= limit * (1.0 + 1e-12),
        "{} > {limit}",
        t.peak_wheel_speed
    );
    // The catalogue differential drive: wheels 0.25 m either side of P,
    // radius 0.1 m, so its faster wheel turns at (|v| + 0.25 |ω|) / 0.1.
    for s in &t.samples {
        let fastest = (s.v.abs() + 0.25 * s.omega.abs()) / 0.1;
        assert!(fastest <= limit * (1.0 + 1e-12), "{fastest} > {limit}");
    }
    // Saturated at the start: the command is the unsaturated one scaled down.
    let (f, s) = (&free.samples[0], &t.samples[0]);
    assert!((s.v / s.omega - f.v / f.omega).abs() < 1e-9);
    assert!(t.reached && t.time_to_goal > free.time_to_goal);
    Ok(())
}

fn noisy(seed: u64) -> Result<Run, FieldError> {
    let mut run = Run::polar(Pose::new(-1.5, 1.0, 0.0), Pose::default(), TEXTBOOK_GAINS)?;
    run.noise = Some(Noise {
        seed,
        slip: 0.3,
        push_speed: 0.05,
        push_turn: 0.1,
    });
    Ok(run)
}

#[test]
fn the_same_seed_gives_the_same_run() -> Result<(), FieldError> {
    let (a, b, c) = (sim(&noisy(7)?), sim(&noisy(7)?), sim(&noisy(8)?));
    assert_eq!(a, b);
    assert_ne!(a.samples, c.samples);
    // Slip slows the robot but feedback still gets there (pushes keep it
    // from settling to the millimetre, so compare with a looser ring).
    assert!(a.final_position_error < 0.05, "{}", a.final_position_error);
    Ok(())
}

#[test]
fn open_loop_follows_the_plan_until_something_slips() -> Result<(), FieldError> {
    let segments = [
        Segment::Line { length: 1.0 },
        Segment::Arc {
            radius: 0.5,
            angle: std::f64::consts::FRAC_PI_2,
        },
        Segment::Line { length: 0.5 },
    ];
    let plan = Plan::new(Pose::new(-1.0, -1.0, 0.0), &segments, Limits::default())?;
    let end = plan.end();
    let clean = sim(&Run::open_loop(plan.clone())?);
    assert!(
        clean.final_pose.distance(&end) < 1e-6,
        "{:?} vs {end:?}",
        clean.final_pose
    );
    // Samples sit on the nominal plan.
    for s in &clean.samples {
        assert!(s.pose.distance(&plan.nominal(s.t)) < 1e-6, "t = {}", s.t);
    }
    // The same slip: open loop misses, closed loop (to the same goal) arrives.
    let noise = Some(Noise {
        seed: 3,
        slip: 0.2,
        push_speed: 0.0,
        push_turn: 0.0,
    });
    let open = sim(&Run {
        noise,
        ..Run::open_loop(plan.clone())?
    });
    assert!(
        open.final_pose.distance(&end) > 0.05,
        "{}",
        open.final_pose.distance(&end)
    );
    let closed = sim(&Run {
        noise,
        ..Run::polar(plan.start, end, TEXTBOOK_GAINS)?
    });
    assert!(closed.reached);
    Ok(())
}

#[test]
fn sampled_data_control_holds_its_command() -> Result<(), FieldError> {
    let mut run = Run::polar(Pose::new(-1.0, 0.5, 0.0), Pose::default(), TEXTBOOK_GAINS)?;
    run.control_rate = Some(10.0);
    run.output_every = 1;
    run.duration = 1.0;
    let t = sim(&run);
    for block in t.samples[..1000].chunks(100) {
        assert!(
            block
                .iter()
                .all(|s| s.v == block[0].v && s.omega == block[0].omega)
        );
    }
    assert_ne!(t.samples[0].v, t.samples[100].v);
    // At 20 Hz the loop still reaches the goal.
    run.control_rate = Some(20.0);
    run.duration = 10.0;
    run.output_every = 100;
    assert!(sim(&run).reached);
    assert!(
        Run {
            control_rate: Some(5000.0),
            ..run
        }
        .simulate()
        .is_err_and(|e| e.field == "control_rate")
    );
    Ok(())
}

#[test]
fn bad_runs_name_their_field() -> Result<(), FieldError> {
    let run = Run::polar(Pose::new(-1.0, 0.5, 0.0), Pose::default(), TEXTBOOK_GAINS)?;
    let cases = [
        (
            Run {
                dt: 0.0,
                ..run.clone()
            },
            "dt",
        ),
        (
            Run {
                dt: 1e-7,
                ..run.clone()
            },
            "dt",
        ),
        (
            Run {
                duration: f64::NAN,
                ..run.clone()
            },
            "duration",
        ),
        (
            Run {
                output_every: 0,
                ..run.clone()
            },
            "output_every",
        ),
        (
            Run {
                start: Pose::new(f64::INFINITY, 0.0, 0.0),
                ..run.clone()
            },
            "start.x",
        ),
        (
            Run {
                max_wheel_speed: Some(-1.0),
                ..run.clone()
            },
            "max_wheel_speed",
        ),
    ];
    for (bad, field) in cases {
        assert!(bad.simulate().is_err_and(|e| e.field == field), "{field}");
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Any start 0.2 to 2 m away, any heading: the textbook gains converge.
    #[test]
    fn textbook_gains_converge_from_anywhere(r in 0.2f64..2.0, phi in -PI..PI, heading in -PI..PI) {
        let start = Pose::new(r * phi.cos(), r * phi.sin(), heading);
        let mut run = Run::polar(start, Pose::default(), TEXTBOOK_GAINS).map_err(|e| TestCaseError::fail(e.to_string()))?;
        run.duration = 15.0;
        run.output_every = 1000;
        let t = run.simulate().map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert!(t.reached, "{:?} ended {:?}", start, t.final_pose);
    }
}

#[test]
fn unstable_gains_stop_at_the_bound_and_say_so_in_words() -> Result<(), FieldError> {
    // k_alpha < 0 breaks the sheet's condition k_alpha + 5/3 k_beta - 2/pi k_rho > 0.
    let start = Pose::new(-1.0, 0.5, 0.0);
    let run = Run::polar(start, Pose::default(), Gains::new(3.0, -8.0, 1.5)?)?;
    let t = sim(&run);
    let d = t.diverged.as_ref().expect("these gains run away");
    assert!(d.t > 0.0 && d.t < 10.0, "stopped at {} s", d.t);
    assert!(
        d.reason
            .starts_with(&format!("diverged after {:.2} s: the distance", d.t)),
        "{}",
        d.reason
    );
    assert!(d.reason.contains("past 100 m"), "{}", d.reason);
    assert!(d.reason.contains("unstable"), "{}", d.reason);
    // What is kept (and plotted) never goes past the bound.
    for s in &t.samples {
        assert!(s.pose.x.hypot(s.pose.y) <= 100.0, "{s:?}");
    }
    assert!(t.final_position_error <= 100.0);
    assert!(!t.reached);
    Ok(())
}

#[test]
fn a_far_start_with_stable_gains_is_not_called_diverged() -> Result<(), FieldError> {
    // 50 m away: past the 100 m floor only if the bound ignored the start.
    let run = Run {
        duration: 60.0,
        ..Run::polar(Pose::new(-50.0, 30.0, 1.0), Pose::default(), TEXTBOOK_GAINS)?
    };
    let t = sim(&run);
    assert!(t.diverged.is_none(), "{:?}", t.diverged);
    assert!(t.reached);
    Ok(())
}
