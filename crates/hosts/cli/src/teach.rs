//! `kinolab lessons` and `check-lesson` (the lesson checker), `widgets`
//! (what a lesson may embed), `pick-cell` (the automation unit's
//! pick-and-place cell) and `ant` (Simon's ant on the beach).

use std::path::{Path, PathBuf};

use clap::Subcommand;
use kinolab_api::teach::{self, LessonFiles};
use serde_json::Value;

use crate::Failure;
use crate::ask::ask;
use crate::input;

#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// Check lesson files (Markdown with front-matter, widgets, quizzes).
    Lessons {
        /// A lessons folder to check; the embedded lessons when omitted.
        dir: Option<PathBuf>,
    },
    /// Check one lesson file as the lesson checker would; print its summary.
    CheckLesson {
        /// A lesson's Markdown file.
        file: PathBuf,
    },
    /// Every widget a lesson can embed, with its parameters.
    Widgets,
    /// Simon's ant crossing a seeded pebble beach at a body size: its path, tortuosity and turns.
    Ant {
        /// An ant's walk file (`*.ant.json`: seed, pebbles, size).
        beach: PathBuf,
    },
    /// The pick-and-place cell: a scripted cell against one that senses each part.
    PickCell {
        /// How far parts land from their nominal place (SD), m.
        #[arg(long, allow_hyphen_values = true)]
        placement_error: f64,
        /// How far off a part the gripper still grasps it, m.
        #[arg(long, allow_hyphen_values = true)]
        gripper_tolerance: f64,
        /// The sensor's error in locating a part (SD), m.
        #[arg(long, allow_hyphen_values = true)]
        sensor_error: f64,
        /// Parts to place (at most 100000).
        #[arg(long, default_value_t = 100)]
        count: u32,
        /// Seed for the parts' positions.
        #[arg(long, default_value_t = 1)]
        seed: u32,
    },
}

pub(crate) fn run(command: Command) -> Result<Value, Failure> {
    match command {
        Command::Lessons { dir } => {
            let files = dir.as_deref().map(read_lesson_files).transpose()?;
            ask(&teach::Lessons { files }, None)
        }
        Command::CheckLesson { file } => ask(
            &teach::CheckLesson {
                file: file.display().to_string(),
                markdown: input::read(&file)?,
            },
            Some(&file),
        ),
        Command::Widgets => ask(&teach::Widgets, None),
        Command::Ant { beach } => ask(
            &teach::AntWalk {
                beach: crate::ask::source(&beach)?,
            },
            Some(&beach),
        ),
        Command::PickCell {
            placement_error,
            gripper_tolerance,
            sensor_error,
            count,
            seed,
        } => ask(
            &teach::PickCell {
                placement_error,
                gripper_tolerance,
                sensor_error,
                count,
                seed,
            },
            None,
        ),
    }
}

/// The most Markdown files `kinolab lessons` reads from a folder.
const MAX_LESSON_FILES: usize = 1000;

/// Markdown and PNG files found in unit folders under `dir`: the Markdown
/// with its text, and the images' paths, all relative to `dir`.
fn read_lesson_files(dir: &Path) -> Result<LessonFiles, Failure> {
    let mut files = LessonFiles::default();
    let read_dir = |d: &Path| {
        std::fs::read_dir(d)
            .map_err(|e| Failure(format!("{}: cannot read folder: {e}", d.display())))
    };
    for entry in read_dir(dir)?.flatten() {
        let path = entry.path();
        if !path.is_dir() {
            continue;
        }
        let folder = entry.file_name().to_string_lossy().into_owned();
        for file in read_dir(&path)?.flatten() {
            let name = file.file_name().to_string_lossy().into_owned();
            if name.ends_with(".md") {
                if files.markdown.len() >= MAX_LESSON_FILES {
                    return Err(Failure(format!(
                        "{}: more than {MAX_LESSON_FILES} lesson files",
                        dir.display()
                    )));
                }
                let text = input::read(&file.path())?;
                files.markdown.push((format!("{folder}/{name}"), text));
            } else if name.ends_with(".png") {
                files.images.push(format!("{folder}/{name}"));
            }
        }
    }
    Ok(files)
}
