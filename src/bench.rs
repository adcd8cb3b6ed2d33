//! The paper's Table 1 on this machine's GPU: GPU time per frame of every method at several
//! light counts, measured in one run, with the ratios between the LTC and BRDF forms.

use crate::error::Result;
use crate::gpu::GpuContext;
use crate::gpu::limits::check_image_size;
use crate::gpu::plane::{PlaneRenderer, ShaderChecks};
use crate::ltc::lut::Lut;
use crate::render::{Method, RenderSettings};
use crate::scene::{RandomLights, Scene, generate_lights, preset};

/// The paper's Table 1 (GTX 1060, its resolution unstated): fps at 100, 500, 1000, 5000
/// lights.
pub const PAPER_LIGHTS: [usize; 4] = [100, 500, 1000, 5000];
pub const PAPER_BRDF_FPS: [f64; 4] = [118.0, 23.0, 12.0, 2.0];
pub const PAPER_LTC_FPS: [f64; 4] = [285.0, 56.0, 28.0, 5.0];

/// One measured cell of the table.
#[derive(Clone, Debug, PartialEq)]
pub struct BenchRow {
    pub method: Method,
    pub lights: usize,
    pub width: usize,
    pub height: usize,
    pub frames: usize,
    pub ms_median: f64,
    pub ms_min: f64,
    pub ms_max: f64,
}

impl BenchRow {
    pub fn fps(&self) -> f64 {
        1e3 / self.ms_median
    }

    /// Light-pixel evaluations per second, in billions (every pixel sees the plane).
    pub fn glightpx_per_s(&self) -> f64 {
        (self.lights * self.width * self.height) as f64 / (self.ms_median * 1e-3) / 1e9
    }

    pub const CSV_HEADER: &'static str =
        "method,lights,width,height,frames,ms_median,ms_min,ms_max,fps,glightpx_per_s";

    pub fn csv(&self) -> String {
        format!(
            "{},{},{},{},{},{:.6},{:.6},{:.6},{:.3},{:.3}",
            self.method.name(),
            self.lights,
            self.width,
            self.height,
            self.frames,
            self.ms_median,
            self.ms_min,
            self.ms_max,
            self.fps(),
            self.glightpx_per_s()
        )
    }
}

/// The benchmark scene: paper-100's material (α = 0.27) and light distribution, seen from
/// above a plane large enough that every pixel shades it, so that light-pixels = lights ×
/// width × height.
pub fn bench_scene(lights: usize) -> Scene {
    let mut scene = preset("paper-100");
    let spread = scene.plane.half_size;
    scene.plane.half_size = 1e3;
    scene.camera.position = [0.0, -2.0, 2.5];
    scene.camera.target = [0.0, 0.0, 0.0];
    scene.lights = generate_lights(
        &RandomLights {
            count: lights,
            seed: 27,
            height: [0.05, 0.6],
            intensity: [0.02, 0.08],
            range: Some(2.0),
        },
        spread,
    );
    scene
}

/// Median of a non-empty sample.
fn median(xs: &mut [f64]) -> f64 {
    xs.sort_by(f64::total_cmp);
    let n = xs.len();
    if n % 2 == 1 {
        xs[n / 2]
    } else {
        0.5 * (xs[n / 2 - 1] + xs[n / 2])
    }
}

/// Frames shaded before timing starts (pipeline compilation, caches, clocks).
pub const WARM_UP_FRAMES: usize = 5;

/// Every light count and the size against the adapter's limits: nothing is measured for a
/// run that cannot finish (`study` checks the same).
pub fn check(
    ctx: &GpuContext,
    light_counts: &[usize],
    (width, height): (usize, usize),
) -> Result<()> {
    for &n in light_counts {
        PlaneRenderer::check_light_count(ctx, "--lights", n)?;
    }
    check_image_size(ctx, width, height, crate::gpu::plane::TEXEL_BYTES)
}

/// Measures every method at every light count: `frames` timed frames after warm-up each.
pub fn run(
    ctx: &GpuContext,
    lut: &Lut,
    light_counts: &[usize],
    (width, height): (usize, usize),
    frames: usize,
    checks: ShaderChecks,
    mut progress: impl FnMut(&BenchRow),
) -> Result<Vec<BenchRow>> {
    check(ctx, light_counts, (width, height))?;
    let mut renderer = PlaneRenderer::new(ctx, lut, checks)?;
    let mut rows = Vec::new();
    for &lights in light_counts {
        let scene = bench_scene(lights);
        let mut frame = renderer.prepare(
            ctx,
            &scene,
            &RenderSettings::single(width, height, Method::Brdf),
        )?;
        for method in Method::F32 {
            let settings = RenderSettings::single(width, height, method);
            renderer.update(ctx, &mut frame, &scene, &settings);
            for _ in 0..WARM_UP_FRAMES {
                renderer.run(ctx, &frame);
            }
            let mut ms: Vec<f64> = (0..frames).map(|_| renderer.run(ctx, &frame)).collect();
            let row = BenchRow {
                method,
                lights,
                width,
                height,
                frames,
                ms_min: ms.iter().copied().fold(f64::INFINITY, f64::min),
                ms_max: ms.iter().copied().fold(0.0, f64::max),
                ms_median: median(&mut ms),
            };
            progress(&row);
            rows.push(row);
        }
    }
    Ok(rows)
}

/// The table in Markdown: one row per method and light count, then the speed-ups of each
/// LTC form over each BRDF form, and the paper's figures for reference.
pub fn markdown(rows: &[BenchRow], device: &str) -> String {
    let mut out = format!(
        "GPU: {device}\n\n| method | lights | size | ms (median) | ms (min–max) | fps | G light-px/s |\n|---|---:|---|---:|---:|---:|---:|\n"
    );
    for r in rows {
        out.push_str(&format!(
            "| {} | {} | {}×{} | {:.3} | {:.3}–{:.3} | {:.1} | {:.2} |\n",
            r.method.name(),
            r.lights,
            r.width,
            r.height,
            r.ms_median,
            r.ms_min,
            r.ms_max,
            r.fps(),
            r.glightpx_per_s()
        ));
    }
    out.push_str("\nSpeed-up (BRDF ms / LTC ms, same run):\n\n| lights | ltc / brdf | ltc-fast / brdf | ltc / brdf-fast | ltc-fast / brdf-fast |\n|---:|---:|---:|---:|---:|\n");
    let mut counts: Vec<usize> = rows.iter().map(|r| r.lights).collect();
    counts.dedup();
    for n in counts {
        let ms = |m: Method| {
            rows.iter()
                .find(|r| r.lights == n && r.method == m)
                .map(|r| r.ms_median)
        };
        let ratio = |b: Method, l: Method| match (ms(b), ms(l)) {
            (Some(b), Some(l)) => format!("{:.2}×", b / l),
            _ => "–".into(),
        };
        out.push_str(&format!(
            "| {n} | {} | {} | {} | {} |\n",
            ratio(Method::Brdf, Method::Ltc),
            ratio(Method::Brdf, Method::LtcFast),
            ratio(Method::BrdfFast, Method::Ltc),
            ratio(Method::BrdfFast, Method::LtcFast)
        ));
    }
    out.push_str("\nThe paper's Table 1 (GTX 1060, resolution not stated), for reference:\n\n| lights | BRDF fps | LTC fps | LTC / BRDF |\n|---:|---:|---:|---:|\n");
    for k in 0..PAPER_LIGHTS.len() {
        out.push_str(&format!(
            "| {} | {} | {} | {:.2}× |\n",
            PAPER_LIGHTS[k],
            PAPER_BRDF_FPS[k],
            PAPER_LTC_FPS[k],
            PAPER_LTC_FPS[k] / PAPER_BRDF_FPS[k]
        ));
    }
    out
}
