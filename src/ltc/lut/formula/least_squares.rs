//! Linear least squares by Householder QR (Golub & Van Loan, "Matrix Computations", §5.3):
//! the formulas' fits solve systems of a few hundred rows and at most a few hundred unknowns,
//! whose normal equations would square a condition number that equispaced Chebyshev columns
//! already make large.

/// The `x` minimising `|A x − b|`, `A` given by its rows (each as long as `x`). `None` where a
/// column is (numerically) a combination of the others: the fit asked for more than the data
/// can hold.
pub fn least_squares(rows: &[Vec<f64>], b: &[f64]) -> Option<Vec<f64>> {
    let m = rows.len();
    let n = rows.first().map_or(0, Vec::len);
    if m < n || b.len() != m {
        return None;
    }
    // Column-major copy, reduced in place.
    let mut a: Vec<Vec<f64>> = (0..n)
        .map(|j| rows.iter().map(|r| r[j]).collect())
        .collect();
    let mut y = b.to_vec();
    let largest = a.iter().flatten().fold(0.0f64, |acc, x| acc.max(x.abs()));
    for k in 0..n {
        let norm = a[k][k..].iter().map(|x| x * x).sum::<f64>().sqrt();
        // A pivot this small against the matrix's largest entry: rank lost in f64.
        if norm <= largest * 1e-13 {
            return None;
        }
        let alpha = if a[k][k] > 0.0 { -norm } else { norm };
        let mut v: Vec<f64> = a[k][k..].to_vec();
        v[0] -= alpha;
        let vv: f64 = v.iter().map(|x| x * x).sum();
        if vv > 0.0 {
            for col in a.iter_mut().skip(k) {
                reflect(&v, vv, &mut col[k..]);
            }
            reflect(&v, vv, &mut y[k..]);
        }
    }
    // Back substitution on the triangle.
    let mut x = vec![0.0; n];
    for i in (0..n).rev() {
        let s: f64 = (i + 1..n).map(|j| a[j][i] * x[j]).sum();
        x[i] = (y[i] - s) / a[i][i];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// `w ← (I − 2 v vᵀ / vᵀv) w`.
fn reflect(v: &[f64], vv: f64, w: &mut [f64]) {
    let d: f64 = v.iter().zip(w.iter()).map(|(a, b)| a * b).sum();
    let f = 2.0 * d / vv;
    for (wi, vi) in w.iter_mut().zip(v) {
        *wi -= f * vi;
    }
}
