//! A finished refit of one cell (`app::matrix::refit` runs it): the lab keeps it as a part, the
//! matrix panel plots it and the lobe panel draws its lobe. Plain data, checked on entry.

use serde::{Deserialize, Serialize};

use crate::ltc::lobe::Lobe;
use crate::ltc::lut::{Channel, Lut};
use crate::ltc::{Ltc, mat3_from_rows};
use crate::named::named_enum;

named_enum! {
    /// Which fitter a refit runs: each shipped table is the minimum of its own objective, so a
    /// cell is refitted with the one that made it.
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
    pub enum Objective {
        /// ltc_code's fit (`fit.rs`): Nelder–Mead on the |·|³ error from both distributions; the
        /// classic table.
        #[default]
        LtcCode = "ltc_code",
        /// The point fit (`fit_point.rs`): the relative L1 error by the lobe-following
        /// quadrature, the four entries and the specular scale free; the point table.
        Point = "point L1",
    }
}

impl Objective {
    /// The objective that made `lut`, as far as its cells tell: the point fit is the only
    /// fitter here that frees the specular scale, and it moves it off 1 in some cells.
    pub fn of_lut(lut: &Lut) -> Self {
        if lut.cells.iter().any(|c| c.get(Channel::SpecScale) != 1.0) {
            Objective::Point
        } else {
            Objective::LtcCode
        }
    }
}

fn one() -> f64 {
    1.0
}

/// A finished refit: what the plot and the lobe panel need, kept between runs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RefitResult {
    pub lobe: Lobe,
    pub cell: (usize, usize),
    #[serde(default)]
    pub objective: Objective,
    /// The scale on the magnitude (`spec.scale`) of the refit and of the stored cell.
    #[serde(default = "one")]
    pub scale: f64,
    #[serde(default = "one")]
    pub stored_scale: f64,
    /// (iteration, best objective).
    pub history: Vec<[f64; 2]>,
    /// The refitted `M⁻¹`, rows, and the lobe's albedos.
    pub cos_from_brdf: [[f64; 3]; 3],
    pub norm: f64,
    pub fresnel: f64,
    /// The stored cell's `M⁻¹` (rows, divided by its middle element).
    pub stored: [[f64; 3]; 3],
    /// Pointwise error (docs/design.md §4) of the refit and of the stored cell, measured alike.
    pub error: f64,
    pub stored_error: f64,
    pub iterations: usize,
    /// Stopped by its tolerance (not the iteration limit, not a cancel).
    pub converged: bool,
    pub cancelled: bool,
}

impl RefitResult {
    /// Whether its numbers make a lobe: all finite, the matrix invertible, the albedos and
    /// scale positive (a stored state from anywhere holds what it holds).
    pub fn is_sound(&self) -> bool {
        let numbers = self
            .cos_from_brdf
            .iter()
            .chain(&self.stored)
            .flatten()
            .chain([
                &self.norm,
                &self.fresnel,
                &self.scale,
                &self.error,
                &self.stored_error,
            ]);
        let finite = numbers.copied().all(f64::is_finite);
        let det = mat3_from_rows(self.cos_from_brdf).determinant();
        finite && det.is_finite() && det != 0.0 && self.norm > 0.0 && self.scale > 0.0
    }

    pub fn ltc(&self) -> Ltc {
        Ltc::from_cos_from_brdf(mat3_from_rows(self.cos_from_brdf), self.norm, self.fresnel)
            .with_scale(self.scale)
    }
}
