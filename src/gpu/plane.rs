//! `shaders/plane.wgsl`: the compute shader that shades the plane; here its pipelines (one per
//! method combination, as override constants) and the renderer that keeps its resources —
//! lights, tables, uniforms and a `Target` per size — between renders, chunks and frames.
//! What it renders is `render::RenderSettings`, as for the CPU reference. One device: the
//! command line's own, or the lab's window's.

use std::collections::HashMap;
use std::ops::Range;

use crate::error::{Error, Result};
use crate::gpu::GpuContext;
use crate::gpu::bin::{self, BinPass, Binning};
use crate::gpu::limits;
use crate::gpu::ltc::{LutBuffer, horizon_constant};
use crate::gpu::scene::{GpuLight, Params, params};
use crate::gpu::target::{self, OUTPUT_FORMAT, PendingRead, Target};
use crate::gpu::timing::{PassTimer, Slot, SlotTimes};
use crate::ltc::lut::Lut;
use crate::ltc::remedy::HorizonRule;
use crate::render::{Frame, LutFilter, Method, RenderSettings, View};
use crate::scene::Scene;

/// The shader text (composed after `scene::SOURCE`).
pub const SOURCE: &str = include_str!("../../shaders/plane.wgsl");

pub use crate::gpu::target::TEXEL_BYTES;

/// `METHOD_*` of plane.wgsl.
pub fn method_constant(m: Method) -> u32 {
    match m {
        Method::Brdf => 0,
        Method::BrdfFast => 1,
        Method::Ltc => 2,
        Method::LtcFast => 3,
        Method::LtcF16 => 4,
        Method::LtcF16Pairs => 5,
    }
}

/// `VIEW_*` of plane.wgsl: method A alone, A | B split, or their difference.
const VIEW_SINGLE: u32 = 0;
const VIEW_SPLIT: u32 = 1;
const VIEW_DIFF: u32 = 2;

/// What a pipeline is specialized for (its override constants): methods A and B, the
/// `VIEW_*`, the LUT filter, whether B reads table B, and the horizon rule.
type PipelineKey = (Method, Method, u32, LutFilter, bool, HorizonRule);

/// The pipeline's methods and view: `View::B` is B shaded as the single A (with B's table).
fn pipeline_key(s: &RenderSettings) -> PipelineKey {
    let (a, b, view, table_b) = match s.view {
        View::A => (s.method_a, s.method_b, VIEW_SINGLE, false),
        // B alone, as A: its table must then be A's slot's, so the renderer swaps them.
        View::B => (s.method_b, s.method_b, VIEW_SINGLE, false),
        View::Split => (s.method_a, s.method_b, VIEW_SPLIT, s.b_reads_table_b),
        View::Diff => (s.method_a, s.method_b, VIEW_DIFF, s.b_reads_table_b),
    };
    (a, b, view, s.rules.filter, table_b, s.rules.horizon)
}

/// Whether wgpu wraps the shader in its runtime bounds checks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShaderChecks {
    /// wgpu's defaults (every render but the benchmark).
    Checked,
    /// Without bounds checks: the benchmark path, as a fast engine would ship (5–17% faster
    /// on the reference GPU, docs/design.md §4.5).
    Trusted,
}

/// The entry points of one specialization.
struct Pipelines {
    shade: wgpu::ComputePipeline,
    reduce: wgpu::ComputePipeline,
    floor: wgpu::ComputePipeline,
    resolve: wgpu::ComputePipeline,
}

/// Where the making of the tile lists is: the next band of tile rows to count, or to write.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum BinStage {
    Count(u32),
    Write(u32),
}

/// The GPU milliseconds of one frame's passes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FrameTimes {
    /// Binning (culled renders), timestamps; `None` when there was none.
    pub bin_ms: Option<f64>,
    /// Shading (timestamps), or submit-to-done wall clock of the whole frame without them.
    pub shade_ms: f64,
}

impl FrameTimes {
    pub fn total_ms(&self) -> f64 {
        self.shade_ms + self.bin_ms.unwrap_or(0.0)
    }

    fn from_slots(slots: SlotTimes, wall_ms: f64) -> Self {
        match slots[Slot::Shade as usize] {
            Some(shade_ms) => Self {
                bin_ms: slots[Slot::Bin as usize],
                shade_ms,
            },
            None => Self {
                bin_ms: None,
                shade_ms: wall_ms,
            },
        }
    }
}

/// The plane shader's module, layout and pipelines, and the resources of the current render.
pub struct PlaneRenderer {
    module: wgpu::ShaderModule,
    layout: wgpu::BindGroupLayout,
    pipeline_layout: wgpu::PipelineLayout,
    pipelines: HashMap<PipelineKey, Pipelines>,
    binning: Binning,
    tables: LutBuffer,
    /// The tables it holds, kept to pack them again with the `nl-fit` correction when a render
    /// first needs it (fitting it takes about a second: not for every render's set-up).
    luts: (Lut, Option<Lut>),
    lights: wgpu::Buffer,
    light_count: usize,
    /// Whether any light has a finite range (else culling would keep every light).
    any_ranged: bool,
    params_buffer: wgpu::Buffer,
    params: Params,
    settings: RenderSettings,
    target: Option<Target>,
    bind_groups: Option<(wgpu::BindGroup, wgpu::BindGroup)>,
    /// How far the current render's tile lists are made: the next band of tile rows to count
    /// or to write (`None`: made, or no culling).
    bin_stage: Option<BinStage>,
    timer: Option<PassTimer>,
    /// Whether the module has the f16 methods (the device has `SHADER_F16`).
    f16: bool,
}

impl PlaneRenderer {
    /// The module, layout and LUT buffer; refused where the LUT exceeds the device's storage.
    pub fn new(ctx: &GpuContext, lut: &Lut, checks: ShaderChecks) -> Result<Self> {
        let device = &ctx.device;
        let desc = wgpu::ShaderModuleDescriptor {
            label: Some("plane.wgsl"),
            source: wgpu::ShaderSource::Wgsl(super::plane_module_source(ctx.has_f16()).into()),
        };
        let module = match checks {
            ShaderChecks::Checked => device.create_shader_module(desc),
            // SAFETY: the module is our own embedded WGSL, validated by naga in
            // tests/shaders.rs; every buffer index in it is bounded by construction (lights
            // by light_count ≤ the buffer's length, tile lists by their total ≤ the capacity,
            // LUT cells clamped into the table, sums and texture writes guarded by the image
            // size), which is what the runtime checks guard.
            #[allow(unsafe_code)]
            ShaderChecks::Trusted => unsafe {
                device.create_shader_module_trusted(desc, wgpu::ShaderRuntimeChecks::unchecked())
            },
        };
        let layout = plane_layout(device);
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("plane"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let tables = LutBuffer::new(ctx, lut, None, false)?;
        Ok(Self {
            module,
            layout,
            pipeline_layout,
            pipelines: HashMap::new(),
            binning: Binning::new(ctx),
            tables,
            luts: (lut.clone(), None),
            lights: light_buffer(ctx, 1),
            light_count: 0,
            any_ranged: false,
            params_buffer: device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("params"),
                size: std::mem::size_of::<Params>() as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            }),
            params: Params::default(),
            settings: RenderSettings::single(1, 1, Method::Brdf),
            target: None,
            bind_groups: None,
            bin_stage: None,
            timer: PassTimer::new(device, &ctx.queue),
            f16: ctx.has_f16(),
        })
    }

    /// Shades with `a` as table A, and `b` as table B where `RenderSettings::table_b`, from
    /// now on (their buffer rewritten, pipelines kept). Both at once: a new table A must not
    /// lose table B.
    pub fn set_tables(&mut self, ctx: &GpuContext, a: &Lut, b: Option<&Lut>) -> Result<()> {
        self.tables = LutBuffer::new(ctx, a, b, self.tables.with_nl)?;
        self.luts = (a.clone(), b.cloned());
        self.bind_groups = None;
        Ok(())
    }

    /// Whether this device can run `method` (`LtcF16` and `LtcF16Pairs` need `SHADER_F16`).
    pub fn supports(&self, method: Method) -> bool {
        !method.needs_f16() || self.f16
    }

    /// The most lights this device shades (`limits::max_lights`).
    pub fn max_lights(ctx: &GpuContext) -> usize {
        limits::max_lights(ctx, std::mem::size_of::<GpuLight>())
    }

    /// Refuses more lights than this device shades.
    pub fn check_light_count(ctx: &GpuContext, count: usize) -> limits::Result<()> {
        limits::check_light_count(ctx, count, std::mem::size_of::<GpuLight>())
    }

    /// Refuses what this device cannot render, before any work: the lights, a method it has
    /// no shaders for, a second table it was not given, the image.
    pub fn check(&self, ctx: &GpuContext, scene: &Scene, settings: &RenderSettings) -> Result<()> {
        Self::check_light_count(ctx, scene.lights.len()).map_err(|e| e.named("scene"))?;
        if let Some(m) = settings.methods().into_iter().find(|&m| !self.supports(m)) {
            return Err(Error::input(
                m.name(),
                format!("{} has no f16 shaders (SHADER_F16)", ctx.info.name),
            ));
        }
        if settings.b_reads_table_b && self.tables.b.is_none() {
            return Err(Error::input("table B", "no second table was given"));
        }
        let f16 = settings.methods().into_iter().find(|m| m.needs_f16());
        if let Some(m) = f16.filter(|_| settings.rules.horizon != HorizonRule::Eq30) {
            return Err(Error::input(
                "--horizon",
                format!(
                    "{} shades with eq30's rules only (docs/design.md §4.7)",
                    m.name()
                ),
            ));
        }
        Ok(target::check_size(ctx, settings.width, settings.height)?)
    }

    /// Starts a render of `scene`: lights, uniforms and the target of its size, made or kept;
    /// the tile lists are made with its first chunk. Nothing is summed yet.
    pub fn begin(
        &mut self,
        ctx: &GpuContext,
        scene: &Scene,
        settings: &RenderSettings,
    ) -> Result<()> {
        self.check(ctx, scene, settings)?;
        if settings.rules.horizon == HorizonRule::NlFit && !self.tables.with_nl {
            let (a, b) = &self.luts;
            self.tables = LutBuffer::new(ctx, a, b.as_ref(), true)?;
            self.bind_groups = None;
        }
        self.upload_lights(ctx, scene);
        let cull = settings.cull && self.any_ranged;
        let (tiles_x, tiles_y) = crate::gpu::scene::tiles(settings.width, settings.height);
        let capacity = if cull {
            bin::capacity(ctx, tiles_x * tiles_y, self.light_count)
        } else {
            1
        };
        let fits = self.target.as_ref().is_some_and(|t| {
            (t.width, t.height) == (settings.width, settings.height) && t.tile_capacity >= capacity
        });
        if !fits {
            self.target = Some(Target::new(ctx, settings.width, settings.height, capacity));
            self.bind_groups = None;
        }
        let target = self.target.as_ref().expect("made above");
        self.params = params(settings, scene);
        self.params.cull = u32::from(cull);
        self.params.tile_capacity = target.tile_capacity.min(u64::from(u32::MAX)) as u32;
        self.params.lut_size = self.tables.size_a as u32;
        let (size_b, base_b) = self.tables.b.unwrap_or((self.tables.size_a, 0));
        self.params.lut_size_b = size_b as u32;
        self.params.lut_base_b = base_b;
        if settings.view == View::B && settings.b_reads_table_b {
            // B alone is shaded as the single method A: with B's table in A's slot.
            self.params.lut_size = size_b as u32;
            self.params.lut_base = base_b;
        }
        self.settings = *settings;
        self.bin_stage = cull.then_some(BinStage::Count(0));
        if self.bind_groups.is_none() {
            self.bind_groups = Some(self.make_bind_groups(ctx));
        }
        Ok(())
    }

    /// The lights of `scene` into the light buffer (grown as needed).
    fn upload_lights(&mut self, ctx: &GpuContext, scene: &Scene) {
        let lights: Vec<GpuLight> = scene.lights.iter().map(GpuLight::from).collect();
        let bytes = std::mem::size_of_val(lights.as_slice()) as u64;
        if bytes > self.lights.size() {
            self.lights = light_buffer(ctx, lights.len().next_power_of_two());
            self.bind_groups = None;
        }
        if !lights.is_empty() {
            ctx.queue
                .write_buffer(&self.lights, 0, bytemuck::cast_slice(&lights));
        }
        self.light_count = lights.len();
        self.any_ranged = scene.lights.iter().any(|l| l.range.is_some());
    }

    /// The plane and binning bind groups of the current target, tables and lights.
    fn make_bind_groups(&self, ctx: &GpuContext) -> (wgpu::BindGroup, wgpu::BindGroup) {
        let t = self.made();
        fn buffer(binding: u32, buffer: &wgpu::Buffer) -> wgpu::BindGroupEntry<'_> {
            wgpu::BindGroupEntry {
                binding,
                resource: buffer.as_entire_binding(),
            }
        }
        let plane = ctx.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("plane"),
            layout: &self.layout,
            entries: &[
                buffer(0, &self.params_buffer),
                buffer(1, &self.lights),
                buffer(2, &self.tables.buffer),
                wgpu::BindGroupEntry {
                    binding: 3,
                    resource: wgpu::BindingResource::TextureView(&t.view),
                },
                buffer(4, &t.sums[0]),
                buffer(5, &t.tile_offsets),
                buffer(6, &t.tile_lights),
                buffer(7, &t.partials),
                buffer(8, &t.sums[1]),
                buffer(9, &t.sums[2]),
            ],
        });
        let bin = ctx.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("bin"),
            layout: &self.binning.layout,
            entries: &[
                buffer(0, &self.params_buffer),
                buffer(1, &self.lights),
                buffer(5, &t.tile_offsets),
                buffer(6, &t.tile_lights),
            ],
        });
        (plane, bin)
    }

    /// The pipelines of a specialization, compiled on first use.
    fn pipelines(&mut self, ctx: &GpuContext, key: PipelineKey) -> &Pipelines {
        let (module, layout) = (&self.module, &self.pipeline_layout);
        self.pipelines.entry(key).or_insert_with(|| {
            let (a, b, view, filter, table_b, horizon) = key;
            let constants = [
                ("METHOD_A", f64::from(method_constant(a))),
                ("METHOD_B", f64::from(method_constant(b))),
                ("VIEW", f64::from(view)),
                (
                    "LUT_NEAREST",
                    f64::from(u8::from(filter == LutFilter::Nearest)),
                ),
                ("TABLE_B", f64::from(u8::from(table_b))),
                ("HORIZON", f64::from(horizon_constant(horizon))),
            ];
            let pipeline = |entry_point| {
                ctx.device
                    .create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                        label: Some(entry_point),
                        layout: Some(layout),
                        module,
                        entry_point: Some(entry_point),
                        compilation_options: wgpu::PipelineCompilationOptions {
                            constants: &constants,
                            zero_initialize_workgroup_memory: false,
                        },
                        cache: None,
                    })
            };
            Pipelines {
                shade: pipeline("shade"),
                reduce: pipeline("reduce"),
                floor: pipeline("floor_of_means"),
                resolve: pipeline("resolve"),
            }
        })
    }

    /// The number of entries a full render sums per pixel (every light, unculled).
    pub fn light_count(&self) -> usize {
        self.light_count
    }

    /// Sums entries `range` of every pixel's list into the kept sums (from zero where the
    /// range starts at 0), then resolves the image; one submission. The first chunk of a
    /// culled render makes the tile lists first. Returns the submission, for waiting.
    pub fn step(&mut self, ctx: &GpuContext, range: Range<usize>) -> wgpu::SubmissionIndex {
        self.params.light_start = range.start as u32;
        self.params.light_end = range.end as u32;
        self.params.bin_row = 0;
        ctx.queue
            .write_buffer(&self.params_buffer, 0, bytemuck::bytes_of(&self.params));
        let key = pipeline_key(&self.settings);
        self.pipelines(ctx, key);
        let pipelines = &self.pipelines[&key];
        let (plane_group, bin_group) = self.bind_groups.as_ref().expect("begin made them");
        let target = self.target.as_ref().expect("begin made it");
        let mut encoder = ctx
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("plane"),
            });
        let mut timer = self.timer.as_mut().filter(|t| t.can_resolve());
        let timed = timer.is_some();
        if let Some(t) = &mut timer {
            t.clear();
        }
        let (tiles_x, tiles_y) = (target.tiles.0 as u32, target.tiles.1 as u32);
        if self.bin_stage.take().is_some() {
            // Lists not (all) made band by band: made whole here, in one pass from row 0.
            self.binning.encode_all(
                &mut encoder,
                bin_group,
                (tiles_x, tiles_y),
                timer.as_deref_mut(),
            );
        }
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("shade"),
                timestamp_writes: timer.as_deref_mut().map(|t| t.writes(Slot::Shade)),
            });
            pass.set_bind_group(0, plane_group, &[]);
            pass.set_pipeline(&pipelines.shade);
            pass.dispatch_workgroups(tiles_x, tiles_y, 1);
        }
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("resolve"),
                timestamp_writes: None,
            });
            pass.set_bind_group(0, plane_group, &[]);
            if self.settings.view == View::Diff {
                pass.set_pipeline(&pipelines.reduce);
                pass.dispatch_workgroups(tiles_x, tiles_y, 1);
                pass.set_pipeline(&pipelines.floor);
                pass.dispatch_workgroups(1, 1, 1);
            }
            pass.set_pipeline(&pipelines.resolve);
            pass.dispatch_workgroups(tiles_x, tiles_y, 1);
        }
        if let Some(t) = timer {
            t.resolve(&mut encoder);
        }
        let index = ctx.queue.submit([encoder.finish()]);
        if timed && let Some(t) = &mut self.timer {
            t.request();
        }
        index
    }

    /// How far the tile lists are made, 0 to 1; `None` when they are (or there are none).
    pub fn binning_progress(&self) -> Option<f32> {
        let rows = self.target.as_ref()?.tiles.1 as f32;
        self.bin_stage.map(|stage| match stage {
            BinStage::Count(r) => r as f32 / (2.0 * rows),
            BinStage::Write(r) => (rows + r as f32) / (2.0 * rows),
        })
    }

    /// Makes the next `rows` tile rows of the tile lists (counting them, then writing them):
    /// binning spread over frames. One submission, timed in `Slot::Bin`. Does nothing when
    /// the lists are made.
    pub fn bin_step(&mut self, ctx: &GpuContext, rows: usize) {
        let Some(stage) = self.bin_stage else {
            return;
        };
        let target = self.target.as_ref().expect("begin made it");
        let (tiles_x, tiles_y) = (target.tiles.0 as u32, target.tiles.1 as u32);
        let (first, pass) = match stage {
            BinStage::Count(r) => (r, BinPass::Count),
            BinStage::Write(0) => (0, BinPass::ScanThenWrite),
            BinStage::Write(r) => (r, BinPass::Write),
        };
        let end = (first + rows.max(1) as u32).min(tiles_y);
        self.params.bin_row = first;
        ctx.queue
            .write_buffer(&self.params_buffer, 0, bytemuck::bytes_of(&self.params));
        let (_, bin_group) = self.bind_groups.as_ref().expect("begin made them");
        let mut encoder = ctx
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("bin band"),
            });
        let mut timer = self.timer.as_mut().filter(|t| t.can_resolve());
        let timed = timer.is_some();
        if let Some(t) = &mut timer {
            t.clear();
        }
        self.binning.encode_band(
            &mut encoder,
            bin_group,
            tiles_x,
            end - first,
            pass,
            timer.as_deref_mut(),
        );
        if let Some(t) = timer {
            t.resolve(&mut encoder);
        }
        ctx.queue.submit([encoder.finish()]);
        if timed && let Some(t) = &mut self.timer {
            t.request();
        }
        self.bin_stage = match (pass, end == tiles_y) {
            (BinPass::Count, true) => Some(BinStage::Write(0)),
            (BinPass::Count, false) => Some(BinStage::Count(end)),
            (_, true) => None,
            (_, false) => Some(BinStage::Write(end)),
        };
    }

    /// Whether the steps are timed (the device has timestamp queries).
    pub fn timed(&self) -> bool {
        self.timer.is_some()
    }

    /// Whether the last step's GPU times are on their way (else `try_times` has none coming).
    pub fn times_pending(&self) -> bool {
        self.timer.as_ref().is_some_and(PassTimer::pending)
    }

    /// The last step's GPU times if they have arrived (poll the device meanwhile); never
    /// waits.
    pub fn try_times(&mut self) -> Option<FrameTimes> {
        let slots = self.timer.as_mut()?.try_read()?;
        Some(FrameTimes {
            bin_ms: slots[Slot::Bin as usize],
            shade_ms: slots[Slot::Shade as usize].unwrap_or(0.0),
        })
    }

    /// Renders the current render whole (one chunk of every light) and waits: the GPU times
    /// (timestamp queries), or the wall clock of submit-to-done where the adapter has none.
    pub fn run(&mut self, ctx: &GpuContext) -> FrameTimes {
        if self.params.cull != 0 {
            self.bin_stage = Some(BinStage::Count(0));
        }
        // A read-back still in flight is taken first, so that this frame's timestamps land.
        if let Some(t) = &mut self.timer {
            let _ = t.read_ms(&ctx.device);
        }
        let start = web_time::Instant::now();
        self.step(ctx, 0..self.light_count);
        let _ = ctx.device.poll(wgpu::PollType::wait_indefinitely());
        let wall_ms = start.elapsed().as_secs_f64() * 1e3;
        let slots = self
            .timer
            .as_mut()
            .map_or([None; 2], |t| t.read_ms(&ctx.device));
        FrameTimes::from_slots(slots, wall_ms)
    }

    /// The current render's target (`begin` makes it).
    fn made(&self) -> &Target {
        self.target.as_ref().expect("begin made the target")
    }

    /// The output of the current render, read back.
    pub fn read(&self, ctx: &GpuContext) -> Frame {
        self.made().read(ctx, &self.settings)
    }

    /// Starts reading the image back without waiting (the browser cannot wait):
    /// `PendingRead::try_take` gives its texels once the GPU is done, and `frame_of` the
    /// frame that `read` gives.
    pub fn start_read(&self, ctx: &GpuContext) -> PendingRead {
        self.made().start_read(ctx)
    }

    /// The frame of texels that `start_read` fetched.
    pub fn frame_of(&self, texels: &[u8]) -> Frame {
        self.made().frame_of(texels, &self.settings)
    }

    /// The entries of the current render's tile lists, read back (blocks): how much culling
    /// kept of `tiles × lights`. `None` where the render is not culled or not yet binned.
    pub fn tile_entries(&self, ctx: &GpuContext) -> Option<(u64, u64)> {
        let t = self.target.as_ref()?;
        (self.params.cull != 0 && self.bin_stage.is_none()).then(|| {
            let all = (t.tiles.0 * t.tiles.1 * self.light_count) as u64;
            (t.tile_entries(ctx), all)
        })
    }

    /// The output texture (for the lab to show without a read-back).
    pub fn output(&self) -> Option<&wgpu::TextureView> {
        self.target.as_ref().map(|t| &t.view)
    }

    /// Begins, poisons, renders whole and reads back one frame: the frame and its GPU ms.
    pub fn render(
        &mut self,
        ctx: &GpuContext,
        scene: &Scene,
        settings: &RenderSettings,
    ) -> Result<(Frame, f64)> {
        self.begin(ctx, scene, settings)?;
        self.target.as_ref().expect("made").poison(ctx);
        let times = self.run(ctx);
        Ok((self.read(ctx), times.total_ms()))
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

/// The plane shader's bindings (src/gpu/plane.rs, scene.wgsl, ltc.wgsl, plane.wgsl).
fn plane_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    use super::binding::{compute, storage, uniform, written_texture};
    let read = |binding| compute(binding, storage(true));
    let write = |binding| compute(binding, storage(false));
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("plane"),
        entries: &[
            compute(0, uniform()),
            read(1),
            read(2),
            compute(3, written_texture(OUTPUT_FORMAT)),
            write(4),
            read(5),
            read(6),
            write(7),
            write(8),
            write(9),
        ],
    })
}
