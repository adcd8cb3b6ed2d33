//! `shaders/sphere_light.wgsl`: lights with a size on the GPU — a sphere's cap, the LTC disk
//! and the representative point — mirroring `crate::light::sphere`, `crate::light::sphere::disk` and
//! `crate::ltc::sphere` by name (docs/design.md §1.10). Composed after `brdf` and `ltc`.

/// The shader text, embedded so the binary runs from anywhere.
pub const SOURCE: &str = include_str!("../../../shaders/sphere_light.wgsl");
