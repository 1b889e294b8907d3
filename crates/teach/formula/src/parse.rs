//! The parser: a strict recursive descent over the formula's characters.

use std::fmt;

use crate::tree::*;

/// Why a formula could not be parsed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MathError {
    /// Byte offset into the formula where the problem was found.
    pub position: usize,
    /// What went wrong, without the position.
    pub message: String,
}

impl MathError {
    fn new(position: usize, message: impl Into<String>) -> Self {
        Self {
            position,
            message: message.into(),
        }
    }
}

impl fmt::Display for MathError {
    /// The message followed by a 1-based column (counted in bytes).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} at column {}", self.message, self.position + 1)
    }
}

impl std::error::Error for MathError {}

/// Parses a formula written in the TeX subset described in the module docs.
///
/// An empty formula is an empty [`Math::Row`].
pub fn parse(src: &str) -> Result<Math, MathError> {
    let mut parser = Parser::new(src);
    let items = parser.parse_row(false)?;
    parser.skip_blank();
    match parser.terminator(false) {
        Some(Terminator::End) | None => Ok(into_row(items)),
        Some(other) => Err(parser.unexpected(other)),
    }
}

/// Wraps atoms into a row, unless there is exactly one.
fn into_row(items: Vec<Math>) -> Math {
    match <[Math; 1]>::try_from(items) {
        Ok([single]) => single,
        Err(items) => Math::Row(items),
    }
}

/// What can end a row: the caller decides which of these it accepts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Terminator {
    End,
    CloseBrace,
    CloseBracket,
    Ampersand,
    NewRow,
    Right,
    EndEnvironment,
}

/// A recursive-descent parser over the formula's bytes.
///
/// `pos` always sits on a character boundary because it only ever advances by
/// whole characters.
struct Parser<'a> {
    src: &'a str,
    pos: usize,
    depth: usize,
    /// The letter style requested by an enclosing `\mathbf{…}` and the like.
    variant: Variant,
}

impl<'a> Parser<'a> {
    fn new(src: &'a str) -> Self {
        Self {
            src,
            pos: 0,
            depth: 0,
            variant: Variant::Italic,
        }
    }

    // ----- Low-level reading -----------------------------------------------

    fn rest(&self) -> &'a str {
        self.src.get(self.pos..).unwrap_or("")
    }

    fn peek(&self) -> Option<char> {
        self.rest().chars().next()
    }

    fn bump(&mut self) -> Option<char> {
        let c = self.peek()?;
        self.pos += c.len_utf8();
        Some(c)
    }

    fn eat(&mut self, expected: char) -> bool {
        let found = self.peek() == Some(expected);
        if found {
            self.pos += expected.len_utf8();
        }
        found
    }

    /// Skips white space and `%` comments, which TeX ignores in math.
    fn skip_blank(&mut self) {
        while let Some(c) = self.peek() {
            if c == '%' {
                while !matches!(self.bump(), None | Some('\n')) {}
            } else if c.is_whitespace() {
                self.bump();
            } else {
                break;
            }
        }
    }

    /// The command starting at `pos` (without the backslash) and the offset
    /// just after it, if `pos` is at a backslash followed by something.
    ///
    /// A command is a run of ASCII letters or a single other character;
    /// `\atan2` is accepted as one name because lessons use it.
    fn command_at(&self, pos: usize) -> Option<(&'a str, usize)> {
        let rest = self.src.get(pos..)?.strip_prefix('\\')?;
        let letters = rest
            .find(|c: char| !c.is_ascii_alphabetic())
            .unwrap_or(rest.len());
        let len = if letters > 0 {
            if rest.get(..letters) == Some("atan")
                && rest.get(letters..).is_some_and(|r| r.starts_with('2'))
            {
                letters + 1
            } else {
                letters
            }
        } else {
            rest.chars().next()?.len_utf8()
        };
        Some((rest.get(..len)?, pos + 1 + len))
    }

    fn peek_command(&self) -> Option<&'a str> {
        self.command_at(self.pos).map(|(name, _)| name)
    }

    /// Reads the command at `pos` (which must be a backslash).
    fn read_command(&mut self) -> Result<&'a str, MathError> {
        match self.command_at(self.pos) {
            Some((name, end)) => {
                self.pos = end;
                Ok(name)
            }
            None => Err(MathError::new(
                self.pos,
                "lone \\ at the end of the formula",
            )),
        }
    }

    /// Runs `f` one nesting level deeper, refusing to go past [`MAX_NESTING`].
    fn nested<T>(
        &mut self,
        f: impl FnOnce(&mut Self) -> Result<T, MathError>,
    ) -> Result<T, MathError> {
        if self.depth >= MAX_NESTING {
            return Err(MathError::new(
                self.pos,
                format!("formula is nested too deeply (more than {MAX_NESTING} levels)"),
            ));
        }
        self.depth += 1;
        let result = f(self);
        self.depth -= 1;
        result
    }

    // ----- Row structure ---------------------------------------------------

    /// What ends the current row at `pos`, if anything. `]` only counts when
    /// reading the optional index of `\sqrt`.
    fn terminator(&self, brackets: bool) -> Option<Terminator> {
        match self.peek() {
            None => Some(Terminator::End),
            Some('}') => Some(Terminator::CloseBrace),
            Some(']') if brackets => Some(Terminator::CloseBracket),
            Some('&') => Some(Terminator::Ampersand),
            Some('\\') => match self.peek_command() {
                Some("\\") => Some(Terminator::NewRow),
                Some("right") => Some(Terminator::Right),
                Some("end") => Some(Terminator::EndEnvironment),
                _ => None,
            },
            Some(_) => None,
        }
    }

    /// The error for a terminator the caller did not expect here.
    fn unexpected(&self, terminator: Terminator) -> MathError {
        let message = match terminator {
            Terminator::End => "unexpected end of formula",
            Terminator::CloseBrace => "unbalanced braces: unexpected }",
            Terminator::CloseBracket => "unexpected ]",
            Terminator::Ampersand => "& is only allowed inside a matrix",
            Terminator::NewRow => "\\\\ is only allowed inside a matrix",
            Terminator::Right => "\\right without matching \\left",
            Terminator::EndEnvironment => "\\end without matching \\begin",
        };
        MathError::new(self.pos, message)
    }

    /// Reads atoms until a terminator (left in place for the caller).
    fn parse_row(&mut self, brackets: bool) -> Result<Vec<Math>, MathError> {
        self.nested(|p| {
            let mut items = Vec::new();
            loop {
                p.skip_blank();
                if p.terminator(brackets).is_some() {
                    return Ok(items);
                }
                p.parse_item(&mut items)?;
            }
        })
    }

    /// Reads the rest of a `{…}` group whose `{` at `open` was just consumed.
    fn parse_group_body(&mut self, open: usize) -> Result<Vec<Math>, MathError> {
        let items = self.parse_row(false)?;
        match self.terminator(false) {
            Some(Terminator::CloseBrace) => {
                self.bump();
                Ok(items)
            }
            Some(Terminator::End) => {
                Err(MathError::new(open, "unbalanced braces: { is never closed"))
            }
            Some(other) => Err(self.unexpected(other)),
            None => Err(MathError::new(self.pos, "unexpected input")),
        }
    }

    /// Reads one atom with its primes and scripts and appends it to `items`.
    fn parse_item(&mut self, items: &mut Vec<Math>) -> Result<(), MathError> {
        let base = match self.peek() {
            Some('^' | '_' | '\'') => None,
            _ => Some(self.parse_atom()?),
        };
        self.skip_blank();
        let primes = self.parse_primes();
        let (sub, sup) = self.parse_scripts()?;
        if sub.is_none() && sup.is_none() {
            items.extend(base);
            items.extend(primes);
            return Ok(());
        }
        let base: Vec<Math> = base.into_iter().chain(primes).collect();
        items.push(Math::Scripts {
            base: Box::new(into_row(base)),
            sub: sub.map(Box::new),
            sup: sup.map(Box::new),
        });
        Ok(())
    }

    /// Reads `'`, `''`, … as one prime symbol.
    fn parse_primes(&mut self) -> Option<Math> {
        let mut count = 0;
        while self.eat('\'') {
            count += 1;
        }
        let text = match count {
            0 => return None,
            1 => "′".to_owned(),
            2 => "″".to_owned(),
            3 => "‴".to_owned(),
            n => "′".repeat(n),
        };
        Some(Math::Symbol(text))
    }

    /// Reads any `_sub` and `^sup` after a base, in either order.
    fn parse_scripts(&mut self) -> Result<(Option<Math>, Option<Math>), MathError> {
        let (mut sub, mut sup) = (None, None);
        loop {
            self.skip_blank();
            let at = self.pos;
            match self.peek() {
                Some('^') => {
                    self.bump();
                    if sup.is_some() {
                        return Err(MathError::new(at, "double superscript"));
                    }
                    sup = Some(self.parse_argument("missing superscript after ^")?);
                }
                Some('_') => {
                    self.bump();
                    if sub.is_some() {
                        return Err(MathError::new(at, "double subscript"));
                    }
                    sub = Some(self.parse_argument("missing subscript after _")?);
                }
                Some('\\') if matches!(self.peek_command(), Some("limits" | "nolimits")) => {
                    // Placement of limits is the renderer's business.
                    self.read_command()?;
                }
                _ => return Ok((sub, sup)),
            }
        }
    }

    /// Reads the argument of a command or script: a `{group}`, one command
    /// with its own arguments, or one character.
    fn parse_argument(&mut self, missing: &str) -> Result<Math, MathError> {
        self.skip_blank();
        let at = self.pos;
        match self.peek() {
            None | Some('}' | '&' | '^' | '_') => Err(MathError::new(at, missing)),
            Some('{') => {
                self.bump();
                self.parse_group_body(at).map(into_row)
            }
            Some('\\') if matches!(self.peek_command(), Some("\\" | "right" | "end") | None) => {
                Err(MathError::new(at, missing))
            }
            // As in TeX, `\frac12` and `x^ab` take a single character.
            Some(c) if c.is_ascii_digit() => Ok(self.parse_number(false)),
            Some(c) if c.is_ascii_alphabetic() => Ok(self.parse_letters(false)),
            Some(_) => self.nested(Self::parse_atom),
        }
    }

    // ----- Atoms -----------------------------------------------------------

    /// Reads one atom without scripts. The caller guarantees input remains
    /// and is not a terminator.
    fn parse_atom(&mut self) -> Result<Math, MathError> {
        let at = self.pos;
        let Some(c) = self.peek() else {
            return Err(MathError::new(at, "unexpected end of formula"));
        };
        match c {
            '{' => {
                self.bump();
                let items = self.parse_group_body(at)?;
                Ok(Math::Group(Box::new(into_row(items))))
            }
            '\\' => self.parse_command(),
            '0'..='9' => Ok(self.parse_number(true)),
            '\'' => Ok(self
                .parse_primes()
                .unwrap_or_else(|| Math::Symbol("′".to_owned()))),
            '~' => {
                self.bump();
                Ok(Math::Space(INTERWORD_SPACE))
            }
            '#' | '$' => Err(MathError::new(at, format!("unexpected {c}"))),
            c if c.is_ascii_alphabetic() => Ok(self.parse_letters(true)),
            c => {
                self.bump();
                Ok(char_atom(c, self.variant))
            }
        }
    }

    /// Reads digits with an optional decimal part, or only one digit unless
    /// `whole`.
    fn parse_number(&mut self, whole: bool) -> Math {
        let start = self.pos;
        if whole {
            self.skip_digits();
        } else {
            self.bump();
        }
        let rest = self.rest();
        if whole
            && rest.starts_with('.')
            && rest
                .get(1..)
                .is_some_and(|r| r.starts_with(|c: char| c.is_ascii_digit()))
        {
            self.bump();
            self.skip_digits();
        }
        let text = self.src.get(start..self.pos).unwrap_or("").to_owned();
        let variant = match self.variant {
            Variant::Bold | Variant::BoldItalic => Variant::Bold,
            _ => Variant::Upright,
        };
        Math::Number { text, variant }
    }

    fn skip_digits(&mut self) {
        while self.peek().is_some_and(|c| c.is_ascii_digit()) {
            self.bump();
        }
    }

    /// Reads one letter, or with `whole` a word when the style is not italic
    /// (`\mathrm{rank}` is one identifier, `ab` two).
    fn parse_letters(&mut self, whole: bool) -> Math {
        let start = self.pos;
        self.bump();
        if whole && self.variant != Variant::Italic {
            while self.peek().is_some_and(|c| c.is_ascii_alphabetic()) {
                self.bump();
            }
        }
        Math::Ident {
            text: self.src.get(start..self.pos).unwrap_or("").to_owned(),
            variant: self.variant,
        }
    }

    /// Reads a command at `pos` together with its arguments.
    fn parse_command(&mut self) -> Result<Math, MathError> {
        let start = self.pos;
        let name = self.read_command()?;
        match name {
            "frac" | "dfrac" | "tfrac" => {
                let missing = format!("missing argument to \\{name}");
                let num = self.parse_argument(&missing)?;
                let den = self.parse_argument(&missing)?;
                Ok(Math::Frac {
                    num: Box::new(num),
                    den: Box::new(den),
                })
            }
            "sqrt" => self.parse_sqrt(),
            "mathbf" => self.parse_styled(name, Variant::Bold),
            "boldsymbol" | "bm" => self.parse_styled(name, Variant::BoldItalic),
            "mathrm" | "mathup" => self.parse_styled(name, Variant::Upright),
            "mathit" | "mathcal" | "mathsf" | "mathnormal" => {
                self.parse_styled(name, Variant::Italic)
            }
            "mathbb" => self.parse_styled(name, Variant::DoubleStruck),
            "text" | "textrm" | "textup" | "mbox" => self.parse_raw_text(name).map(Math::Text),
            "operatorname" => {
                self.eat('*');
                let text = self.parse_raw_text(name)?;
                Ok(Math::Function(text.split_whitespace().collect()))
            }
            "left" => self.parse_fenced(start),
            "begin" => self.parse_environment(start),
            "right" | "end" | "\\" | "limits" | "nolimits" => {
                Err(MathError::new(start, format!("unexpected \\{name}")))
            }
            _ => {
                if let Some(kind) = accent_kind(name) {
                    let body = self.parse_argument(&format!("missing argument to \\{name}"))?;
                    return Ok(Math::Accent {
                        kind,
                        body: Box::new(body),
                    });
                }
                self.simple_command(name)
                    .ok_or_else(|| MathError::new(start, format!("unknown command \\{name}")))
            }
        }
    }

    /// Reads the argument of a style command such as `\mathbf` in that style.
    fn parse_styled(&mut self, name: &str, variant: Variant) -> Result<Math, MathError> {
        let outer = std::mem::replace(&mut self.variant, variant);
        let result = self.parse_argument(&format!("missing argument to \\{name}"));
        self.variant = outer;
        result
    }

    /// Reads `\sqrt[index]{body}` after the command name.
    fn parse_sqrt(&mut self) -> Result<Math, MathError> {
        self.skip_blank();
        let open = self.pos;
        let index = if self.eat('[') {
            let items = self.parse_row(true)?;
            if !self.eat(']') {
                return Err(MathError::new(open, "\\sqrt[ is never closed with ]"));
            }
            Some(Box::new(into_row(items)))
        } else {
            None
        };
        let body = self.parse_argument("missing argument to \\sqrt")?;
        Ok(Math::Sqrt {
            index,
            body: Box::new(body),
        })
    }

    /// Reads the braced argument of `\text` or `\operatorname` as plain text.
    ///
    /// Braces inside only group; `\{`, `\}`, `\_` and friends give the
    /// character, and `\,` `\;` `\ ` give a space.
    fn parse_raw_text(&mut self, name: &str) -> Result<String, MathError> {
        self.skip_blank();
        let open = self.pos;
        if !self.eat('{') {
            return Err(MathError::new(
                open,
                format!("missing argument to \\{name}"),
            ));
        }
        let mut text = String::new();
        let mut depth = 0usize;
        loop {
            let at = self.pos;
            match self.bump() {
                None => return Err(MathError::new(open, "unbalanced braces: { is never closed")),
                Some('{') => depth += 1,
                Some('}') if depth == 0 => return Ok(text),
                Some('}') => depth -= 1,
                Some('\\') => match self.bump() {
                    Some(c @ ('{' | '}' | '_' | '%' | '$' | '&' | '#' | '\\')) => text.push(c),
                    Some(',' | ';' | ':' | ' ' | '!' | '>') => text.push(' '),
                    Some(_) => {
                        self.pos = at;
                        let command = self.read_command()?;
                        return Err(MathError::new(
                            at,
                            format!("unknown command \\{command} in text"),
                        ));
                    }
                    None => return Err(MathError::new(at, "lone \\ at the end of the formula")),
                },
                Some(c) => text.push(c),
            }
        }
    }

    /// Reads `\left<delim> … \right<delim>`; `start` is where `\left` began.
    fn parse_fenced(&mut self, start: usize) -> Result<Math, MathError> {
        let open = self.parse_delimiter("\\left")?;
        let body = self.parse_row(false)?;
        if self.terminator(false) != Some(Terminator::Right) {
            return Err(MathError::new(start, "\\left without matching \\right"));
        }
        self.read_command()?;
        let close = self.parse_delimiter("\\right")?;
        Ok(Math::Fenced {
            open,
            close,
            body: Box::new(into_row(body)),
        })
    }

    /// Reads the delimiter after `\left` or `\right`.
    fn parse_delimiter(&mut self, after: &str) -> Result<Delimiter, MathError> {
        self.skip_blank();
        let at = self.pos;
        let delimiter = match self.peek() {
            Some('\\') => {
                let name = self.read_command()?;
                delimiter_command(name)
            }
            Some(c) => {
                self.bump();
                delimiter_char(c)
            }
            None => None,
        };
        delimiter.ok_or_else(|| MathError::new(at, format!("missing delimiter after {after}")))
    }

    /// Reads `\begin{env} cells \end{env}`; `start` is where `\begin` began.
    fn parse_environment(&mut self, start: usize) -> Result<Math, MathError> {
        let name_at = self.pos;
        let name = self.parse_environment_name("\\begin")?;
        let kind = MatrixKind::from_environment(name)
            .ok_or_else(|| MathError::new(name_at, format!("unknown environment {name}")))?;
        let mut rows = Vec::new();
        let mut row = Vec::new();
        loop {
            let cell = self.parse_row(false)?;
            row.push(into_row(cell));
            match self.terminator(false) {
                Some(Terminator::Ampersand) => {
                    self.bump();
                }
                Some(Terminator::NewRow) => {
                    self.read_command()?;
                    rows.push(std::mem::take(&mut row));
                }
                Some(Terminator::EndEnvironment) => {
                    let end_at = self.pos;
                    self.read_command()?;
                    let end_name = self.parse_environment_name("\\end")?;
                    if end_name != name {
                        return Err(MathError::new(
                            end_at,
                            format!("\\begin{{{name}}} ended by \\end{{{end_name}}}"),
                        ));
                    }
                    rows.push(row);
                    break;
                }
                _ => {
                    return Err(MathError::new(
                        start,
                        format!("\\begin{{{name}}} without matching \\end"),
                    ));
                }
            }
        }
        // A trailing `\\` before `\end` leaves an empty last row.
        if rows.last().is_some_and(|r| r == &[Math::Row(Vec::new())]) {
            rows.pop();
        }
        Ok(Math::Matrix { kind, rows })
    }

    /// Reads `{name}` after `\begin` or `\end`.
    fn parse_environment_name(&mut self, after: &str) -> Result<&'a str, MathError> {
        self.skip_blank();
        let open = self.pos;
        if !self.eat('{') {
            return Err(MathError::new(
                open,
                format!("missing environment name after {after}"),
            ));
        }
        let start = self.pos;
        while self
            .peek()
            .is_some_and(|c| c.is_ascii_alphanumeric() || c == '*')
        {
            self.bump();
        }
        let name = self.src.get(start..self.pos).unwrap_or("");
        if name.is_empty() || !self.eat('}') {
            return Err(MathError::new(
                open,
                format!("missing environment name after {after}"),
            ));
        }
        Ok(name)
    }

    /// Commands without arguments: letters, symbols, operators, functions
    /// and spaces.
    fn simple_command(&self, name: &str) -> Option<Math> {
        if let Some(text) = lookup(GREEK_LOWER, name) {
            return Some(self.greek(text, Variant::Italic));
        }
        if let Some(text) = lookup(GREEK_UPPER, name) {
            return Some(self.greek(text, Variant::Upright));
        }
        if FUNCTIONS.contains(&name) {
            return Some(Math::Function(name.to_owned()));
        }
        if let Some(em) = space_command(name) {
            return Some(Math::Space(em));
        }
        let op = |table: &[(&str, &str)], kind| {
            lookup(table, name).map(|text| Math::Op {
                text: text.to_owned(),
                kind,
            })
        };
        op(LARGE, OpKind::Large)
            .or_else(|| op(BINARY, OpKind::Binary))
            .or_else(|| op(RELATIONS, OpKind::Relation))
            .or_else(|| op(OPENING, OpKind::Open))
            .or_else(|| op(CLOSING, OpKind::Close))
            .or_else(|| op(&[("colon", ":")], OpKind::Punct))
            .or_else(|| lookup(SYMBOLS, name).map(|text| Math::Symbol(text.to_owned())))
    }

    /// A Greek letter in the current style, or its TeX default outside one.
    fn greek(&self, text: &str, default: Variant) -> Math {
        let variant = match self.variant {
            Variant::Italic | Variant::DoubleStruck => default,
            other => other,
        };
        Math::Ident {
            text: text.to_owned(),
            variant,
        }
    }
}

/// Width of `~` and `\ ` in em.
const INTERWORD_SPACE: f32 = 1.0 / 3.0;

/// One character typed directly in math mode.
fn char_atom(c: char, variant: Variant) -> Math {
    let op = |text: &str, kind| Math::Op {
        text: text.to_owned(),
        kind,
    };
    match c {
        '+' => op("+", OpKind::Binary),
        '-' => op("−", OpKind::Binary),
        '*' => op("∗", OpKind::Binary),
        '=' | '<' | '>' | ':' => op(&c.to_string(), OpKind::Relation),
        ',' | ';' => op(&c.to_string(), OpKind::Punct),
        '(' | '[' => op(&c.to_string(), OpKind::Open),
        ')' | ']' => op(&c.to_string(), OpKind::Close),
        c if c.is_alphabetic() => Math::Ident {
            text: c.to_string(),
            variant,
        },
        c => {
            let text = c.to_string();
            let kind = [
                (BINARY, OpKind::Binary),
                (RELATIONS, OpKind::Relation),
                (LARGE, OpKind::Large),
            ]
            .into_iter()
            .find(|(table, _)| table.iter().any(|(_, t)| *t == text))
            .map(|(_, kind)| kind);
            match kind {
                Some(kind) => Math::Op { text, kind },
                None => Math::Symbol(text),
            }
        }
    }
}

fn lookup<'t>(table: &[(&str, &'t str)], name: &str) -> Option<&'t str> {
    table
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, text)| *text)
}

fn accent_kind(name: &str) -> Option<AccentKind> {
    Some(match name {
        "dot" => AccentKind::Dot,
        "ddot" => AccentKind::Ddot,
        "hat" | "widehat" => AccentKind::Hat,
        "bar" | "overline" => AccentKind::Bar,
        "vec" | "overrightarrow" => AccentKind::Vec,
        "tilde" | "widetilde" => AccentKind::Tilde,
        _ => return None,
    })
}

/// Spacing commands, in em.
fn space_command(name: &str) -> Option<f32> {
    Some(match name {
        "," | "thinspace" => 3.0 / 18.0,
        ":" | ">" | "medspace" => 4.0 / 18.0,
        ";" | "thickspace" => 5.0 / 18.0,
        "!" | "negthinspace" => -3.0 / 18.0,
        " " => INTERWORD_SPACE,
        "quad" => 1.0,
        "qquad" => 2.0,
        _ => return None,
    })
}

fn delimiter_char(c: char) -> Option<Delimiter> {
    Some(match c {
        '(' => Delimiter::LeftParen,
        ')' => Delimiter::RightParen,
        '[' => Delimiter::LeftBracket,
        ']' => Delimiter::RightBracket,
        '|' => Delimiter::Bar,
        '<' => Delimiter::LeftAngle,
        '>' => Delimiter::RightAngle,
        '.' => Delimiter::None,
        _ => return None,
    })
}

fn delimiter_command(name: &str) -> Option<Delimiter> {
    Some(match name {
        "{" | "lbrace" => Delimiter::LeftBrace,
        "}" | "rbrace" => Delimiter::RightBrace,
        "|" | "Vert" | "lVert" | "rVert" => Delimiter::DoubleBar,
        "vert" | "lvert" | "rvert" => Delimiter::Bar,
        "langle" => Delimiter::LeftAngle,
        "rangle" => Delimiter::RightAngle,
        "lfloor" => Delimiter::LeftFloor,
        "rfloor" => Delimiter::RightFloor,
        "lceil" => Delimiter::LeftCeil,
        "rceil" => Delimiter::RightCeil,
        _ => return None,
    })
}

const GREEK_LOWER: &[(&str, &str)] = &[
    ("alpha", "α"),
    ("beta", "β"),
    ("gamma", "γ"),
    ("delta", "δ"),
    ("epsilon", "ϵ"),
    ("varepsilon", "ε"),
    ("zeta", "ζ"),
    ("eta", "η"),
    ("theta", "θ"),
    ("vartheta", "ϑ"),
    ("iota", "ι"),
    ("kappa", "κ"),
    ("lambda", "λ"),
    ("mu", "μ"),
    ("nu", "ν"),
    ("xi", "ξ"),
    ("pi", "π"),
    ("varpi", "ϖ"),
    ("rho", "ρ"),
    ("varrho", "ϱ"),
    ("sigma", "σ"),
    ("varsigma", "ς"),
    ("tau", "τ"),
    ("upsilon", "υ"),
    ("phi", "ϕ"),
    ("varphi", "φ"),
    ("chi", "χ"),
    ("psi", "ψ"),
    ("omega", "ω"),
];

const GREEK_UPPER: &[(&str, &str)] = &[
    ("Gamma", "Γ"),
    ("Delta", "Δ"),
    ("Theta", "Θ"),
    ("Lambda", "Λ"),
    ("Xi", "Ξ"),
    ("Pi", "Π"),
    ("Sigma", "Σ"),
    ("Upsilon", "Υ"),
    ("Phi", "Φ"),
    ("Psi", "Ψ"),
    ("Omega", "Ω"),
];

/// Functions set upright with TeX's spacing for operators.
const FUNCTIONS: &[&str] = &[
    "sin", "cos", "tan", "cot", "sec", "csc", "arcsin", "arccos", "arctan", "asin", "acos", "atan",
    "atan2", "sinh", "cosh", "tanh", "coth", "ln", "log", "lg", "exp", "dim", "max", "min", "sup",
    "inf", "lim", "det", "ker", "gcd", "arg", "Pr", "hom",
];

const LARGE: &[(&str, &str)] = &[
    ("sum", "∑"),
    ("prod", "∏"),
    ("int", "∫"),
    ("iint", "∬"),
    ("oint", "∮"),
    ("bigcup", "⋃"),
    ("bigcap", "⋂"),
];

const BINARY: &[(&str, &str)] = &[
    ("pm", "±"),
    ("mp", "∓"),
    ("times", "×"),
    ("cdot", "·"),
    ("div", "÷"),
    ("ast", "∗"),
    ("star", "⋆"),
    ("circ", "∘"),
    ("bullet", "•"),
    ("cup", "∪"),
    ("cap", "∩"),
    ("oplus", "⊕"),
    ("otimes", "⊗"),
    ("wedge", "∧"),
    ("land", "∧"),
    ("vee", "∨"),
    ("lor", "∨"),
    ("+", "+"),
    ("-", "−"),
];

const RELATIONS: &[(&str, &str)] = &[
    ("le", "≤"),
    ("leq", "≤"),
    ("ge", "≥"),
    ("geq", "≥"),
    ("ne", "≠"),
    ("neq", "≠"),
    ("approx", "≈"),
    ("equiv", "≡"),
    ("sim", "∼"),
    ("simeq", "≃"),
    ("cong", "≅"),
    ("propto", "∝"),
    ("in", "∈"),
    ("notin", "∉"),
    ("ni", "∋"),
    ("subset", "⊂"),
    ("subseteq", "⊆"),
    ("supset", "⊃"),
    ("supseteq", "⊇"),
    ("to", "→"),
    ("rightarrow", "→"),
    ("leftarrow", "←"),
    ("gets", "←"),
    ("leftrightarrow", "↔"),
    ("Rightarrow", "⇒"),
    ("implies", "⇒"),
    ("Leftarrow", "⇐"),
    ("Leftrightarrow", "⇔"),
    ("iff", "⇔"),
    ("mapsto", "↦"),
    ("longrightarrow", "⟶"),
    ("perp", "⊥"),
    ("parallel", "∥"),
    ("mid", "∣"),
    ("=", "="),
    ("<", "<"),
    (">", ">"),
];

const OPENING: &[(&str, &str)] = &[
    ("{", "{"),
    ("lbrace", "{"),
    ("langle", "⟨"),
    ("lfloor", "⌊"),
    ("lceil", "⌈"),
];

const CLOSING: &[(&str, &str)] = &[
    ("}", "}"),
    ("rbrace", "}"),
    ("rangle", "⟩"),
    ("rfloor", "⌋"),
    ("rceil", "⌉"),
];

const SYMBOLS: &[(&str, &str)] = &[
    ("infty", "∞"),
    ("partial", "∂"),
    ("nabla", "∇"),
    ("forall", "∀"),
    ("exists", "∃"),
    ("ell", "ℓ"),
    ("hbar", "ℏ"),
    ("angle", "∠"),
    ("deg", "°"),
    ("degree", "°"),
    ("prime", "′"),
    ("dots", "…"),
    ("ldots", "…"),
    ("cdots", "⋯"),
    ("vdots", "⋮"),
    ("ddots", "⋱"),
    ("emptyset", "∅"),
    ("varnothing", "∅"),
    ("top", "⊤"),
    ("bot", "⊥"),
    ("neg", "¬"),
    ("lnot", "¬"),
    ("triangle", "△"),
    ("|", "‖"),
    ("Vert", "‖"),
    ("vert", "|"),
    ("lvert", "|"),
    ("rvert", "|"),
    ("#", "#"),
    ("%", "%"),
    ("$", "$"),
    ("&", "&"),
    ("_", "_"),
];

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn ident(text: &str) -> Math {
        Math::Ident {
            text: text.to_owned(),
            variant: Variant::Italic,
        }
    }

    fn styled(text: &str, variant: Variant) -> Math {
        Math::Ident {
            text: text.to_owned(),
            variant,
        }
    }

    fn number(text: &str) -> Math {
        Math::Number {
            text: text.to_owned(),
            variant: Variant::Upright,
        }
    }

    fn op(text: &str, kind: OpKind) -> Math {
        Math::Op {
            text: text.to_owned(),
            kind,
        }
    }

    fn symbol(text: &str) -> Math {
        Math::Symbol(text.to_owned())
    }

    fn row(items: Vec<Math>) -> Math {
        Math::Row(items)
    }

    fn scripts(base: Math, sub: Option<Math>, sup: Option<Math>) -> Math {
        Math::Scripts {
            base: Box::new(base),
            sub: sub.map(Box::new),
            sup: sup.map(Box::new),
        }
    }

    fn frac(num: Math, den: Math) -> Math {
        Math::Frac {
            num: Box::new(num),
            den: Box::new(den),
        }
    }

    fn accent(kind: AccentKind, body: Math) -> Math {
        Math::Accent {
            kind,
            body: Box::new(body),
        }
    }

    fn ok(src: &str) -> Math {
        parse(src).unwrap_or_else(|e| panic!("{src:?} should parse: {e}"))
    }

    fn err(src: &str) -> MathError {
        match parse(src) {
            Ok(m) => panic!("{src:?} should fail, got {m:?}"),
            Err(e) => e,
        }
    }

    #[test]
    fn empty_and_single_atoms() {
        assert_eq!(ok(""), row(vec![]));
        assert_eq!(ok("   "), row(vec![]));
        assert_eq!(ok("x"), ident("x"));
        assert_eq!(ok("42"), number("42"));
        assert_eq!(ok("3.14"), number("3.14"));
    }

    #[test]
    fn letters_are_separate_identifiers_and_numbers_keep_decimals() {
        assert_eq!(
            ok("2ab + 0.5"),
            row(vec![
                number("2"),
                ident("a"),
                ident("b"),
                op("+", OpKind::Binary),
                number("0.5"),
            ])
        );
        // A full stop without a digit after it is not part of the number.
        assert_eq!(ok("1."), row(vec![number("1"), symbol(".")]));
    }

    #[test]
    fn operators_become_unicode() {
        assert_eq!(
            ok("a - b \\cdot c \\times d \\pm e"),
            row(vec![
                ident("a"),
                op("−", OpKind::Binary),
                ident("b"),
                op("·", OpKind::Binary),
                ident("c"),
                op("×", OpKind::Binary),
                ident("d"),
                op("±", OpKind::Binary),
                ident("e"),
            ])
        );
        assert_eq!(
            ok("x \\le y \\ge z \\ne w \\neq v \\approx u \\to t \\in S"),
            row(vec![
                ident("x"),
                op("≤", OpKind::Relation),
                ident("y"),
                op("≥", OpKind::Relation),
                ident("z"),
                op("≠", OpKind::Relation),
                ident("w"),
                op("≠", OpKind::Relation),
                ident("v"),
                op("≈", OpKind::Relation),
                ident("u"),
                op("→", OpKind::Relation),
                ident("t"),
                op("∈", OpKind::Relation),
                ident("S"),
            ])
        );
        assert_eq!(
            ok("(a, b]"),
            row(vec![
                op("(", OpKind::Open),
                ident("a"),
                op(",", OpKind::Punct),
                ident("b"),
                op("]", OpKind::Close),
            ])
        );
    }

    #[test]
    fn greek_letters() {
        assert_eq!(ok("\\alpha"), ident("α"));
        assert_eq!(ok("\\varphi"), ident("φ"));
        assert_eq!(ok("\\phi"), ident("ϕ"));
        assert_eq!(ok("\\vartheta"), ident("ϑ"));
        assert_eq!(ok("\\epsilon"), ident("ϵ"));
        assert_eq!(ok("\\varepsilon"), ident("ε"));
        assert_eq!(ok("\\omega"), ident("ω"));
        assert_eq!(ok("\\Omega"), styled("Ω", Variant::Upright));
        assert_eq!(ok("\\Delta"), styled("Δ", Variant::Upright));
        for name in GREEK_LOWER.iter().chain(GREEK_UPPER).map(|(n, _)| n) {
            assert!(parse(&format!("\\{name}")).is_ok(), "\\{name}");
        }
    }

    #[test]
    fn symbols_and_dots() {
        assert_eq!(
            ok("\\infty \\partial \\nabla \\ell \\deg"),
            row(vec![
                symbol("∞"),
                symbol("∂"),
                symbol("∇"),
                symbol("ℓ"),
                symbol("°")
            ])
        );
        assert_eq!(
            ok("\\dots\\ldots\\cdots"),
            row(vec![symbol("…"), symbol("…"), symbol("⋯")])
        );
        assert_eq!(ok("n!"), row(vec![ident("n"), symbol("!")]));
        assert_eq!(ok("\\sum"), op("∑", OpKind::Large));
        assert_eq!(ok("\\int"), op("∫", OpKind::Large));
        for name in [
            "prod",
            "mp",
            "times",
            "approx",
            "geq",
            "leq",
            "notin",
            "subset",
            "cup",
            "cap",
            "forall",
            "exists",
            "perp",
            "parallel",
            "angle",
            "circ",
            "rightarrow",
            "leftarrow",
            "Rightarrow",
            "Leftrightarrow",
            "mapsto",
        ] {
            assert!(parse(&format!("\\{name}")).is_ok(), "\\{name}");
        }
    }

    #[test]
    fn functions_are_upright_names() {
        assert_eq!(
            ok("\\sin\\theta"),
            row(vec![Math::Function("sin".into()), ident("θ")])
        );
        assert_eq!(ok("\\atan2(y, x)"), {
            row(vec![
                Math::Function("atan2".into()),
                op("(", OpKind::Open),
                ident("y"),
                op(",", OpKind::Punct),
                ident("x"),
                op(")", OpKind::Close),
            ])
        });
        assert_eq!(ok("\\operatorname{rank}"), Math::Function("rank".into()));
        assert_eq!(ok("\\operatorname{atan2}"), Math::Function("atan2".into()));
        for name in ["cos", "tan", "cot", "ln", "exp", "dim", "max", "min"] {
            assert_eq!(ok(&format!("\\{name}")), Math::Function(name.into()));
        }
    }

    #[test]
    fn text_keeps_spaces() {
        assert_eq!(
            ok("v \\text{ if } x"),
            row(vec![ident("v"), Math::Text(" if ".into()), ident("x")])
        );
        assert_eq!(ok("\\text{a\\_b \\{c\\}}"), Math::Text("a_b {c}".into()));
    }

    #[test]
    fn font_styles() {
        assert_eq!(ok("\\mathbf{v}"), styled("v", Variant::Bold));
        assert_eq!(
            ok("\\mathbf{0}"),
            Math::Number {
                text: "0".into(),
                variant: Variant::Bold
            }
        );
        assert_eq!(
            ok("\\mathrm{d}x"),
            row(vec![styled("d", Variant::Upright), ident("x")])
        );
        assert_eq!(ok("\\mathrm{kg}"), styled("kg", Variant::Upright));
        assert_eq!(ok("\\mathcal{L}"), ident("L"));
        assert_eq!(ok("\\mathbb{R}"), styled("R", Variant::DoubleStruck));
        assert_eq!(
            ok("\\boldsymbol{\\omega}"),
            styled("ω", Variant::BoldItalic)
        );
        // The style ends with its argument.
        assert_eq!(
            ok("\\mathbf{a}b"),
            row(vec![styled("a", Variant::Bold), ident("b")])
        );
    }

    #[test]
    fn sub_and_superscripts() {
        assert_eq!(ok("x^2"), scripts(ident("x"), None, Some(number("2"))));
        assert_eq!(ok("x_i"), scripts(ident("x"), Some(ident("i")), None));
        assert_eq!(
            ok("x_{ij}^{2}"),
            scripts(
                ident("x"),
                Some(row(vec![ident("i"), ident("j")])),
                Some(number("2"))
            )
        );
        assert_eq!(
            ok("x^2_i"),
            scripts(ident("x"), Some(ident("i")), Some(number("2")))
        );
        // One character is one argument, as in TeX.
        assert_eq!(
            ok("x^12"),
            row(vec![
                scripts(ident("x"), None, Some(number("1"))),
                number("2")
            ])
        );
        assert_eq!(ok("R^T"), scripts(ident("R"), None, Some(ident("T"))));
        assert_eq!(ok("R^\\top"), scripts(ident("R"), None, Some(symbol("⊤"))));
        assert_eq!(
            ok("e^{-x}"),
            scripts(
                ident("e"),
                None,
                Some(row(vec![op("−", OpKind::Binary), ident("x")]))
            )
        );
        assert_eq!(
            ok("\\sum_{i=1}^n"),
            scripts(
                op("∑", OpKind::Large),
                Some(row(vec![
                    ident("i"),
                    op("=", OpKind::Relation),
                    number("1")
                ])),
                Some(ident("n"))
            )
        );
        assert_eq!(ok("^2"), scripts(row(vec![]), None, Some(number("2"))));
    }

    #[test]
    fn primes() {
        assert_eq!(ok("f'"), row(vec![ident("f"), symbol("′")]));
        assert_eq!(ok("f''"), row(vec![ident("f"), symbol("″")]));
        assert_eq!(
            ok("f'(x)"),
            row(vec![
                ident("f"),
                symbol("′"),
                op("(", OpKind::Open),
                ident("x"),
                op(")", OpKind::Close),
            ])
        );
        assert_eq!(
            ok("x'_i"),
            scripts(row(vec![ident("x"), symbol("′")]), Some(ident("i")), None)
        );
    }

    #[test]
    fn fractions_and_roots() {
        assert_eq!(ok("\\frac{a}{b}"), frac(ident("a"), ident("b")));
        assert_eq!(ok("\\frac12"), frac(number("1"), number("2")));
        assert_eq!(ok("\\frac\\pi 2"), frac(ident("π"), number("2")));
        assert_eq!(
            ok("\\frac{a+b}{2}"),
            frac(
                row(vec![ident("a"), op("+", OpKind::Binary), ident("b")]),
                number("2")
            )
        );
        assert_eq!(
            ok("\\sqrt{x}"),
            Math::Sqrt {
                index: None,
                body: Box::new(ident("x"))
            }
        );
        assert_eq!(
            ok("\\sqrt[3]{x^2}"),
            Math::Sqrt {
                index: Some(Box::new(number("3"))),
                body: Box::new(scripts(ident("x"), None, Some(number("2"))))
            }
        );
    }

    #[test]
    fn accents() {
        assert_eq!(ok("\\dot{x}"), accent(AccentKind::Dot, ident("x")));
        assert_eq!(ok("\\dot x"), accent(AccentKind::Dot, ident("x")));
        assert_eq!(ok("\\ddot\\theta"), accent(AccentKind::Ddot, ident("θ")));
        assert_eq!(ok("\\hat{n}"), accent(AccentKind::Hat, ident("n")));
        assert_eq!(ok("\\bar x"), accent(AccentKind::Bar, ident("x")));
        assert_eq!(
            ok("\\overline{AB}"),
            accent(AccentKind::Bar, row(vec![ident("A"), ident("B")]))
        );
        assert_eq!(ok("\\vec v"), accent(AccentKind::Vec, ident("v")));
        assert_eq!(ok("\\tilde{q}"), accent(AccentKind::Tilde, ident("q")));
        assert_eq!(
            ok("v = r\\dot\\varphi"),
            row(vec![
                ident("v"),
                op("=", OpKind::Relation),
                ident("r"),
                accent(AccentKind::Dot, ident("φ")),
            ])
        );
        assert_eq!(
            ok("\\dot{x}^2"),
            scripts(accent(AccentKind::Dot, ident("x")), None, Some(number("2")))
        );
    }

    #[test]
    fn fenced() {
        assert_eq!(
            ok("\\left( \\frac{a}{b} \\right)"),
            Math::Fenced {
                open: Delimiter::LeftParen,
                close: Delimiter::RightParen,
                body: Box::new(frac(ident("a"), ident("b"))),
            }
        );
        assert_eq!(
            ok("\\left\\{ x \\right."),
            Math::Fenced {
                open: Delimiter::LeftBrace,
                close: Delimiter::None,
                body: Box::new(ident("x")),
            }
        );
        assert_eq!(
            ok("\\left| x \\right|"),
            Math::Fenced {
                open: Delimiter::Bar,
                close: Delimiter::Bar,
                body: Box::new(ident("x")),
            }
        );
        assert_eq!(
            ok("\\left[ x \\right]"),
            Math::Fenced {
                open: Delimiter::LeftBracket,
                close: Delimiter::RightBracket,
                body: Box::new(ident("x")),
            }
        );
    }

    #[test]
    fn matrices() {
        let two_by_two = vec![vec![ident("a"), ident("b")], vec![ident("c"), ident("d")]];
        assert_eq!(
            ok("\\begin{bmatrix} a & b \\\\ c & d \\end{bmatrix}"),
            Math::Matrix {
                kind: MatrixKind::Bracket,
                rows: two_by_two.clone(),
            }
        );
        assert_eq!(
            ok("\\begin{pmatrix} a & b \\\\ c & d \\\\ \\end{pmatrix}"),
            Math::Matrix {
                kind: MatrixKind::Paren,
                rows: two_by_two.clone(),
            }
        );
        assert_eq!(
            ok("\\begin{vmatrix}a&b\\\\c&d\\end{vmatrix}"),
            Math::Matrix {
                kind: MatrixKind::Bar,
                rows: two_by_two,
            }
        );
        assert_eq!(
            ok("\\begin{matrix} \\cos\\theta & -\\sin\\theta \\end{matrix}"),
            Math::Matrix {
                kind: MatrixKind::Plain,
                rows: vec![vec![
                    row(vec![Math::Function("cos".into()), ident("θ")]),
                    row(vec![
                        op("−", OpKind::Binary),
                        Math::Function("sin".into()),
                        ident("θ")
                    ]),
                ]],
            }
        );
        assert_eq!(
            MatrixKind::Bracket.delimiters(),
            (Delimiter::LeftBracket, Delimiter::RightBracket)
        );
        assert_eq!(
            MatrixKind::Plain.delimiters(),
            (Delimiter::None, Delimiter::None)
        );
    }

    #[test]
    fn spaces_and_groups() {
        assert_eq!(
            ok("a\\,b\\;c\\quad d~e"),
            row(vec![
                ident("a"),
                Math::Space(3.0 / 18.0),
                ident("b"),
                Math::Space(5.0 / 18.0),
                ident("c"),
                Math::Space(1.0),
                ident("d"),
                Math::Space(INTERWORD_SPACE),
                ident("e"),
            ])
        );
        assert_eq!(
            ok("a{+}b"),
            row(vec![
                ident("a"),
                Math::Group(Box::new(op("+", OpKind::Binary))),
                ident("b"),
            ])
        );
        assert_eq!(ok("{}"), Math::Group(Box::new(row(vec![]))));
        assert_eq!(ok("x % a comment\n"), ident("x"));
    }

    #[test]
    fn error_unknown_command() {
        let e = err("a + \\foo");
        assert_eq!(e.position, 4);
        assert_eq!(e.message, "unknown command \\foo");
        assert_eq!(e.to_string(), "unknown command \\foo at column 5");
        assert!(err("\\text{\\alpha}").message.contains("\\alpha"));
        assert_eq!(
            err("\\begin{foo}x\\end{foo}").message,
            "unknown environment foo"
        );
    }

    #[test]
    fn error_unbalanced_braces() {
        let e = err("x^{2");
        assert_eq!(e.position, 2);
        assert!(e.message.contains("unbalanced"), "{e}");
        let e = err("x}");
        assert_eq!(e.position, 1);
        assert!(e.message.contains("unbalanced"), "{e}");
        assert!(err("\\text{abc").message.contains("unbalanced"));
    }

    #[test]
    fn error_left_right() {
        let e = err("a \\left( b");
        assert_eq!(e.position, 2);
        assert_eq!(e.message, "\\left without matching \\right");
        assert_eq!(err("b \\right)").message, "\\right without matching \\left");
        assert!(
            err("\\left x \\right)")
                .message
                .contains("missing delimiter")
        );
    }

    #[test]
    fn error_environments() {
        let e = err("\\begin{bmatrix} a & b");
        assert_eq!(e.position, 0);
        assert!(e.message.contains("without matching \\end"), "{e}");
        let e = err("\\begin{bmatrix} a \\end{pmatrix}");
        assert_eq!(e.position, 18);
        assert!(e.message.contains("ended by"), "{e}");
        assert!(err("a \\end{bmatrix}").message.contains("\\end without"));
        assert!(err("a & b").message.contains("&"));
        assert!(err("a \\\\ b").message.contains("matrix"));
    }

    #[test]
    fn error_missing_arguments() {
        assert_eq!(err("\\frac{a}").message, "missing argument to \\frac");
        assert_eq!(err("\\frac").message, "missing argument to \\frac");
        assert_eq!(err("{\\frac{a}}").message, "missing argument to \\frac");
        assert!(err("\\sqrt").message.contains("\\sqrt"));
        assert!(err("\\dot").message.contains("\\dot"));
        assert!(err("x^").message.contains("superscript"));
        assert!(err("x_").message.contains("subscript"));
        assert!(err("x^2^3").message.contains("double superscript"));
        assert!(err("x_1_2").message.contains("double subscript"));
        assert!(err("x \\").message.contains("lone"));
    }

    #[test]
    fn nesting_is_bounded() {
        let deep = |n: usize| format!("{}x{}", "{".repeat(n), "}".repeat(n));
        assert!(parse(&deep(10)).is_ok());
        assert!(err(&deep(200)).message.contains("nested too deeply"));
        let chain = "\\dot".repeat(500) + "x";
        assert!(err(&chain).message.contains("nested too deeply"));
        let scripts = "x^".repeat(500) + "y";
        assert!(parse(&scripts).is_err());
    }

    #[test]
    fn unicode_input_is_accepted() {
        assert_eq!(
            ok("θ ≤ π"),
            row(vec![ident("θ"), op("≤", OpKind::Relation), ident("π")])
        );
        // Byte offsets count the two-byte Greek letter.
        assert_eq!(err("θ\\foo").position, 2);
    }

    proptest! {
        #[test]
        fn arbitrary_strings_never_panic(src in ".{0,64}") {
            let _ = parse(&src);
        }

        #[test]
        fn tex_like_soup_never_panics(tokens in proptest::collection::vec(
            prop_oneof![
                Just("\\frac"), Just("\\sqrt"), Just("["), Just("]"), Just("{"), Just("}"),
                Just("^"), Just("_"), Just("'"), Just("&"), Just("\\\\"), Just("x"), Just("2.5"),
                Just("\\left("), Just("\\right)"), Just("\\left."), Just("\\begin{bmatrix}"),
                Just("\\end{bmatrix}"), Just("\\end{pmatrix}"), Just("\\dot"), Just("\\text{a b}"),
                Just("\\alpha"), Just("\\mathbf"), Just("\\operatorname{rank}"), Just(" "),
                Just("\\"), Just("\\,"), Just("+"), Just("\\le"), Just("é"), Just("\\text{"),
            ],
            0..40,
        )) {
            let _ = parse(&tokens.concat());
        }
    }
}
