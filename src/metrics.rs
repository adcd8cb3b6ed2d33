//! Image error, measured the same way everywhere (docs/design.md §4).

use glam::DVec3;

use crate::render::{Frame, FrameKind};

/// Rec. 709 / sRGB luminance weights (ITU-R BT.709-6, item 3.3).
pub fn luminance(c: DVec3) -> f64 {
    c.dot(DVec3::new(0.2126, 0.7152, 0.0722))
}

/// The floor under the reference luminance in a relative difference, as a fraction of the
/// reference's mean luminance over the plane: pixels darker than 1% of the mean are near
/// black after tone mapping, and their relative error would only measure noise.
pub const RELATIVE_FLOOR: f64 = 1e-2;

/// The floor of `RELATIVE_FLOOR` for a reference image, never zero. Where the reference is
/// black all over (figure2-case1: the light is below the plane) the approximation stands in,
/// so that the glow of an unclipped LTC reads as a finite ratio (≤ 100 × the number of
/// pixels), not as infinity. Magnitudes: without the case-2 rule the approximation holds
/// negative light, and its plain mean can be ≤ 0.
pub fn relative_floor(exact: &Frame, approx: &Frame) -> f64 {
    let exact_mean = mean_abs_luminance(exact);
    let mean = if exact_mean > 0.0 {
        exact_mean
    } else {
        mean_abs_luminance(approx)
    };
    (RELATIVE_FLOOR * mean).max(f64::MIN_POSITIVE)
}

/// The mean of |luminance| over the plane's pixels (0 without any).
pub fn mean_abs_luminance(frame: &Frame) -> f64 {
    let (sum, count) = plane_pixels(frame).fold((0.0, 0usize), |(s, n), (_, c)| {
        (s + luminance(c).abs(), n + 1)
    });
    if count > 0 { sum / count as f64 } else { 0.0 }
}

/// The least and largest luminance over the plane's pixels (each clamped through zero: 0
/// without any of that sign), and how many are negative — the clipping pictures' exposure
/// and the size of case 2's negative light.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LuminanceRange {
    pub min: f64,
    pub max: f64,
    pub negative: usize,
}

pub fn luminance_range(frame: &Frame) -> LuminanceRange {
    plane_pixels(frame).fold(LuminanceRange::default(), |r, (_, c)| {
        let l = luminance(c);
        LuminanceRange {
            min: r.min.min(l),
            max: r.max.max(l),
            negative: r.negative + usize::from(l < 0.0),
        }
    })
}

fn plane_pixels(frame: &Frame) -> impl Iterator<Item = (usize, DVec3)> + '_ {
    frame
        .pixels
        .iter()
        .enumerate()
        .filter(|(k, _)| frame.on_plane[*k])
        .map(|(k, c)| (k, *c))
}

/// Per pixel `|L_ltc − L_exact| / max(L_exact, floor)` on luminance; zero off the plane.
pub fn relative_difference(approx: &Frame, exact: &Frame) -> Frame {
    let floor = relative_floor(exact, approx);
    let pixels = approx
        .pixels
        .iter()
        .zip(&exact.pixels)
        .zip(&exact.on_plane)
        .map(|((a, e), &on)| {
            if !on {
                return DVec3::ZERO;
            }
            DVec3::splat(relative_error(luminance(*a), luminance(*e), floor))
        })
        .collect();
    Frame {
        kind: FrameKind::RelativeDifference,
        pixels,
        divider: None,
        ..exact.clone()
    }
}

/// `|a − e| / max(e, floor)`: one pixel of the difference map.
pub fn relative_error(a: f64, e: f64, floor: f64) -> f64 {
    (a - e).abs() / e.max(floor)
}

/// The image error of docs/design.md §4.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImageError {
    /// `sqrt(Σ (L_a − L_e)²) / sqrt(Σ L_e²)` over the plane's pixels (luminance).
    pub rel_rmse: f64,
    /// Largest per-pixel relative difference.
    pub max_rel: f64,
    /// 99th percentile of the per-pixel relative difference.
    pub p99_rel: f64,
}

pub fn image_error(approx: &Frame, exact: &Frame) -> ImageError {
    let (mut num, mut den) = (0.0, 0.0);
    for (k, e) in plane_pixels(exact) {
        let (la, le) = (luminance(approx.pixels[k]), luminance(e));
        num += (la - le) * (la - le);
        den += le * le;
    }
    let diff = relative_difference(approx, exact);
    let mut rel: Vec<f64> = plane_pixels(&diff).map(|(_, c)| c.x).collect();
    rel.sort_by(f64::total_cmp);
    let p99 = if rel.is_empty() {
        0.0
    } else {
        rel[((rel.len() - 1) as f64 * 0.99).round() as usize]
    };
    ImageError {
        rel_rmse: if den > 0.0 { (num / den).sqrt() } else { 0.0 },
        max_rel: rel.last().copied().unwrap_or(0.0),
        p99_rel: p99,
    }
}
