//! The point-light fit: on a coarse grid it is never worse than the classic fit at any cell
//! and lower on average; its search, stepped, makes one Nelder–Mead iteration a step and ends
//! no worse than its starts; its quadrature is fine enough on the hardest cells and measures
//! what the table's error metric measures; the shipped table is what the file holds, never
//! worse than the classic one, and halves its error where the metric is re-measured
//! independently.

use std::sync::atomic::{AtomicUsize, Ordering};

use ltc_lab::ltc::cell_fitter::{CellFitter, FitNext, RESTARTS};
use ltc_lab::ltc::fit::{CellProblem, FitSettings, FitStrata, fit_table, pointwise_error};
use ltc_lab::ltc::fit_point::{CellQuadrature, PointObjective, QUADRATURE_STRATA, fit_point_table};
use ltc_lab::ltc::lobe::{Lobe, strata};
use ltc_lab::ltc::lut::{Channel, Lut, Table};
use ltc_lab::ltc::point_params::{CellObjective, PointFit, SCALE_MIN};

#[test]
fn point_fit_is_never_worse_and_better_on_average_on_a_coarse_grid() {
    let settings = FitSettings {
        size: 8,
        ..FitSettings::default()
    };
    let classic = fit_table(&settings, &|| {}).lut;
    let point = fit_point_table(&classic, &settings, &|| {});
    for ch in [Channel::SpecErr, Channel::DiffErr] {
        let (mut c_sum, mut p_sum) = (0.0, 0.0);
        for (c, p) in classic.cells.iter().zip(&point.cells) {
            let (c, p) = (f64::from(c.get(ch)), f64::from(p.get(ch)));
            assert!(p <= c, "{ch:?}: point {p} above classic {c}");
            c_sum += c;
            p_sum += p;
        }
        // The 64² table's ratio is 0.54; on this 8² grid it is 0.58; 0.75 states a margin
        // that a broken fit (ratio → 1) cannot meet.
        if ch == Channel::SpecErr {
            assert!(
                p_sum <= 0.75 * c_sum,
                "mean spec.err ratio {}",
                p_sum / c_sum
            );
        } else {
            assert!(p_sum <= c_sum);
        }
    }
}

/// The hardest cells: the smallest α at normal, oblique and grazing views, small α toward
/// grazing, the grazing row across α (the exact lobe a sliver along the horizon there).
const HARDEST: [(usize, usize); 12] = [
    (0, 0),
    (1, 30),
    (0, 56),
    (2, 50),
    (4, 55),
    (8, 58),
    (12, 60),
    (0, 63),
    (4, 63),
    (12, 63),
    (20, 63),
    (63, 63),
];

/// The shipped point fit of a cell's specular lobe and its problem.
fn shipped(i: usize, j: usize, settings: &FitSettings) -> (CellProblem, PointFit) {
    let strata = FitStrata::new(settings);
    let problem = CellProblem::new(Lobe::Specular, i, j, settings, &strata);
    let fit = PointFit::stored(Lut::embedded_point().cell(i, j), Lobe::Specular);
    (problem, fit)
}

/// The fit's objective by its 64² quadrature against a 4× finer one (256² nodes) at the
/// shipped fit of the hardest cells. 4% (+1e-4): measured at most 3.9%, at cells whose error
/// is below 0.01 (1e-4 absolute); 1% at every cell above 0.05, the grazing row included.
#[test]
fn quadrature_is_fine_enough_on_the_hardest_cells() {
    let settings = FitSettings::default();
    let (coarse_nodes, fine_nodes) = (strata(QUADRATURE_STRATA), strata(4 * QUADRATURE_STRATA));
    for (i, j) in HARDEST {
        let (p, fit) = shipped(i, j, &settings);
        let at = |nodes| {
            CellQuadrature::new(Lobe::Specular, p.view, p.alpha, nodes).relative_l1(&fit, p.norm)
        };
        let (coarse, fine) = (at(&coarse_nodes), at(&fine_nodes));
        assert!(
            (coarse - fine).abs() <= 0.04 * fine + 1e-4,
            "cell ({i}, {j}): {coarse} by {QUADRATURE_STRATA}² nodes, {fine} by 4× finer"
        );
    }
}

/// The fit's quadrature (the lobe's own importance sampling, overlap form) and the table's
/// error metric (`pointwise_error`: two-density MIS, the L1 integrand directly) are
/// independent estimators of the same integral. The MIS one converges slowly from below on
/// the grazing row (at (4, 63): 0.550 at 256², 0.560 at 1024², where the quadrature gives
/// 0.569 at 256² and at 1024² alike), so it runs at 1024² here. 4% (+1e-4): measured at most
/// 2.3%, at (63, 63).
#[test]
fn quadrature_measures_what_the_error_metric_measures() {
    let settings = FitSettings::default();
    let nodes = strata(256);
    for (i, j) in HARDEST {
        let (p, fit) = shipped(i, j, &settings);
        let q =
            CellQuadrature::new(Lobe::Specular, p.view, p.alpha, &nodes).relative_l1(&fit, p.norm);
        let mis = pointwise_error(Lobe::Specular, p.view, p.alpha, &fit.ltc(p.norm, 0.0), 1024);
        assert!(
            (q - mis).abs() <= 0.04 * mis + 1e-4,
            "cell ({i}, {j}): quadrature {q}, MIS {mis}"
        );
    }
}

#[test]
fn shipped_point_table_is_the_file_and_never_worse_than_the_classic_one() {
    let file =
        Lut::read(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("luts/ltc_point.exr"))
            .unwrap();
    assert_eq!(&file, Lut::embedded_point());
    let (classic, point) = (Lut::embedded(), Lut::embedded_point());
    assert_eq!(
        (classic.size, classic.alpha_min),
        (point.size, point.alpha_min)
    );
    for (c, p) in classic.cells.iter().zip(&point.cells) {
        for ch in [Channel::SpecErr, Channel::DiffErr] {
            assert!(p.get(ch) <= c.get(ch));
        }
        // Same albedos: the point fit changes the shape and the scale only.
        for ch in [Channel::SpecNorm, Channel::SpecFresnel, Channel::DiffNorm] {
            assert_eq!(p.get(ch), c.get(ch));
        }
        assert_eq!(c.get(Channel::SpecScale), 1.0);
        let scale = f64::from(p.get(Channel::SpecScale));
        // At most halved (SCALE_MIN); above 1 only by a little (measured max 1.003), as the
        // L1 optimum of an imperfect shape undershoots rather than overshoots.
        assert!(
            (SCALE_MIN as f32 as f64..=1.05).contains(&scale),
            "scale {scale}"
        );
    }
}

/// The point fit's target (docs/design.md §4), re-measured without the tables' own `err` channels: on every
/// fourth cell of both axes the specular error of each table by `pointwise_error` at 128²
/// (twice the resolution the channels were written with). The point table's mean is below
/// 0.55× the classic one's (0.51 measured here; 0.54 over the whole table).
#[test]
fn point_table_halves_the_mean_specular_error() {
    let settings = FitSettings::default();
    let strata = FitStrata::new(&settings);
    let (mut classic_sum, mut point_sum) = (0.0, 0.0);
    for j in (0..settings.size).step_by(4) {
        for i in (0..settings.size).step_by(4) {
            let p = CellProblem::new(Lobe::Specular, i, j, &settings, &strata);
            let err = |lut: &Lut| {
                let fit = PointFit::stored(lut.cell(i, j), Lobe::Specular);
                pointwise_error(Lobe::Specular, p.view, p.alpha, &fit.ltc(p.norm, 0.0), 128)
            };
            classic_sum += err(Lut::embedded());
            point_sum += err(Lut::embedded_point());
        }
    }
    let ratio = point_sum / classic_sum;
    assert!(ratio <= 0.55, "mean spec.err ratio {ratio}");
}

/// A quadrature that counts its evaluations.
struct Counted(CellQuadrature, AtomicUsize);

impl CellObjective for Counted {
    fn relative_l1(&self, fit: &PointFit, norm: f64) -> f64 {
        self.1.fetch_add(1, Ordering::Relaxed);
        self.0.relative_l1(fit, norm)
    }
}

#[test]
fn a_step_is_one_iteration_and_the_fit_never_worse_than_its_starts() {
    let settings = FitSettings::default();
    let fit_strata = FitStrata::new(&settings);
    let (lobe, i, j) = (Lobe::Specular, 20, 50);
    let problem = CellProblem::new(lobe, i, j, &settings, &fit_strata);
    let nodes = strata(QUADRATURE_STRATA);
    let q = CellQuadrature::new(lobe, problem.view, problem.alpha, &nodes);
    let q = Counted(q, AtomicUsize::new(0));
    let stored = PointFit::stored(Lut::shipped(Table::Classic).cell(i, j), lobe);
    let nudged = PointFit {
        entries: stored.entries.map(|x| 1.1 * x),
        scale: 1.0,
    };
    let starts = [stored, nudged];
    let free = PointObjective::Lobe.free(lobe);
    let mut fitter = CellFitter::new(&q, problem.norm, &starts, free, &settings);
    let (mut most, mut observed) = (0, 0);
    let fit = loop {
        q.1.store(0, Ordering::Relaxed);
        let next = fitter.next(&q);
        most = most.max(q.1.load(Ordering::Relaxed));
        match next {
            FitNext::Observed { count, .. } => {
                observed += 1;
                assert_eq!(count, observed);
            }
            FitNext::Done(fit) => break fit,
        }
    };
    // D = 5 (four entries and the scale): a run's step (D + 2), its end measured (1) and
    // the next run's simplex (D + 1).
    assert!(
        most <= 2 * 5 + 4,
        "a step evaluated the objective {most} times"
    );
    assert_eq!(fitter.iterations(), observed);
    // Six runs (two starts, three restarts each) of at least one iteration.
    assert!(observed >= 2 * RESTARTS, "{observed} iterations");
    let value = |f: &PointFit| q.0.relative_l1(f, problem.norm);
    for start in &starts {
        assert!(
            value(&fit) <= value(start),
            "{fit:?} is worse than {start:?}"
        );
    }
}
