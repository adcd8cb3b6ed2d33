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
    // Clipped, the integral is ≥ 0: what rounding leaves below it is 0.
    let integral = if clip.case2 {
        integral.max(0.0)
    } else {
        integral
    };
    paper_scale(integral, normalization)
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
