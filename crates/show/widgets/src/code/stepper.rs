//! Step through your own code: the recorded run of one world on the
//! player, the scene at the instant, what the function was given and
//! answered and printed then, and its `plot` values as curves.

use std::collections::BTreeMap;
use std::rc::Rc;

use egui::{Color32, RichText, Stroke, vec2};
use egui_plot::{Plot, PlotPoints};
use kinolab_exercises::trace::{Outline, Scene, Tick, Trace};
use kinolab_world::Pose;

use crate::behaviour::world_view::{draw_robot, draw_trail, draw_world};
use crate::draw::PlaneView;
use crate::draw::marks::{arrow, star};
use crate::draw::plot::{REFERENCE, series_legend, series_lines};
use crate::player::{Player, Simulation};
use crate::theme;

/// A recorded trace, stepped call by call.
#[derive(Debug, Clone)]
pub(super) struct Stepping {
    trace: Rc<Trace>,
    /// Calls shown so far.
    k: usize,
}

impl Stepping {
    pub(super) fn new(trace: Rc<Trace>) -> Self {
        Self { trace, k: 0 }
    }

    /// The call at the instant (the first before anything ran).
    pub(super) fn tick(&self) -> Option<&Tick> {
        self.trace.ticks.get(self.k)
    }

    pub(super) fn trace(&self) -> &Trace {
        &self.trace
    }
}

impl Simulation for Stepping {
    type Tick = ();
    type Event = ();

    fn step(&mut self) -> Option<()> {
        (self.k + 1 < self.trace.ticks.len()).then(|| self.k += 1)
    }

    fn time(&self) -> f64 {
        self.tick().map_or(0.0, |t| t.t - self.start())
    }

    fn dt(&self) -> f64 {
        let ticks = &self.trace.ticks;
        match (ticks.first(), ticks.last()) {
            (Some(a), Some(b)) if ticks.len() > 1 => {
                ((b.t - a.t) / (ticks.len() - 1) as f64).max(1e-3)
            }
            _ => 0.05,
        }
    }

    fn spring(&mut self, (): &()) {}
}

impl Stepping {
    /// The first call's time: the player's clock starts at zero there.
    fn start(&self) -> f64 {
        self.trace.ticks.first().map_or(0.0, |t| t.t)
    }
}

/// The scene at the instant, beside the function's inputs and answer.
pub(super) fn show(ui: &mut egui::Ui, player: &mut Player<Stepping>) {
    player.run(ui, 16);
    player.controls(ui);
    let wide = ui.available_width() >= 700.0;
    let state = player.state().clone();
    if wide {
        ui.horizontal_top(|ui| {
            let w = ui.available_width() * 0.58;
            scene(ui, &state, w);
            ui.vertical(|ui| panel(ui, &state));
        });
    } else {
        scene(ui, &state, ui.available_width());
        panel(ui, &state);
    }
    let ticks = state.trace().ticks.len();
    player.timeline(
        ui,
        "Your run, call by call",
        ticks.saturating_sub(1),
        &mut |_, _, _, _| {},
    );
    plots(ui, &state);
}

/// The area to show for a scene and path.
fn area(state: &Stepping) -> ([f64; 2], [f64; 2]) {
    let t = state.trace();
    match &t.scene {
        Scene::Plane { area } | Scene::Field { area, .. } => {
            let (mut lo, mut hi) = ([area[0], area[1]], [area[2], area[3]]);
            for p in &t.path {
                lo = [lo[0].min(p[0] - 0.2), lo[1].min(p[1] - 0.2)];
                hi = [hi[0].max(p[0] + 0.2), hi[1].max(p[1] + 0.2)];
            }
            (lo, hi)
        }
        Scene::World(w) => (
            [w.bounds.x_min, w.bounds.y_min],
            [w.bounds.x_max, w.bounds.y_max],
        ),
        Scene::Legs { .. } => ([-0.35, -0.3], [0.35, 0.3]),
        Scene::Arm { reach, .. } => ([-reach - 0.1, -reach - 0.1], [reach + 0.1, reach + 0.1]),
    }
}

fn scene(ui: &mut egui::Ui, state: &Stepping, width: f32) {
    let (rect, _) = ui.allocate_exact_size(
        vec2(width, (width * 0.62).clamp(200.0, 420.0)),
        egui::Sense::hover(),
    );
    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 4.0, ui.visuals().extreme_bg_color);
    let (lo, hi) = area(state);
    let view = PlaneView::fit(rect.shrink(8.0), lo, hi);
    let ink = ui.visuals().text_color();
    let accent = theme::accent(ui);
    let t = state.trace();
    let tick = state.tick();
    let time = tick.map_or(0.0, |k| k.t);
    match &t.scene {
        Scene::Plane { .. } => {
            star(
                &painter,
                view.to_screen([0.0, 0.0]),
                10.0,
                theme::good_color(ui),
                Stroke::new(1.0, ink),
            );
            arrow(
                &painter,
                view.to_screen([0.0, 0.0]),
                vec2(view.length(0.3), 0.0),
                6.0,
                Stroke::new(1.5, theme::good_color(ui)),
            );
        }
        Scene::World(w) => draw_world(ui, &painter, &view, w, time),
        Scene::Field {
            arrows,
            obstacles,
            goal,
            ..
        } => {
            for outline in obstacles {
                draw_outline(&painter, &view, outline, ui.visuals().text_color());
            }
            for [x, y, fx, fy] in arrows {
                let n = fx.hypot(*fy);
                if n > 1e-9 && n.is_finite() {
                    let along = vec2((fx / n) as f32, -(fy / n) as f32) * 9.0;
                    let at = view.to_screen([*x, *y]) - along / 2.0;
                    arrow(
                        &painter,
                        at,
                        along,
                        3.0,
                        Stroke::new(1.0, ui.visuals().weak_text_color()),
                    );
                }
            }
            if let Some(g) = goal {
                star(
                    &painter,
                    view.to_screen(*g),
                    9.0,
                    theme::good_color(ui),
                    Stroke::new(1.0, ink),
                );
            }
        }
        Scene::Legs { com } => legs(&painter, &view, tick, *com, ink, accent),
        Scene::Arm { target, .. } => {
            let ground = [view.to_screen([-1.2, 0.0]), view.to_screen([1.2, 0.0])];
            painter.line_segment(ground, Stroke::new(1.0, ui.visuals().weak_text_color()));
            draw_chain(
                &painter,
                &view,
                target,
                Stroke::new(2.0, theme::good_color(ui).gamma_multiply(0.6)),
            );
            if let Some(k) = tick {
                draw_chain(&painter, &view, &k.links, Stroke::new(6.0, accent));
            }
        }
    }
    let shown = t.path.len().min(path_upto(state));
    draw_trail(
        &painter,
        &view,
        t.path.iter().copied(),
        ui.visuals().weak_text_color(),
    );
    draw_trail(&painter, &view, t.path[..shown].iter().copied(), accent);
    if let Some(k) = tick
        && !matches!(t.scene, Scene::Legs { .. } | Scene::Arm { .. })
    {
        let pose = Pose::new(k.pose[0], k.pose[1], k.pose[2]);
        for [angle, range] in &k.rays {
            let a = k.pose[2] + angle;
            let end = [k.pose[0] + range * a.cos(), k.pose[1] + range * a.sin()];
            painter.line_segment(
                [view.to_screen([pose.x, pose.y]), view.to_screen(end)],
                Stroke::new(0.8, theme::ORANGE.gamma_multiply(0.6)),
            );
        }
        let radius = if matches!(t.scene, Scene::Field { .. }) {
            0.06
        } else {
            0.2
        };
        draw_robot(&painter, &view, &pose, radius, theme::robot_color(ui), ink);
    }
}

/// How much of the path the instant has covered.
fn path_upto(state: &Stepping) -> usize {
    let t = state.trace();
    let (Some(first), Some(now)) = (t.ticks.first(), state.tick()) else {
        return 0;
    };
    let last = t.ticks.last().map_or(1.0, |l| l.t);
    let span = (last - first.t).max(1e-9);
    ((now.t - first.t) / span * t.path.len() as f64).ceil() as usize
}

/// The hexapod's feet from above: standing feet filled, lifted ones
/// hollow, the support polygon of those standing and the centre of mass.
fn legs(
    painter: &egui::Painter,
    view: &PlaneView,
    tick: Option<&Tick>,
    com: [f64; 2],
    ink: Color32,
    accent: Color32,
) {
    let Some(k) = tick else { return };
    let standing: Vec<[f64; 2]> = k
        .feet
        .iter()
        .filter(|f| f[2] > 0.5)
        .map(|f| [f[0], f[1]])
        .collect();
    let hull = kinolab_locomotion::convex_hull(&standing);
    if hull.len() >= 3 {
        let pts = hull.iter().map(|p| view.to_screen(*p)).collect();
        painter.add(egui::Shape::convex_polygon(
            pts,
            accent.gamma_multiply(0.2),
            Stroke::new(1.5, accent),
        ));
    }
    for f in &k.feet {
        let at = view.to_screen([f[0], f[1]]);
        if f[2] > 0.5 {
            painter.circle_filled(at, 6.0, ink);
        } else {
            painter.circle_stroke(at, 6.0, Stroke::new(1.5, ink));
        }
    }
    let c = view.to_screen(com);
    painter.line_segment(
        [c - vec2(7.0, 0.0), c + vec2(7.0, 0.0)],
        Stroke::new(2.0, theme::RED),
    );
    painter.line_segment(
        [c - vec2(0.0, 7.0), c + vec2(0.0, 7.0)],
        Stroke::new(2.0, theme::RED),
    );
    painter.text(
        c + vec2(8.0, -8.0),
        egui::Align2::LEFT_BOTTOM,
        "centre of mass",
        egui::FontId::proportional(theme::SMALL_SIZE),
        ink,
    );
}

/// What the function was given, answered and printed at the instant.
fn panel(ui: &mut egui::Ui, state: &Stepping) {
    let Some(k) = state.tick() else {
        ui.label("Your function was not called in this run.");
        return;
    };
    let mono = |t: &str| RichText::new(t).monospace().size(theme::CODE_SIZE - 1.0);
    ui.label(RichText::new("Your function was given").strong());
    // One wrapping line per input: a long value (a ray, a goal) stays
    // within a phone's width.
    for (name, value) in &k.given {
        ui.add(egui::Label::new(mono(&format!("{name} = {value}"))).wrap());
    }
    ui.add_space(4.0);
    ui.label(RichText::new("and answered").strong());
    ui.add(egui::Label::new(mono(&k.returned)).wrap());
    if !k.output.prints.is_empty() {
        ui.add_space(4.0);
        ui.label(RichText::new("It printed").strong());
        for line in &k.output.prints {
            ui.add(egui::Label::new(mono(line)).wrap());
        }
    }
    if let Some(e) = &state.trace().outcome.error
        && e.t.is_some_and(|t| t <= k.t + 1e-9)
    {
        ui.add_space(4.0);
        ui.label(RichText::new(super::editor::error_line(e)).color(theme::error_color(ui)));
    }
}

/// Every `plot("name", value)` series as a curve over the run, with the
/// instant marked.
fn plots(ui: &mut egui::Ui, state: &Stepping) {
    let t = state.trace();
    let mut series: BTreeMap<&str, Vec<[f64; 2]>> = BTreeMap::new();
    for k in &t.ticks {
        for (name, v) in &k.output.plots {
            if v.is_finite() {
                series.entry(name.as_str()).or_default().push([k.t, *v]);
            }
        }
    }
    if series.is_empty() {
        ui.label(
            RichText::new(
                "Call plot(\"name\", value) in your function to draw a value over the run here.",
            )
            .small()
            .weak(),
        );
        return;
    }
    let now = state.tick().map_or(0.0, |k| k.t);
    let names: Vec<&str> = series.keys().copied().collect();
    Plot::new(ui.scope_id().with("code-plots"))
        .height(160.0)
        .x_axis_label("t (s)")
        .allow_scroll(false)
        .show(ui, |plot| {
            let lines = series
                .into_iter()
                .map(|(name, points)| (name, PlotPoints::from(points)))
                .collect();
            series_lines(plot, lines, Some(now));
        });
    series_legend(ui, &names, &[("now", REFERENCE)]);
}

/// An obstacle the field's robot must not pass through, outlined.
fn draw_outline(painter: &egui::Painter, view: &PlaneView, outline: &Outline, ink: Color32) {
    let stroke = Stroke::new(1.5, ink.gamma_multiply(0.7));
    match outline {
        Outline::Disc { centre, radius } => {
            let r = view.length(*radius).max(1.0);
            painter.circle_stroke(view.to_screen(*centre), r, stroke);
        }
        Outline::Polygon { points } => {
            let mut pts: Vec<egui::Pos2> = points.iter().map(|p| view.to_screen(*p)).collect();
            if let Some(first) = pts.first().copied() {
                pts.push(first);
            }
            painter.add(egui::Shape::line(pts, stroke));
        }
        Outline::Wall {
            from,
            to,
            thickness,
        } => {
            let width = view.length(*thickness).max(stroke.width);
            painter.line_segment(
                [view.to_screen(*from), view.to_screen(*to)],
                Stroke::new(width, stroke.color),
            );
        }
    }
}

/// An arm seen from the side: its links from the shoulder (at the origin)
/// through each joint to the tool, joints as rings.
fn draw_chain(painter: &egui::Painter, view: &PlaneView, points: &[[f64; 2]], stroke: Stroke) {
    let mut at = view.to_screen([0.0, 0.0]);
    for p in points {
        let next = view.to_screen(*p);
        painter.line_segment([at, next], stroke);
        painter.circle_stroke(at, stroke.width * 0.8 + 2.0, Stroke::new(1.5, stroke.color));
        at = next;
    }
}
