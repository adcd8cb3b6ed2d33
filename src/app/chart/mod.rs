//! The speed-versus-accuracy panel: GPU time against image error for every method on the
//! current scene, and fps against the number of lights (the paper's Table 1, with its own
//! figures as a reference series) — measured on demand on the window's own device, in
//! budgeted steps with progress and cancel (`app::chart::measure`), or read from a `study.csv`. The
//! last result is kept with the lab's state.

mod markers;
pub mod measure;
mod plots;
pub mod studies;
mod work_table;

use egui::Color32;
use serde::{Deserialize, Serialize};

use crate::app::chart::measure::{MEASURE_SIZE, MeasureJob, Measurement, REPEATS};
pub use crate::app::chart::plots::{decade_span, speed_ratio};
use crate::app::chart::plots::{fps_plot, time_error_plot};
use crate::app::chart::studies::{ShippedStudy, reference_study};
use crate::app::chart::work_table::work_table;
use crate::app::files::Purpose;
use crate::app::lab::{Checked, Lab, Message, Request};
use crate::app::panel::Panel;
use crate::app::plane::shading::FRAME_BUDGET_MS;
use crate::gpu::work::{Work, work_per_light};
use crate::measure::study::StudyRow;
use crate::render::Method;

/// The chart's last measurement (or study), kept between runs.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ChartState {
    pub measurement: Option<Measurement>,
}

impl Checked for ChartState {
    /// A measurement the chart cannot plot is dropped (a zero or infinite time froze the
    /// plot's axes at 100% CPU, at every start where it was kept).
    fn check(&mut self, _: &Self) -> Vec<String> {
        let Some(why) = self.measurement.as_ref().and_then(|m| m.validate().err()) else {
            return Vec::new();
        };
        self.measurement = None;
        vec![format!(
            "the saved chart was dropped ({why}): measure again"
        )]
    }
}

#[derive(Default)]
pub struct ChartPanel {
    state: ChartState,
    error: Option<String>,
    /// A measurement under way.
    job: Option<MeasureJob>,
    /// A `study.csv` to read instead of measuring.
    study_path: String,
    /// Each method's work per light, counted from the shaders once shown.
    work: Option<Result<Vec<(Method, Work)>, String>>,
    /// Measurements finished since the lab started (a lesson's step asks for one).
    finished: u64,
}

impl Panel for ChartPanel {
    fn show(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        if let Some(job) = &mut self.job {
            if let Some(m) = job.step(FRAME_BUDGET_MS) {
                self.state.measurement = Some(m);
                self.job = None;
                self.finished += 1;
            } else {
                ui.ctx().request_repaint();
            }
        }
        if self.state.measurement.is_none() {
            self.state.measurement = reference_study();
        }
        ui.horizontal_wrapped(|ui| self.toolbar(ui, lab));
        if let Some(e) = &self.error {
            ui.colored_label(Color32::LIGHT_RED, e);
        }
        let Some(m) = &self.state.measurement else {
            return;
        };
        egui::CollapsingHeader::new("work per light, from the shaders")
            .id_salt("chart work")
            .show(ui, |ui| {
                let work = self.work.get_or_insert_with(work_per_light);
                work_table(ui, work, m);
            });
        let half = (ui.available_width() / 2.0 - 6.0).max(80.0);
        let height = ui.available_height().max(80.0);
        ui.horizontal(|ui| {
            ui.allocate_ui(egui::vec2(half, height), |ui| {
                ui.vertical(|ui| time_error_plot(ui, m, height));
            });
            ui.allocate_ui(egui::vec2(half, height), |ui| {
                ui.vertical(|ui| fps_plot(ui, m, lab.forms(), height));
            });
        });
    }

    /// Whether a measurement is under way.
    fn busy(&self) -> bool {
        self.job.is_some()
    }
}

impl ChartPanel {
    pub fn new(state: ChartState) -> Self {
        Self {
            state,
            ..Self::default()
        }
    }

    pub fn state(&self) -> &ChartState {
        &self.state
    }

    /// Measurements finished since the lab started.
    pub fn finished(&self) -> u64 {
        self.finished
    }

    /// *measure* (or its progress and cancel), and a study to read instead.
    fn toolbar(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        match &self.job {
            Some(job) => {
                ui.add(egui::ProgressBar::new(job.progress()).desired_width(90.0))
                    .on_hover_text("The measurement, task by task");
                ui.small(format!("measuring {}", job.describe()));
                if ui.small_button("cancel").on_hover_text("Stop measuring; the chart keeps what it showed").clicked() {
                    self.job = None;
                }
            }
            None => {
                if ui
                    .button("measure")
                    .on_hover_text(format!("Times every method on the current scene at {}×{} (median of {REPEATS} renders, timestamp \
                        queries) and its error against the exact BRDF; then fps at 100–5000 lights. Each render \
                        is summed over frames within the frame budget, so the window stays live", MEASURE_SIZE.0, MEASURE_SIZE.1))
                    .clicked()
                {
                    self.start(lab);
                }
            }
        }
        // A browser picks the file instead of reading a path.
        let picks = cfg!(target_arch = "wasm32");
        if !picks {
            let field = ui
                .add(
                    egui::TextEdit::singleline(&mut self.study_path)
                        .desired_width(110.0)
                        .hint_text("path to a study.csv"),
                )
                .on_hover_text(
                    "A study.csv written by `ltc-lab study`, to plot instead of a live measurement",
                );
            crate::app::ui::widgets::name(ui, &field, "study file");
        }
        if ui
            .small_button("load study")
            .on_hover_text("Plot a study.csv written by `ltc-lab study` (the one named on the left, a picked one in a browser, or drop one on the window)")
            .clicked()
        {
            lab.request(Request::Open(Purpose::Study, self.study_path.clone()));
        }
        for study in ShippedStudy::ALL {
            let hover = format!(
                "Plot the study shipped with the lab ({}), measured on {}",
                study.path(),
                study.device()
            );
            if ui
                .small_button(format!("{} study", study.name()))
                .on_hover_text(hover)
                .clicked()
            {
                self.state.measurement = study.measurement();
                self.error = None;
            }
        }
        if let Some(m) = &self.state.measurement {
            // A shipped study invites a measurement of this machine.
            match m.study {
                Some(_) => ui.small(format!("{} — press measure for this machine", m.device)),
                None => ui.small(&m.device),
            };
        }
    }

    /// Plots a study's rows (read from the file `name`), or says why its file could not be
    /// plotted (the error names the file already).
    pub fn use_study(&mut self, rows: crate::error::Result<Vec<StudyRow>>, name: &str) -> Message {
        match rows {
            Ok(rows) => {
                self.state.measurement = Some(Measurement::from_study(&rows, name));
                self.error = None;
                Message::note(format!("plotting {name}"))
            }
            Err(e) => {
                let said = format!("load study: {e}");
                self.error = Some(said.clone());
                Message::error(said)
            }
        }
    }

    /// Starts measuring the current scene on the lab's device.
    pub fn start(&mut self, lab: &Lab) {
        let Some(ctx) = lab.device() else {
            self.error = Some(format!("measure: {}", lab.describe_device()));
            return;
        };
        match MeasureJob::new(
            ctx,
            &lab.shaded_scene(),
            &lab.tables().a().lut,
            lab.method_file(),
        ) {
            Ok(job) => {
                self.job = Some(job);
                self.error = None;
            }
            Err(e) => self.error = Some(e),
        }
    }
}
