//! The lab's shell: top bar, lesson list, the page, and progress.

use std::collections::HashMap;

use egui::{RichText, ScrollArea};
use kinolab_lessons::{Course, Lesson, LessonError, Unit};

use kinolab_widgets::theme;
use kinolab_widgets::widget::error_box;

use crate::first_screen::FirstScreen;
use crate::images::ImageCache;
use crate::lesson_view::{LessonState, WidgetSlot, blocks_ui, inline_ui};
use crate::progress::{Millis, Progress};

mod progress_card;
use crate::quiz_view::QuizState;
use crate::route::{self, Page};
use progress_card::Notice;

/// Narrower than this, the lesson list starts closed and opens over the
/// page instead of beside it.
const NARROW: f32 = 1100.0;
/// Narrower than this (a phone), the top bar keeps only what it needs.
const PHONE: f32 = 640.0;
/// The lesson list's width when it opens over the page.
const OVERLAY_LIST: f32 = 340.0;
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
    notice: Option<Notice>,
    /// The browser refused to store progress (said once).
    storage_blocked: bool,
    /// Another tab chose a theme: apply it on the next frame.
    theme_changed: bool,
    /// The time now, as the host's clock gives it (see [`KinolabApp::set_clock`]).
    now: Millis,
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
    /// Fonts and text styles are installed (see [`KinolabApp::install_style`]).
    style_ready: bool,
    /// Frames that drew the lab's content.
    frames_drawn: u64,
    /// How much of the page this frame lays out (the first frame: a screenful).
    first_screen: FirstScreen,
    /// How far right the page's content reached on the last frame, and the
    /// screen's right edge (see [`KinolabApp::extent`]).
    extent: (f32, f32),
    /// The named points widgets published on the last frame (see
    /// [`KinolabApp::points`]).
    points: String,
    /// The device has a touch screen: a finger drag scrolls the page from
    /// the first touch on (egui learns of touch only from touch events,
    /// which arrive after the first press).
    touch_screen: bool,
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
            course: kinolab_lessons::bundled::outline(),
            page: Page::Home,
            progress,
            progress_dirty: notice.is_some(),
            notice: notice.map(|n| Notice::problem(n.0)),
            storage_blocked: false,
            theme_changed: false,
            now: 0,
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
            first_screen: FirstScreen::default(),
            extent: (0.0, 0.0),
            points: String::new(),
            touch_screen: false,
        };
        app.follow_hash(hash);
        app
    }

    /// Tell the lab it runs on a touch screen (the browser knows before
    /// the first touch).
    pub fn set_touch_screen(&mut self, on: bool) {
        self.touch_screen = on;
    }

    pub fn page(&self) -> &Page {
        &self.page
    }

    pub fn progress(&self) -> &Progress {
        &self.progress
    }

    pub fn notice(&self) -> Option<&str> {
        self.notice.as_ref().map(|n| n.text.as_str())
    }

    /// Tell the lab the time (milliseconds since 1970), before each frame:
    /// answers and changes are dated so that the latest wins in a merge.
    pub fn set_clock(&mut self, now: Millis) {
        self.now = self.now.max(now);
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
        let address = address.clone();
        self.keep_widgets(&address, &states);
        let hash = route::lesson_hash(&address, &states);
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
        if let Page::Lesson(address) = &page {
            if self.progress.visited.insert(address.clone()) {
                self.progress_dirty = true;
            }
            self.restore_kept_widgets(address);
        }
        self.page = page;
        self.scroll_to_top = true;
    }

    /// Widgets of the lesson at `address` the learner left changed on an
    /// earlier visit come back as they were, unless a link says otherwise
    /// or they are already open.
    fn restore_kept_widgets(&mut self, address: &str) {
        for (id, state) in self.progress.widgets_of(address) {
            if !self.widgets.contains_key(id) && !self.restore.contains_key(id) {
                self.restore.insert(id.to_owned(), state.to_owned());
            }
        }
    }

    /// Keep the current lesson's widget states in the progress, so that
    /// what the learner did survives leaving the lesson or the lab.
    fn keep_widgets(&mut self, address: &str, states: &[(usize, String)]) {
        let prefix = format!("{address}@w");
        let open: Vec<String> = self
            .widgets
            .keys()
            .filter(|id| id.starts_with(&prefix))
            .cloned()
            .collect();
        for id in open {
            let now = id
                .strip_prefix(&prefix)
                .and_then(|n| n.parse::<usize>().ok())
                .and_then(|n| states.iter().find(|(k, _)| *k == n))
                .map(|(_, s)| s.as_str());
            self.progress_dirty |= self.progress.keep_widget(&id, now, self.now);
        }
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

    /// Install the lab's fonts, text styles and theme. Fonts take effect at
    /// the start of the next frame, so the host calls this before the first
    /// one, and that frame already draws the page.
    pub fn install_style(&mut self, ctx: &egui::Context) {
        theme::install(ctx);
        self.apply_theme(ctx);
        self.style_ready = true;
    }

    /// Draw the whole lab into `ui`.
    pub fn show(&mut self, ui: &mut egui::Ui) {
        if !self.style_ready {
            // A host that did not install the style: install it now and
            // draw from the next frame, when the fonts are in.
            self.install_style(ui.ctx());
            ui.ctx().request_repaint();
            return;
        }
        if std::mem::take(&mut self.theme_changed) {
            self.apply_theme(ui.ctx());
        }
        self.first_screen = FirstScreen::new(self.frames_drawn == 0);
        let screen = ui.ctx().content_rect();
        let wide = screen.width() >= NARROW;
        let sidebar_open = *self.sidebar_open.get_or_insert(wide);
        let bar_bottom = self.top_bar(ui, sidebar_open, screen.width() < PHONE);
        if sidebar_open && wide {
            egui::Panel::left("lesson-list")
                .resizable(true)
                .default_size(270.0)
                .size_range(200.0..=380.0)
                .show(ui, |ui| self.sidebar(ui));
        }
        egui::CentralPanel::default().show(ui, |ui| self.main_area(ui));
        if sidebar_open && !wide {
            self.sidebar_overlay(ui.ctx(), screen, bar_bottom);
        }
        self.frames_drawn = self.frames_drawn.saturating_add(1);
    }

    /// On a narrow screen the lesson list opens over the page, which keeps
    /// its full width; a tap beside the list or Escape closes it.
    fn sidebar_overlay(&mut self, ctx: &egui::Context, screen: egui::Rect, top: f32) {
        let area = egui::Rect::from_min_max(egui::pos2(screen.left(), top), screen.max);
        let shade = egui::Area::new(egui::Id::unique("lesson-list-shade"))
            .order(egui::Order::Middle)
            .fixed_pos(area.min)
            .show(ctx, |ui| {
                let (rect, response) = ui.allocate_exact_size(area.size(), egui::Sense::click());
                ui.painter().rect_filled(rect, 0.0, theme::SCRIM);
                response
            });
        let width = OVERLAY_LIST.min(screen.width() - 40.0).max(200.0);
        egui::Area::new(egui::Id::unique("lesson-list-overlay"))
            .order(egui::Order::Foreground)
            .fixed_pos(area.min)
            .show(ctx, |ui| {
                egui::Frame::new()
                    .fill(ui.visuals().panel_fill)
                    .inner_margin(8.0)
                    .show(ui, |ui| {
                        ui.set_width(width);
                        ui.set_height(area.height() - 16.0);
                        self.sidebar(ui);
                    });
            });
        if shade.inner.clicked() || ctx.input(|i| i.key_pressed(egui::Key::Escape)) {
            self.sidebar_open = Some(false);
        }
    }

    /// How far right the page's content reached on the last frame, and the
    /// screen's right edge, in points: content past the screen is cut off,
    /// a layout bug (a UI test checks every page at 360, 1024 and 1280 px,
    /// the end-to-end test the widest lessons at 412, 1024 and 1280 px).
    pub fn extent(&self) -> (f32, f32) {
        self.extent
    }

    /// The points widgets published on the last frame (a port of the
    /// component lab), as `name x y` lines in CSS pixels: what a browser
    /// test aims at on the canvas.
    pub fn points(&self) -> &str {
        &self.points
    }

    /// How many frames have drawn content (0 while fonts are being set up).
    pub fn frames_drawn(&self) -> u64 {
        self.frames_drawn
    }

    /// Whether the last frame laid out the whole page (the first frame
    /// lays out only a screenful, see [`FirstScreen`]).
    pub fn page_complete(&self) -> bool {
        self.frames_drawn > 0 && !self.first_screen.cut()
    }

    /// The top bar; returns where it ends. On a phone it keeps the lesson
    /// list's button, the name and the theme switch.
    fn top_bar(&mut self, ui: &mut egui::Ui, sidebar_open: bool, phone: bool) -> f32 {
        let bar = egui::Panel::top("top-bar").show(ui, |ui| {
            ui.horizontal(|ui| {
                let toggle = ui
                    .selectable_label(
                        sidebar_open,
                        RichText::new("≡ Lessons").size(theme::BUTTON_SIZE),
                    )
                    .on_hover_text("Show or hide the list of lessons");
                if toggle.clicked() {
                    self.sidebar_open = Some(!sidebar_open);
                }
                if ui
                    .link(
                        RichText::new("Kinolab")
                            .strong()
                            .size(theme::heading_size(4)),
                    )
                    .clicked()
                {
                    self.navigate(Page::Home);
                }
                if !phone {
                    ui.label(RichText::new("robotics, live").weak());
                }
                ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                    self.theme_switch(ui, phone);
                    if !phone {
                        self.progress_count(ui);
                    }
                });
            });
        });
        bar.response.rect.bottom()
    }

    fn theme_switch(&mut self, ui: &mut egui::Ui, short: bool) {
        let dark = ui.visuals().dark_mode;
        let (label, hover) = match (dark, short) {
            (true, false) => ("Light theme", "Switch to the light theme"),
            (true, true) => ("Light", "Switch to the light theme"),
            (false, false) => ("Dark theme", "Switch to the dark theme"),
            (false, true) => ("Dark", "Switch to the dark theme"),
        };
        if ui.button(label).on_hover_text(hover).clicked() {
            self.progress.choose_theme(Some(!dark), self.now);
            self.progress_dirty = true;
            self.apply_theme(ui.ctx());
        }
    }

    fn progress_count(&self, ui: &mut egui::Ui) {
        if let Ok(course) = &self.course {
            let addresses = course.addresses();
            let visited = addresses
                .iter()
                .filter(|a| self.progress.visited.contains(*a))
                .count();
            ui.label(
                RichText::new(format!("{visited} of {} lessons opened", addresses.len())).weak(),
            );
        }
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
                if self.first_screen.stop(ui) {
                    break;
                }
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
        if self.touch_screen {
            use egui::containers::scroll_area::{DragScroll, ScrollSource};
            scroll = scroll.scroll_source(ScrollSource {
                drag: DragScroll::Always,
                ..ScrollSource::default()
            });
        }
        if std::mem::take(&mut self.scroll_to_top) {
            scroll = scroll.vertical_scroll_offset(0.0);
        }
        scroll.show(ui, |ui| {
            let column = ui.available_width().min(MAX_COLUMN);
            let margin = ((ui.available_width() - column) / 2.0).max(0.0);
            let page = ui.horizontal(|ui| {
                ui.add_space(margin);
                ui.vertical(|ui| {
                    ui.set_width(column - 16.0);
                    ui.add_space(12.0);
                    self.notice_ui(ui);
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
            self.extent = (page.response.rect.right(), ui.ctx().content_rect().right());
            self.points = probe_text(ui.ctx());
        });
    }

    fn home(&mut self, ui: &mut egui::Ui) {
        ui.label(
            RichText::new("Welcome to Kinolab")
                .size(theme::heading_size(1))
                .strong(),
        );
        ui.label(RichText::new(
            "A robotics lab that runs in your browser. Each lesson is short, explains one idea per section, and lets you play with live widgets computed by the same tested code that the command-line tool uses. Your progress stays in this browser (see the end of this page).",
        ).size(theme::BODY_SIZE));
        ui.add_space(10.0);
        let mut target = None;
        match &self.course {
            Err(e) => error_box(ui, "The lessons could not be loaded", &e.to_string()),
            Ok(course) => {
                for (n, unit) in course.units.iter().enumerate() {
                    if self.first_screen.stop(ui) {
                        break;
                    }
                    unit_card(ui, n, unit, &self.progress, &mut target);
                }
            }
        }
        self.progress_card(ui);
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
            now: self.now,
            images: &mut self.images,
            navigate: &mut navigate,
            first_screen: &mut self.first_screen,
        };
        match lesson.blocks() {
            Ok(blocks) => blocks_ui(ui, blocks, &mut state),
            Err(e) => {
                ui.colored_label(kinolab_widgets::theme::error_color(ui), e.to_string());
            }
        }
        ui.add_space(16.0);
        ui.separator();
        let (previous, next) = course.neighbours(address);
        let title = |address: &str| {
            course
                .lesson(address)
                .map(|(_, l)| l.meta.title.clone())
                .unwrap_or_default()
        };
        let previous = previous.map(|a| (title(&a), a));
        let next = next.map(|a| (title(&a), a));
        if let Some(page) = lesson_neighbours(ui, previous, next) {
            navigate = Some(page);
        }
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

/// Buttons to the previous and the next lesson: side by side with their
/// titles on a wide column; short, one under the other, with the title
/// beside, on a phone.
fn lesson_neighbours(
    ui: &mut egui::Ui,
    previous: Option<(String, String)>,
    next: Option<(String, String)>,
) -> Option<Page> {
    let mut target = None;
    if kinolab_widgets::widget::narrow(ui) {
        for (arrow, lesson) in [("← Previous", previous), ("Next →", next)] {
            if let Some((title, address)) = lesson {
                ui.horizontal_wrapped(|ui| {
                    if ui.button(arrow).clicked() {
                        target = Some(Page::Lesson(address));
                    }
                    ui.label(RichText::new(title).weak());
                });
            }
        }
        return target;
    }
    ui.horizontal(|ui| {
        if let Some((title, address)) = previous
            && ui.button(format!("← Previous: {title}")).clicked()
        {
            target = Some(Page::Lesson(address));
        }
        ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
            if let Some((title, address)) = next
                && ui.button(format!("Next: {title} →")).clicked()
            {
                target = Some(Page::Lesson(address));
            }
        });
    });
    target
}

/// The widgets' published points as `name x y` lines in CSS pixels (a
/// point is `zoom` CSS pixels).
fn probe_text(ctx: &egui::Context) -> String {
    let zoom = ctx.zoom_factor();
    kinolab_widgets::probe::take(ctx)
        .iter()
        .map(|(name, at)| format!("{name} {:.0} {:.0}\n", at.x * zoom, at.y * zoom))
        .collect()
}
