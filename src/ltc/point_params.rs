//! The unknowns of one lobe's point fit (docs/design.md §4.7): the free entries of the
//! normalized `M⁻¹` and the scale on the magnitude, their bounds, which of them a fit frees,
//! and what it minimizes over them. The point fit's objectives (`fit_point`) and its search
//! (`cell_fitter`) both build on these.

use crate::ltc::lobe::Lobe;
use crate::ltc::lut::{Channel, LutCell};
use crate::ltc::{Ltc, cos_from_brdf_from_entries};

/// What a cell's fit minimizes: a relative L1 error of `scale · norm · D` against the lobe,
/// relative to `norm`.
pub trait CellObjective: Sync {
    fn relative_l1(&self, fit: &PointFit, norm: f64) -> f64;
}

/// One lobe of a point-fit cell: the free entries `m00, m02, m20, m22` of the normalized
/// `M⁻¹` and the scale on its magnitude.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointFit {
    pub entries: [f64; 4],
    pub scale: f64,
}

impl PointFit {
    pub fn ltc(&self, norm: f64, fresnel: f64) -> Ltc {
        Ltc::from_cos_from_brdf(cos_from_brdf_from_entries(self.entries), norm, fresnel)
            .with_scale(self.scale)
    }

    /// What a cell of a table stores for `lobe`.
    pub fn stored(cell: &LutCell, lobe: Lobe) -> Self {
        Self {
            entries: Channel::entries(lobe).map(|ch| f64::from(cell.get(ch))),
            scale: match lobe {
                Lobe::Specular => f64::from(cell.get(Channel::SpecScale)),
                Lobe::Diffuse => 1.0,
            },
        }
    }

    /// `det M⁻¹ > 0` and a scale in `[SCALE_MIN, SCALE_MAX]`.
    pub(crate) fn is_valid(&self) -> bool {
        let m = self.entries;
        let det = m[0] * m[3] - m[1] * m[2];
        let scale = (SCALE_MIN..=SCALE_MAX).contains(&self.scale);
        m.iter().all(|x| x.is_finite()) && det > 1e-12 && scale
    }
}

/// The smallest scale the fit may choose. Where no lobe of the family overlaps the exact
/// one (α = 1e-4 at θo = 90°) the L1 optimum is to switch the lobe off (error 1 instead of
/// 2); bilinear filtering would then dim the neighbouring cells' highlights too, so the fit
/// may at most halve the light.
pub const SCALE_MIN: f64 = 0.5;

/// The largest scale the fit may choose. The lobe objective never goes above 1.004; the
/// arrival objective goes to 1.06 where it should, and at the grazing `α_min` cell, where no
/// lobe of the family fits the sliver along the horizon, it would more than double the light
/// (2.3), which bilinear filtering would spread to the neighbouring highlights.
pub const SCALE_MAX: f64 = 1.1;

/// Which parameters the point fit frees for a lobe: the magnitude's scale only for the
/// specular lobe (the diffuse fit is within 2% already; docs/design.md §1 keeps its magnitude `n_d`).
pub fn fits_scale(lobe: Lobe) -> bool {
    lobe == Lobe::Specular
}

/// Which parameters a cell's fit frees beyond `m00, m02, m22`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Free {
    /// The scale on the magnitude (`fits_scale`).
    pub scale: bool,
    /// `m20`: fixed at 0 by the constrained fit.
    pub m20: bool,
}

impl Free {
    /// `fit` moved into the set: `m20` set to 0 where it is not free.
    pub(crate) fn project(self, fit: PointFit) -> PointFit {
        let mut entries = fit.entries;
        if !self.m20 {
            entries[2] = 0.0;
        }
        PointFit { entries, ..fit }
    }
}
