//! One way to map a plane of the world to the screen.

use egui::{Pos2, Rect, Vec2, pos2};

/// A plane of the world (metres, y up) drawn into screen points (y down):
/// the world point `look_at` sits at `centre`, `scale` points per metre.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlaneView {
    pub centre: Pos2,
    pub scale: f32,
    pub look_at: [f64; 2],
}

impl PlaneView {
    /// The world box `[min, max]` fitted into `rect` (at least 0.5 m a side).
    pub fn fit(rect: Rect, min: [f64; 2], max: [f64; 2]) -> Self {
        let w = (max[0] - min[0]).max(0.5);
        let h = (max[1] - min[1]).max(0.5);
        let scale = (rect.width() / w as f32).min(rect.height() / h as f32);
        Self {
            centre: rect.center(),
            scale,
            look_at: [(min[0] + max[0]) / 2.0, (min[1] + max[1]) / 2.0],
        }
    }

    /// `look_at` at the centre of `rect`, with `half_extent` metres to
    /// either side of the shorter dimension.
    pub fn centred(rect: Rect, look_at: [f64; 2], half_extent: f64) -> Self {
        Self {
            centre: rect.center(),
            scale: (rect.width().min(rect.height()) / 2.0) / half_extent.max(1e-6) as f32,
            look_at,
        }
    }

    /// A world point on screen.
    pub fn to_screen(&self, p: [f64; 2]) -> Pos2 {
        pos2(
            self.centre.x + ((p[0] - self.look_at[0]) as f32) * self.scale,
            self.centre.y - ((p[1] - self.look_at[1]) as f32) * self.scale,
        )
    }

    /// A screen point in the world.
    pub fn to_world(&self, at: Pos2) -> [f64; 2] {
        let [dx, dy] = self.delta_to_world(at - self.centre);
        [self.look_at[0] + dx, self.look_at[1] + dy]
    }

    /// A screen displacement as a world displacement.
    pub fn delta_to_world(&self, d: Vec2) -> [f64; 2] {
        [f64::from(d.x / self.scale), f64::from(-d.y / self.scale)]
    }

    /// A world length in screen points.
    pub fn length(&self, metres: f64) -> f32 {
        metres as f32 * self.scale
    }

    /// The world box a screen rectangle shows.
    pub fn visible(&self, rect: Rect) -> ([f64; 2], [f64; 2]) {
        let a = self.to_world(rect.left_bottom());
        let b = self.to_world(rect.right_top());
        (a, b)
    }
}

/// A point given in a frame placed at `pose` (x, y, θ), in the world.
pub fn placed(pose: [f64; 3], p: [f64; 2]) -> [f64; 2] {
    let [dx, dy] = placed_dir(pose[2], p);
    [pose[0] + dx, pose[1] + dy]
}

/// A direction given in a frame turned by `theta`, in the world.
pub fn placed_dir(theta: f64, d: [f64; 2]) -> [f64; 2] {
    let (s, c) = theta.sin_cos();
    [c * d[0] - s * d[1], s * d[0] + c * d[1]]
}

/// A world point in the frame placed at `pose`.
pub fn local(pose: [f64; 3], world: [f64; 2]) -> [f64; 2] {
    let (s, c) = pose[2].sin_cos();
    let (dx, dy) = (world[0] - pose[0], world[1] - pose[1]);
    [c * dx + s * dy, -s * dx + c * dy]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn screen_and_world_round_trip() {
        let rect = Rect::from_min_size(pos2(10.0, 20.0), egui::vec2(400.0, 200.0));
        let view = PlaneView::fit(rect, [-1.0, -0.5], [3.0, 1.5]);
        assert_eq!(view.scale, 100.0);
        let p = [0.7, -0.2];
        let back = view.to_world(view.to_screen(p));
        assert!((back[0] - p[0]).abs() < 1e-5 && (back[1] - p[1]).abs() < 1e-5);
        // y up in the world is up the screen.
        assert!(view.to_screen([0.0, 1.0]).y < view.to_screen([0.0, 0.0]).y);
        let (min, max) = view.visible(rect);
        assert!((min[0] + 1.0).abs() < 1e-5 && (max[1] - 1.5).abs() < 1e-5);
    }

    #[test]
    fn frames_place_and_unplace() {
        let pose = [1.0, 2.0, std::f64::consts::FRAC_PI_2];
        let ahead = placed(pose, [1.0, 0.0]);
        assert!((ahead[0] - 1.0).abs() < 1e-12 && (ahead[1] - 3.0).abs() < 1e-12);
        let back = local(pose, ahead);
        assert!((back[0] - 1.0).abs() < 1e-12 && back[1].abs() < 1e-12);
    }
}
