//! Charts written to PNG with plotters: the study's Pareto chart, the atlas's heat maps and
//! its lines of the sphere lights' errors.
//! Text uses egui's bundled Ubuntu-Light (nothing is read from the system's fonts).

#[cfg(not(target_arch = "wasm32"))]
use std::sync::Once;

use plotters::prelude::*;

use crate::colormap::viridis;
use crate::error::{Error, Result};

/// Registers the bundled font under plotters' "sans-serif" once per process. In the browser
/// build plotters draws text with the page's own fonts and has no registry: nothing to do.
#[cfg(target_arch = "wasm32")]
fn register_font() {}

/// Registers the bundled font under plotters' "sans-serif" once per process.
#[cfg(not(target_arch = "wasm32"))]
fn register_font() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let defs = egui::FontDefinitions::default();
        let data = defs
            .font_data
            .get("Ubuntu-Light")
            .expect("egui bundles Ubuntu-Light");
        // plotters keeps &'static bytes; one copy for the life of the process.
        let bytes: &'static [u8] = Box::leak((*data.font).as_ref().to_vec().into_boxed_slice());
        plotters::style::register_font("sans-serif", FontStyle::Normal, bytes)
            .unwrap_or_else(|_| panic!("egui's Ubuntu-Light is a valid font"));
    });
}

/// A drawing failure of plotters (a font or a backend): the machine's fault, not the input's.
fn plot_error(name: &str, e: impl std::fmt::Display) -> Error {
    Error::machine(name, format!("cannot draw the chart: {e}"))
}

/// One labelled point of a Pareto chart; `highlight` points are drawn large and labelled.
pub struct ParetoPoint {
    pub label: String,
    pub ms: f64,
    pub error: f64,
    pub highlight: bool,
}

/// The floor under errors on the log axis: the exact method's error 0 is drawn there.
pub const ERROR_FLOOR: f64 = 1e-7;

/// Time against error on log axes, one marker per point, highlighted ones labelled.
/// Returns the PNG's bytes; `name` is for errors.
pub fn pareto_png(name: &str, title: &str, points: &[ParetoPoint]) -> Result<Vec<u8>> {
    register_font();
    let (w, h) = (1000u32, 640u32);
    let mut buffer = vec![0u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| plot_error(name, e))?;
        let ms = |f: fn(f64, f64) -> f64, init| points.iter().map(|p| p.ms).fold(init, f);
        let (x0, x1) = (ms(f64::min, f64::INFINITY) / 1.5, ms(f64::max, 0.0) * 1.5);
        let (y0, y1) = (
            ERROR_FLOOR / 2.0,
            points.iter().map(|p| p.error).fold(1e-3, f64::max) * 3.0,
        );
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 20))
            .margin(16)
            .x_label_area_size(44)
            .y_label_area_size(70)
            // x: log10 of the time on a linear axis (plotters' log axis has no ticks inside
            // one decade, where a study's times usually fall), labelled with the times.
            .build_cartesian_2d(x0.log10()..x1.log10(), (y0..y1).log_scale())
            .map_err(|e| plot_error(name, e))?;
        chart
            .configure_mesh()
            .x_desc("GPU ms per frame (log)")
            .y_desc("relative RMSE against the exact BRDF (log; exact at 1e-7)")
            .x_labels(10)
            .x_label_formatter(&|v| {
                let ms = 10f64.powf(*v);
                match ms {
                    m if m >= 10.0 => format!("{m:.0}"),
                    m if m >= 1.0 => format!("{m:.1}"),
                    m => format!("{m:.3}"),
                }
            })
            .y_label_formatter(&|v| format!("{v:.0e}"))
            .label_style(("sans-serif", 14))
            .draw()
            .map_err(|e| plot_error(name, e))?;
        let palette = |k: usize| readable(Palette99::pick(k).to_rgba());
        let mut names: Vec<&str> = points.iter().map(|p| p.label.as_str()).collect();
        names.dedup();
        names.sort_unstable();
        names.dedup();
        let mut labels: Vec<((i32, i32), String, RGBAColor)> = Vec::new();
        for p in points {
            let k = names.iter().position(|n| *n == p.label).unwrap_or(0);
            let y = p.error.max(ERROR_FLOOR);
            let (r, style) = if p.highlight {
                (7, palette(k).filled())
            } else {
                (3, palette(k).mix(0.35).filled())
            };
            chart
                .draw_series(std::iter::once(Circle::new((p.ms.log10(), y), r, style)))
                .map_err(|e| plot_error(name, e))?;
            if p.highlight {
                labels.push((
                    chart.backend_coord(&(p.ms.log10(), y)),
                    p.label.clone(),
                    palette(k),
                ));
            }
        }
        // Labels stacked 17 px apart beside their markers, with a leader line each: the
        // variants of one method sit at nearly the same point. The stack moved up as a whole
        // where it would run off the image's foot (the exact variant, at the floor, was cut
        // off), and a label that would run off the right edge left of its marker.
        labels.sort_by_key(|l| l.0.1);
        let mut next_y = i32::MIN;
        let stacked: Vec<i32> = labels
            .iter()
            .map(|((_, y), _, _)| {
                let ly = (*y).max(next_y);
                next_y = ly + 17;
                ly
            })
            .collect();
        // The plot's foot: above the x labels' area (44 px) and the margin (16 px).
        let overflow = stacked
            .last()
            .map_or(0, |&ly| (ly + 10 - (h as i32 - 60)).max(0));
        for (((x, y), label, colour), ly) in labels.into_iter().zip(stacked) {
            let ly = ly - overflow;
            // 15 px sans-serif: about 8 px a character.
            let width = 8 * label.chars().count() as i32;
            let left = x + 60 + width > w as i32;
            let lx = if left { x - 60 - width } else { x + 60 };
            let end = if left { lx + width + 4 } else { lx - 4 };
            root.draw(&PathElement::new(
                vec![(x, y), (end, ly)],
                colour.stroke_width(1),
            ))
            .map_err(|e| plot_error(name, e))?;
            root.draw(&Text::new(label, (lx, ly - 8), ("sans-serif", 15)))
                .map_err(|e| plot_error(name, e))?;
        }
        root.present().map_err(|e| plot_error(name, e))?;
    }
    encode_png(name, w, h, buffer)
}

/// `c` darkened where it is too pale to read on white (Palette99's yellows and light greens),
/// to a luma of at most 150 of 255 (Rec. 601 weights).
fn readable(c: RGBAColor) -> RGBAColor {
    let luma = 0.299 * f64::from(c.0) + 0.587 * f64::from(c.1) + 0.114 * f64::from(c.2);
    if luma <= 150.0 {
        return c;
    }
    let k = 150.0 / luma;
    let scale = |v: u8| (f64::from(v) * k).round() as u8;
    RGBAColor(scale(c.0), scale(c.1), scale(c.2), c.3)
}

/// A heat map of `value(x, y)` on a grid of cells with the given edges, coloured on the
/// relative-difference scale of `output::diff_scale_position` (log, 0.1% to 100%).
pub fn heat_map_png(
    name: &str,
    title: &str,
    (x_desc, x_edges): (&str, &[f64]),
    (y_desc, y_edges): (&str, &[f64]),
    value: impl Fn(usize, usize) -> f64,
) -> Result<Vec<u8>> {
    register_font();
    let (w, h) = (760u32, 640u32);
    let mut buffer = vec![0u8; (w * h * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| plot_error(name, e))?;
        let (main, bar) = root.split_vertically(h - 60);
        let (xs, ys) = (x_edges, y_edges);
        let mut chart = ChartBuilder::on(&main)
            .caption(title, ("sans-serif", 18))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(56)
            .build_cartesian_2d(xs[0]..xs[xs.len() - 1], ys[0]..ys[ys.len() - 1])
            .map_err(|e| plot_error(name, e))?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(x_desc)
            .y_desc(y_desc)
            .label_style(("sans-serif", 14))
            .draw()
            .map_err(|e| plot_error(name, e))?;
        let cells = (0..xs.len() - 1).flat_map(|i| (0..ys.len() - 1).map(move |j| (i, j)));
        chart
            .draw_series(cells.map(|(i, j)| {
                let [r, g, b] = viridis(crate::output::diff_scale_position(value(i, j)));
                Rectangle::new(
                    [(xs[i], ys[j]), (xs[i + 1], ys[j + 1])],
                    RGBColor(r, g, b).filled(),
                )
            }))
            .map_err(|e| plot_error(name, e))?;
        // The colour scale: log from 0.1% to 100%.
        let bar = bar.margin(8, 16, 70, 24);
        let (bw, _) = bar.dim_in_pixel();
        for x in 0..bw {
            let [r, g, b] = viridis(f64::from(x) / f64::from(bw.max(2) - 1));
            bar.draw(&Rectangle::new(
                [(x as i32, 0), (x as i32 + 1, 16)],
                RGBColor(r, g, b).filled(),
            ))
            .map_err(|e| plot_error(name, e))?;
        }
        for (k, label) in ["0.1%", "1%", "10%", "100%"].iter().enumerate() {
            let x = (f64::from(bw) * k as f64 / 3.0) as i32 - 12;
            bar.draw(&Text::new(*label, (x, 20), ("sans-serif", 14)))
                .map_err(|e| plot_error(name, e))?;
        }
        root.present().map_err(|e| plot_error(name, e))?;
    }
    encode_png(name, w, h, buffer)
}

/// A line of a panel: its label and its points.
pub struct Series {
    pub label: String,
    pub points: Vec<(f64, f64)>,
}

/// Panels side by side sharing their axes' ranges, each with its lines (the k-th series of
/// every panel in the k-th colour, labelled in the first panel's legend).
pub fn line_panels_png(
    name: &str,
    title: &str,
    (x_desc, y_desc): (&str, &str),
    panels: &[(String, Vec<Series>)],
) -> Result<Vec<u8>> {
    register_font();
    let (w, h) = (360 * panels.len().max(1) as u32, 480u32);
    let mut buffer = vec![0u8; (w * h * 3) as usize];
    let all = || panels.iter().flat_map(|p| &p.1).flat_map(|s| &s.points);
    let x1 = all().map(|p| p.0).fold(1e-9, f64::max);
    let y1 = all().map(|p| p.1).fold(1e-9, f64::max) * 1.1;
    {
        let root = BitMapBackend::with_buffer(&mut buffer, (w, h)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| plot_error(name, e))?;
        let root = root
            .titled(title, ("sans-serif", 18))
            .map_err(|e| plot_error(name, e))?;
        let areas = root.split_evenly((1, panels.len().max(1)));
        for (k, ((panel_title, series), area)) in panels.iter().zip(&areas).enumerate() {
            let mut chart = ChartBuilder::on(area)
                .caption(panel_title, ("sans-serif", 15))
                .margin(10)
                .x_label_area_size(40)
                .y_label_area_size(if k == 0 { 56 } else { 36 })
                .build_cartesian_2d(0.0..x1, 0.0..y1)
                .map_err(|e| plot_error(name, e))?;
            chart
                .configure_mesh()
                .x_desc(x_desc)
                .y_desc(if k == 0 { y_desc } else { "" })
                // Integer ticks on a short axis (no label drawn twice by rounding).
                .x_labels(if x1 <= 10.0 {
                    x1.ceil() as usize + 1
                } else {
                    10
                })
                .x_label_formatter(&|v| format!("{v:.0}"))
                .y_label_formatter(&|v| format!("{v:.0}"))
                .light_line_style(WHITE)
                .label_style(("sans-serif", 13))
                .draw()
                .map_err(|e| plot_error(name, e))?;
            for (j, s) in series.iter().enumerate() {
                let colour = Palette99::pick(j).to_rgba();
                chart
                    .draw_series(s.points.iter().map(|&p| Circle::new(p, 3, colour.filled())))
                    .map_err(|e| plot_error(name, e))?;
                let drawn = chart
                    .draw_series(LineSeries::new(
                        s.points.iter().copied(),
                        colour.stroke_width(2),
                    ))
                    .map_err(|e| plot_error(name, e))?;
                // The legend in the last panel: the highest band, whose errors are the lowest.
                if k + 1 == panels.len() {
                    drawn.label(s.label.clone()).legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 16, y)], colour.stroke_width(2))
                    });
                }
            }
            if k + 1 == panels.len() {
                chart
                    .configure_series_labels()
                    .position(SeriesLabelPosition::UpperLeft)
                    .background_style(WHITE.mix(0.85))
                    .border_style(BLACK)
                    .label_font(("sans-serif", 13))
                    .draw()
                    .map_err(|e| plot_error(name, e))?;
            }
        }
        root.present().map_err(|e| plot_error(name, e))?;
    }
    encode_png(name, w, h, buffer)
}

fn encode_png(name: &str, w: u32, h: u32, buffer: Vec<u8>) -> Result<Vec<u8>> {
    let img = image::RgbImage::from_raw(w, h, buffer).expect("the buffer has w × h × 3 bytes");
    let mut out = std::io::Cursor::new(Vec::new());
    img.write_to(&mut out, image::ImageFormat::Png)
        .map_err(|e| plot_error(name, e))?;
    Ok(out.into_inner())
}
