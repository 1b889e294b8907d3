//! The lessons under `lessons/`, embedded when this crate is compiled, so
//! the web build needs no server to fetch them. The Markdown is stored
//! compressed and unpacked once, on first use.

use std::sync::OnceLock;

use crate::course::Course;
use crate::error::LessonError;

mod files {
    include!(concat!(env!("OUT_DIR"), "/bundled_lessons.rs"));
}

/// Every embedded Markdown file as `(path relative to lessons/, text)`.
pub fn markdown_files() -> &'static [(&'static str, &'static str)] {
    static FILES: OnceLock<Vec<(&'static str, &'static str)>> = OnceLock::new();
    FILES.get_or_init(|| {
        let text = unpacked();
        files::MARKDOWN
            .iter()
            .map(|&(path, start, len)| (path, text.get(start..start + len).unwrap_or("")))
            .collect()
    })
}

/// The Markdown blob, unpacked once.
fn unpacked() -> &'static str {
    static TEXT: OnceLock<String> = OnceLock::new();
    TEXT.get_or_init(|| {
        let bytes = fdeflate::decompress_to_vec_bounded(files::PACKED, files::UNPACKED_LEN)
            .unwrap_or_default();
        String::from_utf8(bytes).unwrap_or_default()
    })
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_packed_lessons_unpack_to_the_files_on_disk() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../lessons");
        assert!(!markdown_files().is_empty());
        for (path, text) in markdown_files() {
            let on_disk = std::fs::read_to_string(root.join(path)).unwrap_or_default();
            assert_eq!(*text, on_disk, "{path}");
        }
    }

    /// A lesson speaks to a learner who has only the lab: never of the
    /// sheets, notes or source documents its authors worked from.
    #[test]
    fn no_lesson_speaks_of_documents_the_learner_cannot_see() {
        const UNSEEN: [&str; 8] = [
            "reference sheet",
            "the sheet",
            "the notes",
            "lecture notes",
            "course notes",
            "seed document",
            "source document",
            "the handout",
        ];
        let mut found = Vec::new();
        for (path, text) in markdown_files() {
            let lower = text.to_lowercase();
            for (n, line) in lower.lines().enumerate() {
                for phrase in UNSEEN.iter().filter(|p| line.contains(**p)) {
                    found.push(format!("{path}:{}: \"{phrase}\"", n + 1));
                }
            }
        }
        assert!(found.is_empty(), "{}", found.join("\n"));
    }
}
