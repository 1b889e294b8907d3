#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! The lesson format: front-matter, blocks, widgets, quizzes, and the
//! errors malformed files give.

use kinolab_lessons::{Answer, AnswerError, Block, Course, QuizKind, Span, parse_lesson};

const HEADER: &str =
    "---\ntitle: Test lesson\nminutes: 7\nobjectives:\n  - First aim\n  - Second aim\n---\n";

fn lesson(body: &str) -> Vec<Block> {
    match parse_lesson("test.md", &format!("{HEADER}{body}")) {
        Ok((_, blocks)) => blocks,
        Err(e) => panic!("should parse: {e}"),
    }
}

fn error(source: &str) -> String {
    match parse_lesson("bad.md", source) {
        Ok(_) => panic!("should not parse:\n{source}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn front_matter_fields_are_read() {
    let (fm, blocks) = parse_lesson("t.md", &format!("{HEADER}Hello.\n")).unwrap();
    assert_eq!(fm.title, "Test lesson");
    assert_eq!(fm.minutes, 7);
    assert_eq!(fm.objectives, vec!["First aim", "Second aim"]);
    assert_eq!(blocks.len(), 1);
}

#[test]
fn headings_paragraphs_and_emphasis() {
    let blocks = lesson("## Wheels\n\nA *steered* wheel and a **fixed** one.\n");
    let Block::Heading { level, text } = &blocks[0] else {
        panic!("{blocks:?}")
    };
    assert_eq!(*level, 2);
    assert_eq!(
        *text,
        vec![Span::Text {
            text: "Wheels".into(),
            style: Default::default()
        }]
    );
    let Block::Paragraph(spans) = &blocks[1] else {
        panic!()
    };
    let styled: Vec<(String, bool, bool)> = spans
        .iter()
        .filter_map(|s| match s {
            Span::Text { text, style } => Some((text.clone(), style.emphasis, style.strong)),
            _ => None,
        })
        .collect();
    assert_eq!(
        styled,
        vec![
            ("A ".into(), false, false),
            ("steered".into(), true, false),
            (" wheel and a ".into(), false, false),
            ("fixed".into(), false, true),
            (" one.".into(), false, false),
        ]
    );
}

#[test]
fn lists_tables_code_links_and_images() {
    let blocks = lesson(
        "1. one\n2. two\n\n| a | b |\n|:--|--:|\n| 1 | 2 |\n\n```rust\nlet x = 1;\n```\n\nSee [the sheet](https://example.org) and ![a wheel](wheel.png).\n",
    );
    let Block::List { start, items } = &blocks[0] else {
        panic!("{blocks:?}")
    };
    assert_eq!(*start, Some(1));
    assert_eq!(items.len(), 2);
    let Block::Table {
        header,
        rows,
        align,
    } = &blocks[1]
    else {
        panic!()
    };
    assert_eq!(header.len(), 2);
    assert_eq!(rows.len(), 1);
    assert_eq!(
        align,
        &vec![kinolab_lessons::Align::Left, kinolab_lessons::Align::Right]
    );
    assert_eq!(
        blocks[2],
        Block::Code {
            lang: "rust".into(),
            text: "let x = 1;\n".into()
        }
    );
    let Block::Paragraph(spans) = &blocks[3] else {
        panic!()
    };
    assert!(spans.iter().any(|s| matches!(s, Span::Text { text, style } if text == "the sheet" && style.link.as_deref() == Some("https://example.org"))));
    assert!(spans.iter().any(
        |s| matches!(s, Span::Image { url, alt, .. } if url == "wheel.png" && alt == "a wheel")
    ));
}

#[test]
fn formulas_inline_and_display() {
    let blocks = lesson("Speed $v = r\\dot\\varphi$ here.\n\n$$\\frac{a}{b}$$\n");
    let Block::Paragraph(spans) = &blocks[0] else {
        panic!("{blocks:?}")
    };
    assert!(matches!(spans[1], Span::Math(_)));
    assert!(matches!(blocks[1], Block::Math(_)), "{:?}", blocks[1]);
}

#[test]
fn widget_block_names_a_widget_with_parameters() {
    let blocks = lesson("Text.\n\n```widget\nsupport-polygon\nlegs: 4\nshow margin: yes\n```\n");
    let Block::Widget(w) = &blocks[1] else {
        panic!("{blocks:?}")
    };
    assert_eq!(w.name, "support-polygon");
    assert_eq!(w.param("legs"), Some("4"));
    assert_eq!(w.param("show margin"), Some("yes"));
    assert_eq!(w.param("nothing"), None);
    assert_eq!(w.line, 10, "the fence is on file line 10");
}

#[test]
fn single_choice_quiz_is_checked() {
    let blocks = lesson(
        "```quiz\nkind: single\nquestion: Which is *closed*?\n- [ ] A street\n- [x] A fenced cell\nexplain: Nothing moves unless planned.\n```\n",
    );
    let Block::Quiz(q) = &blocks[0] else {
        panic!("{blocks:?}")
    };
    assert_eq!(q.options().len(), 2);
    assert_eq!(q.check(&Answer::Single(1)), Ok(true));
    assert_eq!(q.check(&Answer::Single(0)), Ok(false));
    assert_eq!(q.check(&Answer::Single(2)), Err(AnswerError::OutOfRange));
    assert_eq!(q.check(&Answer::Numeric(1.0)), Err(AnswerError::WrongKind));
}

#[test]
fn multiple_choice_needs_every_right_tick() {
    let blocks = lesson(
        "```quiz\nkind: multiple\nquestion: Pick the legged ones.\n- [x] Hexapod\n- [ ] Car\n- [x] Biped\nexplain: Legs.\n```\n",
    );
    let Block::Quiz(q) = &blocks[0] else { panic!() };
    assert_eq!(
        q.check(&Answer::Multiple(vec![true, false, true])),
        Ok(true)
    );
    assert_eq!(
        q.check(&Answer::Multiple(vec![true, false, false])),
        Ok(false)
    );
    assert_eq!(
        q.check(&Answer::Multiple(vec![true, true, true])),
        Ok(false)
    );
    assert_eq!(
        q.check(&Answer::Multiple(vec![true])),
        Err(AnswerError::OutOfRange)
    );
}

#[test]
fn numeric_quiz_uses_the_tolerance() {
    let blocks = lesson(
        "```quiz\nkind: numeric\nquestion: How many events for $k = 3$?\nanswer: 120\ntolerance: 0.5\nunit: events\nexplain: $5! = 120$.\n```\n",
    );
    let Block::Quiz(q) = &blocks[0] else { panic!() };
    assert_eq!(
        q.kind,
        QuizKind::Numeric {
            answer: 120.0,
            tolerance: 0.5,
            unit: Some("events".into())
        }
    );
    assert_eq!(q.check(&Answer::Numeric(120.4)), Ok(true));
    assert_eq!(q.check(&Answer::Numeric(120.6)), Ok(false));
    assert_eq!(
        q.check(&Answer::Numeric(f64::NAN)),
        Err(AnswerError::NotFinite)
    );
}

#[test]
fn numeric_quiz_with_zero_tolerance_accepts_the_written_decimal() {
    let blocks = lesson("```quiz\nkind: numeric\nquestion: q\nanswer: 0.3\nexplain: e\n```\n");
    let Block::Quiz(q) = &blocks[0] else { panic!() };
    assert_eq!(q.check(&Answer::Numeric(0.1 + 0.2)), Ok(true));
    assert_eq!(q.check(&Answer::Numeric(0.31)), Ok(false));
}

#[test]
fn unclosed_block_names_file_and_line() {
    let source = format!("{HEADER}Intro.\n\n```quiz\nkind: single\n");
    assert_eq!(
        error(&source),
        "bad.md:10: the ```quiz block opened here is never closed by a ``` line"
    );
}

#[test]
fn unknown_quiz_kind_names_file_and_line() {
    let source =
        format!("{HEADER}\n```quiz\nkind: essay\nquestion: Why?\nexplain: Because.\n```\n");
    assert_eq!(
        error(&source),
        "bad.md:9: unknown quiz kind `essay` (expected single, multiple, numeric or sort)"
    );
}

#[test]
fn quiz_mistakes_are_reported() {
    let two_right =
        format!("{HEADER}```quiz\nkind: single\nquestion: q\n- [x] a\n- [x] b\nexplain: e\n```\n");
    assert_eq!(
        error(&two_right),
        "bad.md:8: a single-choice quiz needs exactly one `- [x]` option, found 2"
    );
    let no_answer = format!("{HEADER}```quiz\nkind: numeric\nquestion: q\nexplain: e\n```\n");
    assert_eq!(error(&no_answer), "bad.md:8: the quiz has no `answer`");
    let bad_number =
        format!("{HEADER}```quiz\nkind: numeric\nquestion: q\nanswer: lots\nexplain: e\n```\n");
    assert_eq!(
        error(&bad_number),
        "bad.md:11: `answer` must be a finite number, found `lots`"
    );
    let stray = format!("{HEADER}```quiz\nkind: single\nwhat is this\n```\n");
    assert_eq!(
        error(&stray),
        "bad.md:10: expected `key: value` or an option `- [ ] …` in the quiz, found `what is this`"
    );
}

#[test]
fn bad_front_matter_names_file_and_line() {
    assert_eq!(
        error("# No front-matter\n"),
        "bad.md:1: a lesson must start with a front-matter block opened by `---`"
    );
    assert_eq!(
        error("---\ntitle: T\nminutes: ten\n---\n"),
        "bad.md:3: `minutes` must be a whole number, found `ten`"
    );
    assert_eq!(
        error("---\ntitle: T\nauthor: me\n---\n"),
        "bad.md:3: unknown front-matter key `author` (expected title, minutes or objectives)"
    );
    assert_eq!(
        error("---\ntitle: T\nminutes: 3\n"),
        "bad.md:1: the front-matter opened on line 1 is never closed by `---`"
    );
    assert_eq!(
        error("---\ntitle: T\nminutes: 3\n---\nBody\n"),
        "bad.md:4: the front-matter has no `objectives` (list at least one)"
    );
}

#[test]
fn bad_widget_and_formula_name_the_line() {
    let no_name = format!("{HEADER}```widget\n\n```\n");
    assert_eq!(
        error(&no_name),
        "bad.md:9: a widget block needs the widget's name on its first line"
    );
    let bad_math = format!("{HEADER}Text\n\nMore $\\frac{{a}}$ here.\n");
    let message = error(&bad_math);
    assert!(
        message.starts_with("bad.md:10: in formula `\\frac{a}`"),
        "{message}"
    );
}

#[test]
fn course_orders_units_and_lessons_and_finds_neighbours() {
    let unit = "---\ntitle: Unit A\n---\nSummary.\n";
    let l1 = format!("{HEADER}One.\n");
    let course = Course::from_files([
        ("02-second/unit.md", unit),
        ("01-first/02-b.md", l1.as_str()),
        ("01-first/unit.md", unit),
        ("01-first/01-a.md", l1.as_str()),
        ("02-second/01-c.md", l1.as_str()),
        ("README.md", "ignored"),
    ])
    .unwrap();
    assert_eq!(course.addresses(), vec!["first/a", "first/b", "second/c"]);
    assert!(course.lesson("first/b").is_some());
    assert!(course.lesson("first/zzz").is_none());
    assert_eq!(
        course.neighbours("first/b"),
        (Some("first/a".into()), Some("second/c".into()))
    );
    assert_eq!(course.neighbours("first/a").0, None);
}

#[test]
fn a_unit_without_unit_md_is_an_error() {
    let l1 = format!("{HEADER}One.\n");
    let err = Course::from_files([("01-first/01-a.md", l1.as_str())]).unwrap_err();
    assert_eq!(
        err.to_string(),
        "first:1: this unit folder has no unit.md with a title"
    );
}

#[test]
fn an_outline_parses_a_body_when_it_is_first_shown() {
    let unit = "---\ntitle: Unit A\n---\nSummary.\n";
    let good = format!("{HEADER}One.\n");
    // A quiz of an unknown kind, on the body's third line.
    let bad = format!("{HEADER}Two.\n\n```quiz\nkind: poem\n```\n");
    let files = [
        ("01-first/unit.md", unit),
        ("01-first/01-a.md", good.as_str()),
        ("01-first/02-b.md", bad.as_str()),
    ];
    // The outline opens: front matter only.
    let outline = Course::outline(files).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(outline.addresses(), vec!["first/a", "first/b"]);
    let (_, a) = outline.lesson("first/a").unwrap();
    assert_eq!(a.blocks().map(<[Block]>::len), Ok(1));
    // The broken body says where when it is shown, and again when checked.
    let (_, b) = outline.lesson("first/b").unwrap();
    let shown = b.blocks().map_err(ToString::to_string).unwrap_err();
    assert!(shown.starts_with("01-first/02-b.md:"), "{shown}");
    assert_eq!(
        outline.check().map_err(|e| e.to_string()),
        Err(shown.clone())
    );
    // The checked course refuses it outright.
    let checked = Course::from_files(files).map_err(|e| e.to_string());
    assert_eq!(checked.unwrap_err(), shown);
}

#[test]
fn every_bundled_lesson_parses_and_has_a_quiz() {
    let course = kinolab_lessons::bundled::course().unwrap_or_else(|e| panic!("{e}"));
    assert!(!course.units.is_empty());
    for unit in &course.units {
        assert!(
            !unit.lessons.is_empty(),
            "unit {} has no lessons",
            unit.slug
        );
        for lesson in &unit.lessons {
            assert!(
                lesson
                    .blocks()
                    .unwrap_or_default()
                    .iter()
                    .any(|b| matches!(b, Block::Quiz(_))),
                "{}/{} has no quiz",
                unit.slug,
                lesson.slug
            );
        }
    }
}

#[test]
fn a_sorting_quiz_grades_every_item() {
    let blocks = lesson(
        "```quiz\nkind: sort\nquestion: Sort them.\nbins: EBT | BO | IO\n- Embodiment => EBT\n- AnyMorphology => BO :: a *design* pattern\n- a laser driver => IO\nexplain: Layers.\n```\n",
    );
    let Block::Quiz(q) = &blocks[0] else { panic!() };
    let QuizKind::Sort { bins, items } = &q.kind else {
        panic!()
    };
    assert_eq!(bins, &["EBT", "BO", "IO"]);
    assert_eq!(items.iter().map(|i| i.bin).collect::<Vec<_>>(), [0, 1, 2]);
    assert!(items[1].why.is_some() && items[0].why.is_none());
    assert_eq!(q.check(&Answer::Sort(vec![0, 1, 2])), Ok(true));
    assert_eq!(q.check(&Answer::Sort(vec![0, 2, 2])), Ok(false));
    assert_eq!(
        q.sort_marks(&Answer::Sort(vec![1, 1, 2])),
        Ok(vec![false, true, true])
    );
    assert_eq!(
        q.check(&Answer::Sort(vec![0, 1])),
        Err(AnswerError::OutOfRange)
    );
    assert_eq!(
        q.check(&Answer::Sort(vec![0, 1, 3])),
        Err(AnswerError::OutOfRange)
    );
    assert_eq!(q.check(&Answer::Single(0)), Err(AnswerError::WrongKind));
}

#[test]
fn malformed_sorting_quizzes_name_the_file_and_line() {
    let quiz = |body: &str| {
        format!(
            "---\ntitle: T\nminutes: 5\nobjectives:\n  - o\n---\n\n```quiz\nkind: sort\nquestion: q\nexplain: e\n{body}```\n"
        )
    };
    // Front matter is 6 lines, a blank, the fence at line 8; body from 12.
    let e = error(&quiz("bins: A | B\n- x => C\n- y => A\n"));
    assert!(
        e.contains(":13:") && e.contains("`C` is not one of the bins"),
        "{e}"
    );
    let e = error(&quiz("bins: A\n- x => A\n- y => A\n"));
    assert!(e.contains(":12:") && e.contains("2 to 6 distinct"), "{e}");
    let e = error(&quiz("- x => A\n- y => A\n"));
    assert!(e.contains("needs `bins"), "{e}");
    let e = error(&quiz("bins: A | B\n- x goes to A\n- y => A\n"));
    assert!(e.contains(":13:") && e.contains("`- text => bin`"), "{e}");
    let e = error(&quiz("bins: A | B\n- [x] x\n- y => A\n"));
    assert!(e.contains("items, not"), "{e}");
    let e = error(&quiz("bins: A | B\n- y => A\n"));
    assert!(e.contains("2 to 20 items"), "{e}");
}

#[test]
fn control_characters_are_refused_where_an_escape_was_meant() {
    // "sets $\nu = \beta v / L$" written from a string in which `\n` and
    // `\b` became a line feed and a backspace.
    let garbled = format!("{HEADER}Text first.\n\nThen it sets $\n u = \u{8}eta v / L$.\n");
    let e = error(&garbled);
    assert!(e.starts_with("bad.md:11:"), "{e}");
    assert!(e.contains("U+0008") && e.contains("`\\beta`"), "{e}");
    let tab = format!("{HEADER}The phase $\theta$ of a leg.\n");
    let e = error(&tab);
    assert!(e.starts_with("bad.md:8:"), "{e}");
    assert!(e.contains("U+0009") && e.contains("`\\theta`"), "{e}");
    let feed = format!("{HEADER}A speed ${{\n}}u$ now.\n");
    assert!(
        error(&feed).contains("U+000A"),
        "a line feed inside an inline formula"
    );
    // Line breaks, tabs that indent, and a display formula over several
    // lines are fine.
    lesson("A line,\r\nand another.\n\n- a list\n\n\t- indented by a tab\n\n$$\na = b\n$$\n");
}
