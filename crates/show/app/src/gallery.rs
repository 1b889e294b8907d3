//! The widget gallery: every widget a lesson can embed, straight from the
//! widget schema, with its parameters and a live copy at its defaults.
//! `#/gallery/<name>` shows one widget alone, for embedding in a course page.

use std::collections::HashMap;

use egui::RichText;
use kinolab_lessons::WidgetSpec;
use kinolab_schema::{Kind, Param, WidgetSchema, widgets};
use kinolab_widgets::theme;
use kinolab_widgets::widget::error_box;

use crate::lesson_view::{WidgetSlot, widget_frame};
use crate::route::Page;

/// The gallery, or one widget of it (`only`). Live widgets are kept in
/// `slots` by name, so they keep their state while the page is open.
pub fn gallery_ui(
    ui: &mut egui::Ui,
    only: Option<&str>,
    slots: &mut HashMap<String, WidgetSlot>,
    navigate: &mut Option<Page>,
) {
    match only {
        None => {
            ui.label(
                RichText::new("Widget gallery")
                    .size(theme::heading_size(1))
                    .strong(),
            );
            ui.label("Every widget a lesson can embed, with the parameters a widget block may give it. Each one below runs at its defaults; open one alone to link or embed it.");
            for schema in widgets() {
                ui.add_space(14.0);
                entry(ui, schema, slots, navigate);
            }
        }
        Some(name) => match kinolab_schema::find(name) {
            Some(schema) => entry(ui, schema, slots, navigate),
            None => error_box(
                ui,
                "No such widget",
                &format!("There is no widget named `{name}`."),
            ),
        },
    }
}

fn entry(
    ui: &mut egui::Ui,
    schema: &WidgetSchema,
    slots: &mut HashMap<String, WidgetSlot>,
    navigate: &mut Option<Page>,
) {
    ui.horizontal_wrapped(|ui| {
        ui.label(
            RichText::new(schema.name)
                .size(theme::heading_size(2))
                .strong(),
        );
        if ui.link("open alone").clicked() {
            *navigate = Some(Page::Gallery(Some(schema.name.to_owned())));
        }
    });
    ui.label(schema.summary);
    if !schema.params.is_empty() {
        egui::CollapsingHeader::new(format!("Parameters ({})", schema.params.len()))
            .id_salt(("params", schema.name))
            .show(ui, |ui| params_table(ui, schema.params));
    }
    let spec = WidgetSpec {
        name: schema.name.to_owned(),
        params: Vec::new(),
        line: 0,
    };
    let slot = slots
        .entry(format!("gallery@{}", schema.name))
        .or_insert_with(|| kinolab_widgets::registry::create(&spec));
    widget_frame(ui, &format!("gallery@{}", schema.name), schema.name, slot);
}

fn params_table(ui: &mut egui::Ui, params: &[Param]) {
    egui::Grid::new(ui.scope_id().with("params"))
        .striped(true)
        .num_columns(3)
        .show(ui, |ui| {
            for p in params {
                ui.label(RichText::new(p.name).monospace());
                ui.label(kind_text(&p.kind, p.default));
                ui.label(RichText::new(p.help).small());
                ui.end_row();
            }
        });
}

/// A parameter's type and default, in words.
pub fn kind_text(kind: &Kind, default: Option<&str>) -> String {
    let what = match kind {
        Kind::Number { min, max } => format!("number {min} to {max}"),
        Kind::Integer { min, max } => format!("whole number {min} to {max}"),
        Kind::YesNo => "yes or no".to_owned(),
        Kind::Choice { options } => options.join(" | "),
        Kind::Catalogue { of } => of.ids().join(" | "),
        Kind::Numbers {
            min_count,
            max_count,
            ..
        } if min_count == max_count => format!("{min_count} numbers"),
        Kind::Numbers {
            min_count,
            max_count,
            ..
        } => format!("{min_count} to {max_count} numbers"),
        Kind::Groups { size: 0, .. } => "groups of numbers, `;` between".to_owned(),
        Kind::Groups { size, .. } => format!("groups of {size} numbers, `;` between"),
        Kind::Text { example, .. } => format!("text such as `{example}`"),
    };
    match default {
        Some(d) => format!("{what} (default {d})"),
        None => what,
    }
}
