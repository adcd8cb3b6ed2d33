//! `shaders/light_shape.wgsl`: one light added to a side's sums by the side's method for its
//! shape (docs/design.md §5.12) — the shapes' method codes the pipelines pass (`SPHERE_A`,
//! `RECT_A`, `DISK_A`… in `gpu::plane::compile`), here with their values and names there.

use crate::light::disk::DiskMethod;
use crate::light::rect::RectMethod;
use crate::light::sphere::SphereMethod;

/// The shader text (composed after scene.wgsl, before plane.wgsl).
pub const SOURCE: &str = include_str!("../../../shaders/light_shape.wgsl");

/// `SPHERE_*` of light_shape.wgsl: its value and its name there.
pub fn sphere_constant(m: SphereMethod) -> (u32, &'static str) {
    match m {
        SphereMethod::Exact => (0, "SPHERE_EXACT"),
        SphereMethod::LtcPoint => (1, "SPHERE_LTC_POINT"),
        SphereMethod::LtcDisk => (2, "SPHERE_LTC_DISK"),
        SphereMethod::RepresentativePoint => (3, "SPHERE_REPRESENTATIVE_POINT"),
    }
}

/// `RECT_*` of light_shape.wgsl: its value and its name there.
pub fn rect_constant(m: RectMethod) -> (u32, &'static str) {
    match m {
        RectMethod::Exact => (0, "RECT_EXACT"),
        RectMethod::LtcPolygon => (1, "RECT_LTC_POLYGON"),
        RectMethod::LtcProxy => (2, "RECT_LTC_PROXY"),
        RectMethod::LtcProxyFast => (3, "RECT_LTC_PROXY_FAST"),
        RectMethod::LtcPoint => (4, "RECT_LTC_POINT"),
    }
}

/// `DISK_*` of light_shape.wgsl: its value and its name there.
pub fn disk_constant(m: DiskMethod) -> (u32, &'static str) {
    match m {
        DiskMethod::Exact => (0, "DISK_EXACT"),
        DiskMethod::LtcDisk => (1, "DISK_LTC_DISK"),
        DiskMethod::LtcPoint => (2, "DISK_LTC_POINT"),
    }
}
