//! `shaders/brdf_aniso.wgsl`: anisotropic GGX on the GPU, mirroring `crate::brdf::aniso` by
//! name.

/// The shader text (composed after `brdf::SOURCE`).
pub const SOURCE: &str = include_str!("../../shaders/brdf_aniso.wgsl");
