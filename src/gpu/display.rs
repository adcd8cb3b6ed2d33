//! `shaders/display.wgsl`: the plane's image for the window — tone-mapped (or in false
//! colour) into the PNG's 8-bit values — so that the lab shows the GPU's image without
//! reading it back. Here its pipeline and the texture, kept while the size holds.

use bytemuck::{Pod, Zeroable};

use crate::gpu::GpuContext;
use crate::gpu::binding::{self, Binding, Kind, binding};
use crate::render::FrameKind;

/// The shader text (composed alone).
pub const SOURCE: &str = include_str!("../../shaders/display.wgsl");

/// The uniforms; must match `Display` in display.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct Display {
    pub exposure: f32,
    pub kind: u32,
    pub _pad0: u32,
    pub _pad1: u32,
}

/// The texture written: the PNG's 8-bit sRGB-encoded values (egui draws texture colours as
/// gamma-space values, so it shows them as a PNG viewer does).
const STORED: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// The display shader's bindings.
pub const DISPLAY: Binding = binding(0, "display", Kind::Uniform);
pub const IMAGE: Binding = binding(1, "image", Kind::Texture);
pub const SHOWN: Binding = binding(2, "shown", Kind::WrittenTexture(STORED));
pub const BINDINGS: [Binding; 3] = [DISPLAY, IMAGE, SHOWN];

/// The display pass and its texture.
pub struct DisplayPass {
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
    uniforms: wgpu::Buffer,
    texture: Option<(wgpu::Texture, wgpu::TextureView, (u32, u32))>,
}

impl DisplayPass {
    pub fn new(ctx: &GpuContext) -> Self {
        let device = &ctx.device;
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("display.wgsl"),
            source: wgpu::ShaderSource::Wgsl(SOURCE.into()),
        });
        let layout = binding::layout(device, "display", &BINDINGS);
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("display"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("display"),
            layout: Some(&pipeline_layout),
            module: &module,
            entry_point: Some("show"),
            compilation_options: wgpu::PipelineCompilationOptions::default(),
            cache: None,
        });
        Self {
            pipeline,
            layout,
            uniforms: device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("display"),
                size: std::mem::size_of::<Display>() as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            }),
            texture: None,
        }
    }

    /// The texture to show, made for `size` if it is not that size yet;
    /// `true` when it was made anew (the window must take the new view).
    pub fn target(&mut self, ctx: &GpuContext, size: (u32, u32)) -> (&wgpu::TextureView, bool) {
        let kept = self.texture.take().filter(|t| t.2 == size);
        let fresh = kept.is_none();
        let (_, view, _) = self.texture.insert(kept.unwrap_or_else(|| {
            let texture = ctx.device.create_texture(&wgpu::TextureDescriptor {
                label: Some("plane display"),
                size: wgpu::Extent3d {
                    width: size.0,
                    height: size.1,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: STORED,
                usage: wgpu::TextureUsages::STORAGE_BINDING
                    | wgpu::TextureUsages::TEXTURE_BINDING
                    | wgpu::TextureUsages::COPY_SRC,
                view_formats: &[],
            });
            let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
            (texture, view, size)
        }));
        (view, fresh)
    }

    /// Records the pass from the renderer's `image` into the display texture (`target`
    /// first).
    pub fn encode(
        &self,
        ctx: &GpuContext,
        encoder: &mut wgpu::CommandEncoder,
        image: &wgpu::TextureView,
        kind: FrameKind,
        exposure: f64,
    ) {
        let Some((texture, _, (w, h))) = &self.texture else {
            return;
        };
        let uniforms = Display {
            exposure: exposure as f32,
            kind: u32::from(kind == FrameKind::RelativeDifference),
            ..Display::default()
        };
        ctx.queue
            .write_buffer(&self.uniforms, 0, bytemuck::bytes_of(&uniforms));
        let stored = texture.create_view(&wgpu::TextureViewDescriptor::default());
        let bind_group = ctx.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("display"),
            layout: &self.layout,
            entries: &[
                DISPLAY.buffer(&self.uniforms),
                IMAGE.texture(image),
                SHOWN.texture(&stored),
            ],
        });
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("display"),
            timestamp_writes: None,
        });
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &bind_group, &[]);
        pass.dispatch_workgroups(w.div_ceil(16), h.div_ceil(16), 1);
    }
}
