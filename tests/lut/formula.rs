//! Formulas in place of the table (docs/design.md §2.10): each fit checked against what an
//! independent formula says, and the fitted tables against the table they replace.

use ltc_lab::ltc::lut::encoding::SHADER_CHANNELS;
use ltc_lab::ltc::lut::formula::{
    chebyshev_fit, chebyshev_terms, chebyshev_value, least_squares, rational_fit, rational_value,
};
use ltc_lab::ltc::lut::{Encoding, Formula, Lut, Storage};

/// `T_k(x) = cos(k · acos x)` on [−1, 1]: the recurrence agrees with the definition to f64's
/// rounding, which grows about linearly with k (1e-13 covers k < 40 with room).
#[test]
fn chebyshev_terms_are_cos_k_acos() {
    for x in [-1.0, -0.7, 0.0, 0.31, 0.999, 1.0f64] {
        for (k, t) in chebyshev_terms(40, x).into_iter().enumerate() {
            let expected = (k as f64 * x.acos()).cos();
            assert!(
                (t - expected).abs() < 1e-13,
                "T_{k}({x}) = {t}, cos form {expected}"
            );
        }
    }
}

/// Least squares solves a square system exactly and an overdetermined consistent one too;
/// a rank-deficient one is refused rather than answered with infinities.
#[test]
fn least_squares_solves_what_it_can_and_refuses_what_it_cannot() {
    // x = (1, −2, 3) through a 4 × 3 system.
    let rows = vec![
        vec![2.0, 1.0, 0.0],
        vec![1.0, 3.0, 1.0],
        vec![0.0, 1.0, 4.0],
        vec![1.0, 0.0, 1.0],
    ];
    let b: Vec<f64> = rows
        .iter()
        .map(|r| r[0] - 2.0 * r[1] + 3.0 * r[2])
        .collect();
    let x = least_squares(&rows, &b).unwrap();
    for (got, want) in x.iter().zip([1.0, -2.0, 3.0]) {
        assert!((got - want).abs() < 1e-12, "{x:?}");
    }
    let dependent = vec![vec![1.0, 2.0], vec![2.0, 4.0], vec![3.0, 6.0]];
    assert_eq!(least_squares(&dependent, &[1.0, 2.0, 3.0]), None);
}

/// A function the series can hold — a polynomial of degree 5 on each axis — is fitted exactly
/// at degree 5 and above (to f64's rounding of a 64-point least squares: 1e-11), between the
/// cells too.
#[test]
fn a_chebyshev_series_holds_a_polynomial_exactly() {
    let f = |r: f64, s: f64| (1.0 + 2.0 * r - r.powi(5)) * (0.5 - s.powi(3) + 0.25 * s.powi(4));
    let n = 64;
    let at = |k: usize| k as f64 / (n - 1) as f64;
    let values: Vec<f64> = (0..n * n).map(|k| f(at(k % n), at(k / n))).collect();
    for degree in [5, 9] {
        let c = chebyshev_fit(&values, n, degree).unwrap();
        for (r, s) in [
            (0.0, 0.0),
            (0.013, 0.97),
            (0.5, 0.5),
            (1.0, 0.2),
            (0.77, 1.0),
        ] {
            let got = chebyshev_value(&c, degree, r, s);
            assert!(
                (got - f(r, s)).abs() < 1e-11,
                "degree {degree} at ({r}, {s})"
            );
        }
    }
    // More terms an axis than cells cannot be fitted.
    assert!(chebyshev_fit(&values[..16], 4, 4).is_none());
}

/// A rational function of total degree 1 is fitted exactly by `rational1` (the iteration
/// settles on it; 1e-9 is the linearised problem's conditioning times f64's rounding).
#[test]
fn a_rational_fit_holds_a_rational_function() {
    let f = |r: f64, s: f64| (1.0 + 3.0 * r - s) / (2.0 + r + 0.5 * s);
    let n = 32;
    let at = |k: usize| k as f64 / (n - 1) as f64;
    let values: Vec<f64> = (0..n * n).map(|k| f(at(k % n), at(k / n))).collect();
    let c = rational_fit(&values, n, 1);
    for (r, s) in [(0.0, 0.0), (0.3, 0.9), (1.0, 1.0), (0.05, 0.5)] {
        let got = rational_value(&c, 1, r, s);
        assert!(
            (got - f(r, s)).abs() < 1e-9,
            "at ({r}, {s}): {got} against {}",
            f(r, s)
        );
    }
}

/// Each channel of a decoded formula table, against the table, as the largest difference
/// over its cells divided by the channel's range.
fn largest_relative_difference(lut: &Lut, encoding: Encoding) -> f64 {
    let decoded = encoding.decoded(lut);
    SHADER_CHANNELS
        .iter()
        .map(|&c| {
            let values: Vec<f64> = lut.cells.iter().map(|cell| cell.shaded(c)).collect();
            let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let got = decoded.cells.iter().map(|cell| cell.shaded(c));
            let worst = values
                .iter()
                .zip(got)
                .map(|(v, g)| (v - g).abs())
                .fold(0.0, f64::max);
            worst / (hi - lo).max(1e-30)
        })
        .fold(0.0, f64::max)
}

/// The shipped table by formulas: every value finite and inside its channel's range (the
/// clamp an engine applies); a Chebyshev series of higher degree nearer the table, and each
/// series' largest miss where a series rings, at the table's edges (α → 0 or grazing).
#[test]
fn formulas_rebuild_the_shipped_table_finite_and_nearer_at_higher_degree() {
    let lut = Lut::embedded();
    let named = |s: &str| Encoding::parse(s).unwrap();
    for name in [
        "cheb8",
        "cheb24",
        "cheb16-f16",
        "rational4",
        "rational8-unorm8",
    ] {
        let decoded = named(name).decoded(lut);
        assert_eq!(decoded.size, lut.size, "{name}");
        for cell in &decoded.cells {
            assert!(cell.0.iter().all(|v| v.is_finite()), "{name}: {cell:?}");
        }
    }
    let [d8, d16, d24] =
        ["cheb8", "cheb16", "cheb24"].map(|n| largest_relative_difference(lut, named(n)));
    assert!(
        d8 > d16 && d16 > d24,
        "cheb8 {d8}, cheb16 {d16}, cheb24 {d24}"
    );
    // Where cheb16 misses most: the outer columns (α → 0) or rows (θo → 90°).
    let fit = Formula::Chebyshev(16).fitted(lut);
    let n = lut.size;
    let mut worst = (0.0, 0, 0);
    for (k, &c) in SHADER_CHANNELS.iter().enumerate() {
        let [lo, hi] = fit.channels[k].range;
        for j in 0..n {
            for i in 0..n {
                let at = |x: usize| x as f64 / (n - 1) as f64;
                let miss =
                    (fit.value(k, at(i), at(j)) - lut.cell(i, j).shaded(c)).abs() / (hi - lo);
                if miss > worst.0 {
                    worst = (miss, i, j);
                }
            }
        }
    }
    let (_, i, j) = worst;
    assert!(
        i <= 4 || j >= n - 5,
        "cheb16 misses most at cell ({i}, {j}), inside the table"
    );
}

/// A formula's name reads back as itself; degrees out of range and a storage that is not one
/// are refused naming what is wrong; its bytes are its coefficients and ranges in f32.
#[test]
fn a_formula_is_named_as_it_is_read_and_costs_its_coefficients() {
    for name in [
        "cheb1",
        "cheb16",
        "cheb40-f16",
        "rational3",
        "rational8-unorm10",
    ] {
        assert_eq!(Encoding::parse(name).unwrap().name(), name);
    }
    assert!(Encoding::parse("cheb41").unwrap_err().contains("1 to 40"));
    assert!(Encoding::parse("rational0").unwrap_err().contains("`0`"));
    assert!(Encoding::parse("cheb8-16").unwrap_err().contains("`16`"));
    let cheb16 = Encoding::parse("cheb16-f16").unwrap();
    assert_eq!(cheb16.storage, Storage::F16);
    assert_eq!(cheb16.bytes(64), 4 * 11 * 17 * 17 + 11 * 2 * 4);
    // P's 45 pairs of total degree ≤ 8 and Q's 44.
    assert_eq!(Formula::Rational(8).coefficients_per_channel(), 89);
    // A series of more terms an axis than an 8² table has cells is fitted at degree 7, and
    // the decoding says so.
    let small = Encoding::parse("f32-8").unwrap().decoded(Lut::embedded());
    let (_, note) = Encoding::parse("cheb12").unwrap().decoded_saying(&small);
    assert!(note.unwrap().contains("cheb7"));
}

/// Where encodings fail (docs/design.md §2.10's failures): the cells whose `M⁻¹` an encoding
/// turns flat or inside out. A Chebyshev series rings at the table's edges — the first
/// columns (α → 0) and the last rows (θo → 90°) — and nowhere inside; 8 bits round the
/// near-mirror columns' small entries to 0. The shipped table has none, and a series of
/// degree 28 none either (measured: 28 cells at degree 8, 2 at 16, 0 from 28).
#[test]
fn encodings_turn_m_inverse_inside_out_only_at_the_tables_edges() {
    let lut = Lut::embedded();
    assert_eq!(lut.inside_out_cells(), 0);
    let n = lut.size;
    // (i, j) of each cell an encoding turns inside out.
    let cells = |name: &str| -> Vec<(usize, usize)> {
        let decoded = Encoding::parse(name).unwrap().decoded(lut);
        (0..n * n)
            .filter(|&k| {
                let single = Lut {
                    cells: vec![decoded.cells[k]],
                    size: 1,
                    ..Lut::default()
                };
                single.inside_out_cells() == 1
            })
            .map(|k| (k % n, k / n))
            .collect()
    };
    for name in ["cheb8", "cheb16"] {
        let at = cells(name);
        assert!(
            !at.is_empty(),
            "{name} no longer turns a cell inside out: pin it anew"
        );
        assert!(
            at.iter().all(|&(i, j)| i <= 8 || j >= n - 5),
            "{name} inside out away from the edges: {at:?}"
        );
    }
    assert_eq!(cells("cheb28"), []);
    let byte = cells("unorm8");
    assert!(
        !byte.is_empty() && byte.iter().all(|&(i, _)| i <= 8),
        "unorm8: {byte:?}"
    );
}
