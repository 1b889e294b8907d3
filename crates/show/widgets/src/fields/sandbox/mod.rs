//! The field sandbox: paint a potential field with the five primitives,
//! see it as shading, arrows and streamlines, find where it traps a robot,
//! follow it with a point robot and a unicycle, and try the remedies.

mod analysis;
mod canvas;
mod exercise;
mod panel;
mod piece;

use kinolab_fields::catalogue::{PRESETS, Preset, preset};
use kinolab_fields::{Field, Vec2};
use kinolab_world::Rect;
use serde::{Deserialize, Serialize};

use crate::link;
use crate::widget::{LabWidget, Params};
use analysis::Analysis;
use exercise::Task;
use piece::Piece;

/// Everything the learner can change, and what a link carries.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Design {
    preset: String,
    pieces: Vec<Piece>,
    goal: Option<[f64; 2]>,
    start: [f64; 2],
    streamlines: bool,
    shading: bool,
    unicycle: bool,
    /// Which remedies' paths are drawn (see [`REMEDIES`]) and the wavefront's.
    remedies: [bool; 5],
    editable: bool,
}

struct Sandbox {
    design: Design,
    initial: Design,
    /// The field the pieces make, or why they do not make one.
    field: Option<Field>,
    problem: Option<String>,
    /// Grows with every edit, so results know when they are stale.
    version: u64,
    area: Rect,
    selected: Option<usize>,
    /// How many pieces came with the preset (an exercise may lock them).
    preset_pieces: usize,
    show_remedies: bool,
    analysis: Analysis,
    task: Option<Task>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    Ok(Box::new(Sandbox::new(p)?))
}

impl Sandbox {
    fn new(p: &Params) -> Result<Self, String> {
        let id = p.choice("preset").unwrap_or("goal-behind-a-rock");
        let found = preset(id).ok_or_else(|| format!("no field preset `{id}`"))?;
        let mut design = Design::from_preset(found)?;
        design.streamlines = p.yes("streamlines");
        design.shading = p.yes("shading");
        design.unicycle = p.yes("unicycle");
        design.editable = p.yes("editable");
        let task = exercise::from_params(p, &design)?;
        let mut sandbox = Sandbox {
            initial: design.clone(),
            design,
            field: None,
            problem: None,
            version: 0,
            area: Rect::from(found.area),
            selected: None,
            preset_pieces: 0,
            show_remedies: p.yes("remedies"),
            analysis: Analysis::default(),
            task,
        };
        sandbox.load_preset_size();
        sandbox.changed();
        Ok(sandbox)
    }
}

impl Design {
    fn from_preset(p: &Preset) -> Result<Self, String> {
        let field = p.field().map_err(|e| e.to_string())?;
        Ok(Self {
            preset: p.id.to_owned(),
            pieces: field.primitives.iter().map(Piece::from_primitive).collect(),
            goal: field.goal.map(|g| [g.x, g.y]),
            start: p.start,
            streamlines: true,
            shading: true,
            unicycle: false,
            remedies: [false; 5],
            editable: true,
        })
    }
}

impl Sandbox {
    /// Rebuild the field from the pieces after any edit.
    fn changed(&mut self) {
        self.version += 1;
        let primitives: Result<Vec<_>, _> = self
            .design
            .pieces
            .iter()
            .enumerate()
            .map(|(i, p)| p.primitive().map_err(|e| format!("field {}: {e}", i + 1)))
            .collect();
        match primitives {
            Ok(primitives) => {
                let goal = self.design.goal.map(|g| Vec2::new(g[0], g[1]));
                self.field = Some(Field::new(self.design.preset.clone(), goal, primitives));
                self.problem = None;
            }
            Err(e) => self.problem = Some(e),
        }
        if let Some(t) = &mut self.task {
            t.feedback = None;
        }
    }

    /// Switch to another preset, keeping the view switches.
    fn load(&mut self, p: &Preset) {
        if let Ok(mut d) = Design::from_preset(p) {
            d.streamlines = self.design.streamlines;
            d.shading = self.design.shading;
            d.unicycle = self.design.unicycle;
            d.editable = self.design.editable;
            self.design = d;
            self.area = Rect::from(p.area);
            self.selected = None;
            self.load_preset_size();
            self.changed();
        }
    }

    fn load_preset_size(&mut self) {
        self.preset_pieces = self.design.pieces.len();
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
    fn ui(&mut self, ui: &mut egui::Ui) {
        let wide = ui.available_width() >= 760.0;
        let canvas_width = if wide {
            ui.available_width() * 0.62
        } else {
            ui.available_width()
        };
        let held = if wide {
            ui.horizontal_top(|ui| {
                let held = self.canvas(ui, canvas_width);
                ui.vertical(|ui| self.panel(ui));
                held
            })
            .inner
        } else {
            let held = self.canvas(ui, canvas_width);
            self.panel(ui);
            held
        };
        if let Some(field) = &self.field {
            let remedies = self.show_remedies;
            self.analysis.update(
                field,
                self.version,
                self.design.start,
                &self.area,
                held,
                self.design.unicycle,
                remedies,
            );
        }
        let mapping = self.analysis.basins.as_ref().is_some_and(|m| !m.done());
        if held || mapping {
            crate::widget::animate(ui);
        }
    }

    fn state(&self) -> Option<String> {
        link::changed(&self.design, &self.initial)
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let Some(design) = link::decode::<Design>(state) else {
            return Err("it is not a state of the field sandbox".into());
        };
        if let Some(p) = PRESETS.iter().find(|p| p.id == design.preset) {
            self.area = Rect::from(p.area);
            self.preset_pieces = p.field().map(|f| f.primitives.len()).unwrap_or(0);
        }
        self.design = design;
        self.changed();
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::analysis::REMEDIES;
    use super::*;
    use crate::registry::spec;

    fn sandbox(params: &[(&str, &str)]) -> Sandbox {
        let p = kinolab_schema::validate(&spec("field-sandbox", params)).unwrap();
        let mut s = Sandbox::new(&p).unwrap();
        s.show_remedies = true;
        s
    }

    #[test]
    fn the_analysis_finds_the_u_trap_and_the_remedies_run() {
        let mut s = sandbox(&[("preset", "u-shaped-wall")]);
        let field = s.field.clone().unwrap();
        s.analysis.update(
            &field,
            s.version,
            s.design.start,
            &s.area,
            false,
            true,
            true,
        );
        let traps: Vec<_> = s
            .analysis
            .minima(&field)
            .into_iter()
            .filter(|m| !m.goal)
            .collect();
        assert_eq!(traps.len(), 1);
        assert!((traps[0].x - 3.75).abs() < 1e-6);
        assert_eq!(s.analysis.remedies.len(), REMEDIES.len() + 1);
        assert!(s.analysis.trail.is_some());
    }

    #[test]
    fn a_link_restores_the_design() {
        let mut s = sandbox(&[("preset", "rock-on-the-axis")]);
        s.design
            .pieces
            .push(Piece::new(piece::Kind::Tangential, [2.0, 0.0]));
        s.changed();
        let link = s.state().unwrap();
        let mut t = sandbox(&[("preset", "rock-on-the-axis")]);
        let _ = t.restore(&link);
        assert_eq!(t.design, s.design);
        assert_eq!(t.preset_pieces, 2);
        let _ = t.restore("zzz");
        assert_eq!(t.design, s.design, "a damaged link changes nothing");
    }
}
