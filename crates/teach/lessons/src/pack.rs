//! The lesson folder as one file. The web page fetches it (`lessons.pack`,
//! written by `web/pack-lessons.mjs`); native builds embed the same format
//! (`build.rs`). Inside a zlib stream, each file in turn: its path under
//! `lessons/`, a zero byte, its length as a little-endian `u32`, its bytes.

use crate::course::Course;
use crate::error::LessonError;

/// The most a pack may unpack to: a damaged or hostile file cannot make
/// the lab reserve more.
const MAX_UNPACKED: usize = 64 << 20;

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

    /// The course these files make, with every image a lesson shows checked.
    pub fn course(&self) -> Result<Course, LessonError> {
        let course = Course::from_files(self.markdown())?;
        let images: Vec<&str> = self
            .files
            .iter()
            .map(|(path, _)| path.as_str())
            .filter(|path| path.ends_with(".png"))
            .collect();
        course.check_images(&images)?;
        Ok(course)
    }

    /// The course these files make, each body parsed when first shown.
    pub fn outline(&self) -> Result<Course, LessonError> {
        Course::outline(self.markdown())
    }
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
}
