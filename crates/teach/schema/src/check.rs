//! The lesson checker: every widget block in a lesson must name a widget
//! of the catalogue and give it parameters its schema accepts.

use kinolab_lessons::summary::visit;
use kinolab_lessons::{Block, Course, Lesson, LessonError};

/// Check every widget block of `lesson` (from `file`).
pub fn check_lesson(file: &str, lesson: &Lesson) -> Result<(), LessonError> {
    let mut first_error = None;
    visit(lesson.blocks().map_err(Clone::clone)?, &mut |block| {
        if let Block::Widget(spec) = block
            && first_error.is_none()
            && let Err(message) = crate::validate(spec)
        {
            first_error = Some(LessonError::new(file, spec.line, message));
        }
    });
    first_error.map_or(Ok(()), Err)
}

/// Check every lesson of a course.
pub fn check_course(course: &Course) -> Result<(), LessonError> {
    for unit in &course.units {
        for lesson in &unit.lessons {
            check_lesson(&lesson.file, lesson)?;
        }
    }
    Ok(())
}
