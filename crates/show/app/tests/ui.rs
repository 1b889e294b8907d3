#![allow(clippy::unwrap_used, clippy::expect_used)] // tests may stop at the first surprise
//! The lab driven the way a learner drives it: by labels, clicks and typing.

use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use kinolab_app::KinolabApp;
use kinolab_app::route::Page;

fn harness(app: KinolabApp) -> Harness<'static, KinolabApp> {
    let mut harness = animated(app);
    harness.run();
    harness
}

/// For pages with a running animation: the caller steps frames itself.
fn animated(app: KinolabApp) -> Harness<'static, KinolabApp> {
    lab(app, tall(1280.0))
}

/// A window `width` wide and tall enough for any page.
fn tall(width: f32) -> egui_kittest::HarnessBuilder<KinolabApp> {
    Harness::builder().with_size(egui::vec2(width, 16000.0))
}

/// The lab in the window `builder` describes.
fn lab(
    app: KinolabApp,
    builder: egui_kittest::HarnessBuilder<KinolabApp>,
) -> Harness<'static, KinolabApp> {
    builder.build_ui_state(|ui, app: &mut KinolabApp| app.show(ui), app)
}

const LESSON: &str = "automation/open-and-closed-worlds";

/// A quiz option's radio button (its text is also on the page as a label).
fn radio<'h>(h: &'h Harness<'static, KinolabApp>, text: &'h str) -> egui_kittest::Node<'h> {
    h.get_by_role_and_label(egui::accesskit::Role::RadioButton, text)
}

#[test]
fn opening_a_lesson_by_its_label_shows_it_and_records_the_visit() {
    let mut h = harness(KinolabApp::new(None, ""));
    assert_eq!(h.state().page(), &Page::Home);
    h.get_all_by_label("○ Open and closed worlds")
        .next()
        .unwrap()
        .click();
    h.run();
    assert_eq!(h.state().page(), &Page::Lesson(LESSON.into()));
    assert!(h.state().progress().visited.contains(LESSON));
    assert_eq!(
        h.state_mut().take_pending_hash().as_deref(),
        Some("#/automation/open-and-closed-worlds")
    );
    h.get_by_label("After this lesson you can");
}

#[test]
fn a_right_answer_is_praised_and_explained() {
    let mut h = harness(KinolabApp::new(None, &format!("#/{LESSON}")));
    radio(
        &h,
        "A palletising arm fed by a conveyor inside a fenced cell",
    )
    .click();
    h.run();
    h.get_all_by_label("Check answer").next().unwrap().click();
    h.run();
    h.get_by_label("Right.");
    h.get_by_label_contains("Inside the fenced cell the conveyor");
    let record = h.state().progress().quizzes[&format!("{LESSON}#0")];
    assert!(record.correct);
    assert_eq!(record.attempts, 1);
}

/// Press Tab until the node `is_it` finds has the keyboard focus; whether
/// it got there within a page's worth of controls.
fn tab_to(
    h: &mut Harness<'static, KinolabApp>,
    is_it: impl Fn(&Harness<'static, KinolabApp>) -> bool,
) -> bool {
    for _ in 0..300 {
        if is_it(h) {
            return true;
        }
        h.key_press(egui::Key::Tab);
        h.run();
    }
    false
}

#[test]
fn a_quiz_is_answered_with_the_keyboard_alone() {
    let mut h = harness(KinolabApp::new(None, &format!("#/{LESSON}")));
    let option = "A palletising arm fed by a conveyor inside a fenced cell";
    let focused = |h: &Harness<'static, KinolabApp>, node: egui_kittest::Node<'_>| {
        let _ = h;
        node.accesskit_node().is_focused()
    };
    assert!(
        tab_to(&mut h, |h| focused(h, radio(h, option))),
        "Tab never reaches the option"
    );
    h.key_press(egui::Key::Space);
    h.run();
    let check = |h: &Harness<'static, KinolabApp>| {
        h.get_all_by_label("Check answer")
            .next()
            .is_some_and(|b| b.accesskit_node().is_focused())
    };
    assert!(tab_to(&mut h, check), "Tab never reaches Check answer");
    h.key_press(egui::Key::Enter);
    h.run();
    h.get_by_label("Right.");
    assert!(h.state().progress().quizzes[&format!("{LESSON}#0")].correct);
}

#[test]
fn a_wrong_answer_is_flagged_then_can_be_corrected() {
    let mut h = harness(KinolabApp::new(None, &format!("#/{LESSON}")));
    radio(&h, "A lawn-mowing robot in a family garden").click();
    h.run();
    h.get_all_by_label("Check answer").next().unwrap().click();
    h.run();
    h.get_by_label("Not quite. Read why, then try again.");
    h.get_by_label_contains("Inside the fenced cell the conveyor");
    assert!(!h.state().progress().quizzes[&format!("{LESSON}#0")].correct);
    radio(
        &h,
        "A palletising arm fed by a conveyor inside a fenced cell",
    )
    .click();
    h.run();
    assert!(
        h.query_by_label("Not quite. Read why, then try again.")
            .is_none(),
        "changing the answer clears the verdict"
    );
    h.get_all_by_label("Check answer").next().unwrap().click();
    h.run();
    h.get_by_label("Right.");
    assert_eq!(
        h.state().progress().quizzes[&format!("{LESSON}#0")].attempts,
        2
    );
}

#[test]
fn a_numeric_answer_is_checked_within_its_tolerance() {
    let mut h = harness(KinolabApp::new(None, &format!("#/{LESSON}")));
    // The third quiz of the lesson asks for a percentage (answer 50 ± 0.5).
    let input = h.get_all_by_label("Your answer:").next().unwrap();
    input.focus();
    input.type_text("40");
    h.run();
    h.get_all_by_label("Check answer").nth(2).unwrap().click();
    h.run();
    assert!(!h.state().progress().quizzes[&format!("{LESSON}#2")].correct);
    h.get_by_label("Not quite. Read why, then try again.");
    let input = h.get_all_by_label("Your answer:").next().unwrap();
    input.focus();
    h.key_press(egui::Key::Backspace);
    h.key_press(egui::Key::Backspace);
    h.run();
    let input = h.get_all_by_label("Your answer:").next().unwrap();
    input.type_text("50,2");
    h.run();
    h.get_all_by_label("Check answer").nth(2).unwrap().click();
    h.run();
    assert!(h.state().progress().quizzes[&format!("{LESSON}#2")].correct);
}

#[test]
fn checking_without_an_answer_asks_for_one() {
    let mut h = harness(KinolabApp::new(None, &format!("#/{LESSON}")));
    h.get_all_by_label("Check answer").next().unwrap().click();
    h.run();
    h.get_by_label("Choose an answer first.");
    assert!(h.state().progress().quizzes.is_empty());
}

#[test]
fn next_and_previous_walk_the_course() {
    let mut h = harness(KinolabApp::new(None, &format!("#/{LESSON}")));
    h.get_by_label_contains("Next: ").click();
    h.run();
    assert_eq!(
        h.state().page(),
        &Page::Lesson("automation/ways-to-move".into())
    );
    h.get_by_label_contains("← Previous: ").click();
    h.run();
    assert_eq!(h.state().page(), &Page::Lesson(LESSON.into()));
}

#[test]
fn corrupted_progress_resets_with_a_visible_notice() {
    let h = harness(KinolabApp::new(
        Some("{\"version\": 1, \"visited\": oops"),
        "",
    ));
    h.get_by_label_contains("Your saved progress could not be read");
    assert!(h.state().progress().visited.is_empty());
}

/// A progress file from another computer adds to what is here and says
/// what it added; a foreign file changes nothing and says why.
#[test]
fn a_progress_file_merges_in_or_is_refused() {
    let other = {
        let mut a = KinolabApp::new(None, &format!("#/{LESSON}"));
        a.set_clock(1_000);
        a.progress_file()
    };
    let mut h = harness(KinolabApp::new(None, ""));
    h.state_mut().set_clock(2_000);
    h.state_mut()
        .load_progress_file("kinolab-progress.json", other.as_bytes());
    h.run();
    h.get_by_label_contains("Loaded kinolab-progress.json: 1 lesson opened.");
    assert!(h.state().progress().visited.contains(LESSON));
    let before = h.state().progress().clone();
    h.state_mut()
        .load_progress_file("notes.json", br#"{"version":2,"visited":["x/y"]}"#);
    h.run();
    h.get_by_label_contains(
        "notes.json was not loaded: it is not a Kinolab progress file. Your progress is unchanged.",
    );
    assert_eq!(h.state().progress(), &before);
    h.get_by_label("Save my progress");
    h.get_by_label("Load progress…");
}

/// Progress another tab stored joins this tab's; a blocked storage is said
/// once, with the file offered.
#[test]
fn another_tabs_progress_merges_and_blocked_storage_is_said_once() {
    let mut tab1 = KinolabApp::new(None, &format!("#/{LESSON}"));
    tab1.set_clock(10);
    let stored_by_tab1 = tab1.progress_json();
    let mut h = harness(KinolabApp::new(None, "#/wheeled-locomotion/wheel-kinds"));
    h.state_mut().merge_stored(&stored_by_tab1);
    let visited = &h.state().progress().visited;
    assert!(visited.contains(LESSON) && visited.contains("wheeled-locomotion/wheel-kinds"));
    h.state_mut().storage_failed();
    h.run();
    h.get_by_label_contains("This browser is not keeping your progress");
    h.get_by_label("Dismiss").click();
    h.run();
    h.state_mut().storage_failed();
    h.run();
    assert!(h.state().notice().is_none(), "said once");
}

#[test]
fn an_unknown_lesson_address_says_so() {
    let h = harness(KinolabApp::new(None, "#/automation/no-such-lesson"));
    h.get_by_label("Lesson not found");
}

#[test]
fn every_lesson_renders_without_widget_errors() {
    let app = KinolabApp::new(None, "");
    let addresses = app.course().unwrap().addresses();
    let mut h = harness(app);
    for address in addresses {
        eprintln!("rendering {address}");
        h.state_mut().follow_hash(&format!("#/{address}"));
        // The drive widget animates, so step a fixed number of frames.
        h.run_steps(6);
        assert!(
            h.query_by_label_contains("cannot be shown").is_none(),
            "{address} shows an error box"
        );
        assert!(h.query_by_label_contains("Lesson not found").is_none());
    }
}

/// The narrowest phone the lab supports, a small laptop and a desktop
/// window, in points.
const WIDTHS: [f32; 3] = [360.0, 1024.0, 1280.0];

#[test]
fn every_page_fits_the_window_on_a_phone_and_a_desktop() {
    let mut too_wide = Vec::new();
    for width in WIDTHS {
        let app = KinolabApp::new(None, "");
        let addresses = app.course().unwrap().addresses();
        let mut h = lab(app, tall(width));
        let widgets = kinolab_schema::widgets().map(|w| format!("gallery/{}", w.name));
        for address in widgets.chain(addresses) {
            h.state_mut().follow_hash(&format!("#/{address}"));
            h.run_steps(6);
            let (right, edge) = h.state().extent();
            assert!(edge > 0.0 && right > 0.0, "{address}: nothing measured");
            assert!(edge <= width + 0.5, "{address}: a screen of {edge}");
            if right > edge + 0.5 {
                too_wide.push(format!("{width} px, {address}: {right:.0} > {edge:.0}"));
            }
            // On a desktop, no table or formula has to scroll sideways
            // (one that almost fits used to, by less than a point).
            let scrolled = kinolab_widgets::widget::take_scrolled_sideways(&h.ctx);
            if width >= 1024.0 && !scrolled.is_empty() {
                too_wide.push(format!(
                    "{width} px, {address}: scrolls sideways by {scrolled:?}"
                ));
            }
        }
    }
    assert!(
        too_wide.is_empty(),
        "wider than the window:\n{}",
        too_wide.join("\n")
    );
}

/// What a widget's task says when it is solved (the feedback's first word).
const SOLVED: &str = "Solved";

#[test]
fn no_task_in_a_lesson_is_solved_before_the_learner_changes_anything() {
    let app = KinolabApp::new(None, "");
    let addresses = app.course().unwrap().addresses();
    let mut h = lab(app, tall(1024.0));
    let mut solved = Vec::new();
    let mut tasks = 0;
    for address in addresses {
        h.state_mut().follow_hash(&format!("#/{address}"));
        h.run_steps(4);
        // A task's Check button (a quiz's is "Check answer").
        let task_check = |n: &egui_kittest::Node<'_>| {
            n.accesskit_node()
                .label()
                .is_some_and(|l| l.starts_with("Check") && l != "Check answer")
        };
        let by_button = || egui_kittest::kittest::by().role(egui::accesskit::Role::Button);
        let checks = h.query_all(by_button()).filter(task_check).count();
        for i in 0..checks {
            tasks += 1;
            if let Some(button) = h.query_all(by_button()).filter(task_check).nth(i) {
                button.click();
            }
            h.run_steps(3);
        }
        if h.query_by_label_contains(SOLVED).is_some() {
            solved.push(address);
        }
    }
    assert!(tasks >= 10, "only {tasks} tasks were found");
    assert!(solved.is_empty(), "solved untouched: {solved:?}");
}

#[test]
fn controls_at_rest_stand_out_in_both_themes() {
    let mut h = harness(KinolabApp::new(None, &format!("#/{LESSON}")));
    h.run();
    for theme in [egui::Theme::Light, egui::Theme::Dark] {
        let visuals = h.ctx.style_of(theme).visuals.clone();
        let outline = visuals.widgets.inactive.bg_stroke;
        assert!(outline.width >= 1.0, "{theme:?}: no outline");
        for background in [
            visuals.panel_fill,
            visuals.window_fill,
            visuals.extreme_bg_color,
        ] {
            let ratio = kinolab_widgets::theme::contrast(outline.color, background);
            assert!(
                ratio >= kinolab_widgets::theme::CONTROL_CONTRAST,
                "{theme:?}: an unchosen control's outline has contrast {ratio:.2} against {background:?}"
            );
        }
    }
}

#[test]
fn the_theme_toggle_switches_and_is_remembered() {
    let mut h = harness(KinolabApp::new(None, ""));
    let dark_before = h.ctx.theme() == egui::Theme::Dark;
    let label = if dark_before {
        "Light theme"
    } else {
        "Dark theme"
    };
    h.get_by_label(label).click();
    h.run();
    assert_eq!(h.state().progress().dark, Some(!dark_before));
    assert_eq!((h.ctx.theme() == egui::Theme::Dark), !dark_before);
}

const ICR_LESSON: &str = "#/wheeled-locomotion/icr-and-holonomy";

#[test]
fn the_disagreeing_wheel_challenge_is_graded_by_the_core() {
    let mut h = animated(KinolabApp::new(None, ICR_LESSON));
    h.run_steps(4);
    h.get_by_label_contains("Challenge: Place the ICR at (0, 2).");
    // The catalogue tricycle starts straight: its ICR is at infinity.
    h.get_by_label_contains("The ICR is at infinity");
    // Mark the right wheel and check; then add a wrong one.
    h.get_by_label("Wheel 5 (fixed)").click();
    h.run_steps(2);
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("Right: wheel 5 misses the point");
    let wheels = h.get_all_by_label("Wheel 1 (fixed)").count();
    assert!(wheels >= 2, "tricycle and cart both have a wheel 1");
    h.get_all_by_label("Wheel 1 (fixed)")
        .last()
        .unwrap()
        .click();
    h.run_steps(2);
    h.get_by_label("Check").click();
    h.run_steps(2);
    h.get_by_label_contains("Not yet: wheel 1 agrees with the majority");
}

#[test]
fn a_changed_layout_travels_in_the_link() {
    let lesson = "#/wheeled-locomotion/wheel-kinds";
    let mut h = animated(KinolabApp::new(None, lesson));
    h.run_steps(4);
    assert_eq!(h.state_mut().take_state_hash().as_deref(), Some(lesson));
    // The lesson starts from the six-wheel example; add a seventh wheel.
    h.get_all_by_label("fixed").next().unwrap().click();
    h.run_steps(3);
    h.get_all_by_label("Wheel 7 (fixed)").next().unwrap();
    let link = h.state_mut().take_state_hash().unwrap();
    assert!(link.starts_with(&format!("{lesson}?w0=")), "{link}");
    // Opening the link shows the seven wheels, and offers the same link back.
    let mut h = animated(KinolabApp::new(None, &link));
    h.run_steps(4);
    h.get_all_by_label("Wheel 7 (fixed)").next().unwrap();
    assert_eq!(
        h.state_mut().take_state_hash().as_deref(),
        Some(link.as_str())
    );
    // A damaged state is ignored: the lesson's own layout shows.
    let mut h = animated(KinolabApp::new(None, &format!("{lesson}?w0=aBROKEN")));
    h.run_steps(4);
    h.get_by_label("Wheel 6 (spherical)");
    assert!(h.query_by_label("Wheel 7 (fixed)").is_none());
    // The same inside one page (a link followed without a reload): the good
    // link brings the seventh wheel back, the damaged one resets the widget
    // and the address loses the broken state.
    h.state_mut().follow_hash(&link);
    h.run_steps(4);
    h.get_all_by_label("Wheel 7 (fixed)").next().unwrap();
    h.state_mut().take_state_hash();
    h.state_mut().follow_hash(&format!("{lesson}?w0=zzz"));
    h.run_steps(4);
    assert!(h.query_by_label("Wheel 7 (fixed)").is_none());
    assert_eq!(h.state_mut().take_state_hash().as_deref(), Some(lesson));
}

const GAINS_LESSON: &str = "#/motion-control/choosing-gains";

#[test]
fn the_reach_within_exercise_is_graded_by_simulation() {
    let mut h = animated(KinolabApp::new(None, GAINS_LESSON));
    h.run_steps(4);
    h.get_by_label_contains(
        "Exercise: Choose gains that reach the goal within 3 s without driving backward.",
    );
    // The textbook gains need about 5.8 s from this start: too slow.
    let checks: Vec<_> = h.get_all_by_label("Check").collect();
    checks[0].click();
    h.run_steps(2);
    h.get_by_label_contains("Not reached within 3 s");
    // Mark the unstable sets of the second exercise (1.5 < 2, 0.5 > 0, −2 < 0).
    for set in ["set 2:", "set 3:", "set 5:"] {
        h.get_by_label_contains(set).click();
        h.run_steps(1);
    }
    h.get_all_by_label("Check").last().unwrap().click();
    h.run_steps(2);
    h.get_by_label_contains("All correct: exactly the unstable sets are marked.");
}

#[test]
fn the_playground_shows_the_run_and_its_stability() {
    let lesson = "#/motion-control/feedback-and-polar-coordinates";
    let mut h = animated(KinolabApp::new(None, lesson));
    h.run_steps(4);
    h.get_all_by_label_contains("Strongly stable: the robot converges")
        .next()
        .unwrap();
    h.get_by_label_contains("Reached (within 1 mm and 0.1°, and stayed) after 5.8");
    // Set k_β from −1.5 to +1.5 as assistive technology would.
    h.get_all_by_label("k_β")
        .next()
        .unwrap()
        .set_value_accesskit(1.5);
    h.run_steps(4);
    let link = h.state_mut().take_state_hash().unwrap();
    assert!(link.starts_with(&format!("{lesson}?w0=")), "{link}");
    // The link with unstable gains (k_β > 0) is restored and explained.
    let mut h = animated(KinolabApp::new(None, &link));
    h.run_steps(4);
    h.get_by_label_contains("k_β > 0");
    h.get_by_label_contains("Not reached");
    assert_eq!(
        h.state_mut().take_state_hash().as_deref(),
        Some(link.as_str())
    );
}

#[test]
fn a_diverging_run_stops_at_the_bound_and_says_so() {
    let lesson = "#/motion-control/feedback-and-polar-coordinates";
    let mut h = animated(KinolabApp::new(None, lesson));
    h.run_steps(4);
    h.get_all_by_label("k_α")
        .next()
        .unwrap()
        .set_value_accesskit(-8.0);
    h.get_all_by_label("k_β")
        .next()
        .unwrap()
        .set_value_accesskit(1.5);
    h.run_steps(4);
    h.get_by_label_contains("grew past 100 m");
    h.get_by_label_contains("The plots show the run up to that moment.");
    assert!(h.query_by_label_contains("Not reached").is_none());
}

/// The top of the first node labelled `label` (a place to watch for jumps).
fn top_of(h: &Harness<'static, KinolabApp>, label: &str) -> f32 {
    h.get_all_by_label_contains(label)
        .next()
        .unwrap()
        .rect()
        .top()
}

#[test]
fn selecting_a_wheel_does_not_move_the_workbench() {
    let mut h = animated(KinolabApp::new(None, "#/gallery/wheel-workbench"));
    h.run_steps(4);
    let canvas = top_of(&h, "Wheel 1 (");
    let below = top_of(&h, "rank C1");
    h.get_all_by_label_contains("Wheel 1 (")
        .next()
        .unwrap()
        .click();
    h.run_steps(4);
    assert!(
        !h.get_by_label("Remove selected")
            .accesskit_node()
            .is_disabled(),
        "a wheel is selected"
    );
    assert_eq!(top_of(&h, "Wheel 1 ("), canvas, "the canvas moved");
    assert_eq!(top_of(&h, "rank C1"), below, "the panel beside it moved");
}

#[test]
fn a_longer_verdict_does_not_move_the_gain_plane() {
    let mut h = animated(KinolabApp::new(None, "#/gallery/controller-playground"));
    h.run_steps(4);
    h.get_by_label("Gain region").click();
    h.run_steps(4);
    let plane = top_of(&h, "The plane at k_ρ");
    // k_β > 0: the verdict grows from one line to two.
    h.get_all_by_label("k_β")
        .next()
        .unwrap()
        .set_value_accesskit(1.5);
    h.run_steps(4);
    h.get_by_label_contains("k_β > 0");
    assert_eq!(top_of(&h, "The plane at k_ρ"), plane, "the plot moved");
}

#[test]
fn the_gallery_lists_every_widget_from_the_schema_and_shows_each_alone() {
    let mut h = animated(KinolabApp::new(None, "#/gallery"));
    h.run_steps(6);
    for schema in kinolab_schema::widgets() {
        h.get_all_by_label(schema.name)
            .next()
            .unwrap_or_else(|| panic!("{} is listed", schema.name));
    }
    assert!(h.query_by_label_contains("cannot be shown").is_none());
    h.get_all_by_label("open alone").nth(3).unwrap().click();
    h.run_steps(4);
    assert_eq!(
        h.state().page(),
        &Page::Gallery(Some(
            kinolab_schema::widgets()
                .nth(3)
                .map(|w| w.name.to_owned())
                .unwrap_or_default()
        ))
    );
    // An unknown name says so.
    let mut h = animated(KinolabApp::new(None, "#/gallery/flux-capacitor"));
    h.run_steps(4);
    h.get_by_label("No such widget");
}

#[test]
fn a_sorting_quiz_marks_each_item() {
    let lesson = "software-stability/what-stability-means";
    let mut h = harness(KinolabApp::new(None, &format!("#/{lesson}")));
    // Six items, three bins each: put every item in "control loop".
    for i in 0..6 {
        h.get_all_by_label("control loop").nth(i).unwrap().click();
        h.run();
    }
    h.get_all_by_label("Check answer").next().unwrap().click();
    h.run();
    h.get_by_label("Not quite. Read why, then try again.");
    // Two items were right; the other four say where they belong.
    assert_eq!(h.get_all_by_label("right:").count(), 2);
    assert_eq!(
        h.get_all_by_label("belongs in walker's balance:").count(),
        2
    );
    assert_eq!(h.get_all_by_label("belongs in software design:").count(), 2);
    assert!(!h.state().progress().quizzes[&format!("{lesson}#0")].correct);
}

#[test]
fn a_learners_code_survives_leaving_the_lesson_and_the_lab() {
    let lesson = "#/motion-control/programming-the-robot";
    let mine = "fn control(rho, alpha, beta) { [1.5 * rho, 4.0 * alpha] }";
    let mut h = animated(KinolabApp::new(None, lesson));
    h.run_steps(4);
    let editor = h.get_by_label("Your code");
    editor.focus();
    h.run_steps(1);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.key_press(egui::Key::Delete);
    h.get_by_label("Your code").type_text(mine);
    h.run_steps(2);
    let _ = h.state_mut().take_state_hash();
    let kept = |h: &Harness<'static, KinolabApp>| {
        h.get_by_label("Your code")
            .accesskit_node()
            .value()
            .unwrap_or_default()
    };
    // Away to another lesson and back: the code is where it was.
    h.state_mut().follow_hash(&format!("#/{LESSON}"));
    h.run_steps(2);
    h.state_mut().follow_hash(lesson);
    h.run_steps(4);
    assert_eq!(kept(&h), mine);
    // And in a new session from the saved progress.
    let saved = h.state().progress_json();
    let mut h = animated(KinolabApp::new(Some(&saved), lesson));
    h.run_steps(4);
    assert_eq!(kept(&h), mine);
}

/// A paragraph of lesson text in a column `width` points wide.
fn running_text(spans: &[kinolab_lessons::Span], width: f32) -> Harness<'static, bool> {
    let spans = spans.to_vec();
    let mut h = Harness::builder()
        .with_size(egui::vec2(width, 400.0))
        .build_ui_state(
            move |ui, ready: &mut bool| {
                if *ready {
                    let mut go = None;
                    kinolab_app::lesson_view::inline_ui(ui, &spans, 16.0, false, &mut go);
                } else {
                    kinolab_widgets::theme::install(ui.ctx());
                    *ready = true;
                }
            },
            false,
        );
    h.run_steps(2);
    h
}

/// Every node with text (a label's text is its accesskit value) and its box.
fn text_boxes(h: &Harness<'_, bool>) -> Vec<(String, egui::accesskit::Rect)> {
    h.query_all(egui_kittest::kittest::by())
        .filter_map(|n| {
            let node = n.accesskit_node();
            Some((
                node.value().or(node.label())?.to_string(),
                node.bounding_box()?,
            ))
        })
        .collect()
}

#[test]
fn punctuation_after_inline_code_never_starts_a_line_alone() {
    let text =
        "Wire the port to `planner.map`, then press Run and watch `motion.source`; it moves.";
    let spans = kinolab_lessons::parse_inline("test.md", 1, text).unwrap();
    // From a column that holds `planner.map` and its comma on one row.
    for width in (150..=420).step_by(3) {
        let h = running_text(&spans, width as f32);
        // A row of text (a one-row label, or one row of a longer one) that
        // begins with punctuation does not begin at the column's left edge.
        let nodes = text_boxes(&h);
        let left = nodes
            .iter()
            .map(|(_, r)| r.x0)
            .fold(f64::INFINITY, f64::min);
        let mut seen = 0;
        for (label, rect) in &nodes {
            if label.starts_with([',', ';']) && rect.y1 - rect.y0 < 24.0 {
                seen += 1;
                assert!(
                    rect.x0 > left + 1.0,
                    "at {width} px `{label}` starts a line alone"
                );
            }
        }
        assert!(seen >= 2, "at {width} px: {nodes:?}");
    }
}

#[test]
fn an_emphasised_word_keeps_its_space_at_any_wrap() {
    // egui slants italics to the right: without a correction the word's
    // last letter leans into the space after it.
    let text = "Cutting off gives zero, and without the min the pull is eight, \
                a push *away* from the goal, and more words follow here.";
    let spans = kinolab_lessons::parse_inline("test.md", 1, text).unwrap();
    let mut starts_a_line = 0;
    for width in (150..=420).step_by(4) {
        let h = running_text(&spans, width as f32);
        // One row of text each (a label's rows are its children).
        let mut rows = text_boxes(&h);
        rows.retain(|(_, r)| r.y1 - r.y0 < 24.0);
        let left = rows.iter().map(|(_, r)| r.x0).fold(f64::INFINITY, f64::min);
        let Some((_, away)) = rows.iter().find(|(t, _)| t == "away") else {
            panic!("at {width} px no row holds `away`: {rows:?}");
        };
        let after = rows
            .iter()
            .find(|(t, r)| t.starts_with(" from") && (r.y0 - away.y0).abs() < 1.0);
        if let Some((_, from)) = after {
            assert!(
                from.x0 >= away.x1 + 2.0,
                "at {width} px ` from` starts at {:.1}, `away` ends at {:.1}",
                from.x0,
                away.x1
            );
            starts_a_line += usize::from(away.x0 <= left + 0.5);
        }
    }
    assert!(
        starts_a_line >= 3,
        "the sweep never put `away` at a line start"
    );
}

#[test]
fn no_line_starts_with_a_space() {
    // The text after an italic word starts with a space; when the italic
    // word ends a line, the next line must not begin with that space.
    let text = "Reading off the plot tells you *which* speed? A small dog trots \
                at a steady pace across a yard, and its legs keep time.";
    let spans = kinolab_lessons::parse_inline("test.md", 1, text).unwrap();
    let mut wrapped_after_italic = 0;
    for width in (150..=420).step_by(3) {
        let h = running_text(&spans, width as f32);
        let mut rows = text_boxes(&h);
        rows.retain(|(_, r)| r.y1 - r.y0 < 24.0);
        let left = rows.iter().map(|(_, r)| r.x0).fold(f64::INFINITY, f64::min);
        for (t, r) in &rows {
            if r.x0 <= left + 0.5 {
                assert!(
                    !t.starts_with(' '),
                    "at {width} px a line starts with `{t}`"
                );
                wrapped_after_italic += usize::from(t.starts_with("speed?"));
            }
        }
    }
    assert!(
        wrapped_after_italic >= 2,
        "the sweep never wrapped after `which`"
    );
}

/// The wheel drive's hint, the one widget that keeps driving on its own.
const DRIVE_HINT: &str = "arrow keys to drive";

#[test]
fn a_page_at_rest_asks_for_no_frames() {
    // Every lesson and widget stops asking for frames within a few once
    // nothing changes, except a wheel drive still driving (next test).
    let app = KinolabApp::new(None, "");
    let addresses = app.course().unwrap().addresses();
    let mut h = lab(app, tall(1280.0).with_max_steps(30));
    let widgets = kinolab_schema::widgets().map(|w| format!("gallery/{}", w.name));
    let mut busy = Vec::new();
    for address in widgets.chain(addresses) {
        h.state_mut().follow_hash(&format!("#/{address}"));
        let settled = h.run_ok().is_some();
        let driving = h.query_all_by_label_contains(DRIVE_HINT).next().is_some();
        if !settled && !driving {
            busy.push(address);
        }
    }
    assert!(busy.is_empty(), "still asking for frames: {busy:?}");
}

#[test]
fn a_wheel_drive_left_alone_pauses_itself() {
    let app = KinolabApp::new(None, "");
    let builder = Harness::builder().with_size(egui::vec2(1280.0, 1600.0));
    let mut h = lab(app, builder.with_step_dt(0.05).with_max_steps(700));
    h.state_mut().follow_hash("#/gallery/wheel-drive");
    let steps = h.run_ok().expect("the drive rests within 35 s");
    assert!(steps >= 590, "it drove for 30 s first, {steps} steps");
    h.get_by_label_contains("Paused after 30 s");
    // Run drives on, and it asks for frames again.
    h.get_by_label("Run").click();
    h.run_steps(3);
    assert!(h.query_by_label_contains("Paused after").is_none());
    assert!(h.ctx.has_requested_repaint());
}

#[test]
fn a_learner_who_asked_for_less_motion_sees_nothing_move_by_itself() {
    let app = KinolabApp::new(None, "");
    let builder = Harness::builder().with_size(egui::vec2(1280.0, 1600.0));
    let mut h = lab(app, builder.with_step_dt(0.05).with_max_steps(40));
    kinolab_widgets::theme::reduce_motion(&h.ctx);
    h.state_mut().follow_hash("#/gallery/wheel-drive");
    // The drive waits for Run, so the page asks for no frames at all.
    h.run_ok().expect("the page rests at once");
    assert!(h.query_by_label("Run").is_some());
    for theme in [egui::Theme::Dark, egui::Theme::Light] {
        assert_eq!(h.ctx.style_of(theme).animation_time, 0.0);
    }
    // Run drives, as for anyone.
    h.get_by_label("Run").click();
    h.run_steps(3);
    assert!(h.ctx.has_requested_repaint());
}

#[test]
fn a_screen_reader_hears_formulas_in_words() {
    // "A wheel of radius $r$ spinning at $\dot\varphi$ … forward at
    // $r\dot\varphi$": each formula is in the accessibility tree as words.
    let h = harness(KinolabApp::new(None, "#/wheeled-locomotion/wheel-kinds"));
    for words in ["r phi dot", "phi dot"] {
        assert!(
            h.query_all_by_label(words).next().is_some(),
            "no formula read as {words:?}"
        );
    }
    // Nothing on the page is read as TeX source.
    assert!(h.query_all_by_label_contains("\\dot").next().is_none());
    // Its sections are headings a screen reader can jump between.
    let headings = h.query_all_by_role(egui::accesskit::Role::Heading).count();
    assert!(headings >= 5, "{headings} headings");
}

#[test]
fn the_wheel_workbench_says_what_it_shows() {
    // Its state in words, as a group's name in the accessibility tree: the
    // wheels, the three degrees and where the ICR is.
    let h = harness(KinolabApp::new(None, "#/gallery/wheel-workbench"));
    let node = h.get_by_role(egui::accesskit::Role::Group);
    let words = node.accesskit_node().label().unwrap_or_default();
    for part in [
        "wheel",
        "Mobility δm",
        "steerability δs",
        "maneuverability δM",
        "ICR",
    ] {
        assert!(words.contains(part), "{part} missing from: {words}");
    }
}

#[test]
fn the_arena_and_the_gait_studio_say_what_they_show() {
    for (address, parts) in [
        (
            "gallery/behaviour-arena",
            &["coordination", "s into the run", "has control", "touch"][..],
        ),
        (
            "gallery/gait-studio",
            &["% of the cycle", "stability margin", "smallest"][..],
        ),
    ] {
        let h = harness(KinolabApp::new(None, &format!("#/{address}")));
        let node = h.get_by_role(egui::accesskit::Role::Group);
        let words = node.accesskit_node().label().unwrap_or_default();
        for part in parts {
            assert!(
                words.contains(part),
                "{address}: {part} missing from: {words}"
            );
        }
    }
}

#[test]
fn the_field_sandbox_says_what_it_shows() {
    // Its pieces, traps and saddles, and where the point robot ends.
    let h = harness(KinolabApp::new(None, "#/gallery/field-sandbox"));
    let node = h.get_by_role(egui::accesskit::Role::Group);
    let words = node.accesskit_node().label().unwrap_or_default();
    for part in ["A field of", "trap", "saddle", "Point robot:"] {
        assert!(words.contains(part), "{part} missing from: {words}");
    }
}

/// What each widget's description must hold on its gallery defaults: a
/// part only that widget says.
const DESCRIBED: &[(&str, &[&str])] = &[
    ("leg-events", &["legs:", "possible event sequences"]),
    ("support-polygon", &["feet on the ground", "margin"]),
    ("gait-studio", &["% of the cycle", "stability margin"]),
    (
        "cpg-lab",
        &["Pulling towards the", "largest lag error", "cycles"],
    ),
    (
        "hexapod-walker",
        &["gait, stride", "% of the cycle", "feet on the ground"],
    ),
    (
        "zmp-cart-table",
        &["s after it", "CoM at", "ZMP at", "capture point"],
    ),
    ("grid-planner", &["world in cells of", "expanded", "cells"]),
    (
        "architecture-arena",
        &["s into the run", "robot in focus", "sprung"],
    ),
    ("sensing-routes", &["wire", "routes:", "range rays"]),
    ("component-lab", &["system at", "sent", "delivered", "lost"]),
    ("which-pattern", &["Patterns chosen for", "needs", "so far"]),
    ("ant-beach", &["ant lengths on beach", "tortuosity"]),
    ("three-slots", &["Body ", "behaviours ", "world "]),
    ("technology-churn", &["stable", "naive", "design"]),
    ("morphology-builder", &["elements", "pairs", "dissolved"]),
    ("scripted-vs-sensing", &["This batch:", "In the long run"]),
    ("wheel-workbench", &["Mobility δm", "ICR"]),
    (
        "wheel-drive",
        &[
            "Robot ",
            "driven by its",
            "Twist (forward, sideways, turn)",
            "Pose x =",
        ],
    ),
    ("frame-rotation", &["Heading θ =", "As the robot sees it"]),
    ("speed-profile", &["m/s", "Total", " s."]),
    ("controller-playground", &["Gains k_ρ =", "k_α", "k_β"]),
    ("mechanism-viewer", &["°", " at ("]),
    (
        "dh-link",
        &["DH:", "a = ", "α = ", "d = ", "θ = ", "Frame i"],
    ),
    ("arm-statics", &["Holding the arm with", "shoulder", "N·m"]),
    ("arm-fall", &["At t =", "the energy is", " J"]),
    ("field-sandbox", &["A field of", "trap"]),
    ("behaviour-arena", &["coordination", "has control"]),
    ("braitenberg", &["s into the run", "vehicle 1", "light"]),
    ("blend-or-choose", &["fly 1 at", "Blend:", "Choose:"]),
    ("code", &["Your code", "Stepping through world"]),
];

#[test]
fn every_widget_says_what_it_shows() {
    // Each widget's state in words on its group in the accessibility
    // tree: a widget that stops describing itself fails here.
    let names: Vec<&str> = kinolab_widgets::registry::CONSTRUCTORS
        .iter()
        .map(|(name, _)| *name)
        .collect();
    let listed: Vec<&str> = DESCRIBED.iter().map(|(name, _)| *name).collect();
    assert_eq!(listed, names, "every widget has its parts here");
    for (name, parts) in DESCRIBED {
        let mut h = animated(KinolabApp::new(None, &format!("#/gallery/{name}")));
        h.run_steps(3);
        let words: Vec<String> = h
            .query_all_by_role(egui::accesskit::Role::Group)
            .filter_map(|n| n.accesskit_node().label())
            .filter(|l| !l.is_empty())
            .collect();
        assert_eq!(words.len(), 1, "{name}: one description, found {words:?}");
        let words = &words[0];
        println!("{name}: {words}");
        for part in *parts {
            assert!(words.contains(part), "{name}: {part} missing from: {words}");
        }
    }
}

/// A learner who opens the lab sees its first screen sooner: the first
/// frame that draws lays out what fits on a 1280×720 screen, and the next,
/// asked for at once, the whole page, down to the last unit in the lesson
/// list and on the home page.
#[test]
fn the_first_frame_lays_out_a_screenful_and_the_next_the_rest() {
    type Seen = (KinolabApp, Vec<bool>);
    let screen = Harness::builder().with_size(egui::vec2(1280.0, 720.0));
    let mut h = screen.build_ui_state(
        |ui, (app, complete): &mut Seen| {
            app.show(ui);
            if app.frames_drawn() > 0 {
                complete.push(app.page_complete());
            }
        },
        (KinolabApp::new(None, ""), Vec::new()),
    );
    h.run();
    let complete = &h.state().1;
    assert_eq!(complete.first(), Some(&false), "{complete:?}");
    assert!(
        complete.len() > 1 && complete[1..].iter().all(|c| *c),
        "{complete:?}"
    );
    let units = &h.state().0.course().unwrap().units;
    let last = format!("Unit {}: {}", units.len(), units[units.len() - 1].title);
    assert_eq!(h.get_all_by_label(&last).count(), 2);
}
