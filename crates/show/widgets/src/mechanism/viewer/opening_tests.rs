//! A learner brings a robot: a URDF dropped on the page, picked in the
//! file dialog or pasted opens in the viewer with a slider per joint,
//! named as in the file and bounded by its limits.

use super::*;
use crate::open;
use egui::accesskit::Role;
use egui_kittest::kittest::Queryable as _;

const UR5: &str = include_str!("../../../../../body/mechanism/robots/ur5.urdf");
const SOLO12: &str = include_str!("../../../../../body/mechanism/robots/solo12.urdf");

type Harness = egui_kittest::Harness<'static, (Viewer, bool)>;

fn harness() -> Harness {
    let viewer = Viewer::from_settings(Settings {
        model: "planar-2r".into(),
        view: None,
        q: None,
        frames: true,
        shapes: false,
        obstacles: None,
        drag: true,
        tree: false,
        task: None,
        target: None,
        tolerance: 0.01,
        sets: None,
        marked: None,
    })
    .unwrap_or_else(|e| panic!("{e}"));
    // The lab's fonts take effect a frame after they are installed.
    egui_kittest::Harness::builder()
        .with_size(egui::vec2(900.0, 1800.0))
        .build_ui_state(
            |ui, (w, ready): &mut (Viewer, bool)| {
                if *ready {
                    egui::ScrollArea::vertical().show(ui, |ui| w.ui(ui));
                } else {
                    crate::theme::install(ui.ctx());
                    *ready = true;
                }
            },
            (viewer, false),
        )
}

/// The viewer with its file panel unfolded.
fn file_panel_open() -> Harness {
    let mut h = harness();
    h.run_steps(2);
    h.get_by_label("Model file: JSON or URDF").click();
    h.run_steps(2);
    h
}

/// The limits the slider of `joint` spans (it must have a slider).
fn slider_limits(h: &Harness, joint: &str) -> [f64; 2] {
    let viewer = &h.state().0;
    let v = viewer
        .model
        .variable(joint)
        .unwrap_or_else(|| panic!("no {joint}"));
    assert!(viewer.driven.contains(&v), "{joint} has a slider");
    viewer
        .model
        .variable_joint(v)
        .and_then(|j| j.limits)
        .unwrap_or_else(|| panic!("{joint} has limits"))
}

#[test]
fn a_dropped_urdf_opens_with_the_files_joint_names_and_limits() {
    let mut h = harness();
    h.run_steps(2);
    let file = open::OpenedFile {
        name: "ur5.urdf".into(),
        bytes: UR5.as_bytes().to_vec(),
    };
    open::deliver_dropped(&h.ctx, file);
    h.run_steps(2);
    let viewer = &h.state().0;
    assert_eq!(viewer.model.name(), "ur5");
    assert_eq!(viewer.driven.len(), 6);
    // The drag target is the tool frame the file names.
    assert_eq!(viewer.end.as_ref().map(|(n, _)| n.as_str()), Some("tool0"));
    h.get_by_role_and_label(Role::Slider, "shoulder_pan_joint");
    h.get_by_role_and_label(Role::Slider, "wrist_3_joint");
    let [lo, hi] = slider_limits(&h, "shoulder_pan_joint");
    assert!(
        (lo + 2.0 * std::f64::consts::PI).abs() < 1e-9
            && (hi - 2.0 * std::f64::consts::PI).abs() < 1e-9
    );
}

#[test]
fn a_picked_file_and_a_pasted_one_open_too() {
    let mut h = file_panel_open();
    h.get_by_label("Open a file…").click();
    h.run_steps(2);
    let requests = open::take_pick_requests(&h.ctx);
    assert_eq!(requests.len(), 1);
    assert!(requests[0].accept.contains(".urdf"));
    let file = open::OpenedFile {
        name: "solo12.urdf".into(),
        bytes: SOLO12.as_bytes().to_vec(),
    };
    open::deliver(&h.ctx, requests[0].widget, file);
    h.run_steps(2);
    assert_eq!(h.state().0.driven.len(), 12, "Solo 12's twelve joints");
    h.get_by_role_and_label(Role::Slider, "FL_HAA");
    h.get_by_label_contains("Opened solo from solo12.urdf.");
    // Pasting a broken file keeps the robot and says what is wrong.
    h.state_mut().0.file_text =
        "<robot name=\"x\"><joint name=\"j\" type=\"fixed\"/></robot>".into();
    h.get_by_label("Open the text below").click();
    h.run_steps(2);
    assert_eq!(h.state().0.driven.len(), 12);
    h.get_by_label_contains("the pasted text was not opened");
    // A pasted URDF opens.
    h.state_mut().0.file_text = UR5.into();
    h.get_by_label("Open the text below").click();
    h.run_steps(2);
    assert_eq!(h.state().0.model.name(), "ur5");
}

#[test]
fn save_as_urdf_hands_the_host_a_file_that_reads_back() {
    let mut h = file_panel_open();
    h.get_by_label("Save as URDF").click();
    h.run_steps(2);
    let saved = crate::export::take_save_requests(&h.ctx);
    assert_eq!(saved.len(), 1);
    assert_eq!(saved[0].name, "planar-2r-arm.urdf");
    let text = String::from_utf8_lossy(&saved[0].bytes);
    let robot = kinolab_mechanism::urdf::read(&text).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(robot.driven().collect::<Vec<_>>(), ["q1", "q2"]);
    h.get_by_label_contains("Saved planar-2r-arm.urdf.");
}
