//! Kinolab's reliability suite: does the `kinolab` command keep its
//! contract on any input?
//!
//! The contract (`shared/contracts/cli.md`, tightened by the reliability
//! issue): every call either prints one JSON document whose numbers are
//! all finite and meaningful and exits 0, or prints one escaped line on
//! stderr naming what is wrong and exits 2; it never panics, never hangs,
//! never exhausts memory, and a failed write of its answer is one line too.
//!
//! - [`seeds`]: valid inputs of every kind, from the catalogues and the
//!   contract's examples;
//! - [`mutate`]: structured damage to JSON trees, texts, bytes and numbers;
//! - [`generate`]: a case for each command from a seed number;
//! - [`run`]: the binary on a case, in a fresh folder, with a time and a
//!   memory limit;
//! - [`contract`]: the verdict on what came out;
//! - [`case`]: cases as files, for the regression folder;
//! - [`tally`]: counts per command and verdict, printed as a table;
//! - [`campaign`]: the regression folder and many generated cases on a
//!   few workers.

pub mod campaign;
pub mod case;
pub mod contract;
pub mod generate;
pub mod mutate;
pub mod run;
pub mod seeds;
pub mod tally;

pub use case::{Case, FileSpec, Sink};
pub use contract::Verdict;
