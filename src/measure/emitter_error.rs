//! Every emitter measured alike (docs/design.md §4.9): each of its methods' error against its
//! exact integral, by the light's solid angle, the elevation of its centre and the roughness,
//! over views θo from 0 to 80° — Σ|method − exact| / Σ exact per lobe. The lights are drawn by
//! their shape's module (`ShapeKind::error_sample`), so a new shape is measured by naming it;
//! `examples/emitter_errors.rs` prints the tables.

use glam::DVec3;
use rayon::prelude::*;

use crate::brdf::{Alpha, Lobes, view_from_theta};
use crate::light::{EmitterShading, ExactRule, ShapeKind};
use crate::ltc::lut::Lut;
use crate::ltc::{Clipping, Normalization};
use crate::measure::shape_error::{BANDS, F0, SIZES};
use crate::render::ShapeMethod;
use crate::scene::SplitMix64;

/// Roughness bands: sharp, middling and rough (the other tables' α from 0.1 to 0.8, in
/// three).
pub const ALPHAS: [[f64; 2]; 3] = [[0.1, 0.3], [0.3, 0.55], [0.55, 0.8]];

/// One cell: a solid angle, a band of the centre's elevation and one of α, and each method's
/// `[specular, diffuse]` error, in `ShapeMethod::all`'s order, the reference left out.
#[derive(Clone, Debug, PartialEq)]
pub struct EmitterError {
    pub solid_angle: f64,
    pub band: [f64; 2],
    pub alpha: [f64; 2],
    pub cases: usize,
    pub methods: Vec<(ShapeMethod, [f64; 2])>,
}

/// The methods a table of `kind` measures: all but its reference.
pub fn measured(kind: ShapeKind) -> Vec<ShapeMethod> {
    let reference = ShapeMethod::reference(kind);
    ShapeMethod::all(kind)
        .into_iter()
        .filter(|&m| m != reference)
        .collect()
}

/// Every (size, band, α) cell of `kind`'s table over `cases` cases each, seeded; the
/// reference at the shape's own nodes (`ShapeKind::exact_nodes`). Empty for a shape that is
/// not an emitter.
pub fn emitter_errors(kind: ShapeKind, lut: &Lut, cases: usize, seed: u64) -> Vec<EmitterError> {
    let cells: Vec<(usize, usize, usize)> = (0..SIZES.len())
        .flat_map(|s| (0..BANDS.len()).flat_map(move |b| (0..ALPHAS.len()).map(move |a| (s, b, a))))
        .collect();
    if kind.error_sample().is_none() {
        return Vec::new();
    }
    cells
        .par_iter()
        .enumerate()
        .map(|(index, &(s, b, a))| {
            let mut rng = SplitMix64(seed.wrapping_add(index as u64));
            cell(kind, lut, (SIZES[s], BANDS[b], ALPHAS[a]), cases, &mut rng)
        })
        .collect()
}

fn cell(
    kind: ShapeKind,
    lut: &Lut,
    (omega, band, alphas): (f64, [f64; 2], [f64; 2]),
    cases: usize,
    rng: &mut SplitMix64,
) -> EmitterError {
    let sample = kind.error_sample().expect("an emitter");
    let methods = measured(kind);
    let reference = ShapeMethod::reference(kind);
    let rule = ExactRule::Nodes(kind.exact_nodes());
    // Σ|method − exact| per method and lobe, and Σ exact per lobe.
    let mut errors = vec![[0.0f64; 2]; methods.len()];
    let mut total = [0.0f64; 2];
    let same = |w: DVec3| w;
    for _ in 0..cases {
        let theta_o = rng.uniform([0.0, 80.0]);
        let alpha = rng.uniform(alphas);
        let v = DVec3::from(view_from_theta(theta_o.to_radians()));
        let (elevation, azimuth) = (
            rng.uniform(band).to_radians(),
            rng.uniform([0.0, 360.0]).to_radians(),
        );
        let (se, ce) = elevation.sin_cos();
        let (sa, ca) = azimuth.sin_cos();
        let direction = DVec3::new(ce * ca, ce * sa, se);
        let (shape, centre) = sample(&mut |r| rng.uniform(r), omega, direction);
        let pair = lut.ltc_pair(alpha, v);
        let s = EmitterShading {
            v,
            alpha: Alpha::isotropic(alpha),
            f0: F0,
            ltc: &pair,
            clip: Clipping::BOTH,
            normalization: Normalization::Corrected,
        };
        let lobes = |m: ShapeMethod| -> Lobes<f64> {
            m.emitter_lobes((shape, centre), &same, &s, rule)
                .map_or_else(Lobes::default, |(l, _)| l)
        };
        let exact = lobes(reference);
        total[0] += exact.specular;
        total[1] += exact.diffuse;
        for (e, &m) in errors.iter_mut().zip(&methods) {
            let got = lobes(m);
            e[0] += (got.specular - exact.specular).abs();
            e[1] += (got.diffuse - exact.diffuse).abs();
        }
    }
    EmitterError {
        solid_angle: omega,
        band,
        alpha: alphas,
        cases,
        methods: methods
            .into_iter()
            .zip(errors)
            .map(|(m, e)| (m, [0, 1].map(|k| e[k] / total[k].max(1e-300))))
            .collect(),
    }
}
