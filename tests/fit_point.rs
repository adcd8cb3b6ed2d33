//! The point-light fit: on a coarse grid it is never worse than the classic fit at any cell
//! and lower on average; its quadrature is fine enough on the hardest cells; the shipped
//! table is what the file holds.

use ltc_lab::ltc::fit::{CellProblem, FitSettings, FitStrata, fit_table};
use ltc_lab::ltc::fit_point::{
    CellQuadrature, QUADRATURE_STEPS, entries, fit_point_table, normalized_matrix,
    quadrature_centre,
};
use ltc_lab::ltc::lobe::Lobe;
use ltc_lab::ltc::lut::{Channel, Lut};

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
        // The 64² table halves the specular error at mid view angles and gains less at
        // normal and grazing views (0.61× overall); on this 8² grid the measured ratio is
        // 0.6–0.7, so 0.8 states a margin that a broken fit (ratio → 1) cannot meet.
        if ch == Channel::SpecErr {
            assert!(
                p_sum <= 0.8 * c_sum,
                "mean spec.err ratio {}",
                p_sum / c_sum
            );
        } else {
            assert!(p_sum <= c_sum);
        }
    }
}

/// The objective by the fit's 48-step quadrature against a 4× finer one, at the shipped
/// point fit of the hardest cells where it holds: the smallest α at normal and oblique
/// views, α = 0.004 to 76°, α = 0.036 at 85°, and the grazing row from α = 0.036 up. (At
/// grazing with α ≤ 0.016 it does not: 3.6 against 1.2 at α = 0.004 — see QUADRATURE_STEPS.)
/// 5%: the largest difference measured on these cells is 2.9%, at (12, 60).
#[test]
fn quadrature_is_fine_enough_on_the_hardest_cells() {
    let lut = Lut::embedded_point();
    let settings = FitSettings::default();
    let strata = FitStrata::new(&settings);
    for (i, j) in [
        (1, 0),
        (1, 30),
        (2, 50),
        (4, 55),
        (8, 58),
        (12, 60),
        (12, 63),
        (16, 63),
        (20, 63),
        (63, 63),
    ] {
        let problem = CellProblem::new(Lobe::Specular, i, j, &settings, &strata);
        let m = normalized_matrix(entries(lut.cell(i, j), Lobe::Specular));
        let at = |steps| {
            CellQuadrature::new(
                Lobe::Specular,
                problem.view,
                problem.alpha,
                quadrature_centre(Lobe::Specular, problem.view),
                steps,
            )
            .relative_l1(m, problem.norm)
        };
        let (coarse, fine) = (at(QUADRATURE_STEPS), at(4 * QUADRATURE_STEPS));
        assert!(
            (coarse - fine).abs() <= 0.05 * fine + 1e-3,
            "cell ({i}, {j}): {coarse} by {QUADRATURE_STEPS} steps, {fine} by {}",
            4 * QUADRATURE_STEPS
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
        // Same albedos: the point fit changes the shape only.
        for ch in [Channel::SpecNorm, Channel::SpecFresnel, Channel::DiffNorm] {
            assert_eq!(p.get(ch), c.get(ch));
        }
    }
}
