//! Learners' code runs in a Web Worker with its own instance of the lab's
//! WebAssembly, never on the page's thread: a run that takes seconds
//! leaves the page responsive, the Stop button ends it, and a run that
//! traps, overflows the stack or hangs ends only that worker. The next
//! run starts a fresh one.
//!
//! The worker (`web/script-worker.js`) is handed the module the page has
//! already compiled, so nothing is downloaded twice, and the address of
//! the page's JavaScript glue, which it imports to instantiate the module;
//! it calls [`kinolab_script_job`] with each job.

use std::cell::RefCell;
use std::rc::Rc;

use kinolab_exercises::job::{Job, read_reply};
use kinolab_widgets::code::runner::{Ran, Runner};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::{Closure, JsValue, wasm_bindgen};

/// The worker's script, beside the page.
const WORKER: &str = "script-worker.js";
/// A job that has not answered after this long is ended. The sandbox ends
/// a run after 5 s of the learner's code; an exercise has at most six
/// worlds, and a slow phone runs several times slower than a desktop.
const PATIENCE_MS: f64 = 90_000.0;

/// Run one job (a [`Job`] as JSON) and answer it as JSON: what the worker
/// calls. The sandbox's deadlines need a clock, which WebAssembly lacks.
#[wasm_bindgen]
pub fn kinolab_script_job(job: &str) -> String {
    kinolab_script::clock::install(|| js_sys::Date::now() / 1000.0);
    kinolab_exercises::job::answer_json(job)
}

/// Make every code panel run its code in a worker.
pub fn install() {
    kinolab_widgets::code::runner::install(|| Box::new(WorkerRunner::default()));
}

/// A worker, made when the first job comes, kept for the jobs after it.
#[derive(Default)]
struct WorkerRunner {
    live: Option<Live>,
    /// When the job under way started, ms.
    started: Option<f64>,
    /// A job that could not even be sent, and why.
    unsent: Option<String>,
}

struct Live {
    worker: web_sys::Worker,
    inbox: Rc<RefCell<Option<Ran>>>,
    _on_message: Closure<dyn FnMut(web_sys::MessageEvent)>,
    _on_error: Closure<dyn FnMut(web_sys::ErrorEvent)>,
}

impl Drop for Live {
    fn drop(&mut self) {
        self.worker.terminate();
    }
}

impl Runner for WorkerRunner {
    fn start(&mut self, job: Job) {
        if self.started.is_some() {
            // A job still under way is abandoned with its worker.
            self.live = None;
        }
        self.started = Some(js_sys::Date::now());
        let sent = serde_json::to_string(&job)
            .map_err(|e| e.to_string())
            .and_then(|job| self.send(&job));
        if let Err(why) = sent {
            self.live = None;
            self.unsent = Some(why);
        }
    }

    fn poll(&mut self) -> Option<Ran> {
        let started = self.started?;
        let ran = match self.unsent.take() {
            Some(why) => Some(Ran::Crashed(format!("the runner could not start: {why}"))),
            None => self.live.as_ref().and_then(|l| l.inbox.take()),
        };
        let ran = match ran {
            Some(ran) => ran,
            None if js_sys::Date::now() - started > PATIENCE_MS => {
                Ran::Crashed("the run took far too long and was ended".into())
            }
            None if self.live.is_none() => Ran::Crashed("the runner could not start".into()),
            None => return None,
        };
        self.started = None;
        if matches!(ran, Ran::Crashed(_)) {
            // Whatever state the crash left it in, it is not used again.
            self.live = None;
        }
        Some(ran)
    }

    fn stop(&mut self) {
        self.started = None;
        self.unsent = None;
        self.live = None;
    }
}

impl WorkerRunner {
    /// The live worker, made if there is none.
    fn worker(&mut self) -> Option<&Live> {
        if self.live.is_none() {
            self.live = spawn().ok();
        }
        self.live.as_ref()
    }

    /// Post `job` (JSON) with the module and the glue's address.
    fn send(&mut self, job: &str) -> Result<(), String> {
        let glue = glue_url().ok_or("the page's script was not found")?;
        let live = self.worker().ok_or("no worker could be started")?;
        let message = js_sys::Object::new();
        let set = |key: &str, value: &JsValue| {
            js_sys::Reflect::set(&message, &key.into(), value).map(|_| ())
        };
        set("glue", &glue.into())
            .and_then(|()| set("module", &wasm_bindgen::module()))
            .and_then(|()| set("job", &job.into()))
            .and_then(|()| live.worker.post_message(&message))
            .map_err(|e| format!("{e:?}"))
    }
}

/// A worker whose answers land in its inbox.
fn spawn() -> Result<Live, JsValue> {
    let options = web_sys::WorkerOptions::new();
    options.set_type(web_sys::WorkerType::Module);
    let worker = web_sys::Worker::new_with_options(WORKER, &options)?;
    let inbox: Rc<RefCell<Option<Ran>>> = Rc::default();
    let to = inbox.clone();
    let on_message =
        Closure::<dyn FnMut(web_sys::MessageEvent)>::new(move |e: web_sys::MessageEvent| {
            to.replace(Some(read(&e.data())));
        });
    let to = inbox.clone();
    let on_error = Closure::<dyn FnMut(web_sys::ErrorEvent)>::new(move |e: web_sys::ErrorEvent| {
        // Handled here: not an error of the page's.
        e.prevent_default();
        to.replace(Some(Ran::Crashed(e.message())));
    });
    worker.set_onmessage(Some(on_message.as_ref().unchecked_ref()));
    worker.set_onerror(Some(on_error.as_ref().unchecked_ref()));
    Ok(Live {
        worker,
        inbox,
        _on_message: on_message,
        _on_error: on_error,
    })
}

/// The worker's message: `{ answer }` (the job's JSON reply) or `{ crashed }`.
fn read(data: &JsValue) -> Ran {
    let field = |key: &str| {
        js_sys::Reflect::get(data, &key.into())
            .ok()
            .and_then(|v| v.as_string())
    };
    if let Some(reply) = field("answer") {
        return match read_reply(&reply) {
            Ok(answer) => Ran::Answered(Box::new(answer)),
            Err(why) => Ran::Refused(why),
        };
    }
    Ran::Crashed(field("crashed").unwrap_or_else(|| "the runner answered nothing".into()))
}

/// The address of the page's JavaScript glue: the module Trunk preloads
/// (its name carries the build's hash).
fn glue_url() -> Option<String> {
    let document = web_sys::window()?.document()?;
    let link = document
        .query_selector("link[rel=modulepreload][href$='.js']")
        .ok()
        .flatten()?;
    js_sys::Reflect::get(&link, &"href".into())
        .ok()?
        .as_string()
}
