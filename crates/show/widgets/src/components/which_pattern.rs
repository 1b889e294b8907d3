//! "Which pattern?": five requirements, each to be met with one of the six
//! patterns. Running a choice builds a small system with that pattern and
//! reports what happened; checking grades all five the same way.

use egui::RichText;
use kinolab_common::Feedback;
use kinolab_components::exercise::{CHOICES, REQUIREMENTS, Trial, trial, which_pattern};
use serde::{Deserialize, Serialize};

use crate::link;
use crate::widget::{LabWidget, Params, feedback_ui};

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct Picks(Vec<Option<String>>);

struct WhichPattern {
    picks: Picks,
    trials: Vec<Option<Trial>>,
    task: bool,
    feedback: Option<Feedback>,
}

pub fn create(p: &Params) -> Result<Box<dyn LabWidget>, String> {
    Ok(Box::new(WhichPattern {
        picks: Picks(vec![None; REQUIREMENTS.len()]),
        trials: vec![None; REQUIREMENTS.len()],
        task: p.choice("task") == Some("match"),
        feedback: None,
    }))
}

impl LabWidget for WhichPattern {
    fn ui(&mut self, ui: &mut egui::Ui) {
        ui.label("Pick a pattern for each need, then run it: the lab builds a small system with that pattern and reports what happened.");
        for (i, r) in REQUIREMENTS.iter().enumerate() {
            ui.separator();
            ui.horizontal_wrapped(|ui| {
                ui.label(RichText::new(r.text).strong());
                let before = self.picks.0[i].clone();
                let shown = before.clone().unwrap_or_else(|| "choose…".to_owned());
                egui::ComboBox::new(ui.scope_id().with(i), "pattern")
                    .selected_text(shown)
                    .show_ui(ui, |ui| {
                        for c in CHOICES {
                            ui.selectable_value(&mut self.picks.0[i], Some(c.to_owned()), c);
                        }
                    });
                if self.picks.0[i] != before {
                    self.trials[i] = None;
                    self.feedback = None;
                }
                let pick = self.picks.0[i].clone();
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
        if self.task {
            ui.separator();
            if ui.button("Check").clicked() {
                let chosen: Vec<(&str, &str)> = REQUIREMENTS
                    .iter()
                    .zip(&self.picks.0)
                    .filter_map(|(r, p)| p.as_deref().map(|p| (r.id, p)))
                    .collect();
                self.feedback = Some(which_pattern(&chosen));
            }
            feedback_ui(ui, self.feedback.as_ref());
        }
    }

    fn state(&self) -> Option<String> {
        self.picks
            .0
            .iter()
            .any(Option::is_some)
            .then(|| link::encode(&self.picks))
            .flatten()
    }

    fn restore(&mut self, state: &str) -> Result<(), String> {
        if let Some(p) = link::decode::<Picks>(state)
            && p.0.len() == REQUIREMENTS.len()
            && p.0.iter().flatten().all(|c| CHOICES.contains(&c.as_str()))
        {
            self.picks = p;
        }
        Ok(())
    }
}
