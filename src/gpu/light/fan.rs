//! `shaders/fan.wgsl`: the fan from a pole to a spherical polygon's edges on the GPU,
//! mirroring `crate::light::fan` by name (docs/design.md §1.14).

/// The shader text, embedded so the binary runs from anywhere.
pub const SOURCE: &str = include_str!("../../../shaders/fan.wgsl");
