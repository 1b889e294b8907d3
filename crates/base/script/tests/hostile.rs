#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! Random hostile scripts: lists nested in lists, strings that double,
//! maps that grow, recursion, function pointers and anonymous functions,
//! long prints and notes that wrap themselves, in random loops. Whatever
//! the mix, every call ends (answered or stopped with one of the
//! sandbox's errors) within its deadline plus a second, and the host
//! never panics or overflows its stack.

use kinolab_script::value::number;
use kinolab_script::{ErrorKind, LIMITS, Script, Signature};
use proptest::prelude::*;

const CONTROL: Signature = Signature {
    name: "control",
    params: &["rho", "alpha", "beta"],
};

/// One hostile statement, repeated `n` times in a loop.
fn fragment(kind: usize, n: u32) -> String {
    let body = match kind {
        0 => "a = [a];",
        1 => "a.push(a.len());",
        2 => "s += s;",
        3 => "m[`k${i}`] = [i, s];",
        4 => "x = deeper(i % 40);",
        5 => "x = Fn(\"deeper\").call(i % 5);",
        6 => "let twice = |y| y * 2; x = twice.call(i);",
        7 => "print(a);",
        8 => "x = if i in a { 1 } else { 0 };",
        9 => "this.k = [this.k, i];",
        10 => "let copy = a; x = copy.len();",
        11 => "s = `${s}${a}`;",
        12 => "m = #{ inner: m, i: i };",
        _ => "x += 1;",
    };
    format!("for i in 0..{n} {{ {body} }}")
}

fn script(parts: &[(usize, u32)]) -> String {
    let body: Vec<String> = parts.iter().map(|(k, n)| fragment(*k, *n)).collect();
    format!(
        "fn deeper(n) {{ if n > 0 {{ deeper(n - 1) }} else {{ 0 }} }}\n\
         fn control(rho, alpha, beta) {{\n  let a = []; let s = \"ab\"; let m = #{{}}; let x = 0;\n  {}\n  [0.0, 0.0]\n}}",
        body.join("\n  ")
    )
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn hostile_scripts_end_within_their_deadline(
        parts in prop::collection::vec((0..14_usize, 1..4000_u32), 1..5)
    ) {
        let source = script(&parts);
        let mut s = Script::compile(&source, CONTROL).unwrap();
        // Twenty calls of the run (a deadline per call, each checked).
        for k in 0..20 {
            let started = std::time::Instant::now();
            let args = vec![number(1.0), number(0.5), number(-0.25)];
            let result = s.call(args, k as f64 * 0.01);
            let took = started.elapsed().as_secs_f64();
            prop_assert!(took < LIMITS.call_seconds + 1.0, "{took:.1} s: {source}");
            if let Err(e) = result {
                prop_assert!(
                    !matches!(e.kind, ErrorKind::Syntax | ErrorKind::Missing),
                    "{e}: {source}"
                );
                prop_assert!(!e.message.is_empty());
                break;
            }
        }
    }
}
