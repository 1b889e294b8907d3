//! Who runs a learner's code for the code panel.
//!
//! A learner's script can be slow, or (whatever the sandbox bounds) bring
//! down what runs it, so the panel never runs it on the page's own thread
//! when it can help it: it hands a [`Job`] to a [`Runner`] and looks for
//! the answer each frame. The host chooses the runner with [`install`]: in
//! the browser a Web Worker with its own copy of the lab, natively a
//! thread. Without one (tests, tools) the job is done at once.

use kinolab_exercises::job::{Answer, Job, answer};

/// How a job ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Ran {
    Answered(Box<Answer>),
    /// The job was refused (an unknown exercise, a held-back world).
    Refused(String),
    /// What ran the code stopped: it crashed, or took far too long and
    /// was ended. The page goes on; a new runner starts for the next job.
    Crashed(String),
}

/// Runs jobs one at a time, off the page's thread where it can.
pub trait Runner {
    /// Start `job`; a job still under way is abandoned.
    fn start(&mut self, job: Job);
    /// The job's outcome, once it has one (then the runner is free).
    fn poll(&mut self) -> Option<Ran>;
    /// Abandon the job under way, ending whatever runs it if need be.
    fn stop(&mut self);
}

/// What makes a runner for each new code panel.
pub type Maker = fn() -> Box<dyn Runner>;

thread_local! {
    static MAKER: std::cell::Cell<Option<Maker>> = const { std::cell::Cell::new(None) };
}

/// Make every code panel from now on use runners made by `make`.
pub fn install(make: Maker) {
    MAKER.with(|m| m.set(Some(make)));
}

/// A runner for a new code panel: the installed kind, or [`AtOnce`].
pub(crate) fn runner() -> Box<dyn Runner> {
    MAKER.with(|m| m.get()).map_or_else(
        || Box::new(AtOnce::default()) as Box<dyn Runner>,
        |make| make(),
    )
}

/// A job's outcome from [`answer`].
pub fn outcome(job: &Job) -> Ran {
    match answer(job) {
        Ok(a) => Ran::Answered(Box::new(a)),
        Err(why) => Ran::Refused(why),
    }
}

/// Does each job as it is started, on the caller's thread.
#[derive(Debug, Default)]
pub struct AtOnce {
    done: Option<Ran>,
}

impl Runner for AtOnce {
    fn start(&mut self, job: Job) {
        self.done = Some(outcome(&job));
    }

    fn poll(&mut self) -> Option<Ran> {
        self.done.take()
    }

    fn stop(&mut self) {
        self.done = None;
    }
}

/// Does each job on a thread of its own (the native window). A stopped
/// job's thread runs on to its script's deadline; its answer is dropped.
#[cfg(not(target_arch = "wasm32"))]
#[derive(Debug, Default)]
pub struct Threaded {
    inbox: Option<std::sync::mpsc::Receiver<Ran>>,
}

#[cfg(not(target_arch = "wasm32"))]
impl Runner for Threaded {
    fn start(&mut self, job: Job) {
        let (send, inbox) = std::sync::mpsc::channel();
        let spawned = std::thread::Builder::new()
            .name("kinolab-script".into())
            // Learners' values may nest deep: room to spare.
            .stack_size(16 << 20)
            .spawn(move || {
                let _ = send.send(outcome(&job));
            });
        self.inbox = match spawned {
            Ok(_) => Some(inbox),
            Err(e) => {
                let (send, inbox) = std::sync::mpsc::channel();
                let _ = send.send(Ran::Crashed(format!("no thread to run the code on: {e}")));
                Some(inbox)
            }
        };
    }

    fn poll(&mut self) -> Option<Ran> {
        use std::sync::mpsc::TryRecvError;
        let inbox = self.inbox.as_ref()?;
        match inbox.try_recv() {
            Ok(ran) => {
                self.inbox = None;
                Some(ran)
            }
            Err(TryRecvError::Empty) => None,
            Err(TryRecvError::Disconnected) => {
                self.inbox = None;
                Some(Ran::Crashed("the thread running the code stopped".into()))
            }
        }
    }

    fn stop(&mut self) {
        self.inbox = None;
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use kinolab_exercises::job::Task;

    fn job() -> Job {
        let e = kinolab_exercises::find("control-park").unwrap();
        Job {
            exercise: e.id.into(),
            source: e.starter.into(),
            task: Task::Run { world: 0 },
        }
    }

    #[cfg(not(target_arch = "wasm32"))]
    #[test]
    fn a_thread_answers_what_doing_it_at_once_answers() {
        let mut at_once = AtOnce::default();
        at_once.start(job());
        let direct = at_once.poll().unwrap();
        let mut threaded = Threaded::default();
        threaded.start(job());
        let started = std::time::Instant::now();
        let answer = loop {
            if let Some(ran) = threaded.poll() {
                break ran;
            }
            assert!(started.elapsed().as_secs() < 60, "no answer");
            std::thread::sleep(std::time::Duration::from_millis(5));
        };
        assert_eq!(answer, direct);
        assert!(threaded.poll().is_none(), "one answer per job");
    }
}
