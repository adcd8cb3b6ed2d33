//! How closely a GPU frame must agree with the CPU reference, and how closely it does: one
//! measure for the native parity tests (tests/gpu_*.rs) and the browser's self-check
//! (`gpu::selfcheck`, docs/design.md §5.8).

use crate::metrics::{luminance, relative_floor};
use crate::render::Frame;

/// Per-pixel agreement of a GPU frame with the CPU reference: 2e-4 of
/// `max(|reference luminance|, floor)`. The GPU shades in f32. Its hit point is off by ~1e-7
/// relative (f32 ray arithmetic over a 5-unit scene), which the inverse-square falloff's
/// relative gradient 2/d (100 at d = 0.02, figure2-case2's light) turns into ~5e-5; f32
/// rounding of 1000-term sums and of the LUT blend adds ~1e-5. The largest difference
/// measured on lavapipe over all cases was 6.9e-5 (figure2-case1, no clipping,
/// paper-literal). The floor (1% of the reference's mean, `metrics::relative_floor`) covers
/// pixels near zero, where the clipping decisions may fall differently in f32 on terms that
/// vanish there.
pub const RADIANCE_TOLERANCE: f64 = 2e-4;

/// Pixels whose camera ray hits the plane in one precision only (its silhouette) are not
/// compared; at most this fraction of the image may be such.
pub const SILHOUETTE_FRACTION: f64 = 0.01;

/// How a GPU frame differs from the CPU's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Parity {
    /// The largest per-pixel difference, relative to `max(reference luminance, floor)`
    /// (infinite where the GPU wrote a non-finite value).
    pub max_rel_diff: f64,
    /// The pixel where it is.
    pub worst: usize,
    /// Pixels on the plane in one frame only.
    pub silhouette: usize,
    pub pixels: usize,
}

impl Parity {
    /// Measures `gpu` against `cpu` (frames of one size).
    pub fn of(gpu: &Frame, cpu: &Frame) -> Self {
        let floor = relative_floor(cpu, cpu);
        let mut parity = Self {
            max_rel_diff: 0.0,
            worst: 0,
            silhouette: 0,
            pixels: cpu.pixels.len(),
        };
        for k in 0..cpu.pixels.len() {
            if gpu.on_plane[k] != cpu.on_plane[k] {
                parity.silhouette += 1;
                continue;
            }
            let (g, c) = (gpu.pixels[k], cpu.pixels[k]);
            let err = if g.is_finite() {
                (g - c).abs().max_element() / luminance(c.abs()).max(floor)
            } else {
                f64::INFINITY
            };
            if err > parity.max_rel_diff {
                parity.max_rel_diff = err;
                parity.worst = k;
            }
        }
        parity
    }

    /// Whether the frames agree: within `RADIANCE_TOLERANCE`, and a silhouette within
    /// `SILHOUETTE_FRACTION`; else why not.
    pub fn check(&self) -> Result<(), String> {
        if self.silhouette as f64 > SILHOUETTE_FRACTION * self.pixels as f64 {
            return Err(format!(
                "{} of {} pixels differ in coverage",
                self.silhouette, self.pixels
            ));
        }
        if self.max_rel_diff > RADIANCE_TOLERANCE {
            return Err(format!(
                "pixel {} differs by {:.2e} (tolerance {RADIANCE_TOLERANCE:.0e})",
                self.worst, self.max_rel_diff
            ));
        }
        Ok(())
    }
}
