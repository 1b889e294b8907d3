//! `kinolab field` (potential fields: vectors, minima, descent), `kinolab
//! run` (behaviours in a world) and `kinolab catalogues` (the example
//! worlds and classic fields).

use std::path::PathBuf;

use clap::Subcommand;
use kinolab_api::{behaviours, fields};
use serde_json::Value;

use crate::Failure;
use crate::args::{fixed, point, points};
use crate::ask::{ask, source};

#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// A potential field: its vector at points, its stable equilibria in a box, or a point robot's descent.
    Field {
        /// A field file (`*.field.json`, see the contract), or `catalogue:<id>`.
        field: PathBuf,
        #[command(flatten)]
        query: FieldQuery,
    },
    /// Run behaviours in a world: the trajectory, who had control when, the events and metrics.
    Run {
        /// A behaviour run file (`*.run.json`, see the README).
        run: PathBuf,
    },
    /// The example worlds and the classic potential fields, by id.
    Catalogues,
}

/// What `kinolab field` is asked: exactly one of --at, --minima, --descend.
#[derive(Debug, clap::Args)]
pub(crate) struct FieldQuery {
    /// Points, m: X,Y[;X,Y...]
    #[arg(long, value_name = "X,Y;X,Y;...", allow_hyphen_values = true)]
    at: Option<String>,
    /// Find every stable equilibrium inside --box.
    #[arg(long)]
    minima: bool,
    /// The box to search, m: XMIN,YMIN,XMAX,YMAX
    #[arg(
        long = "box",
        value_name = "XMIN,YMIN,XMAX,YMAX",
        allow_hyphen_values = true
    )]
    area: Option<String>,
    /// Descend from this start, m: X,Y
    #[arg(long, value_name = "X,Y", allow_hyphen_values = true)]
    descend: Option<String>,
    /// Step length H of the descent, m (default 0.01).
    #[arg(long, allow_hyphen_values = true)]
    step: Option<f64>,
    /// Most steps of the descent (default 10000).
    #[arg(long)]
    max_steps: Option<usize>,
}

pub(crate) fn run(command: Command) -> Result<Value, Failure> {
    match command {
        Command::Field { field, query } => field_query(field, query),
        Command::Run { run } => ask(
            &behaviours::RunBehaviours { run: source(&run)? },
            Some(&run),
        ),
        Command::Catalogues => ask(&fields::Catalogues, None),
    }
}

fn field_query(path: PathBuf, q: FieldQuery) -> Result<Value, Failure> {
    let modes = [q.at.is_some(), q.minima, q.descend.is_some()];
    if modes.iter().filter(|m| **m).count() != 1 {
        return Err(Failure(
            "field: give exactly one of --at, --minima or --descend".into(),
        ));
    }
    let field = source(&path)?;
    let input = Some(path.as_path());
    if let Some(at) = q.at {
        let at = points("at", &at)?;
        return ask(&fields::FieldVectors { field, at }, input);
    }
    if let Some(start) = q.descend {
        let start = point("descend", &start)?;
        let descend = fields::FieldDescend {
            field,
            start,
            step: q.step,
            max_steps: q.max_steps,
        };
        return ask(&descend, input);
    }
    let area = q
        .area
        .ok_or_else(|| Failure("--minima needs --box XMIN,YMIN,XMAX,YMAX".into()))?;
    let area = fixed("box", "XMIN,YMIN,XMAX,YMAX", &area)?;
    ask(&fields::FieldMinima { field, area }, input)
}
