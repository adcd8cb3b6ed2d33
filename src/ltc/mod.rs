//! Linearly Transformed Cosines (Heitz et al. 2016) for point lights, docs/design.md §1.
//!
//! A distribution `D(ω)` is the clamped cosine pushed through a 3×3 matrix `M`
//! (`brdf_from_cos`); it is evaluated through `M⁻¹` (`cos_from_brdf`):
//! `D(ω) = max(ω'.z, 0) · |det M⁻¹| / (π (ω'·ω')²)`, `ω' = M⁻¹ ω`.

pub mod aniso;
pub mod cell_fitter;
pub mod exr_bytes;
pub mod fit;
pub mod fit_point;
pub mod formats;
pub mod lobe;
pub mod lut;
pub mod nelder_mead;
pub mod nl_fit;
pub mod point_params;
pub mod remedy;
pub mod sphere;

use glam::{DMat3, DVec3};

use crate::brdf::Lobes;
use crate::named::named_enum;

/// Which of the paper's two light-clipping rules (eq. 30) are applied. The paper applies both.
/// The command line names them by what they test: `horizon` (case 1) and `transformed` (case 2).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct Clipping {
    /// Case 1: a light below the surface (`n·l ≤ 0`) contributes nothing. Off, `M⁻¹` can lift
    /// it above the horizon and it glows (the paper's Figure 2c).
    pub case1: bool,
    /// Case 2: a light that `M⁻¹` pushes below the horizon (`(M⁻¹l).z ≤ 0`) contributes
    /// nothing. Off, it contributes negative light.
    pub case2: bool,
}

impl Clipping {
    /// The paper's eq. 30: both rules.
    pub const BOTH: Self = Self {
        case1: true,
        case2: true,
    };
    /// Case 1's rule alone (`--clip horizon`).
    pub const CASE1: Self = Self {
        case1: true,
        case2: false,
    };
    /// Case 2's rule alone (`--clip transformed`).
    pub const CASE2: Self = Self {
        case1: false,
        case2: true,
    };
    pub const NONE: Self = Self {
        case1: false,
        case2: false,
    };

    /// Every combination, named as on the command line.
    pub const ALL: [Self; 4] = [Self::BOTH, Self::CASE1, Self::CASE2, Self::NONE];

    /// `both`, `horizon` (case 1's rule only), `transformed` (case 2's only) or `none`.
    pub fn name(self) -> &'static str {
        match (self.case1, self.case2) {
            (true, true) => "both",
            (true, false) => "horizon",
            (false, true) => "transformed",
            (false, false) => "none",
        }
    }
}

impl Default for Clipping {
    fn default() -> Self {
        Self::BOTH
    }
}

named_enum! {
    /// How the LTC sum is normalized.
    #[derive(
        Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
    )]
    pub enum Normalization {
        /// docs/design.md §1: `D` carries its 1/π, and each lobe its magnitude (`F0 n_s + (1−F0) f_s` for
        /// specular, `n_d` for diffuse).
        #[default]
        Corrected = "corrected",
        /// The paper's eq. 25/30 as printed: no 1/π and no magnitudes (kept to show the cost).
        PaperLiteral = "paper",
    }
}

impl Normalization {}

/// One fitted lobe: its matrix both ways, `|det M⁻¹|`, and its magnitudes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ltc {
    /// `M⁻¹`: maps a direction of the BRDF lobe to the clamped-cosine domain.
    pub cos_from_brdf: DMat3,
    /// `M`: maps the clamped cosine onto the BRDF lobe.
    pub brdf_from_cos: DMat3,
    /// `|det M⁻¹|`.
    pub det_cos_from_brdf: f64,
    /// `∫ f cos dω` with F = 1 (specular) or c = 1 (diffuse): the directional albedo.
    pub norm: f64,
    /// The Schlick part `∫ (1 − v·h)⁵ f cos dω` (specular; zero for diffuse).
    pub fresnel: f64,
    /// A fitted factor on the magnitude: the lobe is shaded as `scale × magnitude × D`. One,
    /// but in the point-light table's specular lobe, where it is fitted with the matrix
    /// (`crate::ltc::fit_point`) while `norm` stays the true albedo.
    pub scale: f64,
}

impl Ltc {
    /// From `M⁻¹`, which may be scaled arbitrarily (`D` does not change).
    pub fn from_cos_from_brdf(cos_from_brdf: DMat3, norm: f64, fresnel: f64) -> Self {
        Self {
            cos_from_brdf,
            brdf_from_cos: cos_from_brdf.inverse(),
            det_cos_from_brdf: cos_from_brdf.determinant().abs(),
            norm,
            fresnel,
            scale: 1.0,
        }
    }

    /// From `M`.
    pub fn from_brdf_from_cos(brdf_from_cos: DMat3, norm: f64, fresnel: f64) -> Self {
        let cos_from_brdf = brdf_from_cos.inverse();
        Self {
            cos_from_brdf,
            brdf_from_cos,
            det_cos_from_brdf: cos_from_brdf.determinant().abs(),
            norm,
            fresnel,
            scale: 1.0,
        }
    }

    /// The same lobe with its magnitude scaled by `scale`.
    pub fn with_scale(self, scale: f64) -> Self {
        Self { scale, ..self }
    }

    /// `scale × norm`: the diffuse lobe's magnitude, the specular one's at F0 = 1.
    pub fn magnitude(&self) -> f64 {
        self.scale * self.norm
    }

    /// The clamped cosine itself (`M = I`).
    pub fn identity() -> Self {
        Self::from_cos_from_brdf(DMat3::IDENTITY, 1.0, 0.0)
    }

    /// `D(l)` for a unit `l` in the shading frame, with the given clipping rules;
    /// `PaperLiteral` drops the 1/π (eq. 25).
    pub fn ltc_eval(&self, l: DVec3, clip: Clipping, normalization: Normalization) -> f64 {
        if clip.case1 && l.z <= 0.0 {
            return 0.0;
        }
        let w = self.cos_from_brdf * l;
        if clip.case2 && w.z <= 0.0 {
            return 0.0;
        }
        let len2 = w.length_squared();
        if len2 <= 0.0 || !len2.is_finite() {
            return 0.0;
        }
        let d = w.z * self.det_cos_from_brdf / (len2 * len2);
        match normalization {
            Normalization::Corrected => d / std::f64::consts::PI,
            Normalization::PaperLiteral => d,
        }
    }

    /// A direction distributed as `D`: a cosine-distributed sample pushed through `M`
    /// (the inverse of `ltc_eval`'s change of variables).
    pub fn sample(&self, u1: f64, u2: f64) -> DVec3 {
        self.sample_cosine(cosine_sample(u1, u2))
    }

    /// `sample` for a cosine-distributed direction already drawn.
    pub fn sample_cosine(&self, cosine: DVec3) -> DVec3 {
        (self.brdf_from_cos * cosine).normalize()
    }
}

/// Malley's method: a direction on the upper hemisphere with density `cos θ / π`.
pub fn cosine_sample(u1: f64, u2: f64) -> DVec3 {
    let r = u1.sqrt();
    let phi = std::f64::consts::TAU * u2;
    DVec3::new(r * phi.cos(), r * phi.sin(), (1.0 - u1).max(0.0).sqrt())
}

/// The two fitted lobes of one (θo, α), as the LUT gives them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LtcPair {
    pub spec: Ltc,
    pub diff: Ltc,
}

impl LtcPair {
    /// The LTC of `lobe`.
    pub fn lobe(&self, lobe: lobe::Lobe) -> &Ltc {
        match lobe {
            lobe::Lobe::Specular => &self.spec,
            lobe::Lobe::Diffuse => &self.diff,
        }
    }

    /// The specular magnitude for a material with `F0` (docs/design.md §1): `F0 n_s + (1 − F0) f_s`,
    /// times the fitted scale.
    pub fn spec_magnitude(&self, f0: f64) -> f64 {
        self.spec.scale * (f0 * self.spec.norm + (1.0 - f0) * self.spec.fresnel)
    }

    /// Each lobe's magnitude (specular, diffuse), by which a light with a size scales its
    /// integrals of D: none under the paper-literal normalization (eq. 25 as printed).
    pub fn lobe_weights(&self, f0: f64, normalization: Normalization) -> (f64, f64) {
        match normalization {
            Normalization::Corrected => (self.spec_magnitude(f0), self.diff.magnitude()),
            Normalization::PaperLiteral => (1.0, 1.0),
        }
    }

    /// The LTC approximation of both cosine-weighted lobes for a unit-irradiance light in
    /// direction `l` (unit, shading frame), base colour 1 (eq. 30 with the corrections of docs/design.md §1).
    pub fn ltc_lobes(
        &self,
        l: DVec3,
        f0: f64,
        clip: Clipping,
        normalization: Normalization,
    ) -> Lobes<f64> {
        let (spec_weight, diff_weight) = match normalization {
            Normalization::Corrected => (self.spec_magnitude(f0), self.diff.magnitude()),
            Normalization::PaperLiteral => (1.0, 1.0),
        };
        Lobes {
            specular: spec_weight * self.spec.ltc_eval(l, clip, normalization),
            diffuse: diff_weight * self.diff.ltc_eval(l, clip, normalization),
        }
    }
}

named_enum! {
    /// Which clipping case a light direction falls in for a lobe (docs/design.md §1, the paper's §2.5):
    /// the four combinations of above/below the horizon before and after `M⁻¹`.
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
    pub enum ClipCase {
        /// Above the horizon before and after the transform: shaded as fitted.
        Visible = "visible",
        /// Case 1: below the horizon (`n·l ≤ 0`) but lifted above it by `M⁻¹` — without the
        /// horizon rule it glows (the paper's Figure 2c).
        Lifted = "case 1 (lifted)",
        /// Case 2: above the horizon but pushed below it (`(M⁻¹l).z ≤ 0`) — without the
        /// transformed rule it is negative light.
        PushedBelow = "case 2 (pushed below)",
        /// Below the horizon and still below after `M⁻¹`: either rule removes it.
        StaysBelow = "below, stays below",
    }
}

impl ClipCase {
    /// The case of a direction `l` that `M⁻¹` maps to `transformed` (either need not be
    /// unit): which sides of the horizon the two are on.
    pub fn of(l: DVec3, transformed: DVec3) -> Self {
        match (l.z > 0.0, transformed.z > 0.0) {
            (true, true) => ClipCase::Visible,
            (true, false) => ClipCase::PushedBelow,
            (false, true) => ClipCase::Lifted,
            (false, false) => ClipCase::StaysBelow,
        }
    }
}

impl Ltc {
    pub fn clip_case(&self, l: DVec3) -> ClipCase {
        ClipCase::of(l, self.cos_from_brdf * l)
    }
}

impl LtcPair {
    /// The case of a light for both lobes: an artifact of either lobe (case 1 or case 2)
    /// names it; `l` is above or below the horizon for both alike.
    pub fn clip_case(&self, l: DVec3) -> ClipCase {
        let (s, d) = (self.spec.clip_case(l), self.diff.clip_case(l));
        if s == d || d == ClipCase::Visible || d == ClipCase::StaysBelow {
            s
        } else {
            d
        }
    }
}

/// `M⁻¹ = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]]` from the four entries a LUT cell stores,
/// in the channels' order `m00, m02, m20, m22` (docs/design.md §2).
pub fn cos_from_brdf_from_entries(m: [f64; 4]) -> DMat3 {
    mat3_from_rows([[m[0], 0.0, m[1]], [0.0, 1.0, 0.0], [m[2], 0.0, m[3]]])
}

/// A 3×3 matrix from its rows (glam stores columns).
pub fn mat3_from_rows(rows: [[f64; 3]; 3]) -> DMat3 {
    DMat3::from_cols_array_2d(&rows).transpose()
}

/// The rows of a matrix.
pub fn mat3_rows(m: DMat3) -> [[f64; 3]; 3] {
    m.transpose().to_cols_array_2d()
}
