//! The chart's measurement, on the window's own device and in budgeted steps: every method on
//! the current scene (GPU time and image error against the exact BRDF), then fps against the
//! number of lights. Each render is summed in chunks that fit the frame's budget, so that the
//! window stays live; the result is kept with the lab's state.

mod tasks;

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use serde::{Deserialize, Serialize};

use crate::app::work::pacer::Pacer;
use crate::gpu::GpuContext;
use crate::gpu::method_file::MethodFile;
use crate::gpu::plane::ShaderChecks;
use crate::gpu::plane_render::{Kept, PlaneRender};
use crate::gpu::renderer::PlaneRenderer;
use crate::gpu::target::PendingRead;
use crate::ltc::lut::Lut;
use crate::metrics::image_error;
use crate::render::{Frame, Method, RenderSettings};
use crate::scene::Scene;
use tasks::{curve_tasks, method_tasks, shape_tasks};

/// Size of the measured frames: small enough for a CPU driver to finish in seconds.
pub const MEASURE_SIZE: (usize, usize) = (320, 180);
/// Timed renders per point (median): three, as a CPU driver takes seconds for each.
pub const REPEATS: usize = 3;

/// One measured method: GPU ms (the median of the timed renders) and relative RMSE against
/// the exact BRDF.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Point {
    pub label: String,
    /// The method the point's variant shades with (`None`: not one this program knows).
    #[serde(default)]
    pub method: Option<Method>,
    pub ms: f64,
    pub rel_rmse: f64,
    /// The fastest and slowest of the timed renders (a study.csv has only the median).
    #[serde(default)]
    pub ms_range: Option<[f64; 2]>,
}

/// What the chart plots.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Measurement {
    pub points: Vec<Point>,
    /// (lights, fps) per method.
    pub scaling: Vec<(Method, Vec<[f64; 2]>)>,
    /// (lights, slowest fps, fastest fps) per method, from the timed renders.
    #[serde(default)]
    pub scaling_range: Vec<(Method, Vec<[f64; 3]>)>,
    /// Where it comes from: the device and size, or a study file.
    pub device: String,
    /// The shipped study it is, by name (`ShippedStudy`); `None` for a measurement or a
    /// study file.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub study: Option<String>,
}

impl Measurement {
    /// The points of a `study.csv` (`ltc-lab study`): every row a point, labelled with its
    /// variant.
    pub fn from_study(rows: &[crate::measure::study::StudyRow], source: &str) -> Self {
        Self {
            points: rows
                .iter()
                .map(|r| Point {
                    label: r.variant.clone(),
                    method: crate::measure::study::variant(&r.variant)
                        .map(|v| v.method)
                        // An encoding's variant shades as `ltc` does.
                        .or_else(|| {
                            crate::measure::study::variant_encoding(&r.variant).map(|_| Method::Ltc)
                        }),
                    ms: r.ms_median,
                    rel_rmse: r.rel_rmse,
                    ms_range: None,
                })
                .collect(),
            scaling: study_scaling(rows),
            scaling_range: Vec::new(),
            device: format!("{source}: {} rows", rows.len()),
            study: None,
        }
    }

    /// The median milliseconds of the point labelled `label`.
    pub fn ms_of(&self, label: &str) -> Option<f64> {
        self.points.iter().find(|p| p.label == label).map(|p| p.ms)
    }

    /// LTC's fps over the BRDF's at each light count both were measured at, for the forms `ltc`
    /// and `brdf` (or the first of each kind measured).
    pub fn fps_ratios(&self, ltc: Method, brdf: Method) -> Option<FpsRatios> {
        // A form not timed at the paper's counts (the method file, which is not an LTC form of
        // the lab's) falls back to its side's first: an LTC form for the LTC side, else the
        // BRDF (it fell back to brdf, whose ratio to itself read ×1.00).
        let pick = |chosen: Method, side: fn(Method) -> bool| {
            self.scaling
                .iter()
                .find(|(x, _)| *x == chosen)
                .or_else(|| self.scaling.iter().find(|(x, _)| side(*x)))
        };
        let (ltc, ltc_fps) = pick(ltc, Method::is_ltc)?;
        let (brdf, brdf_fps) = pick(brdf, |m| !m.is_ltc() && m != Method::File)?;
        let ratios = ltc_fps
            .iter()
            .filter_map(|[n, f]| {
                let b = brdf_fps.iter().find(|q| q[0] == *n)?;
                Some((*n, f / b[1]))
            })
            .collect();
        Some((*ltc, *brdf, ratios))
    }
}

/// The LTC and BRDF forms compared, and (lights, LTC's fps over the BRDF's) at each count.
pub type FpsRatios = (Method, Method, Vec<(f64, f64)>);

impl Measurement {
    /// Why the chart cannot plot this, if it cannot: every time and fps finite and > 0, every
    /// error finite and ≥ 0. A zero time (fps = 1000/0) or an infinite one froze the plot's
    /// axes at 100% CPU; a persisted one did so at every start.
    pub fn validate(&self) -> Result<(), String> {
        let positive = |x: f64| x.is_finite() && x > 0.0;
        if let Some(p) = self
            .points
            .iter()
            .find(|p| !(positive(p.ms) && p.rel_rmse.is_finite() && p.rel_rmse >= 0.0))
        {
            return Err(format!(
                "point '{}' has time {} ms and error {}: times must be finite and > 0, errors finite",
                p.label,
                crate::error::number(p.ms),
                crate::error::number(p.rel_rmse)
            ));
        }
        let ranges = self.points.iter().flat_map(|p| p.ms_range).flatten();
        let spreads = self.scaling_range.iter().flat_map(|(_, s)| s).flatten();
        if let Some(x) = ranges.chain(spreads.copied()).find(|&x| !positive(x)) {
            return Err(format!(
                "a timed range holds {}: times and fps must be finite and > 0",
                crate::error::number(x)
            ));
        }
        for (method, fps) in &self.scaling {
            if let Some([lights, f]) = fps.iter().find(|[n, f]| !positive(*n) || !positive(*f)) {
                return Err(format!(
                    "{} at {} lights has {} fps: both must be finite and > 0",
                    method.name(),
                    crate::error::number(*lights),
                    crate::error::number(*f)
                ));
            }
        }
        Ok(())
    }
}

/// Appends `point` to `method`'s series.
fn push_to<const N: usize>(
    series: &mut Vec<(Method, Vec<[f64; N]>)>,
    method: Method,
    point: [f64; N],
) {
    match series.iter_mut().find(|(m, _)| *m == method) {
        Some((_, s)) => s.push(point),
        None => series.push((method, vec![point])),
    }
}

/// fps against the light count from a study's rows: per method (its variant of table A),
/// its first α and culling setting, 1000 / median ms.
fn study_scaling(rows: &[crate::measure::study::StudyRow]) -> Vec<(Method, Vec<[f64; 2]>)> {
    let Some(first) = rows.first() else {
        return Vec::new();
    };
    Method::ALL
        .into_iter()
        .filter_map(|m| {
            let mut series: Vec<[f64; 2]> = rows
                .iter()
                .filter(|r| r.alpha == first.alpha && r.cull == first.cull)
                .filter(|r| r.variant == m.name())
                .map(|r| [r.lights as f64, 1000.0 / r.ms_median])
                .collect();
            series.sort_by(|a, b| a[0].total_cmp(&b[0]));
            (series.len() >= 2).then_some((m, series))
        })
        .collect()
}

/// One render to time: a point of the error chart, or of the fps curves.
struct Task {
    label: String,
    /// The point form the point stands for (`None`: a shape's method, whose points are
    /// ltc-fast's).
    method: Option<Method>,
    scene: Scene,
    settings: RenderSettings,
    /// (method, lights) of an fps curve; `None` for an error point.
    curve: Option<(Method, usize)>,
}

/// The render being summed: its entries summed so far, and the chunk in flight (its entries
/// and when it was submitted).
struct Current {
    render: PlaneRender,
    done: usize,
    in_flight: Option<(usize, web_time::Instant)>,
}

/// An error point's image on its way back, with the repeats' median and range.
struct Reading {
    render: PlaneRender,
    pending: PendingRead,
    median: f64,
    range: [f64; 2],
}

/// A measurement under way.
pub struct MeasureJob {
    ctx: GpuContext,
    renderer: PlaneRenderer,
    tasks: Vec<Task>,
    next: usize,
    /// `None`: the next repeat not begun.
    current: Option<Current>,
    /// The buffers the last render left, for the next.
    kept: Option<Kept>,
    /// GPU ms of the current render so far, and of each finished repeat.
    render_ms: f64,
    repeat_ms: Vec<f64>,
    idle: Arc<AtomicBool>,
    /// Sizes the chunks from their GPU times.
    pacer: Pacer,
    exact: Option<Frame>,
    reading: Option<Reading>,
    result: Measurement,
}

impl MeasureJob {
    /// Every method on `scene` (the method file too, where one is loaded), then the paper's
    /// light counts, on the device of `ctx`.
    pub fn new(
        ctx: &GpuContext,
        scene: &Scene,
        lut: &Lut,
        file: Option<&MethodFile>,
    ) -> Result<Self, String> {
        let ctx = ctx.clone();
        let mut renderer =
            PlaneRenderer::new(&ctx, lut, ShaderChecks::Checked).map_err(|e| e.to_string())?;
        // Checked like every method here, so its time is on the same footing.
        renderer
            .set_method_file(&ctx, file.cloned())
            .map_err(|e| e.to_string())?;
        let (w, h) = MEASURE_SIZE;
        let mut tasks = method_tasks(scene, file);
        tasks.extend(shape_tasks(scene));
        tasks.extend(curve_tasks());
        for t in &tasks {
            renderer
                .check(&ctx, &t.scene, &t.settings)
                .map_err(|e| e.to_string())?;
        }
        Ok(Self {
            result: Measurement {
                device: format!("{} at {w}×{h}", ctx.describe()),
                ..Measurement::default()
            },
            ctx,
            renderer,
            tasks,
            next: 0,
            current: None,
            kept: None,
            render_ms: 0.0,
            repeat_ms: Vec::new(),
            idle: Arc::new(AtomicBool::new(true)),
            pacer: Pacer::default(),
            exact: None,
            reading: None,
        })
    }

    /// "ltc-fast at 500 lights (14 of 21)".
    pub fn describe(&self) -> String {
        match self.tasks.get(self.next) {
            Some(t) => format!("{} ({} of {})", t.label, self.next + 1, self.tasks.len()),
            None => "done".into(),
        }
    }

    /// The fraction done.
    pub fn progress(&self) -> f32 {
        self.next as f32 / self.tasks.len().max(1) as f32
    }

    /// One frame's share: a chunk within `budget_ms` once the last is done and timed; the
    /// measurement when the last task has finished. Never waits on the GPU: an error point's
    /// image is read back over frames too (the browser cannot wait).
    pub fn step(&mut self, budget_ms: f64) -> Option<Measurement> {
        let _ = self.ctx.device.poll(wgpu::PollType::Poll);
        if let Some(r) = self.reading.take() {
            let Some(texels) = r.pending.try_take(&self.ctx) else {
                self.reading = Some(r);
                return None;
            };
            let frame = r.render.frame_of(&texels);
            self.kept = Some(r.render.into_kept());
            return self.error_point(&frame, r.median, r.range);
        }
        if !self.idle.load(Ordering::Acquire) {
            return None;
        }
        let task = self.tasks.get(self.next)?;
        let mut current = match self.current.take() {
            Some(c) => c,
            None => {
                let kept = self.kept.take();
                match self
                    .renderer
                    .begin(&self.ctx, &task.scene, &task.settings, kept)
                {
                    Ok(render) => {
                        self.render_ms = 0.0;
                        Current {
                            render,
                            done: 0,
                            in_flight: None,
                        }
                    }
                    Err(e) => {
                        // Checked in `new`: a failure now is the device's.
                        self.result.device = format!("measurement failed: {e}");
                        self.next = self.tasks.len();
                        return Some(std::mem::take(&mut self.result));
                    }
                }
            }
        };
        if let Some((entries, submitted)) = current.in_flight {
            let ms = match current.render.try_times() {
                Some(t) => t.total_ms(),
                // The timestamps follow the work; wait a frame for them.
                None if current.render.times_pending() => {
                    self.current = Some(current);
                    return None;
                }
                // Without timestamp queries (or none coming): submit to done, at frame
                // granularity.
                None => submitted.elapsed().as_secs_f64() * 1e3,
            };
            self.render_ms += ms;
            self.pacer.record(entries, ms);
            current.in_flight = None;
        }
        let (done, total) = (current.done, current.render.light_count());
        if done >= total {
            return self.finish_repeat(current.render);
        }
        // Paced to the frame's budget, and never past a submission's bound (the chart's small
        // image holds a method file's whole loop budget for every light of a chunk).
        let most = self
            .pacer
            .next(budget_ms)
            .min(current.render.plan().lights_per);
        let end = (done + most).min(total);
        self.idle.store(false, Ordering::Release);
        current.render.step(&self.ctx, done..end);
        let idle = self.idle.clone();
        self.ctx
            .queue
            .on_submitted_work_done(move || idle.store(true, Ordering::Release));
        current.in_flight = Some((end - done, web_time::Instant::now()));
        current.done = end;
        self.current = Some(current);
        None
    }

    /// A repeat's renders are all summed: its time; after the last repeat, the point.
    fn finish_repeat(&mut self, render: PlaneRender) -> Option<Measurement> {
        self.repeat_ms.push(self.render_ms);
        if self.repeat_ms.len() < REPEATS {
            self.kept = Some(render.into_kept());
            return None;
        }
        let mut ms = std::mem::take(&mut self.repeat_ms);
        ms.sort_by(f64::total_cmp);
        let median = ms[ms.len() / 2];
        let range = [ms[0], ms[ms.len() - 1]];
        let task = &self.tasks[self.next];
        match task.curve {
            None => {
                let pending = render.start_read(&self.ctx);
                self.reading = Some(Reading {
                    render,
                    pending,
                    median,
                    range,
                });
                return None;
            }
            Some((method, n)) => {
                self.kept = Some(render.into_kept());
                let fps = |ms: f64| 1e3 / ms.max(1e-9);
                push_to(&mut self.result.scaling, method, [n as f64, fps(median)]);
                let spread = [n as f64, fps(range[1]), fps(range[0])];
                push_to(&mut self.result.scaling_range, method, spread);
            }
        }
        self.next_task()
    }

    /// An error point from its image, read back: its error against the first image (the
    /// exact BRDF's, every light with a size by its exact integral).
    fn error_point(&mut self, frame: &Frame, median: f64, range: [f64; 2]) -> Option<Measurement> {
        let exact = self.exact.get_or_insert_with(|| frame.clone());
        let rel_rmse = image_error(frame, exact).rel_rmse;
        let task = &self.tasks[self.next];
        self.result.points.push(Point {
            label: task.label.clone(),
            method: task.method,
            ms: median,
            rel_rmse,
            ms_range: Some(range),
        });
        self.next_task()
    }

    /// On to the next task; after the last, the measurement.
    fn next_task(&mut self) -> Option<Measurement> {
        self.next += 1;
        (self.next == self.tasks.len()).then(|| std::mem::take(&mut self.result))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// With the method file as the LTC form (not timed at the paper's counts), the ratio is the
    /// lab's LTC form's over the BRDF's, not the BRDF's over itself (×1.00).
    #[test]
    fn a_form_not_timed_falls_back_to_its_own_side() {
        let m = Measurement {
            points: Vec::new(),
            scaling: vec![
                (Method::Brdf, vec![[100.0, 10.0]]),
                (Method::Ltc, vec![[100.0, 30.0]]),
            ],
            scaling_range: Vec::new(),
            device: String::new(),
            study: None,
        };
        let (ltc, brdf, ratios) = m.fps_ratios(Method::File, Method::Brdf).unwrap();
        assert_eq!((ltc, brdf), (Method::Ltc, Method::Brdf));
        assert_eq!(ratios, vec![(100.0, 3.0)]);
    }
}
