//! The grid planner: a world turned into an occupancy grid for a robot of
//! some radius, and Dijkstra or A* searching it cell by cell. Drag the
//! start and the goal, change the cell size and the robot's radius, and
//! play the search to watch its frontier grow.

use egui::{Color32, Painter, Pos2, Rect, RichText, Sense, Stroke, vec2};
use kinolab_common::display::fixed;
use kinolab_world::grid::{Cell, Grid};
use kinolab_world::search::{Algorithm, Search};
use kinolab_world::{Vec2, World};
use serde::{Deserialize, Serialize};

use crate::behaviour::world_view::draw_world;
use crate::draw::labels::Labels;
use crate::draw::{PlaneView, canvas, handle};
use crate::widget::{LabWidget, Params};
use crate::{link, theme};

/// Cells the animation expands per second.
const CELLS_PER_SECOND: f64 = 240.0;

/// What the learner changed, and what a link carries.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Setup {
    cell: f64,
    radius: f64,
    start: [f64; 2],
    goal: [f64; 2],
    astar: bool,
}

struct GridPlanner {
    world: World,
    setup: Setup,
    initial: Setup,
    /// The grid for `(cell, radius)`.
    grid: Option<(f64, f64, Grid)>,
    /// Both searches for the current set-up.
    searches: Option<(Setup, Search, Search)>,
    /// How many expansions are shown; `None` shows them all.
    shown: Option<f64>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let id = p.choice("world").unwrap_or("two-rooms");
    let world = kinolab_world::catalogue::world(id).map_err(|e| e.to_string())?;
    let b = world.bounds;
    let goal = world
        .goal
        .map_or([b.x_max - 1.0, b.y_max - 1.0], |g| [g.x, g.y]);
    let setup = Setup {
        cell: p.number("cell").unwrap_or(0.25),
        radius: world.robot_radius,
        start: [world.start.x, world.start.y],
        goal,
        astar: true,
    };
    Ok(Box::new(GridPlanner {
        world,
        initial: setup.clone(),
        setup,
        grid: None,
        searches: None,
        shown: None,
    }))
}

impl GridPlanner {
    /// The grid, rebuilt only when the cell size or the radius changes.
    fn grid(&mut self) -> Option<&Grid> {
        let (cell, radius) = (self.setup.cell, self.setup.radius);
        let stale = !matches!(&self.grid, Some((c, r, _)) if *c == cell && *r == radius);
        if stale {
            self.grid = Grid::new(&self.world, cell, radius)
                .ok()
                .map(|g| (cell, radius, g));
            self.searches = None;
        }
        self.grid.as_ref().map(|(_, _, g)| g)
    }

    /// Dijkstra's and A*'s searches, redone only when the set-up changes.
    fn searches(&mut self) -> Option<(Search, Search)> {
        let setup = Setup {
            astar: false,
            ..self.setup.clone()
        };
        if let Some((s, d, a)) = &self.searches
            && *s == setup
        {
            return Some((d.clone(), a.clone()));
        }
        let grid = self.grid()?.clone();
        let start = grid.cell_of(v(self.setup.start))?;
        let goal = grid.cell_of(v(self.setup.goal))?;
        let d = grid.search(start, goal, Algorithm::Dijkstra);
        let a = grid.search(start, goal, Algorithm::AStar);
        self.searches = Some((setup, d.clone(), a.clone()));
        Some((d, a))
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.selectable_value(&mut self.setup.astar, false, "Dijkstra");
            ui.selectable_value(&mut self.setup.astar, true, "A* (octile)");
            let label = if self.shown.is_some() {
                "Show all"
            } else {
                "Play the search"
            };
            if ui.button(label).clicked() {
                self.shown = if self.shown.is_some() {
                    None
                } else {
                    Some(0.0)
                };
            }
            if ui.button("Reset").clicked() {
                self.setup = self.initial.clone();
                self.shown = None;
            }
        });
        crate::widget::control_row(ui, |ui| {
            ui.add(egui::Slider::new(&mut self.setup.cell, 0.1..=1.0).text("cell s (m)"));
            ui.add(egui::Slider::new(&mut self.setup.radius, 0.0..=0.6).text("robot radius (m)"));
        });
    }
}

fn v(p: [f64; 2]) -> Vec2 {
    Vec2::new(p[0], p[1])
}

/// The grid's occupied cells, the expanded ones shaded by order, the path.
fn draw_search(
    ui: &egui::Ui,
    painter: &Painter,
    view: &PlaneView,
    grid: &Grid,
    search: &Search,
    shown: usize,
) {
    let half = grid.cell / 2.0;
    let cell_rect = |c: Cell| {
        let p = grid.centre(c);
        Rect::from_two_pos(
            view.to_screen([p.x - half, p.y + half]),
            view.to_screen([p.x + half, p.y - half]),
        )
    };
    let ink = ui.visuals().text_color();
    for j in 0..grid.ny {
        for i in 0..grid.nx {
            if !grid.is_free((i, j)) {
                painter.rect_filled(cell_rect((i, j)), 0.0, ink.gamma_multiply(0.22));
            }
        }
    }
    let accent = theme::accent(ui);
    let n = search.expanded.len().max(1) as f32;
    for (k, &c) in search.expanded.iter().take(shown).enumerate() {
        let early = 1.0 - k as f32 / n;
        painter.rect_filled(
            cell_rect(c).shrink(0.5),
            0.0,
            accent.gamma_multiply(0.12 + 0.33 * early),
        );
    }
    if shown >= search.expanded.len() && search.path.len() > 1 {
        let points: Vec<Pos2> = search
            .path
            .iter()
            .map(|&c| {
                let p = grid.centre(c);
                view.to_screen([p.x, p.y])
            })
            .collect();
        painter.add(egui::Shape::line(
            points,
            Stroke::new(3.0, theme::good_color(ui)),
        ));
    }
}

fn marker(painter: &Painter, labels: &mut Labels, at: Pos2, color: Color32, text: &str) {
    painter.circle(at, 9.0, color, Stroke::new(1.5, Color32::WHITE));
    labels.reserve(egui::Rect::from_center_size(at, vec2(20.0, 20.0)));
    labels
        .add(at, text, color)
        .toward(vec2(0.0, -1.0))
        .beyond(6.0);
}

/// The counts, in words.
fn summary(d: &Search, a: &Search, astar: bool) -> String {
    let cost = d
        .cost
        .map_or("no path: the goal cannot be reached".to_owned(), |c| {
            format!("shortest path {} m", fixed(c, 2))
        });
    let (mine, other) = if astar { (a, d) } else { (d, a) };
    format!(
        "{cost}. {} expanded {} cells; {} would expand {}.",
        if astar { "A*" } else { "Dijkstra" },
        mine.expanded.len(),
        if astar { "Dijkstra" } else { "A*" },
        other.expanded.len()
    )
}

impl LabWidget for GridPlanner {
    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        let width = ui.available_width();
        let b = self.world.bounds;
        let height = (width * (b.height() / b.width()) as f32).clamp(200.0, 520.0);
        let (response, painter) = canvas(ui, vec2(width, height), Sense::hover());
        let rect = response.rect;
        let view = PlaneView::fit(rect.shrink(8.0), [b.x_min, b.y_min], [b.x_max, b.y_max]);
        // The world first (it paints the floor), the grid and search over it.
        draw_world(ui, &painter, &view, &self.world, 0.0);
        let searches = self.searches();
        if let (Some((d, a)), Some(grid)) = (&searches, self.grid().cloned()) {
            let search = if self.setup.astar { a } else { d };
            let shown = self.shown.map_or(usize::MAX, |s| s as usize);
            draw_search(ui, &painter, &view, &grid, search, shown);
        }
        let clamp = |p: [f64; 2]| {
            [
                p[0].clamp(b.x_min, b.x_max - 1e-6),
                p[1].clamp(b.y_min, b.y_max - 1e-6),
            ]
        };
        for (id, which) in [("start", 0), ("goal", 1)] {
            let at = if which == 0 {
                self.setup.start
            } else {
                self.setup.goal
            };
            let h = handle(ui, ui.scope_id().with(id), view.to_screen(at), 10.0, id);
            if let Some(to) = h.dragged_to(&view, at) {
                let moved = clamp(to);
                if which == 0 {
                    self.setup.start = moved;
                } else {
                    self.setup.goal = moved;
                }
                self.shown = None;
            }
        }
        let mut labels = Labels::default();
        let start = view.to_screen(self.setup.start);
        marker(&painter, &mut labels, start, theme::accent(ui), "start");
        let goal = view.to_screen(self.setup.goal);
        marker(&painter, &mut labels, goal, theme::good_color(ui), "goal");
        labels.draw(&painter, &egui::FontId::proportional(theme::LABEL_SIZE));
        if let Some(shown) = &mut self.shown {
            *shown += CELLS_PER_SECOND * crate::widget::frame_dt(ui);
            crate::widget::animate(ui);
        }
        let text = match &searches {
            Some((d, a)) => summary(d, a, self.setup.astar),
            None => "The start or the goal is in an occupied cell (or the cell size does not fit the world): move it onto a free cell.".to_owned(),
        };
        ui.label(RichText::new(text).strong());
        ui.label(RichText::new("Grey cells are occupied for a robot of this radius: their centres are within the radius of an obstacle. Shaded cells were expanded, darker first.").small());
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.setup, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let b = self.world.bounds;
        let inside = |p: [f64; 2]| {
            (b.x_min..=b.x_max).contains(&p[0]) && (b.y_min..=b.y_max).contains(&p[1])
        };
        if let Some(s) = link::decode::<Setup>(state)
            && (0.1..=1.0).contains(&s.cell)
            && (0.0..=0.6).contains(&s.radius)
            && inside(s.start)
            && inside(s.goal)
        {
            self.setup = s;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_summary_counts_both_searches() {
        let world = kinolab_world::catalogue::world("two-rooms").unwrap();
        let grid = Grid::new(&world, 0.25, world.robot_radius).unwrap();
        let (s, g) = (
            grid.cell_of(Vec2::new(1.0, 1.0)).unwrap(),
            grid.cell_of(Vec2::new(9.0, 5.0)).unwrap(),
        );
        let d = grid.search(s, g, Algorithm::Dijkstra);
        let a = grid.search(s, g, Algorithm::AStar);
        let text = summary(&d, &a, true);
        assert!(text.starts_with("shortest path "), "{text}");
        assert!(a.expanded.len() < d.expanded.len());
        assert!(
            text.contains(&format!("A* expanded {} cells", a.expanded.len())),
            "{text}"
        );
    }
}
