//! Picture tests without a GPU.
//!
//! [`CpuRenderer`] draws egui's tessellated output into an RGBA image on the
//! CPU: triangles with barycentric coverage at pixel centres, textures
//! sampled bilinearly, premultiplied "over" blending, clip rectangles. It
//! is slow and simple, and the same input gives the same pixels on every
//! machine, which is what a snapshot needs. Plug it into a harness with
//! [`harness`] and compare with `Harness::snapshot` as usual.
//!
//! Edges are not anti-aliased beyond what egui's own feathering adds
//! (tessellated shapes fade out over one pixel), which is enough for egui.

use std::collections::HashMap;

use egui::epaint::{ClippedPrimitive, ImageData, ImageDelta, Mesh, Primitive, Vertex};
use egui::{Color32, Rect, TextureId, TexturesDelta};
use egui_kittest::TestRenderer;
use image::RgbaImage;

/// A texture kept as premultiplied pixels.
#[derive(Debug, Clone)]
struct Texture {
    size: [usize; 2],
    pixels: Vec<Color32>,
}

/// egui's output drawn on the CPU.
#[derive(Debug, Default)]
pub struct CpuRenderer {
    textures: HashMap<TextureId, Texture>,
}

/// A harness builder that renders with [`CpuRenderer`].
pub fn harness() -> egui_kittest::HarnessBuilder {
    egui_kittest::Harness::builder().renderer(CpuRenderer::default())
}

impl CpuRenderer {
    fn apply(&mut self, id: TextureId, delta: &ImageDelta) {
        let ImageData::Color(image) = &delta.image;
        match delta.pos {
            None => {
                self.textures.insert(
                    id,
                    Texture {
                        size: image.size,
                        pixels: image.pixels.clone(),
                    },
                );
            }
            Some([x0, y0]) => {
                let Some(texture) = self.textures.get_mut(&id) else {
                    return;
                };
                for y in 0..image.size[1] {
                    for x in 0..image.size[0] {
                        let (tx, ty) = (x0 + x, y0 + y);
                        if tx < texture.size[0] && ty < texture.size[1] {
                            texture.pixels[ty * texture.size[0] + tx] =
                                image.pixels[y * image.size[0] + x];
                        }
                    }
                }
            }
        }
    }

    /// Draw one mesh into `canvas` (premultiplied RGBA, `width` wide).
    fn draw_mesh(&self, canvas: &mut Canvas, mesh: &Mesh, clip: Rect, scale: f32) {
        let texture = self.textures.get(&mesh.texture_id);
        for tri in mesh.indices.chunks_exact(3) {
            let get = |i: u32| mesh.vertices.get(i as usize).copied();
            if let (Some(a), Some(b), Some(c)) = (get(tri[0]), get(tri[1]), get(tri[2])) {
                canvas.triangle([a, b, c], texture, clip, scale);
            }
        }
    }
}

/// The image being drawn, premultiplied.
struct Canvas {
    width: usize,
    height: usize,
    pixels: Vec<[f32; 4]>,
}

impl Canvas {
    fn triangle(&mut self, v: [Vertex; 3], texture: Option<&Texture>, clip: Rect, scale: f32) {
        let p = v.map(|v| (v.pos.x * scale, v.pos.y * scale));
        let area = edge(p[0], p[1], p[2]);
        if area.abs() < 1e-12 {
            return;
        }
        let min_x = p
            .iter()
            .map(|q| q.0)
            .fold(f32::INFINITY, f32::min)
            .max(clip.min.x * scale);
        let max_x = p
            .iter()
            .map(|q| q.0)
            .fold(f32::NEG_INFINITY, f32::max)
            .min(clip.max.x * scale);
        let min_y = p
            .iter()
            .map(|q| q.1)
            .fold(f32::INFINITY, f32::min)
            .max(clip.min.y * scale);
        let max_y = p
            .iter()
            .map(|q| q.1)
            .fold(f32::NEG_INFINITY, f32::max)
            .min(clip.max.y * scale);
        let x0 = min_x.floor().max(0.0) as usize;
        let y0 = min_y.floor().max(0.0) as usize;
        let x1 = (max_x.ceil().max(0.0) as usize).min(self.width);
        let y1 = (max_y.ceil().max(0.0) as usize).min(self.height);
        for y in y0..y1 {
            for x in x0..x1 {
                let c = (x as f32 + 0.5, y as f32 + 0.5);
                let w = [
                    edge(p[1], p[2], c),
                    edge(p[2], p[0], c),
                    edge(p[0], p[1], c),
                ];
                if !w.iter().all(|&e| e * area >= 0.0) {
                    continue;
                }
                let w = w.map(|e| e / area);
                let color = shade(&v, w, texture);
                self.blend(y * self.width + x, color);
            }
        }
    }

    fn blend(&mut self, at: usize, src: [f32; 4]) {
        let dst = &mut self.pixels[at];
        let keep = 1.0 - src[3];
        for k in 0..4 {
            dst[k] = src[k] + dst[k] * keep;
        }
    }
}

/// Twice the signed area of the triangle (a, b, c).
fn edge(a: (f32, f32), b: (f32, f32), c: (f32, f32)) -> f32 {
    (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)
}

/// The premultiplied colour at barycentric weights `w`.
fn shade(v: &[Vertex; 3], w: [f32; 3], texture: Option<&Texture>) -> [f32; 4] {
    let mix = |f: &dyn Fn(&Vertex) -> f32| w[0] * f(&v[0]) + w[1] * f(&v[1]) + w[2] * f(&v[2]);
    let vertex = [
        mix(&|v| f32::from(v.color.r())),
        mix(&|v| f32::from(v.color.g())),
        mix(&|v| f32::from(v.color.b())),
        mix(&|v| f32::from(v.color.a())),
    ]
    .map(|c| c / 255.0);
    let texel = match texture {
        Some(t) => sample(t, mix(&|v| v.uv.x), mix(&|v| v.uv.y)),
        None => [1.0; 4],
    };
    [0, 1, 2, 3].map(|k| vertex[k] * texel[k])
}

/// Bilinear sample at normalised (u, v), premultiplied, 0–1.
fn sample(t: &Texture, u: f32, v: f32) -> [f32; 4] {
    let [w, h] = t.size;
    if w == 0 || h == 0 {
        return [0.0; 4];
    }
    let x = (u * w as f32 - 0.5).clamp(0.0, (w - 1) as f32);
    let y = (v * h as f32 - 0.5).clamp(0.0, (h - 1) as f32);
    let (x0, y0) = (x.floor() as usize, y.floor() as usize);
    let (x1, y1) = ((x0 + 1).min(w - 1), (y0 + 1).min(h - 1));
    let (fx, fy) = (x - x0 as f32, y - y0 as f32);
    let px = |x: usize, y: usize| {
        let c = t.pixels[y * w + x];
        [c.r(), c.g(), c.b(), c.a()].map(|v| f32::from(v) / 255.0)
    };
    let (a, b, c, d) = (px(x0, y0), px(x1, y0), px(x0, y1), px(x1, y1));
    [0, 1, 2, 3].map(|k| {
        let top = a[k] + (b[k] - a[k]) * fx;
        let bottom = c[k] + (d[k] - c[k]) * fx;
        top + (bottom - top) * fy
    })
}

impl TestRenderer for CpuRenderer {
    fn handle_delta(&mut self, delta: &mut TexturesDelta) {
        for (id, deltas) in &delta.set {
            for image in deltas {
                self.apply(*id, image);
            }
        }
        for id in &delta.free {
            self.textures.remove(id);
        }
        delta.clear();
    }

    fn render(
        &mut self,
        ctx: &egui::Context,
        output: &egui::FullOutput,
    ) -> Result<RgbaImage, String> {
        let scale = ctx.pixels_per_point();
        let size = ctx.content_rect().size() * scale;
        let (width, height) = (size.x.round() as usize, size.y.round() as usize);
        if width == 0 || height == 0 || width * height > 64_000_000 {
            return Err(format!("cannot render a {width}×{height} picture"));
        }
        let mut canvas = Canvas {
            width,
            height,
            pixels: vec![[0.0; 4]; width * height],
        };
        let primitives: Vec<ClippedPrimitive> = ctx.tessellate(output.shapes.clone(), scale);
        for p in &primitives {
            if let Primitive::Mesh(mesh) = &p.primitive {
                self.draw_mesh(&mut canvas, mesh, p.clip_rect, scale);
            }
        }
        let bytes: Vec<u8> = canvas
            .pixels
            .iter()
            .flat_map(|c| c.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8))
            .collect();
        RgbaImage::from_raw(width as u32, height as u32, bytes)
            .ok_or_else(|| "the picture has the wrong size".to_owned())
    }
}
