#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! The sandbox holds: hostile scripts stop with the documented message
//! and the host goes on; syntax errors name their line and column;
//! `this` keeps notes between calls; `print` and `plot` are kept per call.

use kinolab_script::value::{finite, number};
use kinolab_script::{ErrorKind, Script, Signature};

const CONTROL: Signature = Signature {
    name: "control",
    params: &["rho", "alpha", "beta"],
};

fn compile(source: &str) -> Script {
    Script::compile(source, CONTROL).unwrap_or_else(|e| panic!("{e}"))
}

fn call(script: &mut Script, t: f64) -> Result<[f64; 2], kinolab_script::ScriptError> {
    let args = vec![number(1.0), number(0.5), number(-0.25)];
    let out = script.call(args, t)?;
    finite(&out.value, ["v", "omega"], CONTROL, t).map_err(|e| script.place(e))
}

#[test]
fn a_law_returns_its_command() {
    let mut s = compile("fn control(rho, alpha, beta) { [3.0 * rho, 8.0 * alpha - 1.5 * beta] }");
    assert_eq!(call(&mut s, 0.0).unwrap(), [3.0, 4.375]);
}

#[test]
fn hostile_scripts_stop_with_a_message_in_words() {
    let cases = [
        (
            "fn control(rho, alpha, beta) { loop { } }",
            ErrorKind::Endless,
            "your function did more than 100 000 steps at t = 3.20 s: is there a loop that never ends?",
        ),
        (
            "fn deeper(n) { deeper(n + 1) } fn control(rho, alpha, beta) { deeper(0) }",
            ErrorKind::TooDeep,
            "more than 32 deep at t = 3.20 s",
        ),
        (
            "fn control(rho, alpha, beta) { let a = []; a.pad(100000000, 0); [0.0, 0.0] }",
            ErrorKind::TooLarge,
            "a list of more than 1 000 items (counting the items of lists inside it) at t = 3.20 s",
        ),
        (
            "fn control(rho, alpha, beta) { let s = \"x\"; loop { s += s; } }",
            ErrorKind::TooLarge,
            "does something grow every time round a loop?",
        ),
        (
            "fn control(rho, alpha, beta) { #{ v: 1.0 } }",
            ErrorKind::Shape,
            "`control` must return [v, omega], 2 numbers; at t = 3.20 s it returned `#{\"v\": 1.0}`",
        ),
        (
            "fn control(rho, alpha, beta) { [0.0 / 0.0, 1.0] }",
            ErrorKind::NotFinite,
            "`control` returned NaN for v at t = 3.20 s",
        ),
        (
            "fn control(rho, alpha, beta) { [speed, 1.0] }",
            ErrorKind::Runtime,
            "there is no variable `speed` here",
        ),
    ];
    for (source, kind, words) in cases {
        let mut s = compile(source);
        let e = call(&mut s, 3.2).unwrap_err();
        assert_eq!(e.kind, kind, "{source}: {e}");
        assert!(e.message.contains(words), "{source}: {}", e.message);
        assert_eq!(e.t, Some(3.2));
        assert!(e.line.is_some() && e.column.is_some(), "{source}: {e:?}");
        // The host goes on: the same script can be called again.
        assert!(call(&mut s, 3.25).is_err());
    }
}

/// A run as the simulations make it: up to 2 000 calls, one every
/// 0.01 s, until one fails. Gives the error (if any) and the seconds taken.
fn run(source: &str) -> (Option<kinolab_script::ScriptError>, f64) {
    let mut s = compile(source);
    let started = std::time::Instant::now();
    let error = (0..2000).find_map(|k| call(&mut s, k as f64 * 0.01).err());
    (error, started.elapsed().as_secs_f64())
}

#[test]
fn runaway_scripts_stop_within_a_second_of_their_deadline() {
    use kinolab_script::LIMITS;
    let law = |body: &str| format!("fn control(rho, alpha, beta) {{\n{body}\n[0.0, 0.0]\n}}");
    let cases = [
        // Lists nested inside lists: bounded by the list's size, counted
        // through the nesting, long before the stack is in danger.
        (
            law("let a = []; for i in 0..5000 { a = [a]; }"),
            Some(ErrorKind::TooLarge),
        ),
        (
            law("let a = []; loop { a = [a]; }"),
            Some(ErrorKind::TooLarge),
        ),
        (
            law("let a = []; for i in 0..100000 { a.push(i); }"),
            Some(ErrorKind::TooLarge),
        ),
        // Each search of a long list is charged its length.
        (
            law("let a = []; a.pad(950, 1.5); for i in 0..20 { if 2.5 in a { print(i); } }"),
            Some(ErrorKind::TooSlow),
        ),
        // A thousand lines a call: each print is charged 50 steps.
        (
            law("for i in 0..1000 { print(i); }"),
            Some(ErrorKind::TooSlow),
        ),
        // A long list printed often: the text is charged.
        (
            law("let a = []; a.pad(999, 0.123456789); for i in 0..200 { print(a); }"),
            Some(ErrorKind::Endless),
        ),
        // Copying a long list over and over: each copy is one step.
        (
            law("let a = []; a.pad(999, 1.5); let n = 0; while n < 10000 { let b = a; n += 1; }"),
            Some(ErrorKind::TooSlow),
        ),
        // Notes that wrap themselves once a call.
        (law("this.a = [this.a];"), Some(ErrorKind::TooLarge)),
    ];
    for (source, kind) in cases {
        let (error, seconds) = run(&source);
        assert_eq!(error.as_ref().map(|e| e.kind), kind, "{source}: {error:?}");
        if let Some(e) = &error {
            assert!(
                e.line.is_some() || e.kind == ErrorKind::TooLarge,
                "{source}: {e:?}"
            );
        }
        assert!(
            seconds < LIMITS.run_seconds + 1.0,
            "{source}: {seconds:.1} s"
        );
    }
}

#[test]
fn a_run_of_heavy_calls_stops_once_its_budget_is_spent() {
    // Each call stays under the per-call bound, but 10 million operations
    // in all would freeze a tab for seconds.
    let mut s = compile(
        "fn control(rho, alpha, beta) {\n    let n = 0;\n    while n < 5000 { n += 1; }\n    [0.0, 0.0]\n}",
    );
    let mut calls = 0;
    let e = loop {
        match call(&mut s, calls as f64 * 0.01) {
            Ok(_) => calls += 1,
            Err(e) => break e,
        }
        assert!(calls < 3000, "never stopped");
    };
    assert_eq!(e.kind, ErrorKind::TooSlow, "{e}");
    assert!(e.message.contains("10 000 000 steps in all"), "{e}");
    assert!((100..1000).contains(&calls), "{calls} calls");
    // A copy made before the run spent anything starts afresh.
    let fresh = compile("fn control(rho, alpha, beta) { [rho, 0.0] }");
    let mut copy = fresh.clone();
    assert!(call(&mut copy, 0.0).is_ok());
}

#[test]
fn the_sandbox_s_stops_name_the_line_that_caused_them() {
    let cases = [
        (
            "fn control(rho, alpha, beta) {\n    let n = 0;\n    while rho > 0.0 {\n        n += 1;\n    }\n}",
            [3, 4],
        ),
        (
            "fn deeper(n) {\n    deeper(n + 1)\n}\nfn control(rho, alpha, beta) {\n    deeper(0)\n}",
            [2, 2],
        ),
        (
            "fn control(rho, alpha, beta) {\n    let a = [];\n    a.pad(100000000, 0);\n    [0.0, 0.0]\n}",
            [3, 3],
        ),
        // A wrong answer: the line that gave it.
        (
            "fn control(rho, alpha, beta) {\n    if rho > 0.5 {\n        return #{ v: 1.0 };\n    }\n    [0.0, 0.0]\n}",
            [3, 3],
        ),
    ];
    for (source, lines) in cases {
        let mut s = compile(source);
        let e = call(&mut s, 1.0).unwrap_err();
        let line = e.line.unwrap();
        assert!(lines[0] <= line && line <= lines[1], "{source}: {e:?}");
        // `this` is as it was: the search ran on a copy.
        assert_eq!(s.memory().to_string(), "#{}");
    }
}

#[test]
fn errors_name_their_line_and_column() {
    let e = Script::compile(
        "fn control(rho, alpha, beta) {\n  let v = ;\n  [v, 0.0]\n}",
        CONTROL,
    )
    .unwrap_err();
    assert_eq!(
        (e.kind, e.line, e.column),
        (ErrorKind::Syntax, Some(2), Some(11)),
        "{e}"
    );
    let mut s = compile("fn control(rho, alpha, beta) {\n  [rho,\n   alpha + nope]\n}");
    let e = call(&mut s, 1.0).unwrap_err();
    assert_eq!((e.line, e.kind), (Some(3), ErrorKind::Runtime), "{e}");
    let e = Script::compile("fn control(rho, alpha) { [0.0, 0.0] }", CONTROL).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Missing);
    assert!(e.message.contains("takes 3 parameters"), "{e}");
    let e = Script::compile("fn steer(x) { x }", CONTROL).unwrap_err();
    assert!(e.message.contains("has no function `control`"), "{e}");
}

#[test]
fn this_keeps_notes_between_calls_and_copies_keep_theirs() {
    let mut s = compile(
        "fn control(rho, alpha, beta) { if this.n == () { this.n = 0 } this.n += 1; [this.n * 1.0, 0.0] }",
    );
    assert_eq!(call(&mut s, 0.0).unwrap()[0], 1.0);
    assert_eq!(call(&mut s, 0.1).unwrap()[0], 2.0);
    let mut copy = s.clone();
    assert_eq!(call(&mut copy, 0.2).unwrap()[0], 3.0);
    assert_eq!(call(&mut copy, 0.3).unwrap()[0], 4.0);
    assert_eq!(
        call(&mut s, 0.2).unwrap()[0],
        3.0,
        "the original's notes are its own"
    );
}

#[test]
fn print_and_plot_are_kept_per_call() {
    let mut s = compile(
        "fn control(rho, alpha, beta) { print(`rho is ${rho}`); plot(\"rho\", rho); plot(\"k\", 2); [rho, 0.0] }",
    );
    let out = s
        .call(vec![number(1.5), number(0.0), number(0.0)], 0.0)
        .unwrap();
    assert_eq!(out.output.prints, vec!["rho is 1.5"]);
    assert_eq!(
        out.output.plots,
        vec![("rho".to_owned(), 1.5), ("k".to_owned(), 2.0)]
    );
    let out = s
        .call(vec![number(2.0), number(0.0), number(0.0)], 0.1)
        .unwrap();
    assert_eq!(
        out.output.prints,
        vec!["rho is 2.0"],
        "a fresh call starts empty"
    );
}

#[test]
fn text_joins_numbers_as_interpolation_writes_them() {
    let mut s = compile(
        "fn control(rho, alpha, beta) {\n  print(\"rho \" + rho + \", step \" + 3 + \", near \" + (rho < 1.0));\n  print(rho + \" m\");\n  let s = \"a\"; s += 2.5; print(s);\n  [rho, 0.0]\n}",
    );
    let out = s
        .call(vec![number(2.0), number(0.0), number(0.0)], 0.0)
        .unwrap();
    assert_eq!(
        out.output.prints,
        vec!["rho 2.0, step 3, near false", "2.0 m", "a2.5"]
    );
}

#[test]
fn trigonometry_is_the_cores_bit_for_bit() {
    let f = Signature {
        name: "f",
        params: &["x"],
    };
    let mut s = Script::compile(
        "fn f(x) { [sin(x), cos(x), atan2(x, 0.3), atan(x, 0.3), exp(x), hypot(x, 2.0)] }",
        f,
    )
    .unwrap();
    for x in [0.1, 1.2345, -2.5, 100.0] {
        let out = s.call(vec![number(x)], 0.0).unwrap();
        let got = finite(
            &out.value,
            ["sin", "cos", "atan2", "atan", "exp", "hypot"],
            f,
            0.0,
        )
        .unwrap();
        let t = kinolab_common::trig::atan2(x, 0.3);
        let want = [
            kinolab_common::trig::sin(x),
            kinolab_common::trig::cos(x),
            t,
            t,
            libm::exp(x),
            libm::hypot(x, 2.0),
        ];
        assert_eq!(got.map(f64::to_bits), want.map(f64::to_bits), "x = {x}");
    }
}

/// Runs `body` as `fn f() { … }` and prints what it returns.
fn shown(body: &str) -> String {
    let f = Signature {
        name: "f",
        params: &[],
    };
    let mut s =
        Script::compile(&format!("fn f() {{ {body} }}"), f).unwrap_or_else(|e| panic!("{e}"));
    match s.call(Vec::new(), 0.0) {
        Ok(out) => out.value.to_string(),
        Err(e) => format!("error: {e}"),
    }
}

#[test]
fn lists_and_maps_have_the_functions_a_learner_reaches_for() {
    let cases = [
        (
            "let a = [1, 2]; a.push(3.5); [a.len(), a.pop(), a.len()]",
            "[3, 3.5, 2]",
        ),
        (
            "let a = [4, 5, 6]; let x = a.shift(); [x, a]",
            "[4, [5, 6]]",
        ),
        (
            "let a = [1, 3]; a.insert(1, 2); a.insert(-1, 9); a",
            "[1, 2, 9, 3]",
        ),
        (
            "let a = [1, 2, 3]; [a.remove(-1), a.remove(7), a]",
            "[3, (), [1, 2]]",
        ),
        (
            "let a = [1, 2.0, \"x\"]; [2 in a, \"x\" in a, 5 in a, a.index_of(\"x\")]",
            "[true, true, false, 2]",
        ),
        (
            "let a = []; for x in [1, 2, 3] { a.push(x * x); } a + [0]",
            "[1, 4, 9, 0]",
        ),
        (
            "let a = [1]; a += [2]; a.append([3]); [a, a == [1, 2, 3], a != [1, 2], [].is_empty()]",
            "[[1, 2, 3], true, true, true]",
        ),
        (
            "let a = [0]; a.pad(3, 7); a.clear(); [a.len(), a.pop(), a.shift()]",
            "[0, (), ()]",
        ),
        (
            "let m = #{x: 1, y: 2}; [m.len(), \"x\" in m, \"z\" in m, m.keys(), m.values()]",
            "[2, true, false, [\"x\", \"y\"], [1, 2]]",
        ),
        (
            "let m = #{x: 1, y: 2}; let x = m.remove(\"x\"); [x, m, m.remove(\"q\"), #{}.is_empty()]",
            "[1, #{\"y\": 2}, (), true]",
        ),
        ("let m = #{x: 1}; m.clear(); m.len()", "0"),
        (
            "let x = 3; [-x, -2.5 < x, 1 < 2.0, !(x > 2), 7 % 3, 2 ** 3, 5 / 2, 5.0 / 2]",
            "[-3, true, true, false, 1, 8, 2, 2.5]",
        ),
        (
            "[abs(-3), sign(-0.5), sign(4), min(2, 0.5), max(1, 3), (2.7).floor(), ceiling(2.1)]",
            "[3, -1, 1, 0.5, 3, 2.0, 3.0]",
        ),
        (
            "[round(2.5), to_int(-2.7), to_float(3), (7).is_odd(), log(100.0), to_degrees(PI())]",
            "[3.0, -2, 3.0, true, 2.0, 180.0]",
        ),
        (
            "[abs(-2.5), min(1, 2), max(1.5, 0.5), sqrt(4.0), floor(2.7), PI() > 3.14]",
            "[2.5, 1, 1.5, 2.0, 2.0, true]",
        ),
    ];
    for (body, want) in cases {
        assert_eq!(shown(body), want, "{body}");
    }
}

#[test]
fn numbers_that_do_not_fit_stop_with_an_overflow() {
    for body in [
        "abs(-9223372036854775807 - 1)",
        "to_int(1e30)",
        "9223372036854775807 + 1",
    ] {
        let shown = shown(body);
        assert!(shown.to_lowercase().contains("overflow"), "{body}: {shown}");
    }
}

#[test]
fn reading_past_the_end_of_a_list_names_the_line() {
    let f = Signature {
        name: "f",
        params: &[],
    };
    let mut s = Script::compile("fn f() {\n  let a = [1, 2, 3];\n  a[5]\n}", f).unwrap();
    let e = s.call(Vec::new(), 0.0).unwrap_err();
    assert_eq!(e.kind, ErrorKind::Runtime, "{e}");
    assert_eq!(e.line, Some(3), "{e:?}");
}

/// The first error `source` gives, compiling or calling `f(p)` once with
/// `p` a map the lab hands out.
fn first_error(source: &str) -> kinolab_script::ScriptError {
    use kinolab_script::value::{map, numbers};
    let f = Signature {
        name: "f",
        params: &["p"],
    };
    let mut s = match Script::compile(source, f) {
        Ok(s) => s,
        Err(e) => return e,
    };
    let bumpers = map([("front", false.into()), ("left", false.into())]);
    let p = map([
        ("rays", numbers(&[1.0, 2.0])),
        ("bumpers", bumpers),
        ("t", number(0.5)),
    ]);
    s.call(vec![p], 0.5).unwrap_err()
}

#[test]
fn errors_speak_a_beginners_language() {
    let cases = [
        // Whole numbers where decimals belong: the call rewritten.
        (
            "fn f(p) {\n  sqrt(9)\n}",
            (2, "`sqrt` takes a decimal number: write `sqrt(9.0)`"),
        ),
        (
            "fn f(p) {\n  let x = 4;\n  atan2(x, 2.0)\n}",
            (
                3,
                "`atan2` takes a decimal number, and was given a whole number",
            ),
        ),
        // A key the lab's map does not have: what it has instead.
        (
            "fn f(p) {\n  if p.bumper.front { 1 } else { 0 }\n}",
            (2, "`p` has no `bumper`; it has `bumpers`, `rays`, `t`"),
        ),
        (
            "fn f(p) {\n  p.bumpers.frnt\n}",
            (2, "`p.bumpers` has no `frnt`; it has `front`, `left`"),
        ),
        // A missing `;` is blamed on the line it is missing from.
        (
            "fn f(p) {\n  let a = 1\n  return a;\n}",
            (2, "a `;` is missing at the end of this line"),
        ),
        // Characters pasted from a formula or a slide.
        (
            "fn f(p) {\n  1.0 − p.t\n}",
            (
                2,
                "`−` (a minus sign from a formula) is not understood here: type the ASCII `-` instead",
            ),
        ),
        (
            "fn f(p) {\n  let θ = 1.0;\n}",
            (
                2,
                "`θ` (the Greek letter theta) is not understood here: type `theta` instead",
            ),
        ),
        ("fn f(p) {\n  p.t ≤ 1.0\n}", (2, "type `<=` instead")),
        // Nothing, where a number belongs.
        (
            "fn f(p) {\n  this.count + 1\n}",
            (2, "`+` was given `()` (nothing) and a whole number"),
        ),
        (
            "fn f(p) {\n  let a = [1, 2];\n  a[2]\n}",
            (
                3,
                "asked for item 2 of a list of 2: items are numbered from 0 to 1",
            ),
        ),
    ];
    for (source, (line, words)) in cases {
        let e = first_error(source);
        assert!(e.message.contains(words), "{source}\n{}", e.message);
        assert_eq!(e.line, Some(line), "{source}: {e:?}");
    }
    // `a[2]`: the syntax error's column is where the `;` belongs.
    let e = first_error("fn f(p) {\n  let a = 1\n  return a;\n}");
    assert_eq!(e.column, Some(12), "{e:?}");
}

#[test]
fn a_learners_own_map_answers_nothing_for_a_key_not_yet_set() {
    let f = Signature {
        name: "f",
        params: &[],
    };
    let mut s = Script::compile(
        "fn f() { let m = #{}; let before = m.size; m.size = 2; [before, m.size, this.turn, this.n] }",
        f,
    )
    .unwrap();
    let out = s.call(Vec::new(), 0.0).unwrap();
    assert_eq!(out.value.to_string(), "[(), 2, (), ()]");
}

#[test]
fn a_byte_order_mark_is_not_code() {
    let mut s = compile("\u{feff}fn control(rho, alpha, beta) { [rho, 0.0] }");
    assert_eq!(call(&mut s, 0.0).unwrap(), [1.0, 0.0]);
}

#[test]
fn lists_nested_to_the_bound_are_written_copied_and_dropped_on_a_small_stack() {
    // 999 levels, on a thread with a quarter of a test thread's stack
    // (a browser's is about 1 MB): printing, joining into text, comparing,
    // searching and dropping all work a level at a time, or stop early.
    let worker = std::thread::Builder::new().stack_size(512 * 1024).spawn(|| {
        let f = Signature {
            name: "f",
            params: &[],
        };
        let mut s = Script::compile(
            "fn f() { let a = []; for i in 0..999 { a = [a]; } let b = a; print(a); let t = `${a}`; [a == b, [] in a, t.len() < 200] }",
            f,
        )
        .unwrap();
        s.call(Vec::new(), 0.0).map(|c| (c.value.to_string(), c.output.prints))
    });
    let (value, prints) = worker.unwrap().join().unwrap().unwrap();
    assert_eq!(value, "[true, false, true]");
    assert!(
        prints[0].starts_with("[[[[") && prints[0].contains('…'),
        "{prints:?}"
    );
}

#[test]
fn nothing_is_neither_true_nor_false_but_compares_unequal() {
    let f = Signature {
        name: "f",
        params: &[],
    };
    let mut s = Script::compile("fn f() { this.turning == true }", f).unwrap();
    assert_eq!(s.call(Vec::new(), 0.0).unwrap().value.to_string(), "false");
    let mut s = Script::compile("fn f() { if this.turning { 1 } else { 2 } }", f).unwrap();
    let e = s.call(Vec::new(), 0.0).unwrap_err();
    assert!(
        e.message
            .contains("expected true or false here, not `()` (nothing)"),
        "{e}"
    );
}
