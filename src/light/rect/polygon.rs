//! The clamped cosine over a polygon of directions (docs/design.md §1.11): the polygon clipped
//! at a horizon, Lambert's edge formula for its vector form factor, the LTC over it
//! (`∫_P D = ∫_{M⁻¹P} Do`, Heitz et al. 2016) and Heitz & Hill 2017's proxy for the clipped
//! integral, with three.js's closed form of it. Everything seen from the origin, `n = +z`.

use std::f64::consts::PI;

use glam::DVec3;

use crate::ltc::{Clipping, Ltc, Normalization};

/// The part of the convex polygon `poly` with `z ≥ 0` (Sutherland–Hodgman against one plane):
/// empty where none of it is above; one corner more at most.
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

/// The vector form factor of the polygon `poly` seen from the origin, unclipped:
/// `(1/2π) Σ θ_e n̂_e` (Lambert's edge formula), with `θ_e` the angle an edge subtends and
/// `n̂_e` the unit normal of the plane through it and the origin. Positive z for a polygon
/// whose corners turn clockwise seen from the origin (a `Rect` that faces it). `n̂_e` and
/// `θ_e` come from the corners themselves, `a × b` and `atan2(|a × b|, a·b)`, not from their
/// unit directions: the cross product of two nearly parallel unit vectors keeps only
/// `ε/θ_e` of relative precision, the small polygon's whole value in f32 (shaders/rect_light.wgsl).
pub fn vector_form_factor(poly: &[DVec3]) -> DVec3 {
    let n = poly.len();
    if n < 3 {
        return DVec3::ZERO;
    }
    // The formula does not see the polygon's scale: scaled to a largest component of 1, as
    // the shader must (far or mapped corners overflow f32's |a × b|²).
    let big = poly
        .iter()
        .map(|p| p.abs().max_element())
        .fold(0.0, f64::max);
    if big == 0.0 {
        return DVec3::ZERO;
    }
    let sum: DVec3 = (0..n)
        .map(|k| edge_vector(poly[k] / big, poly[(k + 1) % n] / big))
        .sum();
    -sum / (2.0 * PI)
}

/// One edge's `θ_e n̂_e` (`vector_form_factor`).
pub fn edge_vector(a: DVec3, b: DVec3) -> DVec3 {
    let cross = a.cross(b);
    let len = cross.length();
    if len == 0.0 {
        return DVec3::ZERO;
    }
    cross * (len.atan2(a.dot(b)) / len)
}

/// `(1/π) ∫ ω.z dω` over the polygon's directions, signed (directions below `z = 0` count
/// negatively): the vector form factor's z. The clamped cosine's integral is this over
/// `clip_horizon(poly)`.
pub fn polygon_form_factor(poly: &[DVec3]) -> f64 {
    vector_form_factor(poly).z
}

/// `∫ D(ω) dω` of one LTC lobe over the convex polygon `poly` (a facing `Rect`'s corners):
/// the polygon clipped at the surface's horizon first where `clip.case1` (off: the light below
/// the surface is lifted by `M⁻¹`, ltc_code's leak), its corners mapped by `M⁻¹`, then the
/// clamped cosine's integral where `clip.case2` (the clipped polygon's form factor), or the
/// signed one where not.
///
/// Both clips are made edge by edge, with no clipped polygon built (a shader's list of a
/// changing length is slow): `M⁻¹` keeps an edge's parameter, so each edge is cut to the part
/// `t ∈ [t₀, t₁]` above both horizons, the surface's read from the corners' own heights, the
/// cosine's from the mapped ones. The clipped polygon's boundary is those parts and, from
/// each point where the polygon leaves the region above both horizons to the next where it
/// comes back, a path along the horizon it left by: straight where it comes back by the same
/// one, else through the line where the two meet. tests/lights/rect_light.rs holds it to
/// Sutherland–Hodgman's clipped polygon (`clip_horizon`).
pub fn ltc_polygon(ltc: &Ltc, poly: &[DVec3], clip: Clipping, normalization: Normalization) -> f64 {
    let n = poly.len();
    if n < 3 {
        return 0.0;
    }
    let m = ltc.cos_from_brdf;
    let mapped: Vec<DVec3> = poly.iter().map(|&p| m * p).collect();
    let meet = horizons_meet(m, &mapped, clip);
    // A path along the horizons from a point where the polygon leaves (on horizon `from`)
    // to one where it comes back (on `to`).
    let along = |(e, from): (DVec3, u8), (s, to): (DVec3, u8)| match meet {
        Some(c) if from != to => edge_vector(e, c) + edge_vector(c, s),
        _ => edge_vector(e, s),
    };
    let mut sum = DVec3::ZERO;
    // The point where the polygon last left, and where it first came back before leaving.
    let (mut left, mut first_back) = (None, None);
    for k in 0..n {
        let (p, q) = (poly[k], poly[(k + 1) % n]);
        let (a, b) = (mapped[k], mapped[(k + 1) % n]);
        let mut range = Cut::WHOLE;
        if clip.case1 {
            range = range.cut(p.z, q.z, 1);
        }
        if clip.case2 {
            range = range.cut(a.z, b.z, 2);
        }
        if range.t0 > range.t1 {
            continue;
        }
        let (x0, x1) = (a + (b - a) * range.t0, a + (b - a) * range.t1);
        if range.t0 > 0.0 {
            match left.take() {
                Some(exit) => sum += along(exit, (x0, range.plane0)),
                None => first_back = Some((x0, range.plane0)),
            }
        }
        sum += edge_vector(x0, x1);
        if range.t1 < 1.0 {
            left = Some((x1, range.plane1));
        }
    }
    if let (Some(exit), Some(back)) = (left, first_back) {
        sum += along(exit, back);
    }
    // M⁻¹ with a negative determinant turns the polygon over: its form factor's sign with it.
    let sign = m.determinant().signum();
    let integral = -sign * sum.z / (2.0 * PI);
    // Clipped, the integral is ≥ 0: what rounding leaves below it is 0.
    let integral = if clip.case2 {
        integral.max(0.0)
    } else {
        integral
    };
    paper_scale(integral, normalization)
}

/// The part `t ∈ [t0, t1]` of an edge that is kept, and the horizon (1 the surface's, 2 the
/// cosine's, 0 none) that cut each end.
#[derive(Clone, Copy, Debug)]
pub struct Cut {
    pub t0: f64,
    pub t1: f64,
    pub plane0: u8,
    pub plane1: u8,
}

impl Cut {
    pub const WHOLE: Self = Self {
        t0: 0.0,
        t1: 1.0,
        plane0: 0,
        plane1: 0,
    };

    /// What of `self` keeps a height going from `f0` to `f1` (linearly in `t`) at or above
    /// 0, cut by horizon `plane`; `t0 > t1` where nothing is.
    pub fn cut(self, f0: f64, f1: f64, plane: u8) -> Self {
        match (f0 < 0.0, f1 < 0.0) {
            (true, true) => Self {
                t0: 1.0,
                t1: 0.0,
                ..self
            },
            (true, false) if f0 / (f0 - f1) > self.t0 => Self {
                t0: f0 / (f0 - f1),
                plane0: plane,
                ..self
            },
            (false, true) if f0 / (f0 - f1) < self.t1 => Self {
                t1: f0 / (f0 - f1),
                plane1: plane,
                ..self
            },
            _ => self,
        }
    }
}

/// Where both horizons are clipped at, the direction (in the mapped space) where they meet
/// that the mapped polygon `mapped` holds: the original `ẑ × r` (`r` the last row of `M⁻¹`,
/// so that both `p.z` and `(M⁻¹p).z` are 0), mapped, or its opposite.
pub fn horizons_meet(m: glam::DMat3, mapped: &[DVec3], clip: Clipping) -> Option<DVec3> {
    if !(clip.case1 && clip.case2) {
        return None;
    }
    let r = m.row(2);
    let line = m * DVec3::new(-r.y, r.x, 0.0);
    if line == DVec3::ZERO {
        return None;
    }
    // Inside: on the side of each edge that the polygon's own centre is on.
    let n = mapped.len();
    let centre: DVec3 = mapped.iter().sum();
    let inside = |c: DVec3| {
        (0..n).all(|k| {
            let normal = mapped[k].cross(mapped[(k + 1) % n]);
            normal.dot(c) * normal.dot(centre) >= 0.0
        })
    };
    [line, -line].into_iter().find(|&c| inside(c))
}

/// Heitz & Hill 2017's proxy for one lobe: the unclipped vector form factor `f` of `M⁻¹P`,
/// then the cap of the same vector form factor clipped at the horizon (`proxy_sphere`) where
/// `case2`, or `f.z` (the signed integral) where not.
pub fn ltc_proxy(ltc: &Ltc, poly: &[DVec3], clip: Clipping, normalization: Normalization) -> f64 {
    let f = mapped_form_factor(ltc, poly);
    let integral = if clip.case2 { proxy_sphere(f) } else { f.z };
    paper_scale(integral, normalization)
}

/// `ltc_proxy` with three.js's closed form (`proxy_sphere_fast`) for the clipped cap.
pub fn ltc_proxy_fast(
    ltc: &Ltc,
    poly: &[DVec3],
    clip: Clipping,
    normalization: Normalization,
) -> f64 {
    let f = mapped_form_factor(ltc, poly);
    let integral = if clip.case2 {
        proxy_sphere_fast(f)
    } else {
        f.z
    };
    paper_scale(integral, normalization)
}

/// The vector form factor of `M⁻¹P`, turned back over where `M⁻¹` turns it.
fn mapped_form_factor(ltc: &Ltc, poly: &[DVec3]) -> DVec3 {
    let mapped: Vec<DVec3> = poly.iter().map(|&p| ltc.cos_from_brdf * p).collect();
    ltc.cos_from_brdf.determinant().signum() * vector_form_factor(&mapped)
}

/// The printed eq. 25 drops D's 1/π: the paper-literal integral is π times the corrected one.
fn paper_scale(integral: f64, normalization: Normalization) -> f64 {
    match normalization {
        Normalization::Corrected => integral,
        Normalization::PaperLiteral => PI * integral,
    }
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
