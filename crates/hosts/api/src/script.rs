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

/// `kinolab script check SCRIPT --exercise ID [--all]`: the script on
/// every world. A learner sees the visible worlds in full and how many of
/// the held-back worlds passed; `all` (for instructors) shows every world
/// in full. A script that does not compile or stops on an error still
/// answers.
#[derive(Debug, Clone)]
pub struct CheckScript {
    pub exercise: String,
    pub source: String,
    pub all: bool,
}

impl Operation for CheckScript {
    type Report = Check;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let e = exercise(&self.exercise)?;
        let check = e.check(&self.source, true);
        Ok(if self.all { check } else { check.for_learner() })
    }
}

/// One learner's result in a class's grading.
#[derive(Debug, Clone, Serialize)]
pub struct Row {
    pub file: String,
    pub passed: bool,
    /// Visible and held-back worlds passed, each of how many.
    pub visible: [usize; 2],
    pub held_back: [usize; 2],
    /// What stopped the code, if anything: `syntax`, `endless`, …, or
    /// `unreadable` for a file that could not be read.
    pub error_kind: Option<String>,
    /// The first world that failed and why, the error that stopped the
    /// code, or why the file could not be read.
    pub first_failure: Option<String>,
    /// Something worth knowing that did not stop grading (a file read
    /// with its bad bytes replaced).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub notice: Option<String>,
}

/// A learner's file as the host read it.
#[derive(Debug, Clone)]
pub struct Submission {
    /// The file's name, as given.
    pub file: String,
    /// Its text, or why there is none (missing, empty, not text).
    pub source: Result<String, String>,
    pub notice: Option<String>,
}

impl Submission {
    /// A file read without trouble.
    pub fn text(file: impl Into<String>, source: impl Into<String>) -> Self {
        Self {
            file: file.into(),
            source: Ok(source.into()),
            notice: None,
        }
    }
}

/// `kinolab script grade --exercise ID FILES...`: one row per script, in
/// the order given, graded on every core.
#[derive(Debug, Clone)]
pub struct Grade {
    pub exercise: String,
    pub scripts: Vec<Submission>,
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
        Ok(crate::parallel::map(&self.scripts, |s| row(&e, s)))
    }
}

/// A submission graded: every world, the rows' counts split into visible
/// and held back.
fn row(e: &Exercise, s: &Submission) -> Row {
    let worlds = (e.worlds)();
    let count = |visible: bool| worlds.iter().filter(|w| w.visible == visible).count();
    let (shown, held) = (count(true), count(false));
    let source = match &s.source {
        Ok(text) if text.trim().is_empty() => Err("the file is empty".to_owned()),
        Ok(text) => Ok(text),
        Err(why) => Err(why.clone()),
    };
    let source = match source {
        Ok(text) => text,
        Err(why) => {
            return Row {
                file: s.file.clone(),
                passed: false,
                visible: [0, shown],
                held_back: [0, held],
                error_kind: Some("unreadable".into()),
                first_failure: Some(why),
                notice: s.notice.clone(),
            };
        }
    };
    let c = e.check(source, true);
    let passed = |visible: bool| {
        c.worlds
            .iter()
            .filter(|w| w.visible == visible && w.passed)
            .count()
    };
    let failed = c.worlds.iter().find(|w| !w.passed);
    let first_failure = match (&c.error, failed) {
        (_, Some(w)) => Some(format!("{}: {}", w.name, w.reason.as_deref().unwrap_or(""))),
        (Some(e), None) => Some(format!("does not compile: {e}")),
        (None, None) => None,
    };
    let error_kind = c
        .error
        .as_ref()
        .and_then(|e| serde_json::to_value(e.kind).ok())
        .and_then(|v| v.as_str().map(str::to_owned));
    Row {
        file: s.file.clone(),
        passed: c.passed,
        visible: [passed(true), shown],
        held_back: [passed(false), held],
        error_kind,
        first_failure,
        notice: s.notice.clone(),
    }
}

/// The rows as CSV: `file,passed,visible,held_back,error_kind,first_failure`,
/// the counts written `P/N`.
pub fn csv(rows: &[Row]) -> String {
    let quote = |s: &str| format!("\"{}\"", s.replace('"', "\"\""));
    let mut out = String::from("file,passed,visible,held_back,error_kind,first_failure\n");
    for r in rows {
        out.push_str(&format!(
            "{},{},{}/{},{}/{},{},{}\n",
            quote(&r.file),
            r.passed,
            r.visible[0],
            r.visible[1],
            r.held_back[0],
            r.held_back[1],
            r.error_kind.as_deref().unwrap_or(""),
            quote(r.first_failure.as_deref().unwrap_or(""))
        ));
    }
    out
}
