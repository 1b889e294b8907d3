//! `kinolab mechanisms`, `describe`, `home-state`, `fk`, `ik`, `place`,
//! `jacobian` and `collide`: mechanism models (`*.model.json`, see the
//! contract) or catalogue mechanisms, at the joint values given.

use std::path::{Path, PathBuf};

use clap::Subcommand;
use kinolab_api::mechanism::{self, Ik, ObstacleSpec, On, Query};
use kinolab_api::{forces, robot};
use serde_json::Value;

use crate::args::{fixed, numbers};
use crate::ask::{ask, source};
use crate::{Failure, Printed, output};

#[derive(Debug, Subcommand)]
pub(crate) enum Command {
    /// List the catalogue mechanisms.
    Mechanisms,
    /// A model's structure: joints, bodies, frames, couplings, loops, shapes and solvers.
    Describe {
        /// A model file (`*.model.json`), or `catalogue:<id>`.
        model: PathBuf,
    },
    /// A model's home state: zero clamped into the limits, followers set, loops closed.
    HomeState {
        /// A model file (`*.model.json`), or `catalogue:<id>`.
        model: PathBuf,
    },
    /// Forward kinematics of a model file: the 4×4 pose of a frame (default: the tool).
    Fk {
        /// A model file (`*.model.json`), a URDF file (`*.urdf`), or `catalogue:<id>`.
        model: PathBuf,
        #[command(flatten)]
        q: Joints,
        /// URDF: some joints by name, the rest at zero: NAME=VALUE,...
        #[arg(long, value_name = "NAME=VALUE,...", allow_hyphen_values = true)]
        set: Option<String>,
        /// A frame name: a joint's, `base`, `world` or `tool`; for URDF, a link.
        #[arg(long)]
        frame: Option<String>,
        /// URDF: every link's pose instead of one frame.
        #[arg(long, conflicts_with = "frame")]
        all_frames: bool,
    },
    /// Inverse kinematics of a model file: joint values that put a frame at a target.
    Ik {
        /// A model file (`*.model.json`), a URDF file (`*.urdf`: seed and answer in `--q` order), or `catalogue:<id>`.
        model: PathBuf,
        /// Target position, m: X,Y,Z
        #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
        position: Option<String>,
        /// Target rotation, row-major: R11,...,R33 (position only when omitted)
        #[arg(long, value_name = "R11,...,R33", allow_hyphen_values = true)]
        rotation: Option<String>,
        /// Starting joint values: Q1,...,QN (default: the home state)
        #[arg(long, value_name = "Q1,...,QN", allow_hyphen_values = true)]
        seed: Option<String>,
        /// The frame to place (default: the tool; for URDF, the end of the longest chain).
        #[arg(long)]
        frame: Option<String>,
        /// Give the target in this frame instead of the world.
        #[arg(long)]
        relative_to: Option<String>,
        /// Most iterations per start (at most 1000).
        #[arg(long)]
        max_iterations: Option<usize>,
        /// Most restarts from other seeds (at most 200).
        #[arg(long)]
        restarts: Option<usize>,
    },
    /// Every body's frame at the given joint values.
    Place {
        /// A model file (`*.model.json`), or `catalogue:<id>`.
        model: PathBuf,
        #[command(flatten)]
        q: Joints,
    },
    /// The 6 × dof geometric Jacobian of a frame (default: the tool).
    Jacobian {
        /// A model file (`*.model.json`), or `catalogue:<id>`.
        model: PathBuf,
        #[command(flatten)]
        q: Joints,
        /// A frame name (default `tool`).
        #[arg(long)]
        frame: Option<String>,
    },
    /// Inverse dynamics (the torques for accelerations --qdd, with g(q) and M(q)), or forward dynamics (the accelerations torques --tau produce).
    Dynamics {
        #[command(flatten)]
        at: Posed,
        /// Joint velocities (default zeros): QD1,...,QDN
        #[arg(long, value_name = "QD1,...,QDN", allow_hyphen_values = true)]
        qd: Option<String>,
        /// Joint accelerations: QDD1,...,QDDN
        #[arg(
            long,
            value_name = "QDD1,...,QDDN",
            allow_hyphen_values = true,
            required_unless_present = "tau",
            conflicts_with = "tau"
        )]
        qdd: Option<String>,
        /// Joint torques and forces: T1,...,TN
        #[arg(long, value_name = "T1,...,TN", allow_hyphen_values = true)]
        tau: Option<String>,
    },
    /// The torques that hold the robot still against gravity and loads; with --stiffness, each joint's give and how far the frame sags.
    Statics {
        #[command(flatten)]
        at: Posed,
        /// A force (and moment) the world applies at a frame's origin, root-frame axes, repeatable: FRAME:FX,FY,FZ[,MX,MY,MZ]
        #[arg(long, allow_hyphen_values = true)]
        load: Vec<String>,
        /// Joint stiffness, N·m/rad or N/m: one value for all, or NAME=K,...
        #[arg(long, allow_hyphen_values = true)]
        stiffness: Option<String>,
        /// The frame whose sag is reported (default: as `fk`).
        #[arg(long)]
        frame: Option<String>,
    },
    /// Colliding body pairs and the clearance in a view plane, among the bodies and against obstacles.
    Collide {
        /// A model file (`*.model.json`), or `catalogue:<id>`.
        model: PathBuf,
        #[command(flatten)]
        q: Joints,
        /// The view plane: `plan` (x–y) or `side` (x–z).
        #[arg(long, default_value = "side")]
        plane: String,
        /// An obstacle, repeatable: `circle:X,Y,R` or `rect:X,Y,HALF_W,HALF_H`.
        #[arg(long, allow_hyphen_values = true)]
        obstacle: Vec<String>,
    },
}

/// What moves the robot or holds it still, and which joints are set.
#[derive(Debug, clap::Args)]
pub(crate) struct Posed {
    /// A URDF file (`*.urdf`), a model file (`*.model.json`), or `catalogue:<id>`.
    model: PathBuf,
    #[command(flatten)]
    q: Joints,
    /// Some joints by name, the rest at zero: NAME=VALUE,...
    #[arg(long, value_name = "NAME=VALUE,...", allow_hyphen_values = true)]
    set: Option<String>,
    /// Gravity in the root frame, m/s² (default 0,0,-9.81).
    #[arg(long, value_name = "GX,GY,GZ", allow_hyphen_values = true)]
    gravity: Option<String>,
}

impl Posed {
    fn joints(&self) -> Result<forces::Joints, Failure> {
        Ok(match &self.set {
            Some(set) => forces::Joints::Named(named_values(set)?),
            None => forces::Joints::All(self.q.values()?),
        })
    }

    fn gravity(&self) -> Result<Option<[f64; 3]>, Failure> {
        self.gravity
            .as_deref()
            .map(|g| fixed("gravity", "GX,GY,GZ", g))
            .transpose()
    }
}

/// Joint values for a model.
#[derive(Debug, clap::Args)]
pub(crate) struct Joints {
    /// Joint values, rad (revolute) or m (prismatic): Q1,...,QN (none for a model without joints)
    #[arg(
        long,
        value_name = "Q1,...,QN",
        allow_hyphen_values = true,
        default_value = ""
    )]
    q: String,
}

impl Joints {
    fn values(&self) -> Result<Vec<f64>, Failure> {
        numbers("q", &self.q)
    }
}

pub(crate) fn run(command: Command) -> Result<Value, Failure> {
    match command {
        Command::Mechanisms => ask(&mechanism::Mechanisms, None),
        Command::Describe { model } if is_urdf(&model) => ask(
            &robot::RobotDescribe {
                robot: source(&model)?,
            },
            Some(&model),
        ),
        Command::Describe { model } => on(&model, mechanism::Describe),
        Command::HomeState { model } => on(&model, mechanism::HomeState),
        Command::Fk {
            model,
            q,
            set,
            frame,
            all_frames,
        } if is_urdf(&model) => {
            let joints = match set {
                Some(set) => robot::Setting::Named(named_values(&set)?),
                None => robot::Setting::All(q.values()?),
            };
            let fk = robot::RobotFk {
                robot: source(&model)?,
                joints,
                frame,
                all_frames,
            };
            ask(&fk, Some(&model)).map_err(|e| naming_the_file(e, &model))
        }
        Command::Fk {
            model,
            q,
            set,
            frame,
            all_frames,
        } => {
            if set.is_some() || all_frames {
                return Err(Failure(
                    "--set and --all-frames work on URDF files (`*.urdf`)".into(),
                ));
            }
            on(
                &model,
                mechanism::Fk {
                    q: q.values()?,
                    frame,
                },
            )
        }
        Command::Place { model, q } => on(&model, mechanism::Place { q: q.values()? }),
        Command::Dynamics { at, qd, qdd, tau } => dynamics(&at, qd, qdd, tau),
        Command::Statics {
            at,
            load,
            stiffness,
            frame,
        } => statics(&at, &load, stiffness.as_deref(), frame),
        Command::Jacobian { model, q, frame } => on(
            &model,
            mechanism::Jacobian {
                q: q.values()?,
                frame,
            },
        ),
        Command::Collide {
            model,
            q,
            plane,
            obstacle,
        } => on(
            &model,
            mechanism::Collide {
                q: q.values()?,
                plane,
                obstacles: obstacle
                    .iter()
                    .map(|o| obstacle_spec(o))
                    .collect::<Result<_, _>>()?,
            },
        ),
        Command::Ik {
            model,
            position,
            rotation,
            seed,
            frame,
            relative_to,
            max_iterations,
            restarts,
        } => {
            let ik = Ik {
                frame,
                position: position
                    .map(|p| fixed("position", "X,Y,Z", &p))
                    .transpose()?,
                rotation: rotation
                    .map(|r| fixed("rotation", "R11,...,R33 (row-major)", &r))
                    .transpose()?,
                relative_to,
                seed: seed.map(|s| numbers("seed", &s)).transpose()?,
                max_iterations,
                restarts,
            };
            if is_urdf(&model) {
                let ik = robot::RobotIk {
                    robot: source(&model)?,
                    ik,
                };
                return ask(&ik, Some(&model)).map_err(|e| naming_the_file(e, &model));
            }
            on(&model, ik)
        }
    }
}

/// `kinolab dynamics`: inverse with `--qdd`, forward with `--tau`.
fn dynamics(
    at: &Posed,
    qd: Option<String>,
    qdd: Option<String>,
    tau: Option<String>,
) -> Result<Value, Failure> {
    let asked = match (qdd, tau) {
        (Some(qdd), _) => forces::Asked::Inverse {
            qdd: numbers("qdd", &qdd)?,
        },
        (None, Some(tau)) => forces::Asked::Forward {
            tau: numbers("tau", &tau)?,
        },
        (None, None) => return Err(Failure("give --qdd or --tau".into())),
    };
    let query = forces::Dynamics {
        joints: at.joints()?,
        qd: qd.map(|qd| numbers("qd", &qd)).transpose()?,
        asked,
        gravity: at.gravity()?,
    };
    on(&at.model, query).map_err(|e| naming_the_file(e, &at.model))
}

/// `kinolab statics`: the holding torques, loads and springs.
fn statics(
    at: &Posed,
    load: &[String],
    stiffness: Option<&str>,
    frame: Option<String>,
) -> Result<Value, Failure> {
    let query = forces::Statics {
        joints: at.joints()?,
        loads: load
            .iter()
            .map(|l| load_spec(l))
            .collect::<Result<_, _>>()?,
        stiffness: stiffness.map(stiffness_spec).transpose()?,
        frame,
        gravity: at.gravity()?,
    };
    on(&at.model, query).map_err(|e| naming_the_file(e, &at.model))
}

/// `kinolab export-urdf MODEL`: the URDF text on stdout, each thing URDF
/// could not say as a note on stderr.
pub(crate) fn export_urdf(model: &Path) -> Result<Printed, Failure> {
    let answer = on(model, mechanism::ExportUrdf)?;
    let notices = answer["notices"].as_array().cloned().unwrap_or_default();
    for notice in notices.iter().filter_map(Value::as_str) {
        output::note(notice);
    }
    Ok(Printed::Text(
        answer["urdf"].as_str().unwrap_or_default().to_owned(),
    ))
}

/// A file read as URDF: its name ends in `.urdf`.
fn is_urdf(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("urdf"))
}

/// A failure that names the file: a joint or a link is the file's, so a
/// bad name or value says which file it was looked for in.
fn naming_the_file(Failure(message): Failure, path: &Path) -> Failure {
    let shown = path.display().to_string();
    if message.starts_with(&shown) {
        Failure(message)
    } else {
        Failure(format!("{shown}: {message}"))
    }
}

/// `NAME=VALUE,...` as name and value pairs.
fn named_values(text: &str) -> Result<Vec<(String, f64)>, Failure> {
    text.split(',')
        .map(|pair| {
            let (name, value) = pair
                .split_once('=')
                .ok_or_else(|| Failure(format!("--set: `{}` is not NAME=VALUE", pair.trim())))?;
            match value.trim().parse::<f64>() {
                Ok(v) if v.is_finite() => Ok((name.trim().to_owned(), v)),
                _ => Err(Failure(format!(
                    "--set: `{}` is not a finite number",
                    value.trim()
                ))),
            }
        })
        .collect()
}

/// Ask `query` about the model in the file (or catalogue entry) `model`.
fn on<Q: Query>(model: &Path, query: Q) -> Result<Value, Failure> {
    let on = On {
        model: source(model)?,
        query,
    };
    ask(&on, Some(model))
}

/// `FRAME:FX,FY,FZ` or `FRAME:FX,FY,FZ,MX,MY,MZ`.
fn load_spec(text: &str) -> Result<forces::LoadSpec, Failure> {
    let (frame, values) = text
        .rsplit_once(':')
        .ok_or_else(|| Failure(format!("--load: `{text}` is not FRAME:FX,FY,FZ[,MX,MY,MZ]")))?;
    let v = numbers("load", values)?;
    let (force, moment) = match v.as_slice() {
        [fx, fy, fz] => ([*fx, *fy, *fz], [0.0; 3]),
        [fx, fy, fz, mx, my, mz] => ([*fx, *fy, *fz], [*mx, *my, *mz]),
        _ => {
            return Err(Failure(format!(
                "--load: `{text}` needs three numbers (a force) or six (a force and a moment)"
            )));
        }
    };
    Ok(forces::LoadSpec {
        frame: frame.to_owned(),
        force,
        moment,
    })
}

/// `K` for every joint, or `NAME=K,...`.
fn stiffness_spec(text: &str) -> Result<forces::Stiffness, Failure> {
    if text.contains('=') {
        return named_values(text)
            .map(forces::Stiffness::Named)
            .map_err(|Failure(m)| Failure(m.replace("--set", "--stiffness")));
    }
    let [k] = fixed(
        "stiffness",
        "one number for every joint, or NAME=K,...",
        text,
    )?;
    Ok(forces::Stiffness::All(k))
}

/// `circle:X,Y,R` or `rect:X,Y,HALF_W,HALF_H`.
fn obstacle_spec(text: &str) -> Result<ObstacleSpec, Failure> {
    match text.split_once(':') {
        Some(("circle", numbers)) => Ok(ObstacleSpec {
            circle: Some(fixed("obstacle", "X,Y,R for a circle", numbers)?),
            rect: None,
        }),
        Some(("rect", numbers)) => Ok(ObstacleSpec {
            circle: None,
            rect: Some(fixed("obstacle", "X,Y,HALF_W,HALF_H for a rect", numbers)?),
        }),
        _ => Err(Failure(format!(
            "--obstacle: `{text}` is not `circle:X,Y,R` or `rect:X,Y,HALF_W,HALF_H`"
        ))),
    }
}
