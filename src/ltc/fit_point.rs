//! The point-light fit: the same isotropic family, fitted to what a point light
//! sees. The objective is the pointwise relative L1 error of docs/design.md §4,
//! `∫ |s n D − f cos| dω / ∫ f cos dω`, by a deterministic quadrature that follows the lobe
//! (`CellQuadrature`). Free are all four entries `m00, m02, m20, m22` of the normalized
//! `M⁻¹` (middle element 1, `det > 0` kept) and, for the specular lobe, the scale `s` on its
//! magnitude (`spec.scale`; `n` stays the true albedo). Each cell starts from its classic fit
//! and its neighbours' point fits, and keeps whichever of the classic and the point fit the
//! table's own error metric (`pointwise_error`) rates lower — so no cell is worse than the
//! classic table.

use glam::DVec3;
use rayon::prelude::*;

use crate::brdf::{d_ggx, g2_correlated, lambda_ggx};
use crate::ltc::cell_fitter::fit_cell;
use crate::ltc::fit::{CellProblem, FitSettings, FitStrata, pointwise_error};
use crate::ltc::lobe::{Lobe, Stratum, visible_normal};
use crate::ltc::lut::{Channel, Lut, LutCell};
use crate::ltc::point_params::{CellObjective, Free, PointFit, fits_scale};
use crate::ltc::{Clipping, Ltc, Normalization};

/// Strata per axis of the fit's quadrature (64² nodes); tests/fit/point.rs compares it with
/// a 4× finer one on the hardest cells.
pub const QUADRATURE_STRATA: usize = 64;

/// One node of a cell's quadrature: a direction drawn by the exact lobe's own sampling.
#[derive(Clone, Copy, Debug)]
pub struct Node {
    pub l: DVec3,
    /// The sampling density at `l`.
    pub pdf: f64,
    /// `f cos / pdf` (for the specular lobe `G2/G1(v)`, at most 1).
    pub weight: f64,
}

/// The fixed quadrature of one cell: midpoint strata mapped through the exact lobe's
/// importance sampling (visible GGX normals for the specular lobe, the cosine for the
/// diffuse one), so that the nodes follow the lobe however narrow or grazing it is.
///
/// The L1 distance is taken in its overlap form, `∫ |n D − f| = n + ∫ f − 2 ∫ min(n D, f)`,
/// which holds because `∫ D = 1` over the sphere exactly: only the overlap needs the
/// quadrature, and it lives where `f` does — where the nodes are. Each node's term
/// `min(n D, f) / pdf` is bounded by the lobe's weight, so an LTC lobe far narrower than the
/// node spacing can neither hide between the nodes nor blow up on one of them.
pub struct CellQuadrature {
    /// The nodes where `f > 0` (the others add nothing to the overlap).
    nodes: Vec<Node>,
    count: usize,
    /// `∫ f cos dω` by the same nodes.
    exact_total: f64,
}

impl CellQuadrature {
    pub fn new(lobe: Lobe, view: DVec3, alpha: f64, strata: &[Stratum]) -> Self {
        let nodes: Vec<Node> = strata
            .iter()
            .filter_map(|s| lobe_node(lobe, view, alpha, s))
            .collect();
        Self::from_nodes(nodes, strata.len())
    }

    /// The quadrature of a lobe's nodes where it is non-zero, out of `count` strata.
    pub fn from_nodes(nodes: Vec<Node>, count: usize) -> Self {
        let exact_total = nodes.iter().map(|n| n.weight).sum::<f64>() / count as f64;
        Self {
            nodes,
            count,
            exact_total,
        }
    }

    /// `∫ f cos dω` by these nodes.
    pub fn exact_total(&self) -> f64 {
        self.exact_total
    }

    /// The relative L1 error of `scale · norm · D` for this fit, relative to `norm` (the
    /// stored albedo), as the table's `err` channels are.
    pub fn relative_l1(&self, fit: &PointFit, norm: f64) -> f64 {
        self.relative_l1_ltc(&fit.ltc(norm, 0.0), norm)
    }

    /// `relative_l1` of any lobe: `∫ |ltc.magnitude() · D − f cos| dω / norm`.
    pub fn relative_l1_ltc(&self, ltc: &Ltc, norm: f64) -> f64 {
        let magnitude = ltc.magnitude();
        let mut overlap = 0.0;
        for node in &self.nodes {
            let d = ltc.ltc_eval(node.l, Clipping::CASE2, Normalization::Corrected);
            overlap += (magnitude * d / node.pdf).min(node.weight);
        }
        overlap /= self.count as f64;
        (magnitude + self.exact_total - 2.0 * overlap) / norm
    }
}

impl CellObjective for CellQuadrature {
    fn relative_l1(&self, fit: &PointFit, norm: f64) -> f64 {
        CellQuadrature::relative_l1(self, fit, norm)
    }
}

/// Below this `n·l` (sin 5°) the arrival weight stops growing: a light 0.3 above the plane,
/// as paper-100's are at most, is at 5° once it is 3.4 away, past the range (3) its lights
/// reach (docs/design.md §4.7).
pub const ARRIVAL_Z_MIN: f64 = 0.087_155_742_747_658_17;

/// How much of a point light's shading arrives from elevation `asin z` for lights spread
/// evenly over a plane above the surface: per solid angle there are `∝ 1/sin³e` of them, each
/// giving irradiance `∝ sin²e` (docs/design.md §4.7), so `1/sin e`, floored at `ARRIVAL_Z_MIN`.
pub fn arrival_weight(z: f64) -> f64 {
    1.0 / z.max(ARRIVAL_Z_MIN)
}

/// One node of the arrival quadrature: a direction, its lobe value, and its weight
/// `arrival / (N₁ p_lobe + N₂ p_uniform)` (the balance heuristic of two node sets).
#[derive(Clone, Copy, Debug)]
struct ArrivalNode {
    l: DVec3,
    f: f64,
    weight: f64,
}

/// The arrival objective `∫ |s n D − f cos| a dω / ∫ f cos a dω` with `a = arrival_weight`.
/// The lobe's own nodes cover its peak; as many nodes uniform in solid angle cover the
/// horizon, where `a` is largest and the lobe has few; the two sets are combined by the
/// balance heuristic. The overlap form of `CellQuadrature` does not apply (`∫ D a` is not
/// 1), so the L1 is summed directly.
pub struct ArrivalQuadrature {
    nodes: Vec<ArrivalNode>,
    exact_total: f64,
}

impl ArrivalQuadrature {
    pub fn new(lobe: Lobe, view: DVec3, alpha: f64, strata: &[Stratum]) -> Self {
        let n = strata.len() as f64;
        let uniform_pdf = 1.0 / std::f64::consts::TAU;
        let lobe_pdf = |l: DVec3| lobe_density(lobe, view, alpha, l);
        let node = |l: DVec3, f: f64| ArrivalNode {
            l,
            f,
            weight: arrival_weight(l.z) / (n * lobe_pdf(l) + n * uniform_pdf),
        };
        let from_lobe = strata
            .iter()
            .filter_map(|s| lobe_node(lobe, view, alpha, s))
            .map(|q| node(q.l, q.weight * q.pdf));
        let uniform = strata
            .iter()
            .map(|s| uniform_direction(s.u))
            .filter(|l| l.z > 0.0);
        let uniform = uniform.map(|l| node(l, lobe.eval(view, l, alpha).value));
        let nodes: Vec<ArrivalNode> = from_lobe.chain(uniform).collect();
        let exact_total = nodes.iter().map(|q| q.f * q.weight).sum();
        Self { nodes, exact_total }
    }
}

impl CellObjective for ArrivalQuadrature {
    fn relative_l1(&self, fit: &PointFit, norm: f64) -> f64 {
        let ltc = fit.ltc(norm, 0.0);
        let magnitude = ltc.magnitude();
        let l1: f64 = self
            .nodes
            .iter()
            .map(|q| {
                let d = ltc.ltc_eval(q.l, Clipping::BOTH, Normalization::Corrected);
                (magnitude * d - q.f).abs() * q.weight
            })
            .sum();
        l1 / self.exact_total.max(1e-300)
    }
}

/// The density of `lobe_node`'s directions at `l`: visible GGX normals reflected about
/// (`G1(v) D(h) / (4 v.z)` where `v·h > 0`), or the cosine.
fn lobe_density(lobe: Lobe, v: DVec3, alpha: f64, l: DVec3) -> f64 {
    match lobe {
        Lobe::Specular => {
            let h = (v + l).normalize_or_zero();
            if h.dot(v) <= 0.0 || h.z <= 0.0 {
                return 0.0;
            }
            let g1 = 1.0 / (1.0 + lambda_ggx(v.z, alpha));
            g1 * d_ggx(h.z, alpha) / (4.0 * v.z)
        }
        Lobe::Diffuse => l.z.max(0.0) / std::f64::consts::PI,
    }
}

/// A direction uniform in solid angle over the upper hemisphere from a stratum's `(u1, u2)`:
/// `z = u1`, `φ = 2π u2`.
fn uniform_direction([u1, u2]: [f64; 2]) -> DVec3 {
    let r = (1.0 - u1 * u1).max(0.0).sqrt();
    let phi = std::f64::consts::TAU * u2;
    DVec3::new(r * phi.cos(), r * phi.sin(), u1)
}

/// The lobe's sample for stratum `s` where the lobe is non-zero.
fn lobe_node(lobe: Lobe, v: DVec3, alpha: f64, s: &Stratum) -> Option<Node> {
    let (l, pdf, weight) = match lobe {
        Lobe::Specular => {
            // Visible normals have density G1(v) max(v·h, 0) D(h) / v.z (Heitz 2018 eq. 3);
            // reflecting about h divides it by 4 v·h.
            let h = visible_normal(v, alpha, s);
            let l = 2.0 * h.dot(v) * h - v;
            let g1 = 1.0 / (1.0 + lambda_ggx(v.z, alpha));
            let pdf = g1 * d_ggx(h.z, alpha) / (4.0 * v.z);
            (l, pdf, g2_correlated(v.z, l.z, alpha) / g1)
        }
        Lobe::Diffuse => {
            let l = s.cosine;
            let pdf = l.z / std::f64::consts::PI;
            (l, pdf, lobe.eval(v, l, alpha).value / pdf)
        }
    };
    (weight > 0.0 && pdf > 0.0 && l.z > 0.0).then_some(Node { l, pdf, weight })
}

/// What a point-light table's fit minimizes, and under which constraint (docs/design.md §2,
/// §4.7). Each starts from the classic table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PointObjective {
    /// `∫ |s n D − f cos| dω / ∫ f cos dω`: the lobe as one point light sees it
    /// (`luts/ltc_point.exr`).
    Lobe,
    /// The same, each direction weighted by how much light arrives from it for lights
    /// spread over a plane above the surface (`arrival_weight`): the horizon counts
    /// (`luts/ltc_arrival.exr`).
    Arrival,
    /// `Lobe` with `m20 = 0`: then `(M⁻¹l).z = m22 l.z`, so `M⁻¹` keeps every direction on
    /// its side of the horizon and eq. 30's cases 1 and 2 cannot occur
    /// (`luts/ltc_constrained.exr`).
    Constrained,
}

impl PointObjective {
    /// What the point fit frees for `lobe` under this objective.
    pub fn free(self, lobe: Lobe) -> Free {
        Free {
            scale: fits_scale(lobe),
            m20: self != Self::Constrained,
        }
    }

    /// The quadrature of the objective at one cell.
    pub fn quadrature(
        self,
        lobe: Lobe,
        view: DVec3,
        alpha: f64,
        strata: &[Stratum],
    ) -> Box<dyn CellObjective> {
        match self {
            Self::Lobe | Self::Constrained => {
                Box::new(CellQuadrature::new(lobe, view, alpha, strata))
            }
            Self::Arrival => Box::new(ArrivalQuadrature::new(lobe, view, alpha, strata)),
        }
    }
}

/// A cell of the point table: `current`, with each lobe the point fit improved replaced
/// (entries, scale, error; `norm` and `fresnel` stay the true albedos).
fn merge(current: &LutCell, fits: [Option<(PointFit, f64)>; 2]) -> LutCell {
    let mut cell = *current;
    for (fit, lobe) in fits.iter().zip(Lobe::ALL) {
        if let Some((fit, err)) = fit {
            for (c, v) in Channel::entries(lobe).iter().zip(fit.entries) {
                cell.0[*c as usize] = v as f32;
            }
            cell.0[Channel::err(lobe) as usize] = *err as f32;
            if lobe == Lobe::Specular {
                cell.0[Channel::SpecScale as usize] = fit.scale as f32;
            }
        }
    }
    cell
}

/// The point-fit table from a classic one. A first sweep fits every cell of both lobes,
/// columns (fixed α) in parallel, each column from normal to grazing view so that a cell's
/// neighbour along θo is fitted before it; then `REFINEMENTS` sweeps restart every cell from
/// the fits of all four of its neighbours (the L1 objective has many local minima, and a
/// neighbour often sits in a deeper one). Each sweep reads only the previous table, so the
/// result does not depend on the thread count.
pub fn fit_point_table(classic: &Lut, settings: &FitSettings, on_cell: &(dyn Fn() + Sync)) -> Lut {
    fit_table_for(classic, PointObjective::Lobe, settings, on_cell)
}

/// `fit_point_table` by any of the point objectives. The lobe objective keeps a cell's fit
/// only where the table's error metric rates it below the classic cell; the others keep
/// theirs always (the classic cell breaks the constraint, or is not what they minimize;
/// their fit is never worse than its starts by their own objective).
pub fn fit_table_for(
    classic: &Lut,
    objective: PointObjective,
    settings: &FitSettings,
    on_cell: &(dyn Fn() + Sync),
) -> Lut {
    let n = classic.size;
    assert_eq!(
        n, settings.size,
        "the classic table and the settings disagree on the size"
    );
    let strata = FitStrata::new(settings);
    let quadrature = crate::ltc::lobe::strata(QUADRATURE_STRATA);
    let refit = |current: &LutCell, lobe: Lobe, i: usize, j: usize, starts: &[PointFit]| {
        let problem = CellProblem::new(lobe, i, j, settings, &strata);
        let q = objective.quadrature(lobe, problem.view, problem.alpha, &quadrature);
        let free = objective.free(lobe);
        let point = fit_cell(&*q, problem.norm, starts, free, settings);
        let err = pointwise_error(
            lobe,
            problem.view,
            problem.alpha,
            &point.ltc(problem.norm, problem.fresnel),
            settings.error_samples,
        );
        // Kept only where the table's own error metric rates it below the current cell's
        // stored error (at first the classic one), so that no cell gets worse.
        let stored = f64::from(current.get(Channel::err(lobe)));
        let keep = objective != PointObjective::Lobe || err < stored;
        (point, keep.then_some((point, err)))
    };
    let columns: Vec<Vec<LutCell>> = (0..n)
        .into_par_iter()
        .map(|i| {
            let mut previous: [Option<PointFit>; 2] = [None, None];
            (0..n)
                .map(|j| {
                    let classic_cell = classic.cell(i, j);
                    let fits = std::array::from_fn(|k| {
                        let lobe = Lobe::ALL[k];
                        let mut starts = vec![PointFit::stored(classic_cell, lobe)];
                        starts.extend(previous[k]);
                        let (point, fit) = refit(classic_cell, lobe, i, j, &starts);
                        previous[k] = Some(point);
                        fit
                    });
                    on_cell();
                    merge(classic_cell, fits)
                })
                .collect()
        })
        .collect();
    let mut table = Lut {
        nl_terms: Default::default(),
        aniso: None,
        size: n,
        alpha_min: classic.alpha_min,
        cells: (0..n)
            .flat_map(|j| (0..n).map(move |i| (i, j)))
            .map(|(i, j)| columns[i][j])
            .collect(),
    };
    for _ in 0..REFINEMENTS {
        let cells = (0..n * n)
            .into_par_iter()
            .map(|k| {
                let (i, j) = (k % n, k / n);
                let current = table.cell(i, j);
                let neighbours: Vec<&LutCell> = [(-1, 0), (1, 0), (0, -1), (0, 1)]
                    .into_iter()
                    .filter_map(|(di, dj)| {
                        let (i, j) = (i.checked_add_signed(di)?, j.checked_add_signed(dj)?);
                        (i < n && j < n).then(|| table.cell(i, j))
                    })
                    .collect();
                let fits = std::array::from_fn(|k| {
                    let lobe = Lobe::ALL[k];
                    let mut starts = vec![PointFit::stored(current, lobe)];
                    starts.extend(neighbours.iter().map(|c| PointFit::stored(c, lobe)));
                    refit(current, lobe, i, j, &starts).1
                });
                on_cell();
                merge(current, fits)
            })
            .collect();
        table = Lut { cells, ..table };
    }
    table
}

/// Sweeps from all four neighbours after the first one.
pub const REFINEMENTS: usize = 1;
