//! The 4D fit (docs/design.md §2.9): one LTC of the anisotropic specular lobe per node of the
//! lab's axes, every entry of `M⁻¹` free but for the equivalences (`canonical`), fitted to the
//! pointwise relative L1 error a point light sees (the point fit's objective, §2.6, with the
//! lobe's true albedo as magnitude). A node's mirror symmetries are kept exactly: at φ = 0
//! the lobe is symmetric about the xz-plane, at φ = π/2 about the yz-plane, at normal view
//! about both, and the fit there frees only the entries such a lobe has, so that the table
//! meets its mirror images without a seam. The isotropic nodes (`q = 1`) are the isotropic fit
//! turned by φ, exactly.

mod checkpoint;
mod node;
mod sweeps;

use rayon::prelude::*;

use crate::ltc::aniso::lobe::{aniso_magnitudes, aniso_quadrature};
use crate::ltc::aniso::{AnisoAxes, AnisoCell, AnisoLut, Stored};
use crate::ltc::lobe::strata;
use crate::ltc::lut::Lut;

pub use checkpoint::{FitState, MAX_CHECKPOINT_BYTES};
pub use node::{NodeProblem, Symmetry, moment_start, turned_isotropic};
use node::{entries, rows};
use sweeps::{first_sweep_job, interpolation_sweep, refine_sweep};

/// How the 4D table is fitted.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AnisoFitSettings {
    /// Nodes per axis `(r, q, θ, φ)` (`AnisoAxes::Lab`).
    pub dims: [usize; 4],
    /// Strata per side of the fit's quadrature (the point fit's 64).
    pub fit_strata: usize,
    /// Strata per side for the magnitudes and the stored error: a finer set than the fit's,
    /// none of whose nodes it shares, so that the error is not measured where it was fitted.
    pub measure_strata: usize,
    /// Nelder–Mead's initial step, in units of each entry's own size.
    pub simplex_delta: f64,
    /// Relative tolerance on the simplex values.
    pub tolerance: f64,
    /// Iterations per run.
    pub max_iterations: usize,
    /// Runs per start, each from the previous one's result (a collapsed simplex stalls).
    pub restarts: usize,
    /// Sweeps that restart every node from its neighbours after the first.
    pub refinements: usize,
    /// Sweeps after those that fit each node to its own error and to the errors at the
    /// midpoints of its edges, where the table is read between the nodes.
    pub interpolation_sweeps: usize,
    /// Strata per side of the midpoints' quadratures in those sweeps.
    pub midpoint_strata: usize,
    /// Which matrix the nodes store, and so what interpolation blends.
    pub stored: Stored,
}

impl Default for AnisoFitSettings {
    fn default() -> Self {
        Self {
            dims: [8, 8, 8, 8],
            fit_strata: 64,
            measure_strata: 256,
            simplex_delta: 0.05,
            tolerance: 1e-6,
            max_iterations: 400,
            restarts: 3,
            refinements: 2,
            interpolation_sweeps: 1,
            midpoint_strata: 32,
            stored: Stored::MirrorPole,
        }
    }
}

/// Fits the lab's 4D table, from the beginning or from `resume` (a checkpoint of the same
/// settings). `start` is the 2D table whose fits seed the isotropic nodes (the shipped point
/// table); `on_node` is called once per node and sweep; `on_checkpoint` with the state after
/// each first-sweep job and after each later sweep, which a later call resumes from.
///
/// The first sweep runs every `(r, θ)` in parallel (`sweeps::first_sweep_job`); each
/// refinement sweep restarts every node from itself, its eight neighbours along the axes and
/// its moments, and keeps what lowers its objective; each interpolation sweep refits every
/// node to its own error and its edges' midpoints'. Every sweep reads only the previous
/// sweep's table, so the result depends neither on the thread count nor on where it was
/// resumed.
pub fn fit_aniso_table(
    start: &Lut,
    settings: &AnisoFitSettings,
    resume: Option<FitState>,
    on_node: &(dyn Fn() + Sync),
    on_checkpoint: &(dyn Fn(&FitState) + Sync),
) -> AnisoLut {
    let dims = settings.dims;
    let [na, _, nt, np] = dims;
    let fit_strata = strata(settings.fit_strata);
    let measure_strata = strata(settings.measure_strata);
    let axes = AnisoAxes::Lab;
    let problem = |k: [usize; 4]| {
        let q = axes.node(k, dims);
        NodeProblem::new(
            &q,
            Symmetry::of_node(k[2], k[3], np),
            &fit_strata,
            &measure_strata,
        )
    };
    let state = std::sync::Mutex::new(resume.unwrap_or_else(|| FitState::new(settings)));
    let lock = || {
        state
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    };
    if lock().sweep == 0 {
        let todo: Vec<usize> = (0..na * nt).filter(|&j| !lock().jobs_done[j]).collect();
        todo.into_par_iter().for_each(|job| {
            let (a, t) = (job % na, job / na);
            let column = first_sweep_job((a, t), start, dims, &problem, settings, on_node);
            let mut s = lock();
            s.finish_job(job, &column, dims);
            on_checkpoint(&s);
        });
        let mut s = lock();
        s.sweep = 1;
        on_checkpoint(&s);
    }
    let mid_strata = strata(settings.midpoint_strata);
    loop {
        let (sweep, matrices) = {
            let s = lock();
            (s.sweep, s.matrices.clone())
        };
        let next = if sweep <= settings.refinements {
            refine_sweep(&matrices, dims, &problem, settings, on_node)
        } else if sweep <= settings.refinements + settings.interpolation_sweeps {
            interpolation_sweep(&matrices, dims, &problem, &mid_strata, settings, on_node)
        } else {
            break;
        };
        let mut s = lock();
        s.matrices = next;
        s.sweep += 1;
        on_checkpoint(&s);
    }
    let matrices = lock().matrices.clone();
    let cells = crate::ltc::aniso::all_nodes(dims)
        .collect::<Vec<_>>()
        .into_par_iter()
        .map(|k| {
            let q = axes.node(k, dims);
            let v = q.view();
            let (norm, fresnel) = aniso_magnitudes(v, q.alpha, &measure_strata);
            let form = settings.stored.store(rows(&matrices[index(dims, k)]), v);
            let m = settings.stored.cos_from_brdf(form, v);
            let ltc = crate::ltc::Ltc::from_cos_from_brdf(m, norm, fresnel);
            let err = aniso_quadrature(v, q.alpha, &measure_strata).relative_l1_ltc(&ltc, norm);
            AnisoCell {
                m: entries(form).map(|x| x as f32),
                norm: norm as f32,
                fresnel: fresnel as f32,
                err: err as f32,
            }
        })
        .collect();
    AnisoLut {
        axes,
        dims,
        stored: settings.stored,
        cells,
    }
}

/// How many times `on_node` is called by a whole fit.
pub fn node_visits(settings: &AnisoFitSettings) -> usize {
    let nodes: usize = settings.dims.iter().product();
    nodes * (1 + settings.refinements + settings.interpolation_sweeps)
}

/// The index of node `k` of a table of `dims` (`AnisoLut::index`'s order).
pub(crate) fn index(dims: [usize; 4], [a, b, t, p]: [usize; 4]) -> usize {
    ((p * dims[2] + t) * dims[1] + b) * dims[0] + a
}
