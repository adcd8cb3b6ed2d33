//! `shaders/rect_light.wgsl`: rect lights on the GPU — the polygon clipped at a horizon,
//! Lambert's edge formula, the LTC over a polygon, Heitz & Hill's proxy and three.js's form of
//! it, and the exact rule — mirroring `crate::light::rect` by name (docs/design.md §1.11).
//! Composed after `brdf`, `ltc` and `sphere_light`.

/// The shader text, embedded so the binary runs from anywhere.
pub const SOURCE: &str = include_str!("../../../shaders/rect_light.wgsl");
