//! The drawing pieces every widget shares: the canvas a drawing opens on
//! ([`canvas()`]), one world↔screen view for
//! plane drawings ([`PlaneView`]), draggable handles with accessible names
//! ([`handle`]), grids and axes, a small 3D camera ([`scene3d`]),
//! labels that keep out of each other's way ([`labels`]), and small marks
//! (arrows, crosses, stars, dashed circles: [`marks`]).

mod canvas;
mod grid;
mod handle;
pub mod labels;
pub mod marks;
pub mod plot;
pub mod scene3d;
mod view;

pub use canvas::{canvas, canvas_3d, corner_text, text_on_canvas};
pub use grid::{axes, grid, nice_step};
pub use handle::{Handle, handle};
pub use view::{PlaneView, local, placed, placed_dir};
