//! The Kinolab lab's shell: what hosts the widgets and lessons.
//!
//! - [`shell`]: the top bar, the lesson list, the pages, progress;
//! - [`lesson_view`] and [`quiz_view`]: how lessons and quizzes are drawn
//!   (formulas by `kinolab-formula`, widgets from `kinolab-widgets`);
//! - [`gallery`]: every widget from the schema, live;
//! - [`route`] and [`progress`]: addresses in the URL and what is remembered;
//! - with the `window` feature (on by default), [`window`] runs it all in
//!   eframe: a native window, or the browser canvas through `web`.
//!
//! Everything but [`window`] uses egui alone, so the shell's tests build
//! without the window stack (`cargo test -p kinolab-app --no-default-features`).

pub mod first_screen;
pub mod gallery;
pub mod images;
pub mod lesson_view;
pub mod progress;
pub mod quiz_view;
pub mod route;
pub mod shell;
#[cfg(all(feature = "window", target_arch = "wasm32"))]
pub mod web;
#[cfg(feature = "window")]
pub mod window;

pub use shell::KinolabApp;
