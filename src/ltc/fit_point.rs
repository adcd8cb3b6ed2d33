//! The point-light fit (issue 6): the same isotropic family, fitted to what a point light
//! sees. The objective is the pointwise relative L1 error of DESIGN §4,
//! `∫ |n·D − f cos| dω / ∫ f cos dω`, by a deterministic quadrature centred on the lobe;
//! free are all four entries `m00, m02, m20, m22` of the normalized `M⁻¹` (middle element 1,
//! `det > 0` kept). Each cell starts from the better of its classic fit and its neighbour's
//! point fit, and keeps whichever of the classic and the point fit the table's own error
//! metric rates lower — so no cell is worse than the classic table.

use glam::{DMat3, DVec3};
use rayon::prelude::*;

use crate::ltc::fit::{CellProblem, FitSettings, FitStrata, pointwise_error};
use crate::ltc::lobe::Lobe;
use crate::ltc::lut::{Channel, Lut, LutCell};
use crate::ltc::nelder_mead::nelder_mead;
use crate::ltc::{Clipping, Ltc, Normalization, mat3_from_rows};

/// Quadrature steps in the polar parameter t (θ = π t³ about the lobe's centre); φ gets
/// twice as many. 48 × 96 nodes: the objective stays within 5% (+1e-3) of a 4× finer grid on
/// every cell but the grazing row at α ≤ 0.02, where the exact lobe is a sliver under 1°
/// wide along the horizon (tests/fit_point.rs; there the classic cell stays unless the
/// table's own error metric rates the point fit better).
pub const QUADRATURE_STEPS: usize = 48;

/// The fixed quadrature of one cell: directions, solid-angle weights, the exact lobe there.
pub struct CellQuadrature {
    dirs: Vec<DVec3>,
    weights: Vec<f64>,
    exact: Vec<f64>,
    /// `∫ f cos dω` by the same quadrature.
    exact_total: f64,
}

impl CellQuadrature {
    /// Nodes of `θ = π t³` (t midpoints) and φ midpoints about `centre`, so that they crowd
    /// where a narrow lobe lives while still covering the whole sphere.
    pub fn new(lobe: Lobe, view: DVec3, alpha: f64, centre: DVec3, steps: usize) -> Self {
        let z = centre.normalize();
        let x0 = if z.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
        let x = (x0 - z * z.dot(x0)).normalize();
        let frame = DMat3::from_cols(x, z.cross(x), z);
        let n_phi = 2 * steps;
        let dphi = std::f64::consts::TAU / n_phi as f64;
        let mut dirs = Vec::with_capacity(steps * n_phi);
        let mut weights = Vec::with_capacity(steps * n_phi);
        for i in 0..steps {
            let t = (i as f64 + 0.5) / steps as f64;
            let theta = std::f64::consts::PI * t * t * t;
            let dtheta = 3.0 * std::f64::consts::PI * t * t / steps as f64;
            let (st, ct) = theta.sin_cos();
            for k in 0..n_phi {
                let phi = (k as f64 + 0.5) * dphi;
                dirs.push(frame * DVec3::new(st * phi.cos(), st * phi.sin(), ct));
                weights.push(st * dtheta * dphi);
            }
        }
        let exact: Vec<f64> = dirs
            .iter()
            .map(|&l| lobe.eval(view, l, alpha).value)
            .collect();
        let exact_total = exact.iter().zip(&weights).map(|(f, w)| f * w).sum();
        Self {
            dirs,
            weights,
            exact,
            exact_total,
        }
    }

    /// The relative L1 error of `norm · D` for the LTC with this normalized `M⁻¹`.
    pub fn relative_l1(&self, cos_from_brdf: DMat3, norm: f64) -> f64 {
        let ltc = Ltc::from_cos_from_brdf(cos_from_brdf, norm, 0.0);
        let mut sum = 0.0;
        for ((l, w), f) in self.dirs.iter().zip(&self.weights).zip(&self.exact) {
            let d = ltc.ltc_eval(*l, Clipping::TRANSFORMED, Normalization::Corrected);
            sum += w * (norm * d - f).abs();
        }
        sum / self.exact_total.max(f64::MIN_POSITIVE)
    }
}

/// Where the quadrature crowds its nodes: the mirror direction for the specular lobe (a
/// narrow lobe peaks there, also at grazing views, where the lobe's average direction sits
/// degrees above the sliver the horizon leaves), the normal for the diffuse one.
pub fn quadrature_centre(lobe: Lobe, view: DVec3) -> DVec3 {
    match lobe {
        Lobe::Specular => DVec3::new(-view.x, -view.y, view.z),
        Lobe::Diffuse => DVec3::Z,
    }
}

/// `[[m00, 0, m02], [0, 1, 0], [m20, 0, m22]]`.
pub fn normalized_matrix(m: [f64; 4]) -> DMat3 {
    mat3_from_rows([[m[0], 0.0, m[1]], [0.0, 1.0, 0.0], [m[2], 0.0, m[3]]])
}

/// The stored entries of one lobe of a cell.
pub fn entries(cell: &LutCell, lobe: Lobe) -> [f64; 4] {
    use Channel::*;
    let c = match lobe {
        Lobe::Specular => [SpecM00, SpecM02, SpecM20, SpecM22],
        Lobe::Diffuse => [DiffM00, DiffM02, DiffM20, DiffM22],
    };
    c.map(|ch| f64::from(cell.get(ch)))
}

/// Fits one cell from `starts` (the best of them by the objective), returning the entries.
pub fn fit_cell(
    q: &CellQuadrature,
    norm: f64,
    starts: &[[f64; 4]],
    settings: &FitSettings,
) -> [f64; 4] {
    let objective = |m: &[f64; 4]| {
        let det = m[0] * m[3] - m[1] * m[2];
        if det.is_nan() || det <= 1e-12 || m.iter().any(|x| !x.is_finite()) {
            return f64::INFINITY;
        }
        q.relative_l1(normalized_matrix(*m), norm)
    };
    // From every start, Nelder–Mead restarted from its own result (a collapsed simplex
    // stalls in 4D); the best point wins.
    let mut best = *starts
        .iter()
        .min_by(|a, b| objective(a).total_cmp(&objective(b)))
        .expect("at least one start");
    for &first in starts {
        let mut start = first;
        for _ in 0..RESTARTS {
            // Relative moves: each entry scaled by its own size (entries span 1e-4..2).
            let largest = start.iter().fold(0.0f64, |a, y| a.max(y.abs()));
            let scale: [f64; 4] = start.map(|x| x.abs().max(1e-3 * largest));
            let to_entries =
                |p: &[f64; 4]| -> [f64; 4] { std::array::from_fn(|k| start[k] + p[k] * scale[k]) };
            let m = nelder_mead(
                [0.0; 4],
                settings.simplex_delta,
                settings.tolerance,
                settings.max_iterations,
                |p| objective(&to_entries(p)),
                |_, _| {},
            );
            start = to_entries(&m.point);
        }
        if objective(&start) < objective(&best) {
            best = start;
        }
    }
    best
}

/// Nelder–Mead runs per start (each from the previous one's result).
const RESTARTS: usize = 3;

/// A cell of the point table: the classic cell, with each lobe the point fit improved
/// replaced (its four entries and error; the magnitudes are the same albedos).
fn merge(classic: &LutCell, fits: [Option<(Ltc, f64)>; 2]) -> LutCell {
    use Channel::*;
    let mut cell = *classic;
    let spec = [SpecM00, SpecM02, SpecM20, SpecM22, SpecErr];
    let diff = [DiffM00, DiffM02, DiffM20, DiffM22, DiffErr];
    for (fit, channels) in fits.iter().zip([spec, diff]) {
        if let Some((ltc, err)) = fit {
            let m = crate::ltc::fit::normalized_cos_from_brdf(ltc);
            for (c, v) in channels.iter().zip([m[0], m[1], m[2], m[3], *err]) {
                cell.0[*c as usize] = v as f32;
            }
        }
    }
    cell
}

/// The point-fit table from a classic one: every cell of both lobes refitted, columns (fixed
/// α) in parallel, each column from normal to grazing view so that a cell's neighbour is
/// fitted before it.
pub fn fit_point_table(classic: &Lut, settings: &FitSettings, on_cell: &(dyn Fn() + Sync)) -> Lut {
    let n = classic.size;
    assert_eq!(
        n, settings.size,
        "the classic table and the settings disagree on the size"
    );
    let strata = FitStrata::new(settings);
    let columns: Vec<Vec<LutCell>> = (0..n)
        .into_par_iter()
        .map(|i| {
            let mut previous: [Option<[f64; 4]>; 2] = [None, None];
            (0..n)
                .map(|j| {
                    let classic_cell = classic.cell(i, j);
                    let mut fits: [Option<(Ltc, f64)>; 2] = [None, None];
                    for (k, lobe) in Lobe::BOTH.into_iter().enumerate() {
                        let problem = CellProblem::new(lobe, i, j, settings, &strata);
                        let centre = quadrature_centre(lobe, problem.view);
                        let q = CellQuadrature::new(
                            lobe,
                            problem.view,
                            problem.alpha,
                            centre,
                            QUADRATURE_STEPS,
                        );
                        let classic_entries = entries(classic_cell, lobe);
                        let mut starts = vec![classic_entries];
                        starts.extend(previous[k]);
                        let point = fit_cell(&q, problem.norm, &starts, settings);
                        previous[k] = Some(point);
                        // Keep the point fit only where the table's own error metric rates it
                        // below the classic cell's stored error; else the classic cell, as is.
                        let ltc = Ltc::from_cos_from_brdf(
                            normalized_matrix(point),
                            problem.norm,
                            problem.fresnel,
                        );
                        let err = pointwise_error(
                            lobe,
                            problem.view,
                            problem.alpha,
                            &ltc,
                            settings.error_samples,
                        );
                        let stored = f64::from(classic_cell.get(match lobe {
                            Lobe::Specular => Channel::SpecErr,
                            Lobe::Diffuse => Channel::DiffErr,
                        }));
                        fits[k] = (err < stored).then_some((ltc, err));
                    }
                    on_cell();
                    merge(classic_cell, fits)
                })
                .collect()
        })
        .collect();
    Lut {
        size: n,
        alpha_min: classic.alpha_min,
        cells: (0..n)
            .flat_map(|j| (0..n).map(move |i| (i, j)))
            .map(|(i, j)| columns[i][j])
            .collect(),
    }
}
