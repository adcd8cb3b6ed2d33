//! `shaders/plane.wgsl`: the compute shader that shades the plane into a storage texture;
//! here its buffer types (Pod, with the WGSL structs' explicit padding), its pipelines (one
//! per method combination, as override constants) and the dispatch and read-back. What it
//! renders is `render::RenderSettings`, as for the CPU reference.

use std::collections::HashMap;

use bytemuck::{Pod, Zeroable};
use glam::DVec3;

use crate::error::{Error, Result};
use crate::gpu::GpuContext;
use crate::gpu::limits;
use crate::gpu::timing::PassTimer;
use crate::ltc::Normalization;
use crate::ltc::lut::Lut;
use crate::metrics::relative_floor;
use crate::render::{Frame, FrameKind, LutFilter, Method, RenderSettings, View};
use crate::scene::{Light, Scene};

/// The shader text (composed after `ltc::SOURCE`).
pub const SOURCE: &str = include_str!("../../shaders/plane.wgsl");

/// `METHOD_*` of plane.wgsl.
pub fn method_constant(m: Method) -> u32 {
    match m {
        Method::Brdf => 0,
        Method::BrdfFast => 1,
        Method::Ltc => 2,
        Method::LtcFast => 3,
        Method::LtcF16 => 4,
    }
}

/// `VIEW_*` of plane.wgsl: method A alone, A | B split, or their difference.
const VIEW_SINGLE: u32 = 0;
const VIEW_SPLIT: u32 = 1;
const VIEW_DIFF: u32 = 2;

/// The pipeline's methods A and B and its `VIEW_*`: `View::B` is B shaded as the single A.
fn shader_view(s: &RenderSettings) -> (Method, Method, u32) {
    match s.view {
        View::A => (s.method_a, s.method_b, VIEW_SINGLE),
        View::B => (s.method_b, s.method_b, VIEW_SINGLE),
        View::Split => (s.method_a, s.method_b, VIEW_SPLIT),
        View::Diff => (s.method_a, s.method_b, VIEW_DIFF),
    }
}

/// The uniform block; must match `Params` in plane.wgsl (tests/gpu_layout.rs checks it
/// against naga's layout of the WGSL struct).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct Params {
    pub eye: [f32; 4],
    pub forward: [f32; 4],
    pub right: [f32; 4],
    pub up: [f32; 4],
    pub base_color: [f32; 4],
    pub alpha: f32,
    pub f0: f32,
    pub tan_half_fov: f32,
    pub aspect: f32,
    pub half_size: f32,
    pub divider: f32,
    pub rel_floor: f32,
    pub _pad0: f32,
    pub width: u32,
    pub height: u32,
    pub light_count: u32,
    pub lut_size: u32,
    pub clip: u32,
    pub normalization: u32,
    pub _pad1: u32,
    pub _pad2: u32,
}

/// One light in the storage buffer; must match `GpuLight` in plane.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct GpuLight {
    /// xyz position, w the range (≤ 0: infinite).
    pub position_range: [f32; 4],
    /// rgb colour × intensity.
    pub intensity: [f32; 4],
}

impl From<&Light> for GpuLight {
    fn from(l: &Light) -> Self {
        let p = l.position.map(|x| x as f32);
        let i = l.radiant_intensity().as_vec3();
        // A range below f32's smallest normal would round to 0, which encodes "infinite":
        // kept positive, it lights nothing, as on the CPU.
        let range = l.range.map_or(0.0, |r| (r as f32).max(f32::MIN_POSITIVE));
        Self {
            position_range: [p[0], p[1], p[2], range],
            intensity: [i.x, i.y, i.z, 0.0],
        }
    }
}

/// The uniforms of one render; `rel_floor` is the diff view's floor under B's luminance
/// (`metrics::relative_floor`).
pub fn params(
    settings: &RenderSettings,
    scene: &Scene,
    light_count: usize,
    lut_size: usize,
    rel_floor: f64,
) -> Params {
    let (eye, forward, right, up) = scene.camera_basis();
    let v4 = |v: DVec3| [v.x as f32, v.y as f32, v.z as f32, 0.0];
    let m = &scene.material;
    Params {
        eye: v4(eye),
        forward: v4(forward),
        right: v4(right),
        up: v4(up),
        base_color: v4(DVec3::from(m.base_color)),
        alpha: m.alpha as f32,
        f0: m.f0 as f32,
        tan_half_fov: (scene.camera.fov_y_degrees.to_radians() * 0.5).tan() as f32,
        aspect: (settings.width as f64 / settings.height as f64) as f32,
        half_size: scene.plane.half_size as f32,
        divider: settings.divider_column() as f32,
        rel_floor: (rel_floor as f32).max(f32::MIN_POSITIVE),
        width: settings.width as u32,
        height: settings.height as u32,
        light_count: light_count as u32,
        lut_size: lut_size as u32,
        clip: u32::from(settings.clipping.horizon)
            | (u32::from(settings.clipping.transformed) << 1),
        normalization: match settings.normalization {
            Normalization::Corrected => 0,
            Normalization::PaperLiteral => 1,
        },
        ..Params::default()
    }
}

/// Whether wgpu wraps the shader in its runtime bounds checks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShaderChecks {
    /// wgpu's defaults (every render but the benchmark).
    Checked,
    /// Without bounds checks: the benchmark path, as a fast engine would ship (5–17% faster
    /// on the reference GPU, `../shared/gpu/README.md`).
    Trusted,
}

/// Size of a workgroup side in plane.wgsl (`@workgroup_size(16, 16)`).
const WORKGROUP: u32 = 16;
const OUTPUT_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;
/// Bytes per texel of `OUTPUT_FORMAT`.
pub const TEXEL_BYTES: u32 = 16;

/// What a pipeline is specialized for (its override constants): methods A and B, the
/// `VIEW_*`, the LUT filter.
type PipelineKey = (Method, Method, u32, LutFilter);

fn pipeline_key(s: &RenderSettings) -> PipelineKey {
    let (a, b, view) = shader_view(s);
    (a, b, view, s.lut_filter)
}

/// The plane shader's module, layout, pipelines and LUT buffer.
pub struct PlaneRenderer {
    module: wgpu::ShaderModule,
    bind_group_layout: wgpu::BindGroupLayout,
    pipeline_layout: wgpu::PipelineLayout,
    pipelines: HashMap<PipelineKey, wgpu::ComputePipeline>,
    lut_buffer: wgpu::Buffer,
    lut_size: usize,
    timer: Option<PassTimer>,
    /// Whether the module has the f16 method (the device has `SHADER_F16`).
    f16: bool,
}

/// The resources of one render: uniforms, lights, the output texture and their bind group.
pub struct PreparedFrame {
    pub settings: RenderSettings,
    pub light_count: usize,
    /// The diff view's floor (`metrics::relative_floor`); set by `render`.
    pub rel_floor: f64,
    params: wgpu::Buffer,
    texture: wgpu::Texture,
    bind_group: wgpu::BindGroup,
}

impl PlaneRenderer {
    /// The module, layout and LUT buffer; refused where the LUT exceeds the device's storage.
    pub fn new(ctx: &GpuContext, lut: &Lut, checks: ShaderChecks) -> Result<Self> {
        let packed = super::ltc::pack_lut(lut);
        limits::check_lut_size(
            ctx,
            lut.size,
            std::mem::size_of_val(packed.as_slice()) as u64,
        )?;
        let device = &ctx.device;
        let desc = wgpu::ShaderModuleDescriptor {
            label: Some("plane.wgsl"),
            source: wgpu::ShaderSource::Wgsl(super::plane_module_source(ctx.has_f16()).into()),
        };
        let module = match checks {
            ShaderChecks::Checked => device.create_shader_module(desc),
            // SAFETY: the module is our own embedded WGSL, validated by naga in
            // tests/shaders.rs; every buffer index in it is bounded by construction (lights
            // by light_count ≤ the buffer's length, LUT cells clamped into the table, texture
            // writes guarded by the image size), which is what the runtime checks guard.
            #[allow(unsafe_code)]
            ShaderChecks::Trusted => unsafe {
                device.create_shader_module_trusted(desc, wgpu::ShaderRuntimeChecks::unchecked())
            },
        };
        let storage = |binding, read_only| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let bind_group_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("plane"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::COMPUTE,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
                storage(1, true),
                storage(2, true),
                wgpu::BindGroupLayoutEntry {
                    binding: 3,
                    visibility: wgpu::ShaderStages::COMPUTE,
                    ty: wgpu::BindingType::StorageTexture {
                        access: wgpu::StorageTextureAccess::WriteOnly,
                        format: OUTPUT_FORMAT,
                        view_dimension: wgpu::TextureViewDimension::D2,
                    },
                    count: None,
                },
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("plane"),
            bind_group_layouts: &[Some(&bind_group_layout)],
            immediate_size: 0,
        });
        let lut_buffer = wgpu::util::DeviceExt::create_buffer_init(
            device,
            &wgpu::util::BufferInitDescriptor {
                label: Some("ltc lut"),
                contents: bytemuck::cast_slice(&packed),
                usage: wgpu::BufferUsages::STORAGE,
            },
        );
        Ok(Self {
            module,
            bind_group_layout,
            pipeline_layout,
            pipelines: HashMap::new(),
            lut_buffer,
            lut_size: lut.size,
            timer: PassTimer::new(device, &ctx.queue),
            f16: ctx.has_f16(),
        })
    }

    /// Whether this device can run `method` (`LtcF16` needs `SHADER_F16`).
    pub fn supports(&self, method: Method) -> bool {
        method != Method::LtcF16 || self.f16
    }

    /// The pipeline of a method combination, compiled on first use.
    fn pipeline(&mut self, ctx: &GpuContext, key: PipelineKey) -> &wgpu::ComputePipeline {
        self.pipelines.entry(key).or_insert_with(|| {
            let (a, b, view, filter) = key;
            let constants = [
                ("METHOD_A", f64::from(method_constant(a))),
                ("METHOD_B", f64::from(method_constant(b))),
                ("VIEW", f64::from(view)),
                (
                    "LUT_NEAREST",
                    f64::from(u8::from(filter == LutFilter::Nearest)),
                ),
            ];
            ctx.device
                .create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                    label: Some("plane"),
                    layout: Some(&self.pipeline_layout),
                    module: &self.module,
                    entry_point: Some("shade"),
                    compilation_options: wgpu::PipelineCompilationOptions {
                        constants: &constants,
                        zero_initialize_workgroup_memory: false,
                    },
                    cache: None,
                })
        })
    }

    /// The most lights this device shades (`limits::max_lights`).
    pub fn max_lights(ctx: &GpuContext) -> usize {
        limits::max_lights(ctx, std::mem::size_of::<GpuLight>())
    }

    /// Refuses more lights than this device shades; `input` names the count's source.
    pub fn check_light_count(ctx: &GpuContext, input: &str, count: usize) -> Result<()> {
        limits::check_light_count(ctx, input, count, std::mem::size_of::<GpuLight>())
    }

    /// Refuses what this device cannot render, before any work: the lights, a method it has
    /// no shaders for, the image and its read-back.
    pub fn check(&self, ctx: &GpuContext, scene: &Scene, settings: &RenderSettings) -> Result<()> {
        Self::check_light_count(ctx, "scene", scene.lights.len())?;
        if let Some(m) = settings.methods().into_iter().find(|&m| !self.supports(m)) {
            return Err(Error::input(
                m.name(),
                format!("{} has no f16 shaders (SHADER_F16)", ctx.info.name),
            ));
        }
        limits::check_image_size(ctx, settings.width, settings.height, TEXEL_BYTES)
    }

    /// Uploads a frame's uniforms and lights and makes its output texture.
    pub fn prepare(
        &self,
        ctx: &GpuContext,
        scene: &Scene,
        settings: &RenderSettings,
    ) -> Result<PreparedFrame> {
        self.check(ctx, scene, settings)?;
        let device = &ctx.device;
        let init = |label, contents: &[u8], usage| {
            wgpu::util::DeviceExt::create_buffer_init(
                device,
                &wgpu::util::BufferInitDescriptor {
                    label: Some(label),
                    contents,
                    usage,
                },
            )
        };
        let params = params(settings, scene, scene.lights.len(), self.lut_size, 0.0);
        let params_buffer = init(
            "params",
            bytemuck::bytes_of(&params),
            wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        );
        // A binding cannot be empty: zero lights still get one (unread) element.
        let mut lights: Vec<GpuLight> = scene.lights.iter().map(GpuLight::from).collect();
        if lights.is_empty() {
            lights.push(GpuLight::default());
        }
        let lights_buffer = init(
            "lights",
            bytemuck::cast_slice(&lights),
            wgpu::BufferUsages::STORAGE,
        );
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("plane output"),
            size: wgpu::Extent3d {
                width: settings.width as u32,
                height: settings.height as u32,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: OUTPUT_FORMAT,
            usage: wgpu::TextureUsages::STORAGE_BINDING
                | wgpu::TextureUsages::COPY_SRC
                | wgpu::TextureUsages::COPY_DST
                | wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        });
        let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("plane"),
            layout: &self.bind_group_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: params_buffer.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: lights_buffer.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: self.lut_buffer.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 3,
                    resource: wgpu::BindingResource::TextureView(&view),
                },
            ],
        });
        Ok(PreparedFrame {
            settings: *settings,
            light_count: scene.lights.len(),
            rel_floor: 0.0,
            params: params_buffer,
            texture,
            bind_group,
        })
    }

    /// Changes what a prepared frame shows (method, view, clipping…) without new buffers.
    pub fn update(
        &self,
        ctx: &GpuContext,
        frame: &mut PreparedFrame,
        scene: &Scene,
        settings: &RenderSettings,
    ) {
        assert_eq!(
            (settings.width, settings.height),
            (frame.settings.width, frame.settings.height)
        );
        let params = params(
            settings,
            scene,
            frame.light_count,
            self.lut_size,
            frame.rel_floor,
        );
        ctx.queue
            .write_buffer(&frame.params, 0, bytemuck::bytes_of(&params));
        frame.settings = *settings;
    }

    /// Fills the output with NaN, so that a pixel the shader fails to write shows.
    pub fn poison(&self, ctx: &GpuContext, frame: &PreparedFrame) {
        let (w, h) = (frame.settings.width as u32, frame.settings.height as u32);
        let nan = vec![f32::NAN; (w * h * 4) as usize];
        ctx.queue.write_texture(
            frame.texture.as_image_copy(),
            bytemuck::cast_slice(&nan),
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(w * TEXEL_BYTES),
                rows_per_image: Some(h),
            },
            wgpu::Extent3d {
                width: w,
                height: h,
                depth_or_array_layers: 1,
            },
        );
    }

    /// Shades the frame once and waits; returns the GPU milliseconds (timestamp queries) or
    /// the wall-clock milliseconds of submit-to-done where the adapter has none.
    pub fn run(&mut self, ctx: &GpuContext, frame: &PreparedFrame) -> f64 {
        let settings = frame.settings;
        let key = pipeline_key(&settings);
        self.pipeline(ctx, key);
        let pipeline = &self.pipelines[&key];
        let mut encoder = ctx
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("plane"),
            });
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("plane"),
                timestamp_writes: self.timer.as_ref().map(PassTimer::writes),
            });
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, &frame.bind_group, &[]);
            pass.dispatch_workgroups(
                (settings.width as u32).div_ceil(WORKGROUP),
                (settings.height as u32).div_ceil(WORKGROUP),
                1,
            );
        }
        if let Some(t) = &self.timer {
            t.resolve(&mut encoder);
        }
        let start = std::time::Instant::now();
        ctx.queue.submit([encoder.finish()]);
        let _ = ctx.device.poll(wgpu::PollType::wait_indefinitely());
        let wall_ms = start.elapsed().as_secs_f64() * 1e3;
        match &self.timer {
            Some(t) => t.read_ms(&ctx.device),
            None => wall_ms,
        }
    }

    /// Reads the output back as a frame (alpha marks the plane's pixels).
    pub fn read(&self, ctx: &GpuContext, frame: &PreparedFrame) -> Frame {
        let (w, h) = (frame.settings.width as u32, frame.settings.height as u32);
        let row = (w * TEXEL_BYTES).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
        let buffer = ctx.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("plane readback"),
            size: u64::from(row) * u64::from(h),
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let mut encoder = ctx
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("readback"),
            });
        encoder.copy_texture_to_buffer(
            frame.texture.as_image_copy(),
            wgpu::TexelCopyBufferInfo {
                buffer: &buffer,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(row),
                    rows_per_image: Some(h),
                },
            },
            wgpu::Extent3d {
                width: w,
                height: h,
                depth_or_array_layers: 1,
            },
        );
        ctx.queue.submit([encoder.finish()]);
        let slice = buffer.slice(..);
        slice.map_async(wgpu::MapMode::Read, |_| {});
        let _ = ctx.device.poll(wgpu::PollType::wait_indefinitely());
        let data = slice.get_mapped_range().expect("mapped after the wait");
        let mut pixels = Vec::with_capacity((w * h) as usize);
        let mut on_plane = Vec::with_capacity((w * h) as usize);
        for y in 0..h as usize {
            let start = y * row as usize;
            let texels: &[[f32; 4]] =
                bytemuck::cast_slice(&data[start..start + (w * TEXEL_BYTES) as usize]);
            for t in texels {
                pixels.push(DVec3::new(
                    f64::from(t[0]),
                    f64::from(t[1]),
                    f64::from(t[2]),
                ));
                // NaN (a poisoned, unwritten texel) counts as on the plane, so it is seen.
                on_plane.push(t[3] >= 0.5 || t[3].is_nan());
            }
        }
        let s = frame.settings;
        Frame {
            width: s.width,
            height: s.height,
            kind: if s.view == View::Diff {
                FrameKind::RelativeDifference
            } else {
                FrameKind::Radiance
            },
            pixels,
            on_plane,
            divider: (s.view == View::Split).then(|| s.divider_column()),
        }
    }

    /// Prepares, poisons, shades and reads back one frame. The diff view first renders A
    /// and B alone for its floor (`metrics::relative_floor`), as the CPU does.
    pub fn render(
        &mut self,
        ctx: &GpuContext,
        scene: &Scene,
        settings: &RenderSettings,
    ) -> Result<(Frame, f64)> {
        let mut frame = self.prepare(ctx, scene, settings)?;
        if settings.view == View::Diff {
            let mut alone = |method| {
                self.update(ctx, &mut frame, scene, &settings.alone(method));
                self.run(ctx, &frame);
                self.read(ctx, &frame)
            };
            let (b, a) = (alone(settings.method_b), alone(settings.method_a));
            frame.rel_floor = relative_floor(&b, &a);
            self.update(ctx, &mut frame, scene, settings);
        }
        self.poison(ctx, &frame);
        let ms = self.run(ctx, &frame);
        Ok((self.read(ctx, &frame), ms))
    }
}
