//! Closed and open worlds: a scripted robot against a sensing one.

pub mod scripted_vs_sensing;
