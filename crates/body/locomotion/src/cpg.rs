//! Central pattern generators: one oscillator per leg, coupled so that
//! their phase differences settle on a gait's.
//!
//! dθᵢ/dt = 2πf + Σⱼ wᵢⱼ sin(θⱼ − θᵢ − ψᵢⱼ), with ψᵢⱼ = 2π(φᵢ − φⱼ) from
//! the gait's lift-off phases; integrated by classic RK4 (the network's
//! integrator, [`Network::step_in`]). A file may also ask for Van der Pol
//! oscillators, a weight per pair, kicks (a leg's phase turned on at a
//! time) and changes of the network on the move: what the lab's CPG
//! widget does, so `kinolab cpg` reproduces its runs step for step.

use kinolab_common::trig;
use std::f64::consts::TAU;

use kinolab_common::error::{finite, finite_at, in_range, non_negative, positive};
use serde::{Deserialize, Serialize};

use crate::error::FieldError;
use crate::network::{Model, Network, Scratch, State};

/// The most oscillators, and the most integration steps, of one run.
pub const MAX_OSCILLATORS: usize = 64;
pub const MAX_STEPS: usize = 10_000_000;

/// How close (in cycles) every lag must be to its target to call the
/// network locked.
pub const LOCK_TOLERANCE: f64 = 1e-3;

/// A network of oscillators (the contract's CPG file): all-to-all
/// coupling of one weight, or a weight per pair.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a CPG file (an object with `frequency`, `legs` and `target_phases`)"
)]
pub struct Cpg {
    /// f, Hz.
    pub frequency: f64,
    pub legs: Vec<String>,
    /// φᵢ, the lift-off phases the network should settle on, in [0, 1).
    pub target_phases: Vec<f64>,
    /// w: every wᵢⱼ for i ≠ j (unless `weights` gives them one by one).
    pub weight: f64,
    /// wᵢⱼ, row i pulled by column j (the diagonal is ignored); in place
    /// of `weight` when given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub weights: Option<Vec<Vec<f64>>>,
    /// `phase` oscillators (the default) or `van_der_pol` (μ = 1, started
    /// on their limit cycle's amplitude).
    #[serde(default, skip_serializing_if = "is_phase")]
    pub model: Model,
    /// θᵢ(0), degrees.
    pub initial_deg: Vec<f64>,
    /// s.
    pub dt: f64,
    /// s.
    pub duration: f64,
    /// Legs' phases turned on while the network runs.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub kicks: Vec<Kick>,
    /// The network changed while it runs (at one instant, changes come
    /// before kicks).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub changes: Vec<Change>,
}

fn is_phase(model: &Model) -> bool {
    *model == Model::Phase
}

/// A kick: leg `leg`'s phase turned on by `by_deg` degrees at `at` seconds
/// (at the first integration step that starts there or later).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Kick {
    pub at: f64,
    pub leg: usize,
    pub by_deg: f64,
}

/// The network changed at `at` seconds: what is given replaces what the
/// network had, and the oscillators run on from where they are.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Change {
    pub at: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub frequency: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub target_phases: Option<Vec<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub weights: Option<Vec<Vec<f64>>>,
}

/// Where a run ended.
#[derive(Debug, Clone, PartialEq)]
pub struct Settled {
    /// θᵢ at the end, radians, not wrapped.
    pub theta: Vec<f64>,
    /// ((θ₀ − θᵢ)/2π) mod 1 for each leg.
    pub lag: Vec<f64>,
    /// The lags the coupling aimed at in the end: (φᵢ − φ₀) mod 1.
    pub target_lag: Vec<f64>,
    /// Every lag within [`LOCK_TOLERANCE`] of its target.
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
        check_phases("target_phases", &self.target_phases, n)?;
        if self.initial_deg.len() != n {
            return Err(count_error("initial_deg", n, self.initial_deg.len()));
        }
        for (i, &theta) in self.initial_deg.iter().enumerate() {
            finite_at(theta, || format!("initial_deg[{i}]"))?;
        }
        finite("frequency", self.frequency)?;
        non_negative("weight", self.weight)?;
        if let Some(weights) = &self.weights {
            check_weights("weights", weights, n)?;
        }
        self.check_events(n)?;
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

    /// The kicks' and the changes' values, each against `n` legs.
    fn check_events(&self, n: usize) -> Result<(), FieldError> {
        for (i, kick) in self.kicks.iter().enumerate() {
            let field = |f: &str| format!("kicks[{i}].{f}");
            non_negative(field("at"), kick.at)?;
            if kick.leg >= n {
                return Err(FieldError::new(
                    field("leg"),
                    format!("must name a leg from 0 to {}, got {}", n - 1, kick.leg),
                ));
            }
            finite(field("by_deg"), kick.by_deg)?;
        }
        for (i, change) in self.changes.iter().enumerate() {
            let field = |f: &str| format!("changes[{i}].{f}");
            non_negative(field("at"), change.at)?;
            if let Some(frequency) = change.frequency {
                finite(field("frequency"), frequency)?;
            }
            if let Some(phases) = &change.target_phases {
                check_phases(&field("target_phases"), phases, n)?;
            }
            if let Some(weights) = &change.weights {
                check_weights(&field("weights"), weights, n)?;
            }
        }
        Ok(())
    }

    /// The network the file starts with.
    pub fn network(&self) -> Network {
        let n = self.legs.len();
        let weights = self
            .weights
            .clone()
            .unwrap_or_else(|| vec![vec![self.weight; n]; n]);
        Network {
            model: self.model,
            frequency: self.frequency,
            phases: self.target_phases.clone(),
            weights,
            mu: 1.0,
        }
    }

    /// Integrate from θ(0) to `duration` by RK4 (the last step shortened to
    /// land on it), with each kick and change at the step that starts at
    /// its time (those after `duration` never come).
    pub fn run(&self) -> Result<Settled, FieldError> {
        let steps = self.check()?;
        let mut run = CpgRun::start(self);
        let step_of = |at: f64| (at / self.dt - 1e-9).ceil().max(0.0);
        let due = |at: f64, k: usize| at <= self.duration && step_of(at) <= k as f64;
        let mut changes: Vec<&Change> = self.changes.iter().collect();
        changes.sort_by(|a, b| a.at.total_cmp(&b.at));
        let mut kicks: Vec<&Kick> = self.kicks.iter().collect();
        kicks.sort_by(|a, b| a.at.total_cmp(&b.at));
        let (mut changes, mut kicks) =
            (changes.into_iter().peekable(), kicks.into_iter().peekable());
        for k in 0..=steps {
            while let Some(change) = changes.next_if(|c| due(c.at, k)) {
                run.change(change);
            }
            while let Some(kick) = kicks.next_if(|c| due(c.at, k)) {
                run.kick(kick.leg, kick.by_deg);
            }
            if k < steps {
                run.step((self.duration - k as f64 * self.dt).min(self.dt));
            }
        }
        Ok(run.settled())
    }
}

/// `count` values where `n` were needed.
fn count_error(field: &str, n: usize, count: usize) -> FieldError {
    FieldError::new(field, format!("needs one value per leg ({n}), got {count}"))
}

/// Lift-off phases: one per leg, each in [0, 1).
fn check_phases(field: &str, phases: &[f64], n: usize) -> Result<(), FieldError> {
    if phases.len() != n {
        return Err(count_error(field, n, phases.len()));
    }
    for (i, &phi) in phases.iter().enumerate() {
        if in_range(format!("{field}[{i}]"), phi, 0.0, 1.0)? >= 1.0 {
            return Err(FieldError::new(
                format!("{field}[{i}]"),
                "must be in [0, 1): 1 is the same phase as 0",
            ));
        }
    }
    Ok(())
}

/// Weights: `n` rows of `n`, none negative.
fn check_weights(field: &str, weights: &[Vec<f64>], n: usize) -> Result<(), FieldError> {
    if weights.len() != n || weights.iter().any(|row| row.len() != n) {
        return Err(FieldError::new(
            field,
            format!("must be {n} rows of {n} weights"),
        ));
    }
    for (i, row) in weights.iter().enumerate() {
        for (j, &w) in row.iter().enumerate() {
            non_negative(format!("{field}[{i}][{j}]"), w)?;
        }
    }
    Ok(())
}

/// A CPG run a step at a time: what [`Cpg::run`] does, and what the lab's
/// CPG widget plays (so both compute the same numbers).
#[derive(Debug, Clone, PartialEq)]
pub struct CpgRun {
    pub network: Network,
    pub state: State,
    steps: usize,
    dt: f64,
    scratch: Scratch,
}

impl CpgRun {
    /// The file's network at θ(0) (its kicks and changes not applied:
    /// the caller applies them as the run reaches them).
    pub fn start(cpg: &Cpg) -> Self {
        let network = cpg.network();
        let theta: Vec<f64> = cpg.initial_deg.iter().map(|d| d.to_radians()).collect();
        Self {
            state: network.start(&theta),
            network,
            steps: 0,
            dt: cpg.dt,
            scratch: Scratch::default(),
        }
    }

    /// One RK4 step of `h` seconds.
    pub fn step(&mut self, h: f64) {
        self.network.step_in(&mut self.state, h, &mut self.scratch);
        self.steps += 1;
    }

    /// `steps` whole steps of the file's `dt`.
    pub fn advance(&mut self, steps: usize) {
        for _ in 0..steps {
            self.step(self.dt);
        }
    }

    /// Steps taken.
    pub fn steps(&self) -> usize {
        self.steps
    }

    /// The time after whole steps of `dt`, s.
    pub fn time(&self) -> f64 {
        self.steps as f64 * self.dt
    }

    /// Turn leg `leg`'s phase on by `by_deg` degrees.
    pub fn kick(&mut self, leg: usize, by_deg: f64) {
        self.network.kick(&mut self.state, leg, by_deg.to_radians());
    }

    /// Change the network from now on.
    pub fn change(&mut self, change: &Change) {
        if let Some(frequency) = change.frequency {
            self.network.frequency = frequency;
        }
        if let Some(phases) = &change.target_phases {
            self.network.phases.clone_from(phases);
        }
        if let Some(weights) = &change.weights {
            self.network.weights.clone_from(weights);
        }
    }

    /// Where the run is now, as `kinolab cpg` reports it.
    pub fn settled(&self) -> Settled {
        let lag = self.network.lags(&self.state);
        let target_lag = self.network.target_lags();
        let locked = lag
            .iter()
            .zip(&target_lag)
            .all(|(l, target)| cycle_distance(*l, *target) <= LOCK_TOLERANCE);
        Settled {
            theta: self.state.theta.clone(),
            lag,
            target_lag,
            locked,
            steps: self.steps,
        }
    }
}

/// The phase oscillators' law, the one place it is written:
/// dθᵢ/dt = 2πf + Σⱼ wᵢⱼ sin(θⱼ − θᵢ − ψᵢⱼ), ψᵢⱼ = 2π(φᵢ − φⱼ).
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
            weights: None,
            model: Default::default(),
            initial_deg: vec![0.0, 10.0, 20.0, 30.0],
            dt: 0.001,
            duration: 10.0,
            kicks: Vec::new(),
            changes: Vec::new(),
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

    #[test]
    fn kicks_and_changes_bad_values_name_the_field() {
        let mut cpg = example();
        cpg.kicks = vec![Kick {
            at: 1.0,
            leg: 4,
            by_deg: 10.0,
        }];
        assert_eq!(cpg.check().unwrap_err().field, "kicks[0].leg");
        cpg.kicks[0].leg = 1;
        cpg.kicks[0].at = -1.0;
        assert_eq!(cpg.check().unwrap_err().field, "kicks[0].at");
        cpg.kicks[0].at = 1.0;
        cpg.changes = vec![Change {
            at: 2.0,
            frequency: None,
            target_phases: None,
            weights: Some(vec![vec![1.0; 3]; 4]),
        }];
        assert_eq!(cpg.check().unwrap_err().field, "changes[0].weights");
        cpg.changes[0].weights = None;
        cpg.changes[0].target_phases = Some(vec![0.0, 0.5, 0.5, 1.0]);
        assert_eq!(
            cpg.check().unwrap_err().field,
            "changes[0].target_phases[3]"
        );
        cpg.weights = Some(vec![vec![-1.0; 4]; 4]);
        assert_eq!(cpg.check().unwrap_err().field, "weights[0][0]");
    }

    /// The file's run, and the same run stepped by hand (as the lab's
    /// widget steps it), with a kick and a change on the way.
    #[test]
    fn a_run_with_kicks_and_changes_is_the_run_stepped_by_hand() {
        for model in [Model::Phase, Model::VanDerPol] {
            let dt = 1.0 / 512.0;
            let mut cpg = example();
            cpg.model = model;
            cpg.dt = dt;
            cpg.duration = 3.0;
            cpg.weights = Some(vec![vec![1.5; 4]; 4]);
            let trot = vec![0.0, 0.5, 0.5, 0.0];
            cpg.changes = vec![Change {
                at: 1.0,
                frequency: Some(1.5),
                target_phases: Some(trot.clone()),
                weights: None,
            }];
            cpg.kicks = vec![Kick {
                at: 2.0,
                leg: 2,
                by_deg: 120.0,
            }];
            let settled = cpg.run().unwrap();
            let mut run = CpgRun::start(&cpg);
            run.advance(512);
            run.change(&cpg.changes[0]);
            run.advance(512);
            run.kick(2, 120.0);
            run.advance(512);
            assert_eq!(run.settled(), settled, "{model:?}");
            assert_eq!(run.time(), 3.0);
            assert_eq!(settled.target_lag, vec![0.0, 0.5, 0.5, 0.0]);
            // The file, written and read back, runs the same.
            let text = serde_json::to_string(&cpg).unwrap();
            assert_eq!(Cpg::from_json(&text).unwrap().run().unwrap(), settled);
        }
    }

    #[test]
    fn a_kick_turns_one_phase_and_nothing_else() {
        let mut cpg = example();
        cpg.weight = 0.0;
        cpg.duration = 2.0;
        cpg.kicks = vec![Kick {
            at: 1.0,
            leg: 1,
            by_deg: 90.0,
        }];
        let s = cpg.run().unwrap();
        let expected = (10.0_f64 + 90.0).to_radians() + TAU * 2.0;
        assert!((s.theta[1] - expected).abs() < 1e-9, "{:?}", s.theta);
        assert!((s.theta[2] - (20.0_f64.to_radians() + TAU * 2.0)).abs() < 1e-9);
        // A kick after the run's end never comes.
        cpg.kicks[0].at = 2.5;
        let s = cpg.run().unwrap();
        assert!((s.theta[1] - (10.0_f64.to_radians() + TAU * 2.0)).abs() < 1e-9);
    }

    #[test]
    fn van_der_pol_kicks_keep_the_amplitude() {
        let mut cpg = example();
        cpg.model = Model::VanDerPol;
        let mut run = CpgRun::start(&cpg);
        let before = run.state.x[0].hypot(run.state.v[0] / TAU);
        run.kick(0, 75.0);
        let after = run.state.x[0].hypot(run.state.v[0] / TAU);
        assert!((before - after).abs() < 1e-12);
        assert!((run.state.theta[0] - 75.0_f64.to_radians()).abs() < 1e-12);
    }
}
