//! `shaders/ltc_f16.wgsl`: the `ltc-f16` and `ltc-f16-pairs` methods, composed only on
//! devices with `SHADER_F16`.

/// The shader text; the module it joins must begin with `ENABLE`.
pub const SOURCE: &str = include_str!("../../shaders/ltc_f16.wgsl");

/// The directive that must open a module using f16.
pub const ENABLE: &str = "enable f16;\n";

/// Stands in for `add_ltc_f16` and `add_ltc_f16_pair` where the device has no f16: plane.wgsl
/// names them, but the renderer never dispatches those methods there
/// (`PlaneRenderer::supports`).
pub const STUB: &str = "fn add_ltc_f16(s: ptr<function, Sums>, p: Pixel, ltc: LtcShading, light: GpuLight) {}\n\
fn add_ltc_f16_pair(s: ptr<function, Sums>, p: Pixel, ltc: LtcShading, x_relative: vec3<f32>, j: u32, second: bool) {}\n";
