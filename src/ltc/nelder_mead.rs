//! Downhill simplex (Nelder & Mead 1965) with the standard coefficients and the termination
//! test of Numerical Recipes (3rd ed., §10.5) — the variant ltc_code's fitter uses. The
//! search is a `Simplex` that advances one iteration a call, so that a fit can be spread over
//! the browser's frames (docs/design.md §5.8); `nelder_mead` runs one to the end.

use std::ops::ControlFlow;

/// What an observer that never stops the search returns.
pub const CONTINUE: ControlFlow<()> = ControlFlow::Continue(());

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

/// What one call of `Simplex::next` came to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Next<const D: usize> {
    /// Iteration `iteration` is about to move the simplex, whose best value is `lowest`.
    Observed { iteration: usize, lowest: f64 },
    /// The search ended: by its tolerance or its iteration limit.
    Done(Minimum<D>),
}

/// A search under way: `D + 1` points and their values.
#[derive(Clone, Debug)]
pub struct Simplex<const D: usize> {
    points: Vec<[f64; D]>,
    values: Vec<f64>,
    tol: f64,
    max_iterations: usize,
    iteration: usize,
    /// The best point as of the last ranking (what a stop returns).
    lo: usize,
    /// Ranked and observed: the next call tests and moves.
    ranked: Option<(usize, usize)>,
}

impl<const D: usize> Simplex<D> {
    /// The initial simplex, `start` and a step of `delta` along each axis (`D + 1` values of
    /// `f`). It stops when `2|f_hi − f_lo| < tol (|f_hi| + |f_lo|)` or after
    /// `max_iterations`.
    pub fn new(
        start: [f64; D],
        delta: f64,
        tol: f64,
        max_iterations: usize,
        mut f: impl FnMut(&[f64; D]) -> f64,
    ) -> Self {
        let points: Vec<[f64; D]> = (0..=D)
            .map(|i| {
                let mut p = start;
                if i > 0 {
                    p[i - 1] += delta;
                }
                p
            })
            .collect();
        let values = points.iter().map(&mut f).collect();
        Self {
            points,
            values,
            tol,
            max_iterations,
            iteration: 0,
            lo: 0,
            ranked: None,
        }
    }

    /// One step, at most `D + 2` values of `f`: the move of the iteration observed last, then
    /// the ranking of the next one, which is observed (or ends the search).
    pub fn next(&mut self, mut f: impl FnMut(&[f64; D]) -> f64) -> Next<D> {
        if let Some((hi, nh)) = self.ranked.take() {
            let (a, b) = (self.values[self.lo].abs(), self.values[hi].abs());
            if 2.0 * (a - b).abs() < (a + b) * self.tol {
                return Next::Done(self.minimum(true));
            }
            self.advance(hi, nh, &mut f);
            self.iteration += 1;
        }
        if self.iteration >= self.max_iterations {
            return Next::Done(self.minimum(false));
        }
        self.ranked = Some(self.rank());
        Next::Observed {
            iteration: self.iteration,
            lowest: self.values[self.lo],
        }
    }

    /// Ends the search where it stands: the best point of the last ranking, not converged.
    pub fn stop(&self) -> Minimum<D> {
        self.minimum(false)
    }

    fn minimum(&self, converged: bool) -> Minimum<D> {
        Minimum {
            point: self.points[self.lo],
            value: self.values[self.lo],
            iterations: self.iteration,
            converged,
        }
    }

    /// Sets the best point; the worst and the next worst.
    fn rank(&mut self) -> (usize, usize) {
        let values = &self.values;
        let (mut hi, mut nh) = (0, 0);
        self.lo = 0;
        for i in 1..=D {
            if values[i] < values[self.lo] {
                self.lo = i;
            }
            if values[i] > values[hi] {
                nh = hi;
                hi = i;
            } else if values[i] > values[nh] {
                nh = i;
            }
        }
        (hi, nh)
    }

    /// Replaces the worst point by its reflection, expansion or contraction through the
    /// others' centroid, or shrinks the simplex towards the best point.
    fn advance(&mut self, hi: usize, nh: usize, f: &mut impl FnMut(&[f64; D]) -> f64) {
        // Standard coefficients (Nelder & Mead 1965).
        const REFLECT: f64 = 1.0;
        const EXPAND: f64 = 2.0;
        const CONTRACT: f64 = 0.5;
        const SHRINK: f64 = 0.5;

        let mut o = [0.0; D];
        for (i, p) in self.points.iter().enumerate() {
            if i != hi {
                for k in 0..D {
                    o[k] += p[k] / D as f64;
                }
            }
        }
        let worst = self.points[hi];
        let along = |t: f64| -> [f64; D] { std::array::from_fn(|k| o[k] + t * (o[k] - worst[k])) };
        let (lo, values) = (self.lo, &self.values);
        let r = along(REFLECT);
        let fr = f(&r);
        let replacement = if fr < values[nh] {
            let e = (fr < values[lo]).then(|| along(EXPAND));
            match e.map(|e| (e, f(&e))) {
                Some((e, fe)) if fe < fr => Some((e, fe)),
                _ => Some((r, fr)),
            }
        } else {
            let c = along(-CONTRACT);
            let fc = f(&c);
            (fc < values[hi]).then_some((c, fc))
        };
        if let Some((p, v)) = replacement {
            self.points[hi] = p;
            self.values[hi] = v;
            return;
        }
        let best = self.points[lo];
        for i in 0..=D {
            if i != lo {
                let p = &mut self.points[i];
                *p = std::array::from_fn(|k| best[k] + SHRINK * (p[k] - best[k]));
                self.values[i] = f(p);
            }
        }
    }
}

/// Minimizes `f` from `start` with an initial simplex of step `delta` along each axis; stops
/// by `Simplex`'s tolerance test or after `max_iterations`. `observe` sees the best value
/// at the start of every iteration (the lab plots it) and may stop the search there.
pub fn nelder_mead<const D: usize>(
    start: [f64; D],
    delta: f64,
    tol: f64,
    max_iterations: usize,
    mut f: impl FnMut(&[f64; D]) -> f64,
    mut observe: impl FnMut(usize, f64) -> ControlFlow<()>,
) -> Minimum<D> {
    let mut simplex = Simplex::new(start, delta, tol, max_iterations, &mut f);
    loop {
        match simplex.next(&mut f) {
            Next::Observed { iteration, lowest } => {
                if observe(iteration, lowest).is_break() {
                    return simplex.stop();
                }
            }
            Next::Done(minimum) => return minimum,
        }
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

    #[test]
    fn a_step_evaluates_at_most_d_plus_2_points() {
        // Rosenbrock's valley makes the simplex reflect, expand, contract and shrink.
        let count = std::cell::Cell::new(0);
        let f = |p: &[f64; 3]| {
            count.set(count.get() + 1);
            (1.0 - p[0]).powi(2) + 100.0 * (p[1] - p[0] * p[0]).powi(2) + (p[2] - 0.5).powi(2)
        };
        let mut simplex = Simplex::new([-1.2, 1.0, 0.0], 0.1, 1e-12, 5000, f);
        assert_eq!(count.get(), 4, "the initial simplex is D + 1 points");
        let (mut steps, mut most) = (0, 0);
        let minimum = loop {
            count.set(0);
            let next = simplex.next(f);
            most = most.max(count.get());
            steps += 1;
            if let Next::Done(m) = next {
                break m;
            }
        };
        // Reflect, contract, then shrink the D other points: the bound, reached.
        assert_eq!(most, 5, "a step evaluated {most} points");
        assert!(
            steps > 50 && minimum.converged,
            "{minimum:?} after {steps} steps"
        );
        assert!((minimum.point[0] - 1.0).abs() < 1e-3, "{minimum:?}");
    }

    #[test]
    fn a_stop_keeps_the_best_point_so_far() {
        let f = |p: &[f64; 2]| (p[0] - 3.0).powi(2) + (p[1] - 1.0).powi(2);
        let mut simplex = Simplex::new([0.0, 0.0], 0.5, 1e-12, 500, f);
        let mut lowest = f64::INFINITY;
        for _ in 0..10 {
            match simplex.next(f) {
                Next::Observed { lowest: l, .. } => lowest = l,
                Next::Done(m) => panic!("converged too early: {m:?}"),
            }
        }
        let m = simplex.stop();
        assert!(!m.converged);
        assert_eq!(m.iterations, 9);
        assert_eq!(m.value, lowest);
        assert_eq!(f(&m.point), m.value);
    }
}
