//! `kinolab simulate`, `batch` and `gains`: the polar controller and
//! open-loop plans on run files (`*.run.json`, see the contract).

use std::path::PathBuf;

use clap::Subcommand;
use kinolab_api::control;
use serde_json::Value;

use crate::Failure;
use crate::args::fixed;
use crate::ask::{ask, source};

#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// Simulate a run file: the polar controller (or an open-loop plan) on a differential drive.
    Simulate {
        /// A run file (`*.run.json`, see the contract).
        run: PathBuf,
    },
    /// Simulate a run file from many starts on a circle around its goal.
    Batch {
        /// A run file; its own start is replaced by the circle's.
        run: PathBuf,
        /// Circle radius, m.
        #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
        radius: f64,
        /// Number of starts.
        #[arg(long, default_value_t = 16, allow_hyphen_values = true)]
        count: usize,
        /// Heading of every start, degrees.
        #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
        heading_deg: f64,
        /// Include each run's sampled path.
        #[arg(long)]
        paths: bool,
    },
    /// Stability of polar-controller gains: the conditions, the linearised loop, its eigenvalues.
    Gains {
        /// K_RHO,K_ALPHA,K_BETA
        #[arg(value_name = "K_RHO,K_ALPHA,K_BETA", allow_hyphen_values = true)]
        gains: String,
    },
}

pub(crate) fn run(command: Command) -> Result<Value, Failure> {
    match command {
        Command::Simulate { run } => ask(&control::Simulate { run: source(&run)? }, Some(&run)),
        Command::Batch {
            run,
            radius,
            count,
            heading_deg,
            paths,
        } => ask(
            &control::Batch {
                run: source(&run)?,
                radius,
                count,
                heading_deg,
                paths,
            },
            Some(&run),
        ),
        Command::Gains { gains } => {
            let [k_rho, k_alpha, k_beta] = fixed("gains", "K_RHO,K_ALPHA,K_BETA", &gains)?;
            ask(
                &control::ControllerStability {
                    k_rho,
                    k_alpha,
                    k_beta,
                },
                None,
            )
        }
    }
}
