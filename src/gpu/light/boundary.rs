//! `shaders/boundary.wgsl`: a light's boundary and the search for its brightest point on the
//! GPU, mirroring `crate::light::boundary` by name (docs/design.md §1.14).

/// The shader text, embedded so the binary runs from anywhere.
pub const SOURCE: &str = include_str!("../../../shaders/boundary.wgsl");
