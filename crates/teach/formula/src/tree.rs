//! The formula tree: what a parsed formula is made of. Leaves already hold
//! the final Unicode text (`\alpha` is stored as `α`, `-` as `−`), so a
//! renderer never sees TeX.

/// How deeply groups, arguments and environments may nest inside one formula.
pub const MAX_NESTING: usize = 64;

/// A parsed formula.
///
/// Rows with a single element are unwrapped, so `\frac{a}{b}` has the two
/// identifiers as its numerator and denominator, not one-element rows.
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Math {
    /// Atoms side by side, such as `a + b`.
    Row(Vec<Math>),
    /// A braced group `{…}` inside a row; it behaves as one ordinary atom.
    Group(Box<Math>),
    /// A variable name, normally one letter (`x`, `θ`); a whole word in
    /// upright or bold styles (`\mathrm{max}`).
    Ident { text: String, variant: Variant },
    /// A number, possibly with a decimal part (`3.14`).
    Number { text: String, variant: Variant },
    /// An ordinary symbol without spacing of its own (`∞`, `∂`, `′`, `!`, `|`).
    Symbol(String),
    /// An operator, relation, fence or punctuation mark; `kind` decides spacing.
    Op { text: String, kind: OpKind },
    /// A named function set upright (`sin`, `atan2`, `\operatorname{rank}`).
    Function(String),
    /// Upright prose from `\text{…}`, spaces kept.
    Text(String),
    /// Horizontal space in em (negative for `\!`).
    Space(f32),
    /// `\frac{num}{den}`.
    Frac { num: Box<Math>, den: Box<Math> },
    /// A base with a subscript, a superscript or both.
    Scripts {
        base: Box<Math>,
        sub: Option<Box<Math>>,
        sup: Option<Box<Math>>,
    },
    /// `\sqrt{body}` or `\sqrt[index]{body}`.
    Sqrt {
        index: Option<Box<Math>>,
        body: Box<Math>,
    },
    /// A mark above the body: `\dot x`, `\hat{n}`, `\overline{AB}`.
    Accent { kind: AccentKind, body: Box<Math> },
    /// `\left( … \right)`: delimiters that grow with the body.
    Fenced {
        open: Delimiter,
        close: Delimiter,
        body: Box<Math>,
    },
    /// A matrix-like environment; every row is a list of cells.
    Matrix {
        kind: MatrixKind,
        rows: Vec<Vec<Math>>,
    },
}

/// The letter style TeX would use for an identifier or number.
///
/// Renderers without an italic font may draw `Italic` and `Upright` alike.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Variant {
    /// The default for single Latin and lower-case Greek letters.
    Italic,
    /// Numbers, capital Greek letters, `\mathrm{…}`.
    Upright,
    /// `\mathbf{…}`: vectors and matrices.
    Bold,
    /// `\boldsymbol{…}` / `\bm{…}`.
    BoldItalic,
    /// `\mathbb{…}`: number sets such as ℝ. The text stays the plain letter.
    DoubleStruck,
}

/// What an operator is, which decides the space around it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum OpKind {
    /// `+ − · × ±`: medium space on both sides (none when used as a sign).
    Binary,
    /// `= ≤ → ∈`: thick space on both sides.
    Relation,
    /// `, ;`: thin space after.
    Punct,
    /// `∑ ∏ ∫`: drawn larger; scripts may go above and below.
    Large,
    /// An opening fence that does not grow: `(` `[` `{`.
    Open,
    /// A closing fence that does not grow: `)` `]` `}`.
    Close,
}

/// The mark drawn by an accent command.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum AccentKind {
    /// `\dot`: one dot, a time derivative.
    Dot,
    /// `\ddot`: two dots, a second derivative.
    Ddot,
    /// `\hat`, `\widehat`: a circumflex.
    Hat,
    /// `\bar`, `\overline`: a bar.
    Bar,
    /// `\vec`, `\overrightarrow`: an arrow.
    Vec,
    /// `\tilde`, `\widetilde`: a tilde.
    Tilde,
}

/// A delimiter that stretches to the height of what it encloses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Delimiter {
    /// `.`: nothing is drawn.
    None,
    LeftParen,
    RightParen,
    LeftBracket,
    RightBracket,
    LeftBrace,
    RightBrace,
    /// `|`
    Bar,
    /// `\|`
    DoubleBar,
    LeftAngle,
    RightAngle,
    LeftFloor,
    RightFloor,
    LeftCeil,
    RightCeil,
}

/// Which matrix-like environment a [`Math::Matrix`] came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum MatrixKind {
    /// `matrix`: no delimiters.
    Plain,
    /// `pmatrix`: ( )
    Paren,
    /// `bmatrix`: [ ]
    Bracket,
    /// `Bmatrix`: { }
    Brace,
    /// `vmatrix`: | |, a determinant.
    Bar,
    /// `Vmatrix`: ‖ ‖
    DoubleBar,
    /// `cases`: a left brace, cells aligned left.
    Cases,
    /// `aligned`: equations aligned at `&`, columns alternately right and left.
    Aligned,
}

impl MatrixKind {
    /// The delimiters drawn around this environment.
    pub fn delimiters(self) -> (Delimiter, Delimiter) {
        match self {
            Self::Plain | Self::Aligned => (Delimiter::None, Delimiter::None),
            Self::Paren => (Delimiter::LeftParen, Delimiter::RightParen),
            Self::Bracket => (Delimiter::LeftBracket, Delimiter::RightBracket),
            Self::Brace => (Delimiter::LeftBrace, Delimiter::RightBrace),
            Self::Bar => (Delimiter::Bar, Delimiter::Bar),
            Self::DoubleBar => (Delimiter::DoubleBar, Delimiter::DoubleBar),
            Self::Cases => (Delimiter::LeftBrace, Delimiter::None),
        }
    }

    pub(crate) fn from_environment(name: &str) -> Option<Self> {
        Some(match name {
            "matrix" => Self::Plain,
            "pmatrix" => Self::Paren,
            "bmatrix" => Self::Bracket,
            "Bmatrix" => Self::Brace,
            "vmatrix" => Self::Bar,
            "Vmatrix" => Self::DoubleBar,
            "cases" => Self::Cases,
            "aligned" => Self::Aligned,
            _ => return None,
        })
    }
}
