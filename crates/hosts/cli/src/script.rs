//! `kinolab script`: the graded code exercises, a learner's script checked
//! on every world of one, and a class's scripts graded.

use std::path::PathBuf;

use clap::Subcommand;
use kinolab_api::Operation;
use kinolab_api::script::{self, CheckScript, Exercises, Grade, Submission};

use crate::ask::{ask, failure};
use crate::{Failure, Printed, input};

#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// Every graded code exercise: its hook, the function the learner writes, its worlds.
    Exercises,
    /// A learner's script on every world of an exercise: the visible worlds
    /// in full, and how many held-back worlds passed.
    Check {
        /// The learner's script (`*.rhai`).
        script: PathBuf,
        /// The exercise's id (`kinolab script exercises` lists them).
        #[arg(long)]
        exercise: String,
        /// Every world in full, those held back too (for instructors).
        #[arg(long)]
        all: bool,
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
        Command::Check {
            script,
            exercise,
            all,
        } => {
            let (source, notice) = input::read_script(&script)?;
            if let Some(notice) = notice {
                crate::output::note(&notice);
            }
            let check = CheckScript {
                exercise,
                source,
                all,
            };
            ask(&check, Some(&script)).map(Printed::Json)
        }
        Command::Grade {
            exercise,
            files,
            csv,
        } => {
            let scripts = files.iter().map(|f| submission(f)).collect();
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

/// A learner's file as a row of a class's grading: a file that cannot be
/// read is a row with its reason, not the end of the whole class.
fn submission(path: &std::path::Path) -> Submission {
    let file = path.display().to_string();
    match input::read_script(path) {
        Ok((text, notice)) => Submission {
            file,
            source: Ok(text),
            notice,
        },
        Err(Failure(why)) => {
            // The reason without the file's name, which the row carries.
            let why = why
                .strip_prefix(&format!("{file}: "))
                .map_or(why.clone(), str::to_owned);
            Submission {
                file,
                source: Err(why),
                notice: None,
            }
        }
    }
}
