//! Frames to files: linear radiance to EXR; PNG through a documented tone map; relative
//! difference as a false-colour map with its scale drawn beneath it.

use std::io::Cursor;
use std::path::Path;

use glam::DVec3;

use crate::error::{Error, Result};
use crate::render::{Frame, FrameKind};

/// The tone map of every PNG: radiance × exposure, then Reinhard's `x / (1 + x)` per channel
/// (Reinhard et al. 2002 eq. 3: keeps hues, never clips highlights), then the sRGB transfer
/// function (IEC 61966-2-1). Negative radiance (case-2 light without clipping) shows black.
pub fn tone_map(radiance: DVec3, exposure: f64) -> [u8; 3] {
    let map = |x: f64| {
        let x = (x * exposure).max(0.0);
        let x = if x.is_finite() { x / (1.0 + x) } else { 1.0 };
        to_u8(srgb_encode(x))
    };
    [map(radiance.x), map(radiance.y), map(radiance.z)]
}

/// The sRGB transfer function (IEC 61966-2-1) of a linear value in [0, 1].
pub fn srgb_encode(x: f64) -> f64 {
    if x <= 0.003_130_8 {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    }
}

fn to_u8(x: f64) -> u8 {
    (x.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// The false-colour scale of relative differences: logarithmic from 0.1% to 100% (LTC
/// errors span three decades, docs/design.md §4 measures 1% to 100%).
pub const DIFF_SCALE_DECADES: [f64; 4] = [1e-3, 1e-2, 1e-1, 1.0];

/// Position of a relative difference on the colour scale, in [0, 1].
pub fn diff_scale_position(rel: f64) -> f64 {
    if rel.is_nan() {
        return 1.0;
    }
    let lo = DIFF_SCALE_DECADES[0].log10();
    let hi = DIFF_SCALE_DECADES[3].log10();
    ((rel.max(1e-300).log10() - lo) / (hi - lo)).clamp(0.0, 1.0)
}

/// Background (off the plane) in PNGs.
pub const BACKGROUND: [u8; 3] = [24, 24, 28];

/// An 8-bit picture of a frame: tone-mapped radiance (with the split divider drawn), or the
/// false-colour difference map with its colour bar and labels underneath.
pub fn to_rgb8(frame: &Frame, exposure: f64) -> image::RgbImage {
    let (w, h) = (frame.width as u32, frame.height as u32);
    let pixel = |k: usize| {
        if !frame.on_plane[k] {
            return BACKGROUND;
        }
        match frame.kind {
            FrameKind::Radiance => tone_map(frame.pixels[k], exposure),
            FrameKind::RelativeDifference => {
                crate::colormap::viridis(diff_scale_position(frame.pixels[k].x))
            }
        }
    };
    let mut img = image::RgbImage::from_fn(w, h, |x, y| image::Rgb(pixel((y * w + x) as usize)));
    if let Some(col) = frame.divider.filter(|&c| c > 0 && c < frame.width) {
        for y in 0..h {
            img.put_pixel(col as u32, y, image::Rgb([255, 255, 255]));
        }
    }
    if frame.kind == FrameKind::RelativeDifference {
        img = with_colour_bar(&img);
    }
    img
}

/// Appends a colour bar for `DIFF_SCALE_DECADES` with its labels under `img`.
fn with_colour_bar(img: &image::RgbImage) -> image::RgbImage {
    let w = img.width();
    let scale = if w >= 400 { 2 } else { 1 };
    let bar = 6 * scale;
    let label = 5 * scale;
    let pad = 2 * scale;
    let extra = pad + bar + pad + label + pad;
    let mut out = image::RgbImage::from_pixel(w, img.height() + extra, image::Rgb(BACKGROUND));
    image::imageops::replace(&mut out, img, 0, 0);
    let top = img.height() + pad;
    // The margins shrink with an image narrower than they are (a 1-pixel-wide render still
    // gets its bar), so that `margin + span ≤ w`.
    let margin = (4 * scale).min(w / 4);
    let span = w - 2 * margin;
    for x in 0..span {
        let colour = crate::colormap::viridis(f64::from(x) / f64::from(span.max(2) - 1));
        for y in top..top + bar {
            out.put_pixel(margin + x, y, image::Rgb(colour));
        }
    }
    for (k, text) in ["0.1%", "1%", "10%", "100%"].iter().enumerate() {
        let centre = margin + span * k as u32 / 3;
        let text_w = glyph_text_width(text) * scale;
        // The end labels inside the margins (centred on the bar's ends, half of each fell off
        // the image's edge), the others centred on their tick.
        let left = match k {
            0 => margin,
            3 => (margin + span).saturating_sub(text_w),
            _ => centre.saturating_sub(text_w / 2),
        }
        .min(w.saturating_sub(text_w));
        draw_text(&mut out, text, left, top + bar + pad, scale);
    }
    out
}

/// A difference map's PNG (`to_rgb8`) with `caption` — what the image measures, such as
/// `RMSE 5.04% P99 12.3%` — on a line of its own under the colour bar, in the bar's glyphs.
pub fn png_with_caption(frame: &Frame, exposure: f64, caption: &str) -> Vec<u8> {
    let img = to_rgb8(frame, exposure);
    let w = img.width();
    let scale = if w >= 400 { 2 } else { 1 };
    let line = 7 * scale;
    let mut out = image::RgbImage::from_pixel(w, img.height() + line, image::Rgb(BACKGROUND));
    image::imageops::replace(&mut out, &img, 0, 0);
    draw_text(
        &mut out,
        caption,
        (4 * scale).min(w / 4),
        img.height() + scale,
        scale,
    );
    let mut bytes = Cursor::new(Vec::new());
    out.write_to(&mut bytes, image::ImageFormat::Png)
        .expect("encoding a PNG in memory cannot fail");
    bytes.into_inner()
}

/// 3×5 glyphs for the colour bar's labels and a caption's words, one row per `u8`, three low
/// bits left to right.
fn glyph(c: char) -> [u8; 5] {
    match c {
        '0' => [0b111, 0b101, 0b101, 0b101, 0b111],
        '1' => [0b010, 0b110, 0b010, 0b010, 0b111],
        '2' => [0b111, 0b001, 0b111, 0b100, 0b111],
        '3' => [0b111, 0b001, 0b011, 0b001, 0b111],
        '4' => [0b101, 0b101, 0b111, 0b001, 0b001],
        '5' => [0b111, 0b100, 0b111, 0b001, 0b111],
        '6' => [0b111, 0b100, 0b111, 0b101, 0b111],
        '7' => [0b111, 0b001, 0b010, 0b010, 0b010],
        '8' => [0b111, 0b101, 0b111, 0b101, 0b111],
        '9' => [0b111, 0b101, 0b111, 0b001, 0b111],
        '.' => [0b000, 0b000, 0b000, 0b000, 0b010],
        '%' => [0b101, 0b001, 0b010, 0b100, 0b101],
        'E' => [0b111, 0b100, 0b110, 0b100, 0b111],
        'M' => [0b101, 0b111, 0b111, 0b101, 0b101],
        'P' => [0b110, 0b101, 0b110, 0b100, 0b100],
        'R' => [0b110, 0b101, 0b110, 0b101, 0b101],
        'S' => [0b011, 0b100, 0b010, 0b001, 0b110],
        _ => [0; 5],
    }
}

fn glyph_text_width(text: &str) -> u32 {
    (text.chars().count() as u32 * 4).saturating_sub(1)
}

fn draw_text(img: &mut image::RgbImage, text: &str, left: u32, top: u32, scale: u32) {
    for (n, c) in text.chars().enumerate() {
        for (row, bits) in glyph(c).iter().enumerate() {
            for col in 0..3u32 {
                if bits & (0b100 >> col) == 0 {
                    continue;
                }
                for dy in 0..scale {
                    for dx in 0..scale {
                        let x = left + (n as u32 * 4 + col) * scale + dx;
                        let y = top + row as u32 * scale + dy;
                        if x < img.width() && y < img.height() {
                            img.put_pixel(x, y, image::Rgb([230, 230, 230]));
                        }
                    }
                }
            }
        }
    }
}

/// The frame as an RGB f32 OpenEXR file in memory (linear values, no tone map).
pub fn to_exr_bytes(frame: &Frame) -> Vec<u8> {
    use exr::prelude::*;
    let w = frame.width;
    let image = Image::from_channels(
        (frame.width, frame.height),
        SpecificChannels::rgb(|pos: Vec2<usize>| {
            let c = frame.pixels[pos.y() * w + pos.x()];
            (c.x as f32, c.y as f32, c.z as f32)
        }),
    );
    let mut out = Cursor::new(Vec::new());
    image
        .write()
        // Parallel compression writes chunks in the order they finish: the same image would
        // give different bytes run to run.
        .non_parallel()
        .to_buffered(&mut out)
        .expect("writing an EXR to memory cannot fail");
    out.into_inner()
}

/// The file format an output path asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ImageFormat {
    /// Tone-mapped 8-bit sRGB.
    Png,
    /// Linear f32 radiance.
    Exr,
}

impl ImageFormat {
    /// From the path's extension; anything but `.png` and `.exr` is refused, naming the path.
    pub fn of(path: &Path) -> Result<Self> {
        let ext = path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase());
        match ext.as_deref() {
            Some("png") => Ok(Self::Png),
            Some("exr") => Ok(Self::Exr),
            _ => Err(Error::input(
                path.display().to_string(),
                "the output must end in .png or .exr",
            )),
        }
    }
}

/// The frame encoded as `format`.
pub fn frame_bytes(frame: &Frame, format: ImageFormat, exposure: f64) -> Vec<u8> {
    match format {
        ImageFormat::Exr => to_exr_bytes(frame),
        ImageFormat::Png => {
            let mut out = Cursor::new(Vec::new());
            to_rgb8(frame, exposure)
                .write_to(&mut out, image::ImageFormat::Png)
                .expect("encoding a PNG in memory cannot fail");
            out.into_inner()
        }
    }
}
