//! The lab's teaching side: the lessons checked (the embedded course, a
//! folder of lesson files, or one lesson), the widgets a lesson may embed,
//! and the automation unit's pick-and-place cell.

use kinolab_lessons::summary::{LessonSummary, UnitSummary};
use kinolab_lessons::{Course, Lesson, LessonError};
use serde::Serialize;

use crate::{Error, Files, Operation};

/// Lesson files to check: each Markdown file's path (relative to the
/// lessons folder, `unit/lesson.md`) and text, and the images present.
#[derive(Debug, Clone, Default)]
pub struct LessonFiles {
    pub markdown: Vec<(String, String)>,
    pub images: Vec<String>,
}

/// `kinolab lessons`: the embedded course (`files` `None`), or lesson
/// files, checked as the lab would show them: the Markdown, every widget
/// block against the widget schema, and every image.
#[derive(Debug, Clone, Default)]
pub struct Lessons {
    pub files: Option<LessonFiles>,
}

/// Every unit with its lessons' summaries.
#[derive(Debug, Clone, Serialize)]
pub struct CourseReport {
    /// Always true: a course that fails its checks is an error instead.
    pub ok: bool,
    pub units: Vec<UnitSummary>,
}

/// A lesson's problem names its file and line itself.
fn lessons_error(e: LessonError) -> Error {
    Error::told(e.to_string())
}

impl Operation for Lessons {
    type Report = CourseReport;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let course = match &self.files {
            None => kinolab_lessons::bundled::course(),
            Some(files) => Course::from_files(
                files
                    .markdown
                    .iter()
                    .map(|(path, text)| (path.as_str(), text.as_str())),
            )
            .and_then(|course| {
                let images: Vec<&str> = files.images.iter().map(String::as_str).collect();
                course.check_images(&images)?;
                Ok(course)
            }),
        }
        .map_err(lessons_error)?;
        kinolab_schema::check_course(&course).map_err(lessons_error)?;
        Ok(CourseReport {
            ok: true,
            units: course.summary(),
        })
    }
}

/// One lesson's Markdown checked as the lesson checker would: its
/// summary, or an error naming `file` and the line.
#[derive(Debug, Clone)]
pub struct CheckLesson {
    pub file: String,
    pub markdown: String,
}

impl Operation for CheckLesson {
    type Report = LessonSummary;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let lesson = Lesson::from_markdown(&self.file, &self.markdown).map_err(lessons_error)?;
        kinolab_schema::check_lesson(&self.file, &lesson).map_err(lessons_error)?;
        Ok(LessonSummary::of(self.file.clone(), &lesson))
    }
}

/// Every widget a lesson can embed: name, summary and parameters.
#[derive(Debug, Clone, Copy)]
pub struct Widgets;

impl Operation for Widgets {
    type Report = Vec<&'static kinolab_schema::WidgetSchema>;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        Ok(kinolab_schema::widgets().collect())
    }
}

/// The pick-and-place cell: a scripted cell against one that senses each
/// part, over `count` parts placed from `seed` (lengths in metres).
#[derive(Debug, Clone, Copy)]
pub struct PickCell {
    pub placement_error: f64,
    pub gripper_tolerance: f64,
    pub sensor_error: f64,
    pub count: u32,
    pub seed: u32,
}

/// The most parts one request places.
pub const MAX_PARTS: u32 = 100_000;

impl Operation for PickCell {
    type Report = kinolab_autonomy::PickReport;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let cell = kinolab_autonomy::PickCell::new(
            self.placement_error,
            self.gripper_tolerance,
            self.sensor_error,
        )
        .map_err(|e| Error::argument(e.field, e.message))?;
        if self.count > MAX_PARTS {
            return Err(Error::argument(
                "count",
                format!("must be from 0 to {MAX_PARTS}, got {}", self.count),
            ));
        }
        Ok(cell.report(self.count as usize, u64::from(self.seed)))
    }
}

/// `kinolab ant`: Simon's ant crossing a seeded pebble beach at a body
/// size (a `*.ant.json` file): its path, tortuosity and turns.
#[derive(Debug, Clone)]
pub struct AntWalk {
    pub beach: crate::Source,
}

impl Operation for AntWalk {
    type Report = kinolab_design::ant::Walk;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let walk = self.beach.file_only(
            "beach",
            "an ant's walk file",
            kinolab_design::ant::BeachWalk::from_json,
        )?;
        walk.walk().map_err(|e| Error::input("beach", e))
    }
}
