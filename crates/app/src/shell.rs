//! The lab's shell: top bar, lesson list, the page, and progress.

use std::collections::HashMap;

use egui::{RichText, ScrollArea};
use kinolab_lessons::{Course, Lesson, LessonError, Unit};

use kinolab_widgets::theme;
use kinolab_widgets::widget::error_box;

use crate::images::ImageCache;
use crate::lesson_view::{LessonState, WidgetSlot, blocks_ui, inline_ui};
use crate::progress::Progress;
use crate::quiz_view::QuizState;
use crate::route::{self, Page};

/// Narrower than this, the lesson list starts closed.
const NARROW: f32 = 1100.0;
/// The text column never grows wider than this, for readable lines.
const MAX_COLUMN: f32 = 820.0;

/// The whole lab.
pub struct KinolabApp {
    course: Result<Course, LessonError>,
    page: Page,
    progress: Progress,
    /// Set when progress changed and has not been stored yet.
    progress_dirty: bool,
    /// A message for the learner, such as "progress was reset".
    notice: Option<String>,
    quizzes: HashMap<String, QuizState>,
    widgets: HashMap<String, WidgetSlot>,
    /// Widget states from the link that opened the page, by widget id.
    restore: HashMap<String, String>,
    /// The hash that reflects the widgets' states, to replace (not push)
    /// in the browser's address bar.
    state_hash: Option<String>,
    images: ImageCache,
    sidebar_open: Option<bool>,
    /// The URL hash the app wants the browser to show, once.
    pending_hash: Option<String>,
    scroll_to_top: bool,
    /// Fonts and text styles are installed on the first frame.
    style_ready: bool,
    /// Frames that drew the lab's content.
    frames_drawn: u64,
}

impl std::fmt::Debug for KinolabApp {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("KinolabApp")
            .field("page", &self.page)
            .finish_non_exhaustive()
    }
}

impl KinolabApp {
    /// Start the lab with the stored progress (if any) on the page the URL
    /// hash names.
    pub fn new(stored_progress: Option<&str>, hash: &str) -> Self {
        let (progress, notice) = Progress::restore(stored_progress);
        let mut app = Self {
            course: kinolab_lessons::bundled::course(),
            page: Page::Home,
            progress,
            progress_dirty: notice.is_some(),
            notice: notice.map(|n| n.0),
            quizzes: HashMap::new(),
            widgets: HashMap::new(),
            restore: HashMap::new(),
            state_hash: None,
            images: ImageCache::default(),
            sidebar_open: None,
            pending_hash: None,
            scroll_to_top: false,
            style_ready: false,
            frames_drawn: 0,
        };
        app.follow_hash(hash);
        app
    }

    pub fn page(&self) -> &Page {
        &self.page
    }

    pub fn progress(&self) -> &Progress {
        &self.progress
    }

    pub fn notice(&self) -> Option<&str> {
        self.notice.as_deref()
    }

    /// The course, if the embedded lessons parsed.
    pub fn course(&self) -> Option<&Course> {
        self.course.as_ref().ok()
    }

    /// Show the page a URL hash names (the browser's back and forward
    /// buttons and typed links come through here).
    pub fn follow_hash(&mut self, hash: &str) {
        let page = Page::from_hash(hash);
        if let Page::Lesson(address) = &page
            && self
                .state_hash
                .as_deref()
                .map(|h| h.trim_start_matches('#'))
                != Some(hash.trim_start_matches('#'))
        {
            // A link from outside: each widget it names starts afresh from
            // the lesson's set-up and takes the link's state (a damaged
            // state leaves it as set up), and the address is written anew.
            for (n, state) in route::widget_states(hash) {
                let id = format!("{address}@w{n}");
                self.widgets.remove(&id);
                self.restore.insert(id, state);
            }
            self.state_hash = None;
        }
        if page != self.page {
            self.open(page);
        }
        self.pending_hash = None;
    }

    /// The hash that would reproduce the current lesson's widgets, when it
    /// changed since last asked. The browser should replace its address with
    /// it without adding a history entry.
    pub fn take_state_hash(&mut self) -> Option<String> {
        let Page::Lesson(address) = &self.page else {
            return None;
        };
        let prefix = format!("{address}@w");
        let mut states: Vec<(usize, String)> = self
            .widgets
            .iter()
            .filter_map(|(id, slot)| {
                let n = id.strip_prefix(&prefix)?.parse().ok()?;
                let state = slot.as_ref().ok()?.state()?;
                Some((n, state))
            })
            .collect();
        states.sort();
        let hash = route::lesson_hash(address, &states);
        if self.state_hash.as_deref() == Some(hash.as_str()) {
            return None;
        }
        self.state_hash = Some(hash.clone());
        Some(hash)
    }

    /// Open a page from inside the app; the URL hash follows.
    pub fn navigate(&mut self, page: Page) {
        self.pending_hash = Some(page.hash());
        self.open(page);
    }

    fn open(&mut self, page: Page) {
        if let Page::Lesson(address) = &page
            && self.progress.visited.insert(address.clone())
        {
            self.progress_dirty = true;
        }
        self.page = page;
        self.scroll_to_top = true;
    }

    /// The hash the browser should now show, if it changed.
    pub fn take_pending_hash(&mut self) -> Option<String> {
        self.pending_hash.take()
    }

    /// The progress to store, if it changed since last asked.
    pub fn take_dirty_progress(&mut self) -> Option<String> {
        std::mem::take(&mut self.progress_dirty).then(|| self.progress.to_json())
    }

    /// The progress as it stands, for storing on exit.
    pub fn progress_json(&self) -> String {
        self.progress.to_json()
    }

    /// A window title for the current page.
    pub fn title(&self) -> String {
        match (&self.page, self.course()) {
            (Page::Lesson(address), Some(course)) => match course.lesson(address) {
                Some((_, lesson)) => format!("{} · Kinolab", lesson.meta.title),
                None => "Lesson not found · Kinolab".to_owned(),
            },
            (Page::Gallery(None), _) => "Widget gallery · Kinolab".to_owned(),
            (Page::Gallery(Some(name)), _) => format!("{name} · Kinolab"),
            _ => "Kinolab: a robotics lab in the browser".to_owned(),
        }
    }

    /// Apply the stored theme choice.
    pub fn apply_theme(&self, ctx: &egui::Context) {
        let preference = match self.progress.dark {
            Some(true) => egui::ThemePreference::Dark,
            Some(false) => egui::ThemePreference::Light,
            None => egui::ThemePreference::System,
        };
        ctx.set_theme(preference);
    }

    /// Draw the whole lab into `ui`.
    pub fn show(&mut self, ui: &mut egui::Ui) {
        if !self.style_ready {
            // Fonts change only at the start of the next frame: wait for them.
            theme::install(ui.ctx());
            self.apply_theme(ui.ctx());
            self.style_ready = true;
            ui.ctx().request_repaint();
            return;
        }
        let wide = ui.ctx().content_rect().width() >= NARROW;
        let sidebar_open = *self.sidebar_open.get_or_insert(wide);
        self.top_bar(ui, sidebar_open);
        if sidebar_open {
            egui::Panel::left("lesson-list")
                .resizable(true)
                .default_size(270.0)
                .size_range(200.0..=380.0)
                .show(ui, |ui| self.sidebar(ui));
        }
        egui::CentralPanel::default().show(ui, |ui| self.main_area(ui));
        self.frames_drawn = self.frames_drawn.saturating_add(1);
    }

    /// How many frames have drawn content (0 while fonts are being set up).
    pub fn frames_drawn(&self) -> u64 {
        self.frames_drawn
    }

    fn top_bar(&mut self, ui: &mut egui::Ui, sidebar_open: bool) {
        egui::Panel::top("top-bar").show(ui, |ui| {
            ui.horizontal(|ui| {
                let toggle = ui
                    .selectable_label(sidebar_open, RichText::new("≡ Lessons").size(15.0))
                    .on_hover_text("Show or hide the list of lessons");
                if toggle.clicked() {
                    self.sidebar_open = Some(!sidebar_open);
                }
                if ui
                    .link(RichText::new("Kinolab").strong().size(18.0))
                    .clicked()
                {
                    self.navigate(Page::Home);
                }
                ui.label(RichText::new("robotics, live").weak());
                ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                    let dark = ui.visuals().dark_mode;
                    let (icon, label) = if dark {
                        ("Light theme", "Switch to the light theme")
                    } else {
                        ("Dark theme", "Switch to the dark theme")
                    };
                    if ui.button(icon).on_hover_text(label).clicked() {
                        self.progress.dark = Some(!dark);
                        self.progress_dirty = true;
                        self.apply_theme(ui.ctx());
                    }
                    if let Ok(course) = &self.course {
                        let addresses = course.addresses();
                        let total = addresses.len();
                        let visited = addresses
                            .iter()
                            .filter(|a| self.progress.visited.contains(*a))
                            .count();
                        ui.label(
                            RichText::new(format!("{visited} of {total} lessons opened")).weak(),
                        );
                    }
                });
            });
        });
    }

    fn sidebar(&mut self, ui: &mut egui::Ui) {
        let mut target = None;
        ScrollArea::vertical().show(ui, |ui| {
            ui.add_space(6.0);
            if ui
                .selectable_label(self.page == Page::Home, "Start here")
                .clicked()
            {
                target = Some(Page::Home);
            }
            if ui
                .selectable_label(matches!(self.page, Page::Gallery(_)), "Widget gallery")
                .clicked()
            {
                target = Some(Page::Gallery(None));
            }
            let Ok(course) = &self.course else {
                return;
            };
            for (n, unit) in course.units.iter().enumerate() {
                ui.add_space(8.0);
                ui.label(RichText::new(format!("Unit {}: {}", n + 1, unit.title)).strong());
                for lesson in &unit.lessons {
                    let address = format!("{}/{}", unit.slug, lesson.slug);
                    let done = self.progress.visited.contains(&address);
                    let mark = if done { "●" } else { "○" };
                    let selected = self.page == Page::Lesson(address.clone());
                    let label = format!("{mark} {}", lesson.meta.title);
                    if ui.selectable_label(selected, label).clicked() {
                        target = Some(Page::Lesson(address));
                    }
                }
            }
        });
        if let Some(page) = target {
            self.navigate(page);
            if ui.ctx().content_rect().width() < NARROW {
                self.sidebar_open = Some(false);
            }
        }
    }

    fn main_area(&mut self, ui: &mut egui::Ui) {
        let mut scroll = ScrollArea::vertical().auto_shrink([false, false]);
        if std::mem::take(&mut self.scroll_to_top) {
            scroll = scroll.vertical_scroll_offset(0.0);
        }
        scroll.show(ui, |ui| {
            let column = ui.available_width().min(MAX_COLUMN);
            let margin = ((ui.available_width() - column) / 2.0).max(0.0);
            ui.horizontal(|ui| {
                ui.add_space(margin);
                ui.vertical(|ui| {
                    ui.set_width(column - 16.0);
                    ui.add_space(12.0);
                    if let Some(notice) = self.notice.clone() {
                        ui.horizontal(|ui| {
                            ui.label(RichText::new(notice.clone()).color(theme::warn_color(ui)));
                            if ui.button("Dismiss").clicked() {
                                self.notice = None;
                            }
                        });
                        ui.add_space(8.0);
                    }
                    match self.page.clone() {
                        Page::Home => self.home(ui),
                        Page::Lesson(address) => self.lesson_page(ui, &address),
                        Page::Gallery(only) => {
                            let mut target = None;
                            crate::gallery::gallery_ui(
                                ui,
                                only.as_deref(),
                                &mut self.widgets,
                                &mut target,
                            );
                            if let Some(page) = target {
                                self.navigate(page);
                            }
                        }
                    }
                    ui.add_space(40.0);
                });
            });
        });
    }

    fn home(&mut self, ui: &mut egui::Ui) {
        ui.label(
            RichText::new("Welcome to Kinolab")
                .size(theme::heading_size(1))
                .strong(),
        );
        ui.label(RichText::new(
            "A robotics lab that runs in your browser. Each lesson is short, explains one idea per section, and lets you play with live widgets computed by the same tested code that the command-line tool uses. Your progress stays in this browser.",
        ).size(theme::BODY_SIZE));
        ui.add_space(10.0);
        let mut target = None;
        match &self.course {
            Err(e) => error_box(ui, "The lessons could not be loaded", &e.to_string()),
            Ok(course) => {
                for (n, unit) in course.units.iter().enumerate() {
                    unit_card(ui, n, unit, &self.progress, &mut target);
                }
            }
        }
        if let Some(page) = target {
            self.navigate(page);
        }
    }

    fn lesson_page(&mut self, ui: &mut egui::Ui, address: &str) {
        let course = match &self.course {
            Ok(course) => course,
            Err(e) => {
                error_box(ui, "The lessons could not be loaded", &e.to_string());
                return;
            }
        };
        let Some((unit, lesson)) = course.lesson(address) else {
            error_box(
                ui,
                "Lesson not found",
                &format!("There is no lesson at `{address}`. Pick one from the list."),
            );
            return;
        };
        let mut navigate = None;
        let mut changed = false;
        lesson_header(ui, unit, lesson);
        let mut state = LessonState {
            address,
            file: &lesson.file,
            quizzes: &mut self.quizzes,
            widgets: &mut self.widgets,
            restore: &mut self.restore,
            progress: &mut self.progress,
            progress_changed: &mut changed,
            images: &mut self.images,
            navigate: &mut navigate,
        };
        blocks_ui(ui, &lesson.blocks, &mut state);
        ui.add_space(16.0);
        ui.separator();
        let (previous, next) = course.neighbours(address);
        ui.horizontal(|ui| {
            if let Some(prev) = previous {
                let title = course
                    .lesson(&prev)
                    .map(|(_, l)| l.meta.title.clone())
                    .unwrap_or_default();
                if ui.button(format!("← Previous: {title}")).clicked() {
                    navigate = Some(Page::Lesson(prev));
                }
            }
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                if let Some(next) = next {
                    let title = course
                        .lesson(&next)
                        .map(|(_, l)| l.meta.title.clone())
                        .unwrap_or_default();
                    if ui.button(format!("Next: {title} →")).clicked() {
                        navigate = Some(Page::Lesson(next));
                    }
                }
            });
        });
        self.progress_dirty |= changed;
        if let Some(page) = navigate {
            self.navigate(page);
        }
    }
}

fn unit_card(
    ui: &mut egui::Ui,
    n: usize,
    unit: &Unit,
    progress: &Progress,
    target: &mut Option<Page>,
) {
    egui::Frame::group(ui.style())
        .inner_margin(12.0)
        .corner_radius(8.0)
        .show(ui, |ui| {
            ui.set_width(ui.available_width());
            ui.label(
                RichText::new(format!("Unit {}: {}", n + 1, unit.title))
                    .size(theme::heading_size(2))
                    .strong(),
            );
            let mut ignore = None;
            for block in &unit.summary {
                if let kinolab_lessons::Block::Paragraph(spans) = block {
                    inline_ui(ui, spans, theme::BODY_SIZE, false, &mut ignore);
                }
            }
            ui.add_space(4.0);
            for lesson in &unit.lessons {
                let address = format!("{}/{}", unit.slug, lesson.slug);
                let mark = if progress.visited.contains(&address) {
                    "●"
                } else {
                    "○"
                };
                ui.horizontal(|ui| {
                    if ui
                        .link(
                            RichText::new(format!("{mark} {}", lesson.meta.title))
                                .size(theme::BODY_SIZE),
                        )
                        .clicked()
                    {
                        *target = Some(Page::Lesson(address.clone()));
                    }
                    ui.label(RichText::new(format!("{} min", lesson.meta.minutes)).weak());
                });
            }
        });
    ui.add_space(10.0);
}

fn lesson_header(ui: &mut egui::Ui, unit: &Unit, lesson: &Lesson) {
    ui.label(RichText::new(&unit.title).weak());
    ui.label(
        RichText::new(&lesson.meta.title)
            .size(theme::heading_size(1))
            .strong(),
    );
    ui.label(RichText::new(format!("About {} minutes", lesson.meta.minutes)).weak());
    ui.add_space(6.0);
    egui::Frame::new()
        .fill(theme::accent(ui).gamma_multiply(0.08))
        .corner_radius(6.0)
        .inner_margin(10.0)
        .show(ui, |ui| {
            ui.set_width(ui.available_width());
            ui.label(RichText::new("After this lesson you can").strong());
            for objective in &lesson.meta.objectives {
                ui.label(format!("• {objective}"));
            }
        });
    ui.add_space(6.0);
}
