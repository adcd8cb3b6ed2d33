//! One cell's point fit (docs/design.md §4.7) as a search that advances one Nelder–Mead
//! iteration a call, so that a refit can be spread over the browser's frames
//! (docs/design.md §5.8); `fit_cell` runs it to the end, as the table fits do.

use std::ops::ControlFlow;

use crate::ltc::fit::FitSettings;
use crate::ltc::nelder_mead::{CONTINUE, Next, Simplex};
use crate::ltc::point_params::{CellObjective, Free, PointFit, SCALE_MAX, SCALE_MIN};

/// Fits one lobe of a cell from `starts` (the best of them by the objective).
pub fn fit_cell(
    q: &dyn CellObjective,
    norm: f64,
    starts: &[PointFit],
    free: Free,
    settings: &FitSettings,
) -> PointFit {
    fit_cell_observed(q, norm, starts, free, settings, &mut |_, _| CONTINUE)
}

/// `fit_cell`, telling `observe` the best objective so far at every Nelder–Mead iteration
/// (counted across starts and restarts); a `Break` ends the fit with the best point found.
pub fn fit_cell_observed(
    q: &dyn CellObjective,
    norm: f64,
    starts: &[PointFit],
    free: Free,
    settings: &FitSettings,
    observe: &mut dyn FnMut(usize, f64) -> ControlFlow<()>,
) -> PointFit {
    let mut fitter = CellFitter::new(q, norm, starts, free, settings);
    loop {
        match fitter.next(q) {
            FitNext::Observed { count, lowest } => {
                if observe(count, lowest).is_break() {
                    return fitter.stop(q);
                }
            }
            FitNext::Done(fit) => return fit,
        }
    }
}

/// What one call of `CellFitter::next` came to.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FitNext {
    /// Iteration `count` (across starts and restarts) is under way; `lowest` is the best
    /// objective so far.
    Observed { count: usize, lowest: f64 },
    /// The fit ended: the best point of all its runs.
    Done(PointFit),
}

/// One cell's point fit, advanced one Nelder–Mead iteration a call (at most `2D + 4` values
/// of the objective) so that the browser can spread it over frames. From every start,
/// Nelder–Mead restarted from its own result `RESTARTS` times (a collapsed simplex stalls
/// in 4D); the best point wins. The quadrature is passed to every call, not kept.
pub struct CellFitter {
    norm: f64,
    free: Free,
    settings: FitSettings,
    starts: Vec<PointFit>,
    /// The run under way: its start's index, its restart, its search.
    run: Option<(usize, usize, Descent)>,
    best: PointFit,
    best_value: f64,
    count: usize,
    lowest: f64,
}

impl CellFitter {
    pub fn new(
        q: &dyn CellObjective,
        norm: f64,
        starts: &[PointFit],
        free: Free,
        settings: &FitSettings,
    ) -> Self {
        let starts: Vec<PointFit> = starts.iter().map(|&f| free.project(f)).collect();
        let objective = |fit: &PointFit| objective(q, norm, fit);
        let best = *starts
            .iter()
            .min_by(|a, b| objective(a).total_cmp(&objective(b)))
            .expect("at least one start");
        let best_value = objective(&best);
        let run = Descent::new(starts[0], &objective, free, settings);
        Self {
            norm,
            free,
            settings: *settings,
            starts,
            run: Some((0, 0, run)),
            best,
            best_value,
            count: 0,
            lowest: best_value,
        }
    }

    pub fn next(&mut self, q: &dyn CellObjective) -> FitNext {
        let norm = self.norm;
        let objective = |fit: &PointFit| objective(q, norm, fit);
        loop {
            let Some((start, restart, run)) = &mut self.run else {
                return FitNext::Done(self.best);
            };
            let end = match run.next(&objective) {
                RunNext::Observed(f) => {
                    self.count += 1;
                    self.lowest = self.lowest.min(f);
                    return FitNext::Observed {
                        count: self.count,
                        lowest: self.lowest,
                    };
                }
                RunNext::Done(end) => end,
            };
            let (start, restart) = (*start, *restart);
            self.keep(end, &objective);
            self.run = if restart + 1 < RESTARTS {
                Some((start, restart + 1, end))
            } else {
                self.starts.get(start + 1).map(|&s| (start + 1, 0, s))
            }
            .map(|(i, r, from)| {
                (
                    i,
                    r,
                    Descent::new(from, &objective, self.free, &self.settings),
                )
            });
        }
    }

    /// Nelder–Mead iterations so far, across starts and restarts.
    pub fn iterations(&self) -> usize {
        self.count
    }

    /// Ends the fit where it stands: the best point found.
    pub fn stop(&mut self, q: &dyn CellObjective) -> PointFit {
        if let Some((_, _, run)) = self.run.take() {
            let norm = self.norm;
            self.keep(run.stop(), &|fit: &PointFit| objective(q, norm, fit));
        }
        self.best
    }

    fn keep(&mut self, fit: PointFit, objective: &impl Fn(&PointFit) -> f64) {
        let value = objective(&fit);
        if value < self.best_value {
            self.best = fit;
            self.best_value = value;
        }
    }
}

/// The fit's objective: the quadrature's error where the fit is valid, infinite elsewhere.
fn objective(q: &dyn CellObjective, norm: f64, fit: &PointFit) -> f64 {
    if fit.is_valid() {
        q.relative_l1(fit, norm)
    } else {
        f64::INFINITY
    }
}

/// What one call of `Descent::next` came to.
enum RunNext {
    Observed(f64),
    Done(PointFit),
}

/// One Nelder–Mead run from `start` over the entries (relative moves: each scaled by its own
/// size, as they span 1e-4..2) and, with the scale free, the log of the scale. An entry that
/// is not free has no step: the simplex moves along it without changing the fit.
struct Descent {
    start: PointFit,
    step: [f64; 4],
    simplex: Moves,
}

/// The search over the entries alone, or over the entries and the scale.
enum Moves {
    Entries(Simplex<4>),
    WithScale(Simplex<5>),
}

impl Descent {
    fn new(
        start: PointFit,
        objective: &impl Fn(&PointFit) -> f64,
        free: Free,
        settings: &FitSettings,
    ) -> Self {
        let largest = start.entries.iter().fold(0.0f64, |a, y| a.max(y.abs()));
        let mut step = start.entries.map(|x| x.abs().max(1e-3 * largest));
        if !free.m20 {
            step[2] = 0.0;
        }
        let (delta, tol, limit) = (
            settings.simplex_delta,
            settings.tolerance,
            settings.max_iterations,
        );
        let simplex = if free.scale {
            let f = |p: &[f64; 5]| objective(&at(start, step, p));
            Moves::WithScale(Simplex::new([0.0; 5], delta, tol, limit, f))
        } else {
            let f = |p: &[f64; 4]| objective(&at(start, step, p));
            Moves::Entries(Simplex::new([0.0; 4], delta, tol, limit, f))
        };
        Self {
            start,
            step,
            simplex,
        }
    }

    fn next(&mut self, objective: &impl Fn(&PointFit) -> f64) -> RunNext {
        let (start, step) = (self.start, self.step);
        match &mut self.simplex {
            Moves::Entries(s) => run_next(s, start, step, objective),
            Moves::WithScale(s) => run_next(s, start, step, objective),
        }
    }

    fn stop(&self) -> PointFit {
        let (start, step) = (self.start, self.step);
        match &self.simplex {
            Moves::Entries(s) => at(start, step, &s.stop().point),
            Moves::WithScale(s) => at(start, step, &s.stop().point),
        }
    }
}

/// One step of a run's search, in fits.
fn run_next<const D: usize>(
    simplex: &mut Simplex<D>,
    start: PointFit,
    step: [f64; 4],
    objective: &impl Fn(&PointFit) -> f64,
) -> RunNext {
    match simplex.next(|p| objective(&at(start, step, p))) {
        Next::Observed { lowest, .. } => RunNext::Observed(lowest),
        Next::Done(m) => RunNext::Done(at(start, step, &m.point)),
    }
}

/// The fit at simplex point `p`: the entries moved by `p` times their steps and, with
/// `D = 5`, the scale by `exp p[4]`.
fn at<const D: usize>(start: PointFit, step: [f64; 4], p: &[f64; D]) -> PointFit {
    PointFit {
        entries: std::array::from_fn(|k| start.entries[k] + p[k] * step[k]),
        // Clamped rather than walled off: a simplex that meets a plateau keeps moving the
        // other coordinates, one that meets an infinite wall collapses against it.
        scale: if D == 5 {
            (start.scale * p[D - 1].exp()).clamp(SCALE_MIN, SCALE_MAX)
        } else {
            start.scale
        },
    }
}

/// Nelder–Mead runs per start (each from the previous one's result).
pub const RESTARTS: usize = 3;
