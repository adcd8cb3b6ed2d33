//! The speed-versus-accuracy panel: GPU time against image error for every method on the
//! current scene, and fps against the number of lights (the paper's Table 1, with its own
//! figures as a reference series) — measured on demand on this machine's GPU, on a worker
//! thread with its own device so that the window stays live.

use std::sync::mpsc;

use egui::Color32;

use crate::app::state::LabState;
use crate::bench::{PAPER_BRDF_FPS, PAPER_LIGHTS, PAPER_LTC_FPS, bench_scene};
use crate::gpu::GpuContext;
use crate::gpu::plane::{PlaneRenderer, ShaderChecks};
use crate::ltc::Normalization;
use crate::ltc::lut::Lut;
use crate::metrics::image_error;
use crate::render::{Frame, Method, RenderSettings};
use crate::scene::Scene;

/// Size of the measured frames: small enough for lavapipe to finish in seconds.
pub const MEASURE_SIZE: (usize, usize) = (320, 180);
/// Timed frames per point (median).
const FRAMES: usize = 5;

/// One measured method: GPU ms and relative RMSE against the exact BRDF.
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    pub label: String,
    pub ms: f64,
    pub rel_rmse: f64,
}

#[derive(Clone, Debug, Default, PartialEq)]
pub struct Measurement {
    pub points: Vec<Point>,
    /// (lights, fps) per method.
    pub scaling: Vec<(Method, Vec<[f64; 2]>)>,
    pub device: String,
}

#[derive(Default)]
pub struct ChartPanel {
    pub measurement: Option<Measurement>,
    pub error: Option<String>,
    running: Option<mpsc::Receiver<Result<Measurement, String>>>,
    /// A `study.csv` to read instead of measuring.
    pub study_path: String,
}

impl Measurement {
    /// The points of a `study.csv` (`ltc-lab study`): every row a point, labelled with its
    /// variant, α and light count.
    pub fn from_study(rows: &[crate::study::StudyRow], source: &str) -> Self {
        Self {
            points: rows
                .iter()
                .map(|r| Point {
                    label: r.variant.clone(),
                    ms: r.ms_median,
                    rel_rmse: r.rel_rmse,
                })
                .collect(),
            scaling: Vec::new(),
            device: format!("{source}: {} rows", rows.len()),
        }
    }
}

impl ChartPanel {
    pub fn show(&mut self, ui: &mut egui::Ui, s: &LabState, lut: &Lut) {
        if let Some(rx) = &self.running {
            match rx.try_recv() {
                Ok(Ok(m)) => {
                    self.measurement = Some(m);
                    self.running = None;
                }
                Ok(Err(e)) => {
                    self.error = Some(e);
                    self.running = None;
                }
                Err(mpsc::TryRecvError::Empty) => ui.ctx().request_repaint(),
                Err(mpsc::TryRecvError::Disconnected) => self.running = None,
            }
        }
        ui.horizontal(|ui| {
            let busy = self.running.is_some();
            if ui
                .add_enabled(!busy, egui::Button::new(if busy { "measuring…" } else { "measure" }))
                .on_hover_text(format!("Times every method on the current scene at {}×{} (median of {FRAMES} frames, timestamp queries) and its error against the exact BRDF; then fps at 100–5000 lights", MEASURE_SIZE.0, MEASURE_SIZE.1))
                .clicked()
            {
                self.start(s.shaded_scene(), lut.clone());
            }
            ui.add(egui::TextEdit::singleline(&mut self.study_path).desired_width(110.0).hint_text("study.csv"))
                .on_hover_text("A study.csv written by `ltc-lab study`, to plot instead of a live measurement");
            if ui.small_button("load study").on_hover_text("Plot the study.csv named on the left").clicked() {
                match crate::study::read_csv(std::path::Path::new(self.study_path.trim())) {
                    Ok(rows) => {
                        self.measurement = Some(Measurement::from_study(&rows, self.study_path.trim()));
                        self.error = None;
                    }
                    Err(e) => self.error = Some(e.to_string()),
                }
            }
            if let Some(m) = &self.measurement {
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
                            self.measurement.iter().flat_map(|m| &m.points).collect();
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
                        for (m, series) in self.measurement.iter().flat_map(|m| &m.scaling) {
                            p.line(egui_plot::Line::new(m.name(), series.clone()));
                        }
                    });
            });
        });
    }

    fn start(&mut self, scene: Scene, lut: Lut) {
        let (tx, rx) = mpsc::channel();
        std::thread::spawn(move || {
            let _ = tx.send(measure(&scene, &lut));
        });
        self.error = None;
        self.running = Some(rx);
    }

    /// Measures on this thread (the headless `lab --measure`).
    pub fn measure_now(&mut self, scene: &Scene, lut: &Lut) {
        match measure(scene, lut) {
            Ok(m) => self.measurement = Some(m),
            Err(e) => self.error = Some(e),
        }
    }

    /// Blocks until a running measurement is done (tests and headless use).
    pub fn wait(&mut self) {
        if let Some(rx) = self.running.take() {
            match rx.recv() {
                Ok(Ok(m)) => self.measurement = Some(m),
                Ok(Err(e)) => self.error = Some(e),
                Err(_) => {}
            }
        }
    }
}

/// Every method on `scene`, then fps at the paper's light counts.
pub fn measure(scene: &Scene, lut: &Lut) -> Result<Measurement, String> {
    let ctx = GpuContext::new().map_err(|e| e.to_string())?;
    let mut renderer =
        PlaneRenderer::new(&ctx, lut, ShaderChecks::Checked).map_err(|e| e.to_string())?;
    let (w, h) = MEASURE_SIZE;
    let mut run = |scene: &Scene, s: &RenderSettings| -> Result<(Frame, f64), String> {
        renderer.begin(&ctx, scene, s).map_err(|e| e.to_string())?;
        renderer.run(&ctx);
        let mut ms: Vec<f64> = (0..FRAMES).map(|_| renderer.run(&ctx).total_ms()).collect();
        ms.sort_by(f64::total_cmp);
        Ok((renderer.read(&ctx), ms[FRAMES / 2]))
    };
    let (exact, _) = run(scene, &RenderSettings::single(w, h, Method::Brdf))?;
    let mut points = Vec::new();
    let variants = [
        ("brdf", Method::Brdf, Normalization::Corrected),
        ("brdf-fast", Method::BrdfFast, Normalization::Corrected),
        ("ltc", Method::Ltc, Normalization::Corrected),
        ("ltc-fast", Method::LtcFast, Normalization::Corrected),
        ("ltc-paper", Method::Ltc, Normalization::PaperLiteral),
    ];
    for (label, method, normalization) in variants {
        let mut s = RenderSettings::single(w, h, method);
        s.normalization = normalization;
        let (frame, ms) = run(scene, &s)?;
        points.push(Point {
            label: label.into(),
            ms,
            rel_rmse: image_error(&frame, &exact).rel_rmse,
        });
    }
    let mut scaling = Vec::new();
    for method in Method::F32 {
        let mut series = Vec::new();
        for &n in &PAPER_LIGHTS {
            let (_, ms) = run(
                &bench_scene(n, Some(crate::bench::DEFAULT_RANGE)),
                &RenderSettings::single(w, h, method),
            )?;
            series.push([n as f64, 1e3 / ms]);
        }
        scaling.push((method, series));
    }
    Ok(Measurement {
        points,
        scaling,
        device: format!("{} at {w}×{h}", ctx.describe()),
    })
}
