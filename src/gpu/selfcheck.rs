//! The self-check the browser page runs at `index.html#selfcheck` (docs/design.md §5.8):
//! paper-100 at 160×120, shaded by `ltc-fast` and by `brdf` on the device in chunks of
//! lights, read back without waiting, and compared with the CPU reference at the parity
//! tolerance (`parity`). Nothing here waits: the caller steps it, the browser once per turn
//! of its event loop (where the device's work and the read-back's mapping land), a native
//! test in a loop; each step submits at most one chunk.

use crate::cpu;
use crate::gpu::GpuContext;
use crate::gpu::plane::ShaderChecks;
use crate::gpu::plane_render::{Kept, PlaneRender};
use crate::gpu::renderer::PlaneRenderer;
use crate::gpu::target::PendingRead;
use crate::ltc::lut::Lut;
use crate::measure::parity::Parity;
use crate::render::{Frame, Method, RenderSettings};
use crate::scene::{Scene, preset};

/// The image the check renders: small enough that the CPU reference of both methods takes a
/// fraction of a second in a browser's single thread, large enough for paper-100's lights to
/// cover the plane with highlights of every size.
pub const SIZE: (usize, usize) = (160, 120);

/// The methods compared: the lab's default LTC form and the exact BRDF it is measured
/// against.
pub const METHODS: [Method; 2] = [Method::LtcFast, Method::Brdf];

/// paper-100's lights per chunk: four submissions per image, as the lab's plane sums them.
const CHUNK_LIGHTS: usize = 25;

/// One method's image against the CPU's.
#[derive(Clone, Debug)]
pub struct MethodParity {
    pub method: Method,
    pub parity: Parity,
}

/// The finished check.
#[derive(Clone, Debug)]
pub struct Report {
    pub adapter: String,
    pub methods: Vec<MethodParity>,
}

impl Report {
    /// The largest difference over the methods.
    pub fn max_rel_diff(&self) -> f64 {
        self.methods
            .iter()
            .map(|m| m.parity.max_rel_diff)
            .fold(0.0, f64::max)
    }

    /// Whether every method agrees with the CPU; else which does not and why.
    pub fn check(&self) -> Result<(), String> {
        for m in &self.methods {
            m.parity
                .check()
                .map_err(|why| format!("{}: {why}", m.method.name()))?;
        }
        Ok(())
    }
}

enum Stage {
    /// Summing the current method's lights: the next chunk starts at `done`.
    Summing {
        render: PlaneRender,
        done: usize,
    },
    /// The image asked for.
    Reading {
        render: PlaneRender,
        pending: PendingRead,
    },
    Finished,
}

pub struct SelfCheck {
    ctx: GpuContext,
    renderer: PlaneRenderer,
    scene: Scene,
    lut: &'static Lut,
    /// The index in `METHODS` being rendered.
    method: usize,
    stage: Stage,
    methods: Vec<MethodParity>,
}

impl SelfCheck {
    /// The check on `ctx`'s device with the shipped classic table; the first method begun.
    pub fn new(ctx: GpuContext) -> Result<Self, String> {
        let lut = Lut::embedded();
        let mut renderer =
            PlaneRenderer::new(&ctx, lut, ShaderChecks::Checked).map_err(|e| e.to_string())?;
        let scene = preset("paper-100");
        let render = begin(&ctx, &mut renderer, &scene, 0, None)?;
        Ok(Self {
            ctx,
            renderer,
            scene,
            lut,
            method: 0,
            stage: Stage::Summing { render, done: 0 },
            methods: Vec::new(),
        })
    }

    /// Images read back so far (the first one is the page's first GPU frame).
    pub fn frames_read(&self) -> usize {
        self.methods.len()
    }

    /// One step: a chunk submitted, the read-back asked for, or a frame taken and compared.
    /// The report once both methods are compared.
    pub fn step(&mut self) -> Result<Option<Report>, String> {
        self.stage = match std::mem::replace(&mut self.stage, Stage::Finished) {
            Stage::Summing { mut render, done } if render.binning_progress().is_some() => {
                // Every tile row at once: 8 of them at this size.
                render.bin_step(&self.ctx, SIZE.1);
                Stage::Summing { render, done }
            }
            Stage::Summing { mut render, done } => {
                let total = render.light_count();
                let end = (done + CHUNK_LIGHTS).min(total);
                render.step(&self.ctx, done..end);
                if end == total {
                    let pending = render.start_read(&self.ctx);
                    Stage::Reading { render, pending }
                } else {
                    Stage::Summing { render, done: end }
                }
            }
            Stage::Reading { render, pending } => match pending.try_take(&self.ctx) {
                None => Stage::Reading { render, pending },
                Some(texels) => return self.compare(&render.frame_of(&texels), render),
            },
            Stage::Finished => Stage::Finished,
        };
        Ok(None)
    }

    /// Compares a method's GPU frame with the CPU's, then begins the next method (in the
    /// buffers `render` leaves) or reports.
    fn compare(&mut self, gpu: &Frame, render: PlaneRender) -> Result<Option<Report>, String> {
        let reference = cpu::render(&self.scene, self.lut, &settings(self.method));
        self.methods.push(MethodParity {
            method: METHODS[self.method],
            parity: Parity::of(gpu, &reference),
        });
        self.method += 1;
        if self.method == METHODS.len() {
            return Ok(Some(Report {
                adapter: self.ctx.describe(),
                methods: self.methods.clone(),
            }));
        }
        let kept = Some(render.into_kept());
        let render = begin(
            &self.ctx,
            &mut self.renderer,
            &self.scene,
            self.method,
            kept,
        )?;
        self.stage = Stage::Summing { render, done: 0 };
        Ok(None)
    }
}

/// What method `k` of `METHODS` is rendered with.
fn settings(k: usize) -> RenderSettings {
    RenderSettings::single(SIZE.0, SIZE.1, METHODS[k])
}

/// Method `k`'s render begun.
fn begin(
    ctx: &GpuContext,
    renderer: &mut PlaneRenderer,
    scene: &Scene,
    k: usize,
    kept: Option<Kept>,
) -> Result<PlaneRender, String> {
    renderer
        .begin(ctx, scene, &settings(k), kept)
        .map_err(|e| e.to_string())
}
