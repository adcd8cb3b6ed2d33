//! What a table may hold (docs/design.md §2.5): each channel's range, with why, and the
//! matrices' orientation. Every reader of a table file checks it before use.

use crate::ltc::lobe::Lobe;
use crate::ltc::lut::{Channel, Lut, LutCell};

/// The values a channel may hold in a table that any fit could have made, and why.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChannelLimits {
    pub min: f64,
    /// Whether `min` itself is refused (albedos and scales divide and multiply).
    pub min_excluded: bool,
    pub max: f64,
    pub why: &'static str,
}

impl ChannelLimits {
    pub fn contains(&self, x: f64) -> bool {
        (if self.min_excluded {
            x > self.min
        } else {
            x >= self.min
        }) && x <= self.max
    }

    /// `[a, b]` or `(a, b]`.
    pub fn interval(&self) -> String {
        let open = if self.min_excluded { '(' } else { '[' };
        format!("{open}{}, {}]", self.min, self.max)
    }
}

impl Channel {
    /// The values this channel may hold.
    pub fn limits(self) -> ChannelLimits {
        use Channel::*;
        let limits = |min, min_excluded, max, why| ChannelLimits {
            min,
            min_excluded,
            max,
            why,
        };
        match self {
            SpecNorm | SpecFresnel => limits(
                0.0,
                self == SpecNorm,
                // 1.05 for the albedo, times the fits' largest scale (1.1), which tables in
                // ltc_code's layout carry folded into these channels.
                1.05 * 1.1 * (1.0 + f64::from(f32::EPSILON)),
                "GGX's directional albedo is at most 1 (single scattering only loses energy), 5% for estimation noise, times the fitted scale (at most 1.1) that ltc_code's layout folds in",
            ),
            DiffNorm => limits(
                0.0,
                true,
                6.25,
                "Burley's fd·cos integrates to at most FD² = (0.5 + 2α)² ≤ 6.25; the shipped fits reach 1.56 at α = 1",
            ),
            SpecScale => limits(
                0.0,
                true,
                // The fits' cap (`point_params::SCALE_MAX`), as f32 rounds it up.
                1.1 * (1.0 + f64::from(f32::EPSILON)),
                "a fitted factor on the albedo: 1 in the classic fit, 0.5–1.004 in the point fit, up to 1.1 (the fits' cap) in the arrival fit",
            ),
            SpecErr | DiffErr => limits(
                0.0,
                false,
                4.0,
                "a relative L1 distance of two lobes of near-equal mass, at most 2.05; twice that for estimation noise",
            ),
            SpecM00 | SpecM02 | SpecM20 | SpecM22 | DiffM00 | DiffM02 | DiffM20 | DiffM22 => {
                limits(
                    -100.0,
                    false,
                    100.0,
                    "M⁻¹ divided by its middle element: ltc_code's and this project's fits stay below 2 in magnitude",
                )
            }
        }
    }
}

impl Lut {
    /// Values no fit produces: a channel outside its limits, or a singular or reflecting
    /// `M⁻¹`.
    pub fn validate(&self) -> std::result::Result<(), String> {
        for (k, cell) in self.cells.iter().enumerate() {
            let at = format!("cell (i={}, j={})", k % self.size, k / self.size);
            for c in Channel::ALL {
                let x = f64::from(cell.get(c));
                let limits = c.limits();
                if !limits.contains(x) {
                    return Err(format!(
                        "{} at {at} is {}, outside {} ({})",
                        c.name(),
                        crate::error::number(x),
                        limits.interval(),
                        limits.why
                    ));
                }
            }
            for lobe in Lobe::ALL {
                let det = determinant(cell, lobe);
                if det <= 0.0 {
                    return Err(format!(
                        "the {} matrix at {at} has determinant {} (must be > 0)",
                        lobe.name(),
                        crate::error::number(det)
                    ));
                }
            }
        }
        Ok(())
    }

    /// Cells whose `M⁻¹` (either lobe's) is singular or reflecting — flat or turned inside
    /// out, as an encoding makes it where its error passes `M⁻¹`'s small entries
    /// (docs/design.md §2.10).
    pub fn inside_out_cells(&self) -> usize {
        let inside_out = |cell: &&LutCell| Lobe::ALL.iter().any(|&l| determinant(cell, l) <= 0.0);
        self.cells.iter().filter(inside_out).count()
    }
}

/// The determinant of a lobe's stored `M⁻¹` (its middle entry 1).
fn determinant(cell: &LutCell, lobe: Lobe) -> f64 {
    let [m00, m02, m20, m22] = Channel::entries(lobe).map(|c| f64::from(cell.get(c)));
    m00 * m22 - m02 * m20
}
