//! `shaders/disk_light.wgsl`: disk lights on the GPU — the segment above the surface and the
//! exact rule over it, the LTC disk fed the disk's own ellipse, and the point limit —
//! mirroring `crate::light::disk` by name (docs/design.md §1.12). Composed after `brdf`,
//! `ltc`, `sphere_light` (the cone's algebra) and `rect_light` (`atan2_precise`).

/// The shader text, embedded so the binary runs from anywhere.
pub const SOURCE: &str = include_str!("../../../shaders/disk_light.wgsl");
