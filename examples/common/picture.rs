//! The pictures the examples draw: a small RGB raster with the few drawing
//! operations they need (no font files, no system libraries), and a field
//! on a triangle mesh drawn into it. Included by the examples with
//! `#[path = "common/picture.rs"] mod picture;`.
#![allow(dead_code)]

use std::io::BufWriter;
use std::path::Path;

/// The picture's size in pixels: a screen's, whatever the mesh.
pub const WIDTH: usize = 1200;
/// See [`WIDTH`].
pub const HEIGHT: usize = 800;
/// Glyphs of 8×8 bits drawn at twice their size.
const GLYPH_SCALE: usize = 2;

pub struct Image {
    rgb: Vec<u8>,
}

impl Image {
    /// A white picture.
    pub fn new() -> Image {
        Image {
            rgb: vec![255; 3 * WIDTH * HEIGHT],
        }
    }

    fn set(&mut self, x: usize, y: usize, c: [u8; 3]) {
        if x < WIDTH && y < HEIGHT {
            let k = 3 * (y * WIDTH + x);
            self.rgb[k..k + 3].copy_from_slice(&c);
        }
    }

    pub fn rect(&mut self, x: usize, y: usize, w: usize, h: usize, c: [u8; 3]) {
        for j in y..y + h {
            for i in x..x + w {
                self.set(i, j, c);
            }
        }
    }

    /// Black ASCII text, its top left corner at (x, y).
    pub fn text(&mut self, x: usize, y: usize, text: &str) {
        for (n, ch) in text.chars().enumerate() {
            let glyph = font8x8::legacy::BASIC_LEGACY
                .get(ch as usize)
                .copied()
                .unwrap_or([0; 8]);
            for (row, bits) in glyph.iter().enumerate() {
                for col in 0..8 {
                    if bits & (1 << col) != 0 {
                        let px = x + GLYPH_SCALE * (8 * n + col);
                        self.rect(px, y + GLYPH_SCALE * row, GLYPH_SCALE, GLYPH_SCALE, [0; 3]);
                    }
                }
            }
        }
    }

    /// Colours the pixels whose centre lies in the triangle `p`
    /// (pixel coordinates) by `colour` of the value interpolated
    /// linearly from its corners' `t`. A pixel on an edge shared by
    /// two triangles is taken by either: no gap opens between them.
    pub fn fill_triangle(
        &mut self,
        p: [[f64; 2]; 3],
        t: [f64; 3],
        colour: impl Fn(f64) -> [u8; 3],
    ) {
        let area =
            (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
        if area == 0.0 || !area.is_finite() {
            return;
        }
        let min = |k: usize| p.iter().map(|q| q[k]).fold(f64::INFINITY, f64::min);
        let max = |k: usize| p.iter().map(|q| q[k]).fold(f64::NEG_INFINITY, f64::max);
        // The pixels whose centres (i + ½, j + ½) the bounding box holds.
        let first = |v: f64| (v - 0.5).ceil().max(0.0) as usize;
        let last = |v: f64, n: usize| ((v - 0.5).floor().min(n as f64 - 1.0)).max(-1.0);
        let (i0, j0) = (first(min(0)), first(min(1)));
        let (i1, j1) = (last(max(0), WIDTH), last(max(1), HEIGHT));
        if i1 < 0.0 || j1 < 0.0 {
            return;
        }
        // Barycentric coordinate of corner k at q: the signed area of
        // q with the other two corners over the triangle's.
        let weight = |k: usize, q: [f64; 2]| {
            let (a, b) = (p[(k + 1) % 3], p[(k + 2) % 3]);
            ((b[0] - a[0]) * (q[1] - a[1]) - (q[0] - a[0]) * (b[1] - a[1])) / area
        };
        const ON_EDGE: f64 = -1e-12;
        for j in j0..=j1 as usize {
            for i in i0..=i1 as usize {
                let q = [i as f64 + 0.5, j as f64 + 0.5];
                let w = [weight(0, q), weight(1, q), weight(2, q)];
                if w.iter().all(|&w| w >= ON_EDGE) {
                    self.set(i, j, colour(w[0] * t[0] + w[1] * t[1] + w[2] * t[2]));
                }
            }
        }
    }

    /// A black line from `a` to `b` (pixel coordinates), one pixel wide.
    pub fn line(&mut self, a: [f64; 2], b: [f64; 2]) {
        let steps = (b[0] - a[0]).abs().max((b[1] - a[1]).abs()).ceil().max(1.0) as usize;
        for k in 0..=steps {
            let t = k as f64 / steps as f64;
            let (x, y) = (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]));
            if x >= 0.0 && y >= 0.0 {
                self.set(x as usize, y as usize, [0; 3]);
            }
        }
    }

    pub fn save_png(&self, path: &Path) -> Result<(), Box<dyn std::error::Error>> {
        let file = BufWriter::new(std::fs::File::create(path)?);
        let mut encoder = png::Encoder::new(file, WIDTH as u32, HEIGHT as u32);
        encoder.set_color(png::ColorType::Rgb);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder.write_header()?;
        writer.write_image_data(&self.rgb)?;
        writer.finish()?;
        Ok(())
    }
}

/// Colour of t ∈ [0, 1] on a blue–white–red scale.
pub fn colour(t: f64) -> [u8; 3] {
    let t = if t.is_nan() { 0.5 } else { t.clamp(0.0, 1.0) };
    let (r, g, b) = if t < 0.5 {
        let s = t / 0.5;
        (s, s, 1.0)
    } else {
        let s = (1.0 - t) / 0.5;
        (1.0, s, s)
    };
    [r, g, b].map(|c| (255.0 * c).round() as u8)
}

/// The triangles with corners `x` (model units) coloured by the nodal
/// `values`, linear on each triangle, with `title` above and a colour bar
/// (labelled in `unit`) at the right, as a PNG of [`WIDTH`] × [`HEIGHT`]
/// pixels: each pixel samples the field, so the file's size does not grow
/// with the mesh.
pub fn field_png(
    x: &[[f64; 2]],
    triangles: &[[usize; 3]],
    values: &[f64],
    title: &str,
    path: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    shaded_field_png(x, triangles, values, &[], title, path)
}

/// [`field_png`] with each triangle's colours times its `shade` in
/// [0, 1] (a surface's lighting; empty: none), drawn in the order given
/// (a painter's order: back to front).
pub fn shaded_field_png(
    x: &[[f64; 2]],
    triangles: &[[usize; 3]],
    values: &[f64],
    shade: &[f64],
    title: &str,
    path: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    let (vmin, vmax) = values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for q in x {
        for k in 0..2 {
            lo[k] = lo[k].min(q[k]);
            hi[k] = hi[k].max(q[k]);
        }
    }
    // The drawing area: below the title, left of the colour bar.
    let (left, top, right, bottom) = (20.0, 50.0, WIDTH as f64 - 230.0, HEIGHT as f64 - 20.0);
    let s = ((right - left) / (hi[0] - lo[0])).min((bottom - top) / (hi[1] - lo[1]));
    let (x0, y0) = (
        left + 0.5 * (right - left - s * (hi[0] - lo[0])),
        top + 0.5 * (bottom - top + s * (hi[1] - lo[1])),
    );
    let to_pixels = |q: [f64; 2]| [x0 + s * (q[0] - lo[0]), y0 - s * (q[1] - lo[1])];
    let range = (vmax - vmin).max(f64::MIN_POSITIVE);
    let mut image = Image::new();
    for (k, t) in triangles.iter().enumerate() {
        let light = shade.get(k).copied().unwrap_or(1.0);
        image.fill_triangle(
            t.map(|v| to_pixels(x[v])),
            t.map(|v| (values[v] - vmin) / range),
            |s| colour(s).map(|c| (light * c as f64).round() as u8),
        );
    }
    image.text(20, 16, title);
    // The colour bar, vmax at the top.
    let (bar_x, bar_top, bar_height) = (WIDTH - 210, 80, HEIGHT - 160);
    for k in 0..bar_height {
        let c = colour(1.0 - k as f64 / (bar_height - 1) as f64);
        image.rect(bar_x, bar_top + k, 24, 1, c);
    }
    for (k, v) in [
        (0, vmax),
        (bar_height / 2, 0.5 * (vmin + vmax)),
        (bar_height - 1, vmin),
    ] {
        image.rect(bar_x + 24, bar_top + k, 6, 1, [0; 3]);
        image.text(bar_x + 34, bar_top + k - 8, &format!("{v:.3e}"));
    }
    image.save_png(path)?;
    Ok(())
}

/// The triangles with corners `x` drawn as their edges (black on white),
/// with `title` above: a mesh, as [`field_png`] fits it to the picture.
pub fn mesh_png(
    x: &[[f64; 2]],
    triangles: &[[usize; 3]],
    title: &str,
    path: &Path,
) -> Result<(), Box<dyn std::error::Error>> {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for q in x {
        for k in 0..2 {
            lo[k] = lo[k].min(q[k]);
            hi[k] = hi[k].max(q[k]);
        }
    }
    let (left, top, right, bottom) = (20.0, 50.0, WIDTH as f64 - 20.0, HEIGHT as f64 - 20.0);
    let s = ((right - left) / (hi[0] - lo[0])).min((bottom - top) / (hi[1] - lo[1]));
    let (x0, y0) = (
        left + 0.5 * (right - left - s * (hi[0] - lo[0])),
        top + 0.5 * (bottom - top + s * (hi[1] - lo[1])),
    );
    let to_pixels = |q: [f64; 2]| [x0 + s * (q[0] - lo[0]), y0 - s * (q[1] - lo[1])];
    let mut image = Image::new();
    for t in triangles {
        for k in 0..3 {
            image.line(to_pixels(x[t[k]]), to_pixels(x[t[(k + 1) % 3]]));
        }
    }
    image.text(20, 16, title);
    image.save_png(path)?;
    Ok(())
}
