//! The wall clock that a script's deadlines are measured with.
//!
//! Operations alone do not bound a script's time: one operation may copy
//! a list of thousands of items. So every call also has a deadline in
//! seconds, checked as the script runs. Natively the clock is the
//! system's; WebAssembly has no clock of its own, so the host that runs
//! scripts in a browser installs one (`performance.now()`, say) with
//! [`install`]. Without a clock, only the operation counts bound a call.
//!
//! Deadlines are far above what any honest script needs, so the same
//! script and seed give the same result on any machine; only a script
//! that would freeze its host meets one.

use std::sync::OnceLock;

static CLOCK: OnceLock<fn() -> f64> = OnceLock::new();

/// Use `now` (seconds from any fixed origin) as the clock. The first
/// clock installed stays; later calls change nothing.
pub fn install(now: fn() -> f64) {
    let _ = CLOCK.set(now);
}

/// Seconds from a fixed origin, if there is a clock.
pub(crate) fn now() -> Option<f64> {
    match CLOCK.get() {
        Some(now) => Some(now()),
        None => system(),
    }
}

#[cfg(not(target_arch = "wasm32"))]
fn system() -> Option<f64> {
    static ORIGIN: OnceLock<std::time::Instant> = OnceLock::new();
    Some(
        ORIGIN
            .get_or_init(std::time::Instant::now)
            .elapsed()
            .as_secs_f64(),
    )
}

#[cfg(target_arch = "wasm32")]
fn system() -> Option<f64> {
    None
}
