//! Starts the lab: in a native window, or on the web page's canvas.

#[cfg(not(target_arch = "wasm32"))]
fn main() -> eframe::Result {
    env_logger::init();
    // An optional lesson address opens that lesson: `kinolab-lab automation/ways-to-move`.
    let hash = std::env::args()
        .nth(1)
        .map(|a| format!("#/{a}"))
        .unwrap_or_default();
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_inner_size([1280.0, 800.0])
            .with_min_inner_size([800.0, 560.0])
            .with_title("Kinolab"),
        ..Default::default()
    };
    eframe::run_native(
        "kinolab",
        options,
        Box::new(move |cc| Ok(Box::new(kinolab_app::window::create(cc, &hash)))),
    )
}

#[cfg(target_arch = "wasm32")]
fn main() {
    use wasm_bindgen::JsCast as _;

    // In the worker that runs learners' code (see `web::scripts`) there is
    // no page: the module is there only for its exported functions.
    if web_sys::window().is_none() {
        return;
    }
    eframe::WebLogger::init(log::LevelFilter::Warn).ok();
    let runner = eframe::WebRunner::new();
    // eframe installed its panic hook; add ours on top so a panic is shown
    // on the page, not only in the console.
    let previous = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        previous(info);
        kinolab_app::web::show_fatal(&format!(
            "Kinolab stopped because of an internal error. Reload the page to continue.\n\n{info}"
        ));
    }));
    wasm_bindgen_futures::spawn_local(async move {
        let Some(document) = web_sys::window().and_then(|w| w.document()) else {
            return;
        };
        let Some(canvas) = document
            .get_element_by_id("kinolab-canvas")
            .and_then(|c| c.dyn_into::<web_sys::HtmlCanvasElement>().ok())
        else {
            kinolab_app::web::show_fatal("The page has no canvas with id kinolab-canvas.");
            return;
        };
        if let Err(e) = kinolab_app::web::assets::load().await {
            kinolab_app::web::show_fatal(&format!(
                "Kinolab could not load its lessons: {e}. Check your connection, then reload the page."
            ));
            return;
        }
        let hash = kinolab_app::web::current_hash();
        let result = runner
            .start(
                canvas,
                eframe::WebOptions::default(),
                Box::new(move |cc| Ok(Box::new(kinolab_app::window::create(cc, &hash)))),
            )
            .await;
        match result {
            Ok(()) => {
                // The message stays until the first frame is drawn
                // (`web::after_frame` removes it); until then, say where we are.
                if let Some(loading) = document.get_element_by_id("kinolab-loading") {
                    loading.set_text_content(Some("Drawing the first page…"));
                }
            }
            Err(e) => kinolab_app::web::show_fatal(&format!(
                "Kinolab could not start: {e:?}. It needs a browser with WebGL 2."
            )),
        }
    });
}
