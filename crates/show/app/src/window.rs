//! The shell in eframe: the app as an `eframe::App`, stored progress, and
//! saving the files widgets ask for (natively into the working folder; in
//! the browser as downloads, through [`crate::web`]).

#[cfg(not(target_arch = "wasm32"))]
use crate::progress;
use crate::shell::KinolabApp;

impl eframe::App for KinolabApp {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        #[cfg(target_arch = "wasm32")]
        crate::web::before_frame(self, frame);
        #[cfg(not(target_arch = "wasm32"))]
        {
            let _ = frame;
            self.set_clock(native_now());
        }
        self.show(ui);
        for file in kinolab_widgets::export::take_save_requests(ui.ctx()) {
            save(&file);
        }
        for file in ui.ctx().input(|i| i.raw.dropped_files.clone()) {
            read_dropped(ui.ctx(), file);
        }
        for request in kinolab_widgets::open::take_pick_requests(ui.ctx()) {
            #[cfg(target_arch = "wasm32")]
            if let Err(e) = crate::web::pick(ui.ctx(), request) {
                log::warn!("could not open the file dialog: {e:?}");
            }
            // A native window opens files dropped on it.
            #[cfg(not(target_arch = "wasm32"))]
            log::info!(
                "file dialogs are the browser's; drop {} files on the window",
                request.accept
            );
        }
        #[cfg(target_arch = "wasm32")]
        crate::web::after_frame(self);
        #[cfg(not(target_arch = "wasm32"))]
        if let Some(hash) = self.take_pending_hash() {
            log::debug!("now at {hash}");
            ui.ctx()
                .send_viewport_cmd(egui::ViewportCommand::Title(self.title()));
        }
    }

    /// eframe saves on leaving the page, on losing focus and every half
    /// minute. In the browser that goes through the lab's own storage,
    /// which merges what other tabs stored instead of overwriting it.
    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        #[cfg(target_arch = "wasm32")]
        {
            let _ = storage;
            crate::web::storage::store(self);
        }
        #[cfg(not(target_arch = "wasm32"))]
        storage.set_string(progress::STORAGE_KEY, self.progress_json());
    }
}

/// Read a file dropped on the window and hand it to the widgets.
fn read_dropped(ctx: &egui::Context, file: egui::DroppedFileHandle) {
    use kinolab_widgets::open::{OpenedFile, deliver_dropped};
    let name = file
        .path()
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    #[cfg(target_arch = "wasm32")]
    {
        let ctx = ctx.clone();
        wasm_bindgen_futures::spawn_local(async move {
            match file.bytes_async().await {
                Ok(bytes) => deliver_dropped(&ctx, OpenedFile { name, bytes }),
                Err(e) => log::warn!("could not read {name}: {e}"),
            }
        });
    }
    #[cfg(not(target_arch = "wasm32"))]
    match file.bytes() {
        Ok(bytes) => deliver_dropped(ctx, OpenedFile { name, bytes }),
        Err(e) => log::warn!("could not read {name}: {e}"),
    }
}

/// Save a file a widget asked for.
fn save(file: &kinolab_widgets::export::SaveRequest) {
    #[cfg(target_arch = "wasm32")]
    if let Err(e) = crate::web::download(&file.name, &file.mime, &file.bytes) {
        log::warn!("could not download {}: {e:?}", file.name);
    }
    #[cfg(not(target_arch = "wasm32"))]
    if let Err(e) = std::fs::write(&file.name, &file.bytes) {
        log::warn!("could not save {}: {e}", file.name);
    }
}

/// Milliseconds since 1970 by the computer's clock.
#[cfg(not(target_arch = "wasm32"))]
fn native_now() -> u64 {
    std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_millis() as u64)
}

/// Set up the app for eframe: stored progress, the page the address names.
pub fn create(cc: &eframe::CreationContext<'_>, hash: &str) -> KinolabApp {
    #[cfg(target_arch = "wasm32")]
    let (stored, touch) = (crate::web::storage::load(), crate::web::touch_screen());
    #[cfg(not(target_arch = "wasm32"))]
    let (stored, touch) = (
        cc.storage.and_then(|s| s.get_string(progress::STORAGE_KEY)),
        false,
    );
    #[cfg(target_arch = "wasm32")]
    if crate::web::probing() {
        kinolab_widgets::probe::enable(&cc.egui_ctx);
    }
    let mut app = KinolabApp::new(stored.as_deref(), hash);
    app.install_style(&cc.egui_ctx);
    #[cfg(target_arch = "wasm32")]
    {
        if let (Some(text), Some(_)) = (&stored, app.notice()) {
            // Unreadable progress is set aside, not overwritten.
            crate::web::storage::set_aside(text);
        }
        crate::web::storage::listen(&cc.egui_ctx);
        crate::web::a11y::install(&cc.egui_ctx);
        crate::web::scripts::install();
    }
    #[cfg(not(target_arch = "wasm32"))]
    kinolab_widgets::code::runner::install(|| {
        Box::new(kinolab_widgets::code::runner::Threaded::default())
    });
    #[cfg(target_arch = "wasm32")]
    if crate::web::reduced_motion() {
        kinolab_widgets::theme::reduce_motion(&cc.egui_ctx);
    }
    if touch {
        // A finger drag over text scrolls from the very first touch.
        kinolab_widgets::theme::touch_first(&cc.egui_ctx);
        app.set_touch_screen(true);
    }
    app
}
