//! "Which pattern?": five requirements, each to be met with one of the six
//! patterns. Running a choice builds a small system with that pattern and
//! reports what happened; checking grades all five the same way.

use egui::RichText;
use kinolab_common::Feedback;
use kinolab_components::exercise::{CHOICES, REQUIREMENTS, Trial, trial, which_pattern};
use serde::{Deserialize, Serialize};

use crate::link::{self, Moment};
use crate::widget::{LabWidget, Params, feedback_ui};

/// The widget's name in the schema.
const NAME: &str = "which-pattern";

/// What the lesson sets and a link carries: the schema's parameters, a
/// pick per requirement (named by the requirement's id) and the task.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Settings {
    task: Option<Task>,
    bumper: Option<String>,
    scan: Option<String>,
    path: Option<String>,
    velocity: Option<String>,
    source: Option<String>,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
enum Task {
    Match,
}

/// The links of the first format: a pick per requirement, in order.
#[derive(Deserialize)]
struct Legacy(Vec<Option<String>>);

impl Settings {
    /// The pick for each requirement, in [`REQUIREMENTS`]' order.
    fn picks(&mut self) -> [&mut Option<String>; 5] {
        [
            &mut self.bumper,
            &mut self.scan,
            &mut self.path,
            &mut self.velocity,
            &mut self.source,
        ]
    }

    fn pick(&self, i: usize) -> Option<&str> {
        [
            &self.bumper,
            &self.scan,
            &self.path,
            &self.velocity,
            &self.source,
        ]
        .get(i)
        .and_then(|p| p.as_deref())
    }
}

struct WhichPattern {
    settings: Settings,
    initial: Settings,
    trials: Vec<Option<Trial>>,
    feedback: Option<Feedback>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    let settings: Settings = p.settings()?;
    Ok(Box::new(WhichPattern {
        initial: settings.clone(),
        settings,
        trials: vec![None; REQUIREMENTS.len()],
        feedback: None,
    }))
}

impl WhichPattern {
    fn requirement(&mut self, ui: &mut egui::Ui, i: usize) {
        let r = &REQUIREMENTS[i];
        ui.horizontal_wrapped(|ui| {
            ui.label(RichText::new(r.text).strong());
            let before = self.settings.pick(i).map(str::to_owned);
            let shown = before.clone().unwrap_or_else(|| "choose…".to_owned());
            let picks = self.settings.picks();
            let pick = &mut *picks[i];
            egui::ComboBox::new(ui.scope_id().with(i), "pattern")
                .selected_text(shown)
                .show_ui(ui, |ui| {
                    for c in CHOICES {
                        crate::widget::choose(ui, pick, Some(c.to_owned()), c);
                    }
                });
            if *pick != before {
                self.trials[i] = None;
                self.feedback = None;
            }
            let pick = pick.clone();
            if ui
                .add_enabled(pick.is_some(), egui::Button::new("Run"))
                .clicked()
                && let Some(c) = pick
            {
                self.trials[i] = trial(r.id, &c).ok();
            }
        });
        if let Some(t) = &self.trials[i] {
            let (mark, color) = if t.works {
                ("works", crate::theme::good_color(ui))
            } else {
                ("does not do the job", crate::theme::error_color(ui))
            };
            ui.label(RichText::new(format!("{mark}: {}", t.note)).color(color));
        }
    }
}

impl LabWidget for WhichPattern {
    /// Each need's pattern (or that none is chosen yet), and how the runs
    /// so far went.
    fn describe(&self) -> Option<String> {
        let picks: Vec<String> = REQUIREMENTS
            .iter()
            .enumerate()
            .map(|(i, r)| {
                format!(
                    "{}: {}",
                    r.id,
                    self.settings.pick(i).unwrap_or("not chosen")
                )
            })
            .collect();
        let runs: Vec<&Trial> = self.trials.iter().flatten().collect();
        let works = runs.iter().filter(|t| t.works).count();
        let chosen = (0..REQUIREMENTS.len())
            .filter(|&i| self.settings.pick(i).is_some())
            .count();
        Some(format!(
            "Patterns chosen for {chosen} of {} needs ({}). {} run{} so far, {works} that work{}.",
            REQUIREMENTS.len(),
            picks.join("; "),
            runs.len(),
            if runs.len() == 1 { "" } else { "s" },
            if works == 1 { "s" } else { "" }
        ))
    }

    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.label("Pick a pattern for each need, then run it: the lab builds a small system with that pattern and reports what happened.");
        for i in 0..REQUIREMENTS.len() {
            ui.separator();
            self.requirement(ui, i);
        }
        if self.settings.task == Some(Task::Match) {
            ui.separator();
            if ui.button("Check").clicked() {
                let chosen: Vec<(&str, &str)> = REQUIREMENTS
                    .iter()
                    .enumerate()
                    .filter_map(|(i, r)| self.settings.pick(i).map(|p| (r.id, p)))
                    .collect();
                self.feedback = Some(which_pattern(&chosen));
            }
            feedback_ui(ui, self.feedback.as_ref());
        }
    }

    fn state(&self) -> Option<String> {
        link::write(
            NAME,
            &self.settings,
            &self.initial,
            &Moment::<()>::default(),
        )
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        let settings = match link::read::<Settings, ()>(NAME, state) {
            Ok((settings, _)) => settings,
            Err(why) => {
                let Some(Legacy(old)) = link::decode::<Legacy>(state) else {
                    return Err(why);
                };
                if old.len() != REQUIREMENTS.len() {
                    return Err(why);
                }
                let mut settings = self.initial.clone();
                for (pick, old) in settings.picks().into_iter().zip(old) {
                    *pick = old;
                }
                settings
            }
        };
        // The old format's picks pass through the schema's choices too.
        link::check(NAME, &settings)?;
        // A link is written only when something changed: one holding the
        // lesson's own settings is not one of this widget's.
        if settings == self.initial {
            return Err("it holds nothing this widget would change".into());
        }
        self.settings = settings;
        self.trials = vec![None; REQUIREMENTS.len()];
        self.feedback = None;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::{create, spec};

    fn widget(params: &[(&str, &str)]) -> WhichPattern {
        let p = kinolab_schema::validate(&spec(NAME, params)).unwrap_or_else(|e| panic!("{e}"));
        let settings: Settings = p.settings().unwrap_or_else(|e| panic!("{e}"));
        WhichPattern {
            initial: settings.clone(),
            settings,
            trials: vec![None; REQUIREMENTS.len()],
            feedback: None,
        }
    }

    #[test]
    fn the_picks_are_the_requirements_and_the_choices_are_the_cores() {
        let ids: Vec<&str> = REQUIREMENTS.iter().map(|r| r.id).collect();
        assert_eq!(ids, ["bumper", "scan", "path", "velocity", "source"]);
        for c in CHOICES {
            assert!(create(&spec(NAME, &[("scan", c)])).is_ok(), "{c}");
        }
        assert!(create(&spec(NAME, &[("scan", "telepathy")])).is_err());
    }

    #[test]
    fn a_link_of_the_first_format_still_opens() {
        let picks = [None, Some("push-timed"), None, Some("send"), None];
        let old = link::encode(&picks.to_vec()).unwrap_or_default();
        let mut w = widget(&[("task", "match")]);
        assert_eq!(w.restore(&old), Ok(()));
        assert_eq!(w.settings.scan.as_deref(), Some("push-timed"));
        assert_eq!(w.settings.velocity.as_deref(), Some("send"));
        assert_eq!(w.settings.task, Some(Task::Match));
        // A pick that is no pattern: refused, the lesson's settings kept.
        let bad = [None, Some("telepathy"), None, None, None];
        let mut w = widget(&[("bumper", "event")]);
        assert!(
            w.restore(&link::encode(&bad.to_vec()).unwrap_or_default())
                .is_err()
        );
        assert_eq!(w.settings.bumper.as_deref(), Some("event"));
        assert_eq!(w.settings.scan, None);
    }

    #[test]
    fn the_picks_travel_in_the_link() {
        let mut w = widget(&[]);
        w.settings.path = Some("query".into());
        let text = w.state().unwrap_or_default();
        let mut again = widget(&[]);
        assert_eq!(again.restore(&text), Ok(()));
        assert_eq!(again.settings, w.settings);
    }
}
