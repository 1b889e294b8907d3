//! Software stability: the ant on the beach, the three slots, and
//! technology churn, and the morphology builder.

pub mod ant_beach;
pub mod churn;
pub mod morphology;
pub mod three_slots;
