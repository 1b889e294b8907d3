//! What a lesson sets and a link carries: the schema's parameters, typed;
//! the set-up they make; and the links of the first format.

use kinolab_architectures::exercise::office;
use kinolab_architectures::placing::Placed;
use kinolab_architectures::surprise::OFFICE;
use kinolab_architectures::{Architecture, ArenaSetup, Surprise};
use kinolab_world::{Vec2, World};
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

/// The schema's parameters.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(super) struct Settings {
    pub(super) world: WorldId,
    pub(super) surprise: Scripted,
    /// Simulated planning time per expanded cell, ms.
    pub(super) planning_cost: f64,
    pub(super) task: Option<Task>,
    /// Whose beliefs are drawn and whose run is saved.
    pub(super) focus: Architecture,
    /// The pick-an-architecture task's choice per mission.
    pub(super) picks: Picks,
}

/// The worlds the arena offers (each has a start and a goal).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub(super) enum WorldId {
    Office,
    TwoRooms,
    UTrap,
    Crossing,
}

impl WorldId {
    pub(super) const ALL: [WorldId; 4] = [
        WorldId::Office,
        WorldId::TwoRooms,
        WorldId::UTrap,
        WorldId::Crossing,
    ];

    /// The world's id in the core's catalogue.
    pub(super) fn id(self) -> &'static str {
        match self {
            WorldId::Office => "office",
            WorldId::TwoRooms => "two-rooms",
            WorldId::UTrap => "u-trap",
            WorldId::Crossing => "crossing",
        }
    }
}

/// The surprise scripted into the set-up.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub(super) enum Scripted {
    None,
    Door,
    Person,
    WrongMap,
    Noise,
    MovedGoal,
    Glass,
}

impl Scripted {
    pub(super) const ALL: [Scripted; 7] = [
        Scripted::None,
        Scripted::Door,
        Scripted::Person,
        Scripted::WrongMap,
        Scripted::Noise,
        Scripted::MovedGoal,
        Scripted::Glass,
    ];

    /// Its id, as a lesson and the office's examples write it.
    pub(super) fn id(self) -> &'static str {
        match self {
            Scripted::None => "none",
            Scripted::Door => "door",
            Scripted::Person => "person",
            Scripted::WrongMap => "wrong-map",
            Scripted::Noise => "noise",
            Scripted::MovedGoal => "moved-goal",
            Scripted::Glass => "glass",
        }
    }
}

/// The graded tasks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub(super) enum Task {
    SurviveThePerson,
    PickArchitecture,
}

/// One architecture per mission, written `reactive, hybrid, hierarchical`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(try_from = "String", into = "String")]
pub(super) struct Picks(pub(super) [Architecture; 3]);

impl TryFrom<String> for Picks {
    type Error = String;

    fn try_from(text: String) -> Result<Self, String> {
        let picks = text
            .split(',')
            .map(|t| Architecture::parse("picks", t.trim()).map_err(|e| e.to_string()))
            .collect::<Result<Vec<_>, _>>()?;
        picks
            .try_into()
            .map(Picks)
            .map_err(|_| "`picks` needs three architectures, one per mission".to_owned())
    }
}

impl From<Picks> for String {
    fn from(p: Picks) -> String {
        p.0.map(Architecture::name).join(", ")
    }
}

/// When a scripted surprise happens outside the office (as in the
/// office's own examples): the door closes at 6 s, the person walks from
/// the start, the goal moves at 8 s.
const DOOR_AT: f64 = 6.0;
const GOAL_MOVES_AT: f64 = 8.0;

impl Settings {
    /// The surprise in the set-up: the person-task always has the person.
    pub(super) fn scripted(&self) -> Scripted {
        if self.task == Some(Task::SurviveThePerson) {
            Scripted::Person
        } else {
            self.surprise
        }
    }

    /// The robot in focus, as an index into [`Architecture::ALL`].
    pub(super) fn focus_index(&self) -> usize {
        Architecture::ALL
            .iter()
            .position(|a| *a == self.focus)
            .unwrap_or(0)
    }

    /// The set-up the settings make.
    pub(super) fn setup(&self) -> Result<ArenaSetup, String> {
        let mut setup = if self.world == WorldId::Office {
            office(None).map_err(|e| e.to_string())?
        } else {
            let world =
                kinolab_world::catalogue::world(self.world.id()).map_err(|e| e.to_string())?;
            ArenaSetup::new(world)
        };
        setup
            .surprises
            .extend(self.scripted_surprise(&setup.world)?);
        setup.planning_cost = self.planning_cost / 1e3;
        Ok(setup)
    }

    /// The scripted surprise in `world`: the office has its own examples
    /// (which the lessons describe); elsewhere the door, the person and
    /// the moved goal are placed from the world's geometry, seen from the
    /// start.
    fn scripted_surprise(&self, world: &World) -> Result<Option<Surprise>, String> {
        let kind = self.scripted();
        if kind == Scripted::None {
            return Ok(None);
        }
        if self.world == WorldId::Office {
            return office_surprise(kind.id()).map(Some);
        }
        let start = Vec2::new(world.start.x, world.start.y);
        let placed = |p: Placed, t: f64| p.place(world, start, t).map_err(|e| e.to_string());
        let spec = match kind {
            Scripted::Noise => "noise:0.15",
            Scripted::WrongMap => "wrong-map:0",
            Scripted::Door => return placed(Placed::Door, DOOR_AT).map(Some),
            Scripted::Person => return placed(Placed::Person, 0.0).map(Some),
            Scripted::MovedGoal => return placed(Placed::MovedGoal, GOAL_MOVES_AT).map(Some),
            Scripted::Glass => {
                return Err(
                    "the glass wall belongs to the office: choose the office world for it".into(),
                );
            }
            Scripted::None => return Ok(None),
        };
        Surprise::parse("surprise", spec)
            .map(Some)
            .map_err(|e| e.to_string())
    }
}

/// The office's own example of the surprise `id`.
pub(super) fn office_surprise(id: &str) -> Result<Surprise, String> {
    let (_, spec) = OFFICE
        .iter()
        .find(|(name, _)| *name == id)
        .ok_or_else(|| format!("the office has no surprise `{id}`"))?;
    Surprise::parse("surprise", spec).map_err(|e| e.to_string())
}

/// The links of the first format: the widget's own struct.
#[derive(Deserialize)]
pub(super) struct Legacy {
    world: String,
    surprise: String,
    planning_cost_ms: f64,
    picks: [u8; 3],
}

/// A word as one of the kebab-case choices `T`.
fn named<T: DeserializeOwned>(word: &str) -> Result<T, String> {
    serde_json::from_value(serde_json::Value::String(word.to_owned()))
        .map_err(|_| format!("`{word}` is not a choice this widget has"))
}

impl Legacy {
    /// The old link's settings over the lesson's (`lesson`), not yet
    /// checked against the schema's ranges.
    pub(super) fn settings(self, lesson: &Settings) -> Result<Settings, String> {
        let pick = |k: u8| {
            Architecture::ALL
                .get(usize::from(k))
                .copied()
                .ok_or_else(|| format!("pick {k} is not an architecture"))
        };
        let [a, b, c] = self.picks;
        Ok(Settings {
            world: named(&self.world)?,
            surprise: named(&self.surprise)?,
            planning_cost: self.planning_cost_ms,
            picks: Picks([pick(a)?, pick(b)?, pick(c)?]),
            ..lesson.clone()
        })
    }
}
