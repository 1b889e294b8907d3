//! The language learners write the robot's code in.
//!
//! A learner's code is [Rhai](https://rhai.rs): small, typed at run time,
//! with the syntax of Rust and JavaScript's friendlier habits. The lab runs
//! it in a [`Sandbox`]: no input or output, no imports, nothing of the page
//! or the machine; every call is bounded (operations, call depth, the size
//! of strings, arrays and maps), so a loop that never ends or a string that
//! doubles stops that call with a [`ScriptError`] that says, in a learner's
//! words, what went wrong, where (line and column), when (the simulated
//! time) and what to look at. A [`Script`] is compiled once and called once
//! per tick; `print(…)` and `plot("name", value)` are kept per call
//! ([`Output`]), so a stepper can show what the code saw, returned and
//! printed at any instant.
//!
//! The simulations call their hooks through this crate: the controller's
//! law, a behaviour or a coordinator, a potential-field primitive, the
//! hybrid robot's sequencer, the hexapod's leg sequencer.

pub mod clock;
mod collections;
mod error;
mod maths;
mod sandbox;
mod script;
pub mod value;
mod words;

pub use error::{ErrorKind, ScriptError, When};
pub use rhai::{Array, Dynamic, Map};
pub use sandbox::{LIMITS, Limits, Output};
pub use script::{Call, MAX_SOURCE, Script, Signature};
