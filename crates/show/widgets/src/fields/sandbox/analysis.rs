//! What the sandbox computes about its field, kept until the field or the
//! start changes: equilibria, the unicycle's run, the remedies, and the
//! basin map, which fills in a slice at a time so no frame stalls. (The
//! point robot's descent is the player's run.)

use kinolab_fields::basin::{Basin, Starts, basin};
use kinolab_fields::descend::{Descent, Steps, Trail, Unicycle, follow};
use kinolab_fields::minima::{Equilibrium, Search, equilibria, stable};
use kinolab_fields::remedy::{Remedy, Wavefront, escape};
use kinolab_fields::{Field, Vec2};
use kinolab_world::{Pose, Rect};

/// The remedies the sandbox offers, in the order of its switches.
pub(super) const REMEDIES: [Remedy; 4] = [
    Remedy::Noise {
        magnitude: 0.4,
        seed: 1,
    },
    Remedy::AvoidPast {
        gain: 0.6,
        range: 0.4,
    },
    Remedy::Templates { gain: 1.0 },
    Remedy::WallFollowing,
];

/// A remedy's run, or the wavefront's.
pub(super) struct RemedyRun {
    pub descent: Option<Descent>,
}

/// The basin map in progress.
pub(super) struct BasinMap {
    pub starts: Starts,
    pub cells: Vec<Basin>,
}

impl BasinMap {
    pub fn done(&self) -> bool {
        self.cells.len() >= self.starts.len()
    }
}

/// Everything derived from one version of the field.
#[derive(Default)]
pub(super) struct Analysis {
    /// The field version and start these results are for.
    key: Option<(u64, [f64; 2])>,
    /// Whether the equilibria came from the quick search (while dragging).
    coarse: bool,
    pub equilibria: Vec<Equilibrium>,
    pub trail: Option<Trail>,
    pub remedies: Vec<RemedyRun>,
    remedies_key: Option<(u64, [f64; 2])>,
    pub basins: Option<BasinMap>,
}

/// Descents in the sandbox: 1 cm steps, at most 6000 of them.
pub(super) const STEPS: Steps = Steps {
    step: 0.01,
    max_steps: 6000,
};

/// Basin starts a frame may compute.
const BASIN_SLICE: usize = 24;

impl Analysis {
    /// Bring the results up to date with `field` (version `version`).
    /// While `dragging`, the equilibria search is quick and coarse, and the
    /// remedies wait for the release.
    #[allow(clippy::too_many_arguments)]
    pub fn update(
        &mut self,
        field: &Field,
        version: u64,
        start: [f64; 2],
        area: &Rect,
        dragging: bool,
        unicycle: bool,
        remedies: bool,
    ) {
        let key = Some((version, start));
        if self.key != key || (self.coarse && !dragging) {
            let search = if dragging {
                // A fifth of a millisecond natively: the frame stays
                // within budget while a piece is dragged.
                Search {
                    starts_per_side: 8,
                    max_steps: 20,
                }
            } else {
                Search::default()
            };
            self.equilibria = equilibria(field, area, search).unwrap_or_default();
            self.coarse = dragging;
            if self.key.map(|k| k.0) != Some(version) {
                self.basins = None;
            }
            self.key = key;
            self.trail = None;
        }
        if unicycle && self.trail.is_none() {
            let heading = field.vector(Vec2::new(start[0], start[1]));
            let pose = Pose::new(start[0], start[1], heading.y.atan2(heading.x));
            self.trail = follow(field, pose, &Unicycle::default()).ok();
        }
        if remedies && !dragging && self.remedies_key != key {
            self.remedies = remedy_runs(field, start, area);
            self.remedies_key = key;
        }
        if !dragging && let Some(map) = &mut self.basins {
            let minima = stable(field, &self.equilibria);
            for _ in 0..BASIN_SLICE {
                if map.done() {
                    break;
                }
                let k = map.cells.len();
                map.cells.push(basin(field, &map.starts, k, STEPS, &minima));
            }
        }
    }

    /// Start mapping the basins over `area`.
    pub fn map_basins(&mut self, area: &Rect) {
        let nx = 36;
        let ny = ((nx as f64) * area.height() / area.width())
            .round()
            .clamp(6.0, 36.0) as usize;
        self.basins = Some(BasinMap {
            starts: Starts::new(*area, nx, ny),
            cells: Vec::new(),
        });
    }

    /// The stable equilibria as the core's minima, goal flags included.
    #[cfg(test)]
    pub fn minima(&self, field: &Field) -> Vec<kinolab_fields::minima::Minimum> {
        stable(field, &self.equilibria)
    }
}

fn remedy_runs(field: &Field, start: [f64; 2], area: &Rect) -> Vec<RemedyRun> {
    let s = Vec2::new(start[0], start[1]);
    let mut runs: Vec<RemedyRun> = REMEDIES
        .iter()
        .map(|r| RemedyRun {
            descent: escape(field, s, STEPS, r).ok(),
        })
        .collect();
    let cell = (area.width().max(area.height()) / 60.0).max(0.02);
    runs.push(RemedyRun {
        descent: Wavefront::new(field, area, cell, 0.1)
            .ok()
            .map(|w| w.descend(s)),
    });
    runs
}
