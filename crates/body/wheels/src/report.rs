//! The reports the command line prints and the JavaScript API returns:
//! typed structs, so both say exactly the same thing (field names as in the
//! command-line contract; angles end in `_deg` when in degrees). Print them
//! through [`kinolab_common::display::tidy_report`].

use kinolab_common::angle::degrees;
use nalgebra::Vector3;
use serde::Serialize;

use crate::analysis::{Icr, twist_icr};
use crate::chassis::Chassis;
use crate::error::FieldError;
use crate::kinematics::{Violation, to_inertial};

/// `kinolab analyze`: ranks, the three degrees, DOF, holonomy, the ICR, each
/// wheel's zero-motion line and, for a stuck layout, who disagrees.
#[derive(Debug, Clone, Serialize)]
pub struct AnalysisReport {
    pub name: String,
    pub rank_c1: usize,
    pub rank_c1f: usize,
    pub rank_c1s: usize,
    pub steering_inputs: usize,
    pub degree_of_mobility: usize,
    pub degree_of_steerability: usize,
    pub degree_of_maneuverability: usize,
    pub ddof: usize,
    pub dof: usize,
    pub holonomic: bool,
    pub icr: Icr,
    pub wheels: Vec<WheelReport>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub disagreement: Option<DisagreementReport>,
}

/// One wheel in an [`AnalysisReport`].
#[derive(Debug, Clone, Serialize)]
pub struct WheelReport {
    pub kind: &'static str,
    pub position: [f64; 2],
    /// Standard wheels only: the line the ICR must lie on.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub zero_motion_line: Option<Line>,
}

#[derive(Debug, Clone, Serialize)]
pub struct Line {
    pub point: [f64; 2],
    pub direction: [f64; 2],
}

/// Which wheels keep a stuck layout from moving.
#[derive(Debug, Clone, Serialize)]
pub struct DisagreementReport {
    pub consensus: Icr,
    pub agree: Vec<usize>,
    pub disagree: Vec<Miss>,
}

#[derive(Debug, Clone, Serialize)]
pub struct Miss {
    pub wheel: usize,
    pub miss: f64,
}

/// `kinolab analyze`.
pub fn analysis(chassis: &Chassis) -> AnalysisReport {
    let a = chassis.analyze();
    let wheels = chassis
        .wheels()
        .iter()
        .map(|w| {
            let (point, direction) = w.zero_motion_line();
            WheelReport {
                kind: w.kind.name(),
                position: w.position(),
                zero_motion_line: w
                    .kind
                    .constrains_chassis()
                    .then_some(Line { point, direction }),
            }
        })
        .collect();
    AnalysisReport {
        name: chassis.name().to_owned(),
        rank_c1: a.rank_c1,
        rank_c1f: a.rank_c1f,
        rank_c1s: a.rank_c1s,
        steering_inputs: a.steering_inputs,
        degree_of_mobility: a.mobility,
        degree_of_steerability: a.steerability,
        degree_of_maneuverability: a.maneuverability,
        ddof: a.mobility,
        dof: a.dof,
        holonomic: a.holonomic,
        icr: a.icr,
        wheels,
        disagreement: chassis.disagreement().map(|d| DisagreementReport {
            consensus: d.consensus,
            agree: d.agree,
            disagree: d
                .disagree
                .into_iter()
                .map(|(wheel, miss)| Miss { wheel, miss })
                .collect(),
        }),
    }
}

/// `kinolab drive --twist`: inverse kinematics.
#[derive(Debug, Clone, Serialize)]
pub struct InverseReport {
    pub feasible: bool,
    pub wheels: Vec<WheelMotion>,
    pub violations: Vec<Violation>,
    /// The ICR of the commanded twist.
    pub icr: Icr,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub twist_inertial: Option<[f64; 3]>,
}

/// What one wheel must do for the twist.
#[derive(Debug, Clone, Serialize)]
pub struct WheelMotion {
    pub spin: f64,
    pub steer_deg: f64,
    pub steer_rate_deg: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub roller_speed: Option<f64>,
}

/// `kinolab drive --twist`.
pub fn inverse(
    chassis: &Chassis,
    twist: Vector3<f64>,
    theta: Option<f64>,
) -> Result<InverseReport, FieldError> {
    let ik = chassis.inverse(twist)?;
    Ok(InverseReport {
        feasible: ik.feasible,
        wheels: ik
            .wheels
            .iter()
            .map(|c| WheelMotion {
                spin: c.spin,
                steer_deg: degrees(c.steer),
                steer_rate_deg: degrees(c.steer_rate),
                roller_speed: c.roller_speed,
            })
            .collect(),
        violations: ik.violations,
        icr: twist_icr(&twist),
        twist_inertial: inertial(twist, theta)?,
    })
}

/// `kinolab drive --wheels`: forward kinematics.
#[derive(Debug, Clone, Serialize)]
pub struct ForwardReport {
    pub twist: [f64; 3],
    pub residual: f64,
    pub consistent: bool,
    pub determined: bool,
    pub icr: Icr,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub twist_inertial: Option<[f64; 3]>,
}

/// `kinolab drive --wheels`.
pub fn forward(
    chassis: &Chassis,
    spins: &[Option<f64>],
    theta: Option<f64>,
) -> Result<ForwardReport, FieldError> {
    let fk = chassis.forward(spins)?;
    let twist = Vector3::from(fk.twist);
    Ok(ForwardReport {
        twist: fk.twist,
        residual: fk.residual,
        consistent: fk.consistent,
        determined: fk.determined,
        icr: twist_icr(&twist),
        twist_inertial: inertial(twist, theta)?,
    })
}

/// The twist in the inertial frame, given a heading.
fn inertial(twist: Vector3<f64>, theta: Option<f64>) -> Result<Option<[f64; 3]>, FieldError> {
    let Some(theta) = theta else {
        return Ok(None);
    };
    crate::error::finite("theta", theta)?;
    let v = to_inertial(theta, twist);
    Ok(Some([v.x, v.y, v.z]))
}
