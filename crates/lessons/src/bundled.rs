//! The lessons under `lessons/`, embedded when this crate is compiled, so
//! the web build needs no server to fetch them.

use crate::course::Course;
use crate::error::LessonError;

mod files {
    include!(concat!(env!("OUT_DIR"), "/bundled_lessons.rs"));
}

/// Every embedded Markdown file as `(path relative to lessons/, text)`.
pub fn markdown_files() -> &'static [(&'static str, &'static str)] {
    files::MARKDOWN
}

/// Every embedded image as `(path relative to lessons/, bytes)`.
pub fn images() -> &'static [(&'static str, &'static [u8])] {
    files::IMAGES
}

/// The course built from the embedded lessons, with every image checked.
pub fn course() -> Result<Course, LessonError> {
    let course = Course::from_files(markdown_files().iter().copied())?;
    let images: Vec<&str> = images().iter().map(|(path, _)| *path).collect();
    course.check_images(&images)?;
    Ok(course)
}

/// An embedded image's bytes, by its path relative to `lessons/`.
pub fn image(path: &str) -> Option<&'static [u8]> {
    images()
        .iter()
        .find_map(|(p, bytes)| (*p == path).then_some(*bytes))
}
