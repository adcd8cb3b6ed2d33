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

    /// A light of this shape as `bench` times it, of `size` (`bench --size-for`; a point
    /// has none): each shape's module's (`rect::bench_shape`, `disk::bench_shape`,
    /// `tube::bench_shape`; a sphere of radius `size`).
    pub fn bench_shape(self, size: f64) -> Shape {
        match self {
            Self::Point => Shape::Point,
            Self::Sphere => Shape::of_radius(size),
            Self::Rect => rect::bench_shape(size),
            Self::Disk => disk::bench_shape(size),
            Self::Tube => tube::bench_shape(size),
        }
    }

    /// `bench_shape`'s lights in words, as the benchmark's table titles them.
    pub fn bench_title(self, size: f64) -> String {
        match self {
            Self::Point => "points".to_string(),
            Self::Sphere => format!("every light a sphere of radius {size}"),
            Self::Rect => rect::bench_title(size),
            Self::Disk => disk::bench_title(size),
            Self::Tube => tube::bench_title(size),
        }
    }

    /// The symbol of `bench_shape`'s size in a row's label: a rect's half-edge `h`, else a
    /// radius `r`.
    pub fn size_symbol(self) -> &'static str {
        match self {
            Self::Rect => "h",
            _ => "r",
        }
    }

    /// Its failure presets, its module's (none for points: theirs are `scene::PRESETS`).
    pub fn presets(self) -> &'static [(&'static str, &'static str)] {
        match self {
            Self::Point => &[],
            Self::Sphere => &sphere::PRESETS,
            Self::Rect => &rect::PRESETS,
            Self::Disk => &disk::PRESETS,
            Self::Tube => &tube::PRESETS,
        }
    }

    /// The vectors its lights have beside their radius, as files name them: its module's
    /// (`rect::VECTORS`, `disk::VECTORS`, `tube::VECTORS`; none for a point or a sphere).
    pub fn vector_fields(self) -> &'static [VectorField] {
        match self {
            Self::Point | Self::Sphere => &[],
            Self::Rect => &rect::VECTORS,
            Self::Disk => &disk::VECTORS,
            Self::Tube => &tube::VECTORS,
        }
    }

    /// An emitter's columns in an `eval` file after θo, α and F0, and the reading of a row of
    /// them into the shape and its centre in the row's frame: its module's (`rect`, `disk`,
    /// `tube`: `EVAL_COLUMNS` and `eval_row`). `None` for a point and a sphere, whose rows
    /// are a direction.
    pub fn eval_form(self) -> Option<EvalForm> {
        match self {
            Self::Point | Self::Sphere => None,
            Self::Rect => Some((rect::EVAL_COLUMNS, rect::eval_row)),
            Self::Disk => Some((disk::EVAL_COLUMNS, disk::eval_row)),
            Self::Tube => Some((tube::EVAL_COLUMNS, tube::eval_row)),
        }
    }

    /// How the error tables draw an emitter of this shape (`measure::emitter_error`): of
    /// about `omega` sr from the origin, centred at a unit direction; its module's
    /// `error_sample`. `None` for a point and a sphere (theirs are `measure::sphere_error`'s).
    pub fn error_sample(self) -> Option<ErrorSample> {
        match self {
            Self::Point | Self::Sphere => None,
            Self::Rect => Some(rect::form::error_sample),
            Self::Disk => Some(disk::form::error_sample),
            Self::Tube => Some(tube::form::error_sample),
        }
    }

    /// The Gauss–Legendre nodes its exact method takes as a reference (`ExactRule::Nodes`):
    /// its module's `EXACT_NODES`.
    pub fn exact_nodes(self) -> usize {
        match self {
            Self::Point | Self::Sphere => sphere::EXACT_NODES,
            Self::Rect => rect::EXACT_NODES,
            Self::Disk => disk::EXACT_NODES,
            Self::Tube => tube::EXACT_NODES,
        }
    }

    /// Whether its lights have a radius (`Shape::radius`; a rect's size is its half-edges).
    pub fn has_radius(self) -> bool {
        matches!(self, Self::Sphere | Self::Disk | Self::Tube)
    }

    /// The shapes with a size, whose methods are their own modules' (`ALL` without the point).
    pub fn sized() -> impl Iterator<Item = Self> {
        Self::ALL.into_iter().filter(|&k| k != Self::Point)
    }
}

/// The smallest radius of a light with a size: a tenth of a millimetre in metres, the
/// precision a scene is saved to (`Scene::rounded_for_saving`). Its radiance `I/(π r²)` stays
/// within f32 (≤ 1e6/(π·1e-8) ≈ 3e13) for every intensity `Scene::validate` allows.
pub const MIN_RADIUS: f64 = 1e-4;

/// A light's radius in the lab, where it has one: the scene's smallest (a tenth of a
/// millimetre) to 1 (half the default plane's half-size; larger spheres swallow the view).
pub const RADIUS_RANGE: [f64; 2] = [MIN_RADIUS, 1.0];

/// One of a shape's sizes as the lab's light list drags it (docs/design.md §5.12): its
/// label, what its hover says, its range and drag speed, and how it is read from the shape
/// and written back. Each shape's module has its own (`Shape::sizes`).
#[derive(Clone, Copy)]
pub struct ShapeSize {
    pub label: &'static str,
    pub hover: &'static str,
    pub range: [f64; 2],
    pub speed: f64,
    pub get: fn(Shape) -> f64,
    pub set: fn(Shape, f64) -> Shape,
}

/// A point's and a sphere's one size, its radius: 0 a point, more a sphere.
const RADIUS_SIZES: [ShapeSize; 1] = [ShapeSize {
    label: "r",
    hover: "Radius: 0 is the paper's point light; from 0.0001 a sphere, shaded by each side's method for lights with a size",
    range: [0.0, RADIUS_RANGE[1]],
    speed: 0.001,
    get: Shape::radius,
    set: |_, r| Shape::of_radius(r),
}];

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

    /// A tube's half axis, `None` for the other shapes.
    pub fn half_axis(self) -> Option<DVec3> {
        match self {
            Self::Tube { half_axis, .. } => Some(half_axis),
            _ => None,
        }
    }

    /// Its vectors, as files name them and the checks read them (none for a point or a
    /// sphere, whose one dimension is `radius`), in `ShapeKind::vector_fields`' order.
    pub fn vectors(self) -> Vec<ShapeVector> {
        let values = match self {
            Self::Point | Self::Sphere { .. } => Vec::new(),
            Self::Rect { half_u, half_v } => vec![half_u, half_v],
            Self::Disk { normal, .. } => vec![normal],
            Self::Tube { half_axis, .. } => vec![half_axis],
        };
        let fields = self.kind().vector_fields();
        fields
            .iter()
            .zip(values)
            .map(|(f, value)| ShapeVector {
                name: f.name,
                value,
                direction: f.direction,
            })
            .collect()
    }

    /// The shape of `kind` of this radius (read where `kind.has_radius()`) and these vectors,
    /// in `ShapeKind::vector_fields`' order: a scene file's light.
    pub fn of_dimensions(kind: ShapeKind, radius: f64, vectors: &[DVec3]) -> Self {
        let v = |k: usize| vectors.get(k).copied().unwrap_or_default();
        match kind {
            ShapeKind::Point | ShapeKind::Sphere => Self::of_radius(radius),
            ShapeKind::Rect => Self::Rect {
                half_u: v(0),
                half_v: v(1),
            },
            ShapeKind::Disk => Self::Disk {
                normal: v(0),
                radius,
            },
            ShapeKind::Tube => Self::Tube {
                half_axis: v(0),
                radius,
            },
        }
    }

    /// The same shape with its `k`th vector (`vectors`' order) mapped by `vector(k, v)` and
    /// its radius by `length` (a scene's rounding for saving, the lab's checks).
    pub fn map_dimensions(
        self,
        mut vector: impl FnMut(usize, DVec3) -> DVec3,
        mut length: impl FnMut(f64) -> f64,
    ) -> Self {
        match self {
            Self::Point => Self::Point,
            Self::Sphere { radius } => Self::Sphere {
                radius: length(radius),
            },
            Self::Rect { half_u, half_v } => Self::Rect {
                half_u: vector(0, half_u),
                half_v: vector(1, half_v),
            },
            Self::Disk { normal, radius } => Self::Disk {
                normal: vector(0, normal),
                radius: length(radius),
            },
            Self::Tube { half_axis, radius } => Self::Tube {
                half_axis: vector(0, half_axis),
                radius: length(radius),
            },
        }
    }

    /// Its outline as the lab draws it over the image: polylines in the world about `centre`,
    /// as seen from `eye`, each shape's own (`Rect::outline`, `disk::outline`,
    /// `tube::outline`). None for a point, nor for a sphere, whose silhouette the lab draws as
    /// a circle about its marker.
    pub fn outline(self, centre: DVec3, eye: DVec3) -> Vec<Vec<DVec3>> {
        match self {
            Self::Point | Self::Sphere { .. } => Vec::new(),
            Self::Rect { half_u, half_v } => rect::Rect {
                centre,
                u: half_u,
                v: half_v,
            }
            .outline(),
            Self::Disk { normal, radius } => disk::outline(centre, normal, radius),
            Self::Tube { half_axis, radius } => tube::outline(centre, (half_axis, radius), eye),
        }
    }

    /// Its sizes as the lab drags them, its module's (`rect::SIZES`, `disk::SIZES`,
    /// `tube::SIZES`; a point's and a sphere's radius).
    pub fn sizes(self) -> &'static [ShapeSize] {
        match self.kind() {
            ShapeKind::Point | ShapeKind::Sphere => &RADIUS_SIZES,
            ShapeKind::Rect => &rect::SIZES,
            ShapeKind::Disk => &disk::SIZES,
            ShapeKind::Tube => &tube::SIZES,
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

/// What an emitter's methods read beside its shape, in the shading frame: the view, the
/// material, the pixel's LTC lobes and its rules (each emitter's `*Shading` holds them with the
/// shape; `render::ShapeMethod::emitter_lobes` shades any of them by its method).
#[derive(Clone, Copy, Debug)]
pub struct EmitterShading<'a> {
    pub v: DVec3,
    pub alpha: Alpha<f64>,
    pub f0: f64,
    pub ltc: &'a LtcPair,
    pub clip: Clipping,
    pub normalization: Normalization,
}

impl<'a> EmitterShading<'a> {
    /// At `v` with `alpha`, `f0` and the pixel's LTC lobes `ltc`, by eq. 30's rules and the
    /// corrected normalization: the case the error tables and the encodings' figures measure.
    pub fn corrected(v: DVec3, alpha: Alpha<f64>, f0: f64, ltc: &'a LtcPair) -> Self {
        Self {
            v,
            alpha,
            f0,
            ltc,
            clip: Clipping::BOTH,
            normalization: Normalization::Corrected,
        }
    }

    /// An emitter as its oriented point light toward unit `l` with `irradiance` at the point
    /// (`point_lobes` times it): the exact point light where `exact`, the paper's point
    /// formula else — the form every emitter takes when it is tiny.
    pub fn point_light(&self, exact: bool, l: DVec3, irradiance: f64) -> Lobes<f64> {
        let lobes = point_lobes(
            exact,
            (self.v, l),
            (self.alpha, self.f0),
            self.ltc,
            self.clip,
            self.normalization,
        );
        Lobes {
            specular: irradiance * lobes.specular,
            diffuse: irradiance * lobes.diffuse,
        }
    }
}

/// An emitter's unit-radiance lobes and the area its radiance `I/A` divides by: what each
/// emitter's `emitter_lobes` gives (`rect`, `disk`, `tube`).
pub type EmitterLobes = (Lobes<f64>, f64);

/// An emitter's `eval` columns and its reader of a row (`ShapeKind::eval_form`): `get` reads
/// a column by name; the shape and its centre in the row's frame, or why the row is refused.
pub type EvalForm = (
    &'static str,
    fn(&dyn Fn(&str) -> f64) -> std::result::Result<(Shape, DVec3), String>,
);

/// An emitter's draw for the error tables (`ShapeKind::error_sample`): `uniform` draws in a
/// range, then `omega` (sr) and the centre's unit direction; the shape and its centre.
pub type ErrorSample = fn(&mut dyn FnMut([f64; 2]) -> f64, f64, DVec3) -> (Shape, DVec3);

/// One of a shape's vectors (world) as files name it: its name, and whether only its
/// direction is read (a disk's normal), which must then have some length; else any length,
/// 0 included (a half-edge, a half axis).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VectorField {
    pub name: &'static str,
    pub direction: bool,
}

/// One of a light's vectors: its field and its value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapeVector {
    pub name: &'static str,
    pub value: DVec3,
    pub direction: bool,
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
