//! Sensing routes: which functions each sensor feeds, and what the wiring
//! amounts to.
//!
//! A sensor wired only to behaviours takes a **local** route (each
//! behaviour turns the reading into its own percept); one wired only to the
//! world model takes a **global** route (fused with the others into one
//! model); one wired to both takes a **hybrid** route. No sensor feeding a
//! model is the reactive paradigm; sensors feeding only the model is the
//! hierarchical one; both is hybrid.

use serde::Serialize;

use crate::paradigm::Architecture;

pub const SENSORS: [&str; 6] = [
    "range rays",
    "sonar",
    "bumpers",
    "light sensors",
    "goal bearing",
    "odometry",
];

/// The functions a sensor can feed: four behaviours and the world model.
pub const FUNCTIONS: [&str; 5] = [
    "avoid",
    "go to goal",
    "seek light",
    "follow wall",
    "world model",
];

/// The index of the world model among [`FUNCTIONS`].
pub const MODEL: usize = 4;

/// Which sensor feeds which function: `feeds[sensor][function]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, serde::Deserialize)]
pub struct Wiring {
    pub feeds: [[bool; 5]; 6],
}

/// The route a sensor's data takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Route {
    Unused,
    Local,
    Global,
    Hybrid,
}

impl Route {
    pub fn name(self) -> &'static str {
        match self {
            Route::Unused => "unused",
            Route::Local => "local",
            Route::Global => "global",
            Route::Hybrid => "hybrid",
        }
    }
}

/// Each sensor's route and the paradigm of the whole wiring.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RouteReport {
    pub routes: Vec<Route>,
    /// `None` when nothing is wired.
    pub paradigm: Option<Architecture>,
}

impl Wiring {
    /// The route of sensor `s`.
    pub fn route(&self, s: usize) -> Route {
        let Some(row) = self.feeds.get(s) else {
            return Route::Unused;
        };
        let behaviours = row[..MODEL].iter().any(|f| *f);
        match (behaviours, row[MODEL]) {
            (false, false) => Route::Unused,
            (true, false) => Route::Local,
            (false, true) => Route::Global,
            (true, true) => Route::Hybrid,
        }
    }

    pub fn report(&self) -> RouteReport {
        let routes: Vec<Route> = (0..SENSORS.len()).map(|s| self.route(s)).collect();
        let local = routes
            .iter()
            .any(|r| matches!(r, Route::Local | Route::Hybrid));
        let global = routes
            .iter()
            .any(|r| matches!(r, Route::Global | Route::Hybrid));
        let paradigm = match (local, global) {
            (false, false) => None,
            (true, false) => Some(Architecture::Reactive),
            (false, true) => Some(Architecture::Hierarchical),
            (true, true) => Some(Architecture::Hybrid),
        };
        RouteReport { routes, paradigm }
    }

    /// A typical wiring for each paradigm.
    pub fn preset(kind: Architecture) -> Self {
        // Behaviours: rays, sonar and bumpers to avoid; rays to follow
        // wall; light to seek light; goal bearing and odometry to go to goal.
        let reactive: [[bool; 5]; 6] = [
            [true, false, false, true, false],
            [true, false, false, false, false],
            [true, false, false, false, false],
            [false, false, true, false, false],
            [false, true, false, false, false],
            [false, true, false, false, false],
        ];
        let mut feeds = [[false; 5]; 6];
        for (s, row) in feeds.iter_mut().enumerate() {
            match kind {
                Architecture::Reactive => *row = reactive[s],
                Architecture::Hierarchical => row[MODEL] = true,
                Architecture::Hybrid => {
                    *row = reactive[s];
                    // The cartographer fuses what maps the world.
                    row[MODEL] = matches!(s, 0 | 1 | 5);
                }
            }
        }
        Self { feeds }
    }
}
