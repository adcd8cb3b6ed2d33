//! What a render is, for every renderer alike (the CPU reference, the GPU, the lab): how the
//! lights are summed (`Method`), what a pixel shows (`View`), the rest of the settings, the
//! image that comes back (`Frame`), and the shading point and frame of docs/design.md §1.

mod shape_methods;

use glam::DVec3;

pub use shape_methods::{OfShape, ShapeMethod, ShapeMethods};

use crate::brdf::Alpha;
use crate::ltc::lut::Lut;
use crate::ltc::remedy::HorizonRule;
use crate::ltc::{Clipping, Normalization};
use crate::named::named_enum;

named_enum! {
    /// How one pixel's lights are summed. The CPU reference has one form of each: the fast
    /// forms are the same math as their literal twins there.
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
    pub enum Method {
        /// The exact BRDF as docs/design.md §1 writes it (eq. 28).
        Brdf = "brdf",
        /// The exact BRDF with Filament's `V_SmithGGXCorrelated` and no root for `E`.
        BrdfFast = "brdf-fast",
        /// The paper's LTC (eq. 30): normalize `l`, rotate it into the frame, `M⁻¹ l` per lobe.
        Ltc = "ltc",
        /// LTC with the rotation folded into `M⁻¹` per pixel, the unnormalized light vector and
        /// eq. 27's factoring: one square root per light.
        LtcFast = "ltc-fast",
        /// `LtcFast` with `M⁻¹l` and `D` in f16 (GPUs with `SHADER_F16` only).
        LtcF16 = "ltc-f16",
        /// `LtcF16` with two lights per `vec2<f16>` lane pair, light positions relative to the
        /// workgroup's centre (GPUs with `SHADER_F16` only).
        LtcF16Pairs = "ltc-f16-pairs",
        /// The method loaded from a WGSL file (`--method-file`; docs/design.md §5.13): the GPU
        /// only, one file at a time.
        File = "file",
    }
}

impl Method {
    /// The methods every adapter runs.
    pub const F32: [Self; 4] = [Self::Brdf, Self::BrdfFast, Self::Ltc, Self::LtcFast];

    /// The methods that need `SHADER_F16`.
    pub const F16: [Self; 2] = [Self::LtcF16, Self::LtcF16Pairs];

    pub fn is_ltc(self) -> bool {
        matches!(
            self,
            Self::Ltc | Self::LtcFast | Self::LtcF16 | Self::LtcF16Pairs
        )
    }

    pub fn needs_f16(self) -> bool {
        Self::F16.contains(&self)
    }
}

/// What a pixel shows: one method, the two side by side, or their relative difference.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum View {
    /// Method A alone.
    A,
    /// Method B alone.
    B,
    /// A left of the divider, B right of it.
    Split,
    /// `|L_A − L_B| / max(L_B, floor)` on luminance (`metrics::relative_difference`).
    Diff,
}

/// How the LTC table is read per pixel (the `ltc-nearest` study variant uses `Nearest`).
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
pub enum LutFilter {
    /// Bilinear, as a GPU sampler (docs/design.md §2).
    #[default]
    Bilinear,
    /// The nearest cell.
    Nearest,
}

/// Everything about a render that is not the scene or the table.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderSettings {
    pub width: usize,
    pub height: usize,
    /// The approximation (left of a split, the numerator of a difference): a method per
    /// light shape.
    pub a: ShapeMethods,
    /// The reference (right of a split, the denominator of a difference).
    pub b: ShapeMethods,
    pub view: View,
    /// What the LTC methods shade by beyond their table.
    pub rules: LtcRules,
    /// Where `Split` changes from A to B, as a fraction of the width.
    pub divider: f64,
    /// Each 16×16 tile sums only the lights whose range reaches it (the image is the same to
    /// the bit: the others add exactly 0).
    pub cull: bool,
    /// B is an LTC method shading with table B: two tables compared, not LTC against the
    /// BRDF.
    pub b_reads_table_b: bool,
}

/// How an LTC method shades beyond its table: eq. 30's clipping, the normalization, how the
/// table is read, and the horizon rule.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
#[serde(default)]
pub struct LtcRules {
    pub clipping: Clipping,
    pub normalization: Normalization,
    pub filter: LutFilter,
    pub horizon: HorizonRule,
}

impl RenderSettings {
    /// `method` alone, with the paper's rules (both clipping rules, corrected normalization).
    pub fn single(width: usize, height: usize, method: Method) -> Self {
        Self {
            width,
            height,
            a: ShapeMethods::approximations().with(method),
            b: ShapeMethods::references(),
            view: View::A,
            rules: LtcRules::default(),
            divider: 0.5,
            cull: true,
            b_reads_table_b: false,
        }
    }

    /// LTC (paper form) against the exact BRDF, shown as `view`.
    pub fn compare(width: usize, height: usize, view: View) -> Self {
        Self {
            view,
            ..Self::single(width, height, Method::Ltc)
        }
    }

    /// The first pixel column of B in a split image.
    pub fn divider_column(&self) -> usize {
        ((self.divider.clamp(0.0, 1.0) * self.width as f64).round() as usize).min(self.width)
    }

    /// The methods the view needs, A first.
    pub fn methods(&self) -> Vec<Method> {
        match self.view {
            View::A => vec![self.a.point()],
            View::B => vec![self.b.point()],
            View::Split | View::Diff => vec![self.a.point(), self.b.point()],
        }
    }

    /// The same render showing one method alone, as `View::A`.
    pub fn alone(&self, method: Method) -> Self {
        Self {
            a: self.a.with(method),
            view: View::A,
            ..*self
        }
    }
}

/// The tables a render reads: method A's, and method B's where it shades with one of its own
/// (`RenderSettings::b_reads_table_b`).
#[derive(Clone, Copy, Debug)]
pub struct Tables<'a> {
    pub a: &'a Lut,
    pub b: &'a Lut,
}

impl<'a> From<&'a Lut> for Tables<'a> {
    /// One table for both.
    fn from(lut: &'a Lut) -> Self {
        Self { a: lut, b: lut }
    }
}

impl<'a> Tables<'a> {
    /// The table of method B under `settings`.
    pub fn for_b(&self, settings: &RenderSettings) -> &'a Lut {
        if settings.b_reads_table_b {
            self.b
        } else {
            self.a
        }
    }
}

/// What the pixels of a `Frame` hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameKind {
    /// Linear RGB radiance.
    Radiance,
    /// The relative difference of `metrics::relative_difference`, in all three channels.
    RelativeDifference,
}

/// A rendered image, row-major from the top-left, in f64.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    pub width: usize,
    pub height: usize,
    pub kind: FrameKind,
    pub pixels: Vec<DVec3>,
    /// Whether the pixel's ray hit the plane (the rest is background).
    pub on_plane: Vec<bool>,
    /// The split column, for split renders.
    pub divider: Option<usize>,
}

impl Frame {
    /// The first pixel that no file may hold: NaN or infinite anywhere, or a negative value
    /// where the rules forbid one. Only LTC without the case-2 rule (`max(ω'.z, 0)` dropped)
    /// sums negative terms; every term of eq. 28, of eq. 30 and of a difference is ≥ 0.
    pub fn first_invalid(&self, clipping: Clipping) -> Option<(usize, DVec3)> {
        let negative_forbidden = clipping.case2 || self.kind != FrameKind::Radiance;
        self.pixels
            .iter()
            .copied()
            .enumerate()
            .find(|(_, p)| !p.is_finite() || (negative_forbidden && p.min_element() < 0.0))
    }
}

/// A camera ray's hit on the plane, with what shading needs there.
#[derive(Clone, Copy, Debug)]
pub struct SurfacePoint {
    pub position: DVec3,
    /// Unit vector toward the camera, world space.
    pub view: DVec3,
}

/// The shading frame of docs/design.md §1 at a point with normal `+z`: `t1` along the view's
/// tangential part, `t2 = n × t1`. Maps world vectors to frame coordinates.
#[derive(Clone, Copy, Debug)]
pub struct ShadingFrame {
    pub t1: DVec3,
    pub t2: DVec3,
}

/// A material's roughness as a shading point sees it: α along its tangent and its bitangent,
/// and the tangent (world, in the plane).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gloss {
    pub alpha: Alpha<f64>,
    pub tangent: DVec3,
}

impl Gloss {
    /// An isotropic roughness (its tangent is never read).
    pub fn isotropic(alpha: f64) -> Self {
        Self {
            alpha: Alpha::isotropic(alpha),
            tangent: DVec3::X,
        }
    }
}

impl ShadingFrame {
    /// The frame a material is shaded in: the view's (docs/design.md §1.1) when it is
    /// isotropic, its tangent's when it is anisotropic (§1.13: `t1` the tangent, along which
    /// `alpha.x` acts).
    pub fn of(gloss: &Gloss, view: DVec3) -> Self {
        if gloss.alpha.is_isotropic() {
            return Self::new(view);
        }
        let t1 = DVec3::new(gloss.tangent.x, gloss.tangent.y, 0.0)
            .try_normalize()
            .unwrap_or(DVec3::X);
        Self {
            t1,
            t2: DVec3::Z.cross(t1),
        }
    }

    pub fn new(view: DVec3) -> Self {
        let tangential = DVec3::new(view.x, view.y, 0.0);
        // At normal view any tangent will do: the lobes are rotationally symmetric there.
        let t1 = tangential.try_normalize().unwrap_or(DVec3::X);
        Self {
            t1,
            t2: DVec3::Z.cross(t1),
        }
    }

    /// `tangent_from_world` applied to `w`.
    pub fn tangent_from_world(&self, w: DVec3) -> DVec3 {
        DVec3::new(w.dot(self.t1), w.dot(self.t2), w.z)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(kind: FrameKind, p: DVec3) -> Frame {
        Frame {
            width: 1,
            height: 1,
            kind,
            pixels: vec![p],
            on_plane: vec![true],
            divider: None,
        }
    }

    #[test]
    fn no_file_may_hold_nan_inf_or_forbidden_negative_values() {
        let negative = DVec3::new(-1e-5, 0.0, 0.0);
        let radiance = |p| frame(FrameKind::Radiance, p);
        assert!(radiance(DVec3::ONE).first_invalid(Clipping::BOTH).is_none());
        assert!(radiance(DVec3::NAN).first_invalid(Clipping::NONE).is_some());
        assert!(
            radiance(DVec3::INFINITY)
                .first_invalid(Clipping::NONE)
                .is_some()
        );
        // Negative light is the case-2 artifact: allowed exactly when its rule is off.
        assert!(radiance(negative).first_invalid(Clipping::BOTH).is_some());
        assert!(radiance(negative).first_invalid(Clipping::CASE1).is_none());
        let diff = frame(FrameKind::RelativeDifference, negative);
        assert!(diff.first_invalid(Clipping::NONE).is_some());
    }

    #[test]
    fn methods_and_views_are_named_once() {
        for m in Method::ALL {
            assert_eq!(Method::from_name(m.name()), Some(m));
        }
        let s = RenderSettings::compare(4, 2, View::Split);
        assert_eq!(s.methods(), vec![Method::Ltc, Method::Brdf]);
        assert_eq!(s.alone(Method::Brdf).methods(), vec![Method::Brdf]);
        assert_eq!(RenderSettings { divider: 0.25, ..s }.divider_column(), 1);
    }
}
