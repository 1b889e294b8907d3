//! Classic robots, built from the same types a learner uses. Positions in
//! metres in the robot frame (x forward, y left), P at the origin.

use kinolab_common::trig;
use std::f64::consts::FRAC_PI_2;

use crate::chassis::Chassis;
use crate::error::FieldError;
use crate::wheel::{Wheel, WheelKind};

/// A robot the lab can start from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub struct CatalogueEntry {
    pub id: &'static str,
    pub name: &'static str,
    pub summary: &'static str,
}

const fn entry(id: &'static str, name: &'static str, summary: &'static str) -> CatalogueEntry {
    CatalogueEntry { id, name, summary }
}

/// Every catalogue robot, in teaching order.
pub const CATALOGUE: &[CatalogueEntry] = &[
    entry("unicycle", "Unicycle", "one fixed wheel under P"),
    entry(
        "differential-drive",
        "Differential drive",
        "two fixed wheels on one axle and a castor",
    ),
    entry(
        "two-axles",
        "Two fixed wheels, two axles",
        "fixed wheels whose axles cross: it can only circle one point",
    ),
    entry(
        "bicycle",
        "Bicycle",
        "a fixed rear wheel and a steered front wheel",
    ),
    entry(
        "tricycle",
        "Tricycle",
        "two fixed rear wheels on one axle and a steered front wheel",
    ),
    entry(
        "ackermann-car",
        "Car (Ackermann)",
        "fixed rear axle, two front wheels turned by one linkage",
    ),
    entry(
        "synchro-drive",
        "Synchro drive",
        "three steered wheels turned together by one belt",
    ),
    entry(
        "three-swedish",
        "Three Swedish wheels",
        "three 90° Swedish wheels at 120°: omnidirectional",
    ),
    entry(
        "uranus-mecanum",
        "Uranus (four mecanum wheels)",
        "four 45° Swedish wheels at the corners",
    ),
    entry(
        "omni-steer",
        "Omni-steer",
        "one steered wheel and two Swedish wheels",
    ),
    entry(
        "two-steer",
        "Two-steer",
        "two independently steered wheels and two balls",
    ),
    entry(
        "nomad-xr4000",
        "Nomad XR4000",
        "four steered castors: omnidirectional",
    ),
    entry(
        "rocker-bogie",
        "Rocker-bogie from above",
        "six wheels: four steered corners, two fixed in the middle",
    ),
    entry(
        "every-wheel-kind",
        "Every wheel kind",
        "one of each kind, as in the robot-file example",
    ),
];

fn fixed(x: f64, y: f64, heading_deg: f64, r: f64) -> Wheel {
    Wheel::at(WheelKind::Fixed, x, y, heading_deg.to_radians(), r)
}

fn steered(x: f64, y: f64, heading_deg: f64, r: f64) -> Wheel {
    Wheel::at(WheelKind::Steered, x, y, heading_deg.to_radians(), r)
}

/// A steered wheel at (x, y) turned so its axle points at `icr`, rolling
/// forward for a turn about it to the left.
fn steered_towards(x: f64, y: f64, icr: [f64; 2], r: f64) -> Wheel {
    let to_icr = trig::atan2(icr[1] - y, icr[0] - x);
    Wheel::at(WheelKind::Steered, x, y, to_icr - FRAC_PI_2, r)
}

fn swedish(x: f64, y: f64, heading_deg: f64, gamma_deg: f64, r: f64) -> Wheel {
    let kind = WheelKind::Swedish {
        gamma: gamma_deg.to_radians(),
    };
    Wheel::at(kind, x, y, heading_deg.to_radians(), r)
}

fn castor(x: f64, y: f64, offset: f64, r: f64) -> Wheel {
    Wheel::at(WheelKind::Castor { offset }, x, y, 0.0, r)
}

fn ball(x: f64, y: f64, r: f64) -> Wheel {
    Wheel::at(WheelKind::Spherical, x, y, 0.0, r)
}

/// Wheels on a circle of `radius` around P at the given angles (degrees).
fn ring(radius: f64, angles: [f64; 3], make: impl Fn(f64, f64, f64) -> Wheel) -> Vec<Wheel> {
    angles
        .iter()
        .map(|a| {
            let a = a.to_radians();
            make(radius * trig::cos(a), radius * trig::sin(a), a)
        })
        .collect()
}

/// The example robot file of the command-line contract.
pub const EVERY_WHEEL_KIND: &str = r#"{
  "name": "every-wheel-kind",
  "wheels": [
    { "kind": "fixed",     "alpha_deg": 90,  "beta_deg": 0,   "l": 0.25, "radius": 0.1 },
    { "kind": "fixed",     "alpha_deg": -90, "beta_deg": 180, "l": 0.25, "radius": 0.1 },
    { "kind": "steered",   "alpha_deg": 0,   "beta_deg": 90,  "l": 0.60, "radius": 0.1 },
    { "kind": "castor",    "alpha_deg": 180, "beta_deg": 0,   "l": 0.30, "radius": 0.05, "offset": 0.04 },
    { "kind": "swedish",   "alpha_deg": 60,  "beta_deg": 0,   "l": 0.20, "radius": 0.05, "gamma_deg": 45 },
    { "kind": "spherical", "alpha_deg": 0,   "l": 0.20, "radius": 0.05 }
  ]
}"#;

/// Build the catalogue robot `id`.
pub fn robot(id: &str) -> Result<Chassis, FieldError> {
    let wheels = match id {
        "unicycle" => vec![fixed(0.0, 0.0, 0.0, 0.3)],
        "differential-drive" => vec![
            fixed(0.0, 0.25, 0.0, 0.1),
            fixed(0.0, -0.25, 0.0, 0.1),
            castor(-0.3, 0.0, 0.04, 0.05),
        ],
        "two-axles" => vec![fixed(0.0, 0.25, 0.0, 0.1), fixed(0.5, 0.0, 45.0, 0.1)],
        "bicycle" => vec![
            fixed(0.0, 0.0, 0.0, 0.35),
            steered_towards(1.0, 0.0, [0.0, 3.0], 0.35),
        ],
        "tricycle" => vec![
            fixed(0.0, 0.25, 0.0, 0.1),
            fixed(0.0, -0.25, 0.0, 0.1),
            steered(0.6, 0.0, 0.0, 0.1),
        ],
        "ackermann-car" => vec![
            fixed(0.0, 0.3, 0.0, 0.15),
            fixed(0.0, -0.3, 0.0, 0.15),
            steered_towards(1.0, 0.3, [0.0, 2.5], 0.15).in_group("linkage"),
            steered_towards(1.0, -0.3, [0.0, 2.5], 0.15).in_group("linkage"),
        ],
        "synchro-drive" => ring(0.2, [90.0, 210.0, 330.0], |x, y, _| {
            steered(x, y, 30.0, 0.05).in_group("belt")
        }),
        "three-swedish" => ring(0.2, [90.0, 210.0, 330.0], |x, y, a| {
            swedish(x, y, a.to_degrees() + 90.0, 0.0, 0.05)
        }),
        "uranus-mecanum" => vec![
            swedish(0.25, 0.2, 0.0, -45.0, 0.06),
            swedish(0.25, -0.2, 0.0, 45.0, 0.06),
            swedish(-0.25, 0.2, 0.0, 45.0, 0.06),
            swedish(-0.25, -0.2, 0.0, -45.0, 0.06),
        ],
        "omni-steer" => vec![
            steered(0.3, 0.0, 0.0, 0.08),
            swedish(-0.2, 0.25, 0.0, 0.0, 0.05),
            swedish(-0.2, -0.25, 0.0, 0.0, 0.05),
        ],
        "two-steer" => vec![
            steered(0.3, 0.0, 0.0, 0.08),
            steered(-0.3, 0.0, 0.0, 0.08),
            ball(0.0, 0.25, 0.04),
            ball(0.0, -0.25, 0.04),
        ],
        "nomad-xr4000" => vec![
            castor(0.2, 0.2, 0.03, 0.04),
            castor(0.2, -0.2, 0.03, 0.04),
            castor(-0.2, 0.2, 0.03, 0.04),
            castor(-0.2, -0.2, 0.03, 0.04),
        ],
        "rocker-bogie" => vec![
            steered(0.5, 0.4, 0.0, 0.1),
            fixed(0.0, 0.45, 0.0, 0.1),
            steered(-0.5, 0.4, 0.0, 0.1),
            steered(0.5, -0.4, 0.0, 0.1),
            fixed(0.0, -0.45, 0.0, 0.1),
            steered(-0.5, -0.4, 0.0, 0.1),
        ],
        "every-wheel-kind" => return Chassis::from_json(EVERY_WHEEL_KIND),
        other => {
            let known: Vec<&str> = CATALOGUE.iter().map(|e| e.id).collect();
            return Err(FieldError::new(
                "robot",
                format!("no catalogue robot {other:?}; known: {}", known.join(", ")),
            ));
        }
    };
    let name = CATALOGUE.iter().find(|e| e.id == id).map_or(id, |e| e.name);
    Chassis::new(name, wheels)
}
