//! What the lesson checker reports: each lesson's address, title, time,
//! objectives, quiz count and widgets. The command line and the JS API
//! print the same summaries.

use serde::Serialize;

use crate::course::{Course, Lesson};
use crate::document::Block;

/// One lesson in a few facts.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct LessonSummary {
    pub address: String,
    pub title: String,
    pub minutes: u32,
    pub objectives: Vec<String>,
    pub quizzes: usize,
    pub widgets: Vec<String>,
}

/// A unit and its lessons.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct UnitSummary {
    pub unit: String,
    pub title: String,
    pub lessons: Vec<LessonSummary>,
}

impl LessonSummary {
    pub fn of(address: String, lesson: &Lesson) -> Self {
        let mut quizzes = 0;
        let mut widgets = Vec::new();
        // A lesson whose body does not parse counts none (the checker
        // reports it).
        visit(
            lesson.blocks().unwrap_or_default(),
            &mut |block| match block {
                Block::Quiz(_) => quizzes += 1,
                Block::Widget(w) => widgets.push(w.name.clone()),
                _ => {}
            },
        );
        Self {
            address,
            title: lesson.meta.title.clone(),
            minutes: lesson.meta.minutes,
            objectives: lesson.meta.objectives.clone(),
            quizzes,
            widgets,
        }
    }
}

/// Every block, nested ones (in lists and quotes) included.
pub fn visit<'a>(blocks: &'a [Block], f: &mut impl FnMut(&'a Block)) {
    for block in blocks {
        f(block);
        match block {
            Block::List { items, .. } => items.iter().for_each(|item| visit(item, f)),
            Block::Quote(inner) => visit(inner, f),
            _ => {}
        }
    }
}

impl Course {
    /// Every unit with its lessons' summaries.
    pub fn summary(&self) -> Vec<UnitSummary> {
        self.units
            .iter()
            .map(|u| UnitSummary {
                unit: u.slug.clone(),
                title: u.title.clone(),
                lessons: u
                    .lessons
                    .iter()
                    .map(|l| LessonSummary::of(format!("{}/{}", u.slug, l.slug), l))
                    .collect(),
            })
            .collect()
    }
}
