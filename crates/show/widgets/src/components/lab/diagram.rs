//! The component diagram: boxes in columns (servers to the left of their
//! clients), services as squares on a box's right edge, client ports as
//! circles on its left edge, a wire from each port to its service, and
//! tokens moving along the wires. Drag a port onto a service to wire it;
//! click a port to select it. With a world, the robot is drawn beside it.

use egui::{Align2, Color32, FontId, Pos2, Rect, Sense, Stroke, pos2, vec2};
use kinolab_components::view::ComponentView;
use kinolab_components::{Action, Record, Runtime};

use super::Look;
use super::run::LabRun;
use crate::behaviour::world_view::{draw_robot, draw_trail, draw_world};
use crate::draw::{PlaneView, canvas, marks};
use crate::theme;

const LINE: f32 = 15.0;
const HEADER: f32 = 30.0;
const GAP: f32 = 14.0;
/// The widest gap between columns, points.
const WIDE_GAP: f32 = 72.0;
/// A press this close (points) to an anchor grabs it, with a mouse.
const GRAB: f32 = 12.0;
/// The same with a finger, which covers more than it can aim.
const TOUCH_GRAB: f32 = 22.0;

/// Where each box goes: column = longest chain of servers behind it.
pub fn columns(views: &[ComponentView]) -> Vec<usize> {
    let index = |name: &str| views.iter().position(|c| c.name == name);
    let mut col = vec![0usize; views.len()];
    for _ in 0..views.len() {
        let mut changed = false;
        for (i, c) in views.iter().enumerate() {
            let deepest = c
                .ports
                .iter()
                .filter_map(|p| p.connected_to.as_deref())
                .filter_map(|s| index(s.split('.').next().unwrap_or_default()))
                .filter(|&j| j != i)
                .map(|j| col[j] + 1)
                .max()
                .unwrap_or(0)
                .min(views.len());
            if deepest > col[i] {
                col[i] = deepest;
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    col
}

/// Each box's rectangle inside `area` with the boxes in columns `col`,
/// and the height the layout needs.
fn boxes(views: &[ComponentView], col: &[usize], area: Rect) -> (Vec<Rect>, f32) {
    let ncols = col.iter().max().map_or(1, |m| m + 1);
    let n = ncols as f32;
    // Gaps twice the margin where the boxes stay wide enough for their
    // names, so wires between neighbours have room to curve.
    let width_with = |gap: f32| ((area.width() - gap * (n + 1.0)) / n).clamp(70.0, 190.0);
    let width = if width_with(2.0 * GAP) >= 100.0 {
        width_with(2.0 * GAP)
    } else {
        width_with(GAP)
    };
    // Room left over widens the gaps between columns, where the wires run.
    let gap = ((area.width() - width * n) / (n + 1.0)).clamp(GAP, WIDE_GAP);
    let mut heights = vec![GAP; ncols];
    let mut rects = Vec::with_capacity(views.len());
    for (i, c) in views.iter().enumerate() {
        let h = HEADER + LINE * (c.services.len() + c.ports.len()) as f32 + 4.0;
        let x = area.left() + gap + col[i] as f32 * (width + gap);
        let y = area.top() + heights[col[i]];
        rects.push(Rect::from_min_size(pos2(x, y), vec2(width, h)));
        heights[col[i]] += h + GAP;
    }
    (rects, heights.into_iter().fold(0.0, f32::max))
}

fn service_anchor(r: Rect, i: usize) -> Pos2 {
    pos2(r.right(), r.top() + HEADER + LINE * (i as f32 + 0.5))
}

fn port_anchor(r: Rect, services: usize, j: usize) -> Pos2 {
    pos2(
        r.left(),
        r.top() + HEADER + LINE * ((services + j) as f32 + 0.5),
    )
}

/// A point on the S-curve from `a` (a service) to `b` (a port).
fn curve_point(a: Pos2, b: Pos2, t: f32) -> Pos2 {
    // Forwards, the curve stays between its ends (inside the gap between
    // two columns); backwards it swings out and round.
    let d = if b.x > a.x { (b.x - a.x) / 2.0 } else { 40.0 };
    let (p1, p2) = (a + vec2(d, 0.0), b - vec2(d, 0.0));
    let u = 1.0 - t;
    let w = [u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t];
    pos2(
        w[0] * a.x + w[1] * p1.x + w[2] * p2.x + w[3] * b.x,
        w[0] * a.y + w[1] * p1.y + w[2] * p2.y + w[3] * b.y,
    )
}

/// The path of a wire from `a` (a service) to `b` (a port): an S-curve
/// where it clears every box, otherwise a detour along the gaps between
/// columns and the margin above or below the boxes, so that no wire hides
/// under a box or crosses its names. `lane` spreads detours that share a
/// gap a few points apart.
fn wire_path(a: Pos2, b: Pos2, boxes: &[Rect], lane: usize) -> Vec<Pos2> {
    let curve: Vec<Pos2> = (0..=24)
        .map(|k| curve_point(a, b, k as f32 / 24.0))
        .collect();
    let blocked = |p: &Pos2| boxes.iter().any(|r| r.shrink(1.0).contains(*p));
    if !curve.iter().any(blocked) {
        return curve;
    }
    // Lanes spread over the gap beside each column (at least GAP wide),
    // clear of the port and service marks on the boxes' edges.
    let gap = gap_beside(a, boxes).min(gap_beside(b, boxes));
    let off = gap * (0.3 + 0.15 * (lane % 3) as f32);
    let (x1, x2) = (a.x + off, b.x - off);
    let spanned = boxes
        .iter()
        .filter(|r| r.right() >= x1.min(x2) && r.left() <= x1.max(x2));
    // Above or below the boxes the margin is only GAP high: the lanes
    // there stay inside it, on the canvas.
    let v = GAP * (0.3 + 0.15 * (lane % 3) as f32);
    let above = spanned.clone().map(Rect::top).fold(f32::INFINITY, f32::min) - v;
    let below = spanned.map(Rect::bottom).fold(f32::NEG_INFINITY, f32::max) + v;
    let climb = |y: f32| (a.y - y).abs() + (b.y - y).abs();
    let y = if climb(above) <= climb(below) {
        above
    } else {
        below
    };
    vec![a, pos2(x1, a.y), pos2(x1, y), pos2(x2, y), pos2(x2, b.y), b]
}

/// The free width beside the box edge at `p` (a service on a right edge
/// or a port on a left edge), towards the next box, at most [`WIDE_GAP`].
fn gap_beside(p: Pos2, boxes: &[Rect]) -> f32 {
    boxes
        .iter()
        .filter(|r| (r.left() - p.x).abs() > 1.0 && (r.right() - p.x).abs() > 1.0)
        .map(|r| (r.left() - p.x).abs().min((r.right() - p.x).abs()))
        .fold(WIDE_GAP, f32::min)
        .max(GAP)
}

/// The point a fraction `t` of the way along `path`, by length.
fn along(path: &[Pos2], t: f32) -> Pos2 {
    let total: f32 = path.windows(2).map(|w| w[0].distance(w[1])).sum();
    let mut left = t.clamp(0.0, 1.0) * total;
    for w in path.windows(2) {
        let piece = w[0].distance(w[1]);
        if left <= piece && piece > 0.0 {
            return w[0] + (w[1] - w[0]) * (left / piece);
        }
        left -= piece;
    }
    path.last().copied().unwrap_or_default()
}

/// Every anchor by name: (`component.service`, point) and ports likewise.
#[derive(Debug, Clone, Default)]
pub struct Anchors {
    services: Vec<(String, Pos2)>,
    ports: Vec<(String, Pos2)>,
    /// The boxes, which wires go around.
    boxes: Vec<Rect>,
}

impl Anchors {
    /// Every port and service as a point a browser test can aim at.
    fn publish(&self, ctx: &egui::Context) {
        if !crate::probe::enabled(ctx) {
            return;
        }
        for (name, at) in &self.ports {
            crate::probe::publish(ctx, &format!("port {name}"), *at);
        }
        for (name, at) in &self.services {
            crate::probe::publish(ctx, &format!("service {name}"), *at);
        }
    }

    fn new(views: &[ComponentView], rects: &[Rect]) -> Self {
        let mut services = Vec::new();
        let mut ports = Vec::new();
        for (c, r) in views.iter().zip(rects) {
            for (i, s) in c.services.iter().enumerate() {
                services.push((format!("{}.{}", c.name, s.name), service_anchor(*r, i)));
            }
            for (j, p) in c.ports.iter().enumerate() {
                ports.push((
                    format!("{}.{}", c.name, p.name),
                    port_anchor(*r, c.services.len(), j),
                ));
            }
        }
        Self {
            services,
            ports,
            boxes: rects.to_vec(),
        }
    }

    /// The path of the wire from `service` to `port` (see [`wire_path`]).
    fn wire(&self, service: &str, port: &str) -> Option<Vec<Pos2>> {
        let lane = self.ports.iter().position(|(n, _)| n == port)?;
        let (a, b) = (self.service(service)?, self.ports.get(lane)?.1);
        Some(wire_path(a, b, &self.boxes, lane))
    }

    fn near(list: &[(String, Pos2)], at: Pos2, grab: f32) -> Option<&str> {
        list.iter()
            .filter(|(_, p)| p.distance(at) < grab)
            .min_by(|a, b| a.1.distance(at).total_cmp(&b.1.distance(at)))
            .map(|(n, _)| n.as_str())
    }

    pub fn service(&self, name: &str) -> Option<Pos2> {
        self.services
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, p)| *p)
    }

    pub fn port(&self, name: &str) -> Option<Pos2> {
        self.ports.iter().find(|(n, _)| n == name).map(|(_, p)| *p)
    }
}

/// Draw the diagram of `run` (and the world); a wiring the learner made,
/// and where it was all drawn.
pub fn show(ui: &mut egui::Ui, run: &LabRun, look: &mut Look) -> (Option<Action>, Rect) {
    let rt = &run.rt;
    let (views, world) = (rt.view(), rt.world.is_some());
    let width = ui.available_width();
    let side = world && width >= 640.0;
    let diagram_width = if side { width * 0.66 } else { width };
    legend(ui);
    // The layout of the system as it started, so rewiring moves wires,
    // not boxes.
    let col = if look.columns.len() == views.len() {
        look.columns.clone()
    } else {
        columns(&views)
    };
    let (rects, height) = boxes(
        &views,
        &col,
        Rect::from_min_size(Pos2::ZERO, vec2(diagram_width, 10.0)),
    );
    let mut action = None;
    let mut shown = ui
        .horizontal_top(|ui| {
            let (response, painter) = canvas(
                ui,
                vec2(diagram_width, height.max(120.0)),
                Sense::click_and_drag(),
            );
            let rect = response.rect;
            let rects: Vec<Rect> = rects
                .iter()
                .map(|r| r.translate(rect.min.to_vec2()))
                .collect();
            let anchors = Anchors::new(&views, &rects);
            draw_wires(&painter, rt, look.window, &views, &anchors);
            draw_boxes(ui, &painter, look.selected.as_deref(), &views, &rects);
            let lost = theme::error_color(ui);
            draw_tokens(&painter, rt.trace(), rt.now(), &anchors, lost);
            action = interact(ui, &painter, look, &response, &anchors);
            anchors.publish(ui.ctx());
            look.anchors = anchors;
            if side {
                draw_robot_world(
                    ui,
                    run,
                    vec2(width - diagram_width - 8.0, height.max(220.0)),
                );
            }
        })
        .response
        .rect;
    if world && !side {
        shown = shown.union(draw_robot_world(ui, run, vec2(width, 220.0)));
    }
    (action, shown)
}

/// What each colour means.
fn legend(ui: &mut egui::Ui) {
    ui.horizontal_wrapped(|ui| {
        for p in kinolab_components::exercise::CHOICES {
            let (rect, _) = ui.allocate_exact_size(vec2(10.0, 10.0), Sense::hover());
            ui.painter()
                .circle_filled(rect.center(), 4.5, theme::pattern_color(p));
            ui.label(egui::RichText::new(p).size(theme::SMALL_SIZE));
        }
        ui.label(egui::RichText::new("■ service  ● port").size(theme::SMALL_SIZE));
    });
}

fn draw_boxes(
    ui: &egui::Ui,
    painter: &egui::Painter,
    selected: Option<&str>,
    views: &[ComponentView],
    rects: &[Rect],
) {
    let ink = ui.visuals().text_color();
    let faint = ui.visuals().weak_text_color();
    let small = FontId::proportional(theme::SMALL_SIZE);
    for (c, r) in views.iter().zip(rects) {
        let fill = ui.visuals().window_fill;
        let edge = if c.waiting_on.is_some() {
            theme::error_color(ui)
        } else {
            faint
        };
        painter.rect(
            *r,
            5.0,
            fill,
            Stroke::new(1.2, edge),
            egui::StrokeKind::Inside,
        );
        painter.text(
            r.left_top() + vec2(6.0, 3.0),
            Align2::LEFT_TOP,
            &c.name,
            FontId::proportional(theme::LABEL_SIZE),
            ink,
        );
        let mut state = match &c.waiting_on {
            Some(p) => format!("blocked on {p}"),
            None => c.state.name().to_owned(),
        };
        if c.master {
            state += " · master";
        }
        painter.text(
            r.left_top() + vec2(6.0, 17.0),
            Align2::LEFT_TOP,
            state,
            FontId::proportional(theme::SMALL_SIZE),
            faint,
        );
        for (i, s) in c.services.iter().enumerate() {
            let a = service_anchor(*r, i);
            let color = theme::pattern_color(s.pattern.name());
            painter.rect_filled(Rect::from_center_size(a, vec2(9.0, 9.0)), 1.5, color);
            painter.text(
                a - vec2(8.0, 0.0),
                Align2::RIGHT_CENTER,
                &s.name,
                small.clone(),
                ink,
            );
        }
        for (j, p) in c.ports.iter().enumerate() {
            let a = port_anchor(*r, c.services.len(), j);
            let name = format!("{}.{}", c.name, p.name);
            let color = theme::pattern_color(p.pattern.name());
            let selected = selected == Some(name.as_str());
            painter.circle(
                a,
                if selected { 6.0 } else { 4.5 },
                color,
                Stroke::new(if selected { 2.0 } else { 0.0 }, ink),
            );
            let label = if p.blocking {
                p.name.clone()
            } else {
                format!("{} (cancelled)", p.name)
            };
            painter.text(
                a + vec2(8.0, 0.0),
                Align2::LEFT_CENTER,
                label,
                small.clone(),
                if p.connected_to.is_some() { ink } else { faint },
            );
        }
    }
}

/// Wires, brighter where messages passed in the last tenth of the window.
fn draw_wires(
    painter: &egui::Painter,
    rt: &Runtime,
    window: f64,
    views: &[ComponentView],
    anchors: &Anchors,
) {
    let now = rt.now();
    let recent = (window * 0.1).max(0.05);
    let trace = rt.trace();
    let start = trace.partition_point(|r| r.sent < now - recent);
    for c in views {
        for p in &c.ports {
            let Some(service) = &p.connected_to else {
                continue;
            };
            let port = format!("{}.{}", c.name, p.name);
            let Some(points) = anchors.wire(service, &port) else {
                continue;
            };
            let busy = trace[start..].iter().any(|r| r.port == port);
            let color = theme::pattern_color(p.pattern.name());
            let stroke = if busy {
                Stroke::new(3.0, color)
            } else {
                Stroke::new(1.5, color.gamma_multiply(0.55))
            };
            painter.add(egui::Shape::line(points, stroke));
        }
    }
}

/// Messages on their way, as dots moving along their wires; lost ones as
/// a red cross where they vanished.
fn draw_tokens(
    painter: &egui::Painter,
    trace: &[Record],
    now: f64,
    anchors: &Anchors,
    lost: Color32,
) {
    let start = trace.partition_point(|r| r.sent < now - 2.0);
    for r in &trace[start..] {
        if r.sent > now || matches!(r.pattern, "wiring" | "state" | "note") {
            continue;
        }
        let Some(wire) = anchors.wire(&r.service, &r.port) else {
            continue;
        };
        let upstream = matches!(
            r.kind,
            "command" | "request" | "subscribe" | "unsubscribe" | "activate" | "deactivate"
        );
        let color = theme::pattern_color(r.pattern);
        match r.delivered {
            Some(d) if d > now && d > r.sent => {
                let f = ((now - r.sent) / (d - r.sent)) as f32;
                let t = if upstream { 1.0 - f } else { f };
                painter.circle_filled(along(&wire, t), 4.5, color);
            }
            None if r.status == kinolab_components::Status::Lost && now - r.sent < 0.3 => {
                let at = along(&wire, 0.5);
                marks::cross(painter, at, 5.0, Stroke::new(2.0, lost));
            }
            _ => {}
        }
    }
}

/// Select a port by pressing it; wire it by dragging it onto a service.
/// The drag is read from the pointer's own presses and releases, so it
/// starts at the press however fast the pointer then moves (even when the
/// press and the release reach one frame), and a finger wires as a mouse
/// does. A drop away from every service says so.
fn interact(
    ui: &egui::Ui,
    painter: &egui::Painter,
    look: &mut Look,
    response: &egui::Response,
    anchors: &Anchors,
) -> Option<Action> {
    let grab = if ui.input(|i| i.has_touch_screen()) {
        TOUCH_GRAB
    } else {
        GRAB
    };
    let presses: Vec<(Pos2, bool)> = ui.input(|i| {
        i.events
            .iter()
            .filter_map(|e| match e {
                egui::Event::PointerButton {
                    pos,
                    button: egui::PointerButton::Primary,
                    pressed,
                    ..
                } => Some((*pos, *pressed)),
                _ => None,
            })
            .collect()
    });
    let mut action = None;
    for (at, pressed) in presses {
        if pressed && response.rect.contains(at) {
            look.missed = None;
            look.dragging = Anchors::near(&anchors.ports, at, grab).map(str::to_owned);
            look.selected.clone_from(&look.dragging);
        } else if !pressed && let Some(port) = look.dragging.take() {
            action = drop_port(look, anchors, port, at, grab);
        }
    }
    if let (Some(port), Some(at)) = (&look.dragging, ui.input(|i| i.pointer.latest_pos()))
        && let Some(from) = anchors.port(port)
    {
        let ink = ui.visuals().text_color();
        painter.line_segment([from, at], Stroke::new(2.0, ink));
        let target = Anchors::near(&anchors.services, at, grab).and_then(|s| anchors.service(s));
        if let Some(target) = target {
            painter.circle_stroke(target, grab * 0.8, Stroke::new(2.0, theme::good_color(ui)));
        }
    }
    action
}

/// A dragged port let go at `at`: wired to the service there; a press
/// that did not leave the port only selects it; anywhere else, nothing is
/// wired and the lab says where to drop.
fn drop_port(
    look: &mut Look,
    anchors: &Anchors,
    port: String,
    at: Pos2,
    grab: f32,
) -> Option<Action> {
    if let Some(service) = Anchors::near(&anchors.services, at, grab) {
        return Some(Action::Connect {
            port,
            service: service.to_owned(),
        });
    }
    let stayed = anchors.port(&port).is_some_and(|p| p.distance(at) < grab);
    if !stayed {
        look.missed = Some(format!(
            "Nothing was wired: drop {port} on a service, at the right edge of a box."
        ));
    }
    None
}

/// The robot in its world, with its track; where it was drawn.
fn draw_robot_world(ui: &mut egui::Ui, run: &LabRun, size: egui::Vec2) -> Rect {
    let (rect, _) = ui.allocate_exact_size(size, Sense::hover());
    let Some(sim) = run.rt.world.as_ref() else {
        return rect;
    };
    let b = sim.world.bounds;
    let view = PlaneView::fit(rect.shrink(6.0), [b.x_min, b.y_min], [b.x_max, b.y_max]);
    let painter = ui.painter_at(rect);
    draw_world(ui, &painter, &view, &sim.world, sim.time);
    let color = theme::pattern_color("query");
    draw_trail(&painter, &view, run.track.iter().copied(), color);
    let ink = ui.visuals().text_color();
    draw_robot(&painter, &view, &sim.pose, sim.body.radius(), color, ink);
    rect
}

#[cfg(test)]
mod wire_tests {
    use super::*;

    /// Whether the segment from `a` to `b` passes through the inside of `r`.
    fn crosses(r: Rect, a: Pos2, b: Pos2) -> bool {
        (0..=100).any(|k| r.shrink(1.0).contains(a + (b - a) * (k as f32 / 100.0)))
    }

    #[test]
    fn a_wire_between_neighbours_is_a_curve_and_a_long_one_goes_around() {
        // Three columns of boxes; a service on the first, ports on the
        // second and on the third, the middle box in the way of the long one.
        let first = Rect::from_min_size(pos2(14.0, 14.0), vec2(100.0, 60.0));
        let middle = Rect::from_min_size(pos2(128.0, 14.0), vec2(100.0, 90.0));
        let last = Rect::from_min_size(pos2(242.0, 14.0), vec2(100.0, 60.0));
        let boxes = [first, middle, last];
        let service = pos2(first.right(), 60.0);
        let near = wire_path(service, pos2(middle.left(), 70.0), &boxes, 0);
        assert_eq!(near.len(), 25, "the S-curve");
        let far = wire_path(service, pos2(last.right() - 100.0, 50.0), &boxes, 1);
        assert_eq!(far.len(), 6, "the detour: {far:?}");
        for w in far.windows(2) {
            for r in boxes {
                assert!(!crosses(r, w[0], w[1]), "{w:?} crosses {r:?}");
            }
        }
        // A message token runs the whole path, end to end.
        assert_eq!(along(&far, 0.0), service);
        assert_eq!(along(&far, 1.0), pos2(last.left(), 50.0));
        let half = along(&far, 0.5);
        assert!(half.x > service.x && half.x < last.left(), "{half:?}");
    }
}
