//! The document model a lesson is parsed into: blocks of inline spans.

use serde::{Deserialize, Serialize};

use crate::math::Math;
use crate::quiz::Quiz;

/// A run of inline content: text, code, formulas, links and images.
pub type Inline = Vec<Span>;

/// How a piece of text is emphasised, and where it links to.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct TextStyle {
    pub strong: bool,
    pub emphasis: bool,
    pub strikethrough: bool,
    /// Target of the link this text belongs to, if any.
    pub link: Option<String>,
}

/// One piece of inline content.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Span {
    Text {
        text: String,
        style: TextStyle,
    },
    Code(String),
    Math(Math),
    /// An image file beside the lesson; `line` is where the lesson names it.
    Image {
        url: String,
        alt: String,
        line: usize,
    },
    LineBreak,
}

/// Column alignment in a table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Align {
    Left,
    Center,
    Right,
}

/// A live widget embedded between paragraphs: its registry name and its
/// `key: value` parameters, in file order.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct WidgetSpec {
    pub name: String,
    pub params: Vec<(String, String)>,
    /// Line of the opening fence, for error messages.
    pub line: usize,
}

impl WidgetSpec {
    /// The value of parameter `key`, if given.
    pub fn param(&self, key: &str) -> Option<&str> {
        self.params
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }
}

/// One block of a lesson.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Block {
    Heading {
        level: u8,
        text: Inline,
    },
    Paragraph(Inline),
    /// A formula on its own line.
    Math(Math),
    List {
        /// First number of an ordered list; `None` for bullets.
        start: Option<u64>,
        items: Vec<Vec<Block>>,
    },
    Quote(Vec<Block>),
    Code {
        lang: String,
        text: String,
    },
    Table {
        align: Vec<Align>,
        header: Vec<Inline>,
        rows: Vec<Vec<Inline>>,
    },
    Rule,
    Widget(WidgetSpec),
    Quiz(Quiz),
}

/// The plain text of inline content (formulas left out), for titles,
/// accessible labels and search.
pub fn plain_text(inline: &[Span]) -> String {
    let mut out = String::new();
    for span in inline {
        match span {
            Span::Text { text, .. } | Span::Code(text) => out.push_str(text),
            Span::Image { alt, .. } => out.push_str(alt),
            Span::Math(_) => out.push('…'),
            Span::LineBreak => out.push(' '),
        }
    }
    out
}
