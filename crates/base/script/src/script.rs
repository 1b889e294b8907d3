//! A learner's script: compiled once, its function called once per tick.

use std::cell::Cell;
use std::rc::Rc;

use rhai::{AST, CallFnOptions, Dynamic, Engine, Map, Scope};

use crate::error::{ScriptError, When};
use crate::sandbox::{Budget, LIMITS, Output, Sink, Trail, engine, locating};
use crate::value;

/// The function a hook calls, as the learner must write it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Signature {
    pub name: &'static str,
    pub params: &'static [&'static str],
}

impl Signature {
    /// `control(rho, alpha, beta)`.
    pub fn text(&self) -> String {
        format!("{}({})", self.name, self.params.join(", "))
    }
}

/// The longest script the lab compiles, in bytes.
pub const MAX_SOURCE: usize = 64 * 1024;

/// A compiled script and what it keeps between calls. Cloning it clones
/// that memory too, so a copy of a run replays exactly.
#[derive(Clone)]
pub struct Script {
    engine: Rc<Engine>,
    sink: Sink,
    /// Shared with the engine: what the call under way may use.
    budget: Rc<Budget>,
    /// Operations this script's calls have used in this run, and seconds.
    spent: Cell<u64>,
    seconds: Cell<f64>,
    /// The code, for errors that quote it.
    source: Rc<str>,
    ast: Rc<AST>,
    signature: Signature,
    /// `this` inside the learner's function: a map that starts empty and
    /// keeps whatever the function puts in it, call after call.
    memory: Dynamic,
    /// The last call's `this` and arguments, as they were before it ran:
    /// to find, if its answer is refused, the line that gave it.
    last: std::cell::RefCell<Option<Before>>,
}

/// `this` and the arguments of a call, before it.
type Before = (Dynamic, Vec<Dynamic>);

impl std::fmt::Debug for Script {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Script({})", self.signature.text())
    }
}

impl PartialEq for Script {
    /// The same code (compiled once, shared) with the same memory.
    fn eq(&self, other: &Self) -> bool {
        Rc::ptr_eq(&self.ast, &other.ast) && self.memory.to_string() == other.memory.to_string()
    }
}

/// What one call gave back: the value, and what it printed and plotted.
#[derive(Debug, Clone)]
pub struct Call {
    pub value: Dynamic,
    pub output: Output,
}

impl Script {
    /// Compile `source`, which must define `signature`'s function with its
    /// parameters. A syntax error names the line and column.
    pub fn compile(source: &str, signature: Signature) -> Result<Script, ScriptError> {
        // A byte-order mark, as some editors save files, is not code.
        let source = source.strip_prefix('\u{feff}').unwrap_or(source);
        if source.len() > MAX_SOURCE {
            return Err(ScriptError::too_long(source.len(), MAX_SOURCE));
        }
        let sink = Sink::default();
        let budget = Rc::new(Budget::default());
        let engine = engine(&sink, &budget);
        let ast = engine
            .compile(source)
            .map_err(|e| ScriptError::syntax(&e, source))?;
        let found: Vec<usize> = ast
            .iter_functions()
            .filter(|f| f.name == signature.name)
            .map(|f| f.params.len())
            .collect();
        if !found.contains(&signature.params.len()) {
            return Err(ScriptError::missing(signature, &found));
        }
        Ok(Script {
            engine: Rc::new(engine),
            sink,
            budget,
            spent: Cell::new(0),
            seconds: Cell::new(0.0),
            source: source.into(),
            ast: Rc::new(ast),
            signature,
            memory: Dynamic::from_map(Map::new()),
            last: Default::default(),
        })
    }

    pub fn signature(&self) -> Signature {
        self.signature
    }

    /// What the function keeps between calls (`this`).
    pub fn memory(&self) -> &Dynamic {
        &self.memory
    }

    /// Call the function with `args` at simulated time `t` (or a point).
    pub fn call(&mut self, args: Vec<Dynamic>, t: impl Into<When>) -> Result<Call, ScriptError> {
        let mut memory = std::mem::take(&mut self.memory);
        let call = self.call_with(&mut memory, args, t.into());
        self.memory = memory;
        call
    }

    /// Call the function as a pure one: `this` starts empty and nothing is
    /// kept (a field's value at a point must not depend on earlier points).
    pub fn call_pure(&self, args: Vec<Dynamic>, at: impl Into<When>) -> Result<Call, ScriptError> {
        self.call_with(&mut Dynamic::from_map(Map::new()), args, at.into())
    }

    fn call_with(
        &self,
        memory: &mut Dynamic,
        args: Vec<Dynamic>,
        at: When,
    ) -> Result<Call, ScriptError> {
        *self.sink.borrow_mut() = Output::default();
        let left = LIMITS.run_operations.saturating_sub(self.spent.get());
        let seconds = LIMITS.run_seconds - self.seconds.get();
        self.budget.start(left, seconds);
        let before = (memory.clone(), args.clone());
        let options = CallFnOptions::new().eval_ast(false).bind_this_ptr(memory);
        let result = self.engine.call_fn_with_options::<Dynamic>(
            options,
            &mut Scope::new(),
            &self.ast,
            self.signature.name,
            args,
        );
        let output = std::mem::take(&mut *self.sink.borrow_mut());
        self.spent.set(self.spent.get() + self.budget.used.get());
        self.seconds.set(self.seconds.get() + self.budget.elapsed());
        let value = match result {
            Ok(value) => self.kept(value, memory, at)?,
            Err(e) => {
                let error = ScriptError::run(&e, at, self.signature, &self.source);
                return Err(match error.line {
                    Some(_) => error,
                    None => error.at(self.locate(before)),
                });
            }
        };
        *self.last.borrow_mut() = Some(before);
        Ok(Call { value, output })
    }

    /// `value` and `memory` after a call, unless either nests lists or
    /// maps deeper than the sandbox allows (then both are freed a level
    /// at a time and the call fails).
    fn kept(&self, value: Dynamic, memory: &mut Dynamic, at: When) -> Result<Dynamic, ScriptError> {
        let limit = LIMITS.nesting;
        let what = if value::nesting(&value, limit) > limit {
            "answered"
        } else if value::nesting(memory, limit) > limit {
            "kept in `this`"
        } else {
            return Ok(value);
        };
        value::dispose(value);
        value::dispose(std::mem::replace(memory, Dynamic::from_map(Map::new())));
        Err(ScriptError::nested(self.signature, what, at))
    }

    /// `error`, found in the last call's answer (its shape, a NaN), placed
    /// at the line that gave the answer.
    pub fn place(&self, error: ScriptError) -> ScriptError {
        let before = self.last.borrow().clone();
        match (error.line, before) {
            (None, Some(before)) => error.at(self.locate(before)),
            _ => error,
        }
    }

    /// Where the call with `memory` and `args` ends or fails: run again,
    /// noting each step's place. Rhai reports the sandbox's stops (too
    /// many operations, too deep, too large) at the call, not at the line.
    fn locate(&self, (mut memory, args): Before) -> rhai::Position {
        let trail = Trail::default();
        let engine = locating(&Sink::default(), &trail);
        let options = CallFnOptions::new()
            .eval_ast(false)
            .bind_this_ptr(&mut memory);
        let name = self.signature.name;
        let _ = engine.call_fn_with_options::<Dynamic>(
            options,
            &mut Scope::new(),
            &self.ast,
            name,
            args,
        );
        trail.get()
    }
}
