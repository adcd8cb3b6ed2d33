//! Rect lights, the paper's own case (Heitz et al. 2016): a one-sided rectangle of uniform
//! radiance `L`, in the shading frame (`n = +z`, the shading point at the origin). The
//! polygon it covers, clipped at a horizon; the clamped cosine's integral over a polygon by
//! Lambert's edge formula; the exact BRDF integral over it by quadrature in f64; and the LTC
//! over it (`ltc_polygon`): `∫_P D = ∫_{M⁻¹P} Do`, the polygon's vertices mapped by `M⁻¹`.

use std::f64::consts::PI;

use glam::DVec3;

use crate::brdf::Lobes;
use crate::light::sphere::quadrature::gauss_legendre;
use crate::ltc::{Clipping, Ltc, LtcPair, Normalization};
use crate::named::named_enum;

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
}

/// The part of the convex polygon `poly` with `z ≥ 0` (Sutherland–Hodgman against one plane):
/// empty where none of it is above.
pub fn clip_horizon(poly: &[DVec3]) -> Vec<DVec3> {
    let mut out = Vec::with_capacity(poly.len() + 1);
    for (k, &a) in poly.iter().enumerate() {
        let b = poly[(k + 1) % poly.len()];
        if a.z >= 0.0 {
            out.push(a);
        }
        if (a.z >= 0.0) != (b.z >= 0.0) {
            // Where the edge crosses z = 0.
            let t = a.z / (a.z - b.z);
            let p = a + (b - a) * t;
            out.push(DVec3::new(p.x, p.y, 0.0));
        }
    }
    out
}

/// `(1/π) ∫ ω.z dω` over the directions of the polygon `poly` seen from the origin, signed
/// (directions below `z = 0` count negatively): Lambert's edge formula,
/// `(1/2π) Σ θ_e n̂_e.z`, with `θ_e` the angle an edge subtends and `n̂_e` the unit normal of
/// the plane through it and the origin. Positive for a polygon whose corners turn clockwise
/// seen from the origin (a `Rect` that faces it). The clamped cosine's integral is this over
/// `clip_horizon(poly)`.
pub fn polygon_form_factor(poly: &[DVec3]) -> f64 {
    vector_form_factor(poly).z
}

/// `∫ g(ω) dω` over the directions of the convex polygon `poly` (its corners in either
/// order): each triangle of a fan from its first corner integrated over its area, `n × n`
/// Gauss–Legendre nodes collapsed onto the triangle (Duffy), `dω = cos θ_x dA / |x|²`.
pub fn polygon_integral<const K: usize>(
    poly: &[DVec3],
    n: usize,
    g: impl Fn(DVec3) -> [f64; K],
) -> [f64; K] {
    polygon_integral_about(poly, n, None, g)
}

/// `polygon_integral` for an integrand peaked about the direction `focus` (a glossy lobe's
/// mirror direction): where it points into the polygon, the fan's triangles all meet at the
/// point it hits, where Duffy's collapse crowds their nodes, so the rule converges on a sharp
/// lobe as on a smooth one.
pub fn polygon_integral_about<const K: usize>(
    poly: &[DVec3],
    n: usize,
    focus: Option<DVec3>,
    g: impl Fn(DVec3) -> [f64; K],
) -> [f64; K] {
    let rule = gauss_legendre(n);
    let mut total = [0.0; K];
    if poly.len() < 3 {
        return total;
    }
    // The fan's apex and its triangles' far edges: the focus's hit where it is inside, every
    // edge then; else the first corner, and the edges not through it.
    let apex = focus.and_then(|f| hit_inside(poly, f));
    let (p0, edges): (DVec3, Vec<(DVec3, DVec3)>) = match apex {
        Some(x) => (
            x,
            (0..poly.len())
                .map(|k| (poly[k], poly[(k + 1) % poly.len()]))
                .collect(),
        ),
        None => (
            poly[0],
            (1..poly.len() - 1)
                .map(|k| (poly[k], poly[k + 1]))
                .collect(),
        ),
    };
    for (a, b) in edges {
        let (e1, e2) = (a - p0, b - p0);
        let normal = e1.cross(e2);
        let twice_area = normal.length();
        if twice_area == 0.0 {
            continue;
        }
        let unit = normal / twice_area;
        for &(xs, ws) in &rule {
            let s = 0.5 * (xs + 1.0);
            for &(xt, wt) in &rule {
                let t = 0.5 * (xt + 1.0);
                // (s, t) on the unit square onto the triangle: x = p0 + s e1 + s t (e2 − e1),
                // whose Jacobian is s · |e1 × e2|.
                let x = p0 + e1 * s + (e2 - e1) * (s * t);
                let r2 = x.length_squared();
                if r2 == 0.0 {
                    continue;
                }
                let r = r2.sqrt();
                let cos_x = (x.dot(unit) / r).abs();
                let weight = 0.25 * ws * wt * s * twice_area * cos_x / r2;
                for (acc, value) in total.iter_mut().zip(g(x / r)) {
                    *acc += weight * value;
                }
            }
        }
    }
    total
}

/// Where the ray from the origin along `direction` meets the plane of the convex polygon
/// `poly`, if that point lies inside it.
fn hit_inside(poly: &[DVec3], direction: DVec3) -> Option<DVec3> {
    let normal = (poly[1] - poly[0]).cross(poly[2] - poly[0]);
    let along = direction.dot(normal);
    if along == 0.0 {
        return None;
    }
    let t = poly[0].dot(normal) / along;
    if t <= 0.0 {
        return None;
    }
    let x = direction * t;
    let side = |k: usize| {
        let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
        (b - a).cross(x - a).dot(normal)
    };
    let inside = (0..poly.len()).all(|k| side(k) >= 0.0) || (0..poly.len()).all(|k| side(k) <= 0.0);
    inside.then_some(x)
}

/// `∫ D(ω) dω` of one LTC lobe over the polygon `poly` (a facing `Rect`'s corners): the
/// polygon clipped at the surface's horizon first where `clip.case1` (off: the light below
/// the surface is lifted by `M⁻¹`, ltc_code's leak), its corners mapped by `M⁻¹`, then the
/// clamped cosine's integral where `clip.case2` (the clipped polygon's form factor), or the
/// signed one where not.
pub fn ltc_polygon(ltc: &Ltc, poly: &[DVec3], clip: Clipping, normalization: Normalization) -> f64 {
    let above;
    let poly = if clip.case1 {
        above = clip_horizon(poly);
        &above[..]
    } else {
        poly
    };
    let mapped: Vec<DVec3> = poly.iter().map(|&p| ltc.cos_from_brdf * p).collect();
    let mapped = if clip.case2 {
        clip_horizon(&mapped)
    } else {
        mapped
    };
    // M⁻¹ with a negative determinant turns the polygon over: its form factor's sign with it.
    let sign = ltc.cos_from_brdf.determinant().signum();
    let integral = sign * polygon_form_factor(&mapped);
    match normalization {
        Normalization::Corrected => integral,
        // The printed eq. 25 drops D's 1/π.
        Normalization::PaperLiteral => PI * integral,
    }
}

/// The exact radiance of a rect of unit radiance toward `v`, per lobe (base colour 1):
/// `∫ f(v, ω) cos ω dω` over its directions above the surface, `n × n` nodes a triangle.
pub fn rect_exact(v: DVec3, rect: &Rect, alpha: f64, f0: f64, n: usize) -> Lobes<f64> {
    if !rect.faces_origin() {
        return Lobes::default();
    }
    let above = clip_horizon(&rect.corners());
    // The specular lobe peaks about the mirror direction: the rule crowds its nodes there.
    let mirror = DVec3::new(-v.x, -v.y, v.z);
    let [specular, diffuse] = polygon_integral_about(&above, n, Some(mirror), |l| {
        let lobes = crate::brdf::brdf_cos(v.to_array(), l.to_array(), alpha, f0);
        [lobes.specular, lobes.diffuse]
    });
    Lobes { specular, diffuse }
}

/// The vector form factor of the polygon `poly` seen from the origin, unclipped:
/// `(1/2π) Σ θ_e n̂_e`, oriented as `polygon_form_factor` (whose value is its z).
pub fn vector_form_factor(poly: &[DVec3]) -> DVec3 {
    let n = poly.len();
    if n < 3 {
        return DVec3::ZERO;
    }
    let sum: DVec3 = (0..n)
        .map(|k| {
            let (a, b) = (poly[k].normalize(), poly[(k + 1) % n].normalize());
            let cross = a.cross(b);
            let len = cross.length();
            if len == 0.0 {
                return DVec3::ZERO;
            }
            cross * (len.atan2(a.dot(b)) / len)
        })
        .sum();
    -sum / (2.0 * PI)
}

/// Heitz & Hill 2017's proxy for the clipped integral: the cap of the same vector form
/// factor `f` (its axis along `f`, `sin²σ = |f|`), clipped at the horizon in closed form
/// (`ltc::sphere::illuminance_sphere`, the value ltc_code's second table holds).
pub fn proxy_sphere(f: DVec3) -> f64 {
    let len = f.length();
    if len == 0.0 {
        return 0.0;
    }
    crate::ltc::sphere::illuminance_sphere(f.z / len, len.min(1.0)) / PI
}

/// The closed form three.js ships instead (`LTC_ClippedSphereFormFactor`):
/// `max((|f|² + f.z) / (|f| + 1), 0)`, an approximation of `proxy_sphere`.
pub fn proxy_sphere_fast(f: DVec3) -> f64 {
    let len = f.length();
    ((len * len + f.z) / (len + 1.0)).max(0.0)
}

named_enum! {
    /// The ways a rect light is shaded (docs/design.md §1.11).
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
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

/// Gauss–Legendre nodes per dimension and triangle of `RectMethod::Exact` in `rect_light`:
/// tests/rect_light.rs holds the rule to its bound against Lambert's closed form.
pub const EXACT_NODES: usize = 64;

/// One rect light of unit radiance at one shading point: everything the methods read.
#[derive(Clone, Copy, Debug)]
pub struct RectShading<'a> {
    pub v: DVec3,
    pub rect: Rect,
    pub alpha: f64,
    pub f0: f64,
    /// The LTC lobes at this pixel's (θo, α).
    pub ltc: &'a LtcPair,
}

/// The radiance toward `v` of a rect of unit radiance, per lobe (base colour 1), with the
/// lab's rules (both clipping rules, corrected normalization). A rect facing away gives 0.
pub fn rect_light(method: RectMethod, s: &RectShading<'_>) -> Lobes<f64> {
    if !s.rect.faces_origin() {
        return Lobes::default();
    }
    let corners = s.rect.corners();
    let (clip, normalization) = (Clipping::BOTH, Normalization::Corrected);
    let magnitudes = (s.ltc.spec_magnitude(s.f0), s.ltc.diff.magnitude());
    let by_lobe = |integral: &dyn Fn(&Ltc) -> f64| Lobes {
        specular: magnitudes.0 * integral(&s.ltc.spec),
        diffuse: magnitudes.1 * integral(&s.ltc.diff),
    };
    let mapped_factor = |ltc: &Ltc| {
        let mapped: Vec<DVec3> = corners.iter().map(|&p| ltc.cos_from_brdf * p).collect();
        vector_form_factor(&mapped)
    };
    match method {
        RectMethod::Exact => rect_exact(s.v, &s.rect, s.alpha, s.f0, EXACT_NODES),
        RectMethod::LtcPolygon => by_lobe(&|ltc| ltc_polygon(ltc, &corners, clip, normalization)),
        RectMethod::LtcProxy => by_lobe(&|ltc| proxy_sphere(mapped_factor(ltc))),
        RectMethod::LtcProxyFast => by_lobe(&|ltc| proxy_sphere_fast(mapped_factor(ltc))),
        RectMethod::LtcPoint => {
            let c = s.rect.centre;
            let d = c.length();
            let cos_e = s.rect.normal().normalize().dot(-c / d);
            let e = s.rect.area() * cos_e / (d * d);
            let lobes = s.ltc.ltc_lobes(c / d, s.f0, clip, normalization);
            Lobes {
                specular: e * lobes.specular,
                diffuse: e * lobes.diffuse,
            }
        }
    }
}
