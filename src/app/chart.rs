//! The speed-versus-accuracy panel: GPU time against image error for every method on the
//! current scene, and fps against the number of lights (the paper's Table 1, with its own
//! figures as a reference series) — measured on demand on the window's own device, in
//! budgeted steps with progress and cancel (`app::measure`), or read from a `study.csv`. The
//! last result is kept with the lab's state.

use egui::Color32;

use crate::app::measure::{MEASURE_SIZE, MeasureJob, Measurement, Point, REPEATS};
use crate::app::shading::Shading;
use crate::app::state::LabState;
use crate::bench::{PAPER_BRDF_FPS, PAPER_LIGHTS, PAPER_LTC_FPS};
use crate::ltc::lut::Lut;

#[derive(Default)]
pub struct ChartPanel {
    pub error: Option<String>,
    /// A measurement under way.
    pub job: Option<MeasureJob>,
    /// A `study.csv` to read instead of measuring.
    pub study_path: String,
}

impl ChartPanel {
    pub fn show(&mut self, ui: &mut egui::Ui, s: &mut LabState, lut: &Lut, shading: &Shading) {
        if let Some(job) = &mut self.job {
            if let Some(m) = job.step(shading.budget_ms) {
                s.measurement = Some(m);
                self.job = None;
            } else {
                ui.ctx().request_repaint();
            }
        }
        ui.horizontal_wrapped(|ui| {
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
                        .on_hover_text(format!("Times every method on the current scene at {}×{} (median of {REPEATS} renders, timestamp queries) and its error against the exact BRDF; then fps at 100–5000 lights. Each render is summed over frames within the frame budget, so the window stays live", MEASURE_SIZE.0, MEASURE_SIZE.1))
                        .clicked()
                    {
                        self.start(s, lut, shading);
                    }
                }
            }
            ui.add(egui::TextEdit::singleline(&mut self.study_path).desired_width(110.0).hint_text("study.csv"))
                .on_hover_text("A study.csv written by `ltc-lab study`, to plot instead of a live measurement");
            if ui.small_button("load study").on_hover_text("Plot the study.csv named on the left").clicked() {
                let path = self.study_path.trim();
                if path.is_empty() {
                    self.error = Some("load study: name a study.csv in the field first".into());
                } else {
                    match crate::study::read_csv(std::path::Path::new(path)) {
                        Ok(rows) => {
                            s.measurement = Some(Measurement::from_study(&rows, path));
                            self.error = None;
                        }
                        Err(e) => self.error = Some(e.to_string()),
                    }
                }
            }
            if let Some(m) = &s.measurement {
                ui.small(&m.device);
            }
        });
        if let Some(e) = &self.error {
            ui.colored_label(Color32::LIGHT_RED, e);
        }
        let half = (ui.available_width() / 2.0 - 6.0).max(80.0);
        let height = ui.available_height().max(80.0);
        ui.horizontal(|ui| {
            ui.allocate_ui(egui::vec2(half, height), |ui| {
                // The axes of `study.png` (src/plot.rs): log time, log error, exact at 1e-7.
                let power = |mark: egui_plot::GridMark, _: &std::ops::RangeInclusive<f64>| {
                    format!("{:.3}", 10f64.powf(mark.value))
                };
                let exponent = |mark: egui_plot::GridMark, _: &std::ops::RangeInclusive<f64>| {
                    // Only whole exponents: finer grid marks would round to repeated labels.
                    if (mark.value - mark.value.round()).abs() < 1e-9 {
                        format!("1e{:.0}", mark.value)
                    } else {
                        String::new()
                    }
                };
                egui_plot::Plot::new("time vs error")
                    .x_axis_label("GPU ms per frame (log)")
                    .y_axis_label("relative RMSE against the exact BRDF (log; exact at 1e-7)")
                    .x_axis_formatter(power)
                    .y_axis_formatter(exponent)
                    .legend(egui_plot::Legend::default().position(egui_plot::Corner::LeftBottom))
                    .allow_scroll(false)
                    .show(ui, |p| {
                        // One series per variant (every α and light count of a study).
                        let points: Vec<&Point> =
                            s.measurement.iter().flat_map(|m| &m.points).collect();
                        let mut names: Vec<&str> =
                            points.iter().map(|p| p.label.as_str()).collect();
                        names.sort_unstable();
                        names.dedup();
                        for name in names {
                            let series: Vec<[f64; 2]> = points
                                .iter()
                                .filter(|pt| pt.label == name)
                                .map(|pt| {
                                    [
                                        pt.ms.log10(),
                                        pt.rel_rmse.max(crate::plot::ERROR_FLOOR).log10(),
                                    ]
                                })
                                .collect();
                            p.points(egui_plot::Points::new(name.to_string(), series).radius(5.0));
                        }
                    });
            });
            ui.allocate_ui(egui::vec2(half, height), |ui| {
                egui_plot::Plot::new("fps vs lights")
                    .x_axis_label("lights")
                    .y_axis_label("fps")
                    .legend(egui_plot::Legend::default())
                    .allow_scroll(false)
                    .show(ui, |p| {
                        let paper = |fps: [f64; 4]| -> Vec<[f64; 2]> {
                            PAPER_LIGHTS
                                .iter()
                                .zip(fps)
                                .map(|(&n, f)| [n as f64, f])
                                .collect()
                        };
                        p.line(
                            egui_plot::Line::new("paper BRDF (GTX 1060)", paper(PAPER_BRDF_FPS))
                                .style(egui_plot::LineStyle::dashed_dense()),
                        );
                        p.line(
                            egui_plot::Line::new("paper LTC (GTX 1060)", paper(PAPER_LTC_FPS))
                                .style(egui_plot::LineStyle::dashed_dense()),
                        );
                        for (m, series) in s.measurement.iter().flat_map(|m| &m.scaling) {
                            p.line(egui_plot::Line::new(m.name(), series.clone()));
                        }
                    });
            });
        });
    }

    /// Starts measuring the current scene on the window's device.
    pub fn start(&mut self, s: &LabState, lut: &Lut, shading: &Shading) {
        let Some(ctx) = shading.context() else {
            self.error = Some(format!("measure: {}", shading.describe()));
            return;
        };
        match MeasureJob::new(ctx, &s.shaded_scene(), lut) {
            Ok(job) => {
                self.job = Some(job);
                self.error = None;
            }
            Err(e) => self.error = Some(e),
        }
    }

    /// Whether a measurement is under way.
    pub fn busy(&self) -> bool {
        self.job.is_some()
    }
}
