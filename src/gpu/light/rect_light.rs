//! `shaders/rect_light.wgsl`: rect lights on the GPU — the polygon clipped at a horizon,
//! Lambert's edge formula, the LTC over a polygon, Heitz & Hill's proxy and three.js's form of
//! it, and the exact rule — mirroring `crate::light::rect` by name (docs/design.md §1.11).
//! Composed after `brdf`, `ltc` and `sphere_light`.

use crate::light::rect::RectMethod;

/// The shader text, embedded so the binary runs from anywhere.
pub const SOURCE: &str = include_str!("../../../shaders/rect_light.wgsl");

/// `RECT_*` of rect_light.wgsl: its value and its name there.
pub fn rect_constant(m: RectMethod) -> (u32, &'static str) {
    match m {
        RectMethod::Exact => (0, "RECT_EXACT"),
        RectMethod::LtcPolygon => (1, "RECT_LTC_POLYGON"),
        RectMethod::LtcProxy => (2, "RECT_LTC_PROXY"),
        RectMethod::LtcProxyFast => (3, "RECT_LTC_PROXY_FAST"),
        RectMethod::LtcPoint => (4, "RECT_LTC_POINT"),
    }
}
