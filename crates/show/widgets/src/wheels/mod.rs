//! Wheeled robots: the workbench for layouts and their constraints, driving
//! by spins or twist, and the frames and rotation between them.

pub mod chassis;
pub mod drive;
pub mod frame_rotation;
pub mod workbench;
