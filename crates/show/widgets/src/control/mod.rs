//! Motion control: speed profiles, and the polar go-to-pose controller's
//! playground (its floor, its plots and its link state in their own files).

mod field;
pub mod playground;
pub mod speed_profile;
