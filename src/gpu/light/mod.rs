//! The lights' shaders (docs/design.md §1.10–§1.12, §5.12), one module per WGSL file: each
//! shape's methods (`sphere_light`, `rect_light`, `disk_light`, twins of `crate::light`), the
//! renders' exact rule they share (`polar`, `boundary` and `fan`, twins of `crate::light`'s) and the
//! dispatch of a light to its shape's method (`light_shape`). `gpu` re-exports them, so their
//! paths are `gpu::sphere_light` and so on.

pub mod boundary;
pub mod disk_light;
pub mod fan;
pub mod light_shape;
pub mod polar;
pub mod rect_light;
pub mod sphere_light;
pub mod tube_band;
pub mod tube_light;

/// The lights' shaders as the plane shader composes them: the shapes' files and the rule
/// they share (which reads their precise trigonometry and the rect's `Polygon`), after
/// `brdf`, `brdf_aniso`, `ltc` and `ltc_aniso`.
pub fn sources() -> String {
    [
        sphere_light::SOURCE,
        rect_light::SOURCE,
        disk_light::SOURCE,
        polar::SOURCE,
        boundary::SOURCE,
        fan::SOURCE,
        tube_light::SOURCE,
        tube_band::SOURCE,
    ]
    .join("\n")
}
