//! The benchmark kernels: the core functions the lab calls while a learner
//! plays, each wrapped so that one call is one unit of work.
//!
//! The same list runs natively under criterion (`benches/kernels.rs`) and,
//! compiled to wasm, in headless Chromium (`tests/e2e/bench.mjs` calls
//! [`run_kernel`]); `cargo xtask bench` prints both side by side. Each
//! kernel returns a checksum so the optimiser cannot drop the work.

use std::hint::black_box;

pub mod architecture;
pub mod behaviour;
pub mod components;
pub mod design;
pub mod mechanism;
pub mod player;
#[cfg(all(feature = "compare-k", not(target_arch = "wasm32")))]
pub mod reference;
pub mod script;

/// A named unit of work.
#[derive(Debug, Clone, Copy)]
pub struct Kernel {
    pub name: &'static str,
    pub run: fn() -> f64,
}

const ROTATION: &str = r"\begin{bmatrix} \cos\theta & \sin\theta & 0 \\ -\sin\theta & \cos\theta & 0 \\ 0 & 0 & 1 \end{bmatrix}";

fn parse_lesson() -> f64 {
    let files = kinolab_lessons::bundled::markdown_files();
    let (path, text) = files
        .iter()
        .find(|(p, _)| p.ends_with("02-ways-to-move.md"))
        .copied()
        .unwrap_or(("", ""));
    match kinolab_lessons::parse_lesson(path, black_box(text)) {
        Ok((_, blocks)) => blocks.len() as f64,
        Err(_) => -1.0,
    }
}

fn parse_formula() -> f64 {
    match kinolab_lessons::math::parse(black_box(ROTATION)) {
        Ok(kinolab_lessons::math::Math::Matrix { rows, .. }) => rows.len() as f64,
        _ => -1.0,
    }
}

fn stability() -> f64 {
    let feet = [
        [0.3, 0.2],
        [0.0, 0.25],
        [-0.3, 0.2],
        [-0.3, -0.2],
        [0.0, -0.25],
        [0.3, -0.2],
    ];
    kinolab_locomotion::static_stability(black_box([0.05, 0.02]), black_box(&feet))
        .map_or(f64::NAN, |s| s.margin)
}

/// One gait cycle sampled 100 times (the gait studio's and `kinolab
/// gait`'s work): stance sets, feet and margins.
fn gait_cycle() -> f64 {
    let Some(gait) = kinolab_locomotion::named(black_box("hexapod-wave")) else {
        return f64::NAN;
    };
    kinolab_locomotion::gait::min_margin(&gait.sample(100)).unwrap_or(f64::NAN)
}

/// The contract's CPG example: four oscillators for 10 s at dt = 1 ms.
fn cpg_10s() -> f64 {
    let cpg = kinolab_locomotion::Cpg {
        frequency: 1.0,
        legs: ["LF", "RF", "LH", "RH"].map(String::from).to_vec(),
        target_phases: vec![0.25, 0.75, 0.0, 0.5],
        weight: 2.0,
        weights: None,
        model: Default::default(),
        initial_deg: black_box(vec![0.0, 10.0, 20.0, 30.0]),
        dt: 0.001,
        duration: 10.0,
        kicks: Vec::new(),
        changes: Vec::new(),
    };
    cpg.run().map_or(f64::NAN, |s| s.theta[0])
}

thread_local! {
    static WALKER: std::cell::RefCell<Option<(kinolab_locomotion::walker::Walker, Vec<f64>, f64)>> =
        const { std::cell::RefCell::new(None) };
}

/// One frame of the hexapod walker: the tripod gait moved on 1/120 of a
/// cycle, six leg IKs from the last frame's joints.
fn hexapod_frame() -> f64 {
    WALKER.with(|cell| {
        let mut state = cell.borrow_mut();
        if state.is_none() {
            let walker = kinolab_locomotion::named("hexapod-tripod").and_then(|mut g| {
                g.stride = 0.06;
                kinolab_locomotion::walker::Walker::new(g, 0.03).ok()
            });
            *state = walker.map(|w| {
                let q = w.model.zero_state();
                (w, q, 0.0)
            });
        }
        let Some((walker, q, tau)) = state.as_mut() else {
            return f64::NAN;
        };
        *tau = (*tau + 1.0 / 120.0).rem_euclid(1.0);
        match walker.step(black_box(*tau), q) {
            Ok(step) => {
                let error = step.errors.iter().copied().fold(0.0, f64::max);
                *q = step.q;
                error
            }
            Err(_) => f64::NAN,
        }
    })
}

fn leg_events() -> f64 {
    kinolab_locomotion::leg_events(black_box(17)).map_or(f64::NAN, |n| n as f64)
}

fn pick_cell() -> f64 {
    match kinolab_autonomy::PickCell::new(0.03, 0.01, 0.002) {
        Ok(cell) => cell
            .run(black_box(100), 7)
            .iter()
            .filter(|t| t.scripted_grasped)
            .count() as f64,
        Err(_) => f64::NAN,
    }
}

/// The Ackermann car: four wheels, a linkage, a fixed axle; built once.
fn car() -> &'static kinolab_wheels::Chassis {
    static CAR: std::sync::OnceLock<Option<kinolab_wheels::Chassis>> = std::sync::OnceLock::new();
    CAR.get_or_init(|| kinolab_wheels::catalogue::robot("ackermann-car").ok())
        .as_ref()
        .unwrap_or_else(|| unreachable!("the catalogue car is tested to build"))
}

fn wheels_analyze() -> f64 {
    let a = black_box(car()).analyze();
    (a.maneuverability + a.dof) as f64
}

/// Validation, the trigonometry of every row, then the analysis: what the
/// workbench pays when a learner drags a wheel.
fn wheels_build_analyze() -> f64 {
    let wheels = black_box(car()).wheels().to_vec();
    match kinolab_wheels::Chassis::new("car", wheels) {
        Ok(chassis) => chassis.analyze().maneuverability as f64,
        Err(_) => f64::NAN,
    }
}

fn wheels_inverse() -> f64 {
    let twist = kinolab_wheels::Vector3::new(1.0, 0.0, 0.4);
    black_box(car())
        .inverse(black_box(twist))
        .map_or(f64::NAN, |ik| ik.wheels.iter().map(|w| w.spin).sum())
}

fn wheels_forward() -> f64 {
    let spins = [Some(5.0), Some(6.0), Some(6.2), Some(7.1)];
    black_box(car())
        .forward(black_box(&spins))
        .map_or(f64::NAN, |fk| fk.twist[0] + fk.residual)
}

/// The contract's example run: 10 s of the polar controller at 1 kHz.
fn control_run() -> f64 {
    use kinolab_control::{Pose, Run, TEXTBOOK_GAINS};
    match Run::polar(Pose::new(-1.0, 0.5, 0.0), Pose::default(), TEXTBOOK_GAINS)
        .and_then(|run| black_box(run).simulate())
    {
        Ok(t) => t.path_length,
        Err(_) => f64::NAN,
    }
}

/// The floor under [`control_run`]: its 40 000 bearings (four per RK4
/// step, 10 000 steps) as bare `atan2` calls on a path of the same scale,
/// from (−1, 0.5) towards the goal. Each call's input depends on the one
/// before, as each RK4 stage's does on the stage before: the run cannot
/// start a bearing before the last one is known, and neither can this.
fn atan2_floor() -> f64 {
    let (x0, y0) = black_box((-1.0f64, 0.5f64));
    let mut bearing = 0.0;
    let mut sum = 0.0;
    for i in 0..40_000 {
        let f = 1.0 - f64::from(i) * 2.5e-5 + 1e-12 * bearing;
        bearing = kinolab_common::trig::atan2(-y0 * f, -x0 * f + 1e-3);
        sum += bearing;
    }
    sum
}

/// The playground's "many starts" view: 100 starts on the unit circle at
/// the preview step.
fn control_batch() -> f64 {
    use kinolab_control::batch::{batch, circle_starts, preview};
    use kinolab_control::{Pose, Run, TEXTBOOK_GAINS};
    let goal = Pose::default();
    let runs = Run::polar(goal, goal, TEXTBOOK_GAINS)
        .and_then(|run| batch(&preview(&run), &circle_starts(&goal, 1.0, 100, 0.0)?));
    match runs {
        Ok(runs) => runs.iter().map(|t| t.path_length).sum(),
        Err(_) => f64::NAN,
    }
}

/// Every kernel, in report order.
pub const KERNELS: &[Kernel] = &[
    Kernel {
        name: "lesson_parse",
        run: parse_lesson,
    },
    Kernel {
        name: "formula_parse_matrix",
        run: parse_formula,
    },
    Kernel {
        name: "stability_6_feet",
        run: stability,
    },
    Kernel {
        name: "leg_events_17",
        run: leg_events,
    },
    Kernel {
        name: "pick_cell_100_parts",
        run: pick_cell,
    },
    Kernel {
        name: "wheels_analyze_4",
        run: wheels_analyze,
    },
    Kernel {
        name: "wheels_build_analyze_4",
        run: wheels_build_analyze,
    },
    Kernel {
        name: "wheels_inverse_4",
        run: wheels_inverse,
    },
    Kernel {
        name: "wheels_forward_4",
        run: wheels_forward,
    },
    Kernel {
        name: "control_run_10s_1khz",
        run: control_run,
    },
    Kernel {
        name: "control_atan2_floor_40k",
        run: atan2_floor,
    },
    Kernel {
        name: "control_batch_100_starts",
        run: control_batch,
    },
    Kernel {
        name: "mech_fk_puma_tool",
        run: mechanism::fk_puma,
    },
    Kernel {
        name: "mech_fk_panda_dh_flange",
        run: mechanism::fk_panda_dh,
    },
    Kernel {
        name: "mech_fk_panda_urdf_flange",
        run: mechanism::fk_panda_urdf,
    },
    Kernel {
        name: "mech_urdf_read_50_links",
        run: mechanism::urdf_parse_50,
    },
    Kernel {
        name: "mech_fk_rover_all_frames",
        run: mechanism::fk_rover_all,
    },
    Kernel {
        name: "mech_jacobian_puma",
        run: mechanism::jacobian_puma,
    },
    Kernel {
        name: "mech_rnea_puma",
        run: mechanism::rnea_puma,
    },
    Kernel {
        name: "mech_gravity_puma",
        run: mechanism::gravity_puma,
    },
    Kernel {
        name: "mech_crba_puma",
        run: mechanism::crba_puma,
    },
    Kernel {
        name: "mech_aba_puma",
        run: mechanism::aba_puma,
    },
    Kernel {
        name: "mech_rnea_panda",
        run: mechanism::rnea_panda,
    },
    Kernel {
        name: "mech_gravity_panda",
        run: mechanism::gravity_panda,
    },
    Kernel {
        name: "mech_crba_panda",
        run: mechanism::crba_panda,
    },
    Kernel {
        name: "mech_aba_panda",
        run: mechanism::aba_panda,
    },
    Kernel {
        name: "mech_ik_puma_100_targets",
        run: mechanism::ik_puma_100,
    },
    Kernel {
        name: "mech_ik_puma_100_bent_start",
        run: mechanism::ik_puma_100_bent,
    },
    Kernel {
        name: "mech_ik_panda_100_targets",
        run: mechanism::ik_panda_100,
    },
    Kernel {
        name: "gait_cycle_100_samples",
        run: gait_cycle,
    },
    Kernel {
        name: "cpg_10s_1khz",
        run: cpg_10s,
    },
    Kernel {
        name: "field_vector_8",
        run: behaviour::field_vector,
    },
    Kernel {
        name: "field_arrows_64x64",
        run: behaviour::field_arrows,
    },
    Kernel {
        name: "field_minima_8",
        run: behaviour::field_minima,
    },
    Kernel {
        name: "world_step_16_rays_50_obstacles",
        run: behaviour::world_step,
    },
    Kernel {
        name: "hexapod_walker_frame",
        run: hexapod_frame,
    },
    Kernel {
        name: "astar_200x200",
        run: architecture::astar_200,
    },
    Kernel {
        name: "architecture_arena_frame_3_robots",
        run: architecture::arena_frame,
    },
    Kernel {
        name: "script_law_run_10s_100hz",
        run: script::law_run_script,
    },
    Kernel {
        name: "builtin_law_run_10s_100hz",
        run: script::law_run_builtin,
    },
    Kernel {
        name: "script_compile_100_lines",
        run: script::compile_100_lines,
    },
    Kernel {
        name: "script_behaviour_step_16_rays",
        run: script::behaviour_step,
    },
    Kernel {
        name: "player_scrub_back_60s_behaviour_arena",
        run: player::scrub_behaviour_arena,
    },
    Kernel {
        name: "player_scrub_back_60s_architecture_arena",
        run: player::scrub_architecture_arena,
    },
    Kernel {
        name: "player_frame_overhead",
        run: player::player_frame,
    },
    Kernel {
        name: "arena_frame_100_robots",
        run: behaviour::arena_frame,
    },
    Kernel {
        name: "components_10k_messages",
        run: components::messages_10k,
    },
    Kernel {
        name: "components_robot_system_10s",
        run: components::robot_10s,
    },
    Kernel {
        name: "component_lab_frame_20_components",
        run: components::frame_20,
    },
    Kernel {
        name: "ant_walk_size_1",
        run: design::ant_walk,
    },
    Kernel {
        name: "three_slots_matrix_24",
        run: design::slots_matrix,
    },
];

/// The reference implementation's kernels (native only).
#[cfg(all(feature = "compare-k", not(target_arch = "wasm32")))]
pub const REFERENCE_KERNELS: &[Kernel] = &[
    Kernel {
        name: "k_fk_puma_tool",
        run: reference::k_fk_puma,
    },
    Kernel {
        name: "k_ik_puma_100_targets",
        run: reference::k_ik_puma_100,
    },
];

/// Run kernel `name` `iterations` times; returns the sum of its checksums,
/// or NaN for an unknown name.
pub fn run_named(name: &str, iterations: u32) -> f64 {
    match KERNELS.iter().find(|k| k.name == name) {
        Some(kernel) => (0..iterations).map(|_| black_box((kernel.run)())).sum(),
        None => f64::NAN,
    }
}

#[cfg(target_arch = "wasm32")]
mod wasm {
    use wasm_bindgen::prelude::*;

    /// The kernel names, comma-separated.
    #[wasm_bindgen]
    pub fn kernel_names() -> String {
        super::KERNELS
            .iter()
            .map(|k| k.name)
            .collect::<Vec<_>>()
            .join(",")
    }

    /// See [`super::run_named`].
    #[wasm_bindgen]
    pub fn run_kernel(name: &str, iterations: u32) -> f64 {
        super::run_named(name, iterations)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kernels_compute_what_they_claim() {
        let close = |name: &str, want: f64, tol: f64| {
            let got = run_named(name, 1);
            assert!(
                (got - want).abs() <= tol * want.abs().max(1.0),
                "{name}: {got} vs {want}"
            );
        };
        // A 3 × 3 rotation matrix has three rows.
        close("formula_parse_matrix", 3.0, 0.0);
        // The hexagon's upper-right edge, from (0, 0.25) to (0.3, 0.2), is
        // nearest: |0.3·(0.02 − 0.25) + 0.05·0.05| / √(0.3² + 0.05²).
        close("stability_6_feet", 0.0665 / 0.0925f64.sqrt(), 1e-12);
        // (2·17 − 1)! = 33! ≈ 8.683 × 10³⁶.
        close("leg_events_17", 8.683_317_618_811_886e36, 1e-15);
        // The Ackermann car: δM = 2, DOF = 3.
        close("wheels_analyze_4", 5.0, 0.0);
        close("wheels_build_analyze_4", 2.0, 0.0);
        // The contract run ends at the goal; its path is at least the
        // straight line from (−1, 0.5), √1.25 m, and not twice that.
        let path = run_named("control_run_10s_1khz", 1);
        assert!(
            path > 1.25f64.sqrt() && path < 2.0 * 1.25f64.sqrt(),
            "{path}"
        );
        // Every foot of the walking hexapod within 1e-6 m of its target.
        for _ in 0..5 {
            let error = run_named("hexapod_walker_frame", 1);
            assert!((0.0..1e-6).contains(&error), "{error}");
        }
        // The ant winds across beach 1; 19 of the 24 slot combinations
        // reach their goal (the car fails in the maze and the office, the
        // omni with wandering in the office).
        let t = run_named("ant_walk_size_1", 1);
        assert!(t > 1.05 && t < 2.0, "{t}");
        close("three_slots_matrix_24", 19.0, 0.0);
        // The maze path winds: longer than the diagonal, as long as
        // Ten subscribers of ten publishers changing every 10 ms for 10 s:
        // about 10 000 updates, plus the subscriptions.
        let messages = run_named("components_10k_messages", 1);
        assert!((9_900.0..10_100.0).contains(&messages), "{messages}");
        // The robot waits for its rewire at 5 s: after 10 s it has left
        // its start at x = 1 but is far from the goal at x = 9.
        let x = run_named("components_robot_system_10s", 1);
        assert!(x > 1.1 && x < 8.0, "{x}");
        // The ant winds across beach 1; 19 of the 24 slot combinations
        // reach their goal (the car fails in the maze and the office, the
        // omni with wandering in the office).
        let t = run_named("ant_walk_size_1", 1);
        assert!(t > 1.05 && t < 2.0, "{t}");
        close("three_slots_matrix_24", 19.0, 0.0);
        // The maze path winds: longer than the diagonal, as long as
        // Dijkstra's.
        let astar = run_named("astar_200x200", 1);
        assert!(astar > 199.0 * 0.05 * 2f64.sqrt() + 1.0, "{astar}");
        // The arena's clock advances one 50 ms step a frame.
        let t0 = run_named("architecture_arena_frame_3_robots", 1);
        let t1 = run_named("architecture_arena_frame_3_robots", 1);
        assert!((t1 - t0 - 0.05).abs() < 1e-9 || t1 < t0, "{t0} → {t1}");
        // The scripted robot grasps a part within 1 cm of a 3 cm scatter:
        // p = (1/3)² ≈ 0.11, so about 11 of 100 (binomial σ ≈ 3.1).
        let grasped = run_named("pick_cell_100_parts", 1);
        assert!((2.0..=21.0).contains(&grasped), "{grasped}");
        for kernel in KERNELS {
            assert!((kernel.run)().is_finite(), "{}", kernel.name);
        }
        assert_eq!(run_named("formula_parse_matrix", 3), 9.0);
        assert!(run_named("nope", 1).is_nan());
    }
}
