//! One render of the plane on the GPU, from its start (`PlaneRenderer::begin`) to its image:
//! its lights, uniforms, target and bind groups, the pipelines of its specialization, and how
//! far its tile lists are made. It is summed in chunks of lights (`step`), or whole (`run`),
//! and read back without waiting (`start_read`) or waiting (`read`). Everything it needs
//! exists from its start, so its methods may come in any order; the buffers it leaves
//! (`Kept`) are taken by the next render of its size. Its tile lists are made in `binning`,
//! and its image read back in `readback`.

mod binning;
mod readback;

use std::ops::Range;

use binning::BinStage;

use crate::error::{Error, Result};
use crate::gpu::GpuContext;
use crate::gpu::bin::{self, Binning};
use crate::gpu::failures::scoped;
use crate::gpu::failures::submissions::{METHOD_FILE_SUBMISSION_MS, Plan};
use crate::gpu::ltc::LutBuffer;
use crate::gpu::plane::{self, Pipelines};
use crate::gpu::scene::{GpuLight, Params, light_elements, params};
use crate::gpu::target::Target;
use crate::gpu::timing::{FrameTimes, PassTimer, Slot};
use crate::render::{RenderSettings, View};
use crate::scene::Scene;

/// What a render leaves to the next: its buffers, its target and its timer.
pub struct Kept {
    lights: wgpu::Buffer,
    params: wgpu::Buffer,
    target: Target,
    timer: Option<PassTimer>,
}

/// A render begun: everything its chunks need.
pub struct PlaneRender {
    pipelines: Pipelines,
    binning: Binning,
    kept: Kept,
    plane_group: wgpu::BindGroup,
    bin_group: wgpu::BindGroup,
    params: Params,
    settings: RenderSettings,
    light_count: usize,
    /// How far the tile lists are made: the next band of tile rows to count or to write
    /// (`None`: made, or no culling).
    bin_stage: Option<BinStage>,
    /// The method file its pipelines hold, by name (what a stopped render names).
    file: Option<String>,
    /// The estimated operations of one light at one pixel (`work::light_operations`).
    light_work: f64,
    /// With a method file: the lights of its next submission, paced on the time the last took
    /// (from 1, kept from one `run` to the next), so that one past the time limit is the
    /// file's, not a batch too large for a slow device.
    file_chunk: usize,
    /// Whether a submission of it has run: the first is not held to the time limit, as a
    /// driver that compiles a pipeline at its first dispatch (llvmpipe) times the compile
    /// with it; it sums one light of a file (`file_chunk` starts at 1).
    dispatched: bool,
}

/// How far `PlaneRender::run` is: submissions made, lights summed of all.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RunProgress {
    pub submissions: usize,
    pub lights_done: usize,
    pub lights: usize,
}

/// The time a method file's submission aims at in `run`: well inside the stop's 2 s.
const FILE_SUBMISSION_TARGET_MS: f64 = 200.0;

/// What `PlaneRenderer::begin` hands a new render: the pipelines of its specialization and
/// their layout, the binning passes and the tables' buffer.
pub struct Begun<'a> {
    pub pipelines: Pipelines,
    pub layout: &'a wgpu::BindGroupLayout,
    pub binning: &'a Binning,
    pub tables: &'a LutBuffer,
    /// The name of the method file the pipelines hold, if any.
    pub file: Option<String>,
    /// The estimated operations of one light at one pixel in their module.
    pub light_work: f64,
}

impl PlaneRender {
    /// A render of `scene` as `settings` says (checked by the renderer), in `kept`'s buffers
    /// where they hold it. Nothing is summed yet; a culled render makes its tile lists with
    /// its first chunk, or band by band (`bin_step`).
    pub fn new(
        ctx: &GpuContext,
        begun: Begun<'_>,
        (scene, settings): (&Scene, &RenderSettings),
        kept: Option<Kept>,
    ) -> Self {
        let lights: Vec<GpuLight> = light_elements(&scene.lights);
        let any_ranged = scene.lights.iter().any(|l| l.range.is_some());
        let cull = settings.cull && any_ranged;
        let (tiles_x, tiles_y) = crate::gpu::scene::tiles(settings.width, settings.height);
        let capacity = if cull {
            bin::capacity(ctx, tiles_x * tiles_y, scene.lights.len())
        } else {
            1
        };
        let kept = Kept::for_render(ctx, kept, (settings.width, settings.height), capacity)
            .with_lights(ctx, &lights);
        let mut p = params(settings, scene);
        p.cull = u32::from(cull);
        p.tile_capacity = kept.target.tile_capacity.min(u64::from(u32::MAX)) as u32;
        let tables = begun.tables;
        p.lut_size = tables.size_a as u32;
        let (size_b, base_b) = tables.b.unwrap_or((tables.size_a, 0));
        p.lut_size_b = size_b as u32;
        p.lut_base_b = base_b;
        ((p.aniso_a, p.aniso_dims_a), (p.aniso_b, p.aniso_dims_b)) =
            (tables.aniso_a, tables.aniso_b);
        if settings.view == View::B && settings.b_reads_table_b {
            // B alone is shaded as the single method A: with B's table in A's place.
            p.lut_size = size_b as u32;
            p.lut_base = base_b;
            (p.aniso_a, p.aniso_dims_a) = tables.aniso_b;
        }
        let (plane_group, bin_group) = bind_groups(ctx, &kept, &begun);
        Self {
            pipelines: begun.pipelines,
            binning: begun.binning.clone(),
            kept,
            plane_group,
            bin_group,
            params: p,
            settings: *settings,
            light_count: scene.lights.len(),
            bin_stage: cull.then_some(BinStage::Count(0)),
            file: begun.file,
            light_work: begun.light_work,
            file_chunk: 1,
            dispatched: false,
        }
    }

    /// Its buffers, for the next render.
    pub fn into_kept(self) -> Kept {
        self.kept
    }

    /// What it renders.
    pub fn settings(&self) -> &RenderSettings {
        &self.settings
    }

    /// The number of entries a full render sums per pixel (every light, unculled).
    pub fn light_count(&self) -> usize {
        self.light_count
    }

    /// How it is split into submissions a watchdog never sees (`submissions::Plan`).
    pub fn plan(&self) -> Plan {
        let s = &self.settings;
        Plan::new(s.width, s.height, self.light_count, self.light_work)
    }

    /// Sums entries `range` of every pixel's list into the kept sums (from zero where the
    /// range starts at 0), then resolves the image; one submission. The first chunk of a
    /// culled render makes the tile lists first, where `bin_step` has not.
    pub fn step(&mut self, ctx: &GpuContext, range: Range<usize>) -> wgpu::SubmissionIndex {
        let rows = 0..self.tiles().1;
        self.step_band(ctx, range, rows)
    }

    /// `step` over the tile rows `rows` alone: the image is resolved after the band that ends
    /// at the last row. A band from row 0 comes first for each range (it makes the lists).
    pub fn step_band(
        &mut self,
        ctx: &GpuContext,
        range: Range<usize>,
        rows: Range<u32>,
    ) -> wgpu::SubmissionIndex {
        self.params.light_start = range.start as u32;
        self.params.light_end = range.end as u32;
        self.params.bin_row = rows.start;
        self.write_params(ctx);
        let mut encoder = ctx
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("plane"),
            });
        // Taken while the passes are recorded, and given back.
        let mut timer = self.kept.timer.take();
        let mut timing = timer.as_mut().filter(|t| t.can_resolve());
        if let Some(t) = &mut timing {
            t.clear();
        }
        let tiles = self.tiles();
        if range.start == 0 && rows.start == 0 {
            // The mark of a method file stopped (after the floor in `partials`) begins clear.
            let floor = u64::from(tiles.0 * tiles.1) * 16;
            encoder.clear_buffer(&self.kept.target.partials, floor, Some(16));
        }
        // Binning reads `bin_row` as its first row too: only with a band from row 0.
        if rows.start == 0 && self.bin_stage.take().is_some() {
            // Lists not (all) made band by band: made whole here, in one pass from row 0.
            self.binning
                .encode_all(&mut encoder, &self.bin_group, tiles, timing.as_deref_mut());
        }
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("shade"),
                timestamp_writes: timing.as_deref_mut().map(|t| t.writes(Slot::Shade)),
            });
            pass.set_bind_group(0, &self.plane_group, &[]);
            pass.set_pipeline(&self.pipelines.shade);
            pass.dispatch_workgroups(tiles.0, rows.end.saturating_sub(rows.start), 1);
        }
        if rows.end >= tiles.1 {
            self.encode_resolve(&mut encoder);
        }
        let timed = timing.is_some();
        if let Some(t) = timing {
            t.resolve(&mut encoder);
        }
        let index = ctx.queue.submit([encoder.finish()]);
        if timed && let Some(t) = &mut timer {
            t.request();
        }
        self.kept.timer = timer;
        index
    }

    /// The image from the sums: the difference view's floor first where it shows one.
    fn encode_resolve(&self, encoder: &mut wgpu::CommandEncoder) {
        let tiles = self.tiles();
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("resolve"),
            timestamp_writes: None,
        });
        pass.set_bind_group(0, &self.plane_group, &[]);
        if self.settings.view == View::Diff {
            pass.set_pipeline(&self.pipelines.reduce);
            pass.dispatch_workgroups(tiles.0, tiles.1, 1);
            pass.set_pipeline(&self.pipelines.floor);
            pass.dispatch_workgroups(1, 1, 1);
        }
        pass.set_pipeline(&self.pipelines.resolve);
        pass.dispatch_workgroups(tiles.0, tiles.1, 1);
    }

    fn tiles(&self) -> (u32, u32) {
        let t = self.kept.target.tiles;
        (t.0 as u32, t.1 as u32)
    }

    fn write_params(&self, ctx: &GpuContext) {
        ctx.queue
            .write_buffer(&self.kept.params, 0, bytemuck::bytes_of(&self.params));
    }

    /// Whether its steps are timed (the device has timestamp queries).
    pub fn timed(&self) -> bool {
        self.kept.timer.is_some()
    }

    /// Whether the last step's GPU times are on their way (else `try_times` has none coming).
    pub fn times_pending(&self) -> bool {
        self.kept.timer.as_ref().is_some_and(PassTimer::pending)
    }

    /// The last step's GPU times if they have arrived (poll the device meanwhile); never
    /// waits.
    pub fn try_times(&mut self) -> Option<FrameTimes> {
        let slots = self.kept.timer.as_mut()?.try_read()?;
        Some(FrameTimes {
            bin_ms: slots[Slot::Bin as usize],
            shade_ms: slots[Slot::Shade as usize].unwrap_or(0.0),
        })
    }

    /// Renders it whole (every light, its tile lists made again) in submissions within its
    /// `plan` — with a method file, paced from one light on their times — waiting for each;
    /// `progress` hears each one done. Its GPU times (timestamp queries) summed, or the wall
    /// clock of submit-to-done where the adapter has none. Refused where the device failed
    /// (`GpuContext::check`), and, with a method file, where one submission took past
    /// `METHOD_FILE_SUBMISSION_MS`, naming the file and how far it got.
    pub fn run(
        &mut self,
        ctx: &GpuContext,
        progress: &mut dyn FnMut(RunProgress),
    ) -> Result<FrameTimes> {
        if self.params.cull != 0 {
            self.bin_stage = Some(BinStage::Count(0));
        }
        // A read-back still in flight is taken first, so that this frame's timestamps land.
        if let Some(t) = &mut self.kept.timer {
            let _ = t.read_ms(&ctx.device);
        }
        let plan = self.plan();
        let mut total = FrameTimes {
            bin_ms: None,
            shade_ms: 0.0,
        };
        let mut at = RunProgress {
            submissions: 0,
            lights_done: 0,
            lights: self.light_count,
        };
        let mut row = 0;
        loop {
            let per = if self.file.is_some() {
                self.file_chunk.min(plan.lights_per)
            } else {
                plan.lights_per
            };
            let lights = at.lights_done..(at.lights_done + per).min(self.light_count);
            let rows = row..(row + plan.rows_per).min(plan.rows);
            let start = web_time::Instant::now();
            let (_, error) = scoped(&ctx.device, || {
                self.step_band(ctx, lights.clone(), rows.clone())
            });
            let _ = ctx.device.poll(wgpu::PollType::wait_indefinitely());
            let wall_ms = start.elapsed().as_secs_f64() * 1e3;
            ctx.check()?;
            if let Some(e) = error {
                let message = format!("the device refused the lab's work: {e}");
                return Err(Error::machine(ctx.name(), message));
            }
            let slots = self
                .kept
                .timer
                .as_mut()
                .map_or([None; 2], |t| t.read_ms(&ctx.device));
            let times = FrameTimes::from_slots(slots, wall_ms);
            // The GPU's own time where it has timestamps (what a watchdog counts; the wall
            // clock also holds a driver compiling the pipeline at its first dispatch).
            if std::mem::replace(&mut self.dispatched, true) {
                self.check_time(times.total_ms(), &at)?;
            }
            total.shade_ms += times.shade_ms;
            if let Some(b) = times.bin_ms {
                *total.bin_ms.get_or_insert(0.0) += b;
            }
            at.submissions += 1;
            row = rows.end % plan.rows;
            if row == 0 {
                at.lights_done = lights.end;
                // Towards the target time, by at most 4 times a step.
                let grow = (FILE_SUBMISSION_TARGET_MS / times.total_ms().max(1e-3)).clamp(0.5, 4.0);
                self.file_chunk = ((per as f64 * grow) as usize).clamp(1, plan.lights_per);
            }
            progress(at);
            if at.lights_done >= self.light_count {
                return Ok(total);
            }
        }
    }

    /// Refuses a method file's submission that took `ms` past
    /// `METHOD_FILE_SUBMISSION_MS`, naming the file and how far the render got (`at`).
    fn check_time(&self, ms: f64, at: &RunProgress) -> Result<()> {
        match &self.file {
            Some(name) if ms > METHOD_FILE_SUBMISSION_MS => Err(Error::input(
                name,
                format!(
                    "stopped after {} submissions, {} of {} lights summed: submission {} took {:.1} s, past the {:.0} s one submission with a method file may take (docs/design.md §5.13); measure it on a smaller image or with fewer lights",
                    at.submissions,
                    at.lights_done,
                    at.lights,
                    at.submissions + 1,
                    ms / 1e3,
                    METHOD_FILE_SUBMISSION_MS / 1e3
                ),
            )),
            _ => Ok(()),
        }
    }
}

impl Kept {
    /// The buffers of `kept` where they hold an image of `size` with `capacity` list
    /// entries, else new ones in their place.
    fn for_render(
        ctx: &GpuContext,
        kept: Option<Kept>,
        (width, height): (usize, usize),
        capacity: u64,
    ) -> Self {
        let fits =
            |t: &Target| (t.width, t.height) == (width, height) && t.tile_capacity >= capacity;
        match kept {
            Some(k) if fits(&k.target) => k,
            Some(k) => Self {
                target: Target::new(ctx, width, height, capacity),
                ..k
            },
            None => Self {
                lights: light_buffer(ctx, 1),
                params: ctx.device.create_buffer(&wgpu::BufferDescriptor {
                    label: Some("params"),
                    size: std::mem::size_of::<Params>() as u64,
                    usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                    mapped_at_creation: false,
                }),
                target: Target::new(ctx, width, height, capacity),
                timer: PassTimer::new(&ctx.device, &ctx.queue),
            },
        }
    }

    /// `lights` in its light buffer, grown where it does not hold them.
    fn with_lights(self, ctx: &GpuContext, lights: &[GpuLight]) -> Self {
        let kept = if std::mem::size_of_val(lights) as u64 <= self.lights.size() {
            self
        } else {
            Self {
                lights: light_buffer(ctx, lights.len().next_power_of_two()),
                ..self
            }
        };
        if !lights.is_empty() {
            ctx.queue
                .write_buffer(&kept.lights, 0, bytemuck::cast_slice(lights));
        }
        kept
    }
}

/// A light buffer of `count` lights (a binding cannot be empty: at least one).
fn light_buffer(ctx: &GpuContext, count: usize) -> wgpu::Buffer {
    ctx.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("lights"),
        size: (count.max(1) * std::mem::size_of::<GpuLight>()) as u64,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    })
}

/// The plane's and the binning's bind groups over `kept`'s buffers and the tables.
fn bind_groups(
    ctx: &GpuContext,
    kept: &Kept,
    begun: &Begun<'_>,
) -> (wgpu::BindGroup, wgpu::BindGroup) {
    let t = &kept.target;
    let plane = ctx.device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("plane"),
        layout: begun.layout,
        entries: &[
            plane::PARAMS.buffer(&kept.params),
            plane::LIGHTS.buffer(&kept.lights),
            plane::LUT.buffer(&begun.tables.buffer),
            plane::OUTPUT.texture(&t.view),
            plane::ACCUM_0.buffer(&t.sums[0]),
            plane::TILE_OFFSETS.buffer(&t.tile_offsets),
            plane::TILE_LIGHTS.buffer(&t.tile_lights),
            plane::PARTIALS.buffer(&t.partials),
            plane::ACCUM_1.buffer(&t.sums[1]),
            plane::ACCUM_2.buffer(&t.sums[2]),
        ],
    });
    let bin = ctx.device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("bin"),
        layout: &begun.binning.layout,
        entries: &[
            bin::PARAMS.buffer(&kept.params),
            bin::LIGHTS.buffer(&kept.lights),
            bin::TILE_OFFSETS.buffer(&t.tile_offsets),
            bin::TILE_LIGHTS.buffer(&t.tile_lights),
        ],
    });
    (plane, bin)
}
