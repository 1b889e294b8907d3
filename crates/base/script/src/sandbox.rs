//! The engine every script runs in: the standard pieces a learner needs
//! (numbers, strings, lists and maps), `print` and `plot`
//! kept per call, and the bounds.

use std::cell::RefCell;
use std::rc::Rc;

use rhai::Engine;
use rhai::packages::{BasicStringPackage, CorePackage, Package};

/// What bounds every call of a learner's function.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// Operations (roughly, expressions evaluated) in one call.
    pub operations: u64,
    /// How deep functions may call functions.
    pub call_depth: usize,
    /// Characters in a string, items in an array, entries in a map.
    pub string: usize,
    pub array: usize,
    pub map: usize,
    /// Lines `print` may write in one call, and `plot` values.
    pub prints: usize,
    /// Operations in all the calls of one run (a run of 2 000 calls that
    /// each stay under `operations` could otherwise take minutes).
    pub run_operations: u64,
}

/// The lab's bounds: far above what a controller or a behaviour needs,
/// far below what would freeze a tab.
pub const LIMITS: Limits = Limits {
    operations: 100_000,
    call_depth: 32,
    string: 10_000,
    array: 10_000,
    map: 1_000,
    prints: 20,
    run_operations: 10_000_000,
};

/// What one call printed and plotted.
#[derive(Debug, Clone, Default, PartialEq, serde::Serialize)]
pub struct Output {
    pub prints: Vec<String>,
    pub plots: Vec<(String, f64)>,
}

/// Where the engine's `print` and `plot` put what they are given.
pub(crate) type Sink = Rc<RefCell<Output>>;

/// The operations a call may still use before its run's budget is spent,
/// and those the call has used so far.
#[derive(Debug, Default)]
pub(crate) struct Budget {
    pub left: std::cell::Cell<u64>,
    pub used: std::cell::Cell<u64>,
}

/// An engine with the lab's packages and bounds, writing to `sink` and
/// counting operations against `budget`.
pub(crate) fn engine(sink: &Sink, budget: &Rc<Budget>) -> Engine {
    let mut e = Engine::new_raw();
    CorePackage::new().register_into_engine(&mut e);
    BasicStringPackage::new().register_into_engine(&mut e);
    crate::maths::register(&mut e);
    crate::collections::register(&mut e);
    e.set_max_operations(LIMITS.operations)
        .set_max_call_levels(LIMITS.call_depth)
        .set_max_expr_depths(64, 64)
        .set_max_string_size(LIMITS.string)
        .set_max_array_size(LIMITS.array)
        .set_max_map_size(LIMITS.map)
        .set_max_variables(1_000)
        .set_max_functions(200);
    joins_text(&mut e);
    let counted = budget.clone();
    e.on_progress(move |ops| {
        counted.used.set(ops);
        (ops > counted.left.get()).then_some(rhai::Dynamic::UNIT)
    });
    let prints = sink.clone();
    e.on_print(move |text| {
        let mut out = prints.borrow_mut();
        if out.prints.len() < LIMITS.prints {
            out.prints.push(text.chars().take(200).collect());
        }
    });
    e.on_debug(|_, _, _| {});
    let plots = sink.clone();
    e.register_fn("plot", move |name: &str, value: f64| {
        let mut out = plots.borrow_mut();
        if out.plots.len() < LIMITS.prints {
            out.plots.push((name.chars().take(40).collect(), value));
        }
    });
    let plots = sink.clone();
    e.register_fn("plot", move |name: &str, value: i64| {
        let mut out = plots.borrow_mut();
        if out.plots.len() < LIMITS.prints {
            out.plots
                .push((name.chars().take(40).collect(), value as f64));
        }
    });
    e
}

/// Where a learner's code was last: the line and column of every
/// expression and statement as it runs.
pub(crate) type Trail = Rc<std::cell::Cell<rhai::Position>>;

/// [`engine`] that notes in `trail` where the code is at each step. It
/// runs a failed call again to find where it failed, since Rhai reports
/// the sandbox's stops (too many operations, too deep, too large) at the
/// call, not at the line that caused them.
#[allow(deprecated)] // Rhai marks its debugger interface as volatile, not deprecated
pub(crate) fn locating(sink: &Sink, trail: &Trail) -> Engine {
    let budget = Rc::new(Budget::default());
    budget.left.set(LIMITS.run_operations);
    let mut e = engine(sink, &budget);
    let trail = trail.clone();
    e.register_debugger(
        |_, debugger| debugger,
        move |_, event, _, _, position| {
            let step = matches!(event, rhai::debugger::DebuggerEvent::Step);
            if step && !position.is_none() {
                trail.set(position);
            }
            Ok(rhai::debugger::DebuggerCommand::StepInto)
        },
    );
    e
}

/// `"rho " + rho` and `rho + " m"`: text joined with a number or a truth
/// value, written as the value prints, as in `print` and `${…}`.
fn joins_text(e: &mut Engine) {
    use rhai::ImmutableString as Text;
    fn join(a: impl std::fmt::Display, b: impl std::fmt::Display) -> Text {
        format!("{a}{b}").into()
    }
    let shown = |x: f64| rhai::Dynamic::from_float(x);
    e.register_fn("+", move |s: Text, x: f64| join(s, shown(x)))
        .register_fn("+", move |x: f64, s: Text| join(shown(x), s))
        .register_fn("+", |s: Text, x: i64| join(s, x))
        .register_fn("+", |x: i64, s: Text| join(x, s))
        .register_fn("+", |s: Text, x: bool| join(s, x))
        .register_fn("+", |x: bool, s: Text| join(x, s));
}
