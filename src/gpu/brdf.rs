//! `shaders/brdf.wgsl`: the exact BRDF terms on the GPU, mirroring `crate::brdf` by name.

/// The shader text, embedded so the binary runs from anywhere.
pub const SOURCE: &str = include_str!("../../shaders/brdf.wgsl");
