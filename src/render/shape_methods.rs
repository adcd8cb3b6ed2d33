//! A side's methods keyed by shape (docs/design.md §5.12): one method of each shape's own
//! list, `ShapeMethod`, and a side's set of them, `ShapeMethods`, which the renderers, the
//! pipelines' specializations, the command line and the lab read by `ShapeKind` and never by
//! a field per shape. A new shape is an arm in `ShapeMethod`'s matches and nothing here else.

use glam::DVec3;

use crate::light::disk::{self, DiskMethod};
use crate::light::rect::{self, RectMethod};
use crate::light::sphere::SphereMethod;
use crate::light::tube::{self, TubeMethod};
use crate::light::{EmitterLobes, EmitterShading, ExactRule, Shape, ShapeKind};
use crate::render::Method;

/// One shape's method: a variant per shape, holding a method of that shape's module.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ShapeMethod {
    /// How point lights are summed (the paper's methods and their fast forms).
    Point(Method),
    Sphere(SphereMethod),
    Rect(RectMethod),
    Disk(DiskMethod),
    Tube(TubeMethod),
}

impl ShapeMethod {
    /// The shape it shades.
    pub fn kind(self) -> ShapeKind {
        match self {
            Self::Point(_) => ShapeKind::Point,
            Self::Sphere(_) => ShapeKind::Sphere,
            Self::Rect(_) => ShapeKind::Rect,
            Self::Disk(_) => ShapeKind::Disk,
            Self::Tube(_) => ShapeKind::Tube,
        }
    }

    /// Its name in its shape's list (`exact`, `ltc-polygon`…).
    pub fn name(self) -> &'static str {
        match self {
            Self::Point(m) => m.name(),
            Self::Sphere(m) => m.name(),
            Self::Rect(m) => m.name(),
            Self::Disk(m) => m.name(),
            Self::Tube(m) => m.name(),
        }
    }

    /// One line for a reader of the lab or the command line (a point method: its name).
    pub fn describe(self) -> &'static str {
        match self {
            Self::Point(m) => m.name(),
            Self::Sphere(m) => m.describe(),
            Self::Rect(m) => m.describe(),
            Self::Disk(m) => m.describe(),
            Self::Tube(m) => m.describe(),
        }
    }

    /// Every method of `kind`, in its module's order.
    pub fn all(kind: ShapeKind) -> Vec<Self> {
        match kind {
            ShapeKind::Point => Method::ALL.map(Self::Point).to_vec(),
            ShapeKind::Sphere => SphereMethod::ALL.map(Self::Sphere).to_vec(),
            ShapeKind::Rect => RectMethod::ALL.map(Self::Rect).to_vec(),
            ShapeKind::Disk => DiskMethod::ALL.map(Self::Disk).to_vec(),
            ShapeKind::Tube => TubeMethod::ALL.map(Self::Tube).to_vec(),
        }
    }

    /// The method of `kind` named `name`, if it has one.
    pub fn parse(kind: ShapeKind, name: &str) -> Option<Self> {
        Self::all(kind).into_iter().find(|m| m.name() == name)
    }

    /// What a render shades `kind` by on its approximating side (A) unless told otherwise:
    /// the paper's LTC for points and rects, what engines ship for spheres (EEVEE, Bevy's
    /// pull request) and Heitz & Hill 2017's for disks and tubes (their LTC line).
    pub fn approximation(kind: ShapeKind) -> Self {
        match kind {
            ShapeKind::Point => Self::Point(Method::Ltc),
            ShapeKind::Sphere => Self::Sphere(SphereMethod::LtcDisk),
            ShapeKind::Rect => Self::Rect(RectMethod::LtcPolygon),
            ShapeKind::Disk => Self::Disk(DiskMethod::LtcDisk),
            ShapeKind::Tube => Self::Tube(TubeMethod::LtcLine),
        }
    }

    /// `kind` shaded as its centre's oriented point formula (`ltc-point`), the limit every
    /// shape with a size meets far away: what the benchmark prices a shape's methods against.
    pub fn at_centre(kind: ShapeKind) -> Self {
        match kind {
            ShapeKind::Point => Self::Point(Method::Ltc),
            ShapeKind::Sphere => Self::Sphere(SphereMethod::LtcPoint),
            ShapeKind::Rect => Self::Rect(RectMethod::LtcPoint),
            ShapeKind::Disk => Self::Disk(DiskMethod::LtcPoint),
            ShapeKind::Tube => Self::Tube(TubeMethod::LtcPoint),
        }
    }

    /// What a render shades `kind` by on its reference side (B): the exact integral.
    pub fn reference(kind: ShapeKind) -> Self {
        match kind {
            ShapeKind::Point => Method::REFERENCE.into(),
            ShapeKind::Sphere => SphereMethod::REFERENCE.into(),
            ShapeKind::Rect => RectMethod::REFERENCE.into(),
            ShapeKind::Disk => DiskMethod::REFERENCE.into(),
            ShapeKind::Tube => TubeMethod::REFERENCE.into(),
        }
    }
}

impl ShapeMethod {
    /// An emitter of `shape` (a shape of radiance `I/A`, which is neither a point nor a
    /// sphere) centred at `centre` from the shading point (world, mapped to the shading frame
    /// by `to_frame`): its unit-radiance lobes by this method and its area, each shape's
    /// module's (`EmitterLobes`). `None` for a point, a sphere, or another shape's method.
    pub fn emitter_lobes(
        self,
        (shape, centre): (Shape, DVec3),
        to_frame: &dyn Fn(DVec3) -> DVec3,
        s: &EmitterShading<'_>,
        rule: ExactRule,
    ) -> Option<EmitterLobes> {
        Some(match (shape, self) {
            (Shape::Rect { half_u, half_v }, Self::Rect(m)) => {
                rect::emitter_lobes(m, (centre, half_u, half_v), to_frame, s, rule)
            }
            (Shape::Disk { normal, radius }, Self::Disk(m)) => {
                disk::emitter_lobes(m, (centre, normal, radius), to_frame, s, rule)
            }
            (Shape::Tube { half_axis, radius }, Self::Tube(m)) => {
                tube::emitter_lobes(m, (centre, half_axis, radius), to_frame, s, rule)
            }
            _ => return None,
        })
    }
}

/// A shape's own list of methods, as a side's `ShapeMethods` gives it back typed.
pub trait OfShape: Copy + Into<ShapeMethod> {
    /// The shape whose methods these are.
    const KIND: ShapeKind;
    /// Its exact integral (`ShapeMethod::reference`).
    const REFERENCE: Self;
    /// `m` as this shape's method, where it is one.
    fn of(m: ShapeMethod) -> Option<Self>;
}

macro_rules! of_shape {
    ($($Method:ident => $Kind:ident, $Reference:ident);+ $(;)?) => {$(
        impl From<$Method> for ShapeMethod {
            fn from(m: $Method) -> Self {
                Self::$Kind(m)
            }
        }

        impl OfShape for $Method {
            const KIND: ShapeKind = ShapeKind::$Kind;
            const REFERENCE: Self = $Method::$Reference;
            fn of(m: ShapeMethod) -> Option<Self> {
                match m {
                    ShapeMethod::$Kind(m) => Some(m),
                    _ => None,
                }
            }
        }
    )+};
}

of_shape!(
    Method => Point, Brdf;
    SphereMethod => Sphere, Exact;
    RectMethod => Rect, Exact;
    DiskMethod => Disk, Exact;
    TubeMethod => Tube, Exact;
);

/// How one side of a render shades each shape: one method per shape, chosen together (the
/// plane's A and B sides each have one). Slot `k` holds a method of `ShapeKind::ALL[k]`:
/// made only from a side's defaults and changed only by `set`, which files a method under
/// its own shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ShapeMethods([ShapeMethod; ShapeKind::ALL.len()]);

impl ShapeMethods {
    /// Every shape by its approximation (side A's defaults).
    pub fn approximations() -> Self {
        Self(ShapeKind::ALL.map(ShapeMethod::approximation))
    }

    /// Every shape by its exact integral (side B's defaults).
    pub fn references() -> Self {
        Self(ShapeKind::ALL.map(ShapeMethod::reference))
    }

    /// The method for `kind`.
    pub fn of(&self, kind: ShapeKind) -> ShapeMethod {
        self.0[kind.index()]
    }

    /// The method for `M`'s shape, as that shape's own type.
    pub fn get<M: OfShape>(&self) -> M {
        // The reference is never taken: `set` files every method under its own kind.
        M::of(self.of(M::KIND)).unwrap_or(M::REFERENCE)
    }

    /// How point lights are summed: the side's method in the paper's sense, which also
    /// names its pipeline (`METHOD_A`, `METHOD_B`).
    pub fn point(&self) -> Method {
        self.get()
    }

    /// `m` for its shape.
    pub fn set(&mut self, m: impl Into<ShapeMethod>) {
        let m = m.into();
        self.0[m.kind().index()] = m;
    }

    /// The same with `m` for its shape.
    pub fn with(mut self, m: impl Into<ShapeMethod>) -> Self {
        self.set(m);
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_method_is_filed_under_its_own_shape() {
        for kind in ShapeKind::ALL {
            for m in ShapeMethod::all(kind) {
                assert_eq!(m.kind(), kind);
                assert_eq!(ShapeMethod::parse(kind, m.name()), Some(m));
                let side = ShapeMethods::references().with(m);
                assert_eq!(side.of(kind), m);
                // The other shapes keep theirs.
                for other in ShapeKind::ALL.into_iter().filter(|&o| o != kind) {
                    assert_eq!(side.of(other), ShapeMethod::reference(other));
                }
            }
        }
        assert_eq!(ShapeMethod::parse(ShapeKind::Disk, "ltc-polygon"), None);
        let a = ShapeMethods::approximations();
        assert_eq!(a.get::<RectMethod>(), RectMethod::LtcPolygon);
        assert_eq!(a.point(), Method::Ltc);
    }
}
