//! A channel of the table as one closed-form rational function `P(r, s) / Q(r, s)` of total
//! degree `D` each (docs/design.md §2.10): what an engine can evaluate per lookup with no
//! texture at all. Both are series of Chebyshev products `T_a(x(r)) T_b(x(s))`, `a + b ≤ D`
//! (better conditioned on [0, 1]² than monomials); `Q`'s constant term is 1.
//!
//! Fitted by Sanathanan & Koerner's iteration (IEEE Trans. Automatic Control 8(1), 1963): the
//! linear problem `P − f (Q − 1) = f` weighted by `1/|Q|` of the previous pass, so that it
//! converges on the rational error itself.

use crate::ltc::lut::formula::chebyshev::{chebyshev_terms, chebyshev_x};
use crate::ltc::lut::formula::least_squares::least_squares;

/// Reweighting passes: on the shipped tables each pass past the eighth changes a channel's
/// largest error by under 1%.
const PASSES: usize = 12;

/// Below this fraction of a channel's largest value, its error is fitted as absolute, above
/// as relative. Measured (`lut --encodings --formulas rational6,rational8`, 256 cases a
/// band): floors of 1 (all absolute), 0.3, 0.1, 0.03 and 0.01 of the largest; 0.3 added the
/// least light at both degrees, where α ≥ 0.1 and below.
const RELATIVE_FLOOR: f64 = 0.3;

/// The Chebyshev products of total degree at most `degree`: `(a, b)` with `a + b ≤ degree`.
pub fn total_degree_pairs(degree: usize) -> Vec<(usize, usize)> {
    (0..=degree)
        .flat_map(|a| (0..=degree - a).map(move |b| (a, b)))
        .collect()
}

/// The basis at `(r, s)`, in `total_degree_pairs`' order.
fn basis(pairs: &[(usize, usize)], degree: usize, r: f64, s: f64) -> Vec<f64> {
    let tr = chebyshev_terms(degree + 1, chebyshev_x(r));
    let ts = chebyshev_terms(degree + 1, chebyshev_x(s));
    pairs.iter().map(|&(a, b)| tr[a] * ts[b]).collect()
}

/// The coefficients of `P` (every pair) and then of `Q` (every pair but the constant), fitted
/// to `values[j·n + i]` at `(i/(n−1), j/(n−1))`, the error relative to each value down to
/// `RELATIVE_FLOOR` of the channel's largest and absolute below. It starts from the polynomial fit (`Q = 1`); a pass
/// whose `Q` has a zero on [0, 1]² (checked on a grid four times the table's) or whose largest
/// error is no smaller is taken only part of the way from the last fit (halving, four times),
/// as both `Q`s positive make every blend of them positive; where no part helps, the fit stops.
pub fn rational_fit(values: &[f64], n: usize, degree: usize) -> Vec<f64> {
    let pairs = total_degree_pairs(degree);
    let at = |k: usize| k as f64 / (n - 1) as f64;
    let cells: Vec<(Vec<f64>, f64)> = (0..n * n)
        .map(|k| (basis(&pairs, degree, at(k % n), at(k / n)), values[k]))
        .collect();
    let largest = values.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let floor = (RELATIVE_FLOOR * largest).max(f64::MIN_POSITIVE);
    let weight = |f: f64| 1.0 / f.abs().max(floor);
    let weighted = |phi: &[f64], f: f64| phi.iter().map(|x| x * weight(f)).collect();
    let polynomial = least_squares(
        &cells
            .iter()
            .map(|(phi, f)| weighted(phi, *f))
            .collect::<Vec<_>>(),
        &values.iter().map(|f| f * weight(*f)).collect::<Vec<_>>(),
    )
    .unwrap_or_else(|| vec![0.0; pairs.len()]);
    let mut best: Vec<f64> = polynomial
        .into_iter()
        .chain(std::iter::repeat_n(0.0, pairs.len() - 1))
        .collect();
    // The largest weighted error over the cells.
    let largest_error = |c: &[f64]| {
        let error = |(phi, f): &(Vec<f64>, f64)| (ratio(c, phi) - f).abs() * weight(*f);
        cells.iter().map(error).fold(0.0, f64::max)
    };
    let mut best_error = largest_error(&best);
    for _ in 0..PASSES {
        // P − f (Q − 1) = f, each row divided by the last fit's |Q|.
        let (rows, rhs): (Vec<Vec<f64>>, Vec<f64>) = cells
            .iter()
            .map(|(phi, f)| {
                let w = weight(*f) / denominator(&best, phi).abs();
                let p = phi.iter().map(|x| x * w);
                let q = phi[1..].iter().map(|x| -f * x * w);
                (p.chain(q).collect(), f * w)
            })
            .unzip();
        let Some(next) = least_squares(&rows, &rhs) else {
            break;
        };
        let blends = [1.0, 0.5, 0.25, 0.125, 0.0625].map(|t| {
            let blend: Vec<f64> = next
                .iter()
                .zip(&best)
                .map(|(n, o)| o + t * (n - o))
                .collect();
            blend
        });
        let better = blends.into_iter().find_map(|c| {
            let e = largest_error(&c);
            (e < best_error && denominator_positive(&c, &pairs, degree, 4 * n)).then_some((c, e))
        });
        let Some((c, e)) = better else {
            break;
        };
        (best, best_error) = (c, e);
    }
    best
}

/// `P/Q` from the coefficients and the basis at a point.
fn ratio(c: &[f64], phi: &[f64]) -> f64 {
    let p: f64 = c[..phi.len()].iter().zip(phi).map(|(a, x)| a * x).sum();
    p / denominator(c, phi)
}

/// `Q` from the coefficients and the basis at a point.
fn denominator(c: &[f64], phi: &[f64]) -> f64 {
    let t = phi.len();
    1.0 + c[t..]
        .iter()
        .zip(&phi[1..])
        .map(|(q, x)| q * x)
        .sum::<f64>()
}

/// Whether `Q > 0` at every point of an `m × m` grid on [0, 1]² (a pole inside the table's
/// square would put an infinity between its cells).
fn denominator_positive(c: &[f64], pairs: &[(usize, usize)], degree: usize, m: usize) -> bool {
    let at = |k: usize| k as f64 / (m - 1) as f64;
    (0..m * m).all(|k| denominator(c, &basis(pairs, degree, at(k % m), at(k / m))) > 1e-6)
}

/// The fit `c` at the table's axes `(r, s)`.
pub fn rational_value(c: &[f64], degree: usize, r: f64, s: f64) -> f64 {
    let pairs = total_degree_pairs(degree);
    ratio(c, &basis(&pairs, degree, r, s))
}

/// Coefficients a channel: `P`'s and `Q`'s but its constant.
pub fn rational_coefficients(degree: usize) -> usize {
    2 * total_degree_pairs(degree).len() - 1
}
