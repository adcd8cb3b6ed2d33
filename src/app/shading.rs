//! The lab's renderer: the GPU plane shader on the lab's own headless device, read back into
//! a `Frame`, or — where no adapter exists — the CPU reference at a smaller size, with the
//! reason kept for the window to show.

use crate::gpu::GpuContext;
use crate::gpu::plane::{PlaneRenderer, ShaderChecks};
use crate::ltc::lut::Lut;
use crate::render::{Frame, Method, RenderSettings};
use crate::scene::Scene;

pub struct Shading {
    gpu: Option<(GpuContext, PlaneRenderer)>,
    /// The table both paths shade with.
    lut: Lut,
    /// Why the GPU is not used, for the window.
    pub gpu_error: Option<String>,
}

/// The largest side the CPU fallback renders: the f64 reference shades ~1e8 light-pixels/s
/// on two cores, so 320 px keeps 100 lights interactive.
pub const CPU_FALLBACK_SIDE: usize = 320;

/// One rendered view and how it was made.
pub struct Shaded {
    pub frame: Frame,
    /// GPU milliseconds of the pass (timestamp queries or wall clock), `None` on the CPU.
    pub gpu_ms: Option<f64>,
}

impl Shading {
    pub fn new(lut: &Lut) -> Self {
        let gpu = GpuContext::new().and_then(|ctx| {
            let renderer = PlaneRenderer::new(&ctx, lut, ShaderChecks::Checked)?;
            Ok((ctx, renderer))
        });
        match gpu {
            Ok(gpu) => Self {
                gpu: Some(gpu),
                lut: lut.clone(),
                gpu_error: None,
            },
            Err(e) => Self {
                gpu: None,
                lut: lut.clone(),
                gpu_error: Some(e.to_string()),
            },
        }
    }

    /// The device in words, or why there is none.
    pub fn describe(&self) -> String {
        match (&self.gpu, &self.gpu_error) {
            (Some((ctx, _)), _) => ctx.describe(),
            (None, Some(e)) => format!("no GPU: {e}"),
            (None, None) => "no GPU".into(),
        }
    }

    pub fn has_gpu(&self) -> bool {
        self.gpu.is_some()
    }

    /// Shades with another table from now on (on the CPU where the GPU cannot hold it).
    pub fn set_lut(&mut self, lut: &Lut) {
        if let Some((ctx, renderer)) = &mut self.gpu {
            match PlaneRenderer::new(ctx, lut, ShaderChecks::Checked) {
                Ok(r) => *renderer = r,
                Err(e) => {
                    self.gpu = None;
                    self.gpu_error = Some(e.to_string());
                }
            }
        }
        self.lut = lut.clone();
    }

    /// The GPU's light limit, or the scene limit on the CPU.
    pub fn max_lights(&self) -> usize {
        self.gpu
            .as_ref()
            .map_or(crate::scene::MAX_LIGHTS, |(ctx, _)| {
                PlaneRenderer::max_lights(ctx)
            })
    }

    /// Renders `settings` (the CPU draws the literal form of each method, at most
    /// `CPU_FALLBACK_SIDE` pixels wide).
    pub fn render(&mut self, scene: &Scene, settings: &RenderSettings) -> Result<Shaded, String> {
        match &mut self.gpu {
            Some((ctx, renderer)) => {
                let (frame, ms) = renderer
                    .render(ctx, scene, settings)
                    .map_err(|e| e.to_string())?;
                Ok(Shaded {
                    frame,
                    gpu_ms: Some(ms),
                })
            }
            None => {
                let scale = (CPU_FALLBACK_SIDE as f64 / settings.width.max(settings.height) as f64)
                    .min(1.0);
                let s = RenderSettings {
                    width: ((settings.width as f64 * scale).round() as usize).max(1),
                    height: ((settings.height as f64 * scale).round() as usize).max(1),
                    ..*settings
                };
                Ok(Shaded {
                    frame: crate::cpu::render(scene, &self.lut, &s),
                    gpu_ms: None,
                })
            }
        }
    }

    /// GPU milliseconds of one method alone on `scene` (median of `frames`, after the
    /// pipeline's first use), for the live per-method times; `None` without a GPU.
    pub fn time_method(
        &mut self,
        scene: &Scene,
        settings: &RenderSettings,
        method: Method,
        frames: usize,
    ) -> Option<f64> {
        let (ctx, renderer) = self.gpu.as_mut()?;
        renderer.begin(ctx, scene, &settings.alone(method)).ok()?;
        let mut ms: Vec<f64> = (0..frames.max(1))
            .map(|_| renderer.run(ctx).total_ms())
            .collect();
        ms.sort_by(f64::total_cmp);
        Some(ms[ms.len() / 2])
    }
}
