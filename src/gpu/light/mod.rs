//! The lights' shaders (docs/design.md §1.10–§1.12, §5.12), one module per WGSL file: each
//! shape's methods, its code and its methods' codes (`sphere_light`, `rect_light`,
//! `disk_light`, `tube_light`, twins of `crate::light`), what every emitter shares
//! (`emitter`: its shading and `emitter_lobes`, one arm per shape), the
//! renders' exact rule they share (`polar`, `boundary` and `fan`, twins of `crate::light`'s) and the
//! dispatch of a light to its shape's method (`light_shape`). `gpu` re-exports them, so their
//! paths are `gpu::sphere_light` and so on.
//!
//! Here too is what the GPU side keys by shape, one arm per shape in each, so that a new
//! shape's GPU code is its own modules plus these arms (docs/design.md §5.12): its shader
//! files (`sources`), its code and its second element in the light buffer (`shape_constant`,
//! `second_element`), its methods' codes (`method_constant`) and its override constants
//! (`overrides`).

pub mod boundary;
pub mod disk_light;
pub mod emitter;
pub mod fan;
pub mod light_shape;
pub mod polar;
pub mod rect_light;
pub mod sphere_light;
pub mod tube_band;
pub mod tube_light;

use glam::Vec3;

use crate::light::{Shape, ShapeKind};
use crate::render::{Method, ShapeMethod};

/// The lights' shaders as the plane shader composes them: the shapes' files and the rule
/// they share (which reads their precise trigonometry and the rect's `Polygon`), after
/// `brdf`, `brdf_aniso`, `ltc` and `ltc_aniso`.
pub fn sources() -> String {
    [
        emitter::SOURCE,
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

/// `SHAPE_*` of the shaders (scene.wgsl's for a point and a sphere, each emitter's own file's,
/// as rect_light.wgsl's `SHAPE_RECT`): its value and its name there.
pub fn shape_constant(kind: ShapeKind) -> (u32, &'static str) {
    match kind {
        ShapeKind::Point => (0, "SHAPE_POINT"),
        ShapeKind::Sphere => (1, "SHAPE_SPHERE"),
        ShapeKind::Rect => (2, "SHAPE_RECT"),
        ShapeKind::Disk => (3, "SHAPE_DISK"),
        ShapeKind::Tube => (4, "SHAPE_TUBE"),
    }
}

/// The light buffer's second element for a light of `shape` (`gpu::scene::light_elements`),
/// as its `position_range` and `intensity`: the dimensions its shader reads (a rect's
/// half-edges; a disk's unit normal and radius; a tube's half axis and radius), and in the
/// last w the shape's code (`shape_constant`), which scene.wgsl's `light_shape` reads back.
/// `None` for a point and a sphere, whose one element holds their radius.
pub fn second_element(shape: Shape) -> Option<[[f32; 4]; 2]> {
    let (first, second) = match shape {
        Shape::Point | Shape::Sphere { .. } => return None,
        Shape::Rect { half_u, half_v } => (half_u.as_vec3().extend(0.0), half_v.as_vec3()),
        Shape::Disk { normal, radius } => (
            normal.normalize().as_vec3().extend(radius as f32),
            Vec3::ZERO,
        ),
        Shape::Tube { half_axis, radius } => {
            (half_axis.as_vec3().extend(radius as f32), Vec3::ZERO)
        }
    };
    // A code is a small integer, exact in f32.
    let code = shape_constant(shape.kind()).0 as f32;
    Some([first.to_array(), second.extend(code).to_array()])
}

/// A sized shape's method's code: its own shader's (sphere_light.wgsl's `SPHERE_*`,
/// rect_light.wgsl's `RECT_*`, …). A point's method comes back as the
/// error, its codes being plane.wgsl's (`gpu::plane::shape_method_constant`), so that this
/// module, below the plane's, does not read it.
pub fn method_constant(m: ShapeMethod) -> Result<(u32, &'static str), Method> {
    match m {
        ShapeMethod::Point(m) => Err(m),
        ShapeMethod::Sphere(m) => Ok(sphere_light::sphere_constant(m)),
        ShapeMethod::Rect(m) => Ok(rect_light::rect_constant(m)),
        ShapeMethod::Disk(m) => Ok(disk_light::disk_constant(m)),
        ShapeMethod::Tube(m) => Ok(tube_light::tube_constant(m)),
    }
}

/// The override constants of a shape with a size: the flag that some light has it, and A's
/// and B's method for it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ShapeOverrides {
    /// `None` for the sphere, whose arm `SIZED` alone guards (the shape every light with a
    /// size once was).
    pub present: Option<&'static str>,
    pub a: &'static str,
    pub b: &'static str,
}

/// `kind`'s override constants (a point has the pipeline's `METHOD_A` and `METHOD_B`).
pub fn overrides(kind: ShapeKind) -> ShapeOverrides {
    let (present, a, b) = match kind {
        ShapeKind::Point => (None, "METHOD_A", "METHOD_B"),
        ShapeKind::Sphere => (None, "SPHERE_A", "SPHERE_B"),
        ShapeKind::Rect => (Some("RECTS"), "RECT_A", "RECT_B"),
        ShapeKind::Disk => (Some("DISKS"), "DISK_A", "DISK_B"),
        ShapeKind::Tube => (Some("TUBES"), "TUBE_A", "TUBE_B"),
    };
    ShapeOverrides { present, a, b }
}
