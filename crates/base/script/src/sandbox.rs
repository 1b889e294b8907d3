//! The engine every script runs in: the standard pieces a learner needs
//! (numbers, strings, lists and maps), `print` and `plot`
//! kept per call, and the bounds.

use std::cell::{Cell, RefCell};
use std::rc::Rc;

use rhai::Engine;
use rhai::packages::{BasicStringPackage, CorePackage, Package};

/// What bounds every call of a learner's function.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// Operations (roughly, expressions evaluated) in one call. Work that
    /// Rhai counts as one operation but that grows with a list (looking
    /// an item up, joining lists, printing) is charged by its length.
    pub operations: u64,
    /// How deep functions may call functions.
    pub call_depth: usize,
    /// Characters in a string, items in an array, entries in a map; the
    /// items of lists and maps inside a list or map count towards it.
    pub string: usize,
    pub array: usize,
    pub map: usize,
    /// How deep lists and maps may sit inside each other in what a call
    /// answers or keeps in `this` (inside a call, `array` bounds it).
    pub nesting: usize,
    /// Lines `print` may write in one call, and `plot` values.
    pub prints: usize,
    /// Operations in all the calls of one run (a run of 2 000 calls that
    /// each stay under `operations` could otherwise take minutes).
    pub run_operations: u64,
    /// Wall-clock seconds one call may take, and all the calls of a run
    /// (see [`crate::clock`]).
    pub call_seconds: f64,
    pub run_seconds: f64,
}

/// The lab's bounds: far above what a controller or a behaviour needs,
/// far below what would freeze a tab.
pub const LIMITS: Limits = Limits {
    operations: 100_000,
    call_depth: 32,
    string: 10_000,
    array: 1_000,
    map: 500,
    nesting: 32,
    prints: 20,
    run_operations: 10_000_000,
    call_seconds: 1.0,
    run_seconds: 5.0,
};

/// What one call printed and plotted.
#[derive(Debug, Clone, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Output {
    pub prints: Vec<String>,
    pub plots: Vec<(String, f64)>,
}

/// Where the engine's `print` and `plot` put what they are given.
pub(crate) type Sink = Rc<RefCell<Output>>;

/// Why the sandbox stopped a call (the token Rhai carries back).
pub(crate) mod stop {
    /// More than [`super::Limits::operations`] in this call.
    pub const CALL_STEPS: &str = "call-steps";
    /// The run's operations are spent.
    pub const RUN_STEPS: &str = "run-steps";
    /// This call took more than [`super::Limits::call_seconds`].
    pub const CALL_TIME: &str = "call-time";
    /// The run's seconds are spent.
    pub const RUN_TIME: &str = "run-time";
}

/// What a call may still spend, and what it has spent so far.
#[derive(Debug, Default)]
pub(crate) struct Budget {
    /// Operations the run may still use.
    pub left: Cell<u64>,
    /// Operations this call has used, charges included.
    pub used: Cell<u64>,
    /// Charges for work Rhai counts as one operation.
    pub extra: Cell<u64>,
    /// When this call started (clock seconds), and the seconds the run
    /// may still use.
    pub started: Cell<Option<f64>>,
    pub seconds_left: Cell<f64>,
}

impl Budget {
    /// A budget for a call: `operations` and `seconds` left in the run.
    pub fn start(&self, operations: u64, seconds: f64) {
        self.left.set(operations);
        self.used.set(0);
        self.extra.set(0);
        self.seconds_left.set(seconds);
        self.started.set(crate::clock::now());
    }

    /// Charge `n` operations for work that grows with a value's size.
    pub fn charge(&self, n: usize) {
        self.extra.set(self.extra.get().saturating_add(n as u64));
    }

    /// Seconds since the call started (0 without a clock).
    pub fn elapsed(&self) -> f64 {
        match (self.started.get(), crate::clock::now()) {
            (Some(start), Some(now)) => (now - start).max(0.0),
            _ => 0.0,
        }
    }

    /// Rhai's progress report: whether to stop, and why.
    fn stop(&self, ops: u64) -> Option<&'static str> {
        let used = ops.saturating_add(self.extra.get());
        self.used.set(used);
        if used > LIMITS.operations {
            return Some(stop::CALL_STEPS);
        }
        if used > self.left.get() {
            return Some(stop::RUN_STEPS);
        }
        // The clock costs more than a step: look at it every 64 steps.
        if !ops.is_multiple_of(64) {
            return None;
        }
        let elapsed = self.elapsed();
        if elapsed > LIMITS.call_seconds {
            Some(stop::CALL_TIME)
        } else if elapsed > self.seconds_left.get() {
            Some(stop::RUN_TIME)
        } else {
            None
        }
    }
}

/// An engine with the lab's packages and bounds, writing to `sink` and
/// counting operations against `budget`.
pub(crate) fn engine(sink: &Sink, budget: &Rc<Budget>) -> Engine {
    let mut e = Engine::new_raw();
    CorePackage::new().register_into_engine(&mut e);
    BasicStringPackage::new().register_into_engine(&mut e);
    crate::maths::register(&mut e);
    crate::collections::register(&mut e, budget);
    // The operation count is the budget's (charges included), not Rhai's.
    e.set_max_operations(0)
        .set_max_call_levels(LIMITS.call_depth)
        .set_max_expr_depths(64, 64)
        .set_max_string_size(LIMITS.string)
        .set_max_array_size(LIMITS.array)
        .set_max_map_size(LIMITS.map)
        .set_max_variables(1_000)
        .set_max_functions(200);
    joins_text(&mut e);
    writes_containers(&mut e);
    names_missing_keys(&mut e);
    let counted = budget.clone();
    e.on_progress(move |ops| counted.stop(ops).map(rhai::Dynamic::from));
    let prints = sink.clone();
    let charged = budget.clone();
    e.on_print(move |text| {
        // Making the text was work too, and most lines are dropped: a
        // print costs 50 steps and more for long text.
        charged.charge(50 + text.len() / 16);
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
    budget.start(LIMITS.run_operations, LIMITS.call_seconds);
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

/// `print`, `${…}` and `to_string` of lists and maps, written no deeper
/// and no longer than the sandbox's bounds (Rhai's own writing follows a
/// nested list down, a call per level).
fn writes_containers(e: &mut Engine) {
    use rhai::{Array, ImmutableString as Text, Map};
    // Room for the last item and the closing brackets.
    let most = LIMITS.string - 200;
    let list = move |a: &mut Array| -> Text { crate::value::written_list(a, most).into() };
    let map = move |m: &mut Map| -> Text { crate::value::written_map(m, most).into() };
    for name in ["print", "to_string", "debug", "to_debug"] {
        e.register_fn(name, list).register_fn(name, map);
    }
}

/// Reading a key that a map the lab handed out does not have (`p.bumper`)
/// stops with what the map has; a learner's own map (`this`, a literal)
/// answers `()` for a key not set, and takes it when it is assigned.
fn names_missing_keys(e: &mut Engine) {
    e.on_map_missing_property(|map, name, _| {
        if crate::value::from_the_lab(map) {
            let encoded = format!(
                "{name}{}{}",
                crate::words::KEYS,
                crate::value::key_list(map)
            );
            return Err(
                rhai::EvalAltResult::ErrorPropertyNotFound(encoded, rhai::Position::NONE).into(),
            );
        }
        map.insert(name.into(), rhai::Dynamic::UNIT);
        match map.get_mut(name) {
            Some(value) => value.try_into(),
            None => Ok(rhai::Dynamic::UNIT.into()),
        }
    });
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
