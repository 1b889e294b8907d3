//! Bringing a file into a widget: dropped on the page, or picked with the
//! browser's file dialog.
//!
//! A widget asks for a pick with [`request_pick`]; the host opens the
//! dialog and hands the chosen file back with [`deliver`]; the widget takes
//! it with [`take_delivered`] on a later frame. A file dropped on the page
//! goes the same way ([`deliver_dropped`], [`take_dropped`]): egui hands
//! the host a handle, and the browser reads it asynchronously.

/// A file the learner brought in: its name and its bytes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct OpenedFile {
    pub name: String,
    pub bytes: Vec<u8>,
}

impl OpenedFile {
    /// The file as text (invalid UTF-8 replaced).
    pub fn text(&self) -> String {
        String::from_utf8_lossy(&self.bytes).into_owned()
    }
}

/// A widget's wish to open a file: the widget's id and the file types
/// (`.urdf,.json`) the dialog offers.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PickRequest {
    pub widget: egui::Id,
    pub accept: String,
}

fn requests_id() -> egui::Id {
    egui::Id::unique("kinolab-pick-requests")
}

fn delivered_id(widget: egui::Id) -> egui::Id {
    widget.with("kinolab-picked-file")
}

/// Ask the host for the file dialog; the file comes back to `widget`.
pub fn request_pick(ctx: &egui::Context, widget: egui::Id, accept: &str) {
    ctx.data_mut(|d| {
        d.get_temp_mut_or_default::<Vec<PickRequest>>(requests_id())
            .push(PickRequest {
                widget,
                accept: accept.to_owned(),
            });
    });
}

/// The dialogs asked for since the last call (the host calls this once a
/// frame).
pub fn take_pick_requests(ctx: &egui::Context) -> Vec<PickRequest> {
    ctx.data_mut(|d| std::mem::take(d.get_temp_mut_or_default::<Vec<PickRequest>>(requests_id())))
}

/// Hand a picked file to the widget that asked for it.
pub fn deliver(ctx: &egui::Context, widget: egui::Id, file: OpenedFile) {
    ctx.data_mut(|d| d.insert_temp(delivered_id(widget), Some(file)));
    ctx.request_repaint();
}

/// The file picked for `widget`, once.
pub fn take_delivered(ctx: &egui::Context, widget: egui::Id) -> Option<OpenedFile> {
    ctx.data_mut(|d| d.remove_temp::<Option<OpenedFile>>(delivered_id(widget)))
        .flatten()
}

fn dropped_id() -> egui::Id {
    egui::Id::unique("kinolab-dropped-file")
}

/// Hand a file dropped on the page to the first widget that takes it (the
/// host reads the file: in the browser that takes a moment).
pub fn deliver_dropped(ctx: &egui::Context, file: OpenedFile) {
    ctx.data_mut(|d| d.insert_temp(dropped_id(), Some(file)));
    ctx.request_repaint();
}

/// The file dropped on the page, once: the first widget to ask takes it.
pub fn take_dropped(ctx: &egui::Context) -> Option<OpenedFile> {
    ctx.data_mut(|d| d.remove_temp::<Option<OpenedFile>>(dropped_id()))
        .flatten()
}

/// Whether files are being dragged over the page.
pub fn files_hovering(ctx: &egui::Context) -> bool {
    ctx.input(|i| !i.raw.hovered_files.is_empty())
}
