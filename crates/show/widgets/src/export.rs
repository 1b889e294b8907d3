//! Taking things away from a widget: one module for every widget.
//!
//! A widget only says what it offers, in one [`bar`] of buttons: a PNG of
//! an area on screen (a canvas, a plot), a CSV of what it plotted, and the
//! run's input file in the command line's format ("Save run"), so that the
//! matching `kinolab` command reproduces the run's numbers. The host saves
//! the files (a download in the browser, a file natively); a PNG is cut
//! from a screen capture that arrives a frame later.

use std::sync::{Arc, Mutex};

/// A file a widget asks the host to save.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SaveRequest {
    pub name: String,
    pub mime: String,
    pub bytes: Vec<u8>,
}

fn queue_id() -> egui::Id {
    egui::Id::unique("kinolab-save-requests")
}

/// Ask the host to save `bytes` as `name`; it happens after this frame.
pub fn request_save(ctx: &egui::Context, name: &str, mime: &str, bytes: Vec<u8>) {
    ctx.data_mut(|d| {
        d.get_temp_mut_or_default::<Vec<SaveRequest>>(queue_id())
            .push(SaveRequest {
                name: name.to_owned(),
                mime: mime.to_owned(),
                bytes,
            });
    });
}

/// The files asked for since the last call (the host calls this once a frame).
pub fn take_save_requests(ctx: &egui::Context) -> Vec<SaveRequest> {
    ctx.data_mut(|d| std::mem::take(d.get_temp_mut_or_default::<Vec<SaveRequest>>(queue_id())))
}

/// One thing a widget offers to take away.
pub enum Export<'a> {
    /// The area `rect` on screen as a PNG called `file`.
    Png { file: &'a str, rect: egui::Rect },
    /// A CSV (made only when asked for), copied or saved as `file`.
    Csv {
        file: &'a str,
        make: &'a dyn Fn() -> String,
    },
    /// The run's input file for the command line (`*.run.json`, a world,
    /// gait, CPG, system or field file), saved as `file`; the tooltip says
    /// which command reads it.
    Run {
        file: &'a str,
        command: &'a str,
        make: &'a dyn Fn() -> Result<String, String>,
    },
}

impl std::fmt::Debug for Export<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Export::Png { file, .. } => write!(f, "Png({file})"),
            Export::Csv { file, .. } => write!(f, "Csv({file})"),
            Export::Run { file, .. } => write!(f, "Run({file})"),
        }
    }
}

/// A screen capture on its way: the area to cut, the file, and where the
/// image lands.
#[derive(Clone)]
struct Capture {
    rect: egui::Rect,
    file: String,
    slot: Arc<Mutex<Option<Arc<egui::ColorImage>>>>,
}

/// What the bar last said ("Saved run.csv."), kept per bar.
#[derive(Clone, Default)]
struct BarState {
    capture: Option<Capture>,
    status: String,
}

/// A row of buttons for `offers`, with a line saying what happened; `id`
/// tells bars on one page apart.
pub fn bar(ui: &mut egui::Ui, id: egui::Id, offers: &[Export<'_>]) {
    let mut state: BarState = ui.ctx().data(|d| d.get_temp(id)).unwrap_or_default();
    finish_capture(ui, &mut state);
    ui.horizontal_wrapped(|ui| {
        for offer in offers {
            offer_button(ui, offer, &mut state);
        }
        ui.label(egui::RichText::new(state.status.clone()).small());
    });
    ui.ctx().data_mut(|d| d.insert_temp(id, state));
}

fn offer_button(ui: &mut egui::Ui, offer: &Export<'_>, state: &mut BarState) {
    match offer {
        Export::Png { file, rect } => {
            if ui
                .button("Save PNG")
                .on_hover_text(format!("Save this as {file}"))
                .clicked()
            {
                state.capture = Some(request_capture(ui, *rect, file));
                state.status = "Capturing…".into();
            }
        }
        Export::Csv { file, make } => {
            if ui.button("Copy CSV").clicked() {
                ui.ctx().copy_text(make());
                state.status = "Copied as CSV.".into();
            }
            if ui.button("Save CSV").clicked() {
                request_save(ui.ctx(), file, "text/csv", make().into_bytes());
                state.status = format!("Saved {file}.");
            }
        }
        Export::Run {
            file,
            command,
            make,
        } => {
            let hint = format!("Save this run's input as {file}: `{command}` reproduces it");
            let button = ui.button("Save run").on_hover_ui(|ui| {
                crate::widget::message_ui(ui, &hint, ui.visuals().text_color());
            });
            if button.clicked() {
                state.status = match make() {
                    Ok(text) => {
                        request_save(ui.ctx(), file, "application/json", text.into_bytes());
                        format!("Saved {file}: run `{command}`.")
                    }
                    Err(e) => format!("Could not write the run: {e}."),
                };
            }
        }
    }
}

fn request_capture(ui: &egui::Ui, rect: egui::Rect, file: &str) -> Capture {
    let slot: Arc<Mutex<Option<Arc<egui::ColorImage>>>> = Arc::default();
    let fill = slot.clone();
    let ctx = ui.ctx().clone();
    ui.ctx()
        .send_viewport_cmd(egui::ViewportCommand::Screenshot(
            egui::ScreenshotCallback::new(move |image| {
                if let Ok(mut s) = fill.lock() {
                    *s = Some(image);
                }
                ctx.request_repaint();
            }),
        ));
    Capture {
        rect,
        file: file.to_owned(),
        slot,
    }
}

/// Save a capture that has arrived.
fn finish_capture(ui: &egui::Ui, state: &mut BarState) {
    let Some(capture) = &state.capture else {
        return;
    };
    let Some(image) = capture.slot.lock().ok().and_then(|mut s| s.take()) else {
        return;
    };
    let file = capture.file.clone();
    state.status = match png_of(&image, capture.rect, ui.ctx().pixels_per_point()) {
        Ok(png) => {
            request_save(ui.ctx(), &file, "image/png", png);
            format!("Saved {file}.")
        }
        Err(e) => format!("Could not save the picture: {e}."),
    };
    state.capture = None;
}

/// Plotted series as one CSV: a `t` column (or whatever `x` is) and one
/// column per series, a row per sample of the longest (blank where a
/// series has no value there).
pub fn series_csv(x: &str, series: &[(&str, Vec<[f64; 2]>)]) -> String {
    use std::fmt::Write as _;
    let mut out = String::from(x);
    for (name, _) in series {
        let _ = write!(out, ",{}", csv_field(name));
    }
    out.push('\n');
    let rows = series.iter().map(|(_, s)| s.len()).max().unwrap_or(0);
    for k in 0..rows {
        let x = series
            .iter()
            .find_map(|(_, s)| s.get(k))
            .map_or(0.0, |p| p[0]);
        let _ = write!(out, "{x}");
        for (_, s) in series {
            match s.get(k) {
                Some(p) => {
                    let _ = write!(out, ",{}", p[1]);
                }
                None => out.push(','),
            }
        }
        out.push('\n');
    }
    out
}

/// A CSV field, quoted when it holds a comma or a quote.
pub fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_owned()
    }
}

/// Encode the part of `image` inside `rect` (in points) as PNG.
pub fn png_of(
    image: &egui::ColorImage,
    rect: egui::Rect,
    pixels_per_point: f32,
) -> Result<Vec<u8>, String> {
    let [w, h] = image.size;
    let x0 = ((rect.min.x * pixels_per_point).floor().max(0.0) as usize).min(w);
    let y0 = ((rect.min.y * pixels_per_point).floor().max(0.0) as usize).min(h);
    let x1 = ((rect.max.x * pixels_per_point).ceil().max(0.0) as usize).min(w);
    let y1 = ((rect.max.y * pixels_per_point).ceil().max(0.0) as usize).min(h);
    if x1 <= x0 || y1 <= y0 {
        return Err("the plot is not on screen".into());
    }
    let mut rgba = Vec::with_capacity((x1 - x0) * (y1 - y0) * 4);
    for y in y0..y1 {
        for px in &image.pixels[y * w + x0..y * w + x1] {
            rgba.extend_from_slice(&px.to_srgba_unmultiplied());
        }
    }
    let mut out = Vec::new();
    {
        let mut encoder = png::Encoder::new(&mut out, (x1 - x0) as u32, (y1 - y0) as u32);
        encoder.set_color(png::ColorType::Rgba);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder.write_header().map_err(|e| e.to_string())?;
        writer.write_image_data(&rgba).map_err(|e| e.to_string())?;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn series_share_one_csv_with_a_row_per_sample() {
        let text = series_csv(
            "t (s)",
            &[
                ("x, m", vec![[0.0, 1.0], [0.5, 2.0], [1.0, 3.5]]),
                ("y", vec![[0.0, -1.0], [0.5, 0.25]]),
            ],
        );
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines,
            ["t (s),\"x, m\",y", "0,1,-1", "0.5,2,0.25", "1,3.5,"]
        );
    }

    #[test]
    fn save_requests_queue_until_taken() {
        let ctx = egui::Context::default();
        request_save(&ctx, "a.csv", "text/csv", b"t,x".to_vec());
        request_save(&ctx, "b.png", "image/png", vec![1, 2]);
        let taken = take_save_requests(&ctx);
        assert_eq!(taken.len(), 2);
        assert_eq!(taken[0].name, "a.csv");
        assert_eq!(taken[1].bytes, vec![1, 2]);
        assert!(take_save_requests(&ctx).is_empty());
    }

    #[test]
    fn a_cropped_capture_decodes_to_its_pixels() {
        let mut image = egui::ColorImage::filled([8, 6], egui::Color32::WHITE);
        image.pixels[2 * 8 + 3] = egui::Color32::from_rgb(200, 10, 20);
        // Points (1, 0.5)–(3, 2.5) at 2 pixels per point: pixels 2..6 × 1..5.
        let rect = egui::Rect::from_min_max(egui::pos2(1.0, 0.5), egui::pos2(3.0, 2.5));
        let bytes = png_of(&image, rect, 2.0).unwrap_or_default();
        let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
        let Ok(mut reader) = decoder.read_info() else {
            panic!("not a PNG")
        };
        let mut buf = vec![0; reader.output_buffer_size().unwrap_or(0)];
        let Ok(info) = reader.next_frame(&mut buf) else {
            panic!("no frame")
        };
        assert_eq!((info.width, info.height), (4, 4));
        // Pixel (3, 2) lands at (1, 1) of the crop.
        let at = (4 + 1) * 4;
        assert_eq!(&buf[at..at + 4], &[200, 10, 20, 255]);
        assert_eq!(&buf[0..4], &[255, 255, 255, 255]);
        assert!(
            png_of(
                &image,
                egui::Rect::from_min_max(egui::pos2(50.0, 50.0), egui::pos2(60.0, 60.0)),
                1.0
            )
            .is_err()
        );
    }
}
