//! `kinolab`: the lab's core on the command line.
//!
//! Every call prints exactly one JSON document on stdout. Bad input exits
//! with status 2 and one line on stderr naming the file or option and the
//! field; nothing ever prints a panic or a backtrace.

mod behaviour;
mod components;
mod control;
mod input;
mod legs;
mod mechanism;
mod output;
mod plan;
mod wheels;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use serde_json::{Value, json};

/// The Kinolab robotics lab's core, scriptable. Prints one JSON document per call.
#[derive(Debug, Parser)]
#[command(name = "kinolab", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Count the leg-event sequences of a walker: N = (2k − 1)!
    LegEvents {
        /// Number of legs k (1 to 17 for an exact count).
        legs: u32,
    },
    /// Judge a standing walker's static stability from above.
    Stability {
        /// Centre of mass projected on the ground, metres: X,Y
        #[arg(long, value_name = "X,Y", allow_hyphen_values = true)]
        com: String,
        /// Feet on the ground, metres: X1,Y1;X2,Y2;...
        #[arg(long, value_name = "X,Y;X,Y;...", allow_hyphen_values = true)]
        feet: String,
    },
    /// Rank of C1, the degrees of mobility, steerability and maneuverability, DOF and the ICR of a robot file.
    Analyze {
        /// A robot file (`*.robot.json`), or `catalogue:<id>`.
        robot: PathBuf,
    },
    /// Wheel kinematics: --twist gives each wheel's spin and steering (inverse); --wheels gives the twist (forward).
    Drive {
        /// A robot file (`*.robot.json`), or `catalogue:<id>`.
        robot: PathBuf,
        /// Robot-frame twist, m/s and rad/s: VX,VY,OMEGA
        #[arg(long, value_name = "VX,VY,OMEGA", allow_hyphen_values = true)]
        twist: Option<String>,
        /// One spin per wheel in file order, rad/s; `-` where unknown: S1,S2,...
        #[arg(long, value_name = "S1,S2,...", allow_hyphen_values = true)]
        wheels: Option<String>,
        /// Heading θ (rad) to also report the motion in the inertial frame.
        #[arg(long, allow_hyphen_values = true)]
        theta: Option<f64>,
    },
    /// List the catalogue robots, or print one as a robot file.
    Robots {
        /// A catalogue id such as `tricycle`.
        id: Option<String>,
    },
    /// Simulate a run file: the polar controller (or an open-loop plan) on a differential drive.
    Simulate {
        /// A run file (`*.run.json`, see the contract).
        run: PathBuf,
    },
    /// Simulate a run file from many starts on a circle around its goal.
    Batch {
        /// A run file; its own start is replaced by the circle's.
        run: PathBuf,
        /// Circle radius, m.
        #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
        radius: f64,
        /// Number of starts.
        #[arg(long, default_value_t = 16, allow_hyphen_values = true)]
        count: usize,
        /// Heading of every start, degrees.
        #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
        heading_deg: f64,
        /// Include each run's sampled path.
        #[arg(long)]
        paths: bool,
    },
    /// Stability of polar-controller gains: the conditions, the linearised loop, its eigenvalues.
    Gains {
        /// K_RHO,K_ALPHA,K_BETA
        #[arg(value_name = "K_RHO,K_ALPHA,K_BETA", allow_hyphen_values = true)]
        gains: String,
    },
    /// Forward kinematics of a model file: the 4×4 pose of a frame (default: the tool).
    Fk {
        /// A model file (`*.model.json`), or `catalogue:<id>`.
        model: PathBuf,
        /// Joint values, rad (revolute) or m (prismatic): Q1,...,QN (none for a model without joints)
        #[arg(
            long,
            value_name = "Q1,...,QN",
            allow_hyphen_values = true,
            default_value = ""
        )]
        q: String,
        /// A frame name: a joint's, `base`, `world` or `tool`.
        #[arg(long)]
        frame: Option<String>,
    },
    /// Inverse kinematics of a model file: joint values that put a frame at a target.
    Ik {
        /// A model file (`*.model.json`), or `catalogue:<id>`.
        model: PathBuf,
        /// Target position, m: X,Y,Z
        #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
        position: String,
        /// Target rotation, row-major: R11,...,R33 (position only when omitted)
        #[arg(long, value_name = "R11,...,R33", allow_hyphen_values = true)]
        rotation: Option<String>,
        /// Starting joint values: Q1,...,QN (default: zero, clamped into the limits)
        #[arg(long, value_name = "Q1,...,QN", allow_hyphen_values = true)]
        seed: Option<String>,
        /// The frame to place (default: the tool).
        #[arg(long)]
        frame: Option<String>,
    },
    /// A potential field: its vector at points, its stable equilibria in a box, or a point robot's descent.
    Field {
        /// A field file (`*.field.json`, see the contract), or `catalogue:<id>`.
        field: PathBuf,
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
    },
    /// Run behaviours in a world: the trajectory, who had control when, the events and metrics.
    Run {
        /// A behaviour run file (`*.run.json`, see the README).
        run: PathBuf,
    },
    /// A periodic gait through its cycle: the feet in stance, their positions, the static stability margin.
    Gait {
        /// A gait file (`*.gait.json`, see the contract), or `catalogue:<id>` (`quadruped-crawl`, `hexapod-tripod`, …).
        gait: PathBuf,
        /// Samples over the cycle, at τ = (k + ½)/N.
        #[arg(long, default_value_t = 100, allow_hyphen_values = true)]
        samples: usize,
    },
    /// Phase oscillators, one per leg, coupled towards a gait: where they end and whether they lock.
    Cpg {
        /// A CPG file (`*.cpg.json`, see the contract).
        cpg: PathBuf,
    },
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
        /// Seed for the sensor noise.
        #[arg(long, default_value_t = 0)]
        seed: u64,
        /// Keep one sample in this many steps (of 50 ms).
        #[arg(long, default_value_t = 1)]
        every: usize,
    },
    /// Run a system of components (send, query, push, event and wiring patterns) on a simulated clock; print every message and the final state.
    Components {
        /// A system file (`*.system.json`, see the README), or `example:<id>` (`out-of-order`, `newest-vs-timed`, `events`, `robot`).
        system: PathBuf,
        /// Seconds of simulated time to run (the file's `until` when left out).
        #[arg(long, allow_hyphen_values = true)]
        until: Option<f64>,
    },
    /// Check lesson files (Markdown with front-matter, widgets, quizzes).
    Lessons {
        /// A lessons folder to check; the embedded lessons when omitted.
        dir: Option<PathBuf>,
    },
}

/// The searches `kinolab plan` offers.
#[derive(Debug, Clone, Copy, clap::ValueEnum)]
enum PlanAlgorithm {
    Astar,
    Dijkstra,
}

impl From<PlanAlgorithm> for kinolab_world::search::Algorithm {
    fn from(a: PlanAlgorithm) -> Self {
        match a {
            PlanAlgorithm::Astar => Self::AStar,
            PlanAlgorithm::Dijkstra => Self::Dijkstra,
        }
    }
}

/// A failure reported as one line on stderr.
struct Failure(String);

/// A report as the JSON to print: finite numbers only (see
/// [`kinolab_common::display::tidy_report`]); `context` names the file or
/// option the report was computed from.
fn report(context: &str, report: &impl serde::Serialize) -> Result<Value, Failure> {
    kinolab_common::display::tidy_report(report).map_err(|e| Failure(format!("{context}: {e}")))
}

/// Comma-separated finite numbers; an empty text is no numbers.
fn numbers(option: &str, text: &str) -> Result<Vec<f64>, Failure> {
    if text.trim().is_empty() {
        return Ok(Vec::new());
    }
    text.split(',')
        .map(|part| match part.trim().parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            _ => Err(Failure(format!(
                "--{option}: `{}` is not a finite number",
                part.trim()
            ))),
        })
        .collect()
}

/// One finite number.
fn number(option: &str, text: &str) -> Result<f64, Failure> {
    match numbers(option, text)?.as_slice() {
        [x] => Ok(*x),
        _ => Err(Failure(format!(
            "--{option}: `{}` is not one finite number",
            text.trim()
        ))),
    }
}

fn point(option: &str, text: &str) -> Result<[f64; 2], Failure> {
    match numbers(option, text)?.as_slice() {
        [x, y] => Ok([*x, *y]),
        other => Err(Failure(format!(
            "--{option}: expected two numbers X,Y, got {}",
            other.len()
        ))),
    }
}

fn run(command: Command) -> Result<Value, Failure> {
    match command {
        Command::LegEvents { legs } => {
            let r = kinolab_locomotion::report::leg_events(legs)
                .map_err(|e| Failure(format!("legs: {}", e.message)))?;
            report("legs", &r)
        }
        Command::Stability { com, feet } => {
            let com = point("com", &com)?;
            let feet = feet
                .split(';')
                .filter(|f| !f.trim().is_empty())
                .map(|f| point("feet", f))
                .collect::<Result<Vec<_>, _>>()?;
            let r = kinolab_locomotion::report::stability(com, &feet)
                .map_err(|e| Failure(format!("--{}: {}", e.field, e.message)))?;
            report("stability", &r)
        }
        Command::Analyze { robot } => wheels::analyze(&robot),
        Command::Drive {
            robot,
            twist,
            wheels: spins,
            theta,
        } => wheels::drive(&robot, twist.as_deref(), spins.as_deref(), theta),
        Command::Robots { id } => wheels::robots(id.as_deref()),
        Command::Simulate { run } => control::simulate(&run),
        Command::Batch {
            run,
            radius,
            count,
            heading_deg,
            paths,
        } => control::batch_run(&run, radius, count, heading_deg, paths),
        Command::Gains { gains } => control::gains(&gains),
        Command::Fk { model, q, frame } => mechanism::fk(&model, &q, frame.as_deref()),
        Command::Ik {
            model,
            position,
            rotation,
            seed,
            frame,
        } => mechanism::ik(
            &model,
            &position,
            rotation.as_deref(),
            seed.as_deref(),
            frame.as_deref(),
        ),
        Command::Field {
            field,
            at,
            minima,
            area,
            descend,
            step,
            max_steps,
        } => behaviour::field(
            &field,
            &behaviour::FieldQuery {
                at: at.as_deref(),
                minima,
                area: area.as_deref(),
                descend: descend.as_deref(),
                step,
                max_steps,
            },
        ),
        Command::Run { run } => behaviour::run(&run),
        Command::Gait { gait, samples } => legs::gait(&gait, samples),
        Command::Cpg { cpg } => legs::cpg(&cpg),
        Command::Plan {
            world,
            from,
            to,
            cell,
            algorithm,
        } => plan::plan(&world, &from, &to, cell, algorithm.into()),
        Command::Arena {
            world,
            architecture,
            perturb,
            planning_cost,
            duration,
            seed,
            every,
        } => plan::arena(
            &world,
            &kinolab_architectures::run::Request {
                architecture,
                perturb,
                planning_cost_ms: planning_cost,
                duration,
                seed,
                every,
            },
        ),
        Command::Components { system, until } => components::components(&system, until),
        Command::Lessons { dir } => check_lessons(dir),
    }
}

/// Check lessons as the lab would show them: the Markdown, every widget
/// block against the widget schema, and every image.
fn check_lessons(dir: Option<PathBuf>) -> Result<Value, Failure> {
    let course = match dir {
        None => kinolab_lessons::bundled::course(),
        Some(dir) => {
            let (files, images) = read_lesson_files(&dir)?;
            kinolab_lessons::Course::from_files(files.iter().map(|(p, t)| (p.as_str(), t.as_str())))
                .and_then(|course| {
                    let images: Vec<&str> = images.iter().map(String::as_str).collect();
                    course.check_images(&images)?;
                    Ok(course)
                })
        }
    }
    .and_then(|course| {
        kinolab_schema::check_course(&course)?;
        Ok(course)
    })
    .map_err(|e| Failure(e.to_string()))?;
    Ok(json!({ "ok": true, "units": report("lessons", &course.summary())? }))
}

/// Markdown and PNG files found in unit folders under `dir`: the Markdown
/// with its text, and the images' paths, all relative to `dir`.
type LessonFiles = (Vec<(String, String)>, Vec<String>);

/// The most Markdown files `kinolab lessons` reads from a folder.
const MAX_LESSON_FILES: usize = 1000;

fn read_lesson_files(dir: &std::path::Path) -> Result<LessonFiles, Failure> {
    let mut out = Vec::new();
    let mut images = Vec::new();
    let read_dir = |d: &std::path::Path| {
        std::fs::read_dir(d)
            .map_err(|e| Failure(format!("{}: cannot read folder: {e}", d.display())))
    };
    for entry in read_dir(dir)?.flatten() {
        let path = entry.path();
        if !path.is_dir() {
            continue;
        }
        let folder = entry.file_name().to_string_lossy().into_owned();
        for file in read_dir(&path)?.flatten() {
            let name = file.file_name().to_string_lossy().into_owned();
            if name.ends_with(".md") {
                if out.len() >= MAX_LESSON_FILES {
                    return Err(Failure(format!(
                        "{}: more than {MAX_LESSON_FILES} lesson files",
                        dir.display()
                    )));
                }
                out.push((format!("{folder}/{name}"), input::read(&file.path())?));
            } else if name.ends_with(".png") {
                images.push(format!("{folder}/{name}"));
            }
        }
    }
    Ok((out, images))
}

/// Clap's complaint as one line: what is wrong and which option, without
/// the usage block that follows it.
fn usage_error(e: &clap::Error) -> String {
    use clap::error::ErrorKind;
    if matches!(
        e.kind(),
        ErrorKind::MissingSubcommand | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
    ) {
        return "no command given; `kinolab --help` lists them".into();
    }
    let text = e.to_string();
    let parts: Vec<&str> = text
        .lines()
        .map(str::trim)
        .take_while(|l| !l.starts_with("Usage:"))
        .filter(|l| !l.is_empty() && !l.starts_with("For more information"))
        .collect();
    parts.join(" ").trim_start_matches("error: ").to_owned()
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if e.use_stderr() => return output::fail(&usage_error(&e)),
        Err(e) => {
            // --help and --version go to stdout as clap formats them.
            let _ = e.print();
            return ExitCode::SUCCESS;
        }
    };
    match run(cli.command) {
        Ok(value) => output::print(&value),
        Err(Failure(message)) => output::fail(&message),
    }
}
