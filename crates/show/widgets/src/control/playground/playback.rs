//! The runs a tab shows, played by the one player a sample at a time (the
//! core computes each run whole; every sample is 10 ms apart).

use std::sync::Arc;

use kinolab_control::Trajectory;

use crate::player::Simulation;

/// The runs on screen and the sample shown.
#[derive(Debug, Clone)]
pub(super) struct Shown {
    runs: Arc<Vec<Trajectory>>,
    k: usize,
}

impl Shown {
    pub fn new(runs: Vec<Trajectory>) -> Self {
        Self {
            runs: Arc::new(runs),
            k: 0,
        }
    }

    /// Samples in the longest run.
    fn len(&self) -> usize {
        self.runs.iter().map(|r| r.samples.len()).max().unwrap_or(0)
    }
}

impl Simulation for Shown {
    type Tick = ();
    type Event = ();

    fn step(&mut self) -> Option<()> {
        (self.k + 1 < self.len()).then(|| self.k += 1)
    }

    fn time(&self) -> f64 {
        self.runs
            .iter()
            .find_map(|r| r.samples.get(self.k))
            .map_or(0.0, |s| s.t)
    }

    fn dt(&self) -> f64 {
        let at = |k: usize| self.runs.iter().find_map(|r| r.samples.get(k)).map(|s| s.t);
        match (at(0), at(1)) {
            (Some(a), Some(b)) if b > a => b - a,
            _ => 0.01,
        }
    }

    fn spring(&mut self, (): &()) {}
}
