//! `shaders/bin.wgsl`: tiled culling of ranged lights — per 16×16 tile, the lights whose range
//! reaches the tile's footprint on the plane, in light order; here its pipelines, the buffer
//! sizes and the passes.

use crate::gpu::GpuContext;
use crate::gpu::binding::{self, Binding, Kind, binding};
use crate::gpu::timing::{PassTimer, Slot};

/// The shader text (composed after scene.wgsl).
pub const SOURCE: &str = include_str!("../../shaders/bin.wgsl");

/// The binning shader's bindings (scene.wgsl's and its own; the tile lists are those the
/// plane shader reads, at the same numbers).
pub const PARAMS: Binding = binding(0, "params", Kind::Uniform);
pub const LIGHTS: Binding = binding(1, "lights", Kind::Read);
pub const TILE_OFFSETS: Binding = binding(5, "tile_offsets", Kind::ReadWrite);
pub const TILE_LIGHTS: Binding = binding(6, "tile_lights", Kind::ReadWrite);
pub const BINDINGS: [Binding; 4] = [PARAMS, LIGHTS, TILE_OFFSETS, TILE_LIGHTS];

/// The binning shader's pipelines (count, prefix sum, write) and their layout.
#[derive(Clone)]
pub struct Binning {
    pub layout: wgpu::BindGroupLayout,
    count: wgpu::ComputePipeline,
    scan: wgpu::ComputePipeline,
    write: wgpu::ComputePipeline,
}

/// Bytes of a list entry (a light's index).
pub const ENTRY_BYTES: u64 = 4;

/// The entries the tile lists may hold: every light in every tile, but no more than one
/// storage binding holds (beyond it the shader sums every light in every tile: the same
/// image, unculled).
pub fn capacity(ctx: &GpuContext, tiles: usize, lights: usize) -> u64 {
    let most = ctx
        .limits
        .max_storage_buffer_binding_size
        .min(ctx.limits.max_buffer_size)
        / ENTRY_BYTES;
    ((tiles * lights) as u64).clamp(1, most)
}

impl Binning {
    pub fn new(ctx: &GpuContext) -> Self {
        let device = &ctx.device;
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("bin.wgsl"),
            source: wgpu::ShaderSource::Wgsl(super::bin_module_source().into()),
        });
        let layout = binding::layout(device, "bin", &BINDINGS);
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("bin"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = |entry_point| {
            device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some(entry_point),
                layout: Some(&pipeline_layout),
                module: &module,
                entry_point: Some(entry_point),
                compilation_options: wgpu::PipelineCompilationOptions::default(),
                cache: None,
            })
        };
        Self {
            count: pipeline("bin_count"),
            scan: pipeline("bin_scan"),
            write: pipeline("bin_write"),
            layout,
        }
    }

    /// The whole binning in one compute pass: count, prefix sum, write, every tile (the
    /// uniforms' `bin_row` at 0); timed in `Slot::Bin`.
    pub fn encode_all(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        bind_group: &wgpu::BindGroup,
        (tiles_x, tiles_y): (u32, u32),
        timer: Option<&mut PassTimer>,
    ) {
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("bin"),
            timestamp_writes: timer.map(|t| t.writes(Slot::Bin)),
        });
        pass.set_bind_group(0, bind_group, &[]);
        pass.set_pipeline(&self.count);
        pass.dispatch_workgroups(tiles_x, tiles_y, 1);
        pass.set_pipeline(&self.scan);
        pass.dispatch_workgroups(1, 1, 1);
        pass.set_pipeline(&self.write);
        pass.dispatch_workgroups(tiles_x, tiles_y, 1);
    }

    /// A band of tile rows of one per-tile pass (its first row set in the uniforms'
    /// `bin_row`), after the prefix sum over all tiles for `ScanThenWrite` (the first write
    /// band); timed in `Slot::Bin`.
    pub fn encode_band(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        bind_group: &wgpu::BindGroup,
        (tiles_x, rows, pass): (u32, u32, BinPass),
        timer: Option<&mut PassTimer>,
    ) {
        let mut compute = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("bin"),
            timestamp_writes: timer.map(|t| t.writes(Slot::Bin)),
        });
        compute.set_bind_group(0, bind_group, &[]);
        if pass == BinPass::ScanThenWrite {
            compute.set_pipeline(&self.scan);
            compute.dispatch_workgroups(1, 1, 1);
        }
        compute.set_pipeline(match pass {
            BinPass::Count => &self.count,
            BinPass::Write | BinPass::ScanThenWrite => &self.write,
        });
        if rows > 0 {
            compute.dispatch_workgroups(tiles_x, rows, 1);
        }
    }
}

/// The per-tile passes of binning.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinPass {
    Count,
    /// The prefix sum over all tiles, then a write band (the first one).
    ScanThenWrite,
    Write,
}
