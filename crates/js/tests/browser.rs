#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! The JS API and the lesson loader, run in headless Chromium.
#![cfg(target_arch = "wasm32")]

use wasm_bindgen::JsValue;
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

fn get(value: &JsValue, key: &str) -> JsValue {
    js_sys_get(value, key)
}

#[wasm_bindgen::prelude::wasm_bindgen]
extern "C" {
    #[wasm_bindgen(js_namespace = Reflect, js_name = get)]
    fn js_sys_get(target: &JsValue, key: &str) -> JsValue;
}

#[wasm_bindgen_test]
fn embedded_lessons_load_in_the_browser() {
    let course = kinolab_lessons::bundled::course().unwrap();
    assert_eq!(course.units[0].slug, "automation");
    assert!(course.lesson("automation/open-and-closed-worlds").is_some());
    let list = kinolab_js::lessons().unwrap();
    let first = get(&list, "0");
    assert_eq!(
        get(&first, "address").as_string().unwrap(),
        "automation/open-and-closed-worlds"
    );
    assert!(get(&first, "quizzes").as_f64().unwrap() >= 3.0);
}

#[wasm_bindgen_test]
fn leg_events_through_the_js_api() {
    assert_eq!(kinolab_js::leg_events(6).unwrap(), "39916800");
    assert!(kinolab_js::leg_events(0).is_err());
}

#[wasm_bindgen_test]
fn stability_through_the_js_api() {
    let com = serde_wasm_bindgen::to_value(&[0.5, 0.2]).unwrap();
    let feet = serde_wasm_bindgen::to_value(&[[1.0, 1.0], [-1.0, 1.0], [-1.0, -1.0], [1.0, -1.0]])
        .unwrap();
    let s = kinolab_js::static_stability(com, feet).unwrap();
    assert_eq!(get(&s, "stable").as_bool(), Some(true));
    assert!((get(&s, "margin").as_f64().unwrap() - 0.5).abs() < 1e-12);
    let bad = kinolab_js::static_stability(JsValue::from_str("nope"), JsValue::NULL);
    assert!(bad.is_err());
}

#[wasm_bindgen_test]
fn a_broken_lesson_names_the_line() {
    let error = kinolab_lessons::parse_lesson("x.md", "---\ntitle: T\nminutes: 3\nobjectives:\n  - a\n---\n```quiz\nkind: poem\nquestion: q\nexplain: e\n```\n")
        .unwrap_err();
    assert_eq!(
        error.to_string(),
        "x.md:7: unknown quiz kind `poem` (expected single, multiple or numeric)"
    );
    assert!(kinolab_js::check_lesson("x.md", "no front matter").is_err());
}

#[wasm_bindgen_test]
fn pick_cell_through_the_js_api() {
    let run = kinolab_js::pick_cell(0.02, 0.01, 0.0, 10, 3).unwrap();
    assert!((get(&run, "scriptedSuccess").as_f64().unwrap() - 0.25).abs() < 1e-12);
    assert_eq!(get(&run, "sensingGrasped").as_f64(), Some(10.0));
}
