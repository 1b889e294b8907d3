//! The lessons and the fonts travel beside the wasm, not inside it: the page
//! preloads them while the wasm downloads, and the lab takes them over here
//! before it starts.

use wasm_bindgen::JsCast as _;
use wasm_bindgen_futures::JsFuture;

/// Fetch the lessons and the two fonts (all three at once) and hand them to
/// the crates that use them; what went wrong, in words.
pub async fn load() -> Result<(), String> {
    let window = web_sys::window().ok_or("the page has no window")?;
    let [lessons, sans, mono] = ["lessons.pack", "kinolab-sans.ttf", "kinolab-mono.ttf"]
        .map(|name| (name, window.fetch_with_str(name)));
    let lessons = bytes(lessons).await?;
    let (sans, mono) = (bytes(sans).await?, bytes(mono).await?);
    let files = kinolab_lessons::LessonFiles::unpack(&lessons).map_err(|e| e.to_string())?;
    kinolab_lessons::bundled::provide(files);
    kinolab_formula::layout::fonts::provide(sans, mono);
    Ok(())
}

/// A started fetch's body.
async fn bytes((name, fetch): (&str, js_sys::Promise)) -> Result<Vec<u8>, String> {
    let failed = |_| format!("{name} could not be fetched");
    let response: web_sys::Response = JsFuture::from(fetch)
        .await
        .map_err(failed)?
        .dyn_into()
        .map_err(failed)?;
    if !response.ok() {
        return Err(format!("{name}: the server answered {}", response.status()));
    }
    let body = JsFuture::from(response.array_buffer().map_err(failed)?)
        .await
        .map_err(failed)?;
    Ok(js_sys::Uint8Array::new(&body).to_vec())
}
