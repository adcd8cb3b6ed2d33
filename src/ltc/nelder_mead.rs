//! Downhill simplex (Nelder & Mead 1965) with the standard coefficients and the termination
//! test of Numerical Recipes (3rd ed., §10.5) — the variant ltc_code's fitter uses.

/// What an observer that never stops the search returns.
pub const CONTINUE: std::ops::ControlFlow<()> = std::ops::ControlFlow::Continue(());

/// The outcome of a minimization.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Minimum<const D: usize> {
    pub point: [f64; D],
    pub value: f64,
    /// Simplex iterations taken (at most the limit).
    pub iterations: usize,
    /// Whether the tolerance test stopped it (rather than the iteration limit).
    pub converged: bool,
}

/// Minimizes `f` from `start` with an initial simplex of step `delta` along each axis; stops
/// when `2|f_hi − f_lo| < tol (|f_hi| + |f_lo|)` or after `max_iterations`. `observe` sees the
/// best value after every iteration (the lab plots it) and may stop the search there.
pub fn nelder_mead<const D: usize>(
    start: [f64; D],
    delta: f64,
    tol: f64,
    max_iterations: usize,
    mut f: impl FnMut(&[f64; D]) -> f64,
    mut observe: impl FnMut(usize, f64) -> std::ops::ControlFlow<()>,
) -> Minimum<D> {
    // Standard coefficients (Nelder & Mead 1965).
    const REFLECT: f64 = 1.0;
    const EXPAND: f64 = 2.0;
    const CONTRACT: f64 = 0.5;
    const SHRINK: f64 = 0.5;

    let mut simplex: Vec<[f64; D]> = (0..=D)
        .map(|i| {
            let mut p = start;
            if i > 0 {
                p[i - 1] += delta;
            }
            p
        })
        .collect();
    let mut values: Vec<f64> = simplex.iter().map(&mut f).collect();

    let along = |o: &[f64; D], worst: &[f64; D], t: f64| -> [f64; D] {
        std::array::from_fn(|k| o[k] + t * (o[k] - worst[k]))
    };

    let mut lo = 0;
    for iteration in 0..max_iterations {
        let (mut hi, mut nh) = (0, 0);
        lo = 0;
        for i in 1..=D {
            if values[i] < values[lo] {
                lo = i;
            }
            if values[i] > values[hi] {
                nh = hi;
                hi = i;
            } else if values[i] > values[nh] {
                nh = i;
            }
        }
        if observe(iteration, values[lo]).is_break() {
            return Minimum {
                point: simplex[lo],
                value: values[lo],
                iterations: iteration,
                converged: false,
            };
        }

        let (a, b) = (values[lo].abs(), values[hi].abs());
        if 2.0 * (a - b).abs() < (a + b) * tol {
            return Minimum {
                point: simplex[lo],
                value: values[lo],
                iterations: iteration,
                converged: true,
            };
        }

        // Centroid of all points but the worst.
        let mut o = [0.0; D];
        for (i, p) in simplex.iter().enumerate() {
            if i != hi {
                for k in 0..D {
                    o[k] += p[k] / D as f64;
                }
            }
        }

        let worst = simplex[hi];
        let r = along(&o, &worst, REFLECT);
        let fr = f(&r);
        if fr < values[nh] {
            if fr < values[lo] {
                let e = along(&o, &worst, EXPAND);
                let fe = f(&e);
                if fe < fr {
                    simplex[hi] = e;
                    values[hi] = fe;
                    continue;
                }
            }
            simplex[hi] = r;
            values[hi] = fr;
            continue;
        }

        let c = along(&o, &worst, -CONTRACT);
        let fc = f(&c);
        if fc < values[hi] {
            simplex[hi] = c;
            values[hi] = fc;
            continue;
        }

        let best = simplex[lo];
        for i in 0..=D {
            if i != lo {
                simplex[i] = std::array::from_fn(|k| best[k] + SHRINK * (simplex[i][k] - best[k]));
                values[i] = f(&simplex[i]);
            }
        }
    }
    Minimum {
        point: simplex[lo],
        value: values[lo],
        iterations: max_iterations,
        converged: false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_the_minimum_of_a_shifted_quadratic() {
        let m = nelder_mead(
            [0.0, 0.0],
            0.5,
            1e-12,
            500,
            |p| (p[0] - 1.0).powi(2) + 3.0 * (p[1] + 2.0).powi(2) + 0.25,
            |_, _| CONTINUE,
        );
        assert!(m.converged);
        // The tolerance is on f's relative spread: 1e-12 of 0.25 bounds |Δp|² ~ 1e-13.
        assert!((m.point[0] - 1.0).abs() < 1e-5, "{m:?}");
        assert!((m.point[1] + 2.0).abs() < 1e-5, "{m:?}");
        assert!((m.value - 0.25).abs() < 1e-10);
    }

    #[test]
    fn stops_at_the_iteration_limit() {
        let m = nelder_mead([10.0], 0.01, 0.0, 7, |p| p[0] * p[0] + 1.0, |_, _| CONTINUE);
        assert!(!m.converged);
        assert_eq!(m.iterations, 7);
    }
}
