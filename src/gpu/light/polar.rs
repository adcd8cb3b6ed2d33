//! `shaders/polar.wgsl`: the renders' exact rule on the GPU — the polar rule over a convex
//! region of directions stretched to the lobe — mirroring `crate::light::polar` by name
//! (docs/design.md §1.14). Composed after `sphere_light`, `rect_light` and
//! `disk_light`, whose precise trigonometry and `Polygon` it reads, and which call it.

/// The shader text, embedded so the binary runs from anywhere.
pub const SOURCE: &str = include_str!("../../../shaders/polar.wgsl");
