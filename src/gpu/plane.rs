//! `shaders/plane.wgsl`: the compute shader that shades the plane into a storage texture;
//! here its buffer types (Pod, with the WGSL structs' explicit padding), its pipelines (one
//! per method combination, as override constants) and the dispatch and read-back.

use std::collections::HashMap;

use bytemuck::{Pod, Zeroable};
use glam::DVec3;

use crate::cpu::{Frame, FrameKind, LutFilter};
use crate::error::InputError;
use crate::gpu::GpuContext;
use crate::gpu::timing::PassTimer;
use crate::ltc::lut::Lut;
use crate::ltc::{Clipping, Normalization};
use crate::scene::{Light, Scene};

/// The shader text (composed after `ltc::SOURCE`).
pub const SOURCE: &str = include_str!("../../shaders/plane.wgsl");

/// How one pixel's lights are summed (`METHOD_*` in plane.wgsl).
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, Hash, clap::ValueEnum, serde::Serialize, serde::Deserialize,
)]
pub enum GpuMethod {
    /// The exact BRDF as DESIGN §1 writes it.
    Brdf = 0,
    /// The exact BRDF with Filament's `V_SmithGGXCorrelated` and no root for `E`.
    BrdfFast = 1,
    /// The paper's LTC: normalize `l`, rotate into the frame, `M⁻¹ l` per lobe.
    Ltc = 2,
    /// LTC with the rotation folded into `M⁻¹` per pixel, the unnormalized light vector and
    /// eq. 27's factoring: one square root per light.
    LtcFast = 3,
    /// `LtcFast` with `M⁻¹l` and `D` in f16 (devices with `SHADER_F16` only).
    LtcF16 = 4,
}

impl GpuMethod {
    pub const ALL: [Self; 4] = [Self::Brdf, Self::BrdfFast, Self::Ltc, Self::LtcFast];

    pub fn name(self) -> &'static str {
        match self {
            Self::Brdf => "brdf",
            Self::BrdfFast => "brdf-fast",
            Self::Ltc => "ltc",
            Self::LtcFast => "ltc-fast",
            Self::LtcF16 => "ltc-f16",
        }
    }

    pub fn is_ltc(self) -> bool {
        matches!(self, Self::Ltc | Self::LtcFast | Self::LtcF16)
    }
}

/// What a pixel shows (`VIEW_*` in plane.wgsl).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum GpuView {
    /// Method A's radiance.
    Single = 0,
    /// A left of the divider, B right of it.
    Split = 1,
    /// `|A − B| / max(B, floor)` on luminance.
    Diff = 2,
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
        Self {
            position_range: [p[0], p[1], p[2], l.range.unwrap_or(0.0) as f32],
            intensity: [i.x, i.y, i.z, 0.0],
        }
    }
}

/// What to render, beyond the scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlaneSettings {
    pub width: usize,
    pub height: usize,
    pub method_a: GpuMethod,
    pub method_b: GpuMethod,
    pub view: GpuView,
    pub clipping: Clipping,
    pub normalization: Normalization,
    /// Where the split view changes from A to B, as a fraction of the width.
    pub divider: f64,
    /// The diff view's floor under B's luminance (`metrics::relative_floor`).
    pub rel_floor: f64,
    /// How the LTC table is read (`LUT_NEAREST` in ltc.wgsl).
    pub lut_filter: LutFilter,
}

impl PlaneSettings {
    pub fn single(width: usize, height: usize, method: GpuMethod) -> Self {
        Self {
            width,
            height,
            method_a: method,
            method_b: GpuMethod::Brdf,
            view: GpuView::Single,
            clipping: Clipping::BOTH,
            normalization: Normalization::Corrected,
            divider: 0.5,
            rel_floor: f64::MIN_POSITIVE,
            lut_filter: LutFilter::Bilinear,
        }
    }

    pub fn divider_column(&self) -> usize {
        ((self.divider.clamp(0.0, 1.0) * self.width as f64).round() as usize).min(self.width)
    }

    pub fn params(&self, scene: &Scene, light_count: usize, lut_size: usize) -> Params {
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
            aspect: (self.width as f64 / self.height as f64) as f32,
            half_size: scene.plane.half_size as f32,
            divider: self.divider_column() as f32,
            rel_floor: (self.rel_floor as f32).max(f32::MIN_POSITIVE),
            width: self.width as u32,
            height: self.height as u32,
            light_count: light_count as u32,
            lut_size: lut_size as u32,
            clip: u32::from(self.clipping.horizon) | (u32::from(self.clipping.transformed) << 1),
            normalization: match self.normalization {
                Normalization::Corrected => 0,
                Normalization::PaperLiteral => 1,
            },
            ..Params::default()
        }
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
const TEXEL_BYTES: u32 = 16;

/// What a pipeline is specialized for (its override constants).
type PipelineKey = (GpuMethod, GpuMethod, GpuView, LutFilter);

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
    pub settings: PlaneSettings,
    pub light_count: usize,
    params: wgpu::Buffer,
    texture: wgpu::Texture,
    bind_group: wgpu::BindGroup,
}

impl PlaneRenderer {
    pub fn new(ctx: &GpuContext, lut: &Lut, checks: ShaderChecks) -> Self {
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
        let packed = super::ltc::pack_lut(lut);
        let lut_buffer = wgpu::util::DeviceExt::create_buffer_init(
            device,
            &wgpu::util::BufferInitDescriptor {
                label: Some("ltc lut"),
                contents: bytemuck::cast_slice(&packed),
                usage: wgpu::BufferUsages::STORAGE,
            },
        );
        Self {
            module,
            bind_group_layout,
            pipeline_layout,
            pipelines: HashMap::new(),
            lut_buffer,
            lut_size: lut.size,
            timer: PassTimer::new(device, &ctx.queue),
            f16: ctx.has_f16(),
        }
    }

    /// Whether this device can run `method` (`LtcF16` needs `SHADER_F16`).
    pub fn supports(&self, method: GpuMethod) -> bool {
        method != GpuMethod::LtcF16 || self.f16
    }

    /// The pipeline of a method combination, compiled on first use.
    fn pipeline(&mut self, ctx: &GpuContext, s: &PlaneSettings) -> &wgpu::ComputePipeline {
        let key = (s.method_a, s.method_b, s.view, s.lut_filter);
        self.pipelines.entry(key).or_insert_with(|| {
            let constants = [
                ("METHOD_A", f64::from(s.method_a as u32)),
                ("METHOD_B", f64::from(s.method_b as u32)),
                ("VIEW", f64::from(s.view as u32)),
                (
                    "LUT_NEAREST",
                    f64::from(u8::from(s.lut_filter == LutFilter::Nearest)),
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

    /// The most lights one storage binding holds on this device.
    pub fn buffer_max_lights(ctx: &GpuContext) -> usize {
        let bytes = ctx
            .limits
            .max_storage_buffer_binding_size
            .min(ctx.limits.max_buffer_size);
        (bytes / std::mem::size_of::<GpuLight>() as u64) as usize
    }

    /// The most lights this device shades: the buffer's capacity, or less where the driver
    /// ends shader loops early (`GpuContext::light_loop_limit`).
    pub fn max_lights(ctx: &GpuContext) -> usize {
        let buffer = Self::buffer_max_lights(ctx);
        ctx.light_loop_limit().map_or(buffer, |l| l.min(buffer))
    }

    /// Refuses more lights than one storage binding holds or the driver's loops can sum.
    pub fn check_light_count(ctx: &GpuContext, count: usize) -> Result<(), InputError> {
        let buffer = Self::buffer_max_lights(ctx);
        if count > buffer {
            return Err(InputError::new(
                "scene",
                format!(
                    "{count} lights do not fit in one GPU storage buffer on {} (at most {buffer} of {} bytes)",
                    ctx.info.name,
                    std::mem::size_of::<GpuLight>()
                ),
            ));
        }
        if let Some(limit) = ctx.light_loop_limit().filter(|&l| count > l) {
            return Err(InputError::new(
                "scene",
                format!(
                    "{count} lights do not fit in one shader invocation on {}: its driver ends shader loops after {limit} lights (use --cpu, or a hardware GPU)",
                    ctx.info.name
                ),
            ));
        }
        Ok(())
    }

    /// Uploads a frame's uniforms and lights and makes its output texture.
    pub fn prepare(
        &self,
        ctx: &GpuContext,
        scene: &Scene,
        settings: &PlaneSettings,
    ) -> Result<PreparedFrame, InputError> {
        Self::check_light_count(ctx, scene.lights.len())?;
        for m in [settings.method_a, settings.method_b] {
            if !self.supports(m) {
                return Err(InputError::new(
                    m.name(),
                    format!("{} has no f16 shaders (SHADER_F16)", ctx.info.name),
                ));
            }
        }
        let max_side = ctx.limits.max_texture_dimension_2d as usize;
        if settings.width > max_side || settings.height > max_side {
            return Err(InputError::new(
                "--size",
                format!(
                    "{}×{} exceeds the GPU's largest texture side, {max_side}",
                    settings.width, settings.height
                ),
            ));
        }
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
        let params = settings.params(scene, scene.lights.len(), self.lut_size);
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
        settings: &PlaneSettings,
    ) {
        assert_eq!(
            (settings.width, settings.height),
            (frame.settings.width, frame.settings.height)
        );
        let params = settings.params(scene, frame.light_count, self.lut_size);
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
        self.pipeline(ctx, &settings);
        let pipeline = &self.pipelines[&(
            settings.method_a,
            settings.method_b,
            settings.view,
            settings.lut_filter,
        )];
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
            kind: if s.view == GpuView::Diff {
                FrameKind::RelativeDifference
            } else {
                FrameKind::Radiance
            },
            pixels,
            on_plane,
            divider: (s.view == GpuView::Split).then(|| s.divider_column()),
        }
    }

    /// Prepares, poisons, shades and reads back one frame.
    pub fn render(
        &mut self,
        ctx: &GpuContext,
        scene: &Scene,
        settings: &PlaneSettings,
    ) -> Result<(Frame, f64), InputError> {
        let frame = self.prepare(ctx, scene, settings)?;
        self.poison(ctx, &frame);
        let ms = self.run(ctx, &frame);
        Ok((self.read(ctx, &frame), ms))
    }
}
