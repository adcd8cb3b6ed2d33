//! The anisotropic specular lobe an LTC of the 4D table is fitted to and measured against
//! (docs/design.md §2.9): `f cos = D G2 / (4 cos θo)` with F = 1, sampled by its visible
//! normals, its magnitudes, and the overlap quadrature of its pointwise L1 error.

use glam::DVec3;

use crate::brdf::Alpha;
use crate::brdf::aniso::{d_ggx_aniso, g2_correlated_aniso, lambda_ggx_aniso};
use crate::ltc::fit_point::{CellQuadrature, Node};
use crate::ltc::lobe::{Stratum, visible_normal_aniso};

/// `G1(v) = 1 / (1 + Λ(v))`.
fn g1(v: DVec3, alpha: Alpha<f64>) -> f64 {
    1.0 / (1.0 + lambda_ggx_aniso(v.to_array(), alpha))
}

/// The lobe's node for stratum `s`: the direction reflected about a visible normal, its
/// density `G1(v) D(h) / (4 v.z)` (Heitz 2018 eq. 3, divided by `4 v·h` by the reflection)
/// and its weight `f cos / pdf = G2 / G1(v)`, at most 1; `None` where the lobe is zero.
pub fn aniso_node(v: DVec3, alpha: Alpha<f64>, s: &Stratum) -> Option<Node> {
    let h = visible_normal_aniso(v, alpha, s);
    let l = 2.0 * h.dot(v) * h - v;
    let g1 = g1(v, alpha);
    let pdf = g1 * d_ggx_aniso(h.to_array(), alpha) / (4.0 * v.z);
    let weight = g2_correlated_aniso(v.to_array(), l.to_array(), alpha) / g1;
    (weight > 0.0 && pdf > 0.0 && l.z > 0.0).then_some(Node { l, pdf, weight })
}

/// The overlap quadrature of one anisotropic lobe over `strata` (`CellQuadrature`'s, with
/// this lobe's nodes).
pub fn aniso_quadrature(v: DVec3, alpha: Alpha<f64>, strata: &[Stratum]) -> CellQuadrature {
    let nodes = strata
        .iter()
        .filter_map(|s| aniso_node(v, alpha, s))
        .collect();
    CellQuadrature::from_nodes(nodes, strata.len())
}

/// The lobe's magnitudes: `n = ∫ f cos dω` (F = 1) and `f = ∫ (1 − v·h)⁵ f cos dω`, the Schlick
/// split of docs/design.md §1.5, by the same visible-normal sampling (`lobe_moments`'s).
pub fn aniso_magnitudes(v: DVec3, alpha: Alpha<f64>, strata: &[Stratum]) -> (f64, f64) {
    let (mut norm, mut fresnel) = (0.0, 0.0);
    for s in strata {
        if let Some(node) = aniso_node(v, alpha, s) {
            let h = (v + node.l).normalize_or_zero();
            norm += node.weight;
            fresnel += node.weight * (1.0 - v.dot(h).max(0.0)).powi(5);
        }
    }
    let count = strata.len() as f64;
    (norm / count, fresnel / count)
}
