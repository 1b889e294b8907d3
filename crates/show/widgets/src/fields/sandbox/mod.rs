//! The field sandbox: paint a potential field with the five primitives,
//! see it as shading, arrows and streamlines, find where it traps a robot,
//! follow it with a point robot (played step by step by the player) and a
//! unicycle, and try the remedies. What the learner changed lives in the
//! settings (the schema's `fields`, `goal`, `start`, `paths`); "Save run"
//! writes the field file `kinolab field --descend` follows.

mod analysis;
mod canvas;
mod exercise;
mod panel;
mod piece;
mod run;

use std::sync::Arc;

use kinolab_fields::catalogue::{Preset, preset};
use kinolab_fields::descend::{Descent, descend};
use kinolab_fields::file::{self, Entry};
use kinolab_fields::{Field, Vec2};
use kinolab_world::Rect;
use serde::{Deserialize, Serialize};

use crate::link::{self, Moment};
use crate::player::Player;
use crate::widget::{LabWidget, Params, SavedRun};
use analysis::{Analysis, STEPS};
use exercise::Task;
use piece::Piece;
use run::Descending;

/// The widget's name in the schema.
const NAME: &str = "field-sandbox";

/// The remedies whose paths can be drawn, as the schema's `paths` names
/// them, in the order of [`analysis::REMEDIES`] and then the wavefront.
const PATHS: [&str; 5] = [
    "noise",
    "avoid-past",
    "templates",
    "wall-following",
    "wavefront",
];

/// What the lesson sets and a link carries: the schema's parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    preset: String,
    streamlines: bool,
    shading: bool,
    unicycle: bool,
    remedies: bool,
    editable: bool,
    task: Option<TaskName>,
    at: Option<[f64; 2]>,
    clearance: f64,
    /// The primitives on a line, when they are not the preset's.
    fields: Option<String>,
    goal: Option<[f64; 2]>,
    start: Option<[f64; 2]>,
    paths: Option<String>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum TaskName {
    VectorAt,
    Escape,
    StandOff,
}

/// The links of the first format: the design as the sandbox kept it.
#[derive(Deserialize)]
struct Legacy {
    preset: String,
    pieces: Vec<Piece>,
    goal: Option<[f64; 2]>,
    start: [f64; 2],
    streamlines: bool,
    shading: bool,
    unicycle: bool,
    remedies: [bool; 5],
    editable: bool,
}

/// What the learner edits, read from the settings: the pieces, the goal,
/// the start and which remedies' paths are drawn.
#[derive(Debug, Clone, PartialEq)]
struct Design {
    pieces: Vec<Piece>,
    goal: Option<[f64; 2]>,
    start: [f64; 2],
    drawn: [bool; 5],
}

/// A preset, its goal and its entries as its file has them.
type PresetFile = (&'static Preset, Option<[f64; 2]>, Vec<Entry>);

/// The preset called `id`, its goal and its entries as its file has them.
fn preset_of(id: &str) -> Result<PresetFile, String> {
    let p = preset(id).ok_or_else(|| format!("no field preset `{id}`"))?;
    let (goal, entries) = file::entries(p.file).map_err(|e| e.to_string())?;
    Ok((p, goal, entries))
}

impl Design {
    fn read(s: &Settings) -> Result<Self, String> {
        let (p, goal, entries) = preset_of(&s.preset)?;
        let entries = match &s.fields {
            Some(text) => file::from_line(text)?,
            None => entries,
        };
        let pieces = entries
            .iter()
            .map(|e| Piece::from_entry(e).map_err(|e| e.to_string()))
            .collect::<Result<_, _>>()?;
        let mut drawn = [false; 5];
        for word in s.paths.iter().flat_map(|t| t.split(',')) {
            let k = PATHS
                .iter()
                .position(|p| *p == word.trim())
                .ok_or_else(|| format!("no remedy `{word}`"))?;
            drawn[k] = true;
        }
        Ok(Self {
            pieces,
            goal: s.goal.or(goal),
            start: s.start.unwrap_or(p.start),
            drawn,
        })
    }

    /// Put this design into `s`, leaving out what is the preset's own.
    fn write(&self, s: &mut Settings) {
        let Ok((p, goal, entries)) = preset_of(&s.preset) else {
            return;
        };
        let line = file::line(&self.entries());
        s.fields = (line != file::line(&entries)).then_some(line);
        s.goal = self.goal.filter(|g| Some(*g) != goal);
        s.start = Some(self.start).filter(|at| *at != p.start);
        let drawn: Vec<&str> = PATHS
            .iter()
            .zip(self.drawn)
            .filter_map(|(name, on)| on.then_some(*name))
            .collect();
        s.paths = (!drawn.is_empty()).then(|| drawn.join(", "));
    }

    fn entries(&self) -> Vec<Entry> {
        self.pieces.iter().map(Piece::entry).collect()
    }
}

struct Sandbox {
    settings: Settings,
    initial: Settings,
    design: Design,
    /// The field file the pieces make, and the field as it reads, or why
    /// they do not make one.
    file: Option<String>,
    field: Option<Field>,
    problem: Option<String>,
    /// Grows with every edit, so results know when they are stale.
    version: u64,
    area: Rect,
    selected: Option<usize>,
    /// How many pieces came with the preset (an exercise may lock them).
    preset_pieces: usize,
    analysis: Analysis,
    task: Option<Task>,
    /// The point robot's descent, played step by step.
    descent: Option<Arc<Descent>>,
    player: Option<Player<Descending>>,
    /// The shading, arrows and streamlines of this version of the field.
    backdrop: canvas::Backdrop,
    /// Whether a handle was held last frame (the backdrop is coarser).
    dragging: bool,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    Ok(Box::new(Sandbox::new(p.settings()?)?))
}

impl Sandbox {
    fn new(settings: Settings) -> Result<Self, String> {
        let design = Design::read(&settings)?;
        let (p, _, entries) = preset_of(&settings.preset)?;
        let task = exercise::from_settings(&settings, &design)?;
        let mut sandbox = Sandbox {
            initial: settings.clone(),
            settings,
            design,
            file: None,
            field: None,
            problem: None,
            version: 0,
            area: Rect::from(p.area),
            selected: None,
            preset_pieces: entries.len(),
            analysis: Analysis::default(),
            task,
            descent: None,
            player: None,
            backdrop: canvas::Backdrop::default(),
            dragging: false,
        };
        sandbox.changed();
        Ok(sandbox)
    }

    /// Rebuild the field from the pieces after any edit, and the descent.
    fn changed(&mut self) {
        self.version += 1;
        self.design.write(&mut self.settings);
        let text = file::write(
            &self.settings.preset,
            self.design.goal,
            &self.design.entries(),
        );
        match Field::from_json(&text) {
            Ok(field) => {
                self.field = Some(field);
                self.file = Some(text);
                self.problem = None;
            }
            Err(e) => {
                self.field = None;
                self.file = None;
                self.problem = Some(e.to_string());
            }
        }
        if let Some(t) = &mut self.task {
            t.feedback = None;
        }
        self.restart();
    }

    /// The point robot's descent from the start, at its start.
    fn restart(&mut self) {
        self.design.write(&mut self.settings);
        let playing = self.player.as_ref().is_some_and(|p| p.playing);
        let speed = self.player.as_ref().map(|p| p.speed);
        let [x, y] = self.design.start;
        self.descent = self
            .field
            .as_ref()
            .and_then(|f| descend(f, Vec2::new(x, y), STEPS).ok())
            .map(Arc::new);
        self.player = self.descent.clone().map(|d| {
            let mut player = Player::new(Descending::new(d));
            player.playing = playing;
            if let Some(speed) = speed {
                player.speed = speed;
            }
            player
        });
    }

    /// Switch to another preset, keeping the view switches.
    fn load(&mut self, p: &Preset) {
        let settings = Settings {
            preset: p.id.to_owned(),
            fields: None,
            goal: None,
            start: None,
            paths: None,
            ..self.settings.clone()
        };
        let Ok(design) = Design::read(&settings) else {
            return;
        };
        self.settings = settings;
        self.design = design;
        self.area = Rect::from(p.area);
        self.selected = None;
        self.preset_pieces = self.design.pieces.len();
        self.changed();
    }

    /// Whether piece `i` was added by the learner (after the preset's own).
    fn is_added(&self, i: usize) -> bool {
        i >= self.preset_pieces
    }

    /// In `vector-at` the pointer readout would give the answer away.
    fn hides_readout(&self) -> bool {
        self.task.as_ref().is_some_and(Task::hides_readout)
    }
}

impl LabWidget for Sandbox {
    fn describe(&self) -> Option<String> {
        Some(self.description())
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        if let Some(player) = &mut self.player {
            player.controls(ui);
        }
        let wide = ui.available_width() >= 760.0;
        let canvas_width = if wide {
            ui.available_width() * 0.62
        } else {
            ui.available_width()
        };
        let (held, view) = if wide {
            ui.horizontal_top(|ui| {
                let drawn = self.canvas(ui, canvas_width);
                ui.vertical(|ui| self.panel(ui));
                drawn
            })
            .inner
        } else {
            let drawn = self.canvas(ui, canvas_width);
            self.panel(ui);
            drawn
        };
        self.timeline(ui);
        self.exports(ui, view);
        if let Some(field) = &self.field {
            self.analysis.update(
                field,
                self.version,
                self.design.start,
                &self.area,
                held,
                self.settings.unicycle,
                self.settings.remedies,
            );
        }
        let mapping = self.analysis.basins.as_ref().is_some_and(|m| !m.done());
        if held || mapping {
            crate::widget::animate(ui);
        }
    }

    fn state(&self) -> Option<String> {
        let moment = self.player.as_ref().map(Player::moment).unwrap_or_default();
        link::write(NAME, &self.settings, &self.initial, &moment)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let (settings, moment) = match link::read::<Settings, ()>(NAME, state) {
            Ok(read) => read,
            Err(why) => match link::decode::<Legacy>(state) {
                Some(old) => (old.settings(&self.initial)?, Moment::default()),
                None => return Err(why),
            },
        };
        // The old format's values pass through the schema's ranges too.
        link::check(NAME, &settings)?;
        let mut again = Sandbox::new(settings)?;
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
        use kinolab_common::display::tidy_report;
        let text = self.file.clone()?;
        let d = self.descent.clone()?;
        // A tick is a step: the robot is at the cursor's point.
        let k = self.player.as_ref()?.cursor();
        let mut shows = vec![(
            "/path".to_owned(),
            tidy_report(&d.path.get(..=k)?.to_vec()).ok()?,
        )];
        if k + 1 == d.path.len() {
            shows.push(("/outcome".into(), tidy_report(&d.outcome).ok()?));
            shows.push(("/end".into(), tidy_report(&d.end).ok()?));
        }
        Some(SavedRun {
            file: run::FILE.into(),
            text,
            args: run::args(self.design.start),
            shows,
        })
    }
}

impl Legacy {
    /// The old design as settings (not yet checked against the schema).
    fn settings(self, initial: &Settings) -> Result<Settings, String> {
        let mut s = Settings {
            preset: self.preset,
            streamlines: self.streamlines,
            shading: self.shading,
            unicycle: self.unicycle,
            editable: self.editable,
            fields: None,
            goal: None,
            start: None,
            paths: None,
            ..initial.clone()
        };
        preset_of(&s.preset)?;
        let design = Design {
            pieces: self.pieces,
            goal: self.goal,
            start: self.start,
            drawn: self.remedies,
        };
        design.write(&mut s);
        Ok(s)
    }
}

#[cfg(test)]
mod tests;
