//! The 4D tables measured against the exact anisotropic lobe (docs/design.md §2.9, §4.11):
//! each table's pointwise lobe error `∫ |n D − f cos| dω / ∫ f cos dω` (§4.1, `n` the true
//! albedo, so that only the matrix is judged) at a set of points of the domain, read as
//! each table reads itself there — a node of its own exactly, any other point interpolated.
//! The points: a table's nodes, and the midpoints between them (the centres of its grid's
//! cells, where interpolation is worst).

use glam::DVec3;
use rayon::prelude::*;

use crate::brdf::Alpha;
use crate::ltc::aniso::lobe::{aniso_magnitudes, aniso_quadrature};
use crate::ltc::aniso::{AnisoAxes, AnisoLut, AnisoPoint};
use crate::ltc::lobe::{Stratum, strata};

/// Strata per side of the measure's quadrature (65 536 nodes a point): 4× the fit's 64 per
/// side, none of its nodes shared, so a table is not measured where it was fitted.
pub const MEASURE_STRATA: usize = 256;

/// One point of the domain, by material and a unit view in the tangent frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LobePoint {
    pub alpha: Alpha<f64>,
    pub view: DVec3,
}

impl LobePoint {
    pub fn of(q: &AnisoPoint) -> Self {
        Self {
            alpha: q.alpha,
            view: q.view(),
        }
    }
}

/// The lobe error of each table at `point`, with the lobe's true albedo as their magnitude.
pub fn lobe_errors(tables: &[&AnisoLut], point: &LobePoint, quadrature: &[Stratum]) -> Vec<f64> {
    let q = aniso_quadrature(point.view, point.alpha, quadrature);
    let (norm, fresnel) = aniso_magnitudes(point.view, point.alpha, quadrature);
    tables
        .iter()
        .map(|t| {
            let ltc = t.ltc(point.alpha, point.view);
            let ltc = crate::ltc::Ltc::from_cos_from_brdf(ltc.cos_from_brdf, norm, fresnel);
            q.relative_l1_ltc(&ltc, norm)
        })
        .collect()
}

/// The points of a table's own domain: its nodes (`midpoints = false`) or the centres of
/// the cells between them, on the axes of `axes` with `dims` nodes per axis.
pub fn domain_points(axes: AnisoAxes, dims: [usize; 4], midpoints: bool) -> Vec<AnisoPoint> {
    if !midpoints {
        return crate::ltc::aniso::all_nodes(dims)
            .map(|k| axes.node(k, dims))
            .collect();
    }
    // A cell's centre: the node map at half-integer indices, by averaging the axis
    // coordinates of its corners (each axis's coordinate is linear in the index).
    let fine = dims.map(|n| 2 * n - 1);
    crate::ltc::aniso::all_nodes(fine)
        .filter(|k| k.iter().all(|&i| i % 2 == 1))
        .map(|k| axes.node(k, fine))
        .collect()
}

/// Every table's error at every point, in parallel: `errors[point][table]`.
pub fn errors_at(tables: &[&AnisoLut], points: &[AnisoPoint]) -> Vec<Vec<f64>> {
    let quadrature = strata(MEASURE_STRATA);
    points
        .par_iter()
        .map(|q| lobe_errors(tables, &LobePoint::of(q), &quadrature))
        .collect()
}
