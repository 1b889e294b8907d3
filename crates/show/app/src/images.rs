//! Lesson images: PNG files embedded with the lessons, decoded once and
//! kept as textures.

use std::collections::HashMap;

use egui::{ColorImage, TextureHandle, TextureOptions};

use kinolab_widgets::widget::error_box;

/// Decoded images by their path under `lessons/`.
#[derive(Default)]
pub struct ImageCache {
    textures: HashMap<String, Result<TextureHandle, String>>,
}

impl std::fmt::Debug for ImageCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ImageCache")
            .field("loaded", &self.textures.len())
            .finish()
    }
}

/// Decode PNG bytes into an egui image.
pub fn decode_png(bytes: &[u8]) -> Result<ColorImage, String> {
    let mut decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    decoder.set_transformations(
        png::Transformations::EXPAND | png::Transformations::STRIP_16 | png::Transformations::ALPHA,
    );
    let mut reader = decoder
        .read_info()
        .map_err(|e| format!("not a readable PNG: {e}"))?;
    let mut buffer = vec![0; reader.output_buffer_size().ok_or("the PNG is too large")?];
    let info = reader
        .next_frame(&mut buffer)
        .map_err(|e| format!("not a readable PNG: {e}"))?;
    let pixels = &buffer[..info.buffer_size()];
    let size = [info.width as usize, info.height as usize];
    match info.color_type {
        png::ColorType::Rgba => Ok(ColorImage::from_rgba_unmultiplied(size, pixels)),
        png::ColorType::GrayscaleAlpha => {
            let rgba: Vec<u8> = pixels
                .chunks_exact(2)
                .flat_map(|p| [p[0], p[0], p[0], p[1]])
                .collect();
            Ok(ColorImage::from_rgba_unmultiplied(size, &rgba))
        }
        other => Err(format!("unsupported PNG colour type {other:?}")),
    }
}

impl ImageCache {
    /// Show an image beside the lesson `file`, scaled to fit the column,
    /// with its alt text as the caption and accessible label.
    pub fn show(&mut self, ui: &mut egui::Ui, file: &str, url: &str, alt: &str) {
        let path = kinolab_lessons::image_path(file, url);
        let entry = self.textures.entry(path.clone()).or_insert_with(|| {
            let bytes = kinolab_lessons::bundled::image(&path)
                .ok_or_else(|| format!("no image `{url}` beside this lesson"))?;
            let image = decode_png(bytes)?;
            Ok(ui.ctx().load_texture(url, image, TextureOptions::LINEAR))
        });
        match entry {
            Ok(texture) => {
                let size = texture.size_vec2();
                let scale = (ui.available_width() / size.x).min(1.0);
                ui.vertical_centered(|ui| {
                    ui.add(egui::Image::new((texture.id(), size * scale)).alt_text(alt));
                    ui.label(egui::RichText::new(alt).small().weak());
                });
            }
            Err(message) => error_box(ui, "Image cannot be shown", message),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn encode(width: u32, height: u32, color: png::ColorType, pixels: &[u8]) -> Vec<u8> {
        let mut bytes = Vec::new();
        let mut encoder = png::Encoder::new(&mut bytes, width, height);
        encoder.set_color(color);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder.write_header().unwrap();
        writer.write_image_data(pixels).unwrap();
        writer.finish().unwrap();
        bytes
    }

    #[test]
    fn rgb_and_rgba_pngs_decode_to_the_same_pixels() {
        let rgb = encode(2, 1, png::ColorType::Rgb, &[255, 0, 0, 0, 0, 255]);
        let image = decode_png(&rgb).unwrap();
        assert_eq!(image.size, [2, 1]);
        assert_eq!(image.pixels[0], egui::Color32::from_rgb(255, 0, 0));
        assert_eq!(image.pixels[1], egui::Color32::from_rgb(0, 0, 255));
        let gray = encode(1, 1, png::ColorType::Grayscale, &[128]);
        assert_eq!(
            decode_png(&gray).unwrap().pixels[0],
            egui::Color32::from_gray(128)
        );
    }

    #[test]
    fn garbage_is_an_error_not_a_panic() {
        assert!(
            decode_png(b"not a png")
                .unwrap_err()
                .starts_with("not a readable PNG")
        );
        assert!(decode_png(&[]).is_err());
    }
}
