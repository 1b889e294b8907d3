//! `kinolab script`: the graded code exercises, a learner's script checked
//! on every world of one, and a class's scripts graded.

use std::path::PathBuf;

use clap::Subcommand;
use kinolab_api::Operation;
use kinolab_api::script::{self, CheckScript, Exercises, Grade};

use crate::ask::{ask, failure};
use crate::{Failure, Printed, input};

#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// Every graded code exercise: its hook, the function the learner writes, its worlds.
    Exercises,
    /// A learner's script on every world of an exercise: passed or why not, per world.
    Check {
        /// The learner's script (`*.rhai`).
        script: PathBuf,
        /// The exercise's id (`kinolab script exercises` lists them).
        #[arg(long)]
        exercise: String,
    },
    /// A class's scripts graded on one exercise: one row per file.
    Grade {
        /// The exercise's id.
        #[arg(long)]
        exercise: String,
        /// The scripts, one per learner.
        #[arg(required = true)]
        files: Vec<PathBuf>,
        /// CSV instead of JSON.
        #[arg(long)]
        csv: bool,
    },
}

pub(crate) fn run(command: Command) -> Result<Printed, Failure> {
    match command {
        Command::Exercises => ask(&Exercises, None).map(Printed::Json),
        Command::Check { script, exercise } => {
            let source = input::read(&script)?;
            let check = CheckScript {
                exercise,
                source,
                held_back: true,
            };
            ask(&check, Some(&script)).map(Printed::Json)
        }
        Command::Grade {
            exercise,
            files,
            csv,
        } => {
            let scripts = files
                .iter()
                .map(|f| Ok((f.display().to_string(), input::read(f)?)))
                .collect::<Result<Vec<_>, Failure>>()?;
            let grade = Grade { exercise, scripts };
            let rows = grade
                .report(&mut kinolab_api::NoFiles)
                .map_err(|e| failure(e, None))?;
            if !csv {
                return kinolab_api::tidy(&rows)
                    .map(Printed::Json)
                    .map_err(|e| failure(e, None));
            }
            Ok(Printed::Text(script::csv(&rows)))
        }
    }
}
