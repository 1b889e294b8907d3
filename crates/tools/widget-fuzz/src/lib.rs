//! Every widget fed link states a learner's browser might hand it: valid
//! ones, and ones cut short, altered, of the first format, with hostile
//! values, unknown keys and damaged instants (see [`generate`]).
//!
//! A case passes when the widget neither panics nor takes longer than the
//! frame limit to take the state and draw its frame, and when it ends in a
//! state it can stand behind: a refused link leaves the widget as the
//! lesson set it up (no state of its own), and an accepted one gives back a
//! state that a fresh widget accepts and gives back unchanged.

pub mod generate;

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::time::{Duration, Instant};

use kinolab_widgets::LabWidget;
use kinolab_widgets::registry;

pub use generate::{DAMAGES, Damage, Rng};

/// The longest a widget may take to take a state and draw a frame.
pub const FRAME_LIMIT: Duration = Duration::from_millis(50);

/// What one case did.
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome {
    /// The widget took the state.
    pub accepted: bool,
    /// Why not, when it did not.
    pub refusal: Option<String>,
    pub elapsed: Duration,
}

/// Draws widgets in one egui context with the lab's fonts and styles,
/// its memory cleared between cases.
#[derive(Debug)]
pub struct Stage {
    ctx: egui::Context,
}

impl Default for Stage {
    fn default() -> Self {
        let ctx = egui::Context::default();
        kinolab_widgets::theme::install(&ctx);
        let stage = Self { ctx };
        // Fonts and styles take effect from the next frame.
        stage.frame(|_| {});
        stage
    }
}

impl Stage {
    fn frame(&self, add: impl FnMut(&mut egui::Ui)) {
        let input = egui::RawInput {
            screen_rect: Some(egui::Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(1024.0, 768.0),
            )),
            ..Default::default()
        };
        // Nothing is painted: the textures made are dropped on purpose.
        self.ctx.run_ui(input, add).textures_delta.clear();
    }

    /// Feed `state` to a fresh `widget` (built as a lesson block with no
    /// lines builds it) and draw one frame; a failure says what went wrong.
    pub fn check(
        &self,
        widget: &str,
        state: &str,
        limit: Option<Duration>,
    ) -> Result<Outcome, String> {
        self.ctx.memory_mut(|m| *m = Default::default());
        let started = Instant::now();
        let run = catch_unwind(AssertUnwindSafe(|| -> Result<Outcome, String> {
            let mut w = fresh(widget)?;
            let refusal = w.restore(state).err();
            let accepted = refusal.is_none();
            let kept = w.state();
            self.frame(|ui| w.ui(ui));
            let elapsed = started.elapsed();
            if !accepted && kept != fresh(widget)?.state() {
                return Err(format!(
                    "refused the link but did not stay as set up: {kept:?}"
                ));
            }
            if let Some(kept) = kept {
                round_trip(widget, &kept)?;
            }
            Ok(Outcome {
                accepted,
                refusal,
                elapsed,
            })
        }));
        let outcome = run.map_err(|panic| format!("panicked: {}", panic_text(&panic)))??;
        match limit {
            Some(limit) if outcome.elapsed > limit => Err(format!(
                "took {:.1} ms to take the link and draw (the limit is {} ms)",
                outcome.elapsed.as_secs_f64() * 1e3,
                limit.as_millis()
            )),
            _ => Ok(outcome),
        }
    }
}

fn fresh(widget: &str) -> Result<Box<dyn LabWidget>, String> {
    registry::create(&registry::spec(widget, &[])).map_err(|e| format!("does not build: {e}"))
}

/// A state the widget gave is one a fresh widget takes, and what that
/// widget gives back a third takes and gives back unchanged. (One reading
/// may settle the instant on a tick of the run, or show an instant a
/// replay is still running on to.)
fn round_trip(widget: &str, state: &str) -> Result<(), String> {
    let read = |text: &str| -> Result<Option<String>, String> {
        let mut w = fresh(widget)?;
        w.restore(text)
            .map_err(|e| format!("refused its own state `{text}`: {e}"))?;
        Ok(w.state())
    };
    let once = read(state)?;
    if once.as_deref() == Some(state) {
        return Ok(());
    }
    let Some(once) = once else {
        return Err(format!("its state `{state}` came back as none"));
    };
    match read(&once)? {
        Some(twice) if twice == once => Ok(()),
        other => Err(format!("its state `{once}` came back as {other:?}")),
    }
}

fn panic_text(panic: &Box<dyn std::any::Any + Send>) -> String {
    panic
        .downcast_ref::<String>()
        .cloned()
        .or_else(|| panic.downcast_ref::<&str>().map(|s| (*s).to_owned()))
        .unwrap_or_else(|| "(no message)".to_owned())
}

/// Every widget the registry builds, by name.
pub fn widgets() -> Vec<&'static str> {
    registry::CONSTRUCTORS
        .iter()
        .map(|(name, _)| *name)
        .collect()
}

/// One failing case, with what reproduces it.
#[derive(Debug, Clone)]
pub struct Failure {
    pub widget: &'static str,
    pub damage: Damage,
    pub state: String,
    pub why: String,
}

/// Counts per widget and damage, and the failures.
#[derive(Debug, Default)]
pub struct Tally {
    pub cases: usize,
    pub accepted: usize,
    pub slowest: Duration,
    pub slowest_widget: &'static str,
    pub failures: Vec<Failure>,
}

/// Run `cases` cases from `seed`, the widgets and damages in turn.
pub fn campaign(seed: u64, cases: usize, limit: Option<Duration>) -> Tally {
    let stage = Stage::default();
    let mut rng = Rng::new(seed);
    let names = widgets();
    let mut tally = Tally::default();
    for k in 0..cases {
        let widget = names[k % names.len()];
        let damage = DAMAGES[(k / names.len()) % DAMAGES.len()];
        let Some(schema) = kinolab_schema::find(widget) else {
            continue;
        };
        let state = generate::state(&mut rng, schema, damage);
        tally.cases += 1;
        match stage.check(widget, &state, limit) {
            Ok(outcome) => {
                tally.accepted += usize::from(outcome.accepted);
                if outcome.elapsed > tally.slowest {
                    (tally.slowest, tally.slowest_widget) = (outcome.elapsed, widget);
                }
            }
            Err(why) => tally.failures.push(Failure {
                widget,
                damage,
                state,
                why,
            }),
        }
    }
    tally
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The test command's share of the campaign: every widget with every
    /// kind of damage, twice, with no frame limit (a debug build is ten
    /// times slower than the lab; `cargo xtask fuzz` times the release).
    #[test]
    fn a_seeded_set_of_links_never_breaks_a_widget() {
        let cases = 2 * widgets().len() * DAMAGES.len();
        let tally = campaign(7, cases, None);

        assert_eq!(tally.cases, cases);
        let failures: Vec<String> = tally
            .failures
            .iter()
            .map(|f| format!("{} ({:?}): {}", f.widget, f.damage, f.why))
            .collect();
        assert!(failures.is_empty(), "{failures:#?}");
        // Valid links are taken, damaged ones mostly refused.
        assert!(tally.accepted > widgets().len() / 2, "{}", tally.accepted);
        assert!(tally.accepted < cases / 2, "{}", tally.accepted);
    }

    #[test]
    fn a_damaged_link_leaves_the_widget_as_set_up_and_a_good_one_is_taken() {
        let stage = Stage::default();
        let schema = kinolab_schema::find("leg-events").unwrap_or_else(|| panic!("no schema"));
        assert!(!schema.params.is_empty());
        let good = generate::link(&[("legs".into(), "5".into())]);
        let taken = stage.check("leg-events", &good, None);
        assert!(taken.as_ref().is_ok_and(|o| o.accepted), "{taken:?}");
        let cut = &good[..good.len() - 3];
        let refused = stage.check("leg-events", cut, None);
        assert!(refused.as_ref().is_ok_and(|o| !o.accepted), "{refused:?}");
    }
}
