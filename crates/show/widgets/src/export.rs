//! Files a widget makes for the learner (a CSV of a run, a PNG of plots, a
//! model file): the widget asks, and the host saves them as it can (a
//! download in the browser, a file natively). Plus PNG encoding of
//! captured pixels.

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
