//! Systems of components that talk only through communication patterns,
//! run on a simulated clock.

use kinolab_components::{Report, System};

use crate::{Error, Files, Operation, Source};

/// A system: a system file's text, or a shipped example
/// (`example:out-of-order`).
pub fn system(source: &Source) -> Result<System, Error> {
    source.load(
        "system",
        "example:",
        System::from_json,
        kinolab_components::system::example,
    )
}

/// `kinolab components`: every message and the final state, run until
/// `until` s (the file's own `until` when `None`).
#[derive(Debug, Clone)]
pub struct Components {
    pub system: Source,
    pub until: Option<f64>,
}

impl Operation for Components {
    type Report = Report;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        let system = system(&self.system)?;
        system.run(self.until).map_err(|e| match e.field.as_str() {
            "until" if self.until.is_some() => Error::argument("until", e.message),
            _ => Error::input("system", e),
        })
    }
}
