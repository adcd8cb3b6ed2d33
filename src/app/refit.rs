//! "Refit this cell": the fitter run live on one cell of the table, on a worker thread, from
//! the stored cell's own parameters; its objective per iteration for the plot, a cancel, and
//! the result kept with the lab's state (the lobe panel shows the refitted lobe).

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;

use glam::DMat3;
use serde::{Deserialize, Serialize};

use crate::ltc::fit::{CellProblem, FitSettings, FitStrata, pointwise_error};
use crate::ltc::lobe::Lobe;
use crate::ltc::lut::{Channel, Lut};
use crate::ltc::nelder_mead::CONTINUE;
use crate::ltc::{Ltc, cos_from_brdf_from_entries, mat3_from_rows, mat3_rows};

/// A finished refit: what the plot and the lobe panel need, kept between runs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RefitResult {
    pub lobe: Lobe,
    pub cell: (usize, usize),
    /// (iteration, best objective).
    pub history: Vec<[f64; 2]>,
    /// The refitted `M⁻¹`, rows, and the lobe's albedos.
    pub cos_from_brdf: [[f64; 3]; 3],
    pub norm: f64,
    pub fresnel: f64,
    /// The stored cell's `M⁻¹` (rows, divided by its middle element).
    pub stored: [[f64; 3]; 3],
    /// Pointwise error (DESIGN §4) of the refit and of the stored cell, measured alike.
    pub error: f64,
    pub stored_error: f64,
    pub iterations: usize,
    /// Stopped by its tolerance (not the iteration limit, not a cancel).
    pub converged: bool,
    pub cancelled: bool,
}

impl RefitResult {
    pub fn ltc(&self) -> Ltc {
        Ltc::from_cos_from_brdf(mat3_from_rows(self.cos_from_brdf), self.norm, self.fresnel)
    }
}

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
    /// Refits cell `(i, j)` of `lut` for `lobe`, starting from the stored cell.
    pub fn start(lobe: Lobe, (i, j): (usize, usize), lut: &Lut) -> Self {
        let (tx, rx) = mpsc::channel();
        let settings = FitSettings {
            size: lut.size,
            alpha_min: lut.alpha_min,
            ..FitSettings::default()
        };
        let stored = cos_from_brdf_from_entries(
            Channel::entries(lobe).map(|c| f64::from(lut.cell(i, j).get(c))),
        );
        let cancel = Arc::new(AtomicBool::new(false));
        let stop = cancel.clone();
        std::thread::spawn(move || {
            let strata = FitStrata::new(&settings);
            let problem = CellProblem::new(lobe, i, j, &settings, &strata);
            let start = problem.params_of(stored);
            let fit = problem.fit(start, &settings, &strata, |k, f| {
                let _ = tx.send(Event::Iteration(k, f));
                if stop.load(Ordering::Relaxed) {
                    std::ops::ControlFlow::Break(())
                } else {
                    CONTINUE
                }
            });
            let error =
                |ltc: &Ltc| pointwise_error(lobe, problem.view, problem.alpha, ltc, ERROR_SAMPLES);
            let stored_ltc = Ltc::from_cos_from_brdf(stored, problem.norm, problem.fresnel);
            let result = RefitResult {
                lobe,
                cell: (i, j),
                history: Vec::new(),
                cos_from_brdf: mat3_rows(normalized(fit.ltc.cos_from_brdf)),
                norm: fit.ltc.norm,
                fresnel: fit.ltc.fresnel,
                stored: mat3_rows(stored),
                error: error(&fit.ltc),
                stored_error: error(&stored_ltc),
                iterations: fit.iterations,
                converged: fit.converged,
                cancelled: stop.load(Ordering::Relaxed),
            };
            let _ = tx.send(Event::Done(Box::new(result)));
        });
        Self {
            lobe,
            cell: (i, j),
            history: Vec::new(),
            max_iterations: settings.max_iterations,
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

/// `M⁻¹` divided by its middle element, as the table stores it (DESIGN §2).
fn normalized(m: DMat3) -> DMat3 {
    m * (1.0 / mat3_rows(m)[1][1])
}
