//! Component kernels: raw message throughput of the runtime, the robot
//! system run for 10 simulated seconds, and one frame of a 20-component
//! system (a sixtieth of a second run on, then its view for the boxes).

use std::cell::RefCell;
use std::hint::black_box;

use kinolab_components::{Runtime, System};

/// `n` publishers, each with a subscriber, changing every `every` s.
fn pairs(n: usize, every: f64) -> Option<System> {
    let mut components = Vec::new();
    let mut connections = Vec::new();
    for k in 0..n {
        components.push(serde_json::json!({ "name": format!("p{k}"), "kind": "publisher", "params": { "every": [every] } }));
        components.push(serde_json::json!({ "name": format!("s{k}"), "kind": "subscriber" }));
        connections.push(
            serde_json::json!({ "port": format!("s{k}.value"), "service": format!("p{k}.value") }),
        );
    }
    let file = serde_json::json!({ "seed": 1, "until": 1.0, "latency": { "fixed": 0.001, "jitter": 0.001 }, "components": components, "connections": connections });
    System::from_json(&file.to_string()).ok()
}

/// About 10 000 updates (10 pairs × 1000 changes in 10 s) through the
/// runtime: the number of messages.
pub fn messages_10k() -> f64 {
    let Some(system) = pairs(10, 0.01) else {
        return f64::NAN;
    };
    match system.run(black_box(Some(10.0))) {
        Ok(r) => r.counts.messages as f64,
        Err(_) => f64::NAN,
    }
}

/// The robot system, 10 s of simulated time: the robot's x.
pub fn robot_10s() -> f64 {
    let Ok(system) = kinolab_components::system::example("robot") else {
        return f64::NAN;
    };
    match system.run(black_box(Some(10.0))) {
        Ok(r) => r.robot.map_or(f64::NAN, |p| p[0]),
        Err(_) => f64::NAN,
    }
}

thread_local! {
    static TWENTY: RefCell<Option<Runtime>> = const { RefCell::new(None) };
}

/// One lab frame of 20 components (10 pairs changing every 10 ms): run on
/// by 1/60 s and read the view the boxes are drawn from.
pub fn frame_20() -> f64 {
    TWENTY.with(|cell| {
        let mut slot = cell.borrow_mut();
        if slot.as_ref().is_none_or(|rt| rt.now() > 500.0) {
            *slot = pairs(10, 0.01).and_then(|s| s.build().ok());
        }
        let Some(rt) = slot.as_mut() else {
            return f64::NAN;
        };
        rt.run_until(rt.now() + 1.0 / 60.0);
        rt.view().len() as f64 + rt.trace().len() as f64
    })
}
