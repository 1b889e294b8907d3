//! Progress in the browser's local storage, shared by every tab of the lab.
//!
//! A tab that stores its progress first merges what is stored (another
//! tab may have written since), so nothing another tab did is overwritten;
//! the `storage` event brings another tab's writes into this one as they
//! happen. A browser that will not store (a private window, a full disk)
//! is told to the app once, which offers the progress file instead.

use std::cell::RefCell;

use crate::progress::{STORAGE_KEY, UNREADABLE_KEY};
use crate::shell::KinolabApp;

thread_local! {
    /// Progress other tabs stored since the last frame, oldest first.
    static FROM_OTHER_TABS: RefCell<Vec<String>> = const { RefCell::new(Vec::new()) };
    /// What this tab last stored: while the storage still holds it, no
    /// other tab has written and there is nothing to merge (a widget being
    /// dragged stores its state every frame).
    static LAST_STORED: RefCell<String> = const { RefCell::new(String::new()) };
}

fn storage() -> Result<web_sys::Storage, String> {
    let window = web_sys::window().ok_or("no window")?;
    match window.local_storage() {
        Ok(Some(storage)) => Ok(storage),
        Ok(None) => Err("no local storage".to_owned()),
        Err(e) => Err(format!("{e:?}")),
    }
}

/// The stored progress text, if any.
pub fn load() -> Option<String> {
    storage().ok()?.get_item(STORAGE_KEY).ok().flatten()
}

/// Keep progress that could not be read where a later version can find it.
pub fn set_aside(text: &str) {
    if let Ok(s) = storage() {
        let _ = s.set_item(UNREADABLE_KEY, text);
    }
}

/// Store the app's progress, merged with what other tabs stored; tell
/// the app if the browser refuses.
pub fn store(app: &mut KinolabApp) {
    if let Some(stored) = load()
        && LAST_STORED.with_borrow(|last| *last != stored)
    {
        app.merge_stored(&stored);
    }
    let json = app.progress_json();
    let written =
        storage().and_then(|s| s.set_item(STORAGE_KEY, &json).map_err(|e| format!("{e:?}")));
    match written {
        Ok(()) => LAST_STORED.set(json),
        Err(why) => {
            log::warn!("progress not stored: {why}");
            app.storage_failed();
        }
    }
}

/// Merge in what other tabs stored since the last frame.
pub fn take_other_tabs(app: &mut KinolabApp) {
    for text in FROM_OTHER_TABS.with_borrow_mut(std::mem::take) {
        app.merge_stored(&text);
    }
}

/// Listen for other tabs' writes; each wakes this tab for a frame.
pub fn listen(ctx: &egui::Context) {
    use wasm_bindgen::JsCast;
    use wasm_bindgen::closure::Closure;
    let Some(window) = web_sys::window() else {
        return;
    };
    let ctx = ctx.clone();
    let on_storage =
        Closure::<dyn FnMut(web_sys::StorageEvent)>::new(move |event: web_sys::StorageEvent| {
            if event.key().as_deref() == Some(STORAGE_KEY)
                && let Some(text) = event.new_value()
            {
                FROM_OTHER_TABS.with_borrow_mut(|pending| pending.push(text));
                ctx.request_repaint();
            }
        });
    let _ = window.add_event_listener_with_callback("storage", on_storage.as_ref().unchecked_ref());
    // One listener for the page's life.
    on_storage.forget();
}

/// The time now, milliseconds since 1970.
pub fn now() -> u64 {
    js_sys::Date::now().max(0.0) as u64
}
