//! The chart's two plots (docs/design.md §4.6): GPU time against image error, and fps against
//! the number of lights beside the paper's Table 1, on decade-aligned log axes with readings
//! under the pointer.

use egui::Color32;

use crate::app::chart::markers::{
    Entry, PAPER_BRDF_COLOUR, PAPER_LTC_COLOUR, legend, method_colour, point_marker,
};
use crate::app::chart::measure::{Measurement, Point};
use crate::app::lab::Forms;
use crate::app::ui::axes::log_axis;
use crate::colormap::{round_sig, short_number};
use crate::measure::bench::{PAPER_BRDF_FPS, PAPER_LIGHTS, PAPER_LTC_FPS};

/// GPU time against image error, one marker per variant, with the timed renders' spread as
/// a bar; its legend under it.
pub(super) fn time_error_plot(ui: &mut egui::Ui, m: &Measurement, height: f32) {
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
pub(super) fn fps_plot(ui: &mut egui::Ui, m: &Measurement, forms: &Forms, height: f32) {
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

/// The plot's height, leaving room under it for its legend: its entries' widths (marker,
/// small text, gap) wrapped into rows of the available width, plus one row of slack for the
/// wrapping.
pub(super) fn plot_height(ui: &egui::Ui, height: f32, entries: &[Entry]) -> f32 {
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
pub(super) fn decades<'a>(
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
pub(super) fn name_plot(response: &egui::Response, name: &str) {
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Figure, true, name));
}

/// The hover reading of a plot with log10 coordinates: the series and both values.
pub(super) fn log_reading(pos: &egui_plot::HoverPosition<'_>, x: &str, y: &str) -> Option<String> {
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
