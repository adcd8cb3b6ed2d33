//! `shaders/disk_light.wgsl`: disk lights on the GPU — the segment above the surface and the
//! exact rule over it, the LTC disk fed the disk's own ellipse, and the point limit —
//! mirroring `crate::light::disk` by name (docs/design.md §1.12). Composed after `brdf`,
//! `ltc`, `sphere_light` (the cone's algebra) and `rect_light` (`atan2_precise`).

use crate::light::disk::DiskMethod;

/// The shader text, embedded so the binary runs from anywhere.
pub const SOURCE: &str = include_str!("../../../shaders/disk_light.wgsl");

/// `DISK_*` of disk_light.wgsl: its value and its name there.
pub fn disk_constant(m: DiskMethod) -> (u32, &'static str) {
    match m {
        DiskMethod::Exact => (0, "DISK_EXACT"),
        DiskMethod::LtcDisk => (1, "DISK_LTC_DISK"),
        DiskMethod::LtcPoint => (2, "DISK_LTC_POINT"),
    }
}
