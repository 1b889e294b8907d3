//! Graded code exercises: the list, a learner's script checked on every
//! world of one, and a class's scripts graded together.

use kinolab_exercises::{Check, Exercise, Hook};
use serde::Serialize;

use crate::{Error, Files, Operation};

/// An exercise as the list shows it.
#[derive(Debug, Clone, Serialize)]
pub struct Listed {
    pub id: &'static str,
    pub unit: &'static str,
    pub lesson: &'static str,
    pub hook: Hook,
    /// The function the learner writes, and what it answers.
    pub signature: String,
    pub returns: &'static str,
    pub title: &'static str,
    pub task: &'static str,
    pub starter: &'static str,
    pub hints: &'static [&'static str],
    /// Worlds shown while working, and worlds run only on submitting.
    pub visible: usize,
    pub held_back: usize,
}

/// `kinolab script exercises`: every graded code exercise.
#[derive(Debug, Clone, Copy)]
pub struct Exercises;

impl Operation for Exercises {
    type Report = Vec<Listed>;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        Ok(kinolab_exercises::all().iter().map(listed).collect())
    }
}

fn listed(e: &Exercise) -> Listed {
    let worlds = (e.worlds)();
    let visible = worlds.iter().filter(|w| w.visible).count();
    Listed {
        id: e.id,
        unit: e.unit,
        lesson: e.lesson,
        hook: e.hook,
        signature: e.signature.text(),
        returns: e.hook.returns(),
        title: e.title,
        task: e.task,
        starter: e.starter,
        hints: e.hints,
        visible,
        held_back: worlds.len() - visible,
    }
}

/// The exercise called `id`; an unknown id is the argument's fault.
fn exercise(id: &str) -> Result<Exercise, Error> {
    kinolab_exercises::find(id).ok_or_else(|| {
        let known: Vec<&str> = kinolab_exercises::all().iter().map(|e| e.id).collect();
        Error::argument(
            "exercise",
            format!("no exercise called `{id}` (known: {})", known.join(", ")),
        )
    })
}

/// `kinolab script check SCRIPT --exercise ID`: the script on every world
/// (or, with `held_back` false, only on those shown while working). A
/// script that does not compile or stops on an error still answers.
#[derive(Debug, Clone)]
pub struct CheckScript {
    pub exercise: String,
    pub source: String,
    pub held_back: bool,
}

impl Operation for CheckScript {
    type Report = Check;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let e = exercise(&self.exercise)?;
        Ok(e.check(&self.source, self.held_back))
    }
}

/// One learner's result in a class's grading.
#[derive(Debug, Clone, Serialize)]
pub struct Row {
    pub file: String,
    pub passed: bool,
    /// Worlds passed, of all the exercise's worlds.
    pub worlds_passed: usize,
    pub worlds: usize,
    /// The first world that failed and why, or the error that stopped it.
    pub first_failure: Option<String>,
    pub error: Option<kinolab_script::ScriptError>,
}

/// `kinolab script grade --exercise ID FILES...`: one row per script.
#[derive(Debug, Clone)]
pub struct Grade {
    pub exercise: String,
    /// Each script's name (a file's path) and text.
    pub scripts: Vec<(String, String)>,
}

/// The most scripts graded in one call.
pub const MAX_SCRIPTS: usize = 1000;

impl Operation for Grade {
    type Report = Vec<Row>;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let e = exercise(&self.exercise)?;
        if self.scripts.is_empty() || self.scripts.len() > MAX_SCRIPTS {
            return Err(Error::argument(
                "files",
                format!(
                    "give from 1 to {MAX_SCRIPTS} scripts, not {}",
                    self.scripts.len()
                ),
            ));
        }
        Ok(self
            .scripts
            .iter()
            .map(|(file, source)| row(file, &e.check(source, true)))
            .collect())
    }
}

fn row(file: &str, c: &Check) -> Row {
    let failed = c.worlds.iter().find(|w| !w.passed);
    let first_failure = match (&c.error, failed) {
        (_, Some(w)) => Some(format!("{}: {}", w.name, w.reason.as_deref().unwrap_or(""))),
        (Some(e), None) => Some(format!("does not compile: {e}")),
        (None, None) => None,
    };
    Row {
        file: file.to_owned(),
        passed: c.passed,
        worlds_passed: c.worlds.iter().filter(|w| w.passed).count(),
        worlds: c.worlds.len(),
        first_failure,
        error: c.error.clone(),
    }
}

/// The rows as CSV: `file,passed,worlds_passed,worlds,first_failure`.
pub fn csv(rows: &[Row]) -> String {
    let quote = |s: &str| format!("\"{}\"", s.replace('"', "\"\""));
    let mut out = String::from("file,passed,worlds_passed,worlds,first_failure\n");
    for r in rows {
        out.push_str(&format!(
            "{},{},{},{},{}\n",
            quote(&r.file),
            r.passed,
            r.worlds_passed,
            r.worlds,
            quote(r.first_failure.as_deref().unwrap_or(""))
        ));
    }
    out
}
