//! `kinolab leg-events`, `stability`, `gait`, `cpg`, `zmp` and `walk`:
//! legged walking and balance.

use std::path::PathBuf;

use clap::Subcommand;
use kinolab_api::legs;
use serde_json::Value;

use crate::Failure;
use crate::args::{point, points};
use crate::ask::{ask, source};

#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// Count the leg-event sequences of a walker: N = (2k − 1)!
    LegEvents {
        /// Number of legs k (1 to 17 for an exact count).
        legs: u32,
    },
    /// Judge a standing walker's static stability from above.
    Stability {
        /// Centre of mass projected on the ground, metres: X,Y
        #[arg(long, value_name = "X,Y", allow_hyphen_values = true)]
        com: String,
        /// Feet on the ground, metres: X1,Y1;X2,Y2;...
        #[arg(long, value_name = "X,Y;X,Y;...", allow_hyphen_values = true)]
        feet: String,
    },
    /// A periodic gait through its cycle: the feet in stance, their positions, the static stability margin.
    Gait {
        /// A gait file (`*.gait.json`, see the contract), or `catalogue:<id>` (`quadruped-crawl`, `hexapod-tripod`, …).
        gait: PathBuf,
        /// Samples over the cycle, at τ = (k + ½)/N.
        #[arg(long, default_value_t = 100, allow_hyphen_values = true)]
        samples: usize,
    },
    /// A push on the cart-table model: the body, its ZMP and the capture point each step, and whether the foot held it.
    Zmp {
        /// A push-recovery file (`*.zmp.json`: height, heel, toe, x0, push, duration, dt).
        run: PathBuf,
    },
    /// The lab's hexapod walking a six-legged gait by per-leg inverse kinematics: joint values through one cycle.
    Walk {
        /// A gait file with six legs, or `catalogue:<id>` (`hexapod-tripod`, `hexapod-wave`, …).
        gait: PathBuf,
        /// How high a swinging foot is lifted, m.
        #[arg(long, default_value_t = 0.03, allow_hyphen_values = true)]
        lift: f64,
        /// Instants over the cycle: τ = k/N for k = 0 … N.
        #[arg(long, default_value_t = 60, allow_hyphen_values = true)]
        samples: usize,
        /// The stride, m (the gait's own when left out).
        #[arg(long, allow_hyphen_values = true)]
        stride: Option<f64>,
        /// A learner's leg sequencer: a script file defining `foot(leg, phase)`.
        #[arg(long)]
        sequencer: Option<PathBuf>,
    },
    /// Phase oscillators, one per leg, coupled towards a gait: where they end and whether they lock.
    Cpg {
        /// A CPG file (`*.cpg.json`, see the contract).
        cpg: PathBuf,
    },
}

pub(crate) fn run(command: Command) -> Result<Value, Failure> {
    match command {
        Command::LegEvents { legs } => ask(&legs::LegEvents { legs }, None),
        Command::Stability { com, feet } => ask(
            &legs::Stability {
                com: point("com", &com)?,
                feet: points("feet", &feet)?,
            },
            None,
        ),
        Command::Gait { gait, samples } => ask(
            &legs::GaitCycle {
                gait: source(&gait)?,
                samples,
            },
            Some(&gait),
        ),
        Command::Zmp { run } => ask(&legs::Zmp { run: source(&run)? }, Some(&run)),
        Command::Walk {
            gait,
            lift,
            samples,
            stride,
            sequencer,
        } => ask(
            &legs::Walk {
                gait: source(&gait)?,
                lift,
                samples,
                stride,
                sequencer: sequencer.as_deref().map(crate::input::read).transpose()?,
            },
            Some(&gait),
        ),
        Command::Cpg { cpg } => ask(&legs::Oscillators { cpg: source(&cpg)? }, Some(&cpg)),
    }
}
