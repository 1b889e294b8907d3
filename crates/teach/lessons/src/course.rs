//! Units and lessons put together into a course, with their addresses.

use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::document::{Block, Span};
use crate::error::LessonError;
use crate::front_matter::FrontMatter;

/// One lesson: its address, file and front matter, and its body.
#[derive(Debug, Clone)]
pub struct Lesson {
    /// Address part, e.g. `open-and-closed-worlds`.
    pub slug: String,
    /// The file it was read from, relative to the lessons folder.
    pub file: String,
    pub meta: FrontMatter,
    body: Body,
}

/// A lesson's body: blocks from a prepared course, or the Markdown after
/// its front matter, parsed the first time it is asked for (so a course of
/// fifty lessons opens without parsing fifty bodies; [`Course::check`]
/// parses them all).
#[derive(Debug, Clone)]
enum Body {
    Ready(Vec<Block>),
    #[cfg(feature = "markdown")]
    Markdown {
        text: String,
        first_line: usize,
        parsed: std::sync::OnceLock<Result<Vec<Block>, LessonError>>,
    },
}

impl Lesson {
    /// The lesson's blocks, or why its body does not parse.
    pub fn blocks(&self) -> Result<&[Block], &LessonError> {
        match &self.body {
            Body::Ready(blocks) => Ok(blocks),
            #[cfg(feature = "markdown")]
            Body::Markdown {
                text,
                first_line,
                parsed,
            } => parsed
                .get_or_init(|| crate::parse::parse_body(&self.file, text, *first_line))
                .as_deref(),
        }
    }
}

#[cfg(feature = "markdown")]
impl Lesson {
    /// A lesson read from its file's text: the front matter now, the body
    /// when it is first asked for.
    fn read(slug: String, file: &str, source: &str) -> Result<Self, LessonError> {
        use crate::front_matter::{Required, split};
        let (meta, text, first_line) = split(file, source, Required::Lesson)?;
        Ok(Self {
            slug,
            file: file.to_owned(),
            meta,
            body: Body::Markdown {
                text,
                first_line,
                parsed: std::sync::OnceLock::new(),
            },
        })
    }

    /// One lesson file on its own (outside a course, without an address),
    /// its body parsed and checked.
    pub fn from_markdown(file: &str, source: &str) -> Result<Self, LessonError> {
        let lesson = Self::read(String::new(), file, source)?;
        lesson.blocks().map_err(Clone::clone)?;
        Ok(lesson)
    }
}

/// Lessons are equal when they say the same: a prepared lesson equals the
/// Markdown it was prepared from.
impl PartialEq for Lesson {
    fn eq(&self, other: &Self) -> bool {
        self.slug == other.slug
            && self.file == other.file
            && self.meta == other.meta
            && self.blocks() == other.blocks()
    }
}

/// A lesson in a prepared course: its body as blocks (a body that does not
/// parse cannot be prepared).
impl Serialize for Lesson {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let blocks = self.blocks().map_err(serde::ser::Error::custom)?;
        (&self.slug, &self.file, &self.meta, blocks).serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for Lesson {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let (slug, file, meta, blocks) = Deserialize::deserialize(deserializer)?;
        Ok(Self {
            slug,
            file,
            meta,
            body: Body::Ready(blocks),
        })
    }
}

/// A unit: a titled, ordered group of lessons.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Unit {
    /// Address part, e.g. `automation`.
    pub slug: String,
    pub title: String,
    pub summary: Vec<Block>,
    pub lessons: Vec<Lesson>,
}

/// Every unit, in order.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Course {
    pub units: Vec<Unit>,
}

/// The one rule that turns a file or folder name into its part of a
/// lesson's address: `02-ways-to-move.md` → `ways-to-move`,
/// `01-automation` → `automation` (the ordering number and the extension
/// go).
pub fn address_part(name: &str) -> String {
    let stem = name.strip_suffix(".md").unwrap_or(name);
    match stem.split_once('-') {
        Some((number, rest))
            if !number.is_empty() && number.bytes().all(|b| b.is_ascii_digit()) =>
        {
            rest.to_owned()
        }
        _ => stem.to_owned(),
    }
}

/// Where an image named `url` in the lesson file `lesson_file` lives,
/// relative to the lessons folder: beside the lesson.
pub fn image_path(lesson_file: &str, url: &str) -> String {
    match lesson_file.rsplit_once('/') {
        Some((folder, _)) => format!("{folder}/{url}"),
        None => url.to_owned(),
    }
}

impl Course {
    #[cfg(feature = "markdown")]
    /// Build a course from `(path, text)` pairs, paths relative to the
    /// lessons folder (`01-automation/02-ways-to-move.md`), every lesson's
    /// body parsed and checked. Files are ordered by path; each unit folder
    /// needs a `unit.md`. Files outside a unit folder (such as the authors'
    /// README) are ignored.
    pub fn from_files<'a>(
        files: impl IntoIterator<Item = (&'a str, &'a str)>,
    ) -> Result<Course, LessonError> {
        let course = Self::outline(files)?;
        course.check()?;
        Ok(course)
    }

    /// Parse every lesson's body; the first that does not parse says why.
    pub fn check(&self) -> Result<(), LessonError> {
        for lesson in self.units.iter().flat_map(|u| &u.lessons) {
            lesson.blocks().map_err(Clone::clone)?;
        }
        Ok(())
    }

    #[cfg(feature = "markdown")]
    /// As [`Course::from_files`], with each lesson's body left to be
    /// parsed when it is first shown: what the lab does as it starts.
    pub fn outline<'a>(
        files: impl IntoIterator<Item = (&'a str, &'a str)>,
    ) -> Result<Course, LessonError> {
        let mut files: Vec<(&str, &str)> = files
            .into_iter()
            .filter(|(path, _)| path.ends_with(".md") && path.contains('/'))
            .collect();
        files.sort_by(|a, b| a.0.cmp(b.0));
        let mut course = Course::default();
        for (path, text) in files {
            let Some((folder, name)) = path.split_once('/') else {
                continue;
            };
            if name.contains('/') {
                return Err(LessonError::new(
                    path,
                    1,
                    "lessons sit directly in a unit folder, not deeper",
                ));
            }
            let unit_slug = address_part(folder);
            let unit = match course.units.iter_mut().position(|u| u.slug == unit_slug) {
                Some(i) => &mut course.units[i],
                None => {
                    course.units.push(Unit {
                        slug: unit_slug,
                        title: String::new(),
                        summary: Vec::new(),
                        lessons: Vec::new(),
                    });
                    let last = course.units.len() - 1;
                    &mut course.units[last]
                }
            };
            if name == "unit.md" {
                let (title, summary) = crate::parse::parse_unit(path, text)?;
                unit.title = title;
                unit.summary = summary;
            } else {
                let slug = address_part(name);
                if unit.lessons.iter().any(|l| l.slug == slug) {
                    return Err(LessonError::new(
                        path,
                        1,
                        format!("two lessons in this unit share the address `{slug}`"),
                    ));
                }
                unit.lessons.push(Lesson::read(slug, path, text)?);
            }
        }
        if let Some(unit) = course.units.iter().find(|u| u.title.is_empty()) {
            return Err(LessonError::new(
                &unit.slug,
                1,
                "this unit folder has no unit.md with a title",
            ));
        }
        Ok(course)
    }

    /// Check that every image a lesson shows is among `available` (paths
    /// relative to the lessons folder, like the lessons' own).
    pub fn check_images(&self, available: &[&str]) -> Result<(), LessonError> {
        for lesson in self.units.iter().flat_map(|u| &u.lessons) {
            let mut missing = None;
            let blocks = lesson.blocks().map_err(Clone::clone)?;
            crate::summary::visit(blocks, &mut |block| {
                let spans = match block {
                    Block::Paragraph(spans) | Block::Heading { text: spans, .. } => spans,
                    _ => return,
                };
                for span in spans {
                    if let Span::Image { url, line, .. } = span
                        && missing.is_none()
                        && !available.contains(&image_path(&lesson.file, url).as_str())
                    {
                        missing = Some(LessonError::new(
                            &lesson.file,
                            *line,
                            format!("there is no image `{url}` beside this lesson"),
                        ));
                    }
                }
            });
            if let Some(error) = missing {
                return Err(error);
            }
        }
        Ok(())
    }

    /// Find a lesson by its address `unit/lesson`.
    pub fn lesson(&self, address: &str) -> Option<(&Unit, &Lesson)> {
        let (unit_slug, lesson_slug) = address.trim_matches('/').split_once('/')?;
        let unit = self.units.iter().find(|u| u.slug == unit_slug)?;
        let lesson = unit.lessons.iter().find(|l| l.slug == lesson_slug)?;
        Some((unit, lesson))
    }

    /// Every lesson's address, in course order.
    pub fn addresses(&self) -> Vec<String> {
        self.units
            .iter()
            .flat_map(|u| {
                u.lessons
                    .iter()
                    .map(move |l| format!("{}/{}", u.slug, l.slug))
            })
            .collect()
    }

    /// The addresses before and after `address` in course order.
    pub fn neighbours(&self, address: &str) -> (Option<String>, Option<String>) {
        let all = self.addresses();
        match all.iter().position(|a| a == address) {
            Some(i) => (
                i.checked_sub(1).and_then(|p| all.get(p).cloned()),
                all.get(i + 1).cloned(),
            ),
            None => (None, None),
        }
    }
}
