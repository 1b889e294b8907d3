//! `kinolab plan` (the shortest path across a world's grid), `kinolab
//! arena` (one architecture's run through a world with surprises) and
//! `kinolab routes` (where a wiring sends each sensor's data).

use std::path::PathBuf;

use clap::Subcommand;
use kinolab_api::plans;
use kinolab_world::search::Algorithm;
use serde_json::Value;

use crate::Failure;
use crate::args::point;
use crate::ask::{ask, source};

#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// The shortest path across a world's occupancy grid (8-connected, no corner cutting).
    Plan {
        /// A world file (see the contract), or `catalogue:<id>`.
        world: PathBuf,
        /// Start, m: X,Y
        #[arg(long, value_name = "X,Y", allow_hyphen_values = true)]
        from: String,
        /// Goal, m: X,Y
        #[arg(long, value_name = "X,Y", allow_hyphen_values = true)]
        to: String,
        /// Cell side, m.
        #[arg(long, allow_hyphen_values = true)]
        cell: f64,
        /// The search: `astar` (octile heuristic) or `dijkstra`; the same cost, different work (`expanded`).
        #[arg(long, value_enum, default_value = "astar")]
        algorithm: PlanAlgorithm,
    },
    /// Run one architecture (hierarchical, reactive or hybrid) through a world with scripted surprises; print its trajectory, events and scores.
    Arena {
        /// A world file with a start and a goal, or `catalogue:<id>`.
        world: PathBuf,
        /// `hierarchical`, `reactive` or `hybrid`.
        #[arg(long)]
        architecture: String,
        /// A surprise, repeatable: `door:X0,Y0,X1,Y1@T`, `person:X0,Y0,X1,Y1@SPEED`, `wrong-map:I[,J…]`, `noise:SD`, `goal:X,Y@T`, `glass:X0,Y0,X1,Y1`.
        #[arg(long, allow_hyphen_values = true)]
        perturb: Vec<String>,
        /// Simulated planning time per expanded cell, ms.
        #[arg(long, default_value_t = 2.0, allow_hyphen_values = true)]
        planning_cost: f64,
        /// Seconds to run at most.
        #[arg(long, default_value_t = 120.0, allow_hyphen_values = true)]
        duration: f64,
        /// Seed for the sensor noise: a whole number from 0 to 2^64 − 1.
        #[arg(long, default_value_t = 0, allow_hyphen_values = true, value_parser = crate::args::seed)]
        seed: u64,
        /// Keep one sample in this many steps (of 50 ms).
        #[arg(long, default_value_t = 1)]
        every: usize,
        /// A learner's sequencer for the hybrid robot: a script file defining `next(state)`.
        #[arg(long)]
        sequencer: Option<PathBuf>,
    },
    /// Each sensor's route and the paradigm of a wiring of sensors to functions.
    Routes {
        /// Six rows (range rays, sonar, bumpers, light sensors, goal bearing, odometry) of five 0/1 marks (avoid, go to goal, seek light, follow wall, world model), `;` between rows: `10010;00000;…`
        #[arg(value_name = "ROWS")]
        feeds: String,
    },
}

/// The searches `kinolab plan` offers.
#[derive(Debug, Clone, Copy, clap::ValueEnum)]
pub(crate) enum PlanAlgorithm {
    Astar,
    Dijkstra,
}

impl From<PlanAlgorithm> for Algorithm {
    fn from(a: PlanAlgorithm) -> Self {
        match a {
            PlanAlgorithm::Astar => Self::AStar,
            PlanAlgorithm::Dijkstra => Self::Dijkstra,
        }
    }
}

pub(crate) fn run(command: Command) -> Result<Value, Failure> {
    match command {
        Command::Plan {
            world,
            from,
            to,
            cell,
            algorithm,
        } => ask(
            &plans::Plan {
                world: source(&world)?,
                from: point("from", &from)?,
                to: point("to", &to)?,
                cell,
                algorithm: algorithm.into(),
            },
            Some(&world),
        ),
        Command::Arena {
            world,
            architecture,
            perturb,
            planning_cost,
            duration,
            seed,
            every,
            sequencer,
        } => ask(
            &plans::Arena {
                world: source(&world)?,
                request: kinolab_architectures::run::Request {
                    architecture,
                    perturb,
                    planning_cost_ms: planning_cost,
                    duration,
                    seed,
                    every,
                    sequencer: sequencer.as_deref().map(crate::input::read).transpose()?,
                },
            },
            Some(&world),
        ),
        Command::Routes { feeds } => ask(
            &plans::Routes {
                feeds: feeds_of(&feeds)?,
            },
            None,
        ),
    }
}

/// Six rows of five `0`/`1` marks, `;` between rows.
fn feeds_of(text: &str) -> Result<[[bool; 5]; 6], Failure> {
    let bad = || {
        Failure(format!(
            "feeds: `{text}` is not six rows of five 0/1 marks separated by `;` (`10010;00000;10000;00100;01000;00001`)"
        ))
    };
    let mut feeds = [[false; 5]; 6];
    let rows: Vec<&str> = text.split(';').map(str::trim).collect();
    if rows.len() != 6 {
        return Err(bad());
    }
    for (row, marks) in feeds.iter_mut().zip(&rows) {
        let marks: Vec<char> = marks.chars().filter(|c| *c != ',').collect();
        if marks.len() != 5 {
            return Err(bad());
        }
        for (cell, mark) in row.iter_mut().zip(marks) {
            *cell = match mark {
                '1' => true,
                '0' => false,
                _ => return Err(bad()),
            };
        }
    }
    Ok(feeds)
}
