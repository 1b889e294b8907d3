//! Oscillator networks a learner can step live: phase oscillators with any
//! coupling matrix, and Van der Pol oscillators, the classic
//! amplitude-and-phase alternative. Both settle on a gait's phase lags.
//!
//! - phase oscillators: dθᵢ/dt = 2πf + Σⱼ wᵢⱼ sin(θⱼ − θᵢ − ψᵢⱼ);
//! - Van der Pol: ẍᵢ − μ(1 − xᵢ²)ẋᵢ + (2πf)² xᵢ = Σⱼ wᵢⱼ (ẋⱼ* − ẋᵢ),
//!   where ẋⱼ* is the velocity oscillator j would have if it were shifted
//!   back by ψᵢⱼ: each pulls the others towards their places in the gait.
//!
//! ψᵢⱼ = 2π(φᵢ − φⱼ) from the lift-off phases φ; leg i lifts off when its
//! phase crosses a multiple of 2π. Steps are classic RK4.

use kinolab_common::trig;
use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;

use crate::cpg::cycle_distance;
use crate::error::FieldError;

/// Which oscillators (a CPG file's `model`: `phase` or `van_der_pol`).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Model {
    #[default]
    Phase,
    /// Van der Pol oscillators (amplitude and phase).
    VanDerPol,
}

/// A network: its frequency, target phases and couplings.
#[derive(Debug, Clone, PartialEq)]
pub struct Network {
    pub model: Model,
    /// f, Hz.
    pub frequency: f64,
    /// φᵢ, the lift-off phases to settle on.
    pub phases: Vec<f64>,
    /// wᵢⱼ ≥ 0 (the diagonal is ignored).
    pub weights: Vec<Vec<f64>>,
    /// μ of the Van der Pol oscillators (how hard they hold their amplitude).
    pub mu: f64,
}

/// The network's state: phase oscillators use `theta`; Van der Pol
/// oscillators `x` and `v` (and `theta` is read from them).
#[derive(Debug, Clone, PartialEq)]
pub struct State {
    pub t: f64,
    pub theta: Vec<f64>,
    pub x: Vec<f64>,
    pub v: Vec<f64>,
}

/// The integrator's buffers (see [`Network::step_in`]).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Scratch {
    y: Vec<f64>,
    k: [Vec<f64>; 4],
    probe: Vec<f64>,
}

/// `out` = `y` + `h` · `rate`.
fn stage(y: &[f64], rate: &[f64], h: f64, out: &mut [f64]) {
    for ((o, a), r) in out.iter_mut().zip(y).zip(rate) {
        *o = a + h * r;
    }
}

/// The most oscillators a network may have.
pub const MAX_OSCILLATORS: usize = 16;

impl Network {
    /// Check the sizes and values; errors name the field.
    pub fn check(&self) -> Result<(), FieldError> {
        let n = self.phases.len();
        if n == 0 || n > MAX_OSCILLATORS {
            return Err(FieldError::new(
                "phases",
                format!("needs 1 to {MAX_OSCILLATORS} oscillators, got {n}"),
            ));
        }
        kinolab_common::error::in_range("frequency", self.frequency, 0.0, 20.0)?;
        kinolab_common::error::in_range("mu", self.mu, 0.01, 10.0)?;
        for (i, p) in self.phases.iter().enumerate() {
            kinolab_common::error::in_range(format!("phases[{i}]"), *p, 0.0, 1.0)?;
        }
        if self.weights.len() != n || self.weights.iter().any(|row| row.len() != n) {
            return Err(FieldError::new("weights", format!("must be {n} × {n}")));
        }
        for (i, row) in self.weights.iter().enumerate() {
            for (j, w) in row.iter().enumerate() {
                kinolab_common::error::in_range(format!("weights[{i}][{j}]"), *w, 0.0, 100.0)?;
            }
        }
        Ok(())
    }

    fn omega(&self) -> f64 {
        TAU * self.frequency
    }

    fn psi(&self, i: usize, j: usize) -> f64 {
        TAU * (self.phases[i] - self.phases[j])
    }

    /// A state at `theta` (radians), on the Van der Pol limit cycle's
    /// amplitude (2) for that model.
    pub fn start(&self, theta: &[f64]) -> State {
        let w = self.omega().max(1e-9);
        State {
            t: 0.0,
            theta: theta.to_vec(),
            x: theta.iter().map(|t| 2.0 * trig::cos(*t)).collect(),
            v: theta.iter().map(|t| -2.0 * w * trig::sin(*t)).collect(),
        }
    }

    /// The derivative of the packed state `s` (θ, or x then v) into `out`.
    fn rates(&self, s: &[f64], out: &mut [f64]) {
        let n = self.phases.len();
        let w = self.omega();
        match self.model {
            Model::Phase => {
                crate::cpg::phase_rates(
                    self.frequency,
                    &self.phases,
                    |i, j| self.weights[i][j],
                    s,
                    out,
                );
            }
            Model::VanDerPol => {
                let (x, v) = s.split_at(n);
                let wn = w.max(1e-9);
                for i in 0..n {
                    let pull: f64 = (0..n)
                        .filter(|&j| j != i)
                        .map(|j| {
                            // Oscillator j's state turned back by ψᵢⱼ.
                            let (c, sn) = (trig::cos(self.psi(i, j)), trig::sin(self.psi(i, j)));
                            let q = -v[j] / wn;
                            let shifted_v = -wn * (q * c - x[j] * sn);
                            self.weights[i][j] * (shifted_v - v[i])
                        })
                        .sum();
                    out[i] = v[i];
                    out[n + i] = self.mu * (1.0 - x[i] * x[i]) * v[i] - w * w * x[i] + pull;
                }
            }
        }
    }

    /// The state packed for the integrator (θ, or x then v) into `out`.
    fn pack(&self, s: &State, out: &mut Vec<f64>) {
        out.clear();
        match self.model {
            Model::Phase => out.extend_from_slice(&s.theta),
            Model::VanDerPol => out.extend(s.x.iter().chain(&s.v)),
        }
    }

    fn unpack(&self, packed: &[f64], s: &mut State) {
        let n = self.phases.len();
        match self.model {
            Model::Phase => s.theta.copy_from_slice(packed),
            Model::VanDerPol => {
                s.x.copy_from_slice(&packed[..n]);
                s.v.copy_from_slice(&packed[n..]);
                let w = self.omega().max(1e-9);
                for i in 0..n {
                    // Unwrap the phase read from (x, −v/ω) next to the last one.
                    let read = trig::atan2(-s.v[i] / w, s.x[i]);
                    let turns = ((s.theta[i] - read) / TAU).round();
                    s.theta[i] = read + turns * TAU;
                }
            }
        }
    }

    /// One RK4 step of `h` seconds.
    pub fn step(&self, s: &mut State, h: f64) {
        self.step_in(s, h, &mut Scratch::default());
    }

    /// One RK4 step of `h` seconds, in `scratch`'s buffers (a long run
    /// allocates them once): the one integrator of every network, the
    /// CPG file's (`kinolab cpg`) and the lab's.
    pub fn step_in(&self, s: &mut State, h: f64, scratch: &mut Scratch) {
        let Scratch { y, k, probe } = scratch;
        self.pack(s, y);
        let m = y.len();
        for buffer in k.iter_mut().chain([&mut *probe]) {
            buffer.clear();
            buffer.resize(m, 0.0);
        }
        let [k1, k2, k3, k4] = k;
        self.rates(y, k1);
        stage(y, k1, h / 2.0, probe);
        self.rates(probe, k2);
        stage(y, k2, h / 2.0, probe);
        self.rates(probe, k3);
        stage(y, k3, h, probe);
        self.rates(probe, k4);
        for i in 0..m {
            probe[i] = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
        self.unpack(probe, s);
        s.t += h;
    }

    /// Turn oscillator `i`'s phase on by `by` radians (a kick): a phase
    /// oscillator's θ, or a Van der Pol oscillator's state turned about
    /// its centre (x against −ẋ/ω), its amplitude kept.
    pub fn kick(&self, s: &mut State, i: usize, by: f64) {
        if i >= s.theta.len() {
            return;
        }
        s.theta[i] += by;
        if self.model == Model::VanDerPol {
            let w = self.omega().max(1e-9);
            let (c, sn) = (trig::cos(by), trig::sin(by));
            let q = -s.v[i] / w;
            let (x, q) = (s.x[i] * c - q * sn, s.x[i] * sn + q * c);
            s.x[i] = x;
            s.v[i] = -w * q;
        }
    }

    /// Each oscillator's lag behind the first, in cycles: ((θ₀ − θᵢ)/2π) mod 1.
    pub fn lags(&self, s: &State) -> Vec<f64> {
        s.theta
            .iter()
            .map(|t| ((s.theta[0] - t) / TAU).rem_euclid(1.0))
            .collect()
    }

    /// The lags the gait asks for: (φᵢ − φ₀) mod 1.
    pub fn target_lags(&self) -> Vec<f64> {
        self.phases
            .iter()
            .map(|p| (p - self.phases[0]).rem_euclid(1.0))
            .collect()
    }

    /// The largest distance (cycles) between a lag and its target.
    pub fn lag_error(&self, s: &State) -> f64 {
        self.lags(s)
            .iter()
            .zip(self.target_lags())
            .map(|(l, t)| cycle_distance(*l, t))
            .fold(0.0, f64::max)
    }

    /// Whether leg `i` stands at state `s` for duty factor `beta`: its
    /// phase σ = θ/2π mod 1 has passed the swing part, 1 − β.
    pub fn in_stance(s: &State, i: usize, beta: f64) -> bool {
        (s.theta[i] / TAU).rem_euclid(1.0) >= 1.0 - beta
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn quadruped(gait: &str, model: Model, w: f64) -> Network {
        let g = crate::named(gait).unwrap();
        let mut weights = vec![vec![w; 4]; 4];
        for (i, row) in weights.iter_mut().enumerate() {
            row[i] = 0.0;
        }
        Network {
            model,
            frequency: 1.0,
            phases: g.legs.iter().map(|l| l.phase).collect(),
            weights,
            mu: 1.0,
        }
    }

    #[test]
    fn the_phase_network_is_the_contracts_cpg() {
        // The contract's example: crawl, weight 2, 10 s at 1 ms.
        let cpg = crate::Cpg {
            frequency: 1.0,
            legs: ["LF", "RF", "LH", "RH"].map(String::from).to_vec(),
            target_phases: vec![0.25, 0.75, 0.0, 0.5],
            weight: 2.0,
            weights: None,
            model: Default::default(),
            initial_deg: vec![0.0, 10.0, 20.0, 30.0],
            dt: 0.001,
            duration: 10.0,
            kicks: Vec::new(),
            changes: Vec::new(),
        };
        let mut net = quadruped("quadruped-crawl", Model::Phase, 2.0);
        net.phases = cpg.target_phases.clone();
        let theta: Vec<f64> = cpg.initial_deg.iter().map(|d| d.to_radians()).collect();
        let mut s = net.start(&theta);
        for _ in 0..10_000 {
            net.step(&mut s, 0.001);
        }
        let settled = cpg.run().unwrap();
        for (a, b) in s.theta.iter().zip(&settled.theta) {
            assert!((a - b).abs() < 1e-9, "{a} vs {b}");
        }
    }

    #[test]
    fn a_van_der_pol_oscillator_finds_its_limit_cycle() {
        let mut net = quadruped("quadruped-trot", Model::VanDerPol, 0.0);
        net.phases = vec![0.0];
        net.weights = vec![vec![0.0]];
        // From a small swing and from a large one, to amplitude ≈ 2.
        for x0 in [0.1, 3.0] {
            let mut s = State {
                t: 0.0,
                theta: vec![0.0],
                x: vec![x0],
                v: vec![0.0],
            };
            let mut peak: f64 = 0.0;
            for k in 0..30_000 {
                net.step(&mut s, 0.001);
                if k > 25_000 {
                    peak = peak.max(s.x[0].abs());
                }
            }
            assert!((peak - 2.0).abs() < 0.05, "from {x0}: {peak}");
        }
    }

    #[test]
    fn both_networks_lock_into_the_gait_from_scattered_starts() {
        for model in [Model::Phase, Model::VanDerPol] {
            for gait in ["quadruped-trot", "quadruped-crawl", "quadruped-bound"] {
                let net = quadruped(gait, model, 1.0);
                for seed in 0..4u64 {
                    let theta: Vec<f64> = (0..4)
                        .map(|i| TAU * kinolab_common::random::unit_hash(seed, i, 3))
                        .collect();
                    let mut s = net.start(&theta);
                    for _ in 0..15_000 {
                        net.step(&mut s, 0.002);
                    }
                    // A Van der Pol waveform is not quite a sine, so the
                    // angle read from (x, −ẋ/ω) runs a little unevenly:
                    // quarter-cycle offsets read about 0.01 off.
                    let tolerance = if model == Model::Phase { 1e-3 } else { 0.02 };
                    assert!(
                        net.lag_error(&s) < tolerance,
                        "{model:?} {gait} seed {seed}: {:?}",
                        net.lags(&s)
                    );
                }
            }
        }
    }

    #[test]
    fn bad_networks_name_the_field() {
        let mut net = quadruped("quadruped-trot", Model::Phase, 1.0);
        net.weights[1][2] = -1.0;
        assert_eq!(net.check().unwrap_err().field, "weights[1][2]");
        net.weights.pop();
        assert_eq!(net.check().unwrap_err().field, "weights");
        net.phases.clear();
        assert_eq!(net.check().unwrap_err().field, "phases");
    }
}
