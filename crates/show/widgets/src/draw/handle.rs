//! Draggable handles: every point a learner can grab is a real egui
//! widget with a name, so screen readers and keyboards reach it too.

use egui::{Id, Pos2, Rect, Response, Sense, Vec2, vec2};

use super::PlaneView;

/// A handle's response and how far it moved this frame (by pointer or,
/// when it has keyboard focus, by the arrow keys).
#[derive(Debug)]
pub struct Handle {
    pub response: Response,
    /// Screen points moved this frame.
    pub moved: Vec2,
}

impl Handle {
    pub fn dragged(&self) -> bool {
        self.moved != Vec2::ZERO
    }

    pub fn clicked(&self) -> bool {
        self.response.clicked()
    }

    /// Where the world point `from` under this handle was dragged to this
    /// frame, through `view`; `None` when it did not move.
    pub fn dragged_to(&self, view: &PlaneView, from: [f64; 2]) -> Option<[f64; 2]> {
        self.dragged().then(|| {
            let d = view.delta_to_world(self.moved);
            [from[0] + d[0], from[1] + d[1]]
        })
    }

    /// Whether the learner is holding it (pointer down on it).
    pub fn held(&self) -> bool {
        self.response.is_pointer_button_down_on()
    }
}

/// How far one press of an arrow key moves a focused handle, points, and
/// how many times further with Shift held.
const KEY_STEP: f32 = 4.0;
const SHIFT_STEPS: f32 = 8.0;

/// The arrow keys pressed this frame as a direction on the screen (right
/// and down positive), one unit per press.
pub fn arrows(input: &egui::InputState) -> Vec2 {
    [
        (egui::Key::ArrowLeft, vec2(-1.0, 0.0)),
        (egui::Key::ArrowRight, vec2(1.0, 0.0)),
        (egui::Key::ArrowUp, vec2(0.0, -1.0)),
        (egui::Key::ArrowDown, vec2(0.0, 1.0)),
    ]
    .into_iter()
    .filter(|(key, _)| input.key_pressed(*key))
    .fold(Vec2::ZERO, |sum, (_, dir)| sum + dir)
}

/// A round handle of `radius` points at `at`, named `label` for assistive
/// technology (for example "Goal heading"). Drag it, or focus it with Tab
/// and move it with the arrow keys.
pub fn handle(ui: &mut egui::Ui, id: Id, at: Pos2, radius: f32, label: &str) -> Handle {
    let rect = Rect::from_center_size(at, Vec2::splat(2.0 * radius.max(8.0)));
    let response = ui
        .interact(rect, id, Sense::click_and_drag())
        .on_hover_cursor(egui::CursorIcon::Grab);
    let name = label.to_owned();
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Slider, true, name.clone()));
    let mut moved = response.drag_delta();
    if response.has_focus() {
        let (arrows, shift) = ui.input(|i| (arrows(i), i.modifiers.shift));
        moved += arrows
            * if shift {
                KEY_STEP * SHIFT_STEPS
            } else {
                KEY_STEP
            };
    }
    if response.has_focus() {
        ui.painter().circle_stroke(
            at,
            radius + 3.0,
            egui::Stroke::new(1.5, ui.visuals().selection.stroke.color),
        );
    }
    Handle { response, moved }
}
