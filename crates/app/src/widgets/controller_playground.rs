//! The controller playground: the polar go-to-pose controller on a
//! differential drive. Drag start and goal, set gains, see the path, the
//! robot, and ρ, α, β, v, ω over time; many starts at once; open loop
//! against closed loop under the same slip; the stability region.

use std::sync::{Arc, Mutex};

use egui::{Color32, RichText, Sense, Stroke, vec2};
use egui_plot::{Legend, Line, Plot, PlotPoints, Points, Polygon, VLine};
use kinolab_control::batch::{batch, circle_starts, preview};
use kinolab_control::exercise::{Task, Verdict};
use kinolab_control::{
    Direction, Driver, Gains, Limits, Noise, Plan, Pose, Run, Segment, Trajectory, wrap,
};
use kinolab_lessons::WidgetSpec;

use super::chassis_view::View;
use super::controller_field as field;
use super::controller_params as params;
use super::{LabWidget, known_params, number_param, shown};
use crate::theme;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Tab {
    Run,
    Many,
    OpenVsClosed,
    Gains,
}

const TABS: [(Tab, &str, &str); 4] = [
    (Tab::Run, "run", "One run"),
    (Tab::Many, "many", "Many starts"),
    (Tab::OpenVsClosed, "open-vs-closed", "Open vs closed loop"),
    (Tab::Gains, "gains", "Gain region"),
];

/// Everything a learner can change; a change invalidates the cached runs.
#[derive(Debug, Clone, PartialEq)]
struct Settings {
    start: Pose,
    goal: Pose,
    gains: [f64; 3],
    direction: Direction,
    slip: f64,
    push: f64,
    seed: u64,
    /// Hz; 0 = continuous.
    control_rate: f64,
    /// rad/s; 0 = unlimited.
    max_wheel_speed: f64,
    plan: String,
    many_count: usize,
    many_heading_deg: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Grab {
    Start,
    StartHeading,
    Goal,
    GoalHeading,
}

const ALL_GRABS: [Grab; 4] = [
    Grab::StartHeading,
    Grab::Start,
    Grab::GoalHeading,
    Grab::Goal,
];

/// What the learner is asked to do, and how it went.
struct Exercise {
    task: Task,
    marks: Vec<bool>,
    verdict: Option<Verdict>,
}

/// Where a requested screen capture lands when it arrives.
type CaptureSlot = Arc<Mutex<Option<Arc<egui::ColorImage>>>>;

/// The open-vs-closed comparison: the plan, then open and closed runs.
type Comparison = (Plan, Trajectory, Trajectory);

struct Playground {
    tab: Tab,
    set: Settings,
    initial: Settings,
    initial_tab: Tab,
    computed: Option<Settings>,
    run: Option<Result<Trajectory, String>>,
    many: Option<Result<Vec<Trajectory>, String>>,
    compare: Option<Result<Comparison, String>>,
    /// Playback time, s, and whether it advances.
    cursor: f64,
    playing: bool,
    grab: Option<Grab>,
    /// The view frozen while dragging, so the floor does not slide away.
    frozen: Option<View>,
    exercise: Option<Exercise>,
    /// A requested capture of the plots, and the area to crop.
    capture: Option<(egui::Rect, CaptureSlot)>,
    status: Option<String>,
}

pub(super) fn create(spec: &WidgetSpec) -> Result<Box<dyn LabWidget>, String> {
    known_params(
        spec,
        &[
            "view",
            "start",
            "goal",
            "gains",
            "direction",
            "slip",
            "push",
            "seed",
            "control-rate",
            "max-wheel-speed",
            "plan",
            "task",
            "time-limit",
            "forward-only",
            "sets",
        ],
    )?;
    let tab = match spec.param("view") {
        None => Tab::Run,
        Some(v) => TABS
            .iter()
            .find(|(_, key, _)| *key == v)
            .map(|(t, _, _)| *t)
            .ok_or_else(|| {
                format!("Parameter `view` must be run, many, open-vs-closed or gains, found `{v}`.")
            })?,
    };
    let start = spec
        .param("start")
        .map_or(Ok(Pose::new(-1.0, 0.5, 0.0)), |t| params::pose("start", t))?;
    let goal = spec
        .param("goal")
        .map_or(Ok(Pose::default()), |t| params::pose("goal", t))?;
    let gains = spec
        .param("gains")
        .map_or(Ok(kinolab_control::TEXTBOOK_GAINS), |t| {
            params::gains("gains", t)
        })?;
    let direction = spec
        .param("direction")
        .map_or(Ok(Direction::Auto), params::direction)?;
    let plan = spec
        .param("plan")
        .unwrap_or("line 1; arc 0.5 90; line 0.5")
        .to_string();
    params::plan(&plan).map_err(|e| format!("Parameter `plan`: {e}"))?;
    let seed = number_param(spec, "seed", 1.0, 0.0..=1e9)?.round() as u64;
    let set = Settings {
        start,
        goal,
        gains: [gains.k_rho, gains.k_alpha, gains.k_beta],
        direction,
        slip: number_param(spec, "slip", 0.0, 0.0..=0.5)?,
        push: number_param(spec, "push", 0.0, 0.0..=0.2)?,
        seed,
        control_rate: number_param(spec, "control-rate", 0.0, 0.0..=1000.0)?,
        max_wheel_speed: number_param(spec, "max-wheel-speed", 0.0, 0.0..=100.0)?,
        plan,
        many_count: 24,
        many_heading_deg: 0.0,
    };
    let exercise = match spec.param("task") {
        None => None,
        Some("reach-within") => Some(Task::ReachWithin {
            start,
            goal,
            time_limit: number_param(spec, "time-limit", 3.0, 0.5..=30.0)?,
            forward_only: match spec.param("forward-only") {
                None | Some("no") => false,
                Some("yes") => true,
                Some(other) => {
                    return Err(format!(
                        "Parameter `forward-only` must be yes or no, found `{other}`."
                    ));
                }
            },
        }),
        Some("spot-unstable") => Some(Task::SpotUnstable {
            sets: params::gain_sets(
                spec.param("sets")
                    .unwrap_or("3, 8, -1.5; 3, 2, -1.5; 3, 8, 1.5; 2, 6, -1"),
            )?,
        }),
        Some(other) => {
            return Err(format!(
                "Parameter `task` must be reach-within or spot-unstable, found `{other}`."
            ));
        }
    }
    .map(|task| Exercise {
        marks: match &task {
            Task::SpotUnstable { sets } => vec![false; sets.len()],
            Task::ReachWithin { .. } => Vec::new(),
        },
        task,
        verdict: None,
    });
    Ok(Box::new(Playground {
        tab,
        initial: set.clone(),
        initial_tab: tab,
        set,
        computed: None,
        run: None,
        many: None,
        compare: None,
        cursor: 0.0,
        playing: true,
        grab: None,
        frozen: None,
        exercise,
        capture: None,
        status: None,
    }))
}

/// A labelled slider with a fixed number of decimals (and steps to match).
fn slider(
    ui: &mut egui::Ui,
    value: &mut f64,
    range: std::ops::RangeInclusive<f64>,
    text: &str,
    decimals: usize,
) {
    ui.add(
        egui::Slider::new(value, range)
            .text(text)
            .step_by(10f64.powi(-(decimals as i32)))
            .fixed_decimals(decimals),
    );
}

fn snap(x: f64, step: f64) -> f64 {
    (x / step).round() * step
}

/// One row of the CSV export.
const CSV_HEADER: &str = "run,t,x,y,theta_deg,v,omega,rho,alpha_deg,beta_deg,wheel_speed";

fn csv_rows(out: &mut String, name: &str, t: &Trajectory) {
    use std::fmt::Write as _;
    for s in &t.samples {
        let _ = writeln!(
            out,
            "{name},{:.4},{:.6},{:.6},{:.4},{:.6},{:.6},{:.6},{:.4},{:.4},{:.4}",
            s.t,
            s.pose.x,
            s.pose.y,
            wrap(s.pose.theta).to_degrees(),
            s.v,
            s.omega,
            s.polar.rho,
            s.polar.alpha.to_degrees(),
            s.polar.beta.to_degrees(),
            s.wheel_speed
        );
    }
}

impl Settings {
    fn gains(&self) -> Result<Gains, String> {
        Gains::new(self.gains[0], self.gains[1], self.gains[2]).map_err(|e| e.to_string())
    }

    fn noise(&self) -> Option<Noise> {
        (self.slip > 0.0 || self.push > 0.0).then_some(Noise {
            seed: self.seed,
            slip: self.slip,
            push_speed: self.push,
            // A push of 0.1 m/s comes with up to 0.2 rad/s of twist.
            push_turn: 2.0 * self.push,
        })
    }

    /// The polar controller from `start` to `goal` with every setting applied.
    fn polar_run(&self, start: Pose, goal: Pose) -> Result<Run, String> {
        let gains = self.gains()?;
        let mut run = Run::polar(start, goal, gains).map_err(|e| e.to_string())?;
        run.driver = Driver::Polar {
            gains,
            direction: self.direction,
        };
        run.output_every = 10;
        run.noise = self.noise();
        run.control_rate = (self.control_rate > 0.0).then_some(self.control_rate);
        run.max_wheel_speed = (self.max_wheel_speed > 0.0).then_some(self.max_wheel_speed);
        Ok(run)
    }

    fn plan(&self) -> Result<Plan, String> {
        let segments: Vec<Segment> = params::plan(&self.plan)?;
        Plan::new(self.start, &segments, Limits::default()).map_err(|e| e.to_string())
    }

    fn compare(&self) -> Result<Comparison, String> {
        let plan = self.plan()?;
        let duration = (plan.duration() + 1.0).max(10.0);
        let mut open = Run::open_loop(plan.clone()).map_err(|e| e.to_string())?;
        open.duration = duration;
        open.output_every = 10;
        open.noise = self.noise();
        let mut closed = self.polar_run(self.start, plan.end())?;
        closed.duration = duration;
        let open = open.simulate().map_err(|e| e.to_string())?;
        let closed = closed.simulate().map_err(|e| e.to_string())?;
        Ok((plan, open, closed))
    }

    fn many(&self) -> Result<Vec<Trajectory>, String> {
        let run = preview(&self.polar_run(self.goal, self.goal)?);
        let starts = circle_starts(
            &self.goal,
            1.0,
            self.many_count,
            self.many_heading_deg.to_radians(),
        )
        .map_err(|e| e.to_string())?;
        batch(&run, &starts).map_err(|e| e.to_string())
    }

    /// Link state: numbers joined by `,`, then `!` and the plan with `_` for spaces.
    fn encode(&self, tab: Tab) -> String {
        let tab = TABS
            .iter()
            .find(|(t, _, _)| *t == tab)
            .map_or("run", |(_, k, _)| *k);
        let n = |x: f64| format!("{}", (x * 1000.0).round() / 1000.0);
        let fields = [
            tab.to_string(),
            n(self.start.x),
            n(self.start.y),
            n(wrap(self.start.theta).to_degrees()),
            n(self.goal.x),
            n(self.goal.y),
            n(wrap(self.goal.theta).to_degrees()),
            n(self.gains[0]),
            n(self.gains[1]),
            n(self.gains[2]),
            params::direction_name(self.direction).to_string(),
            n(self.slip),
            n(self.push),
            self.seed.to_string(),
            n(self.control_rate),
            n(self.max_wheel_speed),
        ];
        format!("{}!{}", fields.join(","), self.plan.replace(' ', "_"))
    }

    fn decode(text: &str) -> Option<(Settings, Tab)> {
        let (numbers, plan) = text.split_once('!')?;
        let f: Vec<&str> = numbers.split(',').collect();
        if f.len() != 16 {
            return None;
        }
        let tab = TABS.iter().find(|(_, k, _)| *k == f[0])?.0;
        let x = |i: usize| f[i].parse::<f64>().ok().filter(|v| v.is_finite());
        let plan = plan.replace('_', " ");
        params::plan(&plan).ok()?;
        Some((
            Settings {
                start: Pose::new(x(1)?, x(2)?, x(3)?.to_radians()),
                goal: Pose::new(x(4)?, x(5)?, x(6)?.to_radians()),
                gains: [x(7)?, x(8)?, x(9)?],
                direction: params::direction(f[10]).ok()?,
                slip: x(11)?.clamp(0.0, 0.5),
                push: x(12)?.clamp(0.0, 0.2),
                seed: f[13].parse().ok()?,
                control_rate: x(14)?.clamp(0.0, 1000.0),
                max_wheel_speed: x(15)?.clamp(0.0, 100.0),
                plan,
                many_count: 24,
                many_heading_deg: 0.0,
            },
            tab,
        ))
    }
}

impl Playground {
    /// Recompute what the visible tab shows, once per change.
    fn refresh(&mut self) {
        if self.computed.as_ref() != Some(&self.set) {
            self.computed = Some(self.set.clone());
            self.run = None;
            self.many = None;
            self.compare = None;
        }
        match self.tab {
            Tab::Run => {
                if self.run.is_none() {
                    let run = self
                        .set
                        .polar_run(self.set.start, self.set.goal)
                        .and_then(|r| r.simulate().map_err(|e| e.to_string()));
                    self.run = Some(run);
                }
            }
            Tab::Many => {
                if self.many.is_none() {
                    self.many = Some(self.set.many());
                }
            }
            Tab::OpenVsClosed => {
                if self.compare.is_none() {
                    self.compare = Some(self.set.compare());
                }
            }
            Tab::Gains => {}
        }
    }

    fn stability_line(&self, ui: &mut egui::Ui) {
        match self.set.gains() {
            Ok(g) => {
                let s = g.stability();
                let color = if s.strongly_stable {
                    theme::good_color(ui)
                } else if s.locally_stable {
                    theme::accent(ui)
                } else {
                    theme::warn_color(ui)
                };
                ui.label(RichText::new(s.explanation).color(color));
            }
            Err(e) => {
                ui.label(RichText::new(e).color(theme::warn_color(ui)));
            }
        }
    }

    fn gain_sliders(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            let g = &mut self.set.gains;
            slider(ui, &mut g[0], -2.0..=10.0, "k_ρ", 1);
            slider(ui, &mut g[1], -5.0..=20.0, "k_α", 1);
            slider(ui, &mut g[2], -10.0..=5.0, "k_β", 1);
            egui::ComboBox::from_id_salt(ui.scope_id().with("direction"))
                .selected_text(format!(
                    "drive: {}",
                    params::direction_name(self.set.direction)
                ))
                .show_ui(ui, |ui| {
                    for d in [Direction::Auto, Direction::Forward, Direction::Backward] {
                        ui.selectable_value(&mut self.set.direction, d, params::direction_name(d));
                    }
                });
        });
    }

    fn effects(&mut self, ui: &mut egui::Ui) {
        egui::CollapsingHeader::new("Real-world effects: slip, pushes, control rate, wheel limit")
            .id_salt(ui.scope_id().with("effects"))
            .default_open(
                self.set.slip > 0.0
                    || self.set.push > 0.0
                    || self.set.control_rate > 0.0
                    || self.set.max_wheel_speed > 0.0,
            )
            .show(ui, |ui| {
                ui.horizontal_wrapped(|ui| {
                    slider(ui, &mut self.set.slip, 0.0..=0.5, "slip", 2);
                    slider(ui, &mut self.set.push, 0.0..=0.2, "push (m/s)", 2);
                    ui.add(
                        egui::DragValue::new(&mut self.set.seed)
                            .range(0..=999_999)
                            .prefix("seed "),
                    );
                    if ui.button("new seed").clicked() {
                        self.set.seed = self
                            .set
                            .seed
                            .wrapping_mul(6364136223846793005)
                            .wrapping_add(1442695040888963407)
                            % 1_000_000;
                    }
                });
                ui.horizontal_wrapped(|ui| {
                    slider(
                        ui,
                        &mut self.set.control_rate,
                        0.0..=100.0,
                        "controller rate (Hz, 0 = continuous)",
                        0,
                    );
                    slider(
                        ui,
                        &mut self.set.max_wheel_speed,
                        0.0..=60.0,
                        "wheel limit (rad/s, 0 = none)",
                        0,
                    );
                });
            });
    }

    /// The floor fitted around `keep`; `grabs` are the handles a learner
    /// may drag. Returns the view used.
    fn floor(
        &mut self,
        ui: &mut egui::Ui,
        rect_size: egui::Vec2,
        grabs: &[Grab],
        keep: &[Pose],
    ) -> (egui::Response, egui::Painter, View) {
        let (response, painter) = ui.allocate_painter(rect_size, Sense::click_and_drag());
        let rect = response.rect;
        let painter = painter.with_clip_rect(rect);
        painter.rect_filled(rect, 6.0, ui.visuals().extreme_bg_color);
        let view = self.frozen.unwrap_or_else(|| {
            let (min, max) = field::bounds(keep, 0.7);
            field::fit(rect, min, max)
        });
        // Dragging: grab the nearest handle within reach.
        if response.drag_started()
            && let Some(at) = response.interact_pointer_pos()
        {
            let (start, goal) = (self.set.start, self.set.goal);
            self.grab = grabs
                .iter()
                .map(|g| {
                    let p = match g {
                        Grab::Start => [start.x, start.y],
                        Grab::StartHeading => field::handle(&start),
                        Grab::Goal => [goal.x, goal.y],
                        Grab::GoalHeading => field::handle(&goal),
                    };
                    (*g, view.world(p).distance(at))
                })
                .filter(|(_, d)| *d < 14.0)
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .map(|(g, _)| g);
            if self.grab.is_some() {
                self.frozen = Some(view);
            }
        }
        if response.dragged()
            && let (Some(grab), Some(at)) = (self.grab, response.interact_pointer_pos())
        {
            let [x, y] = field::to_world(&view, at);
            let (x, y) = (snap(x, 0.05), snap(y, 0.05));
            let turn = |p: &Pose| snap((y - p.y).atan2(x - p.x).to_degrees(), 5.0).to_radians();
            match grab {
                Grab::Start => (self.set.start.x, self.set.start.y) = (x, y),
                Grab::Goal => (self.set.goal.x, self.set.goal.y) = (x, y),
                Grab::StartHeading => self.set.start.theta = turn(&self.set.start),
                Grab::GoalHeading => self.set.goal.theta = turn(&self.set.goal),
            }
            self.cursor = 0.0;
            self.playing = true;
        }
        if response.drag_stopped() {
            self.grab = None;
            self.frozen = None;
        }
        if response.hovered() {
            ui.ctx().set_cursor_icon(if self.grab.is_some() {
                egui::CursorIcon::Grabbing
            } else {
                egui::CursorIcon::Crosshair
            });
        }
        field::floor(&painter, &view, rect, ui.visuals().text_color());
        (response, painter, view)
    }

    fn draw_goal(&self, ui: &egui::Ui, painter: &egui::Painter, view: &View) {
        field::pose(
            painter,
            view,
            &self.set.goal,
            theme::good_color(ui),
            "goal",
            true,
        );
    }

    fn draw_start(&self, ui: &egui::Ui, painter: &egui::Painter, view: &View) {
        let ink = ui.visuals().text_color().gamma_multiply(0.7);
        field::pose(painter, view, &self.set.start, ink, "start", true);
    }

    fn playback(&mut self, ui: &mut egui::Ui, end: f64) {
        if self.playing {
            self.cursor += f64::from(ui.input(|i| i.stable_dt)).clamp(0.0, 0.1);
            if self.cursor >= end {
                self.cursor = end;
                self.playing = false;
            } else {
                ui.ctx().request_repaint();
            }
        }
        ui.horizontal(|ui| {
            let label = if self.playing { "Pause" } else { "Play" };
            if ui.button(label).clicked() {
                if !self.playing && self.cursor >= end {
                    self.cursor = 0.0;
                }
                self.playing = !self.playing;
            }
            slider(ui, &mut self.cursor, 0.0..=end, "t (s)", 2);
        });
    }

    fn run_tab(&mut self, ui: &mut egui::Ui) {
        let width = ui.available_width().min(900.0);
        let run = self.run.clone();
        let keep = [self.set.start, self.set.goal];
        let (_, painter, view) = self.floor(ui, vec2(width, 320.0), &ALL_GRABS, &keep);
        let accent = theme::accent(ui);
        let ink = ui.visuals().text_color();
        self.draw_goal(ui, &painter, &view);
        self.draw_start(ui, &painter, &view);
        let Some(run) = run else { return };
        let t = match run {
            Ok(t) => t,
            Err(e) => {
                ui.label(RichText::new(e).color(theme::warn_color(ui)));
                return;
            }
        };
        field::path(&painter, &view, &t.samples, Stroke::new(2.0, accent));
        let end = t.samples.last().map_or(0.0, |s| s.t);
        // Ghosts every second, then the robot at the cursor.
        for s in t
            .samples
            .iter()
            .filter(|s| (s.t.fract() < 1e-9 || (1.0 - s.t.fract()) < 1e-9) && s.t > 0.0)
        {
            field::robot(&painter, &view, &s.pose, ink.gamma_multiply(0.15));
        }
        if let Some(s) = field::at_time(&t.samples, self.cursor) {
            field::robot(&painter, &view, &s.pose, accent);
        }
        ui.label(
            RichText::new("Drag the dots to move start and goal, the rings to turn them.").small(),
        );
        self.playback(ui, end);
        ui.label(summary(&t));
        self.plots(ui, &t, width);
        self.exports(ui, &[("closed", &t)]);
    }

    fn plots(&mut self, ui: &mut egui::Ui, t: &Trajectory, width: f32) {
        let series = |f: &dyn Fn(&kinolab_control::Sample) -> f64| -> PlotPoints<'static> {
            t.samples.iter().map(|s| [s.t, f(s)]).collect()
        };
        let link = ui.scope_id().with("plots-link");
        let cursor = self.cursor;
        let top = ui.cursor().min;
        let plot = |id: &str, y_label: &str| {
            Plot::new(ui.scope_id().with(id))
                .width(width)
                .height(170.0)
                .legend(Legend::default())
                .link_axis(link, [true, false])
                .y_axis_label(y_label.to_owned())
                .allow_scroll(false)
        };
        let (top_plot, bottom_plot) = (
            plot("polar-plot", "ρ (m), α β (rad)"),
            plot("command-plot", "v (m/s), ω (rad/s)").x_axis_label("t (s)"),
        );
        top_plot.show(ui, |plot| {
            plot.line(Line::new("ρ", series(&|s| s.polar.rho)).width(2.0));
            plot.line(Line::new("α", series(&|s| s.polar.alpha)).width(2.0));
            plot.line(Line::new("β", series(&|s| s.polar.beta)).width(2.0));
            plot.vline(VLine::new("now", cursor).color(Color32::GRAY));
        });
        bottom_plot.show(ui, |plot| {
            plot.line(Line::new("v", series(&|s| s.v)).width(2.0));
            plot.line(Line::new("ω", series(&|s| s.omega)).width(2.0));
            plot.vline(VLine::new("now", cursor).color(Color32::GRAY));
        });
        let plots = egui::Rect::from_min_max(top, egui::pos2(top.x + width, ui.cursor().min.y));
        if ui.button("Save plots as PNG").clicked() {
            let slot: CaptureSlot = Arc::default();
            let fill = slot.clone();
            let ctx = ui.ctx().clone();
            ui.ctx()
                .send_viewport_cmd(egui::ViewportCommand::Screenshot(
                    egui::ScreenshotCallback::new(move |image| {
                        if let Ok(mut s) = fill.lock() {
                            *s = Some(image);
                        }
                        ctx.request_repaint();
                    }),
                ));
            self.capture = Some((plots, slot));
            self.status = Some("Capturing the plots…".into());
        }
    }

    /// Finish a requested capture once the image has arrived.
    fn finish_capture(&mut self, ui: &egui::Ui) {
        let Some((rect, slot)) = &self.capture else {
            return;
        };
        let image = slot.lock().ok().and_then(|mut s| s.take());
        if let Some(image) = image {
            let ppp = ui.ctx().pixels_per_point();
            self.status = Some(
                match crate::export::png_of(&image, *rect, ppp).and_then(|png| {
                    crate::export::save("kinolab-controller-plots.png", "image/png", &png)
                }) {
                    Ok(m) | Err(m) => m,
                },
            );
            self.capture = None;
        }
    }

    fn exports(&mut self, ui: &mut egui::Ui, runs: &[(&str, &Trajectory)]) {
        let csv = || {
            let mut out = format!("{CSV_HEADER}\n");
            for (name, t) in runs {
                csv_rows(&mut out, name, t);
            }
            out
        };
        ui.horizontal_wrapped(|ui| {
            if ui.button("Copy CSV").clicked() {
                ui.ctx().copy_text(csv());
                self.status = Some("Copied the run as CSV.".into());
            }
            if ui.button("Save CSV").clicked() {
                self.status = Some(
                    match crate::export::save("kinolab-run.csv", "text/csv", csv().as_bytes()) {
                        Ok(m) | Err(m) => m,
                    },
                );
            }
            if let Some(status) = &self.status {
                ui.label(RichText::new(status).small());
            }
        });
    }

    fn many_tab(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            ui.add(
                egui::Slider::new(&mut self.set.many_count, 4..=100).text("starts on a 1 m circle"),
            );
            ui.add(
                egui::Slider::new(&mut self.set.many_heading_deg, -180.0..=180.0)
                    .text("start heading (°)")
                    .step_by(5.0),
            );
        });
        let width = ui.available_width().min(900.0);
        // The 1 m circle of starts and a little room.
        let ring: Vec<Pose> = [[-0.6, -0.6], [0.6, 0.6]]
            .iter()
            .map(|[dx, dy]| Pose::new(self.set.goal.x + dx, self.set.goal.y + dy, 0.0))
            .collect();
        let (_, painter, view) = self.floor(
            ui,
            vec2(width, 380.0),
            &[Grab::Goal, Grab::GoalHeading],
            &ring,
        );
        let accent = theme::accent(ui);
        let warn = theme::warn_color(ui);
        let Some(many) = self.many.clone() else {
            return;
        };
        match many {
            Ok(runs) => {
                for t in &runs {
                    let color = if t.backward { warn } else { accent };
                    field::path(
                        &painter,
                        &view,
                        &t.samples,
                        Stroke::new(1.3, color.gamma_multiply(0.8)),
                    );
                    if let Some(s) = t.samples.first() {
                        field::pose(
                            &painter,
                            &view,
                            &s.pose,
                            color.gamma_multiply(0.6),
                            "",
                            false,
                        );
                    }
                }
                self.draw_goal(ui, &painter, &view);
                let reached = runs.iter().filter(|t| t.reached).count();
                let slowest = runs
                    .iter()
                    .filter_map(|t| t.time_to_goal)
                    .fold(0.0, f64::max);
                ui.label(format!(
                    "{reached} of {} starts reach the goal within {} s (slowest {:.1} s). Blue drove forward, red rear first.",
                    runs.len(),
                    kinolab_control::batch::PREVIEW_DURATION,
                    slowest
                ));
            }
            Err(e) => {
                ui.label(RichText::new(e).color(warn));
            }
        }
    }

    fn compare_tab(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.label("Plan:");
            ui.add(
                egui::TextEdit::singleline(&mut self.set.plan)
                    .desired_width(360.0)
                    .font(egui::TextStyle::Monospace),
            );
        });
        ui.label(RichText::new("Segments: line METRES, arc RADIUS DEGREES, turn DEGREES, separated by semicolons. Raise the slip under real-world effects.").small());
        let Some(compare) = self.compare.clone() else {
            return;
        };
        let (plan, open, closed) = match compare {
            Ok(c) => c,
            Err(e) => {
                ui.label(RichText::new(e).color(theme::warn_color(ui)));
                return;
            }
        };
        let end = plan.end();
        let total = ui.available_width().min(900.0);
        let half = ((total - 12.0) / 2.0).max(150.0);
        let accent = theme::accent(ui);
        let ink = ui.visuals().text_color();
        let nominal: Vec<kinolab_control::Sample> = open
            .samples
            .iter()
            .map(|s| kinolab_control::Sample {
                pose: plan.nominal(s.t),
                ..*s
            })
            .collect();
        let mut extra: Vec<Pose> = nominal.iter().step_by(20).map(|s| s.pose).collect();
        extra.push(self.set.start);
        let t_end = open.samples.last().map_or(0.0, |s| s.t);
        ui.horizontal_top(|ui| {
            for (title, t) in [("Open loop", &open), ("Closed loop", &closed)] {
                ui.vertical(|ui| {
                    ui.label(RichText::new(title).strong());
                    let (_, painter, view) = self.floor(
                        ui,
                        vec2(half, 280.0),
                        &[Grab::Start, Grab::StartHeading],
                        &extra,
                    );
                    field::path(
                        &painter,
                        &view,
                        &nominal,
                        Stroke::new(1.5, ink.gamma_multiply(0.3)),
                    );
                    field::pose(&painter, &view, &end, theme::good_color(ui), "goal", false);
                    self.draw_start(ui, &painter, &view);
                    field::path(&painter, &view, &t.samples, Stroke::new(2.0, accent));
                    if let Some(s) = field::at_time(&t.samples, self.cursor) {
                        field::robot(&painter, &view, &s.pose, accent);
                    }
                    ui.label(RichText::new(format!(
                        "Ends {:.1} cm and {:.1}° from the goal.",
                        shown(t.final_position_error * 100.0, 0.05),
                        shown(t.final_heading_error.to_degrees().abs(), 0.05)
                    )));
                });
            }
        });
        ui.label(RichText::new("Grey: the plan as drawn on paper. Both robots meet the same slip and pushes (same seed).").small());
        self.playback(ui, t_end);
        self.exports(ui, &[("open", &open), ("closed", &closed)]);
    }

    fn gains_tab(&mut self, ui: &mut egui::Ui) {
        let Ok(g) = self.set.gains() else { return };
        let k_rho = g.k_rho;
        let good = theme::good_color(ui);
        let accent = theme::accent(ui);
        let width = ui.available_width().min(900.0);
        let (a_max, b_min) = (20.0, -10.0);
        let mut picked = None;
        Plot::new(ui.scope_id().with("gain-plane"))
            .width(width)
            .height(300.0)
            .legend(Legend::default())
            .x_axis_label("k_α")
            .y_axis_label("k_β")
            .allow_drag(false)
            .allow_zoom(false)
            .allow_scroll(false)
            .allow_boxed_zoom(false)
            .allow_double_click_reset(false)
            .include_x(-2.0)
            .include_x(a_max)
            .include_y(b_min)
            .include_y(4.0)
            .show(ui, |plot| {
                if k_rho > 0.0 {
                    let local = vec![[k_rho, 0.0], [a_max, 0.0], [a_max, b_min], [k_rho, b_min]];
                    plot.polygon(
                        Polygon::new("locally stable", local)
                            .fill_color(good.gamma_multiply(0.3))
                            .stroke(Stroke::new(1.0, good.gamma_multiply(0.5))),
                    );
                    // Strong: k_β > (3/5)(2 k_ρ / π − k_α), inside the local region.
                    let line = |a: f64| 0.6 * (2.0 * k_rho / std::f64::consts::PI - a);
                    let mut strong = Vec::new();
                    let steps = 40;
                    for i in 0..=steps {
                        let a = k_rho + (a_max - k_rho) * f64::from(i) / f64::from(steps);
                        strong.push([a, line(a).clamp(b_min, 0.0)]);
                    }
                    strong.push([a_max, 0.0]);
                    strong.push([k_rho, 0.0]);
                    plot.polygon(
                        Polygon::new("strongly stable", strong)
                            .fill_color(good.gamma_multiply(0.6))
                            .stroke(Stroke::new(1.0, good)),
                    );
                }
                plot.points(
                    Points::new("your gains", vec![[g.k_alpha, g.k_beta]])
                        .radius(6.0)
                        .color(accent),
                );
                let response = plot.response();
                if (response.clicked() || response.dragged())
                    && let Some(p) = plot.pointer_coordinate()
                {
                    picked = Some([snap(p.x, 0.1), snap(p.y, 0.1)]);
                }
            });
        if let Some([a, b]) = picked {
            self.set.gains[1] = a.clamp(-5.0, 20.0);
            self.set.gains[2] = b.clamp(-10.0, 5.0);
        }
        ui.label(
            RichText::new(format!(
                "The plane at k_ρ = {k_rho:.1}. Click or drag in it to pick k_α and k_β."
            ))
            .small(),
        );
        let s = g.stability();
        egui::Grid::new(ui.scope_id().with("conditions"))
            .striped(true)
            .show(ui, |ui| {
                for c in &s.conditions {
                    let mark = if c.holds { "holds" } else { "fails" };
                    let color = if c.holds { good } else { theme::warn_color(ui) };
                    ui.label(RichText::new(mark).color(color));
                    ui.label(RichText::new(c.expression).monospace());
                    ui.label(format!("{:.3}", shown(c.value, 5e-4)));
                    ui.end_row();
                }
            });
        let eig: Vec<String> = s
            .eigenvalues
            .iter()
            .map(|[re, im]| {
                if im.abs() < 1e-9 {
                    format!("{:.3}", shown(*re, 5e-4))
                } else {
                    format!(
                        "{:.3} {} {:.3}i",
                        shown(*re, 5e-4),
                        if *im < 0.0 { "-" } else { "+" },
                        im.abs()
                    )
                }
            })
            .collect();
        ui.label(format!(
            "Eigenvalues of the linearised loop: {}.",
            eig.join(", ")
        ));
    }

    fn exercise_ui(&mut self, ui: &mut egui::Ui) {
        let gains = self.set.gains();
        let Some(ex) = &mut self.exercise else { return };
        let mut load = None;
        egui::Frame::group(ui.style()).show(ui, |ui| {
            ui.label(RichText::new(format!("Exercise: {}", ex.task.describe())).strong());
            if let Task::SpotUnstable { sets } = &ex.task {
                for (i, (g, mark)) in sets.iter().zip(ex.marks.iter_mut()).enumerate() {
                    ui.horizontal(|ui| {
                        ui.checkbox(mark, format!("set {}: (k_ρ, k_α, k_β) = ({}, {}, {})", i + 1, g.k_rho, g.k_alpha, g.k_beta));
                        if ui.small_button("try it").clicked() {
                            load = Some(*g);
                        }
                    });
                }
            }
            if let Task::ReachWithin { start, goal, .. } = &ex.task {
                ui.label(RichText::new(format!(
                    "From ({}, {}) heading {:.0}° to ({}, {}) heading {:.0}°, with the gains on the sliders.",
                    start.x, start.y, start.theta.to_degrees(), goal.x, goal.y, goal.theta.to_degrees()
                )).small());
            }
            if ui.button("Check").clicked() {
                ex.verdict = Some(match (&ex.task, &gains) {
                    (Task::ReachWithin { .. }, Ok(g)) => ex.task.check_gains(*g).unwrap_or_else(|e| Verdict { met: false, message: e.to_string() }),
                    (Task::ReachWithin { .. }, Err(e)) => Verdict { met: false, message: e.clone() },
                    (Task::SpotUnstable { .. }, _) => ex.task.check_marks(&ex.marks).unwrap_or_else(|e| Verdict { met: false, message: e.to_string() }),
                });
            }
            if let Some(v) = &ex.verdict {
                let color = if v.met { theme::good_color(ui) } else { theme::warn_color(ui) };
                ui.label(RichText::new(&v.message).color(color));
            }
        });
        if let Some(g) = load {
            self.set.gains = [g.k_rho, g.k_alpha, g.k_beta];
            if self.tab == Tab::OpenVsClosed {
                self.tab = Tab::Run;
            }
        }
    }
}

fn summary(t: &Trajectory) -> String {
    let reached = match t.time_to_goal {
        Some(s) => format!("Reached (within 1 mm and 0.1°) after {s:.2} s"),
        None => format!(
            "Not reached: ends {:.1} mm and {:.1}° off",
            t.final_position_error * 1000.0,
            t.final_heading_error.to_degrees().abs()
        ),
    };
    format!(
        "{reached}, driving {}. Path {:.2} m; fastest wheel {:.1} rad/s.",
        if t.backward { "rear first" } else { "forward" },
        t.path_length,
        t.peak_wheel_speed
    )
}

impl LabWidget for Playground {
    fn ui(&mut self, ui: &mut egui::Ui) {
        self.finish_capture(ui);
        ui.horizontal_wrapped(|ui| {
            for (tab, _, label) in TABS {
                if ui.selectable_label(self.tab == tab, label).clicked() && self.tab != tab {
                    self.tab = tab;
                    self.cursor = 0.0;
                    self.playing = true;
                }
            }
        });
        self.gain_sliders(ui);
        self.stability_line(ui);
        self.effects(ui);
        let before = self.set.clone();
        self.refresh();
        match self.tab {
            Tab::Run => self.run_tab(ui),
            Tab::Many => self.many_tab(ui),
            Tab::OpenVsClosed => self.compare_tab(ui),
            Tab::Gains => self.gains_tab(ui),
        }
        self.exercise_ui(ui);
        if self.set != before {
            ui.ctx().request_repaint();
        }
    }

    fn state(&self) -> Option<String> {
        (self.set != self.initial || self.tab != self.initial_tab)
            .then(|| self.set.encode(self.tab))
    }

    fn restore(&mut self, state: &str) {
        if let Some((set, tab)) = Settings::decode(state) {
            self.set = set;
            self.tab = tab;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(params: &[(&str, &str)]) -> WidgetSpec {
        super::super::test_spec("controller-playground", params)
    }

    #[test]
    fn settings_round_trip_through_the_link() {
        let mut set = Settings {
            start: Pose::new(-1.25, 0.5, 0.5),
            goal: Pose::new(0.3, -0.2, -1.0),
            gains: [2.5, 9.0, -2.0],
            direction: Direction::Forward,
            slip: 0.1,
            push: 0.05,
            seed: 42,
            control_rate: 20.0,
            max_wheel_speed: 15.0,
            plan: "line 1; arc 0.5 90".into(),
            many_count: 24,
            many_heading_deg: 0.0,
        };
        let text = set.encode(Tab::OpenVsClosed);
        assert!(!text.contains(' '), "{text}");
        let Some((back, tab)) = Settings::decode(&text) else {
            panic!("{text}")
        };
        assert_eq!(tab, Tab::OpenVsClosed);
        // Headings travel in whole thousandths of a degree.
        assert!((back.start.theta - set.start.theta).abs() < 1e-4);
        set.start.theta = back.start.theta;
        set.goal.theta = back.goal.theta;
        assert_eq!(back, set);
        assert!(Settings::decode("run,1,2!line_1").is_none());
        assert!(Settings::decode(&text.replace("line", "jump")).is_none());
    }

    #[test]
    fn csv_has_one_row_per_sample() {
        let Ok(run) = Run::polar(
            Pose::new(-1.0, 0.5, 0.0),
            Pose::default(),
            kinolab_control::TEXTBOOK_GAINS,
        ) else {
            panic!()
        };
        let Ok(t) = run.simulate() else { panic!() };
        let mut out = format!("{CSV_HEADER}\n");
        csv_rows(&mut out, "closed", &t);
        let lines: Vec<&str> = out.lines().collect();
        assert_eq!(lines.len(), 1 + t.samples.len());
        assert!(
            lines[1].starts_with("closed,0.0000,-1.000000,0.500000,0.0000,3.354102,"),
            "{}",
            lines[1]
        );
        assert_eq!(lines[1].split(',').count(), CSV_HEADER.split(',').count());
    }

    #[test]
    fn parameters_are_checked() {
        assert!(
            create(&spec(&[
                ("view", "many"),
                ("gains", "3, 8, -1.5"),
                ("slip", "0.1")
            ]))
            .is_ok()
        );
        assert!(
            create(&spec(&[
                ("task", "reach-within"),
                ("time-limit", "3"),
                ("forward-only", "yes")
            ]))
            .is_ok()
        );
        for (k, v) in [
            ("view", "sideways"),
            ("plan", "jump 2"),
            ("task", "dance"),
            ("slip", "2"),
            ("start", "1,2"),
        ] {
            assert!(create(&spec(&[(k, v)])).is_err(), "{k}: {v}");
        }
    }
}
