//! A light's shape and the ways each shape is shaded (docs/design.md §1.10, §5.12): the
//! paper's point light, and a sphere (`sphere`: its methods, the cap it covers, the LTC over
//! that cap, and the Gauss–Legendre rule over it that the exact method integrates by); rect
//! lights' polygon methods (`rect`) are in f64 and `eval` so far, not yet a `Shape`. Adding
//! a shape is a module here, a variant of `Shape`, and one arm in each dispatch: the CPU's
//! `cpu::light_term`, the pixel inspector's `pixel::pixel_terms`, the light buffer's
//! `gpu::scene::GpuLight::from` and plane.wgsl's `add_light`.

pub mod rect;
pub mod sphere;

/// Where a light's light comes from.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Shape {
    /// The paper's point light: intensity `I`, irradiance `I/d²` (§1.3).
    #[default]
    Point,
    /// A sphere of this radius and uniform radiance `I/(π r²)`, which lights a distant point
    /// as the point light of intensity `I` does (§1.10).
    Sphere { radius: f64 },
}

impl Shape {
    /// The shape a scene's `radius` names: 0 (or absent) a point, else a sphere.
    pub fn of_radius(radius: f64) -> Self {
        if radius == 0.0 {
            Self::Point
        } else {
            Self::Sphere { radius }
        }
    }

    /// The radius a scene writes for it: 0 for a point.
    pub fn radius(self) -> f64 {
        match self {
            Self::Point => 0.0,
            Self::Sphere { radius } => radius,
        }
    }
}
