//! The component lab's run on the player: the system file the settings
//! make, run a twentieth of a second per tick. A change the learner makes
//! while it runs (wire, cut, cancel) is sprung as an item of the file's
//! script at the time it was made, and the system is run again from the
//! start with it, as `kinolab components` runs the file: what the lab
//! shows at any instant is what the command prints there. (A later script
//! item leaves the past alone: the core draws each message's jitter and
//! loss by its own number.)

use std::sync::Arc;

use kinolab_components::system::{ScriptItem, System};
use kinolab_components::{Action, Runtime};

use crate::player::Simulation;

/// Ticks per second of simulated time.
const TICKS_PER_SECOND: f64 = 20.0;

/// The tick at (or nearest) `t` seconds.
pub fn tick_of(t: f64) -> usize {
    (t * TICKS_PER_SECOND).round().max(0.0) as usize
}

/// A system running: its file (with the learner's changes so far as its
/// script), the runtime, and the robot's track when it has a world.
#[derive(Debug, Clone)]
pub struct LabRun {
    pub system: Arc<System>,
    pub rt: Runtime,
    /// Ticks run.
    k: usize,
    /// The robot's position after each tick.
    pub track: Vec<[f64; 2]>,
}

impl LabRun {
    /// `system` built and run to 0 s (what is due at 0 s has happened, as
    /// with `--until 0`).
    pub fn start(system: System) -> Result<Self, String> {
        let mut rt = system.build().map_err(|e| e.to_string())?;
        rt.run_until(0.0);
        Ok(Self {
            system: Arc::new(system),
            rt,
            k: 0,
            track: Vec::new(),
        })
    }

    /// The time after `k` ticks (never past the file's `until`).
    fn time_of(&self, k: usize) -> f64 {
        (k as f64 / TICKS_PER_SECOND).min(self.system.until)
    }

    /// The system file as `kinolab components` reads it.
    pub fn file(&self) -> Result<String, String> {
        serde_json::to_string_pretty(&*self.system).map_err(|e| e.to_string())
    }
}

impl Simulation for LabRun {
    /// Nothing beyond the time: the run keeps its own track.
    type Tick = ();
    /// A change the learner makes, as the file's script writes it.
    type Event = Action;

    fn step(&mut self) -> Option<()> {
        if self.rt.now() >= self.system.until {
            return None;
        }
        self.k += 1;
        self.rt.run_until(self.time_of(self.k));
        if let Some(sim) = &self.rt.world {
            self.track.push([sim.pose.x, sim.pose.y]);
        }
        Some(())
    }

    fn time(&self) -> f64 {
        self.rt.now()
    }

    fn dt(&self) -> f64 {
        1.0 / TICKS_PER_SECOND
    }

    /// The change joins the script at this instant and the system runs
    /// again from the start to here (it stays as it was if the file can
    /// take no more changes).
    fn spring(&mut self, action: &Action) {
        let mut system = (*self.system).clone();
        system.script.push(ScriptItem {
            at: self.rt.now(),
            action: action.clone(),
        });
        let Ok(mut run) = LabRun::start(system) else {
            return;
        };
        for _ in 0..self.k {
            run.step();
        }
        *self = run;
    }
}
