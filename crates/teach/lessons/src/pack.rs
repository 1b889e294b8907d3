//! The lesson folder as one file. Native builds embed its Markdown and
//! images (`build.rs`). The web page fetches `lessons.pack`, written by the
//! `pack-lessons` tool: the images, and in place of the Markdown the course
//! prepared (parsed and checked when the site is built, so the web lab
//! carries no Markdown parser). Inside a zlib stream, each file in turn:
//! its path under `lessons/`, a zero byte, its length as a little-endian
//! `u32`, its bytes.

use crate::course::Course;
use crate::error::LessonError;

/// The most a pack may unpack to: a damaged or hostile file cannot make
/// the lab reserve more.
const MAX_UNPACKED: usize = 64 << 20;

/// The entry of a web pack that holds the prepared course.
const PREPARED: &str = "course.postcard";

/// Every file of the lesson folder (Markdown and images) by its path.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct LessonFiles {
    files: Vec<(String, Vec<u8>)>,
}

fn damaged(message: impl Into<String>) -> LessonError {
    LessonError::new("lessons.pack", 0, message)
}

impl LessonFiles {
    /// Read a pack; a damaged one is refused with what is wrong, and every
    /// Markdown file must be UTF-8.
    pub fn unpack(packed: &[u8]) -> Result<Self, LessonError> {
        let bytes = fdeflate::decompress_to_vec_bounded(packed, MAX_UNPACKED)
            .map_err(|_| damaged("not a lesson pack (it does not inflate)"))?;
        let mut files = Vec::new();
        let mut rest = bytes.as_slice();
        // Each turn takes at least five bytes, so the loop ends.
        while !rest.is_empty() {
            let (path, body, after) = entry(rest)?;
            if path.ends_with(".md") && std::str::from_utf8(body).is_err() {
                return Err(LessonError::new(path, 0, "the file is not UTF-8 text"));
            }
            files.push((path.to_owned(), body.to_vec()));
            rest = after;
        }
        Ok(Self { files })
    }

    /// The Markdown files as `(path, text)`.
    pub fn markdown(&self) -> Vec<(&str, &str)> {
        self.files
            .iter()
            .filter(|(path, _)| path.ends_with(".md"))
            .filter_map(|(path, body)| Some((path.as_str(), std::str::from_utf8(body).ok()?)))
            .collect()
    }

    /// An image's bytes by its path under `lessons/`.
    pub fn image(&self, path: &str) -> Option<&[u8]> {
        self.files
            .iter()
            .find_map(|(p, body)| (p == path && p.ends_with(".png")).then_some(body.as_slice()))
    }

    /// Every image's path under `lessons/`.
    pub(crate) fn image_paths(&self) -> Vec<&str> {
        self.files
            .iter()
            .map(|(path, _)| path.as_str())
            .filter(|path| path.ends_with(".png"))
            .collect()
    }

    /// The course these files make, every lesson's body parsed and every
    /// image a lesson shows checked.
    pub fn course(&self) -> Result<Course, LessonError> {
        let course = self.outline()?;
        course.check()?;
        course.check_images(&self.image_paths())?;
        Ok(course)
    }

    /// The course these files make: the prepared one if the pack holds it,
    /// else read from the Markdown, each body parsed when first shown.
    pub fn outline(&self) -> Result<Course, LessonError> {
        match self.files.iter().find(|(path, _)| path == PREPARED) {
            Some((_, bytes)) => Course::from_prepared(bytes),
            None => self.read_markdown(),
        }
    }

    #[cfg(feature = "markdown")]
    fn read_markdown(&self) -> Result<Course, LessonError> {
        Course::outline(self.markdown())
    }

    #[cfg(not(feature = "markdown"))]
    fn read_markdown(&self) -> Result<Course, LessonError> {
        Err(damaged("it holds no prepared course"))
    }
}

impl Course {
    /// The course as a prepared course: every lesson parsed (the first that
    /// does not parse is the error) and written compactly.
    pub fn prepare(&self) -> Result<Vec<u8>, LessonError> {
        self.check()?;
        postcard::to_allocvec(self).map_err(|e| damaged(format!("cannot prepare the course: {e}")))
    }

    /// A prepared course read back. It comes from the lab's own build,
    /// beside its wasm; anything else is refused as damaged.
    pub fn from_prepared(bytes: &[u8]) -> Result<Self, LessonError> {
        postcard::from_bytes(bytes).map_err(|_| damaged("its prepared course is damaged"))
    }
}

/// The web lab's pack, from the lesson folder at `root`: the images, and
/// the course prepared from the Markdown (checked first: a lesson that does
/// not parse, or shows an image that is not there, is the error).
#[cfg(feature = "pack")]
pub fn web_pack(root: &std::path::Path) -> Result<Vec<u8>, LessonError> {
    let mut files = LessonFiles::default();
    for (relative, path) in crate::folder::lesson_files(root) {
        let body = std::fs::read(&path)
            .map_err(|e| LessonError::new(&relative, 0, format!("cannot read it: {e}")))?;
        files.files.push((relative, body));
    }
    let prepared = files.course()?.prepare()?;
    let images = files.image_paths();
    let entries = images
        .iter()
        .filter_map(|path| Some((*path, files.image(path)?)))
        .chain([(PREPARED, prepared.as_slice())]);
    crate::folder::pack(entries).ok_or_else(|| damaged("a file is larger than 4 GiB"))
}

/// One file at the start of `bytes`: its path, its body and what follows.
fn entry(bytes: &[u8]) -> Result<(&str, &[u8], &[u8]), LessonError> {
    let nul = bytes
        .iter()
        .position(|&b| b == 0)
        .ok_or_else(|| damaged("a file's path has no end"))?;
    let path = std::str::from_utf8(&bytes[..nul]).map_err(|_| damaged("a path is not UTF-8"))?;
    let length = bytes
        .get(nul + 1..nul + 5)
        .and_then(|b| <[u8; 4]>::try_from(b).ok())
        .map(u32::from_le_bytes)
        .ok_or_else(|| LessonError::new(path, 0, "the pack ends inside the file's length"))?;
    let start = nul + 5;
    let end = start.saturating_add(length as usize);
    let body = bytes
        .get(start..end)
        .ok_or_else(|| LessonError::new(path, 0, "the pack ends inside the file"))?;
    Ok((path, body, &bytes[end..]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Block;

    /// The format, written the way `build.rs` and `web/pack-lessons.mjs` do.
    fn pack(files: &[(&str, &[u8])]) -> Vec<u8> {
        let mut raw = Vec::new();
        for (path, body) in files {
            raw.extend_from_slice(path.as_bytes());
            raw.push(0);
            raw.extend_from_slice(&(body.len() as u32).to_le_bytes());
            raw.extend_from_slice(body);
        }
        miniz_oxide::deflate::compress_to_vec_zlib(&raw, 6)
    }

    #[test]
    fn a_pack_gives_back_its_files() {
        let files = LessonFiles::unpack(&pack(&[
            ("01-a/unit.md", b"text one"),
            ("01-a/map.png", &[137, 80, 78, 71, 0, 1]),
            ("01-a/02-b.md", "δ, ω".as_bytes()),
        ]))
        .unwrap();
        assert_eq!(
            files.markdown(),
            [("01-a/unit.md", "text one"), ("01-a/02-b.md", "δ, ω")]
        );
        assert_eq!(
            files.image("01-a/map.png"),
            Some(&[137, 80, 78, 71, 0, 1][..])
        );
        assert_eq!(files.image("01-a/unit.md"), None);
        assert_eq!(LessonFiles::unpack(&pack(&[])).unwrap().markdown(), []);
    }

    #[test]
    fn a_damaged_pack_is_refused_with_what_is_wrong() {
        let good = pack(&[("01-a/unit.md", b"some text")]);
        let raw = fdeflate::decompress_to_vec(&good).unwrap();
        let cases: [(Vec<u8>, &str); 5] = [
            (b"not zlib".to_vec(), "does not inflate"),
            (
                miniz_oxide::deflate::compress_to_vec_zlib(b"no end", 6),
                "path has no end",
            ),
            (
                miniz_oxide::deflate::compress_to_vec_zlib(&raw[..15], 6),
                "inside the file's length",
            ),
            (
                miniz_oxide::deflate::compress_to_vec_zlib(&raw[..raw.len() - 1], 6),
                "inside the file",
            ),
            (pack(&[("01-a/x.md", &[0xff, 0xfe])]), "not UTF-8"),
        ];
        for (bytes, why) in cases {
            let e = LessonFiles::unpack(&bytes).unwrap_err();
            assert!(e.to_string().contains(why), "{e} should say {why:?}");
        }
    }

    const HEADER: &str = "---\ntitle: A lesson\nminutes: 5\nobjectives:\n  - Read it\n---\n";

    /// A lesson with most of what a body holds: a heading, emphasis, a
    /// formula, a list, a table, a widget, a quiz and an image.
    fn rich_lesson() -> String {
        format!(
            "{HEADER}## Wheels\n\nA *steered* wheel, $v = r\\omega$.\n\n$$\\dot x = \\frac{{r}}{{2}}$$\n\n\
             1. one\n2. two\n\n| a | b |\n|:--|--:|\n| 1 | 2 |\n\n![a map](map.png)\n\n\
             ```widget\nicr-explorer\nwheels: 2\n```\n\n\
             ```quiz\nkind: single\nquestion: Which?\n- [x] This\n- [ ] That\nexplain: Because.\n```\n"
        )
    }

    #[test]
    fn a_prepared_course_reads_back_as_the_markdown_it_came_from() {
        let lesson = rich_lesson();
        let files = [
            (
                "01-a/unit.md",
                "---\ntitle: Unit A\n---\nWhat the unit is about.\n",
            ),
            ("01-a/01-first.md", lesson.as_str()),
        ];
        let course = Course::from_files(files).unwrap();
        let prepared = Course::from_prepared(&course.prepare().unwrap()).unwrap();
        assert_eq!(prepared, course);
        let blocks = prepared.units[0].lessons[0].blocks().unwrap();
        assert!(
            blocks.iter().any(|b| matches!(b, Block::Quiz(_))),
            "{blocks:?}"
        );
        assert!(
            blocks.iter().any(|b| matches!(b, Block::Math(_))),
            "{blocks:?}"
        );
        assert_eq!(
            blocks.len(),
            course.units[0].lessons[0].blocks().unwrap().len()
        );
    }

    #[test]
    fn a_course_with_a_broken_lesson_is_not_prepared_and_damage_is_refused() {
        let broken = format!("{HEADER}```quiz\nkind: single\n```\n");
        let files = [
            ("01-a/unit.md", "---\ntitle: Unit A\n---\n"),
            ("01-a/01-broken.md", broken.as_str()),
        ];
        let e = Course::outline(files).unwrap().prepare().unwrap_err();
        assert!(e.to_string().starts_with("01-a/01-broken.md:"), "{e}");
        let good = [
            ("01-a/unit.md", "---\ntitle: Unit A\n---\n"),
            ("01-a/01-first.md", HEADER),
        ];
        let bytes = Course::from_files(good).unwrap().prepare().unwrap();
        for cut in [0, 1, bytes.len() / 2, bytes.len() - 1] {
            let e = Course::from_prepared(&bytes[..cut]).unwrap_err();
            assert!(e.to_string().contains("damaged"), "{e}");
        }
    }

    #[test]
    fn the_web_pack_holds_the_images_and_the_prepared_course_but_no_markdown() {
        let root = std::env::temp_dir().join(format!("kinolab-web-pack-{}", std::process::id()));
        let unit = root.join("01-a");
        std::fs::create_dir_all(&unit).unwrap();
        std::fs::write(unit.join("unit.md"), "---\ntitle: Unit A\n---\n").unwrap();
        std::fs::write(unit.join("01-first.md"), rich_lesson()).unwrap();
        let png = [137, 80, 78, 71, 13, 10, 26, 10];
        std::fs::write(unit.join("map.png"), png).unwrap();
        let web = LessonFiles::unpack(&crate::web_pack(&root).unwrap()).unwrap();
        assert_eq!(web.markdown(), []);
        assert_eq!(web.image("01-a/map.png"), Some(&png[..]));
        let lesson = rich_lesson();
        let files = [
            ("01-a/unit.md", "---\ntitle: Unit A\n---\n"),
            ("01-a/01-first.md", lesson.as_str()),
        ];
        assert_eq!(web.course().unwrap(), Course::from_files(files).unwrap());
        // A lesson that shows an image the folder lacks stops the pack.
        std::fs::remove_file(unit.join("map.png")).unwrap();
        let e = crate::web_pack(&root).unwrap_err();
        let _ = std::fs::remove_dir_all(&root);
        assert!(e.to_string().contains("no image `map.png`"), "{e}");
    }
}
