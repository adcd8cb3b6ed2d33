//! A light's shape and the ways each shape is shaded (docs/design.md §1.10, §5.12): the
//! paper's point light, a sphere (`sphere`: its methods, the cap it covers, the LTC over
//! that cap, and the Gauss–Legendre rule over it that the exact method integrates by), and a
//! rect (`rect`: the polygon it covers, the LTC over a polygon and the rule over it), and a
//! disk (`disk`: the segment of it above the surface and the rule over it; its LTC is the
//! sphere's cone algebra), and a tube (`tube`: a capsule, its line integrals and its band's rule). What is chosen per shape is keyed by `ShapeKind` (docs/design.md
//! §5.12). Adding a shape is a module here, a variant of `Shape` and of `ShapeKind`, and one
//! arm in each dispatch: the CPU's `cpu::shape_term`, `render::ShapeMethod`, the light
//! buffer's `gpu::scene::light_elements` and light_shape.wgsl's `add_light`.

pub mod boundary;
pub mod disk;
pub mod fan;
pub mod polar;
pub mod rect;
pub mod sphere;
pub mod tube;

use glam::DVec3;

use crate::brdf::{self, Alpha, Lobes};
use crate::ltc::{Clipping, LtcPair, Normalization};
use crate::named::named_enum;

named_enum! {
    /// A shape without its dimensions: what a side's methods, the pipelines' specializations,
    /// the command line's `--method-for` and a method file's functions are keyed by
    /// (docs/design.md §5.12), in `Shape`'s order.
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
    pub enum ShapeKind {
        Point = "point",
        Sphere = "sphere",
        Rect = "rect",
        Disk = "disk",
        Tube = "tube",
    }
}

impl ShapeKind {
    /// One of its lights, as a sentence names it ("a rect light").
    pub fn light_noun(self) -> &'static str {
        match self {
            Self::Point => "a point light",
            Self::Sphere => "a light with a size",
            Self::Rect => "a rect light",
            Self::Disk => "a disk light",
            Self::Tube => "a tube light",
        }
    }

    /// How one of its lights emits, for a reader of the lab (`None`: the radius slider says
    /// it for spheres, and a point needs no words).
    pub fn emits(self) -> Option<&'static str> {
        match self {
            Self::Point | Self::Sphere => None,
            Self::Rect => Some(
                "A rect emits toward half_u × half_v with radiance I/A: far away it is the oriented point light of intensity I cos θe",
            ),
            Self::Disk => Some(
                "A disk emits toward its normal with radiance I/(π r²): far away it is the oriented point light of intensity I cos θe",
            ),
            Self::Tube => Some(
                "A tube (a capsule: the segment ± half_axis swept by a ball of radius r) emits all around with radiance 4I/A, as a sphere does: averaged over directions, far away it is the point light of intensity I",
            ),
        }
    }

    /// Its lights as the lab names them ("rect lights"); a sphere's are every light the
    /// radius slider gives a size.
    pub fn lights_title(self) -> &'static str {
        match self {
            Self::Point => "point lights",
            Self::Sphere => "lights with a size",
            Self::Rect => "rect lights",
            Self::Disk => "disk lights",
            Self::Tube => "tube lights",
        }
    }

    /// The shapes with a size, whose methods are their own modules' (`ALL` without the point).
    pub fn sized() -> impl Iterator<Item = Self> {
        Self::ALL.into_iter().filter(|&k| k != Self::Point)
    }
}

/// Which rule a light's exact method integrates by.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ExactRule {
    /// The shape's own rule at this many Gauss–Legendre nodes a dimension and piece: `eval`'s
    /// (`EXACT_NODES`), the measures' and the tests' references (docs/design.md §1.10–§1.12).
    Nodes(usize),
    /// The renders' rule, on the CPU and the GPU alike (docs/design.md §1.14).
    Render,
}

/// Where a light's light comes from.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Shape {
    /// The paper's point light: intensity `I`, irradiance `I/d²` (§1.3).
    #[default]
    Point,
    /// A sphere of this radius and uniform radiance `I/(π r²)`, which lights a distant point
    /// as the point light of intensity `I` does (§1.10).
    Sphere { radius: f64 },
    /// A one-sided rect about the light's position, of half-edges `half_u`, `half_v` (world),
    /// emitting toward `half_u × half_v` with radiance `I/A` (`A = 4 |half_u × half_v|`), so
    /// that far away it lights as the oriented point light of intensity `I cos θe` (§1.11).
    Rect { half_u: DVec3, half_v: DVec3 },
    /// A one-sided disk about the light's position of `normal` (the side it emits toward; its
    /// length is not read, so that a file's vector reads back as written) and `radius`, of radiance `I/(π r²)`: far away, the oriented point light of
    /// intensity `I cos θe`, as a rect (§1.12).
    Disk { normal: DVec3, radius: f64 },
    /// A capsule: the segment from the light's position `− half_axis` to `+ half_axis`
    /// (world) swept by a ball of `radius`, of uniform radiance `4I/A` (`A = 4π r |half_axis| +
    /// 4π r²`, `light::tube::Tube::area`), so that, as a sphere's, its intensity averaged
    /// over directions is `I` (a convex body's mean projected area is `A/4`) (§1.15).
    Tube { half_axis: DVec3, radius: f64 },
}

impl Shape {
    /// Which shape it is.
    pub fn kind(self) -> ShapeKind {
        match self {
            Self::Point => ShapeKind::Point,
            Self::Sphere { .. } => ShapeKind::Sphere,
            Self::Rect { .. } => ShapeKind::Rect,
            Self::Disk { .. } => ShapeKind::Disk,
            Self::Tube { .. } => ShapeKind::Tube,
        }
    }

    /// The shape a scene's `radius` names: 0 (or absent) a point, else a sphere.
    pub fn of_radius(radius: f64) -> Self {
        if radius == 0.0 {
            Self::Point
        } else {
            Self::Sphere { radius }
        }
    }

    /// The radius a scene writes for it: 0 for a point or a rect.
    pub fn radius(self) -> f64 {
        match self {
            Self::Point | Self::Rect { .. } => 0.0,
            Self::Sphere { radius } | Self::Disk { radius, .. } | Self::Tube { radius, .. } => {
                radius
            }
        }
    }

    /// A disk's normal, `None` for the other shapes.
    pub fn normal(self) -> Option<DVec3> {
        match self {
            Self::Disk { normal, .. } => Some(normal),
            _ => None,
        }
    }

    /// A tube's half axis, `None` for the other shapes.
    pub fn half_axis(self) -> Option<DVec3> {
        match self {
            Self::Tube { half_axis, .. } => Some(half_axis),
            _ => None,
        }
    }

    /// A rect's two half-edges, `None` for the other shapes.
    pub fn half_edges(self) -> Option<(DVec3, DVec3)> {
        match self {
            Self::Rect { half_u, half_v } => Some((half_u, half_v)),
            _ => None,
        }
    }
}

/// A point light's lobes toward unit `l` at unit irradiance, base colour 1: the exact BRDF
/// (0 below the surface) or the LTC (`LtcPair::ltc_lobes`). The limit every light with a size
/// meets far away, which the rect's and the disk's methods shade them as when they are tiny.
pub fn point_lobes(
    exact: bool,
    (v, l): (DVec3, DVec3),
    (alpha, f0): (Alpha<f64>, f64),
    ltc: &LtcPair,
    clip: Clipping,
    normalization: Normalization,
) -> Lobes<f64> {
    match exact {
        true if l.z > 0.0 => brdf::brdf_cos_aniso(v.to_array(), l.to_array(), alpha, f0),
        true => Lobes::default(),
        false => ltc.ltc_lobes(l, f0, clip, normalization),
    }
}
