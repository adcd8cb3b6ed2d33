//! The LTC fitter: the method of selfshadow/ltc_code `fit/fitLTC.cpp` as docs/design.md §2 describes
//! it, in f64. Per cell (θo, α): a frame whose z axis is the lobe's average direction, free
//! `m00, m11, m02` in `M = [x y z] · [[m00, 0, m02], [0, m11, 0], [0, 0, 1]]`, the error
//! `Σ |f cos − n D|³ / (pdf_ltc + pdf_brdf)` over 32×32 midpoint strata sampled from both
//! distributions, minimized by Nelder–Mead, warm-started from the neighbouring cell
//! (roughness from 1 down, view from normal to grazing).

use glam::{DMat3, DVec3};
use rayon::prelude::*;

use crate::ltc::lobe::{Lobe, Stratum, lobe_moments, strata};
use crate::ltc::lut::{ALPHA_MIN, Lut, LutCell, cell_alpha, cell_theta};
use crate::ltc::nelder_mead::{CONTINUE, Minimum, Simplex, nelder_mead};
use crate::ltc::{Clipping, Ltc, Normalization};

/// How a table is fitted. The defaults are ltc_code's where it has one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FitSettings {
    /// Cells per side (ltc_code: 64).
    pub size: usize,
    /// Smallest GGX α; also the floor of the free diagonal entries (ltc_code's `MIN_ALPHA`).
    pub alpha_min: f64,
    /// Strata per side for the fit error (ltc_code: 32).
    pub fit_samples: usize,
    /// Strata per side for the magnitudes and average direction (ltc_code: 32). With the
    /// visible-normal sampling of `lobe_moments`, 256² keeps every magnitude within 1e-3 of
    /// f64 quadrature (tests/fit/classic.rs checks 12 cells, grazing ones included).
    pub moment_samples: usize,
    /// Strata per side for the pointwise error stored in the `err` channels.
    pub error_samples: usize,
    /// Initial simplex step (ltc_code: 0.05).
    pub simplex_delta: f64,
    /// Relative tolerance on the simplex values (ltc_code: 1e-5).
    pub tolerance: f64,
    /// Iteration limit (ltc_code: 100).
    pub max_iterations: usize,
}

impl Default for FitSettings {
    fn default() -> Self {
        Self {
            size: 64,
            alpha_min: ALPHA_MIN,
            fit_samples: 32,
            moment_samples: 256,
            error_samples: 64,
            simplex_delta: 0.05,
            tolerance: 1e-5,
            max_iterations: 100,
        }
    }
}

/// The sample patterns of a fit, made once per table.
#[derive(Clone, Debug)]
pub struct FitStrata {
    pub fit: Vec<Stratum>,
    pub moments: Vec<Stratum>,
}

impl FitStrata {
    pub fn new(settings: &FitSettings) -> Self {
        Self {
            fit: strata(settings.fit_samples),
            moments: strata(settings.moment_samples),
        }
    }
}

/// The free parameters `m00, m11, m02` and the frame they act in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LtcParams {
    pub m: [f64; 3],
    /// `[x y z]`: columns are the frame's axes in the shading frame.
    pub frame: DMat3,
}

impl LtcParams {
    /// `M = [x y z] · [[m00, 0, m02], [0, m11, 0], [0, 0, 1]]` (ltc_code's `LTC::update`).
    pub fn brdf_from_cos(&self) -> DMat3 {
        let [m00, m11, m02] = self.m;
        self.frame * crate::ltc::mat3_from_rows([[m00, 0.0, m02], [0.0, m11, 0.0], [0.0, 0.0, 1.0]])
    }
}

/// The frame of a non-normal cell: z along the lobe's average direction, y = the shading y.
pub fn frame_from_average(dir: DVec3) -> DMat3 {
    DMat3::from_cols(DVec3::new(dir.z, 0.0, -dir.x), DVec3::Y, dir)
}

/// ltc_code's fit objective: `Σ |f cos − n D|³ / (pdf_ltc + pdf_brdf)` over `n × n` strata
/// sampled from the LTC and from the lobe, divided by `n²`.
pub fn fit_error(lobe: Lobe, v: DVec3, alpha: f64, ltc: &Ltc, strata: &[Stratum]) -> f64 {
    mis_sum(lobe, v, alpha, ltc, strata, Density::LtcCode, |diff| {
        diff.abs().powi(3)
    })
}

/// The pointwise error of docs/design.md §4: `∫ |s n D − f cos| dω / ∫ f cos dω` (`s` the fitted
/// scale, 1 but in the point table; `n = ∫ f cos`, the true albedo), estimated by the
/// same two-distribution (balance-heuristic) sampling with `n × n` strata each, weighted
/// with the lobe's true sampling density (unbiased at grazing views, unlike the fit's).
pub fn pointwise_error(lobe: Lobe, v: DVec3, alpha: f64, ltc: &Ltc, n: usize) -> f64 {
    mis_sum(lobe, v, alpha, ltc, &strata(n), Density::Exact, f64::abs) / ltc.norm
}

/// Which density of the lobe's sampling weights the samples.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Density {
    /// ltc_code's `pdf` (the fit objective, kept faithful).
    LtcCode,
    /// `Lobe::sampling_density`.
    Exact,
}

/// `(1/n²) Σ g(f cos − n D) / (pdf_ltc + pdf_lobe)` over both sample sets: an unbiased
/// estimate of `∫ g(f cos − n D) dω` wherever either density covers the integrand.
fn mis_sum(
    lobe: Lobe,
    v: DVec3,
    alpha: f64,
    ltc: &Ltc,
    strata: &[Stratum],
    density: Density,
    g: impl Fn(f64) -> f64,
) -> f64 {
    let term = |l: DVec3| {
        let mut exact = lobe.eval(v, l, alpha);
        if density == Density::Exact {
            exact.pdf = lobe.sampling_density(v, l, alpha);
        }
        // The fitted distribution covers the whole sphere: only the transformed cosine's own
        // clamp applies, never the horizon rule (light below the horizon is fit error).
        let d = ltc.ltc_eval(l, Clipping::CASE2, Normalization::Corrected);
        let pdf = d + exact.pdf;
        if pdf > 0.0 {
            g(exact.value - ltc.magnitude() * d) / pdf
        } else {
            0.0
        }
    };
    let mut sum = 0.0;
    for s in strata {
        sum += term(ltc.sample_cosine(s.cosine));
        sum += term(lobe.sample_stratum(v, alpha, s));
    }
    sum / strata.len() as f64
}

/// One fitted cell.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CellFit {
    pub params: LtcParams,
    pub ltc: Ltc,
    /// Final value of the fit objective.
    pub objective: f64,
    pub iterations: usize,
    pub converged: bool,
}

/// Everything fixed for one cell while its parameters move.
#[derive(Clone, Copy, Debug)]
pub struct CellProblem {
    pub lobe: Lobe,
    pub alpha: f64,
    pub view: DVec3,
    pub norm: f64,
    pub fresnel: f64,
    pub frame: DMat3,
    /// At normal view the lobe is rotationally symmetric: one free parameter (m00 = m11,
    /// m02 = 0), as ltc_code does.
    pub isotropic: bool,
}

impl CellProblem {
    /// The cell (i, j) of a table, with its moments and frame (normal view: the identity).
    pub fn new(lobe: Lobe, i: usize, j: usize, settings: &FitSettings, strata: &FitStrata) -> Self {
        let alpha = cell_alpha(i, settings.size, settings.alpha_min);
        let theta = cell_theta(j, settings.size);
        let view = DVec3::new(theta.sin(), 0.0, theta.cos());
        let moments = lobe_moments(lobe, view, alpha, &strata.moments);
        let isotropic = j == 0;
        Self {
            lobe,
            alpha,
            view,
            norm: moments.norm,
            fresnel: moments.fresnel,
            frame: if isotropic {
                DMat3::IDENTITY
            } else {
                frame_from_average(moments.average_dir)
            },
            isotropic,
        }
    }

    /// The parameters as ltc_code's `FitLTC::update` applies them: diagonal entries floored
    /// at α_min, and tied together at normal view.
    pub fn params(&self, p: &[f64; 3], alpha_min: f64) -> LtcParams {
        let m00 = p[0].max(alpha_min);
        let m = if self.isotropic {
            [m00, m00, 0.0]
        } else {
            [m00, p[1].max(alpha_min), p[2]]
        };
        LtcParams {
            m,
            frame: self.frame,
        }
    }

    /// The free parameters that give the lobe `cos_from_brdf` (any scale) in this cell's
    /// frame: the start of a refit from a stored cell. `M` rotated back by the frame and
    /// scaled to its last diagonal entry 1 is `[[m00, 0, m02], [0, m11, 0], [0, 0, 1]]`.
    pub fn params_of(&self, cos_from_brdf: DMat3) -> [f64; 3] {
        let m = crate::ltc::mat3_rows(self.frame.transpose() * cos_from_brdf.inverse());
        let s = m[2][2];
        [m[0][0] / s, m[1][1] / s, m[0][2] / s]
    }

    pub fn ltc(&self, params: &LtcParams) -> Ltc {
        Ltc::from_brdf_from_cos(params.brdf_from_cos(), self.norm, self.fresnel)
    }

    /// The fit objective at free parameters `p`.
    pub fn objective(&self, p: &[f64; 3], settings: &FitSettings, strata: &FitStrata) -> f64 {
        let ltc = self.ltc(&self.params(p, settings.alpha_min));
        fit_error(self.lobe, self.view, self.alpha, &ltc, &strata.fit)
    }

    /// Nelder–Mead from `start`, to be stepped (`Simplex::next` with `objective`).
    pub fn simplex(
        &self,
        start: [f64; 3],
        settings: &FitSettings,
        strata: &FitStrata,
    ) -> Simplex<3> {
        Simplex::new(
            start,
            settings.simplex_delta,
            settings.tolerance,
            settings.max_iterations,
            |p| self.objective(p, settings, strata),
        )
    }

    /// The cell as the search left it.
    pub fn fitted(&self, minimum: Minimum<3>, settings: &FitSettings) -> CellFit {
        let params = self.params(&minimum.point, settings.alpha_min);
        CellFit {
            params,
            ltc: self.ltc(&params),
            objective: minimum.value,
            iterations: minimum.iterations,
            converged: minimum.converged,
        }
    }

    /// Runs Nelder–Mead from `start`; `observe` sees the best objective per iteration and may
    /// stop it.
    pub fn fit(
        &self,
        start: [f64; 3],
        settings: &FitSettings,
        strata: &FitStrata,
        observe: impl FnMut(usize, f64) -> std::ops::ControlFlow<()>,
    ) -> CellFit {
        let minimum = nelder_mead(
            start,
            settings.simplex_delta,
            settings.tolerance,
            settings.max_iterations,
            |p| self.objective(p, settings, strata),
            observe,
        );
        self.fitted(minimum, settings)
    }
}

/// Fits one lobe over the whole table. ltc_code's serial order visits α from 1 down and,
/// within each α, θo from normal to grazing; each normal-view cell starts from the previous
/// α's normal-view result and every other cell from the cell before it in θo. So the
/// normal-view cells form one chain (fitted first, serially) and each α column is then an
/// independent chain: the columns run in parallel and give exactly the serial result.
/// `on_cell` is called once per fitted cell (for a progress bar).
pub fn fit_lobe(
    lobe: Lobe,
    settings: &FitSettings,
    on_cell: &(dyn Fn() + Sync),
) -> Vec<(CellFit, CellProblem)> {
    let n = settings.size;
    assert!(n >= 2, "a table needs at least 2 cells per side");
    let strata = FitStrata::new(settings);
    let mut normal_view: Vec<Option<(CellFit, CellProblem)>> = vec![None; n];
    let mut start = [1.0, 1.0, 0.0];
    for i in (0..n).rev() {
        let problem = CellProblem::new(lobe, i, 0, settings, &strata);
        let fit = problem.fit(start, settings, &strata, |_, _| CONTINUE);
        start = fit.params.m;
        normal_view[i] = Some((fit, problem));
        on_cell();
    }

    let columns: Vec<Vec<(CellFit, CellProblem)>> = normal_view
        .into_par_iter()
        .enumerate()
        .map(|(i, first)| {
            let first = first.expect("every normal-view cell was fitted");
            let mut column = Vec::with_capacity(n);
            let mut start = first.0.params.m;
            column.push(first);
            for j in 1..n {
                let problem = CellProblem::new(lobe, i, j, settings, &strata);
                let fit = problem.fit(start, settings, &strata, |_, _| CONTINUE);
                start = fit.params.m;
                column.push((fit, problem));
                on_cell();
            }
            column
        })
        .collect();

    // Row-major: index j * n + i.
    (0..n)
        .flat_map(|j| (0..n).map(move |i| (i, j)))
        .map(|(i, j)| columns[i][j])
        .collect()
}

/// A fitted table and how the fit went.
#[derive(Clone, Debug)]
pub struct FittedTable {
    pub lut: Lut,
    /// Cells whose Nelder–Mead stopped at the iteration limit, per lobe (spec, diff).
    pub at_iteration_limit: [usize; 2],
}

/// Fits both lobes and assembles the LUT, with each cell's pointwise error.
pub fn fit_table(settings: &FitSettings, on_cell: &(dyn Fn() + Sync)) -> FittedTable {
    let spec = fit_lobe(Lobe::Specular, settings, on_cell);
    let diff = fit_lobe(Lobe::Diffuse, settings, on_cell);
    let limited =
        |fits: &[(CellFit, CellProblem)]| fits.iter().filter(|(f, _)| !f.converged).count();
    let at_iteration_limit = [limited(&spec), limited(&diff)];
    let cells = spec
        .par_iter()
        .zip(diff.par_iter())
        .map(|((s, sp), (d, dp))| {
            let s_err = pointwise_error(sp.lobe, sp.view, sp.alpha, &s.ltc, settings.error_samples);
            let d_err = pointwise_error(dp.lobe, dp.view, dp.alpha, &d.ltc, settings.error_samples);
            LutCell::from_fits(&s.ltc, s_err, &d.ltc, d_err)
        })
        .collect();
    FittedTable {
        lut: Lut {
            nl_terms: Default::default(),
            aniso: None,
            size: settings.size,
            alpha_min: settings.alpha_min,
            cells,
        },
        at_iteration_limit,
    }
}
