//! What a render of one size keeps on the GPU between chunks and frames: the output texture,
//! the per-pixel sums, the tile lists and the difference view's partial sums; and the image
//! read back as a `Frame`.

use glam::DVec3;

use crate::error::{Error, Result};
use crate::gpu::GpuContext;
use crate::gpu::limits;
use crate::gpu::scene::tiles;
use crate::render::{Frame, FrameKind, RenderSettings, View};

/// The image format: linear radiance (or the relative difference) in rgb, alpha 1 on the
/// plane.
pub const OUTPUT_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;
/// Bytes per texel of `OUTPUT_FORMAT`.
pub const TEXEL_BYTES: u32 = 16;
/// Bytes per pixel of each of the three sum buffers (one vec4).
pub const SUM_BYTES: u64 = 16;

/// The resources of one image size.
pub struct Target {
    pub width: usize,
    pub height: usize,
    pub tiles: (usize, usize),
    pub texture: wgpu::Texture,
    pub view: wgpu::TextureView,
    pub sums: [wgpu::Buffer; 3],
    /// Each tile's first list entry, the total after them.
    pub tile_offsets: wgpu::Buffer,
    pub tile_lights: wgpu::Buffer,
    /// Entries `tile_lights` holds.
    pub tile_capacity: u64,
    /// Per tile Σ|L_A|, Σ|L_B|, pixels; then the difference's floor.
    pub partials: wgpu::Buffer,
}

/// Refuses an image whose texture, sums or read-back the device cannot hold.
pub fn check_size(ctx: &GpuContext, width: usize, height: usize) -> limits::Result<()> {
    limits::check_image_size(ctx, width, height, TEXEL_BYTES)?;
    let sums = (width * height) as u64 * SUM_BYTES;
    let max = ctx
        .limits
        .max_storage_buffer_binding_size
        .min(ctx.limits.max_buffer_size);
    if sums > max {
        return Err(limits::LimitError {
            value: limits::Limited::ImageSize,
            message: format!(
                "{width}×{height} needs {sums} bytes per buffer for its per-pixel sums, more than {}'s max_storage_buffer_binding_size ({max} bytes)",
                ctx.info.name
            ),
        });
    }
    Ok(())
}

fn storage(ctx: &GpuContext, label: &str, bytes: u64, extra: wgpu::BufferUsages) -> wgpu::Buffer {
    ctx.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size: bytes.max(16),
        usage: wgpu::BufferUsages::STORAGE | extra,
        mapped_at_creation: false,
    })
}

impl Target {
    /// A target of `width × height` whose tile lists hold `tile_capacity` entries.
    pub fn new(ctx: &GpuContext, width: usize, height: usize, tile_capacity: u64) -> Self {
        let tiles = tiles(width, height);
        let tile_count = (tiles.0 * tiles.1) as u64;
        let texture = ctx.device.create_texture(&wgpu::TextureDescriptor {
            label: Some("plane output"),
            size: wgpu::Extent3d {
                width: width as u32,
                height: height as u32,
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
        let pixels = (width * height) as u64;
        let none = wgpu::BufferUsages::empty();
        // Zeroed at creation (wgpu clears new buffers): with culling off, the shader still
        // reads the (unused) first offset and the total.
        Self {
            width,
            height,
            tiles,
            texture,
            view,
            sums: std::array::from_fn(|k| {
                // Copied out by the pixel inspector's probe (accum_0).
                let copied = wgpu::BufferUsages::COPY_SRC;
                storage(ctx, &format!("plane sums {k}"), pixels * SUM_BYTES, copied)
            }),
            tile_offsets: storage(
                ctx,
                "tile offsets",
                (tile_count + 1) * 4,
                wgpu::BufferUsages::COPY_SRC,
            ),
            tile_lights: storage(ctx, "tile lights", tile_capacity * 4, none),
            tile_capacity,
            // Cleared after the floor at a render's start (a method file's stop mark).
            partials: storage(
                ctx,
                "partials",
                (tile_count + 1) * 16,
                wgpu::BufferUsages::COPY_DST,
            ),
        }
    }

    /// The entries of the tile lists (their total, after the offsets), read back; blocks.
    /// `None` where the device could not map the copy (it was lost).
    pub fn tile_entries(&self, ctx: &GpuContext) -> Option<u64> {
        let tiles = (self.tiles.0 * self.tiles.1) as u64;
        let data = read_buffer(ctx, &self.tile_offsets, tiles * 4, 4)?;
        Some(u64::from(u32::from_le_bytes([
            data[0], data[1], data[2], data[3],
        ])))
    }

    /// Fills the output with NaN, so that a pixel the shader fails to write shows.
    pub fn poison(&self, ctx: &GpuContext) {
        let (w, h) = (self.width as u32, self.height as u32);
        let nan = vec![f32::NAN; (w * h * 4) as usize];
        ctx.queue.write_texture(
            self.texture.as_image_copy(),
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

    /// Reads the output back as a frame of `settings` (alpha marks the plane's pixels), and
    /// whether a method file was stopped in it (`stopped`); waits for the GPU.
    pub fn read(&self, ctx: &GpuContext, settings: &RenderSettings) -> Result<(Frame, bool)> {
        let (w, h) = (self.width as u32, self.height as u32);
        let data = read_texels(ctx, &self.texture, (w, h), TEXEL_BYTES)?;
        Ok((self.frame_of(&data, settings), stopped(&data)))
    }

    /// Starts reading the output back, for a caller that cannot wait (the browser): the
    /// frame comes from `PendingRead::try_take` and `Target::frame_of` once the GPU is done.
    pub fn start_read(&self, ctx: &GpuContext) -> PendingRead {
        let (w, h) = (self.width as u32, self.height as u32);
        PendingRead::start(ctx, &self.texture, (w, h), TEXEL_BYTES)
    }

    /// The output's texels (`TEXEL_BYTES` each, rows packed) as a frame of `settings`.
    pub fn frame_of(&self, data: &[u8], settings: &RenderSettings) -> Frame {
        let texels: Vec<[f32; 4]> = data
            .chunks_exact(TEXEL_BYTES as usize)
            .map(bytemuck::pod_read_unaligned)
            .collect();
        let pixels = texels
            .iter()
            .map(|t| DVec3::new(f64::from(t[0]), f64::from(t[1]), f64::from(t[2])))
            .collect();
        // NaN (a poisoned, unwritten texel) counts as on the plane, so it is seen.
        let on_plane = texels
            .iter()
            .map(|t| t[3] >= 0.5 || t[3].is_nan())
            .collect();
        Frame {
            width: self.width,
            height: self.height,
            kind: if settings.view == View::Diff {
                FrameKind::RelativeDifference
            } else {
                FrameKind::Radiance
            },
            pixels,
            on_plane,
            divider: (settings.view == View::Split).then(|| settings.divider_column()),
        }
    }
}

/// Whether the output's texels carry the mark of a method file stopped (alpha 2, plane.wgsl
/// `resolve`).
pub fn stopped(data: &[u8]) -> bool {
    data.chunks_exact(TEXEL_BYTES as usize)
        .map(bytemuck::pod_read_unaligned::<[f32; 4]>)
        .any(|t| t[3] > 1.5)
}

/// `bytes` of `buffer` from `offset`, read back; blocks. `None` where the device could not
/// map the copy (it was lost).
pub fn read_buffer(
    ctx: &GpuContext,
    buffer: &wgpu::Buffer,
    offset: u64,
    bytes: u64,
) -> Option<Vec<u8>> {
    let read = ctx.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("buffer readback"),
        size: bytes,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let mut encoder = ctx
        .device
        .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
    encoder.copy_buffer_to_buffer(buffer, offset, &read, 0, bytes);
    ctx.queue.submit([encoder.finish()]);
    let slice = read.slice(..);
    slice.map_async(wgpu::MapMode::Read, |_| {});
    let _ = ctx.device.poll(wgpu::PollType::wait_indefinitely());
    let data = slice.get_mapped_range().ok()?;
    Some(data.to_vec())
}

/// A texture of `size` read back, `texel_bytes` per texel, rows packed tightly (the copy's
/// rows are padded to wgpu's 256-byte alignment); waits for the GPU. A copy the device could
/// not map after the wait is the machine's failure (a lost device).
pub fn read_texels(
    ctx: &GpuContext,
    texture: &wgpu::Texture,
    size: (u32, u32),
    texel_bytes: u32,
) -> Result<Vec<u8>> {
    let pending = PendingRead::start(ctx, texture, size, texel_bytes);
    let _ = ctx.device.poll(wgpu::PollType::wait_indefinitely());
    pending.try_take(ctx).ok_or_else(|| {
        Error::machine(
            format!("GPU {}", ctx.info.name),
            "the image could not be read back (the device was lost?)",
        )
    })
}

/// A texture's read-back in flight: the copy submitted and the buffer's mapping asked for.
/// Nothing waits: the mapping lands when the device is polled (the desktop) or when the
/// browser's event loop runs (the web), and `try_take` then has the texels. Whether it has
/// landed is asked of the buffer itself, not of the mapping's callback: on a device that
/// several threads poll, another thread may still be running the callback when this one's
/// wait returns (the tests share one device).
pub struct PendingRead {
    buffer: wgpu::Buffer,
    row: u32,
    size: (u32, u32),
    texel_bytes: u32,
}

impl PendingRead {
    /// Copies `texture` (of `size`, `texel_bytes` per texel) into a buffer and asks for it.
    pub fn start(
        ctx: &GpuContext,
        texture: &wgpu::Texture,
        (w, h): (u32, u32),
        texel_bytes: u32,
    ) -> Self {
        let row = (w * texel_bytes).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
        let buffer = ctx.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
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
            texture.as_image_copy(),
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
        buffer.slice(..).map_async(wgpu::MapMode::Read, |_| {});
        Self {
            buffer,
            row,
            size: (w, h),
            texel_bytes,
        }
    }

    /// The texels, rows packed tightly, once the GPU is done; `None` before. Polls the
    /// device without waiting.
    pub fn try_take(&self, ctx: &GpuContext) -> Option<Vec<u8>> {
        let _ = ctx.device.poll(wgpu::PollType::Poll);
        let (w, h) = self.size;
        let data = self.buffer.slice(..).get_mapped_range().ok()?;
        Some(
            data.chunks(self.row as usize)
                .take(h as usize)
                .flat_map(|line| &line[..(w * self.texel_bytes) as usize])
                .copied()
                .collect(),
        )
    }
}
