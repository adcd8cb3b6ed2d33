//! The plane on the window's own device: the plane shader summed across frames in chunks
//! paced to a time budget, tone-mapped and shown straight from the GPU.

use web_time::Instant;

use crate::app::work::completion::{Chunk, Completion};
use crate::app::work::pacer::Pacer;
use crate::gpu::GpuContext;
use crate::gpu::display::DisplayPass;
use crate::gpu::failures::submissions::METHOD_FILE_SUBMISSION_MS;
use crate::gpu::plane::ShaderChecks;
use crate::gpu::plane_render::PlaneRender;
use crate::gpu::renderer::PlaneRenderer;
use crate::gpu::timing::FrameTimes;
use crate::render::{FrameKind, Method, RenderSettings};
use crate::scene::Scene;
use crate::tables::NamedTables;

use super::{FRAME_BUDGET_MS, Progress};

/// What a chunk does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Work {
    Bin,
    Shade,
}

/// The plane on the window's device.
pub(super) struct GpuShading {
    pub(super) ctx: GpuContext,
    pub(super) renderer: PlaneRenderer,
    /// The current render, once one has begun.
    pub(super) render: Option<PlaneRender>,
    pub(super) display: DisplayPass,
    pub(super) egui: egui_wgpu::RenderState,
    pub(super) texture: Option<egui::TextureId>,
    /// When the last chunk's work was done, by the wall clock (made with the first chunk,
    /// which brings the window to wake).
    pub(super) completion: Option<Completion>,
    /// Whether chunks are paced on timestamp queries (a discrete or integrated GPU that has
    /// them) or on the wall clock (a CPU driver, or no queries).
    pub(super) paced_on_timestamps: bool,
    /// Sizes the chunks of lights and of binning from their times.
    pub(super) shade_pacer: Pacer,
    pub(super) bin_pacer: Pacer,
    /// The chunk in flight, if any.
    pub(super) in_flight: Option<InFlight>,
    /// How the shown image was last made from the sums (a change re-encodes it).
    pub(super) shown: Option<(FrameKind, f64)>,
    /// Why a method file's render was stopped (a batch past `METHOD_FILE_SUBMISSION_MS`).
    pub(super) stopped: Option<String>,
    /// The next band of tile rows of the light being summed, where one light over the whole
    /// image is past a submission's bound (`submissions::Plan`).
    pub(super) band: u32,
    /// The method file (`MethodFile::id`) whose pipelines have run a chunk: their first is
    /// not held to the time limit.
    pub(super) file_dispatched: Option<u64>,
}

/// A chunk submitted and not yet timed.
pub(super) struct InFlight {
    pub(super) work: Work,
    /// Its size, for its pacer: tile rows or list entries.
    pub(super) units: usize,
    /// Submission to completion, once the waiter has seen it done.
    pub(super) wall_ms: Option<f64>,
    /// Whether it belongs to a render since restarted (its time says nothing of the new one).
    pub(super) stale: bool,
}

impl GpuShading {
    pub(super) fn new(ctx: &GpuContext, rs: &egui_wgpu::RenderState) -> Result<Self, String> {
        let ctx = ctx.clone();
        // The shipped table until the first render's tables are set.
        let lut = crate::ltc::lut::Lut::embedded();
        let renderer =
            PlaneRenderer::new(&ctx, lut, ShaderChecks::Checked).map_err(|e| e.to_string())?;
        Ok(Self {
            display: DisplayPass::new(&ctx),
            completion: None,
            paced_on_timestamps: ctx.has_timestamps()
                && ctx.info.device_type != wgpu::DeviceType::Cpu,
            ctx,
            renderer,
            render: None,
            egui: rs.clone(),
            texture: None,
            shade_pacer: Pacer::default(),
            bin_pacer: Pacer::default(),
            in_flight: None,
            shown: None,
            stopped: None,
            band: 0,
            file_dispatched: None,
        })
    }

    /// Tables A and B into the table buffer.
    pub(super) fn set_tables(&mut self, tables: &NamedTables) -> Result<(), String> {
        self.renderer
            .set_tables(&self.ctx, &tables.a.lut, Some(&tables.b.lut))
            .map_err(|e| e.to_string())
    }

    pub(super) fn begin(&mut self, scene: &Scene, settings: &RenderSettings) -> Result<(), String> {
        // A new render's cost per light may be anything: its chunks start small again.
        self.shade_pacer = Pacer::default();
        self.bin_pacer = Pacer::default();
        self.band = 0;
        if let Some(chunk) = &mut self.in_flight {
            chunk.stale = true;
        }
        let kept = self.render.take().map(PlaneRender::into_kept);
        self.render = Some(
            self.renderer
                .begin(&self.ctx, scene, settings, kept)
                .map_err(|e| e.to_string())?,
        );
        Ok(())
    }

    /// Whether the last chunk's work is done and its time taken (into the progress and its
    /// pacer); polls the device, never waits.
    pub(super) fn ready(&mut self, progress: &mut Progress) -> bool {
        let Some(chunk) = &mut self.in_flight else {
            return true;
        };
        // Runs the timestamp read-back's callback, if one is pending. Only while a chunk is
        // in flight: on a CPU driver (lavapipe) a poll can wait behind the window's own
        // drawing, up to tens of milliseconds of an idle frame.
        let _ = self.ctx.device.poll(wgpu::PollType::Poll);
        if chunk.wall_ms.is_none() {
            match self
                .completion
                .as_ref()
                .map_or(Chunk::Idle, Completion::take)
            {
                Chunk::InFlight => return false,
                Chunk::Done { ms } => chunk.wall_ms = Some(ms),
                Chunk::Idle => chunk.wall_ms = Some(0.0),
            }
        }
        let wall_ms = chunk.wall_ms.unwrap_or(0.0);
        let by_wall_clock = match chunk.work {
            Work::Bin => FrameTimes {
                bin_ms: Some(wall_ms),
                shade_ms: 0.0,
            },
            Work::Shade => FrameTimes {
                bin_ms: None,
                shade_ms: wall_ms,
            },
        };
        let times = match self.render.as_mut().and_then(PlaneRender::try_times) {
            Some(t) if self.paced_on_timestamps => t,
            // The timestamps follow the work: a frame or so later.
            None if self.paced_on_timestamps
                && self.render.as_ref().is_some_and(PlaneRender::times_pending) =>
            {
                return false;
            }
            // None coming (a chunk submitted while the last read-back was still out, or a
            // read-back that failed: seen in a browser), or not paced on them (any read is
            // dropped, so that they do not pile up): the wall clock.
            _ => by_wall_clock,
        };
        if chunk.stale {
            self.in_flight = None;
            return true;
        }
        let (work, units) = (chunk.work, chunk.units);
        if let Some(why) = self.past_the_limit((work, units), times.total_ms()) {
            self.stopped = Some(why);
            self.render = None;
            self.in_flight = None;
            return true;
        }
        progress.gpu_ms += times.total_ms();
        match work {
            Work::Bin => self
                .bin_pacer
                .record(units, times.bin_ms.unwrap_or(times.shade_ms)),
            Work::Shade => self.shade_pacer.record(units, times.shade_ms),
        }
        self.in_flight = None;
        true
    }

    /// Why a method file's render stops after a chunk (`work` of `units`), which took `ms` (the GPU's time where
    /// it has timestamps, else the wall clock): past `METHOD_FILE_SUBMISSION_MS`. The first
    /// chunk a file's pipelines run is spared, as `PlaneRender::run` spares it: a driver that
    /// compiles a pipeline at its first dispatch (lavapipe) times the compile with it (5 s for
    /// threejs-rect.wgsl's module, debug build, 2 cores).
    fn past_the_limit(&mut self, (work, units): (Work, usize), ms: f64) -> Option<String> {
        let render = self.render.as_ref()?;
        let file = render
            .settings()
            .methods()
            .contains(&Method::File)
            .then(|| self.renderer.method_file())??;
        if work != Work::Shade || self.file_dispatched.replace(file.id()) != Some(file.id()) {
            return None;
        }
        if ms <= METHOD_FILE_SUBMISSION_MS {
            return None;
        }
        let batch = if render.plan().rows_per < render.plan().rows {
            format!(
                "one band of {} tile rows of one light",
                render.plan().rows_per
            )
        } else {
            format!("one batch of {units} lights")
        };
        Some(format!(
            "{}: {batch} took {:.1} s, past the lab's {:.0} s for a method file: stopped. Measure it in the terminal (ltc-lab study or bench --method-file)",
            file.name,
            ms / 1e3,
            METHOD_FILE_SUBMISSION_MS / 1e3
        ))
    }

    /// Dispatches the next chunk within the budget: a band of tile rows while the lists are
    /// being made, else entries of every pixel's list (and the image shown from them).
    pub(super) fn chunk(
        &mut self,
        window: &egui::Context,
        progress: &mut Progress,
        kind: FrameKind,
        exposure: f64,
    ) {
        let budget_ms = FRAME_BUDGET_MS;
        let submitted = Instant::now();
        let Some(render) = &mut self.render else {
            return;
        };
        let (work, units) = if render.binning_progress().is_some() {
            let rows = self.bin_pacer.next(budget_ms);
            render.bin_step(&self.ctx, rows);
            (Work::Bin, rows)
        } else if render.plan().rows_per < render.plan().rows {
            // One light over the image is past a submission's bound: a band of rows at a time,
            // the light done with its last band.
            let plan = render.plan();
            let rows = self.band..(self.band + plan.rows_per).min(plan.rows);
            render.step_band(&self.ctx, progress.done..progress.done + 1, rows.clone());
            self.band = rows.end % plan.rows;
            let units = usize::from(self.band == 0);
            progress.done += units;
            self.encode_display(kind, exposure * progress.preview_scale());
            (Work::Shade, units)
        } else {
            // Paced to the frame's budget, and never past a submission's bound.
            let most = self
                .shade_pacer
                .next(budget_ms)
                .min(render.plan().lights_per);
            let end = (progress.done + most).min(progress.total);
            render.step(&self.ctx, progress.done..end);
            let units = end - progress.done;
            progress.done = end;
            self.encode_display(kind, exposure * progress.preview_scale());
            (Work::Shade, units)
        };
        // An empty submission's index stands for all the work before it.
        let index = self.ctx.queue.submit([]);
        let (device, queue) = (&self.ctx.device, &self.ctx.queue);
        self.completion
            .get_or_insert_with(|| Completion::new(device.clone(), queue.clone(), window.clone()))
            .submitted(index, submitted);
        self.in_flight = Some(InFlight {
            work,
            units,
            wall_ms: None,
            stale: false,
        });
        progress.binning = self.render.as_ref().and_then(PlaneRender::binning_progress);
        progress.frames += 1;
    }

    /// Re-encodes the shown image where it was made otherwise (the exposure changed).
    pub(super) fn show(&mut self, kind: FrameKind, exposure: f64) {
        if self.shown != Some((kind, exposure)) {
            self.encode_display(kind, exposure);
        }
    }

    pub(super) fn encode_display(&mut self, kind: FrameKind, exposure: f64) {
        let Some(image) = self.render.as_ref().map(PlaneRender::output) else {
            return;
        };
        let size = image.texture().size();
        let (view, fresh) = self.display.target(&self.ctx, (size.width, size.height));
        if fresh || self.texture.is_none() {
            let mut egui = self.egui.renderer.write();
            self.texture = Some(match self.texture {
                Some(id) => {
                    egui.update_egui_texture_from_wgpu_texture(
                        &self.ctx.device,
                        view,
                        wgpu::FilterMode::Linear,
                        id,
                    );
                    id
                }
                None => {
                    egui.register_native_texture(&self.ctx.device, view, wgpu::FilterMode::Linear)
                }
            });
        }
        let mut encoder = self
            .ctx
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("display"),
            });
        self.display
            .encode(&self.ctx, &mut encoder, image, kind, exposure);
        self.ctx.queue.submit([encoder.finish()]);
        self.shown = Some((kind, exposure));
    }
}
