//! `shaders/light_shape.wgsl`: one light added to a side's sums by the side's method for its
//! shape (docs/design.md §5.12): `add_light`, by `add_point`, `add_sphere` or, for every
//! emitter, `add_emitter` (`gpu::light::emitter`'s `emitter_lobes`). The shapes' method codes
//! are each shape's own module's (`sphere_light::sphere_constant`, …).

/// The shader text (composed after scene.wgsl, before plane.wgsl).
pub const SOURCE: &str = include_str!("../../../shaders/light_shape.wgsl");
