//! `shaders/ltc_f16.wgsl`: the `ltc-f16` method, composed only on devices with `SHADER_F16`.

/// The shader text; the module it joins must begin with `ENABLE`.
pub const SOURCE: &str = include_str!("../../shaders/ltc_f16.wgsl");

/// The directive that must open a module using f16.
pub const ENABLE: &str = "enable f16;\n";

/// Stands in for `add_ltc_f16` where the device has no f16: plane.wgsl's method switch names
/// it, but the renderer never dispatches that method there (`PlaneRenderer::supports`).
pub const STUB: &str = "fn add_ltc_f16(s: ptr<function, Sums>, p: Pixel, light: GpuLight) {}\n";
