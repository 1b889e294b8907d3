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
    let course = kinolab_js::lessons().unwrap();
    let first = get(&get(&get(&get(&course, "units"), "0"), "lessons"), "0");
    assert_eq!(
        get(&first, "address").as_string().unwrap(),
        "automation/open-and-closed-worlds"
    );
    assert!(get(&first, "quizzes").as_f64().unwrap() >= 3.0);
}

#[wasm_bindgen_test]
fn leg_events_through_the_js_api() {
    let six = kinolab_js::leg_events(6).unwrap();
    assert_eq!(get(&six, "events").as_string().unwrap(), "39916800");
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
        "x.md:7: unknown quiz kind `poem` (expected single, multiple, numeric or sort)"
    );
    assert!(kinolab_js::check_lesson("x.md", "no front matter").is_err());
}

#[wasm_bindgen_test]
fn pick_cell_through_the_js_api() {
    let run = kinolab_js::pick_cell(0.02, 0.01, 0.0, 10, 3).unwrap();
    assert!((get(&run, "scripted_success").as_f64().unwrap() - 0.25).abs() < 1e-12);
    assert_eq!(get(&run, "sensing_grasped").as_f64(), Some(10.0));
}

#[wasm_bindgen_test]
fn wheel_analysis_through_the_js_api() {
    let a = kinolab_js::analyze_robot(JsValue::from_str("synchro-drive")).unwrap();
    assert_eq!(get(&a, "degree_of_mobility").as_f64(), Some(1.0));
    assert_eq!(get(&a, "degree_of_steerability").as_f64(), Some(1.0));
    assert_eq!(get(&a, "dof").as_f64(), Some(2.0));
    assert_eq!(
        get(&get(&a, "icr"), "kind").as_string().unwrap(),
        "infinity"
    );
    // A robot-file object works as well as an id.
    let file = kinolab_js::robot_file(JsValue::from_str("tricycle")).unwrap();
    let a = kinolab_js::analyze_robot(file).unwrap();
    assert_eq!(get(&a, "degree_of_maneuverability").as_f64(), Some(2.0));
    let bad = kinolab_js::analyze_robot(JsValue::from_str("f,90,0,0.25,0"))
        .err()
        .unwrap();
    let message: JsValue = bad.into();
    assert!(format!("{message:?}").contains("radius"));
}

#[wasm_bindgen_test]
fn siegwart_example_through_the_js_api() {
    let robot = JsValue::from_str("f,-90,180,1,1;f,90,0,1,1");
    let spins = serde_wasm_bindgen::to_value(&[Some(4.0), Some(2.0)]).unwrap();
    let fk =
        kinolab_js::drive_wheels(robot.clone(), spins, Some(std::f64::consts::FRAC_PI_2)).unwrap();
    let inertial = get(&fk, "twist_inertial");
    assert!((get(&inertial, "1").as_f64().unwrap() - 3.0).abs() < 1e-12);
    assert!((get(&inertial, "2").as_f64().unwrap() - 1.0).abs() < 1e-12);
    let twist = serde_wasm_bindgen::to_value(&[0.0, 1.0, 0.0]).unwrap();
    let ik = kinolab_js::drive_twist(robot, twist, None).unwrap();
    assert_eq!(get(&ik, "feasible").as_bool(), Some(false));
    let dd = kinolab_js::differential_drive(0.5, 0.2, 0.4).unwrap();
    assert!((get(&dd, "omega").as_f64().unwrap() - 0.4).abs() < 1e-12);
}

const RUN: &str = r#"{"controller":{"kind":"polar","k_rho":3,"k_alpha":8,"k_beta":-1.5},
  "start":{"x":-1,"y":0.5,"theta_deg":0},"goal":{"x":0,"y":0,"theta_deg":0}}"#;

#[wasm_bindgen_test]
fn controller_through_the_js_api() {
    let out = kinolab_js::simulate(JsValue::from_str(RUN)).unwrap();
    assert_eq!(get(&out, "reached").as_bool(), Some(true));
    let t = get(&out, "time_to_goal").as_f64().unwrap();
    assert!((5.0..7.0).contains(&t), "{t}");
    let first = js_sys_get(&get(&out, "samples"), "0");
    assert!((get(&first, "v").as_f64().unwrap() - 3.0 * 1.25f64.sqrt()).abs() < 1e-12);

    let batch = kinolab_js::batch_simulate(JsValue::from_str(RUN), 1.0, 12, 0.0, None).unwrap();
    assert_eq!(get(&batch, "all_reached").as_bool(), Some(true));
    assert_eq!(get(&batch, "reached").as_f64(), Some(12.0));

    let s = kinolab_js::controller_stability(3.0, 2.0, -1.5).unwrap();
    assert_eq!(get(&s, "locally_stable").as_bool(), Some(false));
    let Err(bad) = kinolab_js::simulate(JsValue::from_str(&RUN.replace("\"k_rho\"", "\"k_r\"")))
    else {
        panic!("accepted an unknown gain");
    };
    let message = get(&JsValue::from(bad), "message").as_string().unwrap();
    assert!(
        message.starts_with("run: controller: unknown field `k_r`"),
        "{message}"
    );
}

fn parse(json: &str) -> JsValue {
    js_sys_parse(json)
}

#[wasm_bindgen::prelude::wasm_bindgen]
extern "C" {
    #[wasm_bindgen(js_namespace = JSON, js_name = parse)]
    fn js_sys_parse(text: &str) -> JsValue;
}

#[wasm_bindgen_test]
fn mechanisms_through_the_js_api() {
    let puma = kinolab_js::Mechanism::load(JsValue::from_str("catalogue:puma560")).unwrap();
    let fk = puma.fk(vec![0.0; 6], None).unwrap();
    let row = js_sys_get(&get(&fk, "matrix"), "0");
    assert!((js_sys_get(&row, "3").as_f64().unwrap() - 0.4521).abs() < 1e-12);

    let arm = kinolab_js::Mechanism::load(JsValue::from_str("planar-2r")).unwrap();
    let s = arm.ik(parse(r#"{"position":[1.2,0.6,0]}"#)).unwrap();
    assert_eq!(get(&s, "converged").as_bool(), Some(true));
    let jac = arm.jacobian(vec![0.0, 0.5], None).unwrap();
    // ∂y/∂q1 at q = (0, 0.5): the arm's reach along x, 1 + 0.8 cos 0.5.
    let vy = js_sys_get(&get(&jac, "rows"), "1");
    let want = 1.0 + 0.8 * 0.5f64.cos();
    assert!((js_sys_get(&vy, "0").as_f64().unwrap() - want).abs() < 1e-12);

    let hit = arm
        .collide(
            vec![0.0, 0.0],
            "plan",
            parse(r#"[{"circle":[1.5,0.05,0.1]}]"#),
        )
        .unwrap();
    assert_eq!(get(&hit, "colliding").as_bool(), Some(true));

    let linkage = kinolab_js::Mechanism::load(JsValue::from_str("four-bar")).unwrap();
    let info = linkage.describe().unwrap();
    assert_eq!(get(&info, "dof").as_f64(), Some(3.0));

    // A URDF file's text loads too: the Panda's seven arm joints and two
    // fingers, the second following the first.
    let urdf = include_str!("../../../body/mechanism/robots/panda.urdf");
    let panda = kinolab_js::Mechanism::load(JsValue::from_str(urdf)).unwrap();
    assert_eq!(get(&panda.describe().unwrap(), "dof").as_f64(), Some(9.0));
    let link1 = panda.fk(vec![0.0; 9], Some("panda_link1".into())).unwrap();
    let row = js_sys_get(&get(&link1, "matrix"), "2");
    assert_eq!(js_sys_get(&row, "3").as_f64(), Some(0.333));
    // The robots shipped with the lab load by id: the UR5's six joints.
    let ur5 = kinolab_js::Mechanism::load(JsValue::from_str("catalogue:ur5")).unwrap();
    assert_eq!(get(&ur5.describe().unwrap(), "dof").as_f64(), Some(6.0));
    // And any model goes out as URDF that loads back.
    let four_bar = kinolab_js::Mechanism::load(JsValue::from_str("catalogue:four-bar")).unwrap();
    let written = four_bar.to_urdf().unwrap();
    let notices = get(&written, "notices");
    assert_eq!(
        get(&notices, "length").as_f64(),
        Some(1.0),
        "the loop is left open"
    );
    let back = kinolab_js::Mechanism::load(get(&written, "urdf")).unwrap();
    assert_eq!(get(&back.describe().unwrap(), "dof").as_f64(), Some(3.0));

    let Err(bad) = kinolab_js::Mechanism::load(JsValue::from_str("catalogue:warp-drive")) else {
        panic!("accepted an unknown mechanism");
    };
    let message = get(&JsValue::from(bad), "message").as_string().unwrap();
    assert!(
        message.starts_with("model: no built-in mechanism"),
        "{message}"
    );
}

#[wasm_bindgen_test]
fn fields_and_behaviours_through_the_js_api() {
    let field = JsValue::from_str("catalogue:u-shaped-wall");
    let area = serde_wasm_bindgen::to_value(&[0.0, -2.5, 7.0, 2.5]).unwrap();
    let m = get(
        &kinolab_js::field_minima(field.clone(), area).unwrap(),
        "minima",
    );
    // The trap where the back wall's push 2 (1 − d/0.5) meets the pull 1,
    // and the goal.
    let trap = get(&m, "0");
    assert!((get(&trap, "x").as_f64().unwrap() - 3.75).abs() < 1e-9);
    assert_eq!(get(&get(&m, "1"), "goal").as_bool(), Some(true));
    let start = serde_wasm_bindgen::to_value(&[0.5, 0.3]).unwrap();
    let d = kinolab_js::field_descend(field, start, None, None).unwrap();
    assert_eq!(get(&d, "outcome").as_string().unwrap(), "trapped");
    let run = JsValue::from_str(include_str!(
        "../../../mind/behaviours/runs/subsumption.run.json"
    ));
    let r = kinolab_js::run_behaviours(run).unwrap();
    assert_eq!(get(&get(&r, "metrics"), "reached").as_bool(), Some(true));
    let bad = kinolab_js::field_minima(JsValue::from_str("catalogue:nowhere"), JsValue::NULL);
    assert!(bad.is_err());
}

#[wasm_bindgen_test]
fn the_architecture_arena_through_the_js_api() {
    let world = JsValue::from_str("catalogue:office");
    let options =
        parse(r#"{ "architecture": "reactive", "perturb": ["glass:8.2,0,8.2,3.2"], "every": 50 }"#);
    let r = kinolab_js::arena(world.clone(), options).unwrap();
    let m = get(&r, "metrics");
    // The fly at the window: no plan, no way round the glass.
    assert_eq!(get(&m, "reached").as_bool(), Some(false));
    assert!(get(&m, "collisions").as_f64().unwrap() >= 20.0);
    let options = parse(r#"{ "architecture": "hybrid", "perturb": ["door:1,1@2"] }"#);
    assert!(kinolab_js::arena(world, options).is_err());
    let feeds = parse(
        "[[false,false,false,false,true],[false,false,false,false,true],[false,false,false,false,true],[false,false,false,false,true],[false,false,false,false,true],[false,false,false,false,true]]",
    );
    let routes = kinolab_js::routes(feeds).unwrap();
    assert_eq!(
        get(&routes, "paradigm").as_string().unwrap(),
        "hierarchical"
    );
}

#[wasm_bindgen_test]
fn components_run_through_the_js_api() {
    let r = kinolab_js::components(JsValue::from_str("example:out-of-order"), None).unwrap();
    let counts = get(&r, "counts");
    assert_eq!(get(&counts, "messages").as_f64(), Some(6.0));
    assert_eq!(get(&r, "complete").as_bool(), Some(true));
    let robot = kinolab_js::components(JsValue::from_str("example:robot"), Some(40.0)).unwrap();
    let pose = get(&robot, "robot");
    assert!((get(&pose, "0").as_f64().unwrap() - 9.0).abs() < 0.3);
    let bad = parse(r#"{ "components": [] }"#);
    assert!(kinolab_js::components(bad, None).is_err());
}

#[wasm_bindgen::prelude::wasm_bindgen]
extern "C" {
    #[wasm_bindgen(js_namespace = JSON, js_name = stringify)]
    fn js_sys_stringify(value: &JsValue) -> String;
}

/// The glue changes nothing: a function's value is the API's JSON, as
/// JavaScript reads it.
#[wasm_bindgen_test]
fn the_glue_returns_the_api_report_unchanged() {
    let same = |from_js: JsValue, native: kinolab_js::calls::Reply| {
        let native = parse(&native.unwrap().to_string());
        assert_eq!(js_sys_stringify(&from_js), js_sys_stringify(&native));
    };
    let run = JsValue::from_str(RUN);
    same(
        kinolab_js::simulate(run).unwrap(),
        kinolab_js::calls::simulate(serde_json::Value::String(RUN.into())),
    );
    same(
        kinolab_js::analyze_robot(JsValue::from_str("uranus-mecanum")).unwrap(),
        kinolab_js::calls::analyze_robot(serde_json::json!("uranus-mecanum")),
    );
    same(
        kinolab_js::gait(JsValue::from_str("catalogue:hexapod-wave"), Some(24)).unwrap(),
        kinolab_js::calls::gait(serde_json::json!("catalogue:hexapod-wave"), Some(24)),
    );
    let puma = kinolab_js::Mechanism::load(JsValue::from_str("puma560")).unwrap();
    let model = kinolab_js::calls::load_mechanism(serde_json::json!("puma560")).unwrap();
    same(
        puma.jacobian(vec![0.1, 0.8, -0.6, 0.3, 0.5, -0.2], None)
            .unwrap(),
        kinolab_js::calls::on(
            &model,
            &kinolab_api::mechanism::Jacobian {
                q: vec![0.1, 0.8, -0.6, 0.3, 0.5, -0.2],
                frame: None,
            },
        ),
    );
}

/// Hostile code in the page: each stops its own run with a message that
/// names what and where, and the page goes on to grade the next script.
#[wasm_bindgen_test]
fn hostile_scripts_stop_in_the_browser_and_the_page_goes_on() {
    let cases = [
        ("fn control(rho, alpha, beta) {\n loop { }\n}", "endless", 2),
        (
            "fn deeper(n) {\n deeper(n + 1)\n}\nfn control(rho, alpha, beta) { deeper(0) }",
            "too_deep",
            2,
        ),
        (
            "fn control(rho, alpha, beta) {\n let a = [];\n a.pad(100000000, 0);\n [0.0, 0.0]\n}",
            "too_large",
            3,
        ),
        (
            "fn control(rho, alpha, beta) {\n let s = \"x\";\n loop { s += s; }\n}",
            "too_large",
            3,
        ),
        (
            "fn control(rho, alpha, beta) {\n #{ v: 1.0 }\n}",
            "shape",
            2,
        ),
        (
            "fn control(rho, alpha, beta) {\n [0.0 / 0.0, 1.0]\n}",
            "not_finite",
            2,
        ),
    ];
    for (source, kind, line) in cases {
        let report =
            kinolab_js::check_script("control-park".into(), source.into(), Some(false)).unwrap();
        assert_eq!(get(&report, "passed").as_bool(), Some(false), "{source}");
        let error = get(&report, "error");
        assert_eq!(
            get(&error, "kind").as_string().as_deref(),
            Some(kind),
            "{source}"
        );
        assert_eq!(
            get(&error, "line").as_f64(),
            Some(f64::from(line)),
            "{source}"
        );
        assert!(
            get(&error, "message")
                .as_string()
                .unwrap()
                .contains("t = 0.00 s")
        );
    }
    // The page is still alive: the model law passes every world.
    let model = "fn control(rho, alpha, beta) { let v = 3.0 * rho; let w = 8.0 * alpha - 1.5 * beta; let k = max(1.0, max(abs(v) / 0.5, abs(w) / 2.0)); [v / k, w / k] }";
    let report = kinolab_js::check_script("control-park".into(), model.into(), Some(true)).unwrap();
    assert_eq!(get(&report, "passed").as_bool(), Some(true));
}
