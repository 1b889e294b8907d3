//! The catalogue: every widget a lesson may embed and its parameters, one
//! file per domain (as the widgets themselves are grouped in
//! `kinolab-widgets`); each widget reads its parameters through
//! [`crate::validate`] and [`crate::Params::settings`].

mod architecture;
mod autonomy;
mod behaviour;
mod code;
mod components;
mod control;
mod design;
mod fields;
mod locomotion;
mod mechanism;
mod wheels;

use crate::{Kind, Param, WidgetSchema};

pub use wheels::robot_of;

/// Every domain's widgets, in the gallery's order.
static DOMAINS: [&[WidgetSchema]; 11] = [
    locomotion::WIDGETS,
    architecture::WIDGETS,
    components::WIDGETS,
    design::WIDGETS,
    autonomy::WIDGETS,
    wheels::WIDGETS,
    control::WIDGETS,
    mechanism::WIDGETS,
    fields::WIDGETS,
    behaviour::WIDGETS,
    code::WIDGETS,
];

/// Every widget, domain by domain.
pub fn widgets() -> impl Iterator<Item = &'static WidgetSchema> {
    DOMAINS.iter().flat_map(|d| d.iter())
}

pub(super) const fn param(
    name: &'static str,
    kind: Kind,
    default: Option<&'static str>,
    help: &'static str,
) -> Param {
    Param {
        name,
        kind,
        default,
        help,
    }
}

pub(super) const YES_NO: Kind = Kind::YesNo;

/// Three numbers (a pose `x, y, heading_deg`, or gains).
pub(super) const fn triple(min: f64, max: f64) -> Kind {
    Kind::Numbers {
        min_count: 3,
        max_count: 3,
        min,
        max,
    }
}

/// A whole number of degrees of freedom, 0 to 3.
pub(super) const fn degree(name: &'static str, help: &'static str) -> Param {
    param(name, Kind::Integer { min: 0, max: 3 }, None, help)
}
