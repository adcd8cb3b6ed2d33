//! The speed-versus-accuracy panel: GPU time against image error for every method on the
//! current scene, and fps against the number of lights (the paper's Table 1, with its own
//! figures as a reference series) — measured on demand on the window's own device, in
//! budgeted steps with progress and cancel (`app::measure`), or read from a `study.csv`. The
//! last result is kept with the lab's state.

use egui::Color32;

use crate::app::axes::log_axis;

use crate::app::measure::{MEASURE_SIZE, MeasureJob, Measurement, Point, REPEATS};
use crate::app::shading::Shading;
use crate::app::state::LabState;
use crate::bench::{PAPER_BRDF_FPS, PAPER_LIGHTS, PAPER_LTC_FPS};
use crate::colormap::{round_sig, short_number};
use crate::ltc::lut::Lut;
use crate::render::Method;

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
        if s.measurement.is_none() {
            s.measurement = reference_study();
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
            ui.add(egui::TextEdit::singleline(&mut self.study_path).desired_width(110.0).hint_text("path to a study.csv"))
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
                        // The error names the file already.
                        Err(e) => self.error = Some(format!("load study: {e}")),
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
                let exponent = |mark: egui_plot::GridMark, _: &std::ops::RangeInclusive<f64>| {
                    // Only whole exponents: finer grid marks would round to repeated labels.
                    if (mark.value - mark.value.round()).abs() < 1e-9 {
                        format!("1e{:.0}", mark.value)
                    } else {
                        String::new()
                    }
                };
                let plot = egui_plot::Plot::new("time vs error")
                    .x_axis_label("GPU ms per frame (log)")
                    .y_axis_label("relative RMSE (log; exact at 1e-7)")
                    .y_axis_formatter(exponent);
                log_axis(plot, true)
                    .label_formatter(|pos| log_reading(pos, "ms", "error"))
                    // Small and see-through: a study has a dozen variants, over the points.
                    .legend(
                        egui_plot::Legend::default()
                            .position(egui_plot::Corner::LeftBottom)
                            .text_style(egui::TextStyle::Small)
                            .background_alpha(0.5),
                    )
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
                            p.points(
                                egui_plot::Points::new(name.to_string(), series)
                                    .radius(5.0)
                                    .shape(variant_shape(name))
                                    .color(method_colour(name)),
                            );
                        }
                    });
            });
            ui.allocate_ui(egui::vec2(half, height), |ui| {
                let plot = egui_plot::Plot::new("fps vs lights")
                    .x_axis_label("lights (log)")
                    .y_axis_label("fps (log)")
                    .legend(egui_plot::Legend::default())
                    .allow_scroll(false);
                // Both axes by decades: the GTX 1060's thousands of fps and a CPU driver's
                // few share the plot without flattening either.
                let plot = plot.label_formatter(|pos| log_reading(pos, "lights", "fps"));
                log_axis(log_axis(plot, true), false).show(ui, |p| {
                    let log = |series: &[[f64; 2]]| -> Vec<[f64; 2]> {
                        series
                            .iter()
                            .filter(|q| q[0] > 0.0 && q[1] > 0.0)
                            .map(|q| [q[0].log10(), q[1].log10()])
                            .collect()
                    };
                    let paper = |fps: [f64; 4]| -> Vec<[f64; 2]> {
                        let points: Vec<[f64; 2]> = PAPER_LIGHTS
                            .iter()
                            .zip(fps)
                            .map(|(&n, f)| [n as f64, f])
                            .collect();
                        log(&points)
                    };
                    // The paper's lines dashed, in colours no measured method uses.
                    p.line(
                        egui_plot::Line::new("paper BRDF (GTX 1060)", paper(PAPER_BRDF_FPS))
                            .color(PAPER_BRDF_COLOUR)
                            .style(egui_plot::LineStyle::dashed_dense()),
                    );
                    p.line(
                        egui_plot::Line::new("paper LTC (GTX 1060)", paper(PAPER_LTC_FPS))
                            .color(PAPER_LTC_COLOUR)
                            .style(egui_plot::LineStyle::dashed_dense()),
                    );
                    for (m, series) in s.measurement.iter().flat_map(|m| &m.scaling) {
                        p.line(
                            egui_plot::Line::new(m.name(), log(series))
                                .color(method_colour(m.name())),
                        );
                        p.points(
                            egui_plot::Points::new(m.name(), log(series))
                                .radius(3.0)
                                .color(method_colour(m.name())),
                        );
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

/// The paper's reference lines' colours (greys, so that no measured method shares them).
const PAPER_BRDF_COLOUR: Color32 = Color32::from_gray(210);
const PAPER_LTC_COLOUR: Color32 = Color32::from_gray(140);

/// One colour per method in every plot, from its name (a study's variants start with it):
/// egui_plot's automatic colours follow the drawing order and differ between the two plots.
pub fn method_colour(label: &str) -> Color32 {
    const PALETTE: [Color32; 6] = [
        Color32::from_rgb(240, 150, 60),
        Color32::from_rgb(230, 90, 90),
        Color32::from_rgb(70, 140, 255),
        Color32::from_rgb(90, 210, 120),
        Color32::from_rgb(200, 110, 230),
        Color32::from_rgb(60, 210, 210),
    ];
    method_of(label).map_or(Color32::from_gray(180), |(k, _)| PALETTE[k % PALETTE.len()])
}

/// The method a series label names, with its index in `Method::ALL`: the longest method
/// name the label starts with ("ltc-fast-point" is ltc-fast's).
fn method_of(label: &str) -> Option<(usize, Method)> {
    Method::ALL
        .iter()
        .copied()
        .enumerate()
        .filter(|(_, m)| label.starts_with(m.name()))
        .max_by_key(|(_, m)| m.name().len())
}

/// The marker of a method's variant ("ltc-lut16" of ltc): a circle for the method itself,
/// another shape for each variant, so that variants of one colour stay apart.
fn variant_shape(label: &str) -> egui_plot::MarkerShape {
    let variant = method_of(label).map_or(label, |(_, m)| &label[m.name().len()..]);
    if variant.is_empty() {
        return egui_plot::MarkerShape::Circle;
    }
    // Any variant name maps to one of the nine other shapes, the same one every run.
    let k = variant
        .bytes()
        .fold(0usize, |h, b| h.wrapping_mul(31).wrapping_add(b.into()));
    egui_plot::MarkerShape::all()
        .nth(1 + k % 9)
        .unwrap_or(egui_plot::MarkerShape::Square)
}

/// The hover reading of a plot with log10 coordinates: the series and both values.
fn log_reading(pos: &egui_plot::HoverPosition<'_>, x: &str, y: &str) -> Option<String> {
    let value = |v: f64| short_number(round_sig(10f64.powf(v)));
    match pos {
        egui_plot::HoverPosition::NearDataPoint {
            plot_name,
            position,
            ..
        } => Some(format!(
            "{plot_name}\n{} {x}, {y} {}",
            value(position.x),
            value(position.y)
        )),
        egui_plot::HoverPosition::Elsewhere { .. } => None,
    }
}

/// The bundled reference study (assets/study/reference.csv: its device and size are in its
/// comment lines), shown until the user measures or loads one.
pub fn reference_study() -> Option<Measurement> {
    let text = include_str!("../../assets/study/reference.csv");
    let rows = crate::study::parse_csv(text, "assets/study/reference.csv").ok()?;
    let device = text
        .lines()
        .find_map(|l| l.strip_prefix("# device: "))
        .unwrap_or("unknown device");
    let mut m = Measurement::from_study(&rows, "reference study");
    m.device = format!("reference study ({device}) — press measure for this machine");
    Some(m)
}
