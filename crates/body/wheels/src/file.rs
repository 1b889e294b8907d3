//! Robot files (`*.robot.json`, degrees for people) and the compact layout
//! code the lab keeps in its URL.

use serde::{Deserialize, Serialize};

use crate::chassis::Chassis;
use crate::error::FieldError;
use crate::wheel::{Wheel, WheelKind};

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
enum KindName {
    Fixed,
    Steered,
    Castor,
    Swedish,
    Spherical,
}

/// One wheel as a robot file writes it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct WheelEntry {
    kind: KindName,
    alpha_deg: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    beta_deg: Option<f64>,
    l: f64,
    radius: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    offset: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    gamma_deg: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    steer_group: Option<String>,
}

/// A robot file as people write it: the robot's name and its wheels in
/// degrees.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a robot file (an object with `name` and `wheels`)"
)]
pub struct RobotFile {
    #[serde(default)]
    name: String,
    wheels: Vec<WheelEntry>,
}

impl Chassis {
    /// Read a robot file. Errors name the JSON path of the bad field.
    pub fn from_json(text: &str) -> Result<Self, FieldError> {
        let file: RobotFile = kinolab_common::error::from_json(text)?;
        let wheels = file
            .wheels
            .iter()
            .enumerate()
            .map(|(i, e)| entry_to_wheel(i, e))
            .collect::<Result<Vec<_>, _>>()?;
        Chassis::new(file.name, wheels)
    }

    /// The robot file for this chassis.
    pub fn file(&self) -> RobotFile {
        RobotFile {
            name: self.name().to_owned(),
            wheels: self.wheels().iter().map(wheel_to_entry).collect(),
        }
    }

    /// The robot file for this chassis, pretty-printed.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(&self.file()).unwrap_or_default()
    }
}

fn entry_to_wheel(i: usize, e: &WheelEntry) -> Result<Wheel, FieldError> {
    let field = |name: &str| format!("wheels[{i}].{name}");
    let needs = |value: Option<f64>, name: &str, why: &str| {
        value.ok_or_else(|| FieldError::new(field(name), format!("missing: {why}")))
    };
    let refuse = |value: &Option<f64>, name: &str| match value {
        Some(_) => Err(FieldError::new(
            field(name),
            format!("a {:?} wheel has no {name}", e.kind).to_lowercase(),
        )),
        None => Ok(()),
    };
    let kind = match e.kind {
        KindName::Fixed => WheelKind::Fixed,
        KindName::Steered => WheelKind::Steered,
        KindName::Castor => WheelKind::Castor {
            offset: needs(e.offset, "offset", "a castor needs its offset d (metres)")?,
        },
        KindName::Swedish => WheelKind::Swedish {
            gamma: needs(
                e.gamma_deg,
                "gamma_deg",
                "a Swedish wheel needs its roller angle",
            )?
            .to_radians(),
        },
        KindName::Spherical => WheelKind::Spherical,
    };
    if !matches!(e.kind, KindName::Castor) {
        refuse(&e.offset, "offset")?;
    }
    if !matches!(e.kind, KindName::Swedish) {
        refuse(&e.gamma_deg, "gamma_deg")?;
    }
    let beta = match (e.kind, e.beta_deg) {
        (KindName::Spherical, beta) => beta.unwrap_or(0.0),
        (_, beta) => needs(beta, "beta_deg", "the wheel-plane angle β in degrees")?,
    };
    Ok(Wheel {
        kind,
        alpha: e.alpha_deg.to_radians(),
        beta: beta.to_radians(),
        l: e.l,
        radius: e.radius,
        steer_group: e.steer_group.clone(),
    })
}

/// Degrees for people, rounded to 1e-9° so 90° stays 90 after a round trip.
fn degrees(radians: f64) -> f64 {
    let d = radians.to_degrees();
    let r = (d * 1e9).round() / 1e9;
    if r == 0.0 { 0.0 } else { r }
}

fn wheel_to_entry(w: &Wheel) -> WheelEntry {
    let (kind, offset, gamma_deg) = match w.kind {
        WheelKind::Fixed => (KindName::Fixed, None, None),
        WheelKind::Steered => (KindName::Steered, None, None),
        WheelKind::Castor { offset } => (KindName::Castor, Some(offset), None),
        WheelKind::Swedish { gamma } => (KindName::Swedish, None, Some(degrees(gamma))),
        WheelKind::Spherical => (KindName::Spherical, None, None),
    };
    WheelEntry {
        kind,
        alpha_deg: degrees(w.alpha),
        beta_deg: (kind != KindName::Spherical).then(|| degrees(w.beta)),
        l: w.l,
        radius: w.radius,
        offset,
        gamma_deg,
        steer_group: w.steer_group.clone(),
    }
}

/// A number in its shortest exact form (0.25 stays "0.25"), so a layout
/// survives the trip through a URL bit for bit.
fn short(v: f64) -> String {
    if v == 0.0 { "0".into() } else { format!("{v}") }
}

impl Chassis {
    /// The compact layout code: wheels separated by `;`, each
    /// `kind,alpha_deg,beta_deg,l,radius` with kind `f` fixed, `s` steered,
    /// `c` castor, `w` Swedish, `o` spherical, then `d=` (castor offset),
    /// `g=` (roller angle, degrees) and `s=` (steering group) as needed.
    pub fn to_compact(&self) -> String {
        self.wheels()
            .iter()
            .map(|w| {
                let letter = match w.kind {
                    WheelKind::Fixed => "f",
                    WheelKind::Steered => "s",
                    WheelKind::Castor { .. } => "c",
                    WheelKind::Swedish { .. } => "w",
                    WheelKind::Spherical => "o",
                };
                let mut text = format!(
                    "{letter},{},{},{},{}",
                    short(degrees(w.alpha)),
                    short(degrees(w.beta)),
                    short(w.l),
                    short(w.radius)
                );
                match w.kind {
                    WheelKind::Castor { offset } => text += &format!(",d={}", short(offset)),
                    WheelKind::Swedish { gamma } => {
                        text += &format!(",g={}", short(degrees(gamma)));
                    }
                    _ => {}
                }
                if let Some(group) = &w.steer_group {
                    text += &format!(",s={group}");
                }
                text
            })
            .collect::<Vec<_>>()
            .join(";")
    }

    /// Read a compact layout code (see [`Chassis::to_compact`]).
    pub fn from_compact(name: &str, code: &str) -> Result<Self, FieldError> {
        let wheels = code
            .split(';')
            .map(str::trim)
            .filter(|part| !part.is_empty())
            .enumerate()
            .map(|(i, part)| compact_wheel(i, part))
            .collect::<Result<Vec<_>, _>>()?;
        Chassis::new(name, wheels)
    }
}

fn compact_wheel(i: usize, part: &str) -> Result<Wheel, FieldError> {
    let field = format!("layout wheel {}", i + 1);
    let bad = |what: String| FieldError::new(field.clone(), what);
    let pieces: Vec<&str> = part.split(',').map(str::trim).collect();
    if pieces.len() < 5 {
        return Err(bad(format!(
            "expected kind,alpha_deg,beta_deg,l,radius, got {part:?}"
        )));
    }
    let number = |name: &str, text: &str| {
        text.parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| bad(format!("{name} must be a number, got {text:?}")))
    };
    let alpha = number("alpha_deg", pieces[1])?.to_radians();
    let beta = number("beta_deg", pieces[2])?.to_radians();
    let l = number("l", pieces[3])?;
    let radius = number("radius", pieces[4])?;
    let (mut offset, mut gamma, mut group) = (None, None, None);
    for extra in &pieces[5..] {
        match extra.split_once('=') {
            Some(("d", v)) => offset = Some(number("d", v)?),
            Some(("g", v)) => gamma = Some(number("g", v)?.to_radians()),
            Some(("s", v)) => group = Some(v.to_owned()),
            _ => return Err(bad(format!("unknown extra {extra:?} (use d=, g= or s=)"))),
        }
    }
    let kind = match pieces[0] {
        "f" => WheelKind::Fixed,
        "s" => WheelKind::Steered,
        "c" => WheelKind::Castor {
            offset: offset.ok_or_else(|| bad("a castor needs d=<offset>".into()))?,
        },
        "w" => WheelKind::Swedish {
            gamma: gamma.ok_or_else(|| bad("a Swedish wheel needs g=<roller angle>".into()))?,
        },
        "o" => WheelKind::Spherical,
        other => {
            return Err(bad(format!(
                "unknown kind {other:?} (f fixed, s steered, c castor, w Swedish, o spherical)"
            )));
        }
    };
    Ok(Wheel {
        kind,
        alpha,
        beta,
        l,
        radius,
        steer_group: group,
    })
}
