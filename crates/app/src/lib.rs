//! The Kinolab lab: one egui app for the browser canvas and a native window.
//!
//! - [`app`]: the shell (top bar, lesson list, pages, progress);
//! - [`lesson_view`] and [`quiz_view`]: how lessons and quizzes are drawn;
//! - [`math_view`]: formula typesetting;
//! - [`widgets`]: the live widgets lessons embed by name;
//! - [`route`] and [`progress`]: addresses in the URL and what is remembered.

pub mod app;
pub mod export;
pub mod images;
pub mod lesson_view;
pub mod math_view;
pub mod progress;
pub mod quiz_view;
pub mod route;
pub mod theme;
#[cfg(target_arch = "wasm32")]
pub mod web;
pub mod widgets;

pub use app::KinolabApp;

impl eframe::App for KinolabApp {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        #[cfg(target_arch = "wasm32")]
        web::before_frame(self, frame);
        #[cfg(not(target_arch = "wasm32"))]
        let _ = frame;
        self.show(ui);
        #[cfg(target_arch = "wasm32")]
        web::after_frame(self);
        #[cfg(not(target_arch = "wasm32"))]
        if let Some(hash) = self.take_pending_hash() {
            log::debug!("now at {hash}");
            ui.ctx()
                .send_viewport_cmd(egui::ViewportCommand::Title(self.title()));
        }
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        storage.set_string(progress::STORAGE_KEY, self.progress_json());
    }
}

/// Set up the app for eframe: text styles, theme, stored progress.
pub fn create(cc: &eframe::CreationContext<'_>, hash: &str) -> KinolabApp {
    #[cfg(target_arch = "wasm32")]
    let stored = {
        let _ = cc; // the browser's own storage is read directly
        web::load_progress()
    };
    #[cfg(not(target_arch = "wasm32"))]
    let stored = cc.storage.and_then(|s| s.get_string(progress::STORAGE_KEY));
    KinolabApp::new(stored.as_deref(), hash)
}
