//! The go-to-pose controller: a run file simulated, the same run from a
//! circle of starts, and the stability of a set of gains.

use kinolab_control::file::RunSpec;
use kinolab_control::{Gains, report};

use crate::{Error, Files, Operation, Source};

/// A control run file (`*.run.json`): the polar controller or an
/// open-loop plan on a wheeled robot.
pub fn run_file(source: &Source) -> Result<RunSpec, Error> {
    source.file_only("run", "a run file", kinolab_control::file::from_json)
}

/// `kinolab simulate`: the run's samples, whether and when it arrived.
#[derive(Debug, Clone)]
pub struct Simulate {
    pub run: Source,
}

impl Operation for Simulate {
    type Report = report::SimulationReport;
    fn report(&self, files: &mut dyn Files) -> Result<Self::Report, Error> {
        let spec = run_file(&self.run.with_scripts("run", files)?)?;
        let trajectory = spec.run.simulate().map_err(|e| Error::input("run", e))?;
        Ok(report::simulation(&spec, &trajectory))
    }
}

/// `kinolab batch`: the run from `count` starts on a circle of `radius`
/// around its goal, all facing `heading_deg`; each run's path when `paths`.
#[derive(Debug, Clone)]
pub struct Batch {
    pub run: Source,
    pub radius: f64,
    pub count: usize,
    pub heading_deg: f64,
    pub paths: bool,
}

impl Operation for Batch {
    type Report = report::BatchReport;
    fn report(&self, files: &mut dyn Files) -> Result<Self::Report, Error> {
        let spec = run_file(&self.run.with_scripts("run", files)?)?;
        report::circle_batch(&spec, self.radius, self.count, self.heading_deg, self.paths).map_err(
            |e| match e.field.as_str() {
                "heading" => Error::argument("heading_deg", e.message),
                "radius" | "count" => Error::argument(e.field.clone(), e.message),
                _ => Error::input("run", e),
            },
        )
    }
}

/// `kinolab gains`: the local and strong stability conditions, the
/// linearised loop and its eigenvalues.
#[derive(Debug, Clone, Copy)]
pub struct ControllerStability {
    pub k_rho: f64,
    pub k_alpha: f64,
    pub k_beta: f64,
}

impl Operation for ControllerStability {
    type Report = report::StabilityReport;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let gains = Gains::new(self.k_rho, self.k_alpha, self.k_beta)
            .map_err(|e| Error::argument("gains", e.to_string()))?;
        Ok(report::stability(&gains))
    }
}
