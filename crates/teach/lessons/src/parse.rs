//! Markdown (through pulldown-cmark) to the lesson document model.

use std::ops::Range;

use pulldown_cmark::{
    Alignment, CodeBlockKind, CowStr, Event, HeadingLevel, Options, Parser as Markdown, Tag, TagEnd,
};

use crate::document::{Align, Block, Inline, Span, TextStyle, WidgetSpec};
use crate::error::LessonError;
use crate::front_matter::{self, FrontMatter, Required};
use crate::math;
use crate::quiz::{self, Quiz, QuizKind};

/// Parse a whole lesson file: front-matter, then body.
pub fn parse_lesson(file: &str, source: &str) -> Result<(FrontMatter, Vec<Block>), LessonError> {
    let (fm, body, first_line) = front_matter::split(file, source, Required::Lesson)?;
    let blocks = parse_body(file, &body, first_line)?;
    Ok((fm, blocks))
}

/// Parse a unit's `unit.md`: a title and a summary.
pub(crate) fn parse_unit(file: &str, source: &str) -> Result<(String, Vec<Block>), LessonError> {
    let (fm, body, first_line) = front_matter::split(file, source, Required::Unit)?;
    Ok((fm.title, parse_body(file, &body, first_line)?))
}

/// Parse one line of inline Markdown (a quiz question or option).
pub fn parse_inline(file: &str, line: usize, text: &str) -> Result<Inline, LessonError> {
    let blocks = parse_body(file, text, line)?;
    match blocks.into_iter().next() {
        None => Ok(Vec::new()),
        Some(Block::Paragraph(inline)) => Ok(inline),
        Some(Block::Math(m)) => Ok(vec![Span::Math(m)]),
        Some(_) => Err(LessonError::new(
            file,
            line,
            "expected a line of text here, not a block (heading, list, code…)",
        )),
    }
}

fn options() -> Options {
    Options::ENABLE_TABLES | Options::ENABLE_STRIKETHROUGH | Options::ENABLE_MATH
}

/// Parse Markdown that starts on file line `first_line`.
pub(crate) fn parse_body(
    file: &str,
    body: &str,
    first_line: usize,
) -> Result<Vec<Block>, LessonError> {
    let events: Vec<(Event<'_>, Range<usize>)> = Markdown::new_ext(body, options())
        .into_offset_iter()
        .collect();
    let line_starts = std::iter::once(0)
        .chain(body.match_indices('\n').map(|(i, _)| i + 1))
        .collect();
    let mut parser = BodyParser {
        file,
        body,
        events,
        pos: 0,
        line_starts,
        first_line,
        display_math: false,
    };
    parser.check_characters()?;
    parser.check_nesting()?;
    parser.blocks()
}

/// What a control character in a lesson most likely was: a backslash
/// escape that a program turned into the character (`\beta` written from
/// a string where `\b` is a backspace).
fn control_name(c: char) -> String {
    let meant = match c {
        '\u{7}' => " (was `\\a` meant?)",
        '\u{8}' => " (was `\\b`, as in `\\beta`, meant?)",
        '\u{b}' => " (was `\\v`, as in `\\varphi`, meant?)",
        '\u{c}' => " (was `\\f`, as in `\\frac`, meant?)",
        '\t' => " (was `\\t`, as in `\\tau` or `\\theta`, meant?)",
        '\n' => " (was `\\n`, as in `\\nu`, meant?)",
        '\r' => " (was `\\r`, as in `\\rho`, meant?)",
        _ => "",
    };
    format!("U+{:04X}{meant}", u32::from(c))
}

/// The deepest nesting of quotes, lists and emphasis a lesson may use: far
/// more than any text needs, and shallow enough that reading, checking and
/// drawing the blocks (which recurse) never exhaust the stack.
pub const MAX_NESTING: usize = 16;

struct BodyParser<'f, 'src> {
    file: &'f str,
    body: &'src str,
    events: Vec<(Event<'src>, Range<usize>)>,
    pos: usize,
    line_starts: Vec<usize>,
    first_line: usize,
    /// Set when the inline run just read contained a `$$ … $$` formula.
    display_math: bool,
}

fn is_inline_start(tag: &Tag<'_>) -> bool {
    matches!(
        tag,
        Tag::Emphasis | Tag::Strong | Tag::Strikethrough | Tag::Link { .. } | Tag::Image { .. }
    )
}

fn is_inline_event(event: &Event<'_>) -> bool {
    match event {
        Event::Start(tag) => is_inline_start(tag),
        Event::Text(_)
        | Event::Code(_)
        | Event::InlineMath(_)
        | Event::DisplayMath(_)
        | Event::InlineHtml(_)
        | Event::SoftBreak
        | Event::HardBreak => true,
        _ => false,
    }
}

impl<'src> BodyParser<'_, 'src> {
    fn line_of(&self, offset: usize) -> usize {
        let index = self.line_starts.partition_point(|&s| s <= offset);
        self.first_line + index.saturating_sub(1)
    }

    fn error(&self, offset: usize, message: impl Into<String>) -> LessonError {
        LessonError::new(self.file, self.line_of(offset), message)
    }

    /// No control characters in the text (line breaks aside, and tabs
    /// that indent a line), and none at all inside a formula.
    fn check_characters(&self) -> Result<(), LessonError> {
        let body = self.body;
        let indents = |at: usize| {
            let line = body[..at].rfind('\n').map_or(0, |i| i + 1);
            body[line..at].chars().all(|c| c == ' ' || c == '\t')
        };
        let stray = |(at, c): &(usize, char)| match c {
            '\n' | '\r' => false,
            '\t' => !indents(*at),
            c => c.is_control(),
        };
        if let Some((at, c)) = body.char_indices().find(stray) {
            return Err(self.error(
                at,
                format!("a control character, {}, in the text", control_name(c)),
            ));
        }
        for (event, range) in &self.events {
            let (Event::InlineMath(src) | Event::DisplayMath(src)) = event else {
                continue;
            };
            let inline = matches!(event, Event::InlineMath(_));
            let bad = |c: char| c.is_control() && (inline || c == '\t');
            if let Some(c) = src.chars().find(|&c| bad(c)) {
                return Err(self.error(
                    range.start,
                    format!(
                        "a control character, {}, in the formula `{src}`",
                        control_name(c)
                    ),
                ));
            }
        }
        Ok(())
    }

    fn peek(&self) -> Option<&(Event<'src>, Range<usize>)> {
        self.events.get(self.pos)
    }

    /// Take the next event (each is read once: no copy of its text).
    fn next(&mut self) -> Option<(Event<'src>, Range<usize>)> {
        let item = self
            .events
            .get_mut(self.pos)
            .map(|slot| std::mem::replace(slot, (Event::Rule, 0..0)));
        self.pos += 1;
        item
    }

    /// Blocks until the end of the enclosing container (whose `End` is
    /// consumed) or the end of the input.
    fn blocks(&mut self) -> Result<Vec<Block>, LessonError> {
        let mut blocks = Vec::new();
        while let Some((event, _)) = self.peek() {
            if is_inline_event(event) {
                // A tight list item holds text without a paragraph around it.
                let inline = self.inline()?;
                if !inline.is_empty() {
                    blocks.push(Block::Paragraph(inline));
                }
                continue;
            }
            let Some((event, range)) = self.next() else {
                break;
            };
            match event {
                Event::End(_) => return Ok(blocks),
                Event::Start(tag) => {
                    if let Some(block) = self.block(tag, range)? {
                        blocks.push(block);
                    }
                }
                Event::Rule => blocks.push(Block::Rule),
                Event::Html(_) | Event::TaskListMarker(_) | Event::FootnoteReference(_) => {}
                other => {
                    return Err(self.error(range.start, format!("unexpected Markdown {other:?}")));
                }
            }
        }
        Ok(blocks)
    }

    fn block(&mut self, tag: Tag<'src>, range: Range<usize>) -> Result<Option<Block>, LessonError> {
        Ok(Some(match tag {
            Tag::Paragraph => {
                self.display_math = false;
                let inline = self.inline()?;
                self.expect_end(range.start)?;
                match inline.as_slice() {
                    [Span::Math(m)] if self.display_math => Block::Math(m.clone()),
                    _ => Block::Paragraph(inline),
                }
            }
            Tag::Heading { level, .. } => {
                let text = self.inline()?;
                self.expect_end(range.start)?;
                Block::Heading {
                    level: heading_level(level),
                    text,
                }
            }
            Tag::BlockQuote(_) => Block::Quote(self.blocks()?),
            Tag::List(start) => {
                let mut items = Vec::new();
                while let Some((Event::Start(Tag::Item), _)) = self.peek() {
                    self.pos += 1;
                    items.push(self.blocks()?);
                }
                self.expect_end(range.start)?;
                Block::List { start, items }
            }
            Tag::CodeBlock(kind) => {
                let info = match kind {
                    CodeBlockKind::Fenced(info) => info.trim().to_owned(),
                    CodeBlockKind::Indented => String::new(),
                };
                let text = self.code_text();
                self.expect_end(range.start)?;
                if !info.is_empty() && !self.fence_closed(&range) {
                    return Err(self.error(
                        range.start,
                        format!("the ```{info} block opened here is never closed by a ``` line"),
                    ));
                }
                let content_line = self.line_of(range.start) + 1;
                match info.as_str() {
                    "widget" => Block::Widget(self.widget(&text, content_line)?),
                    "exercise" => Block::Widget(self.exercise(&text, content_line)?),
                    "quiz" => Block::Quiz(self.quiz(&text, content_line)?),
                    _ => Block::Code { lang: info, text },
                }
            }
            Tag::Table(aligns) => self.table(aligns, range.start)?,
            Tag::HtmlBlock | Tag::MetadataBlock(_) | Tag::FootnoteDefinition(_) => {
                self.skip_container();
                return Ok(None);
            }
            other => {
                return Err(self.error(
                    range.start,
                    format!("this Markdown construct is not supported in lessons: {other:?}"),
                ));
            }
        }))
    }

    fn expect_end(&mut self, opened_at: usize) -> Result<(), LessonError> {
        match self.next() {
            Some((Event::End(_), _)) => Ok(()),
            _ => Err(self.error(opened_at, "a block opened here is not closed")),
        }
    }

    /// Whether the fenced block spanning `range` ends with a closing fence
    /// (Markdown silently closes it at the end of the file otherwise).
    fn fence_closed(&self, range: &Range<usize>) -> bool {
        let block = self.body.get(range.clone()).unwrap_or("").trim_end();
        let last_line = block.rsplit('\n').next().unwrap_or("").trim();
        block.contains('\n') && (last_line.starts_with("```") || last_line.starts_with("~~~"))
    }

    /// Refuse Markdown nested deeper than [`MAX_NESTING`], naming the line.
    fn check_nesting(&self) -> Result<(), LessonError> {
        let mut depth = 0usize;
        for (event, range) in &self.events {
            match event {
                Event::Start(_) => depth += 1,
                Event::End(_) => depth = depth.saturating_sub(1),
                _ => {}
            }
            if depth > MAX_NESTING {
                return Err(self.error(
                    range.start,
                    format!("quotes, lists or emphasis nested more than {MAX_NESTING} deep"),
                ));
            }
        }
        Ok(())
    }

    /// Consume events up to the `End` that closes an already opened
    /// container, returning them (nested containers included).
    fn take_container(&mut self) -> Vec<Event<'src>> {
        let mut taken = Vec::new();
        let mut depth = 1usize;
        while let Some((event, _)) = self.next() {
            match event {
                Event::Start(_) => depth += 1,
                Event::End(_) => {
                    depth -= 1;
                    if depth == 0 {
                        break;
                    }
                }
                _ => {}
            }
            taken.push(event);
        }
        taken
    }

    fn skip_container(&mut self) {
        self.take_container();
    }

    fn code_text(&mut self) -> String {
        let mut text = String::new();
        while let Some((Event::Text(t), _)) = self.peek() {
            text.push_str(t);
            self.pos += 1;
        }
        text
    }

    /// Inline spans up to (not including) the enclosing block's `End` or the
    /// next block-level event.
    fn inline(&mut self) -> Result<Inline, LessonError> {
        let mut spans: Inline = Vec::new();
        let mut style = TextStyle::default();
        let mut emphasis = 0u32;
        let mut strong = 0u32;
        let mut strike = 0u32;
        let mut links: Vec<String> = Vec::new();
        let mut depth = 0u32;
        while let Some((event, _)) = self.peek() {
            let closes_inline_tag = depth > 0 && matches!(event, Event::End(_));
            if !(is_inline_event(event) || closes_inline_tag) {
                break;
            }
            let Some((event, range)) = self.next() else {
                break;
            };
            match event {
                Event::Start(Tag::Image { dest_url, .. }) => {
                    let alt = self.image_alt();
                    spans.push(Span::Image {
                        url: dest_url.to_string(),
                        alt,
                        line: self.line_of(range.start),
                    });
                    continue;
                }
                Event::Start(tag) => {
                    depth += 1;
                    match tag {
                        Tag::Emphasis => emphasis += 1,
                        Tag::Strong => strong += 1,
                        Tag::Strikethrough => strike += 1,
                        Tag::Link { dest_url, .. } => links.push(dest_url.to_string()),
                        _ => {}
                    }
                }
                Event::End(tag) => {
                    depth = depth.saturating_sub(1);
                    match tag {
                        TagEnd::Emphasis => emphasis = emphasis.saturating_sub(1),
                        TagEnd::Strong => strong = strong.saturating_sub(1),
                        TagEnd::Strikethrough => strike = strike.saturating_sub(1),
                        TagEnd::Link => {
                            links.pop();
                        }
                        _ => {}
                    }
                }
                Event::Text(text) | Event::InlineHtml(text) => {
                    push_text(&mut spans, &text, &style);
                }
                Event::Code(code) => spans.push(Span::Code(code.to_string())),
                Event::InlineMath(src) => spans.push(Span::Math(self.math(&src, range.start)?)),
                Event::DisplayMath(src) => {
                    self.display_math = true;
                    spans.push(Span::Math(self.math(&src, range.start)?));
                }
                Event::SoftBreak => push_text(&mut spans, &CowStr::from(" "), &style),
                Event::HardBreak => spans.push(Span::LineBreak),
                _ => {}
            }
            style = TextStyle {
                strong: strong > 0,
                emphasis: emphasis > 0,
                strikethrough: strike > 0,
                link: links.last().cloned(),
            };
        }
        Ok(spans)
    }

    fn image_alt(&mut self) -> String {
        let mut alt = String::new();
        for event in self.take_container() {
            if let Event::Text(t) | Event::Code(t) = event {
                alt.push_str(&t);
            }
        }
        alt
    }

    fn math(&self, src: &str, offset: usize) -> Result<math::Math, LessonError> {
        math::parse(src).map_err(|e| self.error(offset, format!("in formula `{src}`: {e}")))
    }

    fn table(&mut self, aligns: Vec<Alignment>, opened_at: usize) -> Result<Block, LessonError> {
        let align = aligns
            .iter()
            .map(|a| match a {
                Alignment::Center => Align::Center,
                Alignment::Right => Align::Right,
                Alignment::Left | Alignment::None => Align::Left,
            })
            .collect();
        let mut header = Vec::new();
        let mut rows = Vec::new();
        while let Some((event, range)) = self.next() {
            match event {
                Event::Start(Tag::TableHead) => header = self.table_row()?,
                Event::Start(Tag::TableRow) => rows.push(self.table_row()?),
                Event::End(TagEnd::Table) => {
                    return Ok(Block::Table {
                        align,
                        header,
                        rows,
                    });
                }
                _ => return Err(self.error(range.start, "unexpected content in a table")),
            }
        }
        Err(self.error(opened_at, "a table opened here is not closed"))
    }

    fn table_row(&mut self) -> Result<Vec<Inline>, LessonError> {
        let mut cells = Vec::new();
        while let Some((event, range)) = self.next() {
            match event {
                Event::Start(Tag::TableCell) => {
                    cells.push(self.inline()?);
                    self.expect_end(range.start)?;
                }
                Event::End(_) => return Ok(cells),
                _ => return Err(self.error(range.start, "unexpected content in a table row")),
            }
        }
        Ok(cells)
    }

    /// A graded code exercise: its id on the first line, shown in the code
    /// panel (the `code` widget), which the widget schema checks like any
    /// widget, the id against the exercises there are.
    fn exercise(&self, text: &str, first_line: usize) -> Result<WidgetSpec, LessonError> {
        let id = text.trim();
        if id.is_empty() || id.contains(char::is_whitespace) || id.contains(':') {
            return Err(LessonError::new(
                self.file,
                first_line,
                "an exercise block holds the exercise's id alone, such as `control-park`",
            ));
        }
        Ok(WidgetSpec {
            name: "code".to_owned(),
            params: vec![("exercise".to_owned(), id.to_owned())],
            line: first_line - 1,
        })
    }

    fn widget(&self, text: &str, first_line: usize) -> Result<WidgetSpec, LessonError> {
        let mut lines = text
            .lines()
            .enumerate()
            .filter(|(_, l)| !l.trim().is_empty());
        let Some((_, name)) = lines.next() else {
            return Err(LessonError::new(
                self.file,
                first_line,
                "a widget block needs the widget's name on its first line",
            ));
        };
        let name = name.trim();
        if name.contains(':') || name.contains(char::is_whitespace) {
            return Err(LessonError::new(
                self.file,
                first_line,
                format!(
                    "`{name}` is not a widget name: the first line is the name alone, parameters follow as `key: value`"
                ),
            ));
        }
        let mut params = Vec::new();
        for (offset, line) in lines {
            let Some((key, value)) = line.split_once(':') else {
                return Err(LessonError::new(
                    self.file,
                    first_line + offset,
                    format!(
                        "expected a widget parameter `key: value`, found `{}`",
                        line.trim()
                    ),
                ));
            };
            params.push((key.trim().to_owned(), value.trim().to_owned()));
        }
        Ok(WidgetSpec {
            name: name.to_owned(),
            params,
            line: first_line - 1,
        })
    }

    fn quiz(&self, text: &str, first_line: usize) -> Result<Quiz, LessonError> {
        let file = self.file;
        let fence = first_line - 1;
        let raw = quiz::read_raw(file, text, first_line)?;
        let missing =
            |what: &str| LessonError::new(file, fence, format!("the quiz has no `{what}`"));
        let question = parse_inline(
            file,
            fence,
            raw.question.as_deref().ok_or_else(|| missing("question"))?,
        )?;
        let explain = parse_inline(
            file,
            fence,
            raw.explain.as_deref().ok_or_else(|| missing("explain"))?,
        )?;
        let kind_name = raw.kind.clone().ok_or_else(|| missing("kind"))?;
        let options = raw
            .options
            .iter()
            .map(|(text, _)| parse_inline(file, fence, text))
            .collect::<Result<Vec<_>, _>>()?;
        let marks: Vec<bool> = raw.options.iter().map(|(_, right)| *right).collect();
        let right_count = marks.iter().filter(|r| **r).count();
        let kind = match kind_name.as_str() {
            "single" | "multiple" => {
                if options.len() < 2 {
                    return Err(LessonError::new(
                        file,
                        fence,
                        "a choice quiz needs at least two options",
                    ));
                }
                if kind_name == "single" {
                    if right_count != 1 {
                        return Err(LessonError::new(
                            file,
                            fence,
                            format!(
                                "a single-choice quiz needs exactly one `- [x]` option, found {right_count}"
                            ),
                        ));
                    }
                    let correct = marks.iter().position(|r| *r).unwrap_or(0);
                    QuizKind::Single { options, correct }
                } else {
                    if right_count == 0 {
                        return Err(LessonError::new(
                            file,
                            fence,
                            "a multiple-choice quiz needs at least one `- [x]` option",
                        ));
                    }
                    QuizKind::Multiple {
                        options,
                        correct: marks,
                    }
                }
            }
            "numeric" => {
                if !options.is_empty() {
                    return Err(LessonError::new(
                        file,
                        fence,
                        "a numeric quiz has no options",
                    ));
                }
                let (answer, line) = raw.answer.clone().ok_or_else(|| missing("answer"))?;
                let answer = parse_number(file, line, "answer", &answer)?;
                let tolerance = match raw.tolerance.clone() {
                    Some((t, line)) => {
                        let t = parse_number(file, line, "tolerance", &t)?;
                        if t < 0.0 {
                            return Err(LessonError::new(
                                file,
                                line,
                                "`tolerance` must not be negative",
                            ));
                        }
                        t
                    }
                    None => 0.0,
                };
                QuizKind::Numeric {
                    answer,
                    tolerance,
                    unit: raw.unit.clone(),
                }
            }
            "sort" => sort_kind(file, fence, &raw, options.is_empty())?,
            other => {
                return Err(LessonError::new(
                    file,
                    fence,
                    format!(
                        "unknown quiz kind `{other}` (expected single, multiple, numeric or sort)"
                    ),
                ));
            }
        };
        if kind_name != "sort" && !raw.items.is_empty() {
            return Err(LessonError::new(
                file,
                raw.items[0].line,
                "only a `kind: sort` quiz has `- text => bin` items",
            ));
        }
        Ok(Quiz {
            question,
            kind,
            explain,
        })
    }
}

/// A sorting question: 2 to 6 distinct bins, 2 to 20 items each naming one.
fn sort_kind(
    file: &str,
    fence: usize,
    raw: &crate::quiz::RawQuiz,
    no_options: bool,
) -> Result<QuizKind, LessonError> {
    if !no_options {
        return Err(LessonError::new(
            file,
            fence,
            "a sorting quiz has items, not `- [ ]` options",
        ));
    }
    let (bins_text, bins_line) = raw
        .bins
        .as_ref()
        .ok_or_else(|| LessonError::new(file, fence, "a sorting quiz needs `bins: A | B | …`"))?;
    let bins: Vec<String> = bins_text.split('|').map(|b| b.trim().to_owned()).collect();
    let distinct = bins.iter().collect::<std::collections::BTreeSet<_>>().len() == bins.len();
    if !(2..=6).contains(&bins.len()) || bins.iter().any(String::is_empty) || !distinct {
        return Err(LessonError::new(
            file,
            *bins_line,
            "`bins` needs 2 to 6 distinct names separated by `|`",
        ));
    }
    if !(2..=20).contains(&raw.items.len()) {
        return Err(LessonError::new(
            file,
            fence,
            "a sorting quiz needs 2 to 20 items",
        ));
    }
    let items = raw
        .items
        .iter()
        .map(|item| {
            let bin = bins.iter().position(|b| *b == item.bin).ok_or_else(|| {
                LessonError::new(
                    file,
                    item.line,
                    format!(
                        "`{}` is not one of the bins ({})",
                        item.bin,
                        bins.join(", ")
                    ),
                )
            })?;
            if item.text.is_empty() {
                return Err(LessonError::new(
                    file,
                    item.line,
                    "a sorting item has no text",
                ));
            }
            Ok(crate::quiz::SortItem {
                text: parse_inline(file, item.line, &item.text)?,
                bin,
                why: item
                    .why
                    .as_deref()
                    .map(|w| parse_inline(file, item.line, w))
                    .transpose()?,
            })
        })
        .collect::<Result<Vec<_>, LessonError>>()?;
    Ok(QuizKind::Sort { bins, items })
}

fn parse_number(file: &str, line: usize, key: &str, text: &str) -> Result<f64, LessonError> {
    let cleaned: String = text
        .chars()
        .filter(|c| !c.is_whitespace() && *c != '_')
        .collect();
    match cleaned.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(LessonError::new(
            file,
            line,
            format!("`{key}` must be a finite number, found `{text}`"),
        )),
    }
}

fn heading_level(level: HeadingLevel) -> u8 {
    match level {
        HeadingLevel::H1 => 1,
        HeadingLevel::H2 => 2,
        HeadingLevel::H3 => 3,
        HeadingLevel::H4 => 4,
        HeadingLevel::H5 => 5,
        HeadingLevel::H6 => 6,
    }
}

/// Append text, merging with the previous span when the style is the same.
fn push_text(spans: &mut Inline, text: &str, style: &TextStyle) {
    if let Some(Span::Text {
        text: prev,
        style: prev_style,
    }) = spans.last_mut()
        && prev_style == style
    {
        prev.push_str(text);
        return;
    }
    spans.push(Span::Text {
        text: text.to_owned(),
        style: style.clone(),
    });
}
