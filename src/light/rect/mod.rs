//! Rect lights, the paper's own case (Heitz et al. 2016; docs/design.md §1.11): a one-sided
//! parallelogram (a rectangle where its half-edges are perpendicular) of uniform radiance,
//! in the shading frame (`n = +z`, the shading point at the origin). The polygon it covers
//! and the LTC over it are in `polygon`, the exact integral's rule in `quadrature`; here the
//! light, its methods and their dispatch.

pub mod form;
pub mod polygon;
pub mod quadrature;
pub mod region;

use glam::DVec3;

use crate::brdf::{self, Alpha, Lobes};
use crate::light::{EmitterLobes, EmitterShading, ExactRule};
use crate::named::named_enum;

pub use form::{EVAL_COLUMNS, PRESETS, SIZES, VECTORS, bench_shape, bench_title, eval_row};

pub use polygon::{
    clip_horizon, ltc_polygon, ltc_proxy, ltc_proxy_fast, polygon_form_factor, proxy_sphere,
    proxy_sphere_fast, vector_form_factor,
};
pub use quadrature::{polygon_integral, polygon_integral_about};

/// A rectangle: its centre and two half-edge vectors; it emits toward `u × v` only.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rect {
    pub centre: DVec3,
    pub u: DVec3,
    pub v: DVec3,
}

impl Rect {
    /// Its four corners, `c − u − v`, `c + u − v`, `c + u + v`, `c − u + v`: a convex polygon
    /// whose order turns about `u × v`.
    pub fn corners(&self) -> [DVec3; 4] {
        let (c, u, v) = (self.centre, self.u, self.v);
        [c - u - v, c + u - v, c + u + v, c - u + v]
    }

    /// `u × v`: its normal (the side it emits toward), of length a quarter of its area.
    pub fn normal(&self) -> DVec3 {
        self.u.cross(self.v)
    }

    /// Its area, `4 |u × v|`.
    pub fn area(&self) -> f64 {
        4.0 * self.normal().length()
    }

    /// Whether the shading point (the origin) is on the side it emits toward.
    pub fn faces_origin(&self) -> bool {
        self.centre.dot(self.normal()) < 0.0
    }

    /// `(|u| + |v|) / |c|`: a bound on the angle its half-diagonal subtends (`RECT_POINT_LIMIT`).
    pub fn angular_size(&self) -> f64 {
        (self.u.length() + self.v.length()) / self.centre.length()
    }

    /// The irradiance of its oriented point light at unit radiance: `A cos θe / d²`, with
    /// `θe` between its normal and the direction to the origin.
    pub fn point_irradiance(&self) -> f64 {
        let d2 = self.centre.length_squared();
        let cos_e = -self.normal().normalize().dot(self.centre) / d2.sqrt();
        self.area() * cos_e.max(0.0) / d2
    }
}

named_enum! {
    /// The ways a rect light is shaded (docs/design.md §1.11).
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
    pub enum RectMethod {
        /// The BRDF integrated over the rect's directions above the surface (`rect_exact`).
        Exact = "exact",
        /// Heitz et al. 2016: the rect clipped at the horizon, mapped by `M⁻¹`, clipped at
        /// the cosine's horizon, Lambert's edge sum (`ltc_polygon`).
        LtcPolygon = "ltc-polygon",
        /// Heitz & Hill 2017: the unclipped vector form factor of `M⁻¹P`, then the clipped
        /// cap of the same vector form factor (`proxy_sphere`).
        LtcProxy = "ltc-proxy",
        /// The proxy's closed-form approximation three.js ships (`proxy_sphere_fast`).
        LtcProxyFast = "ltc-proxy-fast",
        /// The centre as an oriented point light of intensity `L·A·cos θe` (the limit).
        LtcPoint = "ltc-point",
    }
}

impl RectMethod {
    /// One line for a reader of the lab or the command line.
    pub fn describe(self) -> &'static str {
        match self {
            Self::Exact => {
                "The BRDF integrated over the rect above the surface (8 Gauss–Legendre nodes per dimension and triangle in renders): the reference"
            }
            Self::LtcPolygon => {
                "Heitz et al. 2016: the rect clipped at the horizon, mapped by M⁻¹, Lambert's edge formula (the paper's own case)"
            }
            Self::LtcProxy => {
                "Heitz & Hill 2017: M⁻¹P's unclipped vector form factor, clipped as the sphere of the same form factor (ltc_code's second table)"
            }
            Self::LtcProxyFast => {
                "The proxy's closed form three.js ships: max((|F|² + F.z)/(|F| + 1), 0)"
            }
            Self::LtcPoint => {
                "The rect's centre as an oriented point light of intensity L·A·cos θe"
            }
        }
    }
}

/// Gauss–Legendre nodes per dimension and triangle of `RectMethod::Exact` in `rect_light`:
/// tests/lights/rect_light.rs holds the rule to its bound against Lambert's closed form.
pub const EXACT_NODES: usize = 64;

/// Below this `angular_size` every method shades a rect as its oriented point light. The
/// edge formula sums terms of size `s/d` to a value of size `(s/d)²`: its f32 rounding is
/// some `2⁻²⁴ d/s` of the value, 6e-5 here, while the point light differs from the rect by
/// `O((s/d)²)` of the lobe's curvature, 1e-6 here (tests/lights/rect_light.rs measures both).
pub const RECT_POINT_LIMIT: f64 = 1e-3;

/// One rect light of unit radiance at one shading point: everything the methods read.
#[derive(Clone, Copy, Debug)]
pub struct RectShading<'a> {
    /// The view, the material, the LTC lobes and the rules (every emitter's).
    pub pixel: EmitterShading<'a>,
    pub rect: Rect,
}

/// A rect's unit-radiance lobes by `method` and its area (`EmitterLobes`), centred at
/// `centre` from the shading point with half-edges `half_u`, `half_v` (world, mapped to the
/// shading frame by `to_frame`), the exact method by `rule` (cpu::shape_term's, eval's).
pub fn emitter_lobes(
    method: RectMethod,
    (centre, half_u, half_v): (DVec3, DVec3, DVec3),
    to_frame: &dyn Fn(DVec3) -> DVec3,
    s: &EmitterShading<'_>,
    rule: ExactRule,
) -> EmitterLobes {
    let rect = Rect {
        centre: to_frame(centre),
        u: to_frame(half_u),
        v: to_frame(half_v),
    };
    let shading = RectShading { pixel: *s, rect };
    (rect_light_with(method, &shading, rule), rect.area())
}

/// The radiance toward `v` of a rect of unit radiance, per lobe (base colour 1), the exact
/// method by `EXACT_NODES`. A rect facing away gives 0.
pub fn rect_light(method: RectMethod, s: &RectShading<'_>) -> Lobes<f64> {
    rect_light_with(method, s, ExactRule::Nodes(EXACT_NODES))
}

/// `rect_light` with the exact method by `rule` (the renders take `ExactRule::Render`).
pub fn rect_light_with(method: RectMethod, s: &RectShading<'_>, rule: ExactRule) -> Lobes<f64> {
    if !s.rect.faces_origin() {
        return Lobes::default();
    }
    if s.rect.angular_size() < RECT_POINT_LIMIT {
        return rect_point(method, s);
    }
    let corners = s.rect.corners();
    let (clip, normalization) = (s.pixel.clip, s.pixel.normalization);
    match method {
        RectMethod::Exact => match rule {
            ExactRule::Nodes(nodes) => {
                rect_exact(s.pixel.v, &s.rect, s.pixel.alpha, s.pixel.f0, nodes)
            }
            ExactRule::Render => region::rect_rule(s.pixel.v, &s.rect, s.pixel.alpha, s.pixel.f0),
        },
        RectMethod::LtcPolygon => {
            by_lobe(s, &|ltc| ltc_polygon(ltc, &corners, clip, normalization))
        }
        RectMethod::LtcProxy => by_lobe(s, &|ltc| ltc_proxy(ltc, &corners, clip, normalization)),
        RectMethod::LtcProxyFast => {
            by_lobe(s, &|ltc| ltc_proxy_fast(ltc, &corners, clip, normalization))
        }
        RectMethod::LtcPoint => rect_point(method, s),
    }
}

/// Each lobe's integral times its magnitude (none for the paper-literal normalization).
fn by_lobe(s: &RectShading<'_>, integral: &dyn Fn(&crate::ltc::Ltc) -> f64) -> Lobes<f64> {
    let (spec_weight, diff_weight) = s.pixel.ltc.lobe_weights(s.pixel.f0, s.pixel.normalization);
    Lobes {
        specular: spec_weight * integral(&s.pixel.ltc.spec),
        diffuse: diff_weight * integral(&s.pixel.ltc.diff),
    }
}

/// The rect as its oriented point light at the centre (`point_irradiance`): the exact point
/// light for the exact method, the paper's point formula for the LTC ones.
pub fn rect_point(method: RectMethod, s: &RectShading<'_>) -> Lobes<f64> {
    let e = s.rect.point_irradiance();
    let l = s.rect.centre.normalize();
    let exact = method == RectMethod::Exact;
    s.pixel.point_light(exact, l, e)
}

/// The exact radiance of a rect of unit radiance toward `v`, per lobe (base colour 1):
/// `∫ f(v, ω) cos ω dω` over its directions above the surface, `n × n` nodes a triangle.
pub fn rect_exact(v: DVec3, rect: &Rect, alpha: Alpha<f64>, f0: f64, n: usize) -> Lobes<f64> {
    if !rect.faces_origin() {
        return Lobes::default();
    }
    let above = clip_horizon(&rect.corners());
    // The specular lobe peaks about the mirror direction: the rule crowds its nodes there.
    let mirror = DVec3::new(-v.x, -v.y, v.z);
    let [specular, diffuse] = polygon_integral_about(&above, n, Some(mirror), |l| {
        let lobes = brdf::brdf_cos_aniso(v.to_array(), l.to_array(), alpha, f0);
        [lobes.specular, lobes.diffuse]
    });
    Lobes { specular, diffuse }
}
