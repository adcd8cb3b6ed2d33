//! "Refit this cell": a fitter run live on one cell of the table, on a worker thread (in the
//! browser, one iteration a step over the frames: `background::spawn_steps`), from
//! the stored cell's own parameters: ltc_code's (the classic table's) or the point fit's
//! (the point table's). Its objective per iteration for the plot, a cancel, and the result
//! kept with the lab's state (the lobe panel shows the refitted lobe).

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;

use crate::app::lab::refit_result::{Objective, RefitResult};
use crate::ltc::cell_fitter::{CellFitter, FitNext};
use crate::ltc::fit::{CellProblem, FitSettings, FitStrata, pointwise_error};
use crate::ltc::fit_point::{CellQuadrature, PointObjective, QUADRATURE_STRATA};
use crate::ltc::lobe::Lobe;
use crate::ltc::lut::{Lut, normalized_cos_from_brdf};
use crate::ltc::nelder_mead::{Next, Simplex};
use crate::ltc::point_params::PointFit;
use crate::ltc::{cos_from_brdf_from_entries, mat3_rows};

enum Event {
    Iteration(usize, f64),
    Done(Box<RefitResult>),
}

/// A refit under way.
pub struct Refit {
    pub lobe: Lobe,
    pub cell: (usize, usize),
    pub history: Vec<[f64; 2]>,
    pub max_iterations: usize,
    cancel: Arc<AtomicBool>,
    rx: mpsc::Receiver<Event>,
}

/// Strata per side of the pointwise error compared (the shipped tables' `err` channel's).
const ERROR_SAMPLES: usize = 64;

impl Refit {
    /// Refits cell `(i, j)` of `lut` for `lobe` by `objective`, starting from the stored cell.
    pub fn start(lobe: Lobe, (i, j): (usize, usize), lut: &Lut, objective: Objective) -> Self {
        let (tx, rx) = mpsc::channel();
        let settings = FitSettings {
            size: lut.size,
            alpha_min: lut.alpha_min,
            ..FitSettings::default()
        };
        let stored = PointFit::stored(lut.cell(i, j), lobe);
        let cancel = Arc::new(AtomicBool::new(false));
        let mut job = Job {
            lobe,
            cell: (i, j),
            settings,
            stored,
            objective,
            stage: Stage::Setup,
            cancel: cancel.clone(),
            tx,
            abandoned: false,
        };
        crate::app::work::background::spawn_steps("refit", Box::new(move || job.step()));
        Self {
            lobe,
            cell: (i, j),
            history: Vec::new(),
            max_iterations: match objective {
                // Each start's runs, each up to the limit.
                Objective::Point => settings.max_iterations * crate::ltc::cell_fitter::RESTARTS,
                Objective::LtcCode => settings.max_iterations,
            },
            cancel,
            rx,
        }
    }

    /// Stops the fit at its next iteration (the result still arrives, marked cancelled).
    pub fn cancel(&self) {
        self.cancel.store(true, Ordering::Relaxed);
    }

    /// Takes what the worker sent; the result once it is done.
    pub fn poll(&mut self) -> Option<RefitResult> {
        while let Ok(e) = self.rx.try_recv() {
            match e {
                Event::Iteration(k, f) => self.history.push([k as f64, f]),
                Event::Done(mut r) => {
                    r.history = std::mem::take(&mut self.history);
                    return Some(*r);
                }
            }
        }
        None
    }

    /// The fraction of the iteration limit used so far.
    pub fn progress(&self) -> f32 {
        self.history.len() as f32 / self.max_iterations.max(1) as f32
    }
}

/// A refit's inputs and where it stands, moved to its thread (the desktop) or stepped over
/// the browser's frames: one Nelder–Mead iteration a step, after a first step that sets the
/// cell's problem up.
struct Job {
    lobe: Lobe,
    cell: (usize, usize),
    settings: FitSettings,
    stored: PointFit,
    objective: Objective,
    stage: Stage,
    cancel: Arc<AtomicBool>,
    tx: mpsc::Sender<Event>,
    /// The panel dropped the refit.
    abandoned: bool,
}

enum Stage {
    Setup,
    Fitting(Box<Fitting>),
    Done,
}

/// A cell's problem and its search.
struct Fitting {
    problem: CellProblem,
    search: Search,
}

/// The search of each objective, started from the stored cell.
enum Search {
    LtcCode {
        strata: FitStrata,
        simplex: Simplex<3>,
    },
    Point {
        quadrature: CellQuadrature,
        fitter: Box<CellFitter>,
    },
}

impl Job {
    /// One step; whether the refit is done (its result sent).
    fn step(&mut self) -> bool {
        match std::mem::replace(&mut self.stage, Stage::Done) {
            Stage::Setup => self.stage = Stage::Fitting(Box::new(self.set_up())),
            Stage::Fitting(mut fitting) => match self.advance(&mut fitting) {
                Some(result) => self.send(Event::Done(Box::new(result))),
                // Nobody waits for it (the panel started another, or closed): it ends here.
                None if self.abandoned => {}
                None => self.stage = Stage::Fitting(fitting),
            },
            Stage::Done => {}
        }
        matches!(self.stage, Stage::Done)
    }

    /// Sends `event` to the panel; notes when the panel no longer listens.
    fn send(&mut self, event: Event) {
        self.abandoned |= self.tx.send(event).is_err();
    }

    fn set_up(&self) -> Fitting {
        let (lobe, (i, j), settings) = (self.lobe, self.cell, &self.settings);
        let strata = FitStrata::new(settings);
        let problem = CellProblem::new(lobe, i, j, settings, &strata);
        let search = match self.objective {
            Objective::LtcCode => {
                let start = problem.params_of(cos_from_brdf_from_entries(self.stored.entries));
                let simplex = problem.simplex(start, settings, &strata);
                Search::LtcCode { strata, simplex }
            }
            Objective::Point => {
                let nodes = crate::ltc::lobe::strata(QUADRATURE_STRATA);
                let quadrature = CellQuadrature::new(lobe, problem.view, problem.alpha, &nodes);
                let free = PointObjective::Lobe.free(lobe);
                let fitter =
                    CellFitter::new(&quadrature, problem.norm, &[self.stored], free, settings);
                Search::Point {
                    quadrature,
                    fitter: Box::new(fitter),
                }
            }
        };
        Fitting { problem, search }
    }

    /// One iteration, sent for the plot; the result once the search ends or is cancelled.
    fn advance(&mut self, fitting: &mut Fitting) -> Option<RefitResult> {
        let settings = &self.settings;
        let Fitting { problem, search } = fitting;
        let cancelled = self.cancel.load(Ordering::Relaxed);
        let (fit, iterations, converged) = match search {
            Search::LtcCode { strata, simplex } => {
                let minimum = if cancelled {
                    simplex.stop()
                } else {
                    match simplex.next(|p| problem.objective(p, settings, strata)) {
                        Next::Observed { iteration, lowest } => {
                            self.send(Event::Iteration(iteration, lowest));
                            return None;
                        }
                        Next::Done(minimum) => minimum,
                    }
                };
                let fit = problem.fitted(minimum, settings);
                let entries = normalized_cos_from_brdf(&fit.ltc);
                let point = PointFit {
                    entries,
                    scale: 1.0,
                };
                (point, fit.iterations, fit.converged)
            }
            Search::Point { quadrature, fitter } => {
                let point = if cancelled {
                    fitter.stop(quadrature)
                } else {
                    match fitter.next(quadrature) {
                        FitNext::Observed { count, lowest } => {
                            self.send(Event::Iteration(count, lowest));
                            return None;
                        }
                        FitNext::Done(point) => point,
                    }
                };
                // Its restarts end where Nelder–Mead stops moving: there is no iteration
                // limit to hit for the whole fit, only per run.
                (point, fitter.iterations(), true)
            }
        };
        let mut result = self.measure(problem, fit, iterations, converged);
        result.cancelled = cancelled;
        Some(result)
    }

    /// The refit and the stored cell, measured alike.
    fn measure(
        &self,
        problem: &CellProblem,
        fit: PointFit,
        iterations: usize,
        converged: bool,
    ) -> RefitResult {
        let lobe = self.lobe;
        let ltc = |p: &PointFit| p.ltc(problem.norm, problem.fresnel);
        let error = |p: &PointFit| {
            pointwise_error(lobe, problem.view, problem.alpha, &ltc(p), ERROR_SAMPLES)
        };
        RefitResult {
            lobe,
            cell: self.cell,
            objective: self.objective,
            scale: fit.scale,
            stored_scale: self.stored.scale,
            history: Vec::new(),
            cos_from_brdf: mat3_rows(cos_from_brdf_from_entries(fit.entries)),
            norm: problem.norm,
            fresnel: problem.fresnel,
            stored: mat3_rows(cos_from_brdf_from_entries(self.stored.entries)),
            error: error(&fit),
            stored_error: error(&self.stored),
            iterations,
            converged,
            cancelled: false,
        }
    }
}
