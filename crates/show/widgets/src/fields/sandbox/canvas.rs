//! The sandbox's picture: strength shading, arrows, streamlines, the
//! primitives with their handles, equilibria, the robots' trails and the
//! basin map.

use egui::{Color32, Painter, Pos2, Rect, Sense, Stroke, vec2};
use kinolab_common::display::fixed;
use kinolab_fields::basin::Basin;
use kinolab_fields::descend::Outcome;
use kinolab_fields::minima::Kind as Equilibrium;
use kinolab_fields::{Field, Vec2};

use super::Sandbox;
use super::piece::Kind;
use crate::draw::labels::Labels;
use crate::draw::marks::{self, arrow, cross, dashed_circle, star};
use crate::draw::{PlaneView, canvas, corner_text, handle};
use crate::theme;

const SHADE_COLUMNS: usize = 60;
const ARROW_COLUMNS: usize = 22;

fn v(p: [f64; 2]) -> Vec2 {
    Vec2::new(p[0], p[1])
}

fn w(p: Vec2) -> [f64; 2] {
    [p.x, p.y]
}

/// Colours for the picture, readable in both themes.
pub(super) struct Ink {
    pub text: Color32,
    pub faint: Color32,
    pub accent: Color32,
    pub good: Color32,
    pub bad: Color32,
    pub obstacle: Color32,
    pub unicycle: Color32,
}

impl Ink {
    pub fn of(ui: &egui::Ui) -> Self {
        let text = ui.visuals().text_color();
        Self {
            text,
            faint: text.gamma_multiply(0.35),
            accent: theme::accent(ui),
            good: theme::good_color(ui),
            bad: theme::error_color(ui),
            obstacle: theme::solid_color(ui),
            unicycle: theme::robot_color(ui),
        }
    }
}

impl Sandbox {
    /// Draw the field and take the handles; returns whether a handle is
    /// held, and where the picture is.
    pub(super) fn canvas(&mut self, ui: &mut egui::Ui, width: f32) -> (bool, Rect) {
        let area = self.area;
        let height = (width * (area.height() / area.width()) as f32).clamp(300.0, 560.0);
        let (response, painter) = canvas(ui, vec2(width, height), Sense::hover());
        let rect = response.rect;
        let view = PlaneView::fit(
            rect.shrink(6.0),
            [area.x_min, area.y_min],
            [area.x_max, area.y_max],
        );
        let ink = Ink::of(ui);
        painter.rect_stroke(
            rect,
            6.0,
            Stroke::new(1.0, ink.faint),
            egui::StrokeKind::Inside,
        );
        if let Some(field) = &self.field {
            let wanted = Wanted {
                version: self.version,
                coarse: self.dragging,
                shading: self.settings.shading,
                streamlines: self.settings.streamlines,
            };
            let b = &mut self.backdrop;
            b.update(field, &area, wanted);
            shade(&painter, &view, b, field, ink.accent);
            self.draw_basins(&painter, &view, &ink);
            let b = &self.backdrop;
            arrows(&painter, &view, b, field, ink.faint);
            lines(&painter, &view, b, ink.text.gamma_multiply(0.55));
        }
        // Range circles and bands end at the field's edge, not in the
        // frame around it.
        let field_rect = Rect::from_two_pos(
            view.to_screen([area.x_min, area.y_min]),
            view.to_screen([area.x_max, area.y_max]),
        );
        let inside = painter.with_clip_rect(field_rect.intersect(painter.clip_rect()));
        self.draw_pieces(&inside, &view, &ink);
        let at = self.player.as_mut().map(|p| p.state().k);
        self.draw_runs(&painter, &view, &ink, at);
        self.draw_equilibria(&painter, &view, &ink);
        if let Some(at) = self.task.as_ref().and_then(super::exercise::Task::point) {
            let p = view.to_screen(at);
            cross(&painter, p, 5.0, Stroke::new(2.0, ink.text));
            let mut labels = Labels::default();
            labels.reserve(egui::Rect::from_center_size(p, vec2(12.0, 12.0)));
            labels.add(p, "P", ink.text);
            labels.draw(&painter, &egui::FontId::proportional(theme::BODY_SIZE));
        }
        let held = self.handles(ui, &view);
        if self.dragging && !held {
            // Released: one more frame, at full detail.
            ui.ctx().request_repaint();
        }
        self.dragging = held;
        if let (Some(field), Some(at), false) =
            (&self.field, response.hover_pos(), self.hides_readout())
        {
            let p = view.to_world(at);
            let f = field.vector(v(p));
            let text = format!(
                "F({}, {}) = ({}, {}), ‖F‖ = {}",
                fixed(p[0], 2),
                fixed(p[1], 2),
                fixed(f.x, 2),
                fixed(f.y, 2),
                fixed(f.norm(), 2)
            );
            corner_text(&painter, rect, 0, text, ink.text);
        }
        (held, rect)
    }

    fn draw_pieces(&self, painter: &Painter, view: &PlaneView, ink: &Ink) {
        let thin = Stroke::new(1.2, ink.obstacle);
        for (i, piece) in self.design.pieces.iter().enumerate() {
            let chosen = self.selected == Some(i);
            let stroke = Stroke::new(
                if chosen { 2.5 } else { 1.5 },
                if chosen { ink.accent } else { ink.obstacle },
            );
            let at = view.to_screen(piece.at);
            let range = view.length(piece.range);
            match piece.kind {
                Kind::Uniform => {
                    let corner = painter.clip_rect().right_top() + vec2(-46.0, 40.0);
                    let d = piece.direction_deg.to_radians();
                    let along = vec2(d.cos() as f32, -d.sin() as f32) * 30.0;
                    painter.circle_stroke(corner, 22.0, thin);
                    arrow(painter, corner - along * 0.5, along, 9.0, stroke);
                }
                Kind::Attractive => {
                    if !piece.unlimited || piece.profile == super::piece::ProfileKind::Linear {
                        dashed_circle(
                            painter,
                            at,
                            range,
                            Stroke::new(1.0, ink.good.gamma_multiply(0.8)),
                        );
                    }
                    painter.circle_stroke(at, 9.0, Stroke::new(stroke.width, ink.good));
                }
                Kind::Repulsive | Kind::Tangential => {
                    let r = view.length(piece.radius).max(3.0);
                    painter.circle(at, r, ink.obstacle.gamma_multiply(0.35), stroke);
                    dashed_circle(painter, at, r + range, Stroke::new(1.0, ink.obstacle));
                    if piece.kind == Kind::Tangential {
                        spin_mark(painter, at, r + 10.0, piece.flipped, stroke);
                    }
                }
                Kind::Perpendicular => {
                    let to = view.to_screen(piece.to);
                    painter.line_segment([at, to], Stroke::new(stroke.width + 2.0, stroke.color));
                    let along = (to - at).normalized();
                    let n = vec2(-along.y, along.x) * range;
                    for side in [1.0, -1.0] {
                        let pts = [at + n * side, to + n * side];
                        painter.extend(egui::Shape::dashed_line(
                            &pts,
                            Stroke::new(1.0, ink.obstacle),
                            5.0,
                            4.0,
                        ));
                    }
                }
            }
        }
        if let Some(goal) = self.design.goal {
            star(
                painter,
                view.to_screen(goal),
                10.0,
                ink.good,
                Stroke::new(1.0, ink.text),
            );
        }
    }

    /// The remedies' paths, the point robot's (faint ahead of it, `at`
    /// steps along), the unicycle's trail and the start.
    fn draw_runs(&self, painter: &Painter, view: &PlaneView, ink: &Ink, at: Option<usize>) {
        let path = |points: &[[f64; 2]], color: Color32, width: f32| {
            let pts = points.iter().map(|p| view.to_screen(*p));
            marks::path(painter, pts, Stroke::new(width, color));
        };
        for (run, shown) in self.analysis.remedies.iter().zip(self.design.drawn) {
            if let (true, Some(d)) = (shown, &run.descent) {
                path(&d.path, ink.good.gamma_multiply(0.9), 2.0);
            }
        }
        if let (Some(d), Some(k)) = (&self.descent, at) {
            path(&d.path, ink.accent.gamma_multiply(0.3), 1.5);
            let k = k.min(d.path.len().saturating_sub(1));
            path(&d.path[..=k], ink.accent, 2.5);
            let robot = view.to_screen(d.path[k]);
            painter.circle_filled(robot, 5.0, ink.accent);
            if k + 1 == d.path.len() && d.outcome == Outcome::Trapped {
                // Stuck: a ring round the robot (a cross means a trap, and
                // the robot may have stopped on a saddle instead).
                painter.circle_stroke(robot, 10.0, Stroke::new(2.0, ink.bad));
            }
        }
        if self.settings.unicycle
            && let Some(t) = &self.analysis.trail
        {
            let pts: Vec<[f64; 2]> = t.poses.iter().map(|p| [p.x, p.y]).collect();
            path(&pts, ink.unicycle, 2.0);
            if let Some(last) = t.poses.last() {
                let at = view.to_screen([last.x, last.y]);
                let along = vec2(last.theta.cos() as f32, -last.theta.sin() as f32) * 16.0;
                arrow(painter, at, along, 7.0, Stroke::new(2.0, ink.unicycle));
            }
        }
        let start = view.to_screen(self.design.start);
        painter.circle(
            start,
            7.0,
            ink.accent.gamma_multiply(0.3),
            Stroke::new(2.0, ink.accent),
        );
    }

    fn draw_equilibria(&self, painter: &Painter, view: &PlaneView, ink: &Ink) {
        for e in &self.analysis.equilibria {
            let at = view.to_screen([e.x, e.y]);
            let goal = self
                .design
                .goal
                .is_some_and(|g| (v(g) - Vec2::new(e.x, e.y)).norm() < 1e-6);
            match e.kind {
                Equilibrium::Stable if goal => {
                    painter.circle_stroke(at, 13.0, Stroke::new(2.0, ink.good));
                }
                Equilibrium::Stable => {
                    painter.circle_filled(at, 9.0, ink.bad.gamma_multiply(0.25));
                    cross(painter, at, 7.0, Stroke::new(3.0, ink.bad));
                }
                Equilibrium::Saddle => {
                    let d = 7.0;
                    let pts = vec![
                        at + vec2(0.0, -d),
                        at + vec2(d, 0.0),
                        at + vec2(0.0, d),
                        at + vec2(-d, 0.0),
                        at + vec2(0.0, -d),
                    ];
                    painter.add(egui::Shape::line(pts, Stroke::new(2.0, ink.unicycle)));
                }
                Equilibrium::Unstable => {
                    painter.circle_stroke(at, 5.0, Stroke::new(1.5, ink.faint));
                }
            }
        }
    }

    fn draw_basins(&self, painter: &Painter, view: &PlaneView, ink: &Ink) {
        let Some(map) = &self.analysis.basins else {
            return;
        };
        let s = &map.starts;
        let half = vec2(
            view.length(s.area.width() / s.nx as f64) / 2.0,
            view.length(s.area.height() / s.ny as f64) / 2.0,
        );
        let cells = map.cells.iter().enumerate().map(|(k, b)| {
            let at = view.to_screen(w(s.start(k)));
            (Rect::from_center_size(at, half * 2.0), basin_color(*b, ink))
        });
        marks::cells(painter, cells);
    }

    /// Handles for every piece, the start and (when it stands alone) the
    /// goal. Returns whether one is held.
    fn handles(&mut self, ui: &mut egui::Ui, view: &PlaneView) -> bool {
        let mut held = false;
        let area = self.area;
        let clamp = |p: [f64; 2]| area.clamp(p[0], p[1]);
        let base = ui.scope_id().with("sandbox");
        for i in 0..self.design.pieces.len() {
            let piece = self.design.pieces[i];
            if piece.kind == Kind::Uniform || self.edit_mode(i) != Some(false) {
                continue;
            }
            let label = format!("{} field {}", piece.kind.name(), i + 1);
            let h = handle(ui, base.with(i), view.to_screen(piece.at), 10.0, &label);
            held |= h.held();
            if h.clicked() || h.dragged() {
                self.selected = Some(i);
            }
            if h.dragged() {
                let d = view.delta_to_world(h.moved);
                let goal_here = self.design.goal.is_some_and(|g| g == piece.at)
                    && piece.kind == Kind::Attractive;
                let p = &mut self.design.pieces[i];
                p.at = clamp([p.at[0] + d[0], p.at[1] + d[1]]);
                if p.kind == Kind::Perpendicular {
                    p.to = clamp([p.to[0] + d[0], p.to[1] + d[1]]);
                }
                if goal_here {
                    self.design.goal = Some(p.at);
                }
                self.changed();
            }
            if piece.kind == Kind::Perpendicular {
                let h = handle(
                    ui,
                    base.with((i, "end")),
                    view.to_screen(piece.to),
                    9.0,
                    &format!("{label}, far end"),
                );
                held |= h.held();
                let p = &mut self.design.pieces[i];
                if let Some(to) = h.dragged_to(view, p.to) {
                    p.to = clamp(to);
                    self.changed();
                }
            }
        }
        let h = handle(
            ui,
            base.with("start"),
            view.to_screen(self.design.start),
            10.0,
            "Robot start",
        );
        held |= h.held();
        if let Some(to) = h.dragged_to(view, self.design.start) {
            self.design.start = clamp(to);
            self.restart();
        }
        held
    }
}

fn basin_color(b: Basin, ink: &Ink) -> Color32 {
    let traps = theme::TRAP_COLORS;
    match b {
        Basin::Goal => ink.good.gamma_multiply(0.3),
        Basin::Trap { minimum } => traps[minimum % traps.len()].gamma_multiply(0.35),
        Basin::Stalled => theme::NEUTRAL.gamma_multiply(0.35),
        Basin::Wandering => theme::YELLOW.gamma_multiply(0.3),
    }
}

/// A small curved arrow showing a tangential field's turn.
fn spin_mark(painter: &Painter, at: Pos2, r: f32, clockwise: bool, stroke: Stroke) {
    let sign = if clockwise { 1.0 } else { -1.0 };
    let pts: Vec<Pos2> = (0..=12)
        .map(|i| {
            let a = -0.9 + 1.8 * i as f32 / 12.0;
            at + vec2(a.cos(), sign * a.sin()) * r
        })
        .collect();
    let end = pts[12];
    let before = pts[11];
    painter.add(egui::Shape::line(pts, stroke));
    arrow(painter, before, (end - before) * 1.5, 7.0, stroke);
}

/// How many rows of cells as square as `columns` columns give over `area`,
/// within `[min, max]`.
fn rows(area: &kinolab_world::Rect, columns: usize, min: f64, max: f64) -> usize {
    (columns as f64 * area.height() / area.width())
        .round()
        .clamp(min, max) as usize
}

/// A field magnitude `m` as 0 to 1, rising fast and then levelling off (a
/// quarter of the field's scale gives 63 %).
fn strength(field: &Field, m: f64) -> f32 {
    (1.0 - (-m / (field.scale() * 0.25)).exp()) as f32
}

/// What the backdrop is sampled for.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Wanted {
    version: u64,
    /// A piece is being dragged: coarser shading and arrows and shorter
    /// streamlines, so the drag keeps up on a slow phone (the arrows were
    /// most of a dragged frame's drawing); full detail on release.
    coarse: bool,
    shading: bool,
    streamlines: bool,
}

/// What the canvas draws under the pieces, sampled once per version of the
/// field: a hover, a scroll or a played descent redraws from it without
/// evaluating the field again.
#[derive(Debug, Default)]
pub(super) struct Backdrop {
    sampled: Option<Wanted>,
    /// The field's area the grids cover, m.
    size: [f64; 2],
    /// Cell centres and the field there, row by row, and the grid's size.
    shade: Vec<(Vec2, Vec2)>,
    shade_grid: (usize, usize),
    arrows: Vec<(Vec2, Vec2)>,
    arrow_grid: (usize, usize),
    lines: Vec<Vec<Vec2>>,
}

impl Backdrop {
    fn update(&mut self, field: &Field, area: &kinolab_world::Rect, wanted: Wanted) {
        if self.sampled == Some(wanted) {
            return;
        }
        self.sampled = Some(wanted);
        self.size = [area.width(), area.height()];
        let columns = if wanted.coarse {
            SHADE_COLUMNS / 2
        } else {
            SHADE_COLUMNS
        };
        self.shade_grid = (columns, rows(area, columns, 4.0, 60.0));
        self.shade = match wanted.shading {
            true => field.arrows(area, self.shade_grid.0, self.shade_grid.1),
            false => Vec::new(),
        };
        let columns = if wanted.coarse {
            ARROW_COLUMNS / 2
        } else {
            ARROW_COLUMNS
        };
        self.arrow_grid = (columns, rows(area, columns, 3.0, 30.0));
        self.arrows = field.arrows(area, self.arrow_grid.0, self.arrow_grid.1);
        let steps = if wanted.coarse { 150 } else { 400 };
        self.lines = match wanted.streamlines {
            true => streamlines(area, field, steps),
            false => Vec::new(),
        };
    }

    /// A cell of a `grid` (columns, rows) over the area, m.
    fn cell(&self, (nx, ny): (usize, usize)) -> [f64; 2] {
        [
            self.size[0] / nx.max(1) as f64,
            self.size[1] / ny.max(1) as f64,
        ]
    }
}

/// The field's strength as shading: stronger is darker accent.
fn shade(painter: &Painter, view: &PlaneView, b: &Backdrop, field: &Field, color: Color32) {
    let (hx, hy) = (b.cell(b.shade_grid)[0] / 2.0, b.cell(b.shade_grid)[1] / 2.0);
    let shading = b.shade.iter().map(|&(p, f)| {
        let t = strength(field, f.norm());
        let a = view.to_screen([p.x - hx, p.y + hy]);
        let c = view.to_screen([p.x + hx, p.y - hy]);
        (Rect::from_two_pos(a, c), color.gamma_multiply(0.35 * t))
    });
    marks::cells(painter, shading);
}

/// Arrows on a grid: direction exact, length growing with strength up to
/// most of a cell.
fn arrows(painter: &Painter, view: &PlaneView, b: &Backdrop, field: &Field, color: Color32) {
    let cell = view.length(b.cell(b.arrow_grid)[0]);
    for &(p, f) in &b.arrows {
        let m = f.norm();
        if m < 1e-9 {
            continue;
        }
        let len = cell * 0.8 * strength(field, m);
        let dir = vec2(f.x as f32, -f.y as f32) / m as f32;
        let at = view.to_screen(w(p)) - dir * len / 2.0;
        arrow(painter, at, dir * len, 4.0, Stroke::new(1.0, color));
    }
}

/// The streamlines, as screen polylines.
fn lines(painter: &Painter, view: &PlaneView, b: &Backdrop, color: Color32) {
    for line in &b.lines {
        let pts = line.iter().map(|&p| view.to_screen(w(p)));
        marks::path(painter, pts, Stroke::new(1.0, color));
    }
}

/// Streamlines from a grid of seeds, each followed downstream for at most
/// `steps` steps.
fn streamlines(area: &kinolab_world::Rect, field: &Field, steps: usize) -> Vec<Vec<Vec2>> {
    let step = (area.width() + area.height()) / 300.0 * 400.0 / steps as f64;
    let mut lines = Vec::with_capacity(15);
    for j in 0..3 {
        for i in 0..5 {
            let mut p = Vec2::new(
                area.x_min + (i as f64 + 0.25) * area.width() / 5.0,
                area.y_min + (j as f64 + 0.5) * area.height() / 3.0,
            );
            let mut line = vec![p];
            for _ in 0..steps {
                let f = field.vector(p);
                if f.norm() < 1e-6 || !area.contains(p.x, p.y) {
                    break;
                }
                p += f / f.norm() * step;
                line.push(p);
            }
            lines.push(line);
        }
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_backdrop_is_sampled_once_per_field_and_coarser_while_dragging() {
        let preset = kinolab_fields::catalogue::preset("u-shaped-wall").expect("a preset");
        let field = preset.field().expect("a field");
        let area = kinolab_world::Rect::from(preset.area);
        let still = Wanted {
            version: 1,
            coarse: false,
            shading: true,
            streamlines: true,
        };
        let mut b = Backdrop::default();
        b.update(&field, &area, still);
        let (nx, ny) = b.shade_grid;
        assert_eq!((nx, b.shade.len()), (SHADE_COLUMNS, nx * ny));
        assert_eq!(b.lines.len(), 15);
        let arrows_still = b.arrows.len();
        // The same field again (a hover, a scroll): nothing is resampled.
        let first = b.shade.as_ptr();
        b.update(&field, &area, still);
        assert_eq!(b.shade.as_ptr(), first);
        // Dragging: a quarter of the shading's samples.
        b.update(
            &field,
            &area,
            Wanted {
                version: 2,
                coarse: true,
                ..still
            },
        );
        assert_eq!(b.shade_grid.0, SHADE_COLUMNS / 2);
        assert_eq!(b.arrow_grid.0, ARROW_COLUMNS / 2);
        assert!(b.arrows.len() * 3 < arrows_still, "{}", b.arrows.len());
        assert!(
            b.shade.len() * 3 < nx * ny,
            "{} of {}",
            b.shade.len(),
            nx * ny
        );
        // The samples are the field's own values at the cell centres.
        let (p, f) = b.arrows[7];
        assert_eq!(field.vector(p), f);
        // Shading off: nothing sampled for it.
        b.update(
            &field,
            &area,
            Wanted {
                shading: false,
                ..still
            },
        );
        assert!(b.shade.is_empty());
    }
}
