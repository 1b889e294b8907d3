//! Legs: how many leg-event sequences a walker has, whether a stance is
//! statically stable, a gait through its cycle, and oscillators settling
//! into a gait.

use kinolab_locomotion::balance::{PushRun, Recovery};
use kinolab_locomotion::walker::{Step, Walker};
use kinolab_locomotion::{Cpg, Gait, report};
use serde::Serialize;

use crate::source::unknown;
use crate::{Error, Files, Operation, Source};

/// `kinolab leg-events`: N = (2k − 1)!, exact as a decimal string.
#[derive(Debug, Clone, Copy)]
pub struct LegEvents {
    pub legs: u32,
}

impl Operation for LegEvents {
    type Report = report::LegEventsReport;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        report::leg_events(self.legs).map_err(|e| Error::argument("legs", e.message))
    }
}

/// `kinolab stability`: the support polygon, the margin and the nearest
/// edge point for a centre of mass and the feet on the ground.
#[derive(Debug, Clone)]
pub struct Stability {
    pub com: [f64; 2],
    pub feet: Vec<[f64; 2]>,
}

impl Operation for Stability {
    type Report = report::StabilityReport;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        report::stability(self.com, &self.feet)
            .map_err(|e| Error::argument(e.field.clone(), e.message))
    }
}

/// A gait: a gait file's text, or a named gait (`catalogue:hexapod-tripod`).
pub fn gait(source: &Source) -> Result<Gait, Error> {
    source.load("gait", "catalogue:", Gait::from_json, |id| {
        kinolab_locomotion::named(id).ok_or_else(|| {
            let known: Vec<&str> = kinolab_locomotion::named_ids().collect();
            unknown("gait", id, &known)
        })
    })
}

/// `kinolab gait`: the cycle at `samples` instants τ = (k + ½)/N.
#[derive(Debug, Clone)]
pub struct GaitCycle {
    pub gait: Source,
    pub samples: usize,
}

impl Operation for GaitCycle {
    type Report = report::GaitReport;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        report::gait(&gait(&self.gait)?, self.samples)
            .map_err(Error::argument_or_input(&["samples"], "gait"))
    }
}

/// `kinolab cpg`: where coupled phase oscillators end and whether they lock.
#[derive(Debug, Clone)]
pub struct Oscillators {
    pub cpg: Source,
}

impl Operation for Oscillators {
    type Report = report::CpgReport;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let cpg = self.cpg.file_only("cpg", "a CPG file", Cpg::from_json)?;
        report::cpg(&cpg).map_err(|e| Error::input("cpg", e))
    }
}

/// `kinolab zmp`: a push-recovery run of the cart-table model (a
/// `*.zmp.json` file): the body, its ZMP and the capture point each step.
#[derive(Debug, Clone)]
pub struct Zmp {
    pub run: Source,
}

impl Operation for Zmp {
    type Report = Recovery;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let run = self
            .run
            .file_only("run", "a push-recovery file", PushRun::from_json)?;
        run.run().map_err(|e| Error::input("run", e))
    }
}

/// `kinolab walk`: the lab's hexapod walking a six-legged gait by per-leg
/// inverse kinematics, at `samples` + 1 instants of one cycle.
#[derive(Debug, Clone)]
pub struct Walk {
    pub gait: Source,
    /// How high a swinging foot is lifted, m.
    pub lift: f64,
    pub samples: usize,
    /// The stride, m (the gait's own when `None`).
    pub stride: Option<f64>,
    /// A learner's leg sequencer (`foot(leg, phase)`), in place of the
    /// gait's timing.
    pub sequencer: Option<String>,
}

/// The walker through one cycle: each instant, the smallest stability
/// margin, and how far the body moved forwards.
#[derive(Debug, Clone, Serialize)]
pub struct WalkReport {
    pub gait: String,
    pub stride: f64,
    pub lift: f64,
    pub steps: Vec<Step>,
    pub min_margin: Option<f64>,
    pub progress: f64,
}

impl Operation for Walk {
    type Report = WalkReport;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let mut gait = gait(&self.gait)?;
        if let Some(stride) = self.stride {
            gait.stride = stride;
        }
        let as_argument = Error::argument_or_input(&["lift", "samples", "stride"], "gait");
        let mut walker = Walker::new(gait.clone(), self.lift).map_err(&as_argument)?;
        if let Some(source) = &self.sequencer {
            walker = walker
                .with_sequencer(source)
                .map_err(|e| Error::argument("sequencer", e.message))?;
        }
        let steps = walker
            .cycle(self.samples)
            .map_err(|e| match e.field.as_str() {
                "sequencer" => Error::argument("sequencer", e.message),
                _ => as_argument(e),
            })?;
        let min_margin = steps
            .iter()
            .map(|s| s.margin.unwrap_or(f64::NEG_INFINITY))
            .reduce(f64::min)
            .filter(|m| m.is_finite());
        Ok(WalkReport {
            gait: gait.name,
            stride: gait.stride,
            lift: self.lift,
            progress: kinolab_locomotion::walker::progress(&steps),
            min_margin,
            steps,
        })
    }
}
