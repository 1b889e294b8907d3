//! The lab's own lessons, the files under `lessons/`. Native builds embed
//! them (the `embedded` feature: the command line, the JS package and the
//! native window need no server); the web lab leaves them out of its wasm
//! and its page hands them over, fetched beside the wasm with the course
//! already prepared (see `pack.rs`), before the lab starts ([`provide`]).

use std::sync::OnceLock;

use crate::course::Course;
use crate::error::LessonError;
use crate::pack::LessonFiles;

static PROVIDED: OnceLock<LessonFiles> = OnceLock::new();

/// Hand over the lessons the page fetched; the first call wins.
pub fn provide(files: LessonFiles) {
    let _ = PROVIDED.set(files);
}

/// The lessons: those handed over, else the embedded ones.
pub fn files() -> Option<&'static LessonFiles> {
    PROVIDED.get().or_else(embedded)
}

#[cfg(feature = "embedded")]
fn embedded() -> Option<&'static LessonFiles> {
    mod packed {
        include!(concat!(env!("OUT_DIR"), "/bundled_lessons.rs"));
    }
    static FILES: OnceLock<LessonFiles> = OnceLock::new();
    Some(FILES.get_or_init(|| LessonFiles::unpack(packed::PACKED).unwrap_or_default()))
}

#[cfg(not(feature = "embedded"))]
fn embedded() -> Option<&'static LessonFiles> {
    None
}

/// Every Markdown file as `(path relative to lessons/, text)`.
pub fn markdown_files() -> Vec<(&'static str, &'static str)> {
    files().map(LessonFiles::markdown).unwrap_or_default()
}

/// The course the lessons make, every body parsed and every image checked.
pub fn course() -> Result<Course, LessonError> {
    loaded()?.course()
}

/// The course as the lab opens it: prepared (the web lab), or read from
/// the Markdown with each lesson's body parsed when it is first shown, so
/// the first page does not wait for every lesson.
pub fn outline() -> Result<Course, LessonError> {
    loaded()?.outline()
}

fn loaded() -> Result<&'static LessonFiles, LessonError> {
    files().ok_or_else(|| LessonError::new("lessons", 0, "the lessons have not been loaded"))
}

/// An image's bytes, by its path relative to `lessons/`.
pub fn image(path: &str) -> Option<&'static [u8]> {
    files()?.image(path)
}

#[cfg(all(test, feature = "embedded"))]
mod tests {
    use super::*;

    #[test]
    fn the_packed_lessons_unpack_to_the_files_on_disk() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../lessons");
        fn count(dir: &std::path::Path) -> usize {
            let entries = std::fs::read_dir(dir).into_iter().flatten().flatten();
            entries
                .map(|e| match e.path() {
                    p if p.is_dir() => count(&p),
                    p => usize::from(p.extension().is_some_and(|x| x == "md")),
                })
                .sum()
        }
        let count = count(&root);
        assert_eq!(markdown_files().len(), count);
        for (path, text) in markdown_files() {
            let on_disk = std::fs::read_to_string(root.join(path)).unwrap_or_default();
            assert_eq!(text, on_disk, "{path}");
        }
    }

    /// The web page's pack holds the images the build embeds and, prepared,
    /// the very course the embedded Markdown makes (and no Markdown).
    #[cfg(feature = "pack")]
    #[test]
    fn the_web_pack_holds_the_course_the_embedded_markdown_makes() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../lessons");
        let web = LessonFiles::unpack(&crate::web_pack(&root).unwrap()).unwrap();
        let embedded = files().unwrap();
        assert_eq!(web.course().unwrap(), embedded.course().unwrap());
        assert_eq!(web.markdown(), []);
        fn images(files: &LessonFiles) -> Vec<(&str, Option<&[u8]>)> {
            let paths = files.image_paths();
            paths.into_iter().map(|p| (p, files.image(p))).collect()
        }
        assert_eq!(images(&web), images(embedded));
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
