//! The lights' shaders (docs/design.md §1.10–§1.12, §5.12), one module per WGSL file: each
//! shape's methods (`sphere_light`, `rect_light`, `disk_light`, twins of `crate::light`) and
//! the dispatch of a light to its shape's method (`light_shape`). `gpu` re-exports them, so
//! their paths are `gpu::sphere_light` and so on.

pub mod disk_light;
pub mod light_shape;
pub mod rect_light;
pub mod sphere_light;
