//! A smooth integrand over a spherical polygon as a fan from a pole to its edges
//! (docs/design.md §1.14): `∫ g dω = Σ_edges ∫ (∫_0^{u_B} g sin u du) dψ`, each edge's
//! points `B` uniform in the angle they turn, each meridian from the pole to `B` in `u`.
//! `shaders/fan.wgsl` has it by name.
//!
//! Against the polar rule's azimuth, an edge's own parameter keeps a thin polygon (a strip
//! light, a rect seen edge-on) smooth: where an edge passes close to the pole the azimuth
//! sweeps fast but the meridians are short, and the two cancel (`dψ/ds = (c·n̂) / sin² u_B`).

use glam::DVec3;

use crate::light::polar::rule;

/// `∫ g(ω) dω` over the convex spherical polygon of unit corners `corners` (in order), by
/// the fan from the unit `pole` inside it, `n × n` Gauss–Legendre nodes an edge.
pub fn fan_integral(corners: &[DVec3], pole: DVec3, n: usize, g: impl Fn(DVec3) -> f64) -> f64 {
    let rule = rule(n);
    let mut total = 0.0;
    for k in 0..corners.len() {
        let (a, b) = (corners[k], corners[(k + 1) % corners.len()]);
        let turn = a.cross(b).length().atan2(a.dot(b));
        if turn <= 0.0 {
            continue;
        }
        let k_sin = 1.0 / turn.sin();
        for &(xs, ws) in rule {
            let s = 0.5 * (xs + 1.0);
            let (p, q) = ((1.0 - s) * turn, s * turn);
            let point = (a * p.sin() + b * q.sin()) * k_sin;
            let along = (b * q.cos() - a * p.cos()) * (turn * k_sin);
            let cross = pole.cross(point);
            let sin_b = cross.length();
            if sin_b == 0.0 {
                continue;
            }
            let u_b = sin_b.atan2(pole.dot(point));
            let d = (point - pole * pole.dot(point)) / sin_b;
            // dψ/ds = c·(B × B') / |c × B|².
            let dpsi = pole.dot(point.cross(along)) / (sin_b * sin_b);
            let mut radial = 0.0;
            for &(xu, wu) in rule {
                let (sin_u, cos_u) = (0.5 * u_b * (xu + 1.0)).sin_cos();
                radial += wu * sin_u * g(pole * cos_u + d * sin_u);
            }
            total += 0.25 * ws * dpsi * u_b * radial;
        }
    }
    total.abs()
}
