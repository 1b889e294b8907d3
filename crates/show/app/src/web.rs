//! The browser side: the URL hash, the page title, browser storage, and
//! the signals the end-to-end test and the page shell read.

use std::cell::RefCell;

use crate::route::Page;
use crate::shell::KinolabApp;

pub mod a11y;
pub mod assets;
pub mod scripts;
pub mod storage;

/// How many recent frames' CPU times are kept for the benchmark.
const FRAME_HISTORY: usize = 2000;

thread_local! {
    /// CPU milliseconds of recent frames (logic and painting), oldest first.
    static FRAME_MS: RefCell<std::collections::VecDeque<f32>> =
        const { RefCell::new(std::collections::VecDeque::new()) };
    /// The hash the app last acted on.
    static LAST_HASH: RefCell<Option<String>> = const { RefCell::new(None) };
    /// What the DOM signals last said, so they are written only on change.
    static LAST_SIGNAL: RefCell<String> = const { RefCell::new(String::new()) };
}

fn window() -> Option<web_sys::Window> {
    web_sys::window()
}

/// Whether the page was opened with `?probe` (a browser test that needs
/// the widgets' named points).
pub fn probing() -> bool {
    window()
        .and_then(|w| w.location().search().ok())
        .is_some_and(|s| s.split(['?', '&']).any(|p| p == "probe"))
}

/// Whether the device has a touch screen (a phone, a tablet).
pub fn touch_screen() -> bool {
    window().is_some_and(|w| w.navigator().max_touch_points() > 0)
}

/// Whether the learner asked the system for less motion.
pub fn reduced_motion() -> bool {
    window()
        .and_then(|w| {
            w.match_media("(prefers-reduced-motion: reduce)")
                .ok()
                .flatten()
        })
        .is_some_and(|m| m.matches())
}

/// The browser's current hash, read fresh (not eframe's copy, which lags
/// one event behind our own changes).
pub fn current_hash() -> String {
    window()
        .and_then(|w| w.location().hash().ok())
        .unwrap_or_default()
}

/// The CPU time of the frames drawn since the last call, in milliseconds
/// (`window.wasmBindings.kinolab_frame_times()`, read by `cargo xtask bench`).
#[wasm_bindgen::prelude::wasm_bindgen]
pub fn kinolab_frame_times() -> Vec<f32> {
    FRAME_MS.with_borrow_mut(|f| f.drain(..).collect())
}

/// The size of the lab's wasm memory in bytes: its heap, stack and data
/// (`window.wasmBindings.kinolab_heap_bytes()`, read by `cargo xtask bench`).
#[wasm_bindgen::prelude::wasm_bindgen]
pub fn kinolab_heap_bytes() -> f64 {
    (core::arch::wasm32::memory_size(0) * 65536) as f64
}

/// Follow the back and forward buttons and edited URLs; note the last
/// frame's CPU time.
pub fn before_frame(app: &mut KinolabApp, frame: &eframe::Frame) {
    app.set_clock(storage::now());
    storage::take_other_tabs(app);
    if let Some(seconds) = frame.info().cpu_usage {
        FRAME_MS.with_borrow_mut(|f| {
            if f.len() == FRAME_HISTORY {
                f.pop_front();
            }
            f.push_back(seconds * 1000.0);
        });
    }
    let hash = current_hash();
    let changed = LAST_HASH.with_borrow(|last| last.as_deref() != Some(hash.as_str()));
    if changed {
        if LAST_HASH.with_borrow(|last| last.is_some()) || Page::from_hash(&hash) != *app.page() {
            app.follow_hash(&hash);
        }
        LAST_HASH.set(Some(hash));
    }
}

/// Push the app's navigation to the URL, store progress, update signals.
pub fn after_frame(app: &mut KinolabApp) {
    if let Some(hash) = app.take_pending_hash() {
        if let Some(w) = window()
            && current_hash() != hash
        {
            let _ = w.location().set_hash(&hash);
        }
        LAST_HASH.set(Some(current_hash()));
    }
    if let Some(hash) = app.take_state_hash()
        && current_hash() != hash
        && let Some(w) = window()
        && let Ok(history) = w.history()
    {
        // Replace, not push: dragging a wheel must not fill the back button.
        let _ = history.replace_state_with_url(&wasm_bindgen::JsValue::NULL, "", Some(&hash));
        LAST_HASH.set(Some(current_hash()));
    }
    if app.take_dirty_progress().is_some() {
        storage::store(app);
    }
    let page = app.page().address();
    if app.frames_drawn() == 0 {
        return;
    }
    let (right, screen) = app.extent();
    let extent = format!("{right:.0} {screen:.0}");
    let notice = app.notice().unwrap_or_default().to_owned();
    let opened = app.progress().visited.len().to_string();
    let complete = app.page_complete();
    let signal = format!(
        "{page}|{}|{extent}|{}|{notice}|{opened}|{complete}",
        app.title(),
        app.points()
    );
    if LAST_SIGNAL.with_borrow(|last| *last != signal) {
        if let Some(document) = window().and_then(|w| w.document()) {
            document.set_title(&app.title());
            if let Some(root) = document.document_element() {
                let _ = root.set_attribute("data-kinolab-page", &page);
                // Where the page's content ends and where the screen does.
                let _ = root.set_attribute("data-kinolab-extent", &extent);
                // Where the widgets' named points are (for browser tests).
                let _ = root.set_attribute("data-kinolab-points", app.points());
                // The line over the page, and how many lessons were opened
                // (what another tab's progress changes).
                let _ = root.set_attribute("data-kinolab-notice", &notice);
                let _ = root.set_attribute("data-kinolab-opened", &opened);
                if root.get_attribute("data-kinolab-first-frame-ms").is_none() {
                    // Milliseconds from navigation to the first drawn frame.
                    let now = window()
                        .and_then(|w| w.performance())
                        .map_or(0.0, |p| p.now());
                    let _ = root.set_attribute("data-kinolab-first-frame-ms", &format!("{now:.1}"));
                    if let Some(loading) = document.get_element_by_id("kinolab-loading") {
                        loading.remove();
                    }
                }
                // Ready once a frame laid out the whole page (the first
                // lays out a screenful).
                if complete {
                    let _ = root.set_attribute("data-kinolab-ready", "1");
                }
            }
        }
        LAST_SIGNAL.set(signal);
    }
}

/// Offer `bytes` to the learner as a file download.
pub fn download(name: &str, mime: &str, bytes: &[u8]) -> Result<(), wasm_bindgen::JsValue> {
    use wasm_bindgen::JsCast;
    let array = js_sys::Uint8Array::from(bytes);
    let parts = js_sys::Array::of1(&array);
    let options = web_sys::BlobPropertyBag::new();
    options.set_type(mime);
    let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &options)?;
    let url = web_sys::Url::create_object_url_with_blob(&blob)?;
    let document = window().and_then(|w| w.document()).ok_or("no document")?;
    let a: web_sys::HtmlAnchorElement = document.create_element("a")?.dyn_into()?;
    a.set_href(&url);
    a.set_download(name);
    a.click();
    web_sys::Url::revoke_object_url(&url)?;
    Ok(())
}

/// Show a readable message over the canvas (start failures and panics).
pub fn show_fatal(message: &str) {
    let Some(document) = window().and_then(|w| w.document()) else {
        return;
    };
    if let Some(element) = document.get_element_by_id("kinolab-error") {
        element.set_text_content(Some(message));
        let _ = element.set_attribute("style", "display:block");
    }
    if let Some(loading) = document.get_element_by_id("kinolab-loading") {
        loading.remove();
    }
}

/// Open the browser's file dialog for a widget; the chosen file's bytes go
/// back to it through [`kinolab_widgets::open::deliver`].
pub fn pick(
    ctx: &egui::Context,
    request: kinolab_widgets::open::PickRequest,
) -> Result<(), wasm_bindgen::JsValue> {
    use wasm_bindgen::JsCast;
    use wasm_bindgen::closure::Closure;
    let document = window().and_then(|w| w.document()).ok_or("no document")?;
    let input: web_sys::HtmlInputElement = document.create_element("input")?.dyn_into()?;
    input.set_type("file");
    input.set_accept(&request.accept);
    let chosen = input.clone();
    let ctx = ctx.clone();
    let on_change = Closure::once(move || {
        let Some(file) = chosen.files().and_then(|list| list.get(0)) else {
            return;
        };
        wasm_bindgen_futures::spawn_local(async move {
            let Ok(buffer) = wasm_bindgen_futures::JsFuture::from(file.array_buffer()).await else {
                log::warn!("could not read {}", file.name());
                return;
            };
            let bytes = js_sys::Uint8Array::new(&buffer).to_vec();
            let opened = kinolab_widgets::open::OpenedFile {
                name: file.name(),
                bytes,
            };
            kinolab_widgets::open::deliver(&ctx, request.widget, opened);
        });
    });
    input.set_onchange(Some(on_change.as_ref().unchecked_ref()));
    // The dialog may stay open for minutes: the closure lives as long as
    // the page (one small closure per dialog opened).
    on_change.forget();
    input.click();
    Ok(())
}
