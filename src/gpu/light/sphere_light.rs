//! `shaders/sphere_light.wgsl`: lights with a size on the GPU — a sphere's cap, the LTC disk
//! and the representative point — mirroring `crate::light::sphere`, `crate::light::sphere::disk` and
//! `crate::ltc::sphere` by name (docs/design.md §1.10). Composed after `brdf` and `ltc`.

use crate::light::sphere::SphereMethod;

/// The shader text, embedded so the binary runs from anywhere.
pub const SOURCE: &str = include_str!("../../../shaders/sphere_light.wgsl");

/// `SPHERE_*` of sphere_light.wgsl: its value and its name there.
pub fn sphere_constant(m: SphereMethod) -> (u32, &'static str) {
    match m {
        SphereMethod::Exact => (0, "SPHERE_EXACT"),
        SphereMethod::LtcPoint => (1, "SPHERE_LTC_POINT"),
        SphereMethod::LtcDisk => (2, "SPHERE_LTC_DISK"),
        SphereMethod::RepresentativePoint => (3, "SPHERE_REPRESENTATIVE_POINT"),
    }
}
