//! The speed-versus-accuracy panel: GPU time against image error for every method on the
//! current scene, and fps against the number of lights (the paper's Table 1, with its own
//! figures as a reference series) — measured on demand on the window's own device, in
//! budgeted steps with progress and cancel (`app::chart::measure`), or read from a `study.csv`. The
//! last result is kept with the lab's state.

pub mod measure;
pub mod studies;

use egui::Color32;
use serde::{Deserialize, Serialize};

use crate::app::chart::measure::{MEASURE_SIZE, MeasureJob, Measurement, Point, REPEATS};
use crate::app::chart::studies::{ShippedStudy, reference_study};
use crate::app::files::Purpose;
use crate::app::lab::{Checked, Forms, Lab, Message, Request};
use crate::app::panel::Panel;
use crate::app::plane::shading::FRAME_BUDGET_MS;
use crate::app::ui::axes::log_axis;
use crate::colormap::{round_sig, short_number};
use crate::gpu::work::{Work, work_per_light};
use crate::light::disk::DiskMethod;
use crate::light::rect::RectMethod;
use crate::light::sphere::SphereMethod;
use crate::measure::bench::{PAPER_BRDF_FPS, PAPER_LIGHTS, PAPER_LTC_FPS};
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
                    .on_hover_text(format!("Times every method on the current scene at {}×{} (median of {REPEATS} renders, timestamp queries) and its error against the exact BRDF; then fps at 100–5000 lights. Each render is summed over frames within the frame budget, so the window stays live", MEASURE_SIZE.0, MEASURE_SIZE.1))
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

/// A legend entry: the series' name, colour and marker (`None`: a dashed line).
type Entry = (String, Color32, Option<egui_plot::MarkerShape>);

/// GPU time against image error, one marker per variant, with the timed renders' spread as
/// a bar; its legend under it.
fn time_error_plot(ui: &mut egui::Ui, m: &Measurement, height: f32) {
    let mut names: Vec<&str> = m.points.iter().map(|p| p.label.as_str()).collect();
    names.sort_unstable();
    names.dedup();
    let method = |name: &str| {
        m.points
            .iter()
            .find(|p| p.label == name)
            .and_then(|p| p.method)
    };
    let entries: Vec<Entry> = names
        .iter()
        .map(|&n| {
            let (colour, shape) = point_marker(n, method(n));
            (n.to_string(), colour, Some(shape))
        })
        .collect();
    let error = |p: &Point| p.rel_rmse.max(crate::plot::ERROR_FLOOR).log10();
    let times = m
        .points
        .iter()
        .flat_map(|p| [p.ms].into_iter().chain(p.ms_range.into_iter().flatten()));
    let errors = m.points.iter().map(|p| 10f64.powf(error(p)));
    // The axes of `study.png` (src/plot.rs): log time, log error, exact at 1e-7.
    let plot = egui_plot::Plot::new("time vs error")
        .height(plot_height(ui, height, &entries))
        .x_axis_label("GPU ms per frame (log)")
        .y_axis_label("relative RMSE (log; exact at 1e-7)");
    let plot = decades(log_axis(log_axis(plot, true), false), times, errors)
        .label_formatter(|pos| log_reading(pos, "ms", "error"))
        .allow_scroll(false);
    let response = plot.show(ui, |p| {
        for name in &names {
            let mine = m.points.iter().filter(|pt| pt.label == *name);
            for pt in mine.clone() {
                if let Some([lo, hi]) = pt.ms_range {
                    let y = error(pt);
                    let bar = vec![[lo.log10(), y], [hi.log10(), y]];
                    p.line(
                        egui_plot::Line::new(name.to_string(), bar)
                            .color(point_marker(name, method(name)).0),
                    );
                }
            }
            let series: Vec<[f64; 2]> = mine.map(|pt| [pt.ms.log10(), error(pt)]).collect();
            p.points(
                egui_plot::Points::new(name.to_string(), series)
                    .radius(5.0)
                    .shape(point_marker(name, method(name)).1)
                    .color(point_marker(name, method(name)).0),
            );
        }
    });
    name_plot(&response.response, "time vs error plot");
    legend(ui, &entries);
}

/// fps against the light count (the paper's Table 1 as dashed references), with the timed
/// renders' spread as bars; its legend and the LTC/BRDF ratio under it.
fn fps_plot(ui: &mut egui::Ui, m: &Measurement, forms: &Forms, height: f32) {
    let mut entries: Vec<Entry> = vec![
        ("paper BRDF (GTX 1060)".into(), PAPER_BRDF_COLOUR, None),
        ("paper LTC (GTX 1060)".into(), PAPER_LTC_COLOUR, None),
    ];
    entries.extend(m.scaling.iter().map(|(method, _)| {
        let name = method.name();
        (
            name.to_string(),
            method_colour(Some(*method)),
            Some(egui_plot::MarkerShape::Circle),
        )
    }));
    let paper: Vec<[f64; 2]> = PAPER_LIGHTS.iter().map(|&n| [n as f64, 0.0]).collect();
    let xs = m
        .scaling
        .iter()
        .flat_map(|(_, s)| s.iter().map(|q| q[0]))
        .chain(paper.iter().map(|q| q[0]));
    let ys = m.scaling.iter().flat_map(|(_, s)| s.iter().map(|q| q[1]));
    let ys = ys.chain(PAPER_BRDF_FPS).chain(PAPER_LTC_FPS);
    // The paper's Table 1 comparison first, where a small window still shows it.
    let ratio = speed_ratio(m, forms);
    if let Some(line) = &ratio {
        ui.small(line);
    }
    let header = if ratio.is_some() {
        ui.spacing().interact_size.y
    } else {
        0.0
    };
    let plot = egui_plot::Plot::new("fps vs lights")
        .height(plot_height(ui, height - header, &entries))
        .x_axis_label("lights (log)")
        .y_axis_label("fps (log)")
        .allow_scroll(false);
    // Both axes by decades: the GTX 1060's thousands of fps and a CPU driver's few share the
    // plot without flattening either.
    let plot = decades(log_axis(log_axis(plot, true), false), xs, ys)
        .label_formatter(|pos| log_reading(pos, "lights", "fps"));
    let response = plot.show(ui, |p| {
        for (name, colour, fps) in [
            ("paper BRDF (GTX 1060)", PAPER_BRDF_COLOUR, PAPER_BRDF_FPS),
            ("paper LTC (GTX 1060)", PAPER_LTC_COLOUR, PAPER_LTC_FPS),
        ] {
            let line = PAPER_LIGHTS
                .iter()
                .zip(fps)
                .map(|(&n, f)| [(n as f64).log10(), f.log10()]);
            p.line(
                egui_plot::Line::new(name, line.collect::<Vec<_>>())
                    .color(colour)
                    .style(egui_plot::LineStyle::dashed_dense()),
            );
        }
        for (method, series) in &m.scaling {
            let (name, colour) = (method.name(), method_colour(Some(*method)));
            let log: Vec<[f64; 2]> = series
                .iter()
                .filter(|q| q[0] > 0.0 && q[1] > 0.0)
                .map(|q| [q[0].log10(), q[1].log10()])
                .collect();
            p.line(egui_plot::Line::new(name, log.clone()).color(colour));
            p.points(egui_plot::Points::new(name, log).radius(3.0).color(colour));
            let spread = m.scaling_range.iter().filter(|(r, _)| r == method);
            for [n, lo, hi] in spread.flat_map(|(_, r)| r) {
                let bar = vec![[n.log10(), lo.log10()], [n.log10(), hi.log10()]];
                p.line(egui_plot::Line::new(name, bar).color(colour));
            }
        }
    });
    name_plot(&response.response, "fps vs lights plot");
    legend(ui, &entries);
}

/// The lab's LTC and BRDF forms' `Measurement::fps_ratios`, in words: the paper's Table 1 comparison.
pub fn speed_ratio(m: &Measurement, forms: &Forms) -> Option<String> {
    let (ltc, brdf, ratios) = m.fps_ratios(forms.ltc, forms.brdf)?;
    let ratios: Vec<String> = ratios
        .iter()
        // Plain counts: a thin space between thousands is where a line would break.
        .map(|(n, r)| format!("×{r:.2} at {n} lights"))
        .collect();
    (!ratios.is_empty()).then(|| {
        format!(
            "LTC/BRDF speed ({} over {}): {}",
            ltc.name(),
            brdf.name(),
            ratios.join(", ")
        )
    })
}

/// The plot's height, leaving room under it for its legend: its entries' widths (marker,
/// small text, gap) wrapped into rows of the available width, plus one row of slack for the
/// wrapping.
fn plot_height(ui: &egui::Ui, height: f32, entries: &[Entry]) -> f32 {
    let font = egui::TextStyle::Small.resolve(ui.style());
    let widths = entries.iter().map(|(name, _, _)| {
        let text = ui.fonts_mut(|f| f.layout_no_wrap(name.clone(), font.clone(), Color32::WHITE));
        10.0 + 4.0 + text.size().x + 12.0
    });
    let rows = (widths.sum::<f32>() / ui.available_width().max(1.0)).ceil() + 1.0;
    let row = ui.spacing().interact_size.y;
    (height - rows * row).max(60.0)
}

/// The plot's bounds widened to whole decades on both axes, so that each always has at least
/// two labelled ticks (a narrow span of times showed one or none).
fn decades<'a>(
    plot: egui_plot::Plot<'a>,
    xs: impl Iterator<Item = f64>,
    ys: impl Iterator<Item = f64>,
) -> egui_plot::Plot<'a> {
    let [x0, x1] = decade_span(xs);
    let [y0, y1] = decade_span(ys);
    plot.include_x(x0).include_x(x1).include_y(y0).include_y(y1)
}

/// log10 of the whole decades around the positive finite `values`: at least one decade.
pub fn decade_span(values: impl Iterator<Item = f64>) -> [f64; 2] {
    let logs = values.filter(|v| v.is_finite() && *v > 0.0).map(f64::log10);
    let (lo, hi) = logs.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
        (a.min(v), b.max(v))
    });
    if !lo.is_finite() {
        return [0.0, 1.0];
    }
    let (lo, hi) = (lo.floor(), hi.ceil());
    [lo, hi.max(lo + 1.0)]
}

/// A plot's accessible name, so that it can be found as a user finds it.
fn name_plot(response: &egui::Response, name: &str) {
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Figure, true, name));
}

/// The series' names with their markers, under the plot: egui_plot's legend sits inside
/// the plot, over the points.
fn legend(ui: &mut egui::Ui, entries: &[Entry]) {
    ui.horizontal_wrapped(|ui| {
        ui.spacing_mut().item_spacing = egui::vec2(4.0, 0.0);
        let font = egui::TextStyle::Small.resolve(ui.style());
        let ink = ui.visuals().text_color();
        for (name, colour, shape) in entries {
            // Marker and name as one widget, so that a row never ends with a lone marker.
            let text = ui.fonts_mut(|f| f.layout_no_wrap(name.clone(), font.clone(), ink));
            let size = egui::vec2(14.0 + text.size().x, text.size().y.max(10.0));
            let (rect, response) = ui.allocate_exact_size(size, egui::Sense::hover());
            response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Label, true, name));
            let dot = egui::Rect::from_center_size(
                egui::pos2(rect.left() + 5.0, rect.center().y),
                egui::vec2(10.0, 10.0),
            );
            marker(ui.painter(), dot, *colour, *shape);
            ui.painter()
                .galley(rect.left_top() + egui::vec2(14.0, 0.0), text, ink);
            ui.add_space(8.0);
        }
    });
}

/// A legend's marker: the plot's marker shape, or a dash for a dashed line.
fn marker(
    painter: &egui::Painter,
    rect: egui::Rect,
    colour: Color32,
    shape: Option<egui_plot::MarkerShape>,
) {
    use egui_plot::MarkerShape as M;
    let (c, r) = (rect.center(), rect.width() * 0.45);
    let stroke = egui::Stroke::new(1.5, colour);
    let polygon =
        |points: Vec<egui::Pos2>| egui::Shape::convex_polygon(points, colour, egui::Stroke::NONE);
    let at = |dx: f32, dy: f32| c + egui::vec2(dx * r, dy * r);
    let shape = match shape {
        None => egui::Shape::line_segment([at(-1.0, 0.0), at(1.0, 0.0)], stroke),
        Some(M::Circle) => egui::Shape::circle_filled(c, r, colour),
        Some(M::Square) => egui::Shape::rect_filled(
            egui::Rect::from_center_size(c, egui::vec2(1.6 * r, 1.6 * r)),
            0.0,
            colour,
        ),
        Some(M::Diamond) => polygon(vec![
            at(0.0, -1.0),
            at(1.0, 0.0),
            at(0.0, 1.0),
            at(-1.0, 0.0),
        ]),
        Some(M::Up) => polygon(vec![at(0.0, -1.0), at(1.0, 0.8), at(-1.0, 0.8)]),
        Some(M::Down) => polygon(vec![at(0.0, 1.0), at(-1.0, -0.8), at(1.0, -0.8)]),
        Some(M::Left) => polygon(vec![at(-1.0, 0.0), at(0.8, -1.0), at(0.8, 1.0)]),
        Some(M::Right) => polygon(vec![at(1.0, 0.0), at(-0.8, 1.0), at(-0.8, -1.0)]),
        Some(M::Plus) => egui::Shape::Vec(vec![
            egui::Shape::line_segment([at(-1.0, 0.0), at(1.0, 0.0)], stroke),
            egui::Shape::line_segment([at(0.0, -1.0), at(0.0, 1.0)], stroke),
        ]),
        Some(M::Cross | M::Asterisk) => egui::Shape::Vec(vec![
            egui::Shape::line_segment([at(-0.8, -0.8), at(0.8, 0.8)], stroke),
            egui::Shape::line_segment([at(-0.8, 0.8), at(0.8, -0.8)], stroke),
        ]),
    };
    painter.add(shape);
}

/// The paper's reference lines' colours (greys, so that no measured method shares them).
const PAPER_BRDF_COLOUR: Color32 = Color32::from_gray(210);
const PAPER_LTC_COLOUR: Color32 = Color32::from_gray(140);

/// One colour per method in every plot (grey for a point of no known method): egui_plot's
/// automatic colours follow the drawing order and differ between the two plots.
pub fn method_colour(method: Option<Method>) -> Color32 {
    const PALETTE: [Color32; 6] = [
        Color32::from_rgb(240, 150, 60),
        Color32::from_rgb(230, 90, 90),
        Color32::from_rgb(70, 140, 255),
        Color32::from_rgb(90, 210, 120),
        Color32::from_rgb(200, 110, 230),
        Color32::from_rgb(60, 210, 210),
    ];
    // The method file in white: the one point that is not the lab's.
    if method == Some(Method::File) {
        return Color32::WHITE;
    }
    let index = method.map(Method::index);
    index.map_or(Color32::from_gray(180), |k| PALETTE[k % PALETTE.len()])
}

/// A point's colour and marker: a shape's method ("rect ltc-proxy", a study's
/// "rect-ltc-proxy") in its shape's colour with a marker of its own among that shape's methods;
/// any other by its point method's colour and its variant's marker.
fn point_marker(label: &str, method: Option<Method>) -> (Color32, egui_plot::MarkerShape) {
    sized_marker(label).unwrap_or((method_colour(method), variant_shape(label, method)))
}

/// The colour of a light shape's methods and each method's marker, by its place among the
/// shape's methods; `None` for a label that names no shape's method.
fn sized_marker(label: &str) -> Option<(Color32, egui_plot::MarkerShape)> {
    use egui_plot::MarkerShape::*;
    const SHAPES: [egui_plot::MarkerShape; 5] = [Circle, Diamond, Square, Cross, Up];
    let (family, method) = label.split_once([' ', '-'])?;
    let (colour, names): (Color32, Vec<&str>) = match family {
        "sphere" => (
            Color32::from_rgb(150, 200, 255),
            SphereMethod::ALL.map(SphereMethod::name).to_vec(),
        ),
        "rect" => (
            Color32::from_rgb(250, 210, 80),
            RectMethod::ALL.map(RectMethod::name).to_vec(),
        ),
        "disk" => (
            Color32::from_rgb(255, 120, 180),
            DiskMethod::ALL.map(DiskMethod::name).to_vec(),
        ),
        _ => return None,
    };
    let k = names.iter().position(|n| *n == method)?;
    Some((colour, SHAPES[k % SHAPES.len()]))
}

/// The marker of a method's variant ("ltc-lut16" of ltc): a circle for the method itself,
/// another shape for each variant (by what its name adds to the method's), so that variants
/// of one colour stay apart.
fn variant_shape(label: &str, method: Option<Method>) -> egui_plot::MarkerShape {
    let variant = method
        .and_then(|m| label.strip_prefix(m.name()))
        .unwrap_or(label);
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

/// Each method's work per light (docs/design.md §4.10) beside its measured time per light at
/// the measurement's largest light count, and the time's ratio to `brdf`'s.
fn work_table(ui: &mut egui::Ui, work: &Result<Vec<(Method, Work)>, String>, m: &Measurement) {
    let work = match work {
        Ok(w) => w,
        Err(e) => {
            ui.colored_label(Color32::LIGHT_RED, format!("cannot count: {e}"));
            return;
        }
    };
    // ns per light per pixel is the fps curve's last point: ms per frame over lights × pixels.
    let per_light = |method: Method| {
        let (_, curve) = m.scaling.iter().find(|(x, _)| *x == method)?;
        let &[lights, fps] = curve.last()?;
        Some((lights, 1e3 / fps / lights))
    };
    let brdf = per_light(Method::Brdf).map(|p| p.1);
    egui::Grid::new("chart work grid")
        .striped(true)
        .spacing([12.0, 2.0])
        .show(ui, |ui| {
            for (head, hover) in [
                ("method", "The method's function that adds one light"),
                ("arith.", "Additions, multiplications and the like per light (vectors per component)"),
                ("div.", "Divisions per light (about 9 arithmetic operations' issue slots on a GPU)"),
                ("special", "Roots and transcendental functions per light (about 8 arithmetic operations' issue slots on a GPU)"),
                ("reads", "Loads of memory outside the function per light"),
                ("ms / light", "Measured: ms per frame over lights, at the largest light count measured"),
                ("× brdf", "That time over brdf's"),
            ] {
                ui.small(head).on_hover_text(hover);
            }
            ui.end_row();
            for (method, w) in work {
                ui.monospace(method.name());
                for x in [w.arithmetic, w.divisions, w.special, w.reads] {
                    ui.monospace(x.to_string());
                }
                match per_light(*method) {
                    Some((lights, ms)) => {
                        ui.monospace(format!("{} ({lights:.0} lights)", short_number(ms)));
                        let ratio = brdf.map_or("–".into(), |b| format!("{:.2}", ms / b));
                        ui.monospace(ratio);
                    }
                    None => {
                        ui.monospace("–");
                        ui.monospace("–");
                    }
                }
                ui.end_row();
            }
        });
}
