//! Integrals over a polygon of directions in f64 (docs/design.md §1.11): the ground truth of
//! rect lights. Each triangle of a fan is integrated over its area, Gauss–Legendre nodes
//! collapsed onto it (Duffy), `dω = cos θ_x dA / |x|²`; the fan meets where a glossy lobe
//! peaks, and each of its triangles is split at its point nearest the shading point, so the
//! nodes crowd at both peaks.

use glam::DVec3;

use crate::light::sphere::quadrature::gauss_legendre;

/// `∫ g(ω) dω` over the directions of the convex planar polygon `poly` (its corners in either
/// order): each triangle of a fan from its point nearest the origin integrated over its area,
/// `n × n` Gauss–Legendre nodes collapsed onto the triangle (Duffy), `dω = cos θ_x dA / |x|²`.
pub fn polygon_integral<const K: usize>(
    poly: &[DVec3],
    n: usize,
    g: impl Fn(DVec3) -> [f64; K],
) -> [f64; K] {
    polygon_integral_about(poly, n, None, g)
}

/// `polygon_integral` for an integrand peaked about the direction `focus` (a glossy lobe's
/// mirror direction). Two peaks are served: the fan meets where `focus` points into the
/// polygon (the lobe's peak, which can be arbitrarily sharp), else at the polygon's point
/// nearest the shading point; and each fan triangle is split into three at its own point
/// nearest the shading point, where `cos θ_x / |x|²` peaks (of width the distance: the sharper
/// peak for a large light close by). That point moves continuously with the light, so the
/// rule has no choice that f32 and f64 could make apart. Duffy's collapse crowds each
/// triangle's nodes at its apex.
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
    let apex = focus
        .and_then(|f| hit_inside(poly, f))
        .unwrap_or_else(|| nearest_point(poly).0);
    for k in 0..poly.len() {
        let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
        let (x, _) = nearest_point(&[apex, a, b]);
        for (p, q) in [(apex, a), (a, b), (b, apex)] {
            add_triangle(&mut total, &rule, [x, p, q], &g);
        }
    }
    total
}

/// One triangle's `∫ g dω`, `n × n` nodes collapsed onto its first corner (Duffy): (s, t) on
/// the unit square to `p0 + s e1 + s t (e2 − e1)`, whose Jacobian is `s |e1 × e2|`.
fn add_triangle<const K: usize>(
    total: &mut [f64; K],
    rule: &[(f64, f64)],
    [p0, a, b]: [DVec3; 3],
    g: &impl Fn(DVec3) -> [f64; K],
) {
    let (e1, e2) = (a - p0, b - p0);
    let normal = e1.cross(e2);
    let twice_area = normal.length();
    if twice_area == 0.0 {
        return;
    }
    let unit = normal / twice_area;
    for &(xs, ws) in rule {
        let s = 0.5 * (xs + 1.0);
        for &(xt, wt) in rule {
            let t = 0.5 * (xt + 1.0);
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

/// The point of the convex planar polygon `poly` nearest the origin, and whether it is the
/// foot of the perpendicular (inside) rather than the nearest point of its edges.
pub fn nearest_point(poly: &[DVec3]) -> (DVec3, bool) {
    let normal = (poly[1] - poly[0]).cross(poly[2] - poly[0]);
    let foot = normal * (poly[0].dot(normal) / normal.length_squared());
    if normal.length_squared() > 0.0 && inside(poly, foot, normal) {
        return (foot, true);
    }
    (0..poly.len())
        .map(|k| {
            let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
            let t = (-a.dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
            if t.is_finite() { a + (b - a) * t } else { a }
        })
        .min_by(|x, y| x.length_squared().total_cmp(&y.length_squared()))
        .map_or((poly[0], false), |x| (x, false))
}

/// Whether `x`, in the plane of the convex polygon `poly` (of normal `normal`), is inside it.
fn inside(poly: &[DVec3], x: DVec3, normal: DVec3) -> bool {
    let side = |k: usize| {
        let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
        (b - a).cross(x - a).dot(normal)
    };
    (0..poly.len()).all(|k| side(k) >= 0.0) || (0..poly.len()).all(|k| side(k) <= 0.0)
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
    inside(poly, x, normal).then_some(x)
}
