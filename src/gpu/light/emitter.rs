//! `shaders/emitter.wgsl`: what every emitter's methods share on the GPU — `EmitterShading`
//! (the view, the material and the rules, `crate::light::EmitterShading`'s twin) and
//! `emitter_lobes`, any emitter's unit-radiance lobes and area by its shape's method
//! (`crate::render::ShapeMethod::emitter_lobes`'s twin), one arm per shape calling the shape's
//! `<shape>_emitter_lobes` (docs/design.md §5.12).

/// The shader text, embedded so the binary runs from anywhere.
pub const SOURCE: &str = include_str!("../../../shaders/emitter.wgsl");
