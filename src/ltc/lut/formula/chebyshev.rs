//! A channel of the table as a tensor Chebyshev series of degree `D` on each axis, as three.js
//! PR #34611 ships its tables (coefficients in the code, the 64² textures rebuilt from them at
//! run time), fitted here by least squares at the table's cells.

use crate::ltc::lut::formula::least_squares::least_squares;

/// `T_0(x) … T_{n−1}(x)` by the three-term recurrence `T_{k+1} = 2x T_k − T_{k−1}`.
pub fn chebyshev_terms(n: usize, x: f64) -> Vec<f64> {
    let mut t = Vec::with_capacity(n);
    for k in 0..n {
        t.push(match k {
            0 => 1.0,
            1 => x,
            _ => 2.0 * x * t[k - 1] - t[k - 2],
        });
    }
    t
}

/// A table axis's place `t` in [0, 1] as Chebyshev's `x` in [−1, 1].
pub fn chebyshev_x(t: f64) -> f64 {
    2.0 * t - 1.0
}

/// The coefficients `c[a][b]` (row-major, `(D+1)²`) of `Σ c_ab T_a(x(r)) T_b(x(s))` fitting
/// `values[j·n + i]` (cell `i` at `r = i/(n−1)`, row `j` at `s = j/(n−1)`) by least squares.
/// On a tensor grid the fit separates: each row's coefficients along `r`, then each of those
/// along `s`. `None` where the grid has fewer cells a side than the series has terms.
pub fn chebyshev_fit(values: &[f64], n: usize, degree: usize) -> Option<Vec<f64>> {
    let terms = degree + 1;
    let design: Vec<Vec<f64>> = (0..n)
        .map(|i| chebyshev_terms(terms, chebyshev_x(i as f64 / (n - 1) as f64)))
        .collect();
    // Along r, row by row: by_row[j][a].
    let by_row: Vec<Vec<f64>> = (0..n)
        .map(|j| least_squares(&design, &values[j * n..(j + 1) * n]))
        .collect::<Option<_>>()?;
    // Along s, coefficient by coefficient: c[a][b].
    let mut c = vec![0.0; terms * terms];
    for a in 0..terms {
        let column: Vec<f64> = by_row.iter().map(|row| row[a]).collect();
        let along_s = least_squares(&design, &column)?;
        for (b, x) in along_s.into_iter().enumerate() {
            c[a * terms + b] = x;
        }
    }
    Some(c)
}

/// The series `c` (as `chebyshev_fit` gives it) at the table's axes `(r, s)`.
pub fn chebyshev_value(c: &[f64], degree: usize, r: f64, s: f64) -> f64 {
    let terms = degree + 1;
    let tr = chebyshev_terms(terms, chebyshev_x(r));
    let ts = chebyshev_terms(terms, chebyshev_x(s));
    let mut sum = 0.0;
    for (a, ta) in tr.iter().enumerate() {
        for (b, tb) in ts.iter().enumerate() {
            sum += c[a * terms + b] * ta * tb;
        }
    }
    sum
}
