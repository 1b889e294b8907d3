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

/// The largest lesson image, in pixels (a 4096 × 4096 image takes 64 MB).
const LARGEST: usize = 4096 * 4096;

/// Decode PNG bytes into an egui image: every colour type and bit depth,
/// not interlaced.
pub fn decode_png(bytes: &[u8]) -> Result<ColorImage, String> {
    let unreadable = |e: minipng::Error| format!("not a readable PNG: {e}");
    let header = minipng::decode_png_header(bytes).map_err(unreadable)?;
    let size = [header.width() as usize, header.height() as usize];
    if size[0].saturating_mul(size[1]) > LARGEST {
        return Err(format!(
            "the PNG is {} × {} pixels; a lesson image may have at most 16 million",
            size[0], size[1]
        ));
    }
    let room = header
        .required_bytes()
        .max(header.required_bytes_rgba8bpc());
    let mut buffer = vec![0; room];
    let mut image = minipng::decode_png(bytes, &mut buffer).map_err(unreadable)?;
    image.convert_to_rgba8bpc().map_err(unreadable)?;
    Ok(ColorImage::from_rgba_unmultiplied(size, image.pixels()))
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
    fn grey_with_alpha_sixteen_bits_and_a_palette_decode_too() {
        let ga = encode(1, 1, png::ColorType::GrayscaleAlpha, &[100, 50]);
        let pixel = decode_png(&ga).unwrap().pixels[0];
        assert_eq!(
            pixel,
            egui::Color32::from_rgba_unmultiplied(100, 100, 100, 50)
        );
        let mut bytes = Vec::new();
        let mut encoder = png::Encoder::new(&mut bytes, 1, 1);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Sixteen);
        let mut writer = encoder.write_header().unwrap();
        writer
            .write_image_data(&[0xff, 0x00, 0x80, 0x10, 0x00, 0x00])
            .unwrap();
        writer.finish().unwrap();
        let pixel = decode_png(&bytes).unwrap().pixels[0];
        assert_eq!(pixel, egui::Color32::from_rgb(0xff, 0x80, 0x00));
        let mut bytes = Vec::new();
        let mut encoder = png::Encoder::new(&mut bytes, 2, 1);
        encoder.set_color(png::ColorType::Indexed);
        encoder.set_depth(png::BitDepth::Eight);
        encoder.set_palette(vec![10, 20, 30, 200, 100, 0]);
        let mut writer = encoder.write_header().unwrap();
        writer.write_image_data(&[1, 0]).unwrap();
        writer.finish().unwrap();
        let image = decode_png(&bytes).unwrap();
        assert_eq!(image.pixels[0], egui::Color32::from_rgb(200, 100, 0));
        assert_eq!(image.pixels[1], egui::Color32::from_rgb(10, 20, 30));
    }

    #[test]
    fn a_huge_image_is_refused_before_its_pixels_are_made() {
        // 4100 × 4100 at one bit a pixel: 2 MB to encode, 67 MB as RGBA.
        let (w, h) = (4100u32, 4100u32);
        let mut bytes = Vec::new();
        let mut encoder = png::Encoder::new(&mut bytes, w, h);
        encoder.set_color(png::ColorType::Grayscale);
        encoder.set_depth(png::BitDepth::One);
        let mut writer = encoder.write_header().unwrap();
        writer
            .write_image_data(&vec![0; (w as usize).div_ceil(8) * h as usize])
            .unwrap();
        writer.finish().unwrap();
        let why = decode_png(&bytes).unwrap_err();
        assert!(why.contains("4100 × 4100"), "{why}");
        // A header that lies about its size is refused too.
        let mut lying = encode(1, 1, png::ColorType::Rgb, &[0, 0, 0]);
        lying[16..20].copy_from_slice(&100_000u32.to_be_bytes());
        assert!(decode_png(&lying).is_err());
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
