//! The playground's floor: a grid fitted around what matters, and the
//! start and goal poses as named handles (drag the dot to move a pose,
//! its ring to turn it; or Tab to a handle and use the arrow keys).

use egui::{Painter, Sense};
use kinolab_common::angle::snap;
use kinolab_control::Pose;

use super::settings::pose;
use super::{NAME, Playground};
use crate::control::field;
use crate::draw::labels::Labels;
use crate::draw::{PlaneView, canvas, handle};
use crate::theme;

/// Which poses a floor lets the learner drag.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Grabs {
    StartAndGoal,
    Start,
    Goal,
}

/// The four handles a pose can have.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Part {
    Place,
    Heading,
}

impl Playground {
    /// The floor fitted around `keep`, with the handles `grabs` allows.
    /// The view stays put while the learner drags, and until the pointer
    /// leaves the floor, so nothing jumps from under it.
    pub(super) fn floor(
        &mut self,
        ui: &mut egui::Ui,
        size: egui::Vec2,
        grabs: Grabs,
        keep: &[Pose],
    ) -> (Painter, PlaneView) {
        let salt = ui.next_auto_id();
        let (response, painter) = canvas(ui, size, Sense::hover());
        let rect = response.rect;
        let view = self.frozen.unwrap_or_else(|| {
            let (min, max) = field::bounds(keep, 0.7);
            PlaneView::fit(rect, min, max)
        });
        field::floor(&painter, &view, rect, ui.visuals().text_color());
        let mut held = false;
        if grabs != Grabs::Goal {
            held |= self.pose_handles(ui, salt, &view, true);
        }
        if grabs != Grabs::Start {
            held |= self.pose_handles(ui, salt, &view, false);
        }
        if held {
            self.frozen = Some(view);
        } else if !response.contains_pointer() {
            self.frozen = None;
        }
        (painter, view)
    }

    /// The dot and ring of the start (or goal) pose; true while held.
    fn pose_handles(
        &mut self,
        ui: &mut egui::Ui,
        salt: egui::Id,
        view: &PlaneView,
        start: bool,
    ) -> bool {
        let name = if start { "Start" } else { "Goal" };
        let mut held = false;
        for part in [Part::Heading, Part::Place] {
            let now = if start { self.set.start } else { self.set.goal };
            let p = pose(now);
            let (at, label) = match part {
                Part::Place => (view.to_screen([p.x, p.y]), format!("{name} position")),
                Part::Heading => (
                    view.to_screen(field::heading_tip(&p)),
                    format!("{name} heading"),
                ),
            };
            let h = handle(ui, salt.with((name, part as u8)), at, 9.0, &label);
            held |= h.held();
            if h.dragged() {
                let to = h.response.interact_pointer_pos().unwrap_or(at + h.moved);
                let moved = drag_pose(now, part, view.to_world(to));
                let mut next = self.set.clone();
                *(if start {
                    &mut next.start
                } else {
                    &mut next.goal
                }) = moved;
                // Only where the schema allows a pose (within ±5 m).
                if next != self.set && crate::link::check(NAME, &next).is_ok() {
                    self.set = next;
                    self.replay_from_start();
                }
            }
        }
        held
    }

    /// The start and goal poses, named (the goal alone when `start` is
    /// off), their names clear of the robot drawn at `robot`.
    pub(super) fn draw_ends(
        &self,
        ui: &egui::Ui,
        painter: &Painter,
        view: &PlaneView,
        start: bool,
        robot: Option<&Pose>,
    ) {
        let mut labels = Labels::default();
        if let Some(p) = robot {
            labels.reserve(field::robot_area(view, p));
        }
        field::pose(
            painter,
            &mut labels,
            view,
            &pose(self.set.goal),
            theme::good_color(ui),
            "goal",
            true,
        );
        if start {
            let ink = ui.visuals().text_color().gamma_multiply(0.7);
            let p = &pose(self.set.start);
            field::pose(painter, &mut labels, view, p, ink, "start", true);
        }
        labels.draw(painter, &egui::FontId::proportional(theme::TITLE_SIZE));
    }
}

/// A pose `x, y, heading_deg` with its place moved to `to` (snapped to
/// 5 cm), or turned to face `to` (in 5° steps).
fn drag_pose(pose: [f64; 3], part: Part, to: [f64; 2]) -> [f64; 3] {
    let [x, y, heading] = pose;
    match part {
        Part::Place => [snap(to[0], 0.05), snap(to[1], 0.05), heading],
        Part::Heading => [x, y, snap((to[1] - y).atan2(to[0] - x).to_degrees(), 5.0)],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dragging_snaps_places_and_headings() {
        let p = [0.0, 0.0, 0.0];
        let moved = pose(drag_pose(p, Part::Place, [0.123, -0.26]));
        assert!((moved.x - 0.1).abs() < 1e-12 && (moved.y + 0.25).abs() < 1e-12);
        let turned = pose(drag_pose(p, Part::Heading, [0.0, 1.0]));
        assert!((turned.theta - std::f64::consts::FRAC_PI_2).abs() < 1e-12 && turned.x == 0.0);
    }
}
