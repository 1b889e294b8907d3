//! The learner's progress on screen: the card on the start page (save it
//! as a file, load one, lessons that were retired), the notice line over
//! the page, and progress arriving from another tab.

use std::collections::BTreeSet;

use egui::RichText;
use kinolab_widgets::{open, probe, theme};

use super::KinolabApp;
use crate::progress::{Progress, file};

/// A line over the page for the learner.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Notice {
    pub text: String,
    /// Something went wrong (drawn in the error colour).
    pub problem: bool,
    /// Offer the progress file beside it (storage does not work).
    pub offer_file: bool,
}

impl Notice {
    pub fn problem(text: String) -> Self {
        Self {
            text,
            problem: true,
            offer_file: false,
        }
    }

    fn news(text: String) -> Self {
        Self {
            text,
            problem: false,
            offer_file: false,
        }
    }
}

/// The id the progress file's dialog delivers to.
fn picker() -> egui::Id {
    egui::Id::unique("kinolab-progress-file")
}

impl KinolabApp {
    /// Progress another tab stored: merged in, nothing overwritten.
    pub fn merge_stored(&mut self, text: &str) {
        if let (theirs, None) = Progress::restore(Some(text)) {
            let before = self.progress.dark;
            self.progress.merge(&theirs);
            self.theme_changed |= before != self.progress.dark;
        }
    }

    /// The browser would not store progress (a private window, a full
    /// disk): say so once and offer the file instead.
    pub fn storage_failed(&mut self) {
        if !std::mem::replace(&mut self.storage_blocked, true) {
            self.notice = Some(Notice {
                text: "This browser is not keeping your progress (a private window or full storage). The lab works as usual; save your progress as a file before you leave.".to_owned(),
                problem: true,
                offer_file: true,
            });
        }
    }

    /// The progress file's text, as saved now.
    pub fn progress_file(&self) -> String {
        file::write(&self.progress, self.now)
    }

    /// Merge a progress file in, or refuse it and change nothing.
    pub fn load_progress_file(&mut self, name: &str, bytes: &[u8]) {
        self.notice = Some(match file::read(bytes) {
            Ok(theirs) => {
                let added = self.progress.merge(&theirs);
                self.progress_dirty |= !added.is_empty();
                Notice::news(format!("Loaded {name}: {}.", added.describe()))
            }
            Err(why) => Notice::problem(format!(
                "{name} was not loaded: {why}. Your progress is unchanged."
            )),
        });
    }

    fn save_progress_file(&self, ctx: &egui::Context) {
        let bytes = self.progress_file().into_bytes();
        kinolab_widgets::export::request_save(ctx, file::FILE_NAME, "application/json", bytes);
    }

    /// The notice line, with its buttons.
    pub(super) fn notice_ui(&mut self, ui: &mut egui::Ui) {
        let Some(notice) = self.notice.clone() else {
            return;
        };
        ui.horizontal_wrapped(|ui| {
            let text = RichText::new(&notice.text);
            if notice.problem {
                ui.label(text.color(theme::error_color(ui)));
            } else {
                ui.label(text);
            }
            if notice.offer_file {
                let save = ui.button("Save my progress");
                probe::publish(ui.ctx(), "notice.save", save.rect.center());
                if save.clicked() {
                    self.save_progress_file(ui.ctx());
                }
            }
            if ui.button("Dismiss").clicked() {
                self.notice = None;
            }
        });
        ui.add_space(8.0);
    }

    /// The start page's card: where progress lives, and the file.
    pub(super) fn progress_card(&mut self, ui: &mut egui::Ui) {
        if let Some(picked) = open::take_delivered(ui.ctx(), picker()) {
            self.load_progress_file(&picked.name, &picked.bytes);
        }
        ui.add_space(10.0);
        egui::Frame::group(ui.style())
            .inner_margin(12.0)
            .corner_radius(8.0)
            .show(ui, |ui| {
                ui.set_width(ui.available_width());
                ui.label(RichText::new("Your progress").strong().size(theme::heading_size(3)));
                ui.label(
                    "The lessons you opened, your quiz answers and the code and settings you left in widgets stay in this browser, shared by its tabs, until you clear its site data. To carry on at another computer, save them as a file and load it there: loading adds to what is here and never removes anything.",
                );
                ui.horizontal_wrapped(|ui| {
                    let save = ui.button("Save my progress");
                    let load = ui.button("Load progress…");
                    probe::publish(ui.ctx(), "progress.save", save.rect.center());
                    probe::publish(ui.ctx(), "progress.load", load.rect.center());
                    if save.clicked() {
                        self.save_progress_file(ui.ctx());
                    }
                    if load.clicked() {
                        open::request_pick(ui.ctx(), picker(), ".json");
                    }
                });
                self.retired_ui(ui);
            });
    }

    /// Records of lessons this version does not have: kept, and said.
    fn retired_ui(&self, ui: &mut egui::Ui) {
        let Ok(course) = &self.course else {
            return;
        };
        let known: BTreeSet<String> = course.addresses().into_iter().collect();
        let retired = self.progress.retired(&known);
        if !retired.is_empty() {
            let list: Vec<&str> = retired.iter().map(String::as_str).collect();
            ui.label(RichText::new(format!(
                "Kept from lessons this version no longer has: {}. Their answers stay in your progress and its file.",
                list.join(", ")
            )).weak());
        }
    }
}
