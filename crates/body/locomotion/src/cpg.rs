//! Central pattern generators: one phase oscillator per leg, coupled so
//! that their phase differences settle on a gait's.
//!
//! dθᵢ/dt = 2πν + Σⱼ wᵢⱼ sin(θⱼ − θᵢ − ψᵢⱼ), with ψᵢⱼ = 2π(φᵢ − φⱼ) from
//! the gait's lift-off phases; integrated by classic RK4.

use kinolab_common::trig;
use std::f64::consts::TAU;

use kinolab_common::error::{finite, finite_at, in_range, non_negative, positive};
use serde::Deserialize;

use crate::error::FieldError;

/// The most oscillators, and the most integration steps, of one run.
pub const MAX_OSCILLATORS: usize = 64;
pub const MAX_STEPS: usize = 10_000_000;

/// How close (in cycles) every lag must be to its target to call the
/// network locked.
pub const LOCK_TOLERANCE: f64 = 1e-3;

/// A network of phase oscillators (the contract's CPG file): all-to-all
/// coupling of one weight.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a CPG file (an object with `frequency`, `legs` and `target_phases`)"
)]
pub struct Cpg {
    /// ν, Hz.
    pub frequency: f64,
    pub legs: Vec<String>,
    /// φᵢ, the lift-off phases the network should settle on, in [0, 1).
    pub target_phases: Vec<f64>,
    /// w: every wᵢⱼ for i ≠ j.
    pub weight: f64,
    /// θᵢ(0), degrees.
    pub initial_deg: Vec<f64>,
    /// s.
    pub dt: f64,
    /// s.
    pub duration: f64,
}

/// Where a run ended.
#[derive(Debug, Clone, PartialEq)]
pub struct Settled {
    /// θᵢ at the end, radians, not wrapped.
    pub theta: Vec<f64>,
    /// ((θ₀ − θᵢ)/2π) mod 1 for each leg.
    pub lag: Vec<f64>,
    /// Every lag within [`LOCK_TOLERANCE`] of φᵢ − φ₀ (mod 1).
    pub locked: bool,
    pub steps: usize,
}

impl Cpg {
    /// Read a CPG file; errors name the field as the file spells it.
    pub fn from_json(text: &str) -> Result<Self, FieldError> {
        let cpg: Cpg = kinolab_common::error::from_json(text)?;
        cpg.check()?;
        Ok(cpg)
    }

    /// The number of RK4 steps, after checking every value.
    pub fn check(&self) -> Result<usize, FieldError> {
        let n = self.legs.len();
        if n == 0 || n > MAX_OSCILLATORS {
            return Err(FieldError::new(
                "legs",
                format!("needs 1 to {MAX_OSCILLATORS} legs, got {n}"),
            ));
        }
        for (field, len) in [
            ("target_phases", self.target_phases.len()),
            ("initial_deg", self.initial_deg.len()),
        ] {
            if len != n {
                return Err(FieldError::new(
                    field,
                    format!("needs one value per leg ({n}), got {len}"),
                ));
            }
        }
        for (i, (&phi, &theta)) in self.target_phases.iter().zip(&self.initial_deg).enumerate() {
            if in_range(format!("target_phases[{i}]"), phi, 0.0, 1.0)? >= 1.0 {
                return Err(FieldError::new(
                    format!("target_phases[{i}]"),
                    "must be in [0, 1): 1 is the same phase as 0",
                ));
            }
            finite_at(theta, || format!("initial_deg[{i}]"))?;
        }
        finite("frequency", self.frequency)?;
        non_negative("weight", self.weight)?;
        let dt = positive("dt", self.dt)?;
        let duration = non_negative("duration", self.duration)?;
        let steps = (duration / dt - 1e-9).ceil().max(0.0);
        if steps > MAX_STEPS as f64 {
            return Err(FieldError::new(
                "dt",
                format!("duration / dt = {steps:.0} steps; at most {MAX_STEPS}"),
            ));
        }
        Ok(steps as usize)
    }

    /// dθ/dt at `theta`: every pair coupled with the one weight.
    fn rates(&self, theta: &[f64], out: &mut [f64]) {
        phase_rates(
            self.frequency,
            &self.target_phases,
            |_, _| self.weight,
            theta,
            out,
        );
    }

    /// Integrate from θ(0) to `duration` by RK4 (the last step shortened to
    /// land on it).
    pub fn run(&self) -> Result<Settled, FieldError> {
        let steps = self.check()?;
        let n = self.legs.len();
        let mut theta: Vec<f64> = self.initial_deg.iter().map(|d| d.to_radians()).collect();
        let (mut k1, mut k2, mut k3, mut k4) =
            (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        let mut probe = vec![0.0; n];
        for k in 0..steps {
            let h = (self.duration - k as f64 * self.dt).min(self.dt);
            self.rates(&theta, &mut k1);
            stage(&theta, &k1, h / 2.0, &mut probe);
            self.rates(&probe, &mut k2);
            stage(&theta, &k2, h / 2.0, &mut probe);
            self.rates(&probe, &mut k3);
            stage(&theta, &k3, h, &mut probe);
            self.rates(&probe, &mut k4);
            for i in 0..n {
                theta[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            }
        }
        let lag: Vec<f64> = theta
            .iter()
            .map(|t| ((theta[0] - t) / TAU).rem_euclid(1.0))
            .collect();
        let locked = lag.iter().zip(&self.target_phases).all(|(l, phi)| {
            let target = (phi - self.target_phases[0]).rem_euclid(1.0);
            cycle_distance(*l, target) <= LOCK_TOLERANCE
        });
        Ok(Settled {
            theta,
            lag,
            locked,
            steps,
        })
    }
}

/// The phase oscillators' law, the one place it is written:
/// dθᵢ/dt = 2πν + Σⱼ wᵢⱼ sin(θⱼ − θᵢ − ψᵢⱼ), ψᵢⱼ = 2π(φᵢ − φⱼ).
pub(crate) fn phase_rates(
    frequency: f64,
    phases: &[f64],
    weight: impl Fn(usize, usize) -> f64,
    theta: &[f64],
    out: &mut [f64],
) {
    for (i, rate) in out.iter_mut().enumerate() {
        let pull: f64 = (0..theta.len())
            .filter(|&j| j != i)
            .map(|j| {
                let psi = TAU * (phases[i] - phases[j]);
                weight(i, j) * trig::sin(theta[j] - theta[i] - psi)
            })
            .sum();
        *rate = TAU * frequency + pull;
    }
}

/// `out` = `theta` + `h` · `rate`.
fn stage(theta: &[f64], rate: &[f64], h: f64, out: &mut [f64]) {
    for ((o, t), r) in out.iter_mut().zip(theta).zip(rate) {
        *o = t + h * r;
    }
}

/// The distance between two phases on the unit circle of cycles.
pub fn cycle_distance(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(1.0);
    d.min(1.0 - d)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn example() -> Cpg {
        Cpg {
            frequency: 1.0,
            legs: ["LF", "RF", "LH", "RH"].map(String::from).to_vec(),
            target_phases: vec![0.25, 0.75, 0.0, 0.5],
            weight: 2.0,
            initial_deg: vec![0.0, 10.0, 20.0, 30.0],
            dt: 0.001,
            duration: 10.0,
        }
    }

    #[test]
    fn the_contract_example_locks_into_the_crawl() {
        let s = example().run().unwrap();
        assert!(s.locked, "{:?}", s.lag);
        for (lag, want) in s.lag.iter().zip([0.0, 0.5, 0.75, 0.25]) {
            assert!(cycle_distance(*lag, want) < 1e-6, "{lag} vs {want}");
        }
        assert_eq!(s.steps, 10_000);
    }

    #[test]
    fn uncoupled_oscillators_keep_their_start() {
        let mut cpg = example();
        cpg.weight = 0.0;
        cpg.duration = 2.25;
        let s = cpg.run().unwrap();
        for (i, theta) in s.theta.iter().enumerate() {
            let exact = (10.0 * i as f64).to_radians() + TAU * 2.25;
            assert!((theta - exact).abs() < 1e-9, "{theta} vs {exact}");
            let lag = (-(10.0 * i as f64) / 360.0).rem_euclid(1.0);
            assert!(cycle_distance(s.lag[i], lag) < 1e-9);
        }
        assert!(!s.locked);
    }

    #[test]
    fn halving_the_step_changes_almost_nothing() {
        let coarse = example().run().unwrap();
        let mut fine = example();
        fine.dt /= 2.0;
        let fine = fine.run().unwrap();
        for (a, b) in coarse.theta.iter().zip(&fine.theta) {
            assert!((a - b).abs() < 1e-9, "{a} vs {b}");
        }
    }

    #[test]
    fn bad_networks_name_the_field() {
        let mut cpg = example();
        cpg.initial_deg.pop();
        assert_eq!(cpg.check().unwrap_err().field, "initial_deg");
        let mut cpg = example();
        cpg.target_phases[1] = 1.0;
        assert_eq!(cpg.check().unwrap_err().field, "target_phases[1]");
        let mut cpg = example();
        cpg.dt = 1e-9;
        assert_eq!(cpg.check().unwrap_err().field, "dt");
        cpg.dt = 0.0;
        assert_eq!(cpg.check().unwrap_err().field, "dt");
    }
}
