//! Classic fields, each a lesson in how fields fail, shipped as field files.

use crate::{Field, FieldError};

/// A preset: its id, a title, what it shows, a good start, and its file.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Preset {
    pub id: &'static str,
    pub title: &'static str,
    pub shows: &'static str,
    pub start: [f64; 2],
    /// The area worth looking at: [x_min, y_min, x_max, y_max].
    pub area: [f64; 4],
    pub file: &'static str,
}

pub const PRESETS: [Preset; 7] = [
    Preset {
        id: "goal-behind-a-rock",
        title: "Goal behind a rock",
        shows: "all five primitives at once: the contract's example",
        start: [0.3, 0.2],
        area: [-0.5, -1.5, 5.5, 2.0],
        file: include_str!("../presets/goal-behind-a-rock.field.json"),
    },
    Preset {
        id: "rock-on-the-axis",
        title: "A rock on the axis",
        shows: "a saddle, not a trap: only a start exactly on the axis stalls",
        start: [0.0, 0.0],
        area: [-0.5, -2.0, 5.0, 2.0],
        file: include_str!("../presets/rock-on-the-axis.field.json"),
    },
    Preset {
        id: "u-shaped-wall",
        title: "A U-shaped wall",
        shows: "a true trap: every start in the U's mouth ends inside it",
        start: [0.5, 0.3],
        area: [0.0, -2.5, 7.0, 2.5],
        file: include_str!("../presets/u-shaped-wall.field.json"),
    },
    Preset {
        id: "narrow-gap",
        title: "A gap too narrow",
        shows: "two overlapping pushes: as set the robot still squeezes through; widen their ranges and the gap closes",
        start: [0.5, 0.1],
        area: [0.0, -2.0, 6.0, 2.0],
        file: include_str!("../presets/narrow-gap.field.json"),
    },
    Preset {
        id: "goal-by-an-obstacle",
        title: "A goal next to an obstacle",
        shows: "the repulsion outweighs the pull near the goal: the robot stops short",
        start: [1.0, 0.5],
        area: [0.0, -1.5, 6.0, 1.5],
        file: include_str!("../presets/goal-by-an-obstacle.field.json"),
    },
    Preset {
        id: "wall-ahead",
        title: "A wall ahead",
        shows: "where pull and push balance: range and gain set how close the robot stops",
        start: [0.5, 0.0],
        area: [0.0, -2.0, 6.0, 2.0],
        file: include_str!("../presets/wall-ahead.field.json"),
    },
    Preset {
        id: "corridor",
        title: "Oscillation in a corridor",
        shows: "strong walls on both sides: a unicycle weaves from side to side",
        start: [0.6, 0.3],
        area: [0.0, -1.2, 6.5, 1.2],
        file: include_str!("../presets/corridor.field.json"),
    },
];

/// The preset called `id`.
pub fn preset(id: &str) -> Option<&'static Preset> {
    PRESETS.iter().find(|p| p.id == id)
}

impl Preset {
    pub fn field(&self) -> Result<Field, FieldError> {
        Field::from_json(self.file)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_preset_reads_and_is_named_after_its_id() {
        for p in PRESETS {
            let f = p.field().unwrap_or_else(|e| panic!("{}: {e}", p.id));
            assert_eq!(f.name, p.id);
            assert!(kinolab_world::Rect::new("area", p.area).is_ok());
        }
    }
}
