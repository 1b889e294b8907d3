//! Potential fields: the sandbox where learners paint, analyse and follow
//! them.

pub mod sandbox;
