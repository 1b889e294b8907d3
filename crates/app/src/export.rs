//! Saving what a learner made: a file download in the browser, a file in
//! the working folder natively. Plus PNG encoding of captured pixels.

/// Save `bytes` as `name`. Returns where it went, for the status line.
pub fn save(name: &str, mime: &str, bytes: &[u8]) -> Result<String, String> {
    #[cfg(target_arch = "wasm32")]
    {
        download(name, mime, bytes)
            .map(|()| format!("Downloaded {name}."))
            .map_err(|e| format!("Could not download {name}: {e:?}"))
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        let _ = mime;
        std::fs::write(name, bytes)
            .map(|()| {
                let path = std::env::current_dir()
                    .map(|d| d.join(name).display().to_string())
                    .unwrap_or_else(|_| name.to_string());
                format!("Saved {path}.")
            })
            .map_err(|e| format!("Could not save {name}: {e}"))
    }
}

#[cfg(target_arch = "wasm32")]
fn download(name: &str, mime: &str, bytes: &[u8]) -> Result<(), wasm_bindgen::JsValue> {
    use wasm_bindgen::JsCast;
    let array = js_sys::Uint8Array::from(bytes);
    let parts = js_sys::Array::of1(&array);
    let options = web_sys::BlobPropertyBag::new();
    options.set_type(mime);
    let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &options)?;
    let url = web_sys::Url::create_object_url_with_blob(&blob)?;
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document")?;
    let a: web_sys::HtmlAnchorElement = document.create_element("a")?.dyn_into()?;
    a.set_href(&url);
    a.set_download(name);
    a.click();
    web_sys::Url::revoke_object_url(&url)?;
    Ok(())
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
