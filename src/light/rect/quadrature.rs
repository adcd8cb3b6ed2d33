//! Integrals over a polygon of directions in f64 (docs/design.md §1.11): the ground truth of
//! rect lights. Each triangle of a fan is integrated over its area, Gauss–Legendre nodes
//! collapsed onto it (Duffy), `dω = cos θ_x dA / |x|²`; for a glossy lobe the fan's apex is
//! where the lobe peaks, so the nodes crowd there.

use glam::DVec3;

use crate::light::sphere::quadrature::gauss_legendre;

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
