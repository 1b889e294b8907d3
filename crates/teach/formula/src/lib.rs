//! Formulas: a small subset of TeX math, parsed into a tree the lab can
//! typeset.
//!
//! Lessons write formulas the way people already type them
//! (`v = r\dot\varphi`, `\frac{a}{b}`, `\begin{bmatrix} … \end{bmatrix}`).
//! [`parse`] turns such a string into a [`Math`] tree; with the `egui`
//! feature, [`layout`] sets it as TeX would (scripts, fractions on the math
//! axis, stretchy fences, matrices) and draws it in an egui `Ui`.
//!
//! The parser is strict: an unknown command, an unbalanced brace or a
//! missing argument is a [`MathError`] pointing at the byte where it
//! happened, so a typo in a lesson fails the lesson checker instead of
//! showing up as garbage. It never panics, and it refuses formulas nested
//! deeper than [`MAX_NESTING`].
//!
//! Written by hand: the maintained Rust TeX-math crates (`pulldown-latex`,
//! `latex2mathml`, `katex` bindings) produce MathML or HTML for a browser's
//! renderer, not geometry an egui painter can draw, and a JavaScript engine
//! would not fit the lab's size budget.

mod parse;
mod tree;

#[cfg(feature = "egui")]
pub mod layout;
pub mod speak;

pub use parse::{MathError, parse};
pub use speak::spoken;
pub use tree::{AccentKind, Delimiter, MAX_NESTING, Math, MatrixKind, OpKind, Variant};
