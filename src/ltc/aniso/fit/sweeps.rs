//! The 4D fit's sweeps over the table (docs/design.md §2.9): the first, from the isotropic
//! nodes down to the thinnest lobes; the refinements from each node's neighbours; and the
//! interpolation-aware sweeps, which weigh the midpoints of a node's edges too.

use glam::DMat3;
use rayon::prelude::*;

use crate::ltc::Ltc;
use crate::ltc::aniso::canonical::canonical;
use crate::ltc::aniso::fit::node::{NodeProblem, entries, rows, turned_isotropic};
use crate::ltc::aniso::fit::{AnisoFitSettings, index};
use crate::ltc::aniso::lobe::aniso_quadrature;
use crate::ltc::aniso::{AnisoAxes, AnisoPoint};
use crate::ltc::fit_point::CellQuadrature;
use crate::ltc::lobe::Stratum;
use crate::ltc::lut::Lut;

/// Where the fit of one node starts and how it compares.
struct Fitted {
    m: [f64; 9],
    value: f64,
}

/// The first sweep's job for one `(r, θ)`: its isotropic nodes from the 2D table `start`
/// (fitted at φ = 0 in the mirror-symmetric family and turned to each φ), then `q` from
/// isotropic down to the thinnest lobe, each node warm-started from the node one step more
/// isotropic, from its neighbour in φ and from the lobe's moments. The nodes `(q, φ)`, `φ`
/// fastest.
pub fn first_sweep_job(
    (a, t): (usize, usize),
    start: &Lut,
    dims: [usize; 4],
    problem: &(dyn Fn([usize; 4]) -> NodeProblem + Sync),
    settings: &AnisoFitSettings,
    on_node: &(dyn Fn() + Sync),
) -> Vec<[f64; 9]> {
    let [_, nb, _, np] = dims;
    let axes = AnisoAxes::Lab;
    let mut m = vec![[0.0; 9]; nb * np];
    let iso = axes.node([a, nb - 1, t, 0], dims);
    let seed = start.ltc_pair(iso.alpha.x, iso.view()).spec.cos_from_brdf;
    let (iso_m, _) = problem([a, nb - 1, t, 0]).refine(entries(seed), settings);
    for p in 0..np {
        let phi = axes.node([a, nb - 1, t, p], dims).phi;
        m[(nb - 1) * np + p] = entries(canonical(turned_isotropic(rows(&iso_m), phi)));
        on_node();
    }
    for b in (0..nb - 1).rev() {
        for p in 0..np {
            if t == 0 && p > 0 {
                // At normal view φ means nothing: every φ is the first one's lobe.
                m[b * np + p] = m[b * np];
            } else {
                let node = problem([a, b, t, p]);
                let mut starts = vec![m[(b + 1) * np + p], node.moments];
                if p > 0 {
                    starts.push(m[b * np + p - 1]);
                }
                m[b * np + p] = best_of(&node, &starts, 2, settings).m;
            }
            on_node();
        }
    }
    m
}

/// One refinement sweep over every node that is fitted (not the isotropic ones, which are
/// exact turns, nor the normal-view ones past φ = 0, which copy it).
pub fn refine_sweep(
    matrices: &[[f64; 9]],
    dims: [usize; 4],
    problem: &(dyn Fn([usize; 4]) -> NodeProblem + Sync),
    settings: &AnisoFitSettings,
    on_node: &(dyn Fn() + Sync),
) -> Vec<[f64; 9]> {
    let [_, nb, _, _] = dims;
    let nodes: Vec<[usize; 4]> = crate::ltc::aniso::all_nodes(dims).collect();
    let mut out: Vec<[f64; 9]> = nodes
        .par_iter()
        .map(|&k| {
            let current = matrices[index(dims, k)];
            let fixed = k[1] == nb - 1 || (k[2] == 0 && k[3] > 0);
            if fixed {
                on_node();
                return current;
            }
            let node = problem(k);
            let mut starts = vec![current, node.moments];
            for axis in 0..4 {
                for step in [-1isize, 1] {
                    let mut n = k;
                    let Some(x) = n[axis].checked_add_signed(step) else {
                        continue;
                    };
                    if x >= dims[axis] {
                        continue;
                    }
                    n[axis] = x;
                    starts.push(matrices[index(dims, n)]);
                }
            }
            let fitted = best_of(&node, &starts, 2, settings);
            on_node();
            if fitted.value < node.objective(&node.symmetry.project(current)) {
                fitted.m
            } else {
                current
            }
        })
        .collect();
    // Normal view: every φ takes the φ = 0 node's matrix again.
    for k in nodes.iter().filter(|k| k[2] == 0 && k[3] > 0) {
        out[index(dims, *k)] = out[index(dims, [k[0], k[1], 0, 0])];
    }
    out
}

/// One edge of a node: the neighbour's stored form and the quadrature of the lobe at the
/// edge's midpoint.
struct Edge {
    neighbour: DMat3,
    mid: AnisoPoint,
    quadrature: CellQuadrature,
    norm: f64,
}

/// One sweep of the interpolation-aware fit: each node (but the fixed ones) restarted from
/// itself, minimizing the mean of its own error and the errors at the midpoints of its edges
/// along every axis, the midpoints read as the table reads them (the two stored forms
/// averaged). Reads only the previous sweep's table.
pub fn interpolation_sweep(
    matrices: &[[f64; 9]],
    dims: [usize; 4],
    problem: &(dyn Fn([usize; 4]) -> NodeProblem + Sync),
    mid_strata: &[Stratum],
    settings: &AnisoFitSettings,
    on_node: &(dyn Fn() + Sync),
) -> Vec<[f64; 9]> {
    let [_, nb, _, _] = dims;
    let fine = dims.map(|n| 2 * n - 1);
    let nodes: Vec<[usize; 4]> = crate::ltc::aniso::all_nodes(dims).collect();
    let mut out: Vec<[f64; 9]> = nodes
        .par_iter()
        .map(|&k| {
            let current = matrices[index(dims, k)];
            let fixed = k[1] == nb - 1 || (k[2] == 0 && k[3] > 0);
            if fixed {
                on_node();
                return current;
            }
            let node = problem(k);
            let own_point = AnisoAxes::Lab.node(k, dims);
            let mut edges = Vec::new();
            for axis in 0..4 {
                // At normal view the φ neighbours are this node's own lobe.
                if axis == 3 && k[2] == 0 {
                    continue;
                }
                for step in [-1isize, 1] {
                    let mut n = k;
                    let Some(x) = n[axis].checked_add_signed(step) else {
                        continue;
                    };
                    if x >= dims[axis] {
                        continue;
                    }
                    n[axis] = x;
                    let mut mid = k.map(|i| 2 * i);
                    mid[axis] = 2 * k[axis].min(x) + 1;
                    let q = AnisoAxes::Lab.node(mid, fine);
                    let v = q.view();
                    let quadrature = aniso_quadrature(v, q.alpha, mid_strata);
                    let norm = quadrature.exact_total();
                    let qn = AnisoAxes::Lab.node(n, dims);
                    edges.push(Edge {
                        neighbour: settings
                            .stored
                            .store(rows(&matrices[index(dims, n)]), qn.view()),
                        mid: q,
                        quadrature,
                        norm,
                    });
                }
            }
            let objective = |m: &[f64; 9]| {
                let own = node.objective(m);
                if !own.is_finite() {
                    return own;
                }
                let mine = settings.stored.store(rows(m), own_point.view());
                let mids: f64 = edges
                    .iter()
                    .map(|e| {
                        let blend = settings
                            .stored
                            .cos_from_brdf((mine + e.neighbour) * 0.5, e.mid.view());
                        // A singular (or NaN) blend reads as the largest error.
                        let det = blend.determinant().abs();
                        if det.is_nan() || det <= 0.0 {
                            return 2.0;
                        }
                        let ltc = Ltc::from_cos_from_brdf(blend, e.norm, 0.0);
                        e.quadrature.relative_l1_ltc(&ltc, e.norm)
                    })
                    .sum();
                (own + mids) / (1 + edges.len()) as f64
            };
            let start = node.symmetry.project(current);
            let (m, value) = node.refine_with(start, settings, &objective);
            on_node();
            if value < objective(&start) {
                m
            } else {
                current
            }
        })
        .collect();
    for k in nodes.iter().filter(|k| k[2] == 0 && k[3] > 0) {
        out[index(dims, *k)] = out[index(dims, [k[0], k[1], 0, 0])];
    }
    out
}

/// Runs the `runs` best of `starts` (by the objective, each first put in the node's
/// symmetry and in canonical form with `m11` as it is) and returns the best result.
fn best_of(node: &NodeProblem, starts: &[[f64; 9]], runs: usize, s: &AnisoFitSettings) -> Fitted {
    let mut ranked: Vec<Fitted> = starts
        .iter()
        .map(|&m| {
            let m = node.symmetry.project(entries(canonical(rows(&m))));
            Fitted {
                value: node.objective(&m),
                m,
            }
        })
        .collect();
    ranked.sort_by(|a, b| a.value.total_cmp(&b.value));
    ranked
        .iter()
        .take(runs)
        .map(|f| {
            let (m, value) = node.refine(f.m, s);
            Fitted { m, value }
        })
        .min_by(|a, b| a.value.total_cmp(&b.value))
        .expect("at least one start")
}
