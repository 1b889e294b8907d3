//! Behaviours run in a world: the trajectory, who had control when, the
//! world's events and the run's metrics.

use kinolab_behaviours::run::{RunReport, Setup, run};

use crate::{Error, Files, Operation, Source};

/// A behaviour run file.
pub fn setup(source: &Source) -> Result<Setup, Error> {
    source.file_only("run", "a behaviour run file", Setup::from_json)
}

/// `kinolab run`.
#[derive(Debug, Clone)]
pub struct RunBehaviours {
    pub run: Source,
}

impl Operation for RunBehaviours {
    type Report = RunReport;
    fn report(&self, files: &mut dyn Files) -> Result<Self::Report, Error> {
        let source = self.run.with_scripts("run", files)?;
        run(&setup(&source)?).map_err(|e| Error::input("run", e))
    }
}
