//! Braitenberg vehicles: a few vehicles and lights; wire each vehicle
//! (straight or crossed, excitatory or inhibitory, gain and base speed) or
//! pick one of the four classic characters, and watch. Each vehicle is a
//! behaviours run of the core (`kinolab run`), played by the one player;
//! a light dragged or a vehicle rewired while it runs is an event of the
//! run, replayed on scrubbing, carried in the link and written into the
//! run file's script.

use egui::{RichText, Sense, Slider, vec2};
use kinolab_behaviours::braitenberg::{Character, Sign, Wiring};
use kinolab_behaviours::coordinate::Coordinator;
use kinolab_behaviours::library::{Behaviour, Named};
use kinolab_behaviours::run::{Change, Runner, Setup};
use kinolab_common::trajectory::Sample as Motion;
use kinolab_world::{Light, Pose, Sensors, World};
use serde::{Deserialize, Serialize};

use super::world_view::{draw_robot, draw_trail, draw_world};
use crate::draw::{PlaneView, canvas, handle};
use crate::export::{self, Export};
use crate::link::{self, Moment};
use crate::player::{Player, Simulation};
use crate::widget::{LabWidget, Params, SavedRun, range};

/// The widget's name in the schema.
const NAME: &str = "braitenberg";

/// What the lesson sets and a link carries: the vehicles as they start
/// and where the lights are.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    vehicles: String,
    gains: Option<Vec<f64>>,
    bases: Option<Vec<f64>>,
    lights: Vec<[f64; 2]>,
}

/// The links of the first format: each vehicle's wiring and the lights.
#[derive(Deserialize)]
struct Legacy {
    wirings: Vec<Wiring>,
    lights: Vec<[f64; 2]>,
}

/// What a learner does while the vehicles run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case", deny_unknown_fields)]
enum Event {
    /// Light `light` dragged to `at`.
    Light { light: usize, at: [f64; 2] },
    /// Vehicle `vehicle` rewired.
    Rewire { vehicle: usize, wiring: Wiring },
}

/// The room, m, and how close to its walls a light may stand.
const ROOM: [f64; 4] = [0.0, 0.0, 8.0, 6.0];
const MARGIN: f64 = 0.2;
const INTENSITY: f64 = 4.0;
/// Where the vehicles start: spread along the room's left side.
const STARTS: [[f64; 3]; 4] = [
    [1.0, 4.5, -0.3],
    [1.0, 1.5, 0.3],
    [2.0, 5.2, -0.6],
    [2.0, 0.8, 0.6],
];
/// The run: a minute, 20 steps a second, seed 1.
const DURATION: f64 = 60.0;
const DT: f64 = 0.05;
const SEED: u64 = 1;

impl Settings {
    /// Each vehicle's wiring as it starts.
    fn wirings(&self) -> Result<Vec<Wiring>, String> {
        let names: Vec<&str> = self.vehicles.split(',').map(str::trim).collect();
        names
            .iter()
            .enumerate()
            .map(|(i, n)| {
                let c = Character::ALL
                    .into_iter()
                    .find(|c| c.name() == *n)
                    .ok_or_else(|| format!("no character `{n}`"))?;
                let mut w = c.wiring();
                let pick = |list: &Option<Vec<f64>>, own: f64| match list {
                    Some(values) => values.get(i).copied().ok_or("too few numbers"),
                    None => Ok(own),
                };
                w.gain = pick(&self.gains, w.gain)?;
                w.base = pick(&self.bases, w.base)?;
                Ok(w)
            })
            .collect()
    }

    /// These settings with the vehicles starting as `wirings`.
    fn wired(&self, wirings: &[Wiring]) -> Settings {
        let own = |w: &Wiring| w.character().wiring();
        let names: Vec<&str> = wirings.iter().map(|w| w.character().name()).collect();
        let gains = wirings.iter().any(|w| w.gain != own(w).gain);
        let bases = wirings.iter().any(|w| w.base != own(w).base);
        Settings {
            vehicles: names.join(", "),
            gains: gains.then(|| wirings.iter().map(|w| w.gain).collect()),
            bases: bases.then(|| wirings.iter().map(|w| w.base).collect()),
            lights: self.lights.clone(),
        }
    }

    /// Vehicle `i`'s run, with `script` (what was done while it ran),
    /// exactly as its run file reads.
    fn setup(&self, i: usize, wiring: Wiring, script: Vec<Change>) -> Result<Setup, String> {
        let [x, y, theta] = STARTS.get(i).copied().ok_or("at most four vehicles")?;
        let mut world = World::empty("lights", kinolab_world::Rect::from(ROOM));
        world.start = Pose::new(x, y, theta);
        world.lights = self
            .lights
            .iter()
            .map(|l| Light {
                x: l[0],
                y: l[1],
                intensity: INTENSITY,
            })
            .collect();
        let sensors = Sensors {
            lights: Some(Default::default()),
            ..Sensors::default()
        };
        let brain = Named::new(vehicle(i), Behaviour::Braitenberg(wiring));
        let coordinator = Coordinator::Sum {
            gains: Default::default(),
        };
        let mut setup = Setup::new(world, vec![brain], coordinator);
        setup.sensors = sensors;
        setup.duration = DURATION;
        setup.dt = DT;
        setup.seed = SEED;
        setup.stop_at_goal = false;
        setup.script = script;
        setup.check().map_err(|e| e.to_string())?;
        Ok(setup)
    }
}

/// Vehicle `i`'s behaviour, by name.
fn vehicle(i: usize) -> String {
    format!("vehicle-{}", i + 1)
}

/// A light kept inside the room.
fn in_room(at: [f64; 2]) -> [f64; 2] {
    [
        at[0].clamp(ROOM[0] + MARGIN, ROOM[2] - MARGIN),
        at[1].clamp(ROOM[1] + MARGIN, ROOM[3] - MARGIN),
    ]
}

/// The event as a change to the run file of vehicle `i`, at `t`; `None`
/// when it does not concern that vehicle.
fn change(t: f64, event: &Event, i: usize) -> Option<Change> {
    match event {
        Event::Light { light, at } => Some(Change::MoveLight {
            at: t,
            light: *light,
            x: at[0],
            y: at[1],
        }),
        Event::Rewire { vehicle: v, wiring } => (*v == i).then(|| Change::ReplaceBehaviour {
            at: t,
            behaviour: Box::new(Named::new(vehicle(i), Behaviour::Braitenberg(*wiring))),
        }),
    }
}

/// One vehicle's step, as the player keeps it.
#[derive(Debug, Clone)]
struct Moved {
    pose: Pose,
    v: f64,
    omega: f64,
    control: Option<usize>,
    events: Vec<kinolab_world::Event>,
}

/// The vehicles' runs, stepped together.
#[derive(Debug, Clone)]
struct Room {
    runners: Vec<Runner>,
}

impl Simulation for Room {
    type Tick = Vec<Moved>;
    type Event = Event;

    fn step(&mut self) -> Option<Vec<Moved>> {
        if self.runners.iter().all(Runner::done) {
            return None;
        }
        Some(
            self.runners
                .iter_mut()
                .map(|r| {
                    let frame = r.step();
                    Moved {
                        pose: frame.pose,
                        v: frame.driven.vx,
                        omega: frame.driven.omega,
                        control: frame.decision.in_control,
                        events: frame.events,
                    }
                })
                .collect(),
        )
    }

    fn time(&self) -> f64 {
        self.runners.first().map_or(0.0, |r| r.sim.time)
    }

    fn dt(&self) -> f64 {
        DT
    }

    fn spring(&mut self, event: &Event) {
        let t = self.time();
        for (i, r) in self.runners.iter_mut().enumerate() {
            if let Some(c) = change(t, event, i) {
                r.apply(&c);
            }
        }
    }
}

impl Room {
    /// Vehicle `i`'s wiring now.
    fn wiring(&self, i: usize) -> Option<Wiring> {
        match self.runners.get(i)?.behaviours.first()?.behaviour {
            Behaviour::Braitenberg(w) => Some(w),
            _ => None,
        }
    }

    fn lights(&self) -> Vec<[f64; 2]> {
        self.runners.first().map_or_else(Vec::new, |r| {
            r.sim.world.lights.iter().map(|l| [l.x, l.y]).collect()
        })
    }
}

struct Vehicles {
    settings: Settings,
    initial: Settings,
    player: Option<Player<Room>>,
    problem: Option<String>,
    /// Which vehicle's run "Save run" writes.
    saving: usize,
    /// A light being dragged, and where it is so far.
    dragging: Option<(usize, [f64; 2])>,
    /// A slider being dragged: the vehicle and the wiring so far.
    pending: Option<(usize, Wiring)>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    let v = Vehicles::new(settings);
    match &v.problem {
        Some(problem) => Err(problem.clone()),
        None => Ok(Box::new(v)),
    }
}

impl Vehicles {
    fn new(settings: Settings) -> Self {
        let mut v = Vehicles {
            initial: settings.clone(),
            settings,
            player: None,
            problem: None,
            saving: 0,
            dragging: None,
            pending: None,
        };
        v.rebuild();
        v
    }

    /// The run the settings make, paused at its start (playing on if it was).
    fn rebuild(&mut self) {
        let playing = self.player.as_ref().is_some_and(|p| p.playing);
        let speed = self.player.as_ref().map(|p| p.speed);
        let runners = self.settings.wirings().and_then(|wirings| {
            wirings
                .iter()
                .enumerate()
                .map(|(i, w)| {
                    let setup = self.settings.setup(i, *w, Vec::new())?;
                    Runner::new(&setup).map_err(|e| e.to_string())
                })
                .collect::<Result<Vec<_>, String>>()
        });
        match runners {
            Ok(runners) => {
                let mut player = Player::new(Room { runners });
                player.playing = playing;
                if let Some(speed) = speed {
                    player.speed = speed;
                }
                self.player = Some(player);
                self.problem = None;
            }
            Err(e) => {
                self.player = None;
                self.problem = Some(e);
            }
        }
        self.saving = self.saving.min(self.count().saturating_sub(1));
    }

    fn count(&self) -> usize {
        self.settings.vehicles.split(',').count()
    }

    /// Do `event` now: at the start it changes the settings (a new run);
    /// later it is sprung on the run where it is shown.
    fn act(&mut self, event: Event) {
        let Some(player) = &mut self.player else {
            return;
        };
        if player.cursor() > 0 {
            player.spring(event);
            return;
        }
        match event {
            Event::Light { light, at } => {
                if let Some(l) = self.settings.lights.get_mut(light) {
                    *l = at;
                }
            }
            Event::Rewire { vehicle, wiring } => {
                if let Ok(mut wirings) = self.settings.wirings()
                    && let Some(w) = wirings.get_mut(vehicle)
                {
                    *w = wiring;
                    self.settings = self.settings.wired(&wirings);
                }
            }
        }
        self.rebuild();
    }
}

impl Vehicles {
    fn canvas(&mut self, ui: &mut egui::Ui, width: f32) -> egui::Rect {
        let (response, painter) = canvas(ui, vec2(width, width * 0.75), Sense::hover());
        let rect = response.rect;
        let view = PlaneView::fit(rect.shrink(4.0), [ROOM[0], ROOM[1]], [ROOM[2], ROOM[3]]);
        let ink = ui.visuals().text_color();
        let Some(player) = &mut self.player else {
            return rect;
        };
        let room = player.state().clone();
        if let Some(first) = room.runners.first() {
            draw_world(ui, &painter, &view, &first.sim.world, 0.0);
        }
        let shown = player.ticks_shown();
        for (i, r) in room.runners.iter().enumerate() {
            let start = [r.sim.world.start.x, r.sim.world.start.y];
            let trail = std::iter::once(start).chain(
                shown
                    .iter()
                    .filter_map(|t| t.get(i))
                    .map(|m| [m.pose.x, m.pose.y]),
            );
            draw_trail(
                &painter,
                &view,
                trail,
                crate::theme::palette(i).gamma_multiply(0.7),
            );
            draw_robot(
                &painter,
                &view,
                &r.sim.pose,
                r.sim.body.radius(),
                crate::theme::palette(i),
                ink,
            );
        }
        self.light_handles(ui, &view, &room.lights());
        rect
    }

    /// The lights as handles: a drag takes effect where it ends (a
    /// keyboard move at once).
    fn light_handles(&mut self, ui: &mut egui::Ui, view: &PlaneView, lights: &[[f64; 2]]) {
        let base = ui.scope_id().with("lights");
        let mut done = None;
        for (k, l) in lights.iter().enumerate() {
            let shown = match self.dragging {
                Some((d, at)) if d == k => at,
                _ => *l,
            };
            let h = handle(
                ui,
                base.with(k),
                view.to_screen(shown),
                12.0,
                &format!("Light {}", k + 1),
            );
            if let Some(to) = h.dragged_to(view, shown) {
                let to = in_room(to);
                if h.response.dragged() {
                    self.dragging = Some((k, to));
                } else {
                    done = Some((k, to));
                }
            }
            if h.response.drag_stopped()
                && let Some((d, at)) = self.dragging.take()
            {
                done = Some((d, at));
            }
        }
        if let Some((light, at)) = done {
            self.act(Event::Light { light, at });
        }
    }
}

impl Vehicles {
    fn wiring_ui(&mut self, ui: &mut egui::Ui) {
        let Some(player) = &mut self.player else {
            return;
        };
        let room = player.state().clone();
        let mut done = None;
        for i in 0..room.runners.len() {
            let Some(now) = room.wiring(i) else { continue };
            let mut w = match self.pending {
                Some((v, w)) if v == i => w,
                _ => now,
            };
            ui.push_id(i, |ui| {
                if let Some(edit) = wiring_editor(ui, i, &mut w) {
                    match edit {
                        Edit::Dragging => self.pending = Some((i, w)),
                        Edit::Done => {
                            self.pending = None;
                            done = Some((i, w));
                        }
                    }
                }
            });
        }
        if let Some((vehicle, wiring)) = done
            && room.wiring(vehicle) != Some(wiring)
        {
            self.act(Event::Rewire { vehicle, wiring });
        }
    }
}

/// What a learner did to a wiring this frame.
enum Edit {
    /// A slider is still being dragged.
    Dragging,
    Done,
}

/// Vehicle `i`'s wiring: a character's, or crossed/sign, gain and base.
fn wiring_editor(ui: &mut egui::Ui, i: usize, w: &mut Wiring) -> Option<Edit> {
    ui.label(
        RichText::new(format!(
            "Vehicle {} ({} · {})",
            i + 1,
            w.character().vehicle(),
            w.character().name()
        ))
        .color(crate::theme::palette(i))
        .strong(),
    );
    let before = *w;
    ui.horizontal_wrapped(|ui| {
        for c in Character::ALL {
            if ui
                .small_button(c.vehicle())
                .on_hover_text(c.name())
                .clicked()
            {
                *w = c.wiring();
            }
        }
    });
    ui.horizontal(|ui| {
        ui.checkbox(&mut w.crossed, "crossed");
        ui.radio_value(&mut w.sign, Sign::Excitatory, "excitatory");
        ui.radio_value(&mut w.sign, Sign::Inhibitory, "inhibitory");
    });
    let mut sliding = false;
    let mut released = false;
    for (value, param, text) in [
        (&mut w.gain, "gains", "gain w"),
        (&mut w.base, "bases", "base (rad/s)"),
    ] {
        let r = ui.add(Slider::new(value, range(NAME, param)).text(text));
        sliding |= r.dragged();
        released |= r.drag_stopped();
    }
    if sliding && !released {
        return Some(Edit::Dragging);
    }
    (*w != before || released).then_some(Edit::Done)
}

impl Vehicles {
    /// Vehicle `i`'s run file, with what was done to it so far.
    fn run_file(&self, i: usize) -> Result<String, String> {
        let player = self.player.as_ref().ok_or("nothing runs")?;
        let wiring = *self
            .settings
            .wirings()?
            .get(i)
            .ok_or("there is no such vehicle")?;
        let script = player
            .events()
            .iter()
            .filter_map(|(t, e)| change(*t, e, i))
            .collect();
        Ok(self.settings.setup(i, wiring, script)?.to_json())
    }

    fn exports(&mut self, ui: &mut egui::Ui, view: egui::Rect) {
        let count = self.count();
        if count > 1 {
            ui.horizontal_wrapped(|ui| {
                ui.label("Save the run of");
                for i in 0..count {
                    crate::widget::choose(ui, &mut self.saving, i, format!("vehicle {}", i + 1));
                }
            });
        }
        let file = format!("vehicle-{}.run.json", self.saving + 1);
        let command = format!("kinolab run {file}");
        let make = || self.run_file(self.saving);
        export::bar(
            ui,
            ui.scope_id().with("braitenberg-exports"),
            &[
                Export::Png {
                    file: "kinolab-braitenberg.png",
                    rect: view,
                },
                Export::Run {
                    file: &file,
                    command: &command,
                    make: &make,
                },
            ],
        );
    }
}

impl Vehicles {
    /// The instant shown: each vehicle's character, where it is and how
    /// far from the nearest light.
    fn description(&self) -> String {
        use kinolab_common::display::fixed;
        let Some(player) = &self.player else {
            let why = self.problem.as_deref().unwrap_or_default();
            return format!("The vehicles cannot run: {why}");
        };
        let room = player.peek();
        let lights = room.lights();
        let vehicles: Vec<String> = room
            .runners
            .iter()
            .enumerate()
            .map(|(i, r)| {
                let p = r.sim.pose;
                let character = room.wiring(i).map_or("unwired", |w| w.character().name());
                let nearest = lights
                    .iter()
                    .map(|l| (l[0] - p.x).hypot(l[1] - p.y))
                    .fold(f64::INFINITY, f64::min);
                let light = if nearest.is_finite() {
                    format!(", {} m from the nearest light", fixed(nearest, 1))
                } else {
                    String::new()
                };
                format!(
                    "vehicle {} ({character}) at ({}, {}) m{light}",
                    i + 1,
                    fixed(p.x, 1),
                    fixed(p.y, 1)
                )
            })
            .collect();
        format!(
            "{} s into the run, {} light{}: {}.",
            fixed(player.time(), 1),
            lights.len(),
            if lights.len() == 1 { "" } else { "s" },
            vehicles.join("; ")
        )
    }
}

impl LabWidget for Vehicles {
    fn describe(&self) -> Option<String> {
        Some(self.description())
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        if let Some(problem) = &self.problem {
            crate::widget::error_box(ui, "These vehicles cannot run", problem);
            return;
        }
        ui.horizontal_wrapped(|ui| {
            if let Some(player) = &mut self.player {
                player.controls(ui);
            }
            if ui
                .button("Reset")
                .on_hover_text("The lesson's vehicles and lights")
                .clicked()
            {
                self.settings = self.initial.clone();
                self.rebuild();
            }
        });
        let wide = ui.available_width() >= 760.0;
        let view = if wide {
            let w = ui.available_width() * 0.62;
            ui.horizontal_top(|ui| {
                let view = self.canvas(ui, w);
                ui.vertical(|ui| self.wiring_ui(ui));
                view
            })
            .inner
        } else {
            let view = self.canvas(ui, ui.available_width());
            self.wiring_ui(ui);
            view
        };
        if let Some(player) = &mut self.player {
            player.timeline(ui, "Time", (DURATION / DT) as usize, &mut |_, _, _, _| {});
            player.run(ui, 50);
        }
        ui.label(RichText::new("Drag the lights. Straight wiring joins each sensor to its own side's wheel; crossed, to the other side's. What you change at the start makes a new run; later, it happens at that instant of this run.").small());
        self.exports(ui, view);
    }

    fn state(&self) -> Option<String> {
        let moment = self.player.as_ref().map(Player::moment).unwrap_or_default();
        link::write(NAME, &self.settings, &self.initial, &moment)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let (settings, moment) = match link::read::<Settings, Event>(NAME, state) {
            Ok(read) => read,
            Err(why) => match link::decode::<Legacy>(state) {
                Some(old) => {
                    let mut settings = self.initial.wired(&old.wirings);
                    settings.lights = old.lights;
                    (settings, Moment::default())
                }
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema's ranges too.
        link::check(NAME, &settings)?;
        check_events(&settings, &moment.events)?;
        let mut again = Vehicles::new(settings);
        if let Some(problem) = again.problem {
            return Err(problem);
        }
        again.initial = self.initial.clone();
        if let Some(player) = &mut again.player {
            player.replay(&moment.events, moment.instant);
        }
        *self = again;
        Ok(())
    }

    fn seek(&mut self, t: f64) {
        if let Some(player) = &mut self.player {
            player.seek_time(t);
        }
    }

    fn saved_run(&mut self) -> Option<SavedRun> {
        let i = self.saving;
        let text = self.run_file(i).ok()?;
        let wiring = *self.settings.wirings().ok()?.get(i)?;
        let start = self.settings.setup(i, wiring, Vec::new()).ok()?.world.start;
        let file = format!("vehicle-{}.run.json", i + 1);
        Some(SavedRun {
            text,
            args: vec!["run".into(), file.clone()],
            file,
            shows: shows(self.player.as_ref()?, i, start)?,
        })
    }
}

/// What vehicle `i` has done up to the instant shown, as `kinolab run`
/// prints it: its samples (every step, from `start`) and its events.
fn shows(player: &Player<Room>, i: usize, start: Pose) -> Option<Vec<(String, serde_json::Value)>> {
    let mut samples = vec![kinolab_behaviours::run::Sample {
        motion: Motion::new(0.0, [start.x, start.y, start.theta], 0.0, 0.0),
        control: None,
    }];
    let mut events = Vec::new();
    for (k, tick) in player.ticks_shown().iter().enumerate() {
        let m = tick.get(i)?;
        samples.push(kinolab_behaviours::run::Sample {
            motion: Motion::new(
                player.time_at(k + 1),
                [m.pose.x, m.pose.y, m.pose.theta],
                m.v,
                m.omega,
            ),
            control: m.control.map(|_| vehicle(i)),
        });
        events.extend(m.events.iter().cloned());
    }
    Some(vec![
        (
            "/samples".into(),
            kinolab_common::display::tidy_report(&samples).ok()?,
        ),
        (
            "/events".into(),
            kinolab_common::display::tidy_report(&events).ok()?,
        ),
    ])
}

/// Events of a link that this run can take: lights that are there, moved
/// within the room; vehicles that are there, wired within the schema's
/// ranges; times within the run.
fn check_events(settings: &Settings, events: &[(f64, Event)]) -> Result<(), String> {
    let vehicles = settings.vehicles.split(',').count();
    for (t, e) in events {
        let fits = (0.0..=DURATION).contains(t)
            && match e {
                Event::Light { light, at } => *light < settings.lights.len() && in_room(*at) == *at,
                Event::Rewire { vehicle, wiring } => {
                    *vehicle < vehicles
                        && range(NAME, "gains").contains(&wiring.gain)
                        && range(NAME, "bases").contains(&wiring.base)
                }
            };
        if !fits {
            return Err(format!("its event at {t} s does not fit these vehicles"));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::spec;

    fn vehicles(params: &[(&str, &str)]) -> Vehicles {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        Vehicles::new(p.settings().unwrap_or_else(|e| panic!("{e}")))
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        // Two wirings (crossed, sign, gain, base) and two lights.
        let love = (false, 1_u32, 3.0_f64, 6.0_f64);
        let rewired = (true, 0_u32, 2.5_f64, 4.0_f64);
        let lights = vec![(5.0_f64, 3.0_f64), (2.0, 2.0)];
        let old = link::encode(&(vec![love, rewired], lights)).unwrap_or_default();
        let mut w = vehicles(&[]);
        assert_eq!(w.restore(&old), Ok(()));
        assert_eq!(w.settings.vehicles, "love, aggression");
        assert_eq!(w.settings.gains, Some(vec![3.0, 2.5]));
        assert_eq!(w.settings.bases, None);
        assert_eq!(w.settings.lights, vec![[5.0, 3.0], [2.0, 2.0]]);
        // A gain past the schema's range: refused, the lesson's kept.
        let bad = (true, 0_u32, 60.0_f64, 4.0_f64);
        let old = link::encode(&(vec![bad], vec![(5.0_f64, 3.0_f64)])).unwrap_or_default();
        let mut w = vehicles(&[("vehicles", "fear")]);
        assert!(w.restore(&old).is_err());
        assert_eq!(w.settings.vehicles, "fear");
    }

    #[test]
    fn what_is_done_while_it_runs_travels_in_the_link_and_the_run_file() {
        let mut w = vehicles(&[("vehicles", "love, explorer")]);
        w.seek(2.0);
        w.act(Event::Light {
            light: 0,
            at: [3.0, 3.0],
        });
        w.seek(4.0);
        let mut wiring = Character::Fear.wiring();
        wiring.gain = 2.0;
        w.act(Event::Rewire { vehicle: 1, wiring });
        w.seek(6.5);
        let text = w.state().unwrap_or_default();
        let mut again = vehicles(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.settings, w.settings);
        again.saving = 1;
        w.saving = 1;
        let run = w.saved_run();
        assert_eq!(again.saved_run(), run);
        let run = run.unwrap_or_else(|| panic!("no run"));
        assert!(run.text.contains("replace_behaviour"), "{}", run.text);
        assert!(run.text.contains("move_light"), "{}", run.text);
        // The file is exactly the run shown.
        let setup = Setup::from_json(&run.text).unwrap_or_else(|e| panic!("{e}"));
        let report = kinolab_behaviours::run::run(&setup).unwrap_or_else(|e| panic!("{e}"));
        let printed = kinolab_common::display::tidy_report(&report.samples[..131].to_vec())
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(run.shows[0].1, printed);
    }

    #[test]
    fn changes_at_the_start_are_settings() {
        let mut w = vehicles(&[]);
        let mut wiring = Character::Explorer.wiring();
        wiring.base = 2.0;
        w.act(Event::Rewire { vehicle: 0, wiring });
        w.act(Event::Light {
            light: 1,
            at: [7.0, 5.0],
        });
        assert_eq!(w.settings.vehicles, "explorer, fear");
        assert_eq!(w.settings.bases, Some(vec![2.0, 4.0]));
        assert_eq!(w.settings.lights[1], [7.0, 5.0]);
        assert!(w.player.as_ref().is_some_and(|p| p.events().is_empty()));
        // The run file reads back as the same set-up.
        let setup = w.settings.setup(0, wiring, Vec::new());
        let again = setup.as_ref().map(|s| Setup::from_json(&s.to_json()));
        assert_eq!(again.ok().and_then(Result::ok), setup.ok());
    }
}
