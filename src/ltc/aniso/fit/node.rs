//! One node of the 4D fit (docs/design.md §2.9): its lobe's quadrature and magnitudes, the
//! entries its mirror symmetry frees, its objective, and the Nelder–Mead search over them.

use std::ops::ControlFlow;

use glam::{DMat3, DVec3};

use crate::brdf::Alpha;
use crate::ltc::aniso::AnisoPoint;
use crate::ltc::aniso::canonical::proper;
use crate::ltc::aniso::fit::AnisoFitSettings;
use crate::ltc::aniso::lobe::{aniso_magnitudes, aniso_node, aniso_quadrature};
use crate::ltc::fit_point::CellQuadrature;
use crate::ltc::lobe::Stratum;
use crate::ltc::nelder_mead::nelder_mead;
use crate::ltc::{Ltc, mat3_from_rows, mat3_rows};

/// Which entries of `M⁻¹` (row-major) a node's fit frees. The upper-left block is kept
/// symmetric (the canonical turn) and `m11` fixed (the scale): that leaves seven.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Symmetry {
    /// No mirror symmetry: `m00, m01 (= m10), m02, m12, m20, m21, m22`.
    None,
    /// Symmetric about the xz-plane (φ = 0): `m00, m02, m20, m22` — the 2D table's form.
    MirrorY,
    /// Symmetric about the yz-plane (φ = π/2): `m00, m12, m21, m22`.
    MirrorX,
    /// Both (normal view): `m00, m22`.
    Both,
}

impl Symmetry {
    /// The free entries' indices in the row-major matrix.
    pub fn free(self) -> &'static [usize] {
        match self {
            Self::None => &[0, 1, 2, 5, 6, 7, 8],
            Self::MirrorY => &[0, 2, 6, 8],
            Self::MirrorX => &[0, 5, 7, 8],
            Self::Both => &[0, 8],
        }
    }

    /// The symmetry of the lab's node at view index `t` of `nt`, azimuth index `p` of `np`.
    pub fn of_node(t: usize, p: usize, np: usize) -> Self {
        match (t == 0, p == 0, p + 1 == np) {
            (true, _, _) => Self::Both,
            (false, true, _) => Self::MirrorY,
            (false, false, true) => Self::MirrorX,
            _ => Self::None,
        }
    }

    /// `m` with the entries this symmetry zeroes set to zero, and `m10 = m01`.
    pub fn project(self, m: [f64; 9]) -> [f64; 9] {
        let mut out = [0.0; 9];
        out[4] = m[4];
        for &k in self.free() {
            out[k] = m[k];
        }
        out[3] = out[1];
        out
    }
}

/// What one node's fit works with: the lobe's quadrature and its true albedo, and a start
/// matched to the lobe's moments.
pub struct NodeProblem {
    pub quadrature: CellQuadrature,
    pub norm: f64,
    pub fresnel: f64,
    pub symmetry: Symmetry,
    /// `M⁻¹` of the LTC with the lobe's mean direction and spread (`moment_start`).
    pub moments: [f64; 9],
}

impl NodeProblem {
    pub fn new(q: &AnisoPoint, symmetry: Symmetry, fit: &[Stratum], measure: &[Stratum]) -> Self {
        let v = q.view();
        let (norm, fresnel) = aniso_magnitudes(v, q.alpha, measure);
        Self {
            quadrature: aniso_quadrature(v, q.alpha, fit),
            norm,
            fresnel,
            symmetry,
            moments: entries(moment_start(v, q.alpha, fit)),
        }
    }

    /// The objective at `M⁻¹`: the relative L1 error of `n D`, infinite for a matrix that is
    /// singular or not finite.
    pub fn objective(&self, m: &[f64; 9]) -> f64 {
        let cos_from_brdf = rows(m);
        let det = cos_from_brdf.determinant();
        let size = m.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        if !det.is_finite() || det.abs() <= 1e-12 * size * size * size {
            return f64::INFINITY;
        }
        let ltc = Ltc::from_cos_from_brdf(cos_from_brdf, self.norm, self.fresnel);
        self.quadrature.relative_l1_ltc(&ltc, self.norm)
    }

    /// Nelder–Mead over the free entries, in relative moves from `start` (each entry by its
    /// own size, floored at 1e-3 of the largest), restarted from its own result; the best
    /// matrix found and its objective.
    pub fn refine(&self, start: [f64; 9], settings: &AnisoFitSettings) -> ([f64; 9], f64) {
        self.refine_with(start, settings, &|m| self.objective(m))
    }

    /// `refine` of another objective over the same free entries.
    pub fn refine_with(
        &self,
        start: [f64; 9],
        settings: &AnisoFitSettings,
        objective: &dyn Fn(&[f64; 9]) -> f64,
    ) -> ([f64; 9], f64) {
        let mut best = self.symmetry.project(start);
        let mut best_value = objective(&best);
        for _ in 0..settings.restarts {
            let (m, value) = match self.symmetry.free().len() {
                7 => self.run::<7>(best, settings, objective),
                4 => self.run::<4>(best, settings, objective),
                _ => self.run::<2>(best, settings, objective),
            };
            if value < best_value {
                (best, best_value) = (m, value);
            }
        }
        (best, best_value)
    }

    fn run<const D: usize>(
        &self,
        start: [f64; 9],
        s: &AnisoFitSettings,
        objective: &dyn Fn(&[f64; 9]) -> f64,
    ) -> ([f64; 9], f64) {
        let free = self.symmetry.free();
        let largest = start.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        let step: [f64; D] = std::array::from_fn(|k| start[free[k]].abs().max(1e-3 * largest));
        let at = |p: &[f64; D]| {
            let mut m = start;
            for k in 0..D {
                m[free[k]] = start[free[k]] + p[k] * step[k];
            }
            m[3] = m[1];
            m
        };
        let minimum = nelder_mead(
            [0.0; D],
            s.simplex_delta,
            s.tolerance,
            s.max_iterations,
            |p| objective(&at(p)),
            |_, _| ControlFlow::Continue(()),
        );
        (at(&minimum.point), minimum.value)
    }
}

/// The LTC matched to the lobe's first two moments, a start that knows nothing of any other
/// node: `M = [2σ₁ e₁, 2σ₂ e₂, z]` with `z` the lobe's mean direction and `e₁, e₂`, `σ₁², σ₂²`
/// the principal axes and variances of its directions projected on the plane across `z`
/// (the clamped cosine's projections have variance ¼ along every axis, and `M` stretches
/// them by its first two columns). Returned as `M⁻¹`.
pub fn moment_start(v: DVec3, alpha: Alpha<f64>, fit: &[Stratum]) -> DMat3 {
    let nodes: Vec<_> = fit.iter().filter_map(|s| aniso_node(v, alpha, s)).collect();
    let total: f64 = nodes.iter().map(|n| n.weight).sum();
    let mean = nodes.iter().fold(DVec3::ZERO, |a, n| a + n.weight * n.l);
    let Some(z) = mean.try_normalize().filter(|_| total > 0.0) else {
        return DMat3::IDENTITY;
    };
    let x = z.any_orthonormal_vector();
    let y = z.cross(x);
    let (mut sxx, mut sxy, mut syy) = (0.0, 0.0, 0.0);
    for n in &nodes {
        let (a, b) = (n.l.dot(x), n.l.dot(y));
        sxx += n.weight * a * a;
        sxy += n.weight * a * b;
        syy += n.weight * b * b;
    }
    let (sxx, sxy, syy) = (sxx / total, sxy / total, syy / total);
    // The 2×2 covariance's eigenvalues and its major axis's angle.
    let half_gap = (0.25 * (sxx - syy).powi(2) + sxy * sxy).sqrt();
    let mid = 0.5 * (sxx + syy);
    let angle = 0.5 * (2.0 * sxy).atan2(sxx - syy);
    let (e1, e2) = (
        angle.cos() * x + angle.sin() * y,
        -angle.sin() * x + angle.cos() * y,
    );
    let spread = |variance: f64| 2.0 * variance.max(1e-12).sqrt();
    let brdf_from_cos =
        DMat3::from_cols(spread(mid + half_gap) * e1, spread(mid - half_gap) * e2, z);
    proper_inverse(brdf_from_cos)
}

/// `M⁻¹` of a forward matrix, with a positive determinant.
fn proper_inverse(brdf_from_cos: DMat3) -> DMat3 {
    proper(brdf_from_cos.inverse())
}

/// A matrix from its row-major entries.
pub fn rows(m: &[f64; 9]) -> DMat3 {
    mat3_from_rows([[m[0], m[1], m[2]], [m[3], m[4], m[5]], [m[6], m[7], m[8]]])
}

/// The row-major entries of a matrix.
pub fn entries(m: DMat3) -> [f64; 9] {
    let r = mat3_rows(m);
    [
        r[0][0], r[0][1], r[0][2], r[1][0], r[1][1], r[1][2], r[2][0], r[2][1], r[2][2],
    ]
}

/// The isotropic lobe's `M⁻¹` at view azimuth `φ` in the table's frame: `R(φ) M⁻¹ R(−φ)`,
/// the view-frame matrix turned (its canonical turn, since the 2D table's block is diagonal).
pub fn turned_isotropic(view_frame: DMat3, phi: f64) -> DMat3 {
    DMat3::from_rotation_z(phi) * view_frame * DMat3::from_rotation_z(-phi)
}
