//! What the adapter can hold, checked before any work: the lights, the image and its
//! read-back, the LUT. Each refusal is a `LimitError`: which value and the limit it exceeds;
//! the caller names where the value came from (the CLI its flag, a scene its file).

use crate::error::Error;
use crate::gpu::GpuContext;
use crate::named::named_enum;

named_enum! {
    /// The values the adapter limits.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub enum Limited {
        /// An image's width and height.
        ImageSize = "image size",
        /// How many lights are shaded at once.
        LightCount = "light count",
        /// A LUT's cells per side.
        TableSize = "LUT",
    }
}

impl Limited {}

/// A value beyond the adapter's limits, and the sentence naming the limit.
#[derive(Debug, thiserror::Error)]
#[error("{}: {message}", value.name())]
pub struct LimitError {
    pub value: Limited,
    pub message: String,
}

impl LimitError {
    fn new(value: Limited, message: String) -> Self {
        Self { value, message }
    }

    /// Bad input named `input` (a flag, a file) instead of the value.
    pub fn named(self, input: &str) -> Error {
        Error::input(input, self.message)
    }
}

impl From<LimitError> for Error {
    fn from(e: LimitError) -> Self {
        Error::input(e.value.name(), e.message)
    }
}

pub type Result<T, E = LimitError> = std::result::Result<T, E>;

/// The bytes one storage binding may hold on this device.
fn storage_binding_bytes(ctx: &GpuContext) -> u64 {
    ctx.limits
        .max_storage_buffer_binding_size
        .min(ctx.limits.max_buffer_size)
}

/// The most lights of `light_bytes` each that one storage binding holds.
pub fn buffer_max_lights(ctx: &GpuContext, light_bytes: usize) -> usize {
    (storage_binding_bytes(ctx) / light_bytes as u64) as usize
}

/// `LOAD` of plane.wgsl: the lights a workgroup loads into its shared memory at a time (one
/// tile of the light loop), which bounds the loop's iterations below.
pub const LOAD: usize = 256;

/// The most lights one invocation of plane.wgsl sums on this adapter, where the driver caps
/// shader loops: Mesa's llvmpipe (lavapipe) ends every loop of an invocation after 65 535
/// iterations in all (`LP_MAX_TGSI_LOOP_ITERATIONS`, shared between loops), and the light
/// loop takes one iteration per light plus one per `LOAD`-light tile: 65 535 · 256/257 =
/// 65 280 lights at most, less one tile of margin (at the limit itself invocations end before
/// writing their pixel).
pub fn light_loop_limit(ctx: &GpuContext) -> Option<usize> {
    let llvmpipe = ctx.info.name.contains("llvmpipe") || ctx.info.driver.contains("llvmpipe");
    llvmpipe.then_some(65_535 * LOAD / (LOAD + 1) - LOAD)
}

/// The most lights this device shades: the buffer's capacity, or less where the driver ends
/// shader loops early.
pub fn max_lights(ctx: &GpuContext, light_bytes: usize) -> usize {
    let buffer = buffer_max_lights(ctx, light_bytes);
    light_loop_limit(ctx).map_or(buffer, |l| l.min(buffer))
}

/// Refuses more lights than one storage binding holds or the driver's loops can sum.
pub fn check_light_count(ctx: &GpuContext, count: usize, light_bytes: usize) -> Result<()> {
    let buffer = buffer_max_lights(ctx, light_bytes);
    if count > buffer {
        return Err(LimitError::new(
            Limited::LightCount,
            format!(
                "{count} lights do not fit in one GPU storage buffer on {}: at most {buffer} lights of {light_bytes} bytes (max_storage_buffer_binding_size {})",
                ctx.info.name,
                mib(storage_binding_bytes(ctx))
            ),
        ));
    }
    if let Some(limit) = light_loop_limit(ctx).filter(|&l| count > l) {
        return Err(LimitError::new(
            Limited::LightCount,
            format!(
                "{count} lights do not fit in one shader invocation on {}: its driver ends shader loops after {limit} lights (render on the CPU, or on a hardware GPU)",
                ctx.info.name
            ),
        ));
    }
    Ok(())
}

/// Refuses an image the device cannot hold: a side beyond `max_texture_dimension_2d`, or a
/// read-back (rows padded to wgpu's 256-byte alignment) beyond `max_buffer_size`.
pub fn check_image_size(
    ctx: &GpuContext,
    width: usize,
    height: usize,
    texel_bytes: u32,
) -> Result<()> {
    let max_side = ctx.limits.max_texture_dimension_2d as usize;
    if width > max_side || height > max_side {
        return Err(LimitError::new(
            Limited::ImageSize,
            format!(
                "{width}×{height} exceeds the GPU's largest texture side (max_texture_dimension_2d {max_side})"
            ),
        ));
    }
    let bytes = readback_bytes(width, height, texel_bytes);
    if bytes > ctx.limits.max_buffer_size {
        return Err(LimitError::new(
            Limited::ImageSize,
            format!(
                "{width}×{height} needs a {} read-back buffer, more than the GPU's max_buffer_size ({})",
                mib(bytes),
                mib(ctx.limits.max_buffer_size)
            ),
        ));
    }
    Ok(())
}

/// The bytes of an image's read-back buffer: rows padded to `COPY_BYTES_PER_ROW_ALIGNMENT`.
pub fn readback_bytes(width: usize, height: usize, texel_bytes: u32) -> u64 {
    let row = (width as u64 * u64::from(texel_bytes))
        .next_multiple_of(u64::from(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT));
    row * height as u64
}

/// Refuses a LUT whose packed buffer one storage binding cannot hold.
pub fn check_lut_size(ctx: &GpuContext, lut_size: usize, packed_bytes: u64) -> Result<()> {
    let max = storage_binding_bytes(ctx);
    if packed_bytes > max {
        return Err(LimitError::new(
            Limited::TableSize,
            format!(
                "a {lut_size}×{lut_size} table needs {} of GPU storage, more than {}'s max_storage_buffer_binding_size ({})",
                mib(packed_bytes),
                ctx.info.name,
                mib(max)
            ),
        ));
    }
    Ok(())
}

/// Bytes for messages, exact (limits are often 2³¹ − 1, one byte from a round need) and in
/// MiB or GiB.
fn mib(bytes: u64) -> String {
    let m = bytes as f64 / f64::from(1u32 << 20);
    if m >= 1024.0 {
        format!("{bytes} bytes = {:.2} GiB", m / 1024.0)
    } else {
        format!("{bytes} bytes = {m:.1} MiB")
    }
}
