//! The grid planner: a world turned into an occupancy grid for a robot of
//! some radius, and Dijkstra or A* searching it cell by cell, which the
//! player plays, steps and scrubs. Drag the start and the goal, change the
//! cell size and the robot's radius: the search is done again and shown
//! whole; play it to watch its frontier grow.

use std::sync::Arc;

use egui::{Color32, Painter, Pos2, Rect, RichText, Sense, Stroke, vec2};
use kinolab_common::display::fixed;
use kinolab_world::grid::{Cell, Grid};
use kinolab_world::search::{Algorithm, Search};
use kinolab_world::{Vec2, World};
use serde::{Deserialize, Serialize};

use crate::behaviour::world_view::draw_world;
use crate::draw::labels::Labels;
use crate::draw::{PlaneView, canvas, handle, marks};
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::player::{Player, Simulation, Speed};
use crate::theme;
use crate::widget::{LabWidget, Params, SavedRun, range};

/// The widget's name in the schema.
const NAME: &str = "grid-planner";

/// Cells the search expands per second at 1×, one a tick (it plays at 4×
/// at first: 240 a second).
const CELLS_PER_SECOND: f64 = 60.0;

/// What the lesson sets and a link carries: the schema's parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    world: String,
    cell: f64,
    /// The world's own robot radius, start and goal when `None`.
    radius: Option<f64>,
    start: Option<[f64; 2]>,
    goal: Option<[f64; 2]>,
    algorithm: Algo,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum Algo {
    Astar,
    Dijkstra,
}

impl Algo {
    fn core(self) -> Algorithm {
        match self {
            Algo::Astar => Algorithm::AStar,
            Algo::Dijkstra => Algorithm::Dijkstra,
        }
    }

    /// As `kinolab plan --algorithm` takes it.
    fn name(self) -> &'static str {
        match self {
            Algo::Astar => "astar",
            Algo::Dijkstra => "dijkstra",
        }
    }
}

/// The links of the first format: the widget's own struct.
#[derive(Deserialize)]
struct Legacy {
    cell: f64,
    radius: f64,
    start: [f64; 2],
    goal: [f64; 2],
    astar: bool,
}

/// One search, played a cell a tick (the core does it whole).
#[derive(Debug, Clone)]
struct Expanding {
    search: Arc<Search>,
    /// Cells expanded so far.
    k: usize,
}

impl Simulation for Expanding {
    type Tick = ();
    type Event = ();

    fn step(&mut self) -> Option<()> {
        (self.k < self.search.expanded.len()).then(|| self.k += 1)
    }

    fn time(&self) -> f64 {
        self.k as f64 / CELLS_PER_SECOND
    }

    fn dt(&self) -> f64 {
        1.0 / CELLS_PER_SECOND
    }

    fn spring(&mut self, (): &()) {}
}

/// Both searches of one set-up, on its grid.
struct Searches {
    grid: Grid,
    dijkstra: Search,
    astar: Search,
}

struct GridPlanner {
    world: World,
    settings: Settings,
    initial: Settings,
    /// The grid and both searches for the settings (`None` when the start
    /// or the goal is not on a free cell), and the player of the chosen one.
    searches: Option<Searches>,
    player: Option<Player<Expanding>>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    let world = kinolab_world::catalogue::world(&settings.world).map_err(|e| e.to_string())?;
    let mut widget = GridPlanner {
        world,
        initial: settings.clone(),
        settings,
        searches: None,
        player: None,
    };
    widget.rebuild();
    Ok(Box::new(widget))
}

impl GridPlanner {
    fn radius(&self) -> f64 {
        self.settings.radius.unwrap_or(self.world.robot_radius)
    }

    fn start(&self) -> [f64; 2] {
        let s = self.world.start;
        self.settings.start.unwrap_or([s.x, s.y])
    }

    fn goal(&self) -> [f64; 2] {
        let b = self.world.bounds;
        let fallback = self
            .world
            .goal
            .map_or([b.x_max - 1.0, b.y_max - 1.0], |g| [g.x, g.y]);
        self.settings.goal.unwrap_or(fallback)
    }

    /// The grid and both searches for the settings, and the chosen one on
    /// the player, paused at its start.
    fn rebuild(&mut self) {
        // The world a link or Reset chose (the schema checked its id).
        if let Ok(world) = kinolab_world::catalogue::world(&self.settings.world) {
            self.world = world;
        }
        self.searches = Grid::new(&self.world, self.settings.cell, self.radius())
            .ok()
            .and_then(|grid| {
                let start = grid.cell_of(v(self.start()))?;
                let goal = grid.cell_of(v(self.goal()))?;
                Some(Searches {
                    dijkstra: grid.search(start, goal, Algorithm::Dijkstra),
                    astar: grid.search(start, goal, Algorithm::AStar),
                    grid,
                })
            });
        self.player = self.searches.as_ref().map(|s| {
            let search = match self.settings.algorithm {
                Algo::Astar => &s.astar,
                Algo::Dijkstra => &s.dijkstra,
            };
            let mut player = Player::new(Expanding {
                search: Arc::new(search.clone()),
                k: 0,
            });
            player.speed = Speed::Four;
            player
        });
    }

    /// After a change: the search again, shown whole.
    fn redo(&mut self) {
        self.rebuild();
        if let Some(player) = &mut self.player {
            player.seek(usize::MAX);
        }
    }

    fn controls(&mut self, ui: &mut egui::Ui) {
        let before = self.settings.clone();
        let mut radius = self.radius();
        let s = &mut self.settings;
        ui.horizontal_wrapped(|ui| {
            crate::widget::choose(ui, &mut s.algorithm, Algo::Dijkstra, "Dijkstra");
            crate::widget::choose(ui, &mut s.algorithm, Algo::Astar, "A* (octile)");
            if ui
                .button("Play the search")
                .on_hover_text("From the first cell, as it expands")
                .clicked()
                && let Some(player) = &mut self.player
            {
                player.restart();
            }
            if ui.button("Show all").clicked()
                && let Some(player) = &mut self.player
            {
                player.playing = false;
                player.seek(usize::MAX);
            }
            if ui.button("Reset").clicked() {
                *s = self.initial.clone();
            }
        });
        crate::widget::control_row(ui, |ui| {
            ui.add(egui::Slider::new(&mut s.cell, range(NAME, "cell")).text("cell s (m)"));
            let slider = egui::Slider::new(&mut radius, range(NAME, "radius"));
            if ui.add(slider.text("robot radius (m)")).changed() {
                s.radius = Some(radius);
            }
        });
        if self.settings != before {
            self.redo();
        }
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
    ends: [[f64; 2]; 2],
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
    let walls = (0..grid.ny)
        .flat_map(|j| (0..grid.nx).map(move |i| (i, j)))
        .filter(|&c| !grid.is_free(c))
        .map(|c| (cell_rect(c), ink.gamma_multiply(0.22)));
    marks::cells(painter, walls);
    let accent = theme::accent(ui);
    let n = search.expanded.len().max(1) as f32;
    let searched = search.expanded.iter().take(shown).enumerate();
    let searched = searched.map(|(k, &c)| {
        let early = 1.0 - k as f32 / n;
        let color = accent.gamma_multiply(0.12 + 0.33 * early);
        (cell_rect(c).shrink(0.5), color)
    });
    marks::cells(painter, searched);
    if shown >= search.expanded.len() && search.path.len() > 1 {
        draw_path(ui, painter, view, grid, &search.path, ends);
    }
}

/// The path from cell centre to cell centre (the length the search
/// measures), and a dashed step from the start dot to the first centre and
/// from the last centre to the goal dot: with big cells the dots sit off
/// the centres.
fn draw_path(
    ui: &egui::Ui,
    painter: &Painter,
    view: &PlaneView,
    grid: &Grid,
    path: &[Cell],
    [start, goal]: [[f64; 2]; 2],
) {
    let colour = theme::good_color(ui);
    let points: Vec<Pos2> = path
        .iter()
        .map(|&c| {
            let p = grid.centre(c);
            view.to_screen([p.x, p.y])
        })
        .collect();
    let (Some(&first), Some(&last)) = (points.first(), points.last()) else {
        return;
    };
    let step = Stroke::new(2.0, colour);
    for (dot, centre) in [(start, first), (goal, last)] {
        let dashes = egui::Shape::dashed_line(&[view.to_screen(dot), centre], step, 5.0, 4.0);
        painter.extend(dashes);
    }
    painter.add(egui::Shape::line(points, Stroke::new(3.0, colour)));
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
        .map_or("No path: the goal cannot be reached".to_owned(), |c| {
            format!("Shortest path {} m", fixed(c, 2))
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

impl GridPlanner {
    /// The world, the grid, the search as far as it has got, and the
    /// start and goal handles; where it was drawn.
    fn picture(&mut self, ui: &mut egui::Ui) -> Rect {
        let width = ui.available_width();
        let b = self.world.bounds;
        let height = (width * (b.height() / b.width()) as f32).clamp(200.0, 520.0);
        let (response, painter) = canvas(ui, vec2(width, height), Sense::hover());
        let view = PlaneView::fit(
            response.rect.shrink(8.0),
            [b.x_min, b.y_min],
            [b.x_max, b.y_max],
        );
        // The world first (it paints the floor), the grid and search over it.
        draw_world(ui, &painter, &view, &self.world, 0.0);
        let ends = [self.start(), self.goal()];
        if let (Some(s), Some(player)) = (&self.searches, &mut self.player) {
            let shown = player.state().k;
            let search = &player.state().search;
            draw_search(ui, &painter, &view, &s.grid, search, shown, ends);
        }
        self.handles(ui, &painter, &view);
        response.rect
    }

    /// The start and the goal, dragged (or moved with the keys).
    fn handles(&mut self, ui: &mut egui::Ui, painter: &Painter, view: &PlaneView) {
        let b = self.world.bounds;
        let clamp = |p: [f64; 2]| {
            [
                p[0].clamp(b.x_min, b.x_max - 1e-6),
                p[1].clamp(b.y_min, b.y_max - 1e-6),
            ]
        };
        let (start, goal) = (self.start(), self.goal());
        for (id, at) in [("start", start), ("goal", goal)] {
            let h = handle(ui, ui.scope_id().with(id), view.to_screen(at), 10.0, id);
            if let Some(to) = h.dragged_to(view, at) {
                let moved = Some(clamp(to));
                if id == "start" {
                    self.settings.start = moved;
                } else {
                    self.settings.goal = moved;
                }
                self.redo();
            }
        }
        let mut labels = Labels::default();
        let accent = theme::accent(ui);
        marker(painter, &mut labels, view.to_screen(start), accent, "start");
        let good = theme::good_color(ui);
        marker(painter, &mut labels, view.to_screen(goal), good, "goal");
        labels.draw(painter, &egui::FontId::proportional(theme::LABEL_SIZE));
    }

    /// The run's input for `kinolab plan`: the world, grown by the radius
    /// chosen here.
    fn world_file(&self) -> String {
        let mut world = self.world.clone();
        world.robot_radius = self.radius();
        world.to_json()
    }

    fn file_name(&self) -> String {
        format!("{}.world.json", self.settings.world)
    }

    fn args(&self) -> Vec<String> {
        let point = |p: [f64; 2]| format!("{},{}", p[0], p[1]);
        vec![
            "plan".into(),
            self.file_name(),
            "--from".into(),
            point(self.start()),
            "--to".into(),
            point(self.goal()),
            "--cell".into(),
            self.settings.cell.to_string(),
            "--algorithm".into(),
            self.settings.algorithm.name().into(),
        ]
    }

    fn exports(&self, ui: &mut egui::Ui, view: Rect) {
        let command = format!("kinolab {}", self.args().join(" "));
        let file = self.file_name();
        let world = || Ok(self.world_file());
        export::bar(
            ui,
            ui.scope_id().with("planner-exports"),
            &[
                Export::Png {
                    file: "kinolab-grid-planner.png",
                    rect: view,
                },
                Export::Run {
                    file: &file,
                    command: &command,
                    make: &world,
                },
            ],
        );
    }
}

impl GridPlanner {
    /// How far the search shown has got, and what both searches find.
    fn status(&self) -> String {
        let (Some(s), Some(player)) = (&self.searches, &self.player) else {
            return "The start or the goal is in an occupied cell (or the cell size does not fit the world): move it onto a free cell.".to_owned();
        };
        let astar = self.settings.algorithm == Algo::Astar;
        let of = if astar { &s.astar } else { &s.dijkstra }.expanded.len();
        // A tick expands a cell: the cursor counts the cells shown.
        let k = player.cursor();
        let now = if k < of {
            format!("Expanded {k} of {of} cells so far. ")
        } else {
            String::new()
        };
        now + summary(&s.dijkstra, &s.astar, astar).as_str()
    }
}

impl LabWidget for GridPlanner {
    /// The world and cell size, then the search as far as it is shown.
    fn describe(&self) -> Option<String> {
        Some(format!(
            "The {} world in cells of {} m. {}",
            self.settings.world,
            fixed(self.settings.cell, 2),
            self.status()
        ))
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        self.controls(ui);
        if let Some(player) = &mut self.player {
            player.controls(ui);
        }
        let view = self.picture(ui);
        if let Some(player) = &mut self.player {
            let cells = player.state().search.expanded.len();
            player.timeline(ui, "Cells expanded", cells, &mut |_, _, _, _| {});
            player.run(ui, 8);
        }
        ui.label(RichText::new(self.status()).strong());
        ui.label(RichText::new("Grey cells are occupied for a robot of this radius: their centres are within the radius of an obstacle. Shaded cells were expanded, darker first.").small());
        self.exports(ui, view);
    }

    fn state(&self) -> Option<String> {
        let moment = self.player.as_ref().map(Player::moment).unwrap_or_default();
        link::write(NAME, &self.settings, &self.initial, &moment)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if link::is_bare(state) {
            return Err("it is empty (cut short)".into());
        }
        let (settings, moment) = match link::read::<Settings, ()>(NAME, state) {
            Ok(read) => read,
            Err(why) => match link::decode::<Legacy>(state) {
                Some(old) => (
                    Settings {
                        cell: old.cell,
                        radius: Some(old.radius),
                        start: Some(old.start),
                        goal: Some(old.goal),
                        algorithm: if old.astar {
                            Algo::Astar
                        } else {
                            Algo::Dijkstra
                        },
                        ..self.initial.clone()
                    },
                    // The first format showed the whole search.
                    Moment {
                        instant: f64::INFINITY,
                        events: Vec::new(),
                    },
                ),
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema's ranges too.
        link::check(NAME, &settings)?;
        self.settings = settings;
        self.rebuild();
        if let Some(player) = &mut self.player {
            player.replay(&moment.events, moment.instant);
        }
        Ok(())
    }

    fn seek(&mut self, t: f64) {
        if let Some(player) = &mut self.player {
            player.seek_time(t);
        }
    }

    /// The search's result as `kinolab plan` prints it: the line under
    /// the picture gives it from the start.
    fn saved_run(&mut self) -> Option<SavedRun> {
        let s = self.searches.as_ref()?;
        let found = s
            .grid
            .plan(
                v(self.start()),
                v(self.goal()),
                self.settings.algorithm.core(),
            )
            .ok()?;
        let mut shows = Vec::new();
        match found {
            Some(path) => {
                let report = kinolab_common::display::tidy_report(&path).ok()?;
                for key in ["cost", "cells", "expanded"] {
                    shows.push((format!("/{key}"), report.get(key)?.clone()));
                }
            }
            None => {
                shows.push(("/cost".into(), serde_json::Value::Null));
                shows.push(("/cells".into(), serde_json::json!([])));
            }
        }
        Some(SavedRun {
            file: self.file_name(),
            text: self.world_file(),
            args: self.args(),
            shows,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::spec;

    fn widget(params: &[(&str, &str)]) -> GridPlanner {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        let settings: Settings = p.settings().unwrap_or_else(|e| panic!("{e}"));
        let mut w = GridPlanner {
            world: kinolab_world::catalogue::world(&settings.world).unwrap(),
            initial: settings.clone(),
            settings,
            searches: None,
            player: None,
        };
        w.rebuild();
        w
    }

    fn expanded(w: &mut GridPlanner) -> usize {
        w.player.as_mut().map_or(0, |p| p.state().k)
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        let old = (0.5_f64, 0.3_f64, [1.0_f64, 1.0], [9.0_f64, 5.0], false);
        let mut w = widget(&[]);
        assert_eq!(w.restore(&link::encode(&old).unwrap_or_default()), Ok(()));
        assert_eq!(w.settings.cell, 0.5);
        assert_eq!(w.settings.radius, Some(0.3));
        assert_eq!(w.settings.goal, Some([9.0, 5.0]));
        assert_eq!(w.settings.algorithm, Algo::Dijkstra);
        let all = w.searches.as_ref().map_or(0, |s| s.dijkstra.expanded.len());
        assert!(all > 0);
        assert_eq!(expanded(&mut w), all, "shown whole, as it was");
        // Out of the schema's range, or off the world: refused, the
        // lesson's settings kept.
        for bad in [
            (5.0_f64, 0.3_f64, [1.0_f64, 1.0], [9.0_f64, 5.0], true),
            (0.5, 0.3, [1.0, 1.0], [90.0, 5.0], true),
        ] {
            let mut w = widget(&[("cell", "0.4")]);
            assert!(w.restore(&link::encode(&bad).unwrap_or_default()).is_err());
            assert_eq!(w.settings.cell, 0.4);
            assert_eq!(w.settings.goal, None);
        }
    }

    #[test]
    fn the_instant_travels_in_the_link() {
        let mut w = widget(&[("world", "corridor"), ("radius", "0.3")]);
        w.settings.goal = Some([2.0, 2.0]);
        w.settings.algorithm = Algo::Dijkstra;
        w.rebuild();
        w.seek(0.8);
        assert_eq!(expanded(&mut w), 48);
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.settings, w.settings);
        assert_eq!(expanded(&mut again), 48);
        assert_eq!(again.saved_run(), w.saved_run());
    }

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
        assert!(text.starts_with("Shortest path "), "{text}");
        assert!(a.expanded.len() < d.expanded.len());
        assert!(
            text.contains(&format!("A* expanded {} cells", a.expanded.len())),
            "{text}"
        );
    }
}
