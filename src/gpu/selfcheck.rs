//! The self-check the browser page runs at `index.html#selfcheck` (docs/design.md §5.8):
//! paper-100 at 160×120, shaded by `ltc-fast` and by `brdf` on the device in chunks of
//! lights, read back without waiting, and compared with the CPU reference at the parity
//! tolerance (`parity`). Nothing here waits: the caller steps it, the browser once per turn
//! of its event loop (where the device's work and the read-back's mapping land), a native
//! test in a loop; each step submits at most one chunk.

use crate::cpu;
use crate::gpu::GpuContext;
use crate::gpu::plane::{PlaneRenderer, ShaderChecks};
use crate::gpu::target::PendingRead;
use crate::ltc::lut::Lut;
use crate::parity::Parity;
use crate::render::{Method, RenderSettings};
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
        done: usize,
    },
    /// The image asked for.
    Reading(PendingRead),
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
        let renderer =
            PlaneRenderer::new(&ctx, lut, ShaderChecks::Checked).map_err(|e| e.to_string())?;
        let mut check = Self {
            ctx,
            renderer,
            scene: preset("paper-100"),
            lut,
            method: 0,
            stage: Stage::Finished,
            methods: Vec::new(),
        };
        check.begin()?;
        Ok(check)
    }

    fn settings(&self) -> RenderSettings {
        RenderSettings::single(SIZE.0, SIZE.1, METHODS[self.method])
    }

    fn begin(&mut self) -> Result<(), String> {
        let settings = self.settings();
        self.renderer
            .begin(&self.ctx, &self.scene, &settings)
            .map_err(|e| e.to_string())?;
        self.stage = Stage::Summing { done: 0 };
        Ok(())
    }

    /// Images read back so far (the first one is the page's first GPU frame).
    pub fn frames_read(&self) -> usize {
        self.methods.len()
    }

    /// One step: a chunk submitted, the read-back asked for, or a frame taken and compared.
    /// The report once both methods are compared.
    pub fn step(&mut self) -> Result<Option<Report>, String> {
        match &self.stage {
            Stage::Summing { done } if self.renderer.binning_progress().is_some() => {
                let done = *done;
                // Every tile row at once: 8 of them at this size.
                self.renderer.bin_step(&self.ctx, SIZE.1);
                self.stage = Stage::Summing { done };
            }
            Stage::Summing { done } => {
                let total = self.renderer.light_count();
                let end = (done + CHUNK_LIGHTS).min(total);
                self.renderer.step(&self.ctx, *done..end);
                self.stage = if end == total {
                    Stage::Reading(self.renderer.start_read(&self.ctx))
                } else {
                    Stage::Summing { done: end }
                };
            }
            Stage::Reading(pending) => {
                let Some(texels) = pending.try_take(&self.ctx) else {
                    return Ok(None);
                };
                let gpu = self.renderer.frame_of(&texels);
                let reference = cpu::render(&self.scene, self.lut, &self.settings());
                self.methods.push(MethodParity {
                    method: METHODS[self.method],
                    parity: Parity::of(&gpu, &reference),
                });
                self.method += 1;
                if self.method == METHODS.len() {
                    self.stage = Stage::Finished;
                    return Ok(Some(Report {
                        adapter: self.ctx.describe(),
                        methods: self.methods.clone(),
                    }));
                }
                self.begin()?;
            }
            Stage::Finished => {}
        }
        Ok(None)
    }
}
