//! The `nl-fit` horizon remedy (docs/design.md §4.7): per cell of a table, a correction of
//! each lobe as a function of `n·l` alone, `w(z) = max(0, 1 + t (c₀ + c₁ t))` with
//! `t = max(0, 1 − z / NL_BAND_Z)`, so that lights above 30° are shaded as fitted and lights
//! below are scaled by a quadratic that vanishes at 30°. The coefficients are fitted to the
//! exact lobe by least squares over the light directions below 30° and kept with the table
//! (`Lut::nl_terms`, and beside each cell on the GPU): two multiply-adds and a max per light
//! and lobe.

use glam::DVec3;
use rayon::prelude::*;

use crate::ltc::lobe::Lobe;
use crate::ltc::lut::{Lut, LutSample, bilinear_taps};
use crate::ltc::{Clipping, LtcPair, Normalization};

/// Where the correction ends: `n·l` = sin 30°, the top of the last band of docs/design.md
/// §4.7 where the LTC is worse than above it.
pub const NL_BAND_Z: f64 = 0.5;

/// The elevation bands the coefficients are fitted over (degrees), each given the same
/// weight, as the horizon measure reports them.
const FIT_BANDS: [[f64; 2]; 3] = [[0.0, 5.0], [5.0, 15.0], [15.0, 30.0]];

/// How finely a cell's coefficients are fitted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NlFitSettings {
    /// Nodes per band: midpoints uniform in `z` (uniform in solid angle) times midpoints in
    /// azimuth over `[0, π]` (the lobes are symmetric about the view's plane).
    pub z_nodes: usize,
    pub phi_nodes: usize,
    /// Passes of reweighted least squares, each a 2×2 solve over the nodes.
    pub passes: usize,
}

impl Default for NlFitSettings {
    /// 8 × 24 nodes per band and 12 passes keep a 64² table's fit near a second on two
    /// cores; tests/math/horizon.rs checks that twice as many of each moves the measured band
    /// errors by under 2% of themselves or 0.1 percentage point.
    fn default() -> Self {
        Self {
            z_nodes: 8,
            phi_nodes: 24,
            passes: 12,
        }
    }
}

/// `w(z)` for the coefficients `c` of one lobe.
pub fn nl_weight(c: [f64; 2], z: f64) -> f64 {
    let t = (1.0 - z / NL_BAND_Z).max(0.0);
    (1.0 + t * (c[0] + c[1] * t)).max(0.0)
}

/// One cell's coefficients: `[spec c₀, spec c₁, diff c₀, diff c₁]` (one vec4 on the GPU).
pub type NlTerms = [f64; 4];

/// The coefficients of every cell of `lut` (`[j * size + i]`, as its cells), fitted on first
/// use (about a second on two cores) and kept with the table.
pub fn nl_terms(lut: &Lut) -> &[NlTerms] {
    lut.nl_terms
        .get_or_init(|| fit_terms(lut, &NlFitSettings::default()))
}

/// Fits every cell's coefficients at the cell's own (θo, α).
pub fn fit_terms(lut: &Lut, settings: &NlFitSettings) -> Vec<NlTerms> {
    let n = lut.size;
    (0..n * n)
        .into_par_iter()
        .map(|k| {
            let (i, j) = (k % n, k / n);
            let theta = lut.theta_o(j);
            let view = DVec3::new(theta.sin(), 0.0, theta.cos());
            let pair = LutSample::of_cell(lut.cell(i, j)).ltc_pair();
            cell_terms(&pair, view, lut.alpha(i), settings)
        })
        .collect()
}

/// The coefficients at texture coordinate `uv`, filtered as `Lut::sample_uv` filters the
/// cells (the same taps and weights).
pub fn nl_sample_uv(lut: &Lut, u: f64, v: f64) -> NlTerms {
    let (terms, n) = (nl_terms(lut), lut.size);
    let (i0, i1, fx) = bilinear_taps(n, u);
    let (j0, j1, fy) = bilinear_taps(n, v);
    let at = |i: usize, j: usize| terms[j * n + i];
    std::array::from_fn(|c| {
        let top = at(i0, j0)[c] * (1.0 - fx) + at(i1, j0)[c] * fx;
        let bottom = at(i0, j1)[c] * (1.0 - fx) + at(i1, j1)[c] * fx;
        top * (1.0 - fy) + bottom * fy
    })
}

/// The coefficients of the cell containing `uv` (as `Lut::sample_nearest`).
pub fn nl_sample_nearest(lut: &Lut, u: f64, v: f64) -> NlTerms {
    let n = lut.size;
    let index = |t: f64| ((t * n as f64).floor().max(0.0) as usize).min(n - 1);
    nl_terms(lut)[index(v) * n + index(u)]
}

/// Both lobes' coefficients for one view and roughness.
pub fn cell_terms(pair: &LtcPair, view: DVec3, alpha: f64, settings: &NlFitSettings) -> NlTerms {
    let [s0, s1] = lobe_terms(Lobe::Specular, pair, (view, alpha), settings);
    let [d0, d1] = lobe_terms(Lobe::Diffuse, pair, (view, alpha), settings);
    [s0, s1, d0, d1]
}

/// The L1 fit of the horizon measure (docs/design.md §4.7) over the bands' nodes:
/// `Σ_band Σ |L w(z) − f| / Σ_band f`, so that each band counts alike whatever its share of
/// the lobe. `L w(z) = L + L t c₀ + L t² c₁` is linear in `c`, so iteratively reweighted
/// least squares solves it: each pass a 2×2 weighted least squares, each node weighted by the
/// inverse of its last residual. Zero where the LTC is zero at every node.
fn lobe_terms(
    lobe: Lobe,
    pair: &LtcPair,
    (view, alpha): (DVec3, f64),
    settings: &NlFitSettings,
) -> [f64; 2] {
    let ltc = *pair.lobe(lobe);
    // (t, L, f, 1 / Σ_band f) per node.
    let mut nodes: Vec<[f64; 4]> = Vec::new();
    for [lo, hi] in FIT_BANDS {
        let band: Vec<[f64; 3]> = band_nodes(lo, hi, settings)
            .map(|l| {
                let f = lobe.eval(view, l, alpha).value;
                let d = ltc.ltc_eval(l, Clipping::BOTH, Normalization::Corrected);
                let t = (1.0 - l.z / NL_BAND_Z).max(0.0);
                [t, ltc.magnitude() * d, f]
            })
            .collect();
        let total: f64 = band.iter().map(|n| n[2]).sum();
        if total > 0.0 {
            nodes.extend(band.into_iter().map(|[t, l, f]| [t, l, f, 1.0 / total]));
        }
    }
    let mut c = [0.0; 2];
    for _ in 0..settings.passes {
        let (mut a, mut b) = ([0.0f64; 3], [0.0f64; 2]);
        for &[t, l, f, band] in &nodes {
            let (x0, x1) = (l * t, l * t * t);
            let residual = l + x0 * c[0] + x1 * c[1] - f;
            // The residual's floor keeps an exactly fitted node from taking all the weight.
            let w = band / residual.abs().max(1e-9 * (l.abs() + f.abs()) + 1e-300);
            a[0] += w * x0 * x0;
            a[1] += w * x0 * x1;
            a[2] += w * x1 * x1;
            b[0] += w * x0 * (f - l);
            b[1] += w * x1 * (f - l);
        }
        let det = a[0] * a[2] - a[1] * a[1];
        // A (near-)singular system: the LTC is zero at the nodes, or at a single t.
        if det.is_nan() || det <= 1e-12 * (a[0] * a[2]).max(1e-300) {
            break;
        }
        let next = [
            (b[0] * a[2] - b[1] * a[1]) / det,
            (a[0] * b[1] - a[1] * b[0]) / det,
        ];
        if !next.iter().all(|x| x.is_finite()) {
            break;
        }
        c = next;
    }
    c
}

/// The nodes of one band (degrees): `z_nodes × phi_nodes` unit directions.
fn band_nodes(lo: f64, hi: f64, s: &NlFitSettings) -> impl Iterator<Item = DVec3> {
    let (z0, z1) = (lo.to_radians().sin(), hi.to_radians().sin());
    let (nz, nphi) = (s.z_nodes, s.phi_nodes);
    (0..nz).flat_map(move |a| {
        let z = z0 + (z1 - z0) * (a as f64 + 0.5) / nz as f64;
        let r = (1.0 - z * z).max(0.0).sqrt();
        (0..nphi).map(move |b| {
            let phi = std::f64::consts::PI * (b as f64 + 0.5) / nphi as f64;
            DVec3::new(r * phi.cos(), r * phi.sin(), z)
        })
    })
}
