//! Potential fields: the summed vector at points, the stable equilibria in
//! a box, and a point robot's descent; and the classic fields and example
//! worlds the lab ships.

use kinolab_fields::Field;
use kinolab_fields::descend::Steps;
use kinolab_fields::report;
use serde::Serialize;

use crate::source::unknown;
use crate::{Error, Files, Operation, Source};

/// A field: a field file's text, or a classic field's id
/// (`catalogue:u-shaped-wall`).
pub fn field(source: &Source) -> Result<Field, Error> {
    source.load("field", "catalogue:", Field::from_json, |id| {
        match kinolab_fields::catalogue::preset(id) {
            Some(preset) => preset.field(),
            None => {
                let known: Vec<&str> = kinolab_fields::catalogue::PRESETS
                    .iter()
                    .map(|p| p.id)
                    .collect();
                Err(unknown("field", id, &known))
            }
        }
    })
}

/// A problem with an argument named by the core's field (`at[2]`, `box`,
/// `max_steps`), or else with the field file.
fn argument(e: kinolab_common::FieldError) -> Error {
    let name = e.field.split('[').next().unwrap_or_default().to_owned();
    if ["at", "box", "start", "step", "max_steps"].contains(&name.as_str()) {
        Error::argument(name, e.message)
    } else {
        Error::input("field", e)
    }
}

/// `kinolab field --at`: the field's vector at each point, in order.
#[derive(Debug, Clone)]
pub struct FieldVectors {
    pub field: Source,
    pub at: Vec<[f64; 2]>,
}

impl Operation for FieldVectors {
    type Report = report::Vectors;
    fn report(&self, files: &mut dyn Files) -> Result<Self::Report, Error> {
        report::vectors(&field(&self.field.with_scripts("field", files)?)?, &self.at)
            .map_err(argument)
    }
}

/// `kinolab field --minima --box`: every stable equilibrium in the box
/// `[x_min, y_min, x_max, y_max]`.
#[derive(Debug, Clone)]
pub struct FieldMinima {
    pub field: Source,
    pub area: [f64; 4],
}

impl Operation for FieldMinima {
    type Report = report::Minima;
    fn report(&self, files: &mut dyn Files) -> Result<Self::Report, Error> {
        report::minima_in(
            &field(&self.field.with_scripts("field", files)?)?,
            self.area,
        )
        .map_err(argument)
    }
}

/// `kinolab field --descend`: a point robot following the field in steps
/// of `step` (default 0.01 m), at most `max_steps` (default 10 000).
#[derive(Debug, Clone)]
pub struct FieldDescend {
    pub field: Source,
    pub start: [f64; 2],
    pub step: Option<f64>,
    pub max_steps: Option<usize>,
}

impl Operation for FieldDescend {
    type Report = kinolab_fields::descend::Descent;
    fn report(&self, files: &mut dyn Files) -> Result<Self::Report, Error> {
        let defaults = Steps::default();
        let steps = Steps {
            step: self.step.unwrap_or(defaults.step),
            max_steps: self.max_steps.unwrap_or(defaults.max_steps),
        };
        report::descent(
            &field(&self.field.with_scripts("field", files)?)?,
            self.start,
            steps,
        )
        .map_err(argument)
    }
}

/// A classic field: its id, title and what it shows.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct FieldEntry {
    pub id: &'static str,
    pub title: &'static str,
    pub shows: &'static str,
}

/// The example worlds' ids and the classic fields.
#[derive(Debug, Clone, Serialize)]
pub struct CatalogueReport {
    pub worlds: Vec<&'static str>,
    pub fields: Vec<FieldEntry>,
}

/// The example worlds and classic fields.
#[derive(Debug, Clone, Copy)]
pub struct Catalogues;

impl Operation for Catalogues {
    type Report = CatalogueReport;
    fn report(&self, _: &mut dyn Files) -> Result<Self::Report, Error> {
        Ok(CatalogueReport {
            worlds: kinolab_world::catalogue::WORLDS
                .iter()
                .map(|(id, _)| *id)
                .collect(),
            fields: kinolab_fields::catalogue::PRESETS
                .iter()
                .map(|p| FieldEntry {
                    id: p.id,
                    title: p.title,
                    shows: p.shows,
                })
                .collect(),
        })
    }
}
