//! Built-in mechanisms: arms described by DH tables, and rigs built from
//! parts (a rover with a rocker-bogie, a rover carrying an arm, a hexapod
//! from one leg, a four-bar linkage), and real robots read from the URDF
//! files shipped with the lab.

mod arms;
mod rigs;

use crate::error::FieldError;
use crate::model::Model;

pub use arms::puma560_rows;

/// Catalogue entries: id, name, one-line summary.
pub const CATALOGUE: &[(&str, &str, &str)] = &[
    (
        "planar-2r",
        "Planar 2R arm",
        "two revolute joints in a plane, links 1 m and 0.8 m",
    ),
    (
        "planar-3r",
        "Planar 3R arm",
        "three revolute joints in a plane: position and heading of the hand",
    ),
    (
        "vertical-2r",
        "Two-link arm in a vertical plane",
        "shoulder and elbow turning about horizontal axes, links of 0.5 m (3 kg) and 0.4 m (2 kg): gravity loads the joints",
    ),
    (
        "vertical-3r",
        "Three-link arm in a vertical plane",
        "shoulder, elbow and wrist, links of 0.5 m (4 kg), 0.4 m (2.5 kg) and 0.15 m (1 kg)",
    ),
    (
        "double-pendulum",
        "Double pendulum",
        "two rods of 0.5 m and 1 kg hanging one from the other, free to swing",
    ),
    (
        "puma560",
        "Puma 560",
        "the classic six-joint industrial arm, standard DH, on a 0.6718 m base",
    ),
    (
        "stanford",
        "Stanford arm",
        "a six-joint arm with a prismatic third joint, standard DH",
    ),
    (
        "panda",
        "Franka Panda",
        "a seven-joint redundant arm described in modified DH",
    ),
    (
        "rocker-bogie",
        "Rocker-bogie rover",
        "six wheels on two rockers and two bogies; a differential couples the rockers",
    ),
    (
        "rover-arm",
        "Rover with an arm",
        "a mobile manipulator: a rover (x, y, yaw) carrying a three-joint arm",
    ),
    (
        "hexapod",
        "Hexapod",
        "one three-joint leg model mounted six times on a body",
    ),
    (
        "four-bar",
        "Four-bar linkage",
        "a crank-rocker: a closed chain kept shut by a loop constraint",
    ),
    (
        "ur5",
        "UR5 (URDF)",
        "Universal Robots' six-joint arm, read from its URDF file",
    ),
    (
        "panda-urdf",
        "Franka Panda (URDF)",
        "the Panda as its maker describes it in URDF: seven joints and a gripper whose second finger mimics the first",
    ),
    (
        "solo12",
        "Solo 12 quadruped (URDF)",
        "an open-source quadruped, three joints a leg, read from its URDF file",
    ),
];

/// A robot from a URDF file shipped with the lab (see the README for
/// their licences).
fn shipped(packed: &[u8]) -> Result<Model, FieldError> {
    let damaged = || FieldError::new("model", "the shipped robot file is damaged");
    let bytes = fdeflate::decompress_to_vec(packed).map_err(|_| damaged())?;
    let text = String::from_utf8(bytes).map_err(|_| damaged())?;
    crate::urdf::read(&text).map(|robot| robot.model)
}

/// A URDF file from `robots/`, deflated by `build.rs`.
macro_rules! packed {
    ($name:literal) => {
        include_bytes!(concat!(env!("OUT_DIR"), "/", $name, ".urdf.zlib"))
    };
}

/// A built-in mechanism by id.
pub fn mechanism(id: &str) -> Result<Model, FieldError> {
    match id {
        "planar-2r" => arms::planar(&[1.0, 0.8]),
        "planar-3r" => arms::planar(&[1.0, 0.8, 0.3]),
        "vertical-2r" => arms::vertical("Two-link arm", &[(0.5, 3.0), (0.4, 2.0)], false),
        "vertical-3r" => arms::vertical(
            "Three-link arm",
            &[(0.5, 4.0), (0.4, 2.5), (0.15, 1.0)],
            false,
        ),
        "double-pendulum" => arms::vertical("Double pendulum", &[(0.5, 1.0), (0.5, 1.0)], true),
        "puma560" => arms::puma560(),
        "stanford" => arms::stanford(),
        "panda" => arms::panda(),
        "rocker-bogie" => rigs::rocker_bogie(),
        "rover-arm" => rigs::rover_arm(),
        "hexapod" => rigs::hexapod(),
        "four-bar" => rigs::four_bar(rigs::FOUR_BAR),
        "ur5" => shipped(packed!("ur5")),
        "panda-urdf" => shipped(packed!("panda")),
        "solo12" => shipped(packed!("solo12")),
        other => {
            let known: Vec<&str> = CATALOGUE.iter().map(|(id, _, _)| *id).collect();
            Err(FieldError::new(
                "model",
                format!(
                    "no built-in mechanism `{other}` (known: {})",
                    known.join(", ")
                ),
            ))
        }
    }
}
