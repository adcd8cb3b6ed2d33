//! A sphere's cap above the surface as a region of the renders' exact rule (docs/design.md
//! §1.14; `sphere_rule` in shaders/sphere_light.wgsl): both lobes by the polar rule about the
//! mirror direction, or about the cap's brightest boundary point where it does not hold it.

use glam::{DVec2, DVec3};

use crate::brdf::{Alpha, Lobes, brdf_cos_aniso};
use crate::light::boundary::{Arc, brightest};
use crate::light::polar::{Bounds, DIFFUSE_NODES, Lobe, Polar, mirror, rule_nodes};
use crate::light::sphere::cap::Cap;
use crate::light::sphere::quadrature::visible_half_azimuth;

/// The exact integrals `∫ f cos dω` over the cap above the surface toward `v`, per lobe (base
/// colour 1, unit radiance), by the renders' rule.
pub fn cap_rule(v: DVec3, cap: &Cap, alpha: Alpha<f64>, f0: f64) -> Lobes<f64> {
    let lobes = |l: DVec3| brdf_cos_aniso(v.to_array(), l.to_array(), alpha, f0);
    let Some(polar) = cap_polar(cap, |l| lobes(l).specular, mirror(v)) else {
        return Lobes::default();
    };
    let lobe =
        Lobe::specular(polar.pole, v, (alpha.x, alpha.y)).within(&polar.bounds, cap_middle(cap));
    Lobes {
        specular: polar.integral(&lobe, rule_nodes(alpha), |l| lobes(l).specular),
        diffuse: polar.integral(&Lobe::round(polar.pole), DIFFUSE_NODES, |l| {
            lobes(l).diffuse
        }),
    }
}

/// The cap above the surface as a polar region (`None` where none of it is): the cap and the horizon, its pole at `focus` where it holds it, else at its
/// boundary's point where `g` is largest; cut where the horizon meets the cap's circle, along
/// the circle and the horizon as they pass the pole (their tangents where it is on them, the
/// directions along them where it is near), and toward the horizon's foot. A point inside the
/// sphere sees the upper hemisphere.
pub fn cap_polar(cap: &Cap, g: impl Fn(DVec3) -> f64, focus: DVec3) -> Option<Polar> {
    if cap.below_horizon() {
        return None;
    }
    if cap.encloses() {
        let mut polar = Polar::new(Bounds::above(None), focus, 4);
        polar.cut_both(DVec3::Z.cross(focus));
        polar.cut_foot(DVec3::Z);
        return Some(polar);
    }
    let a = cap.axis;
    let bounds = Bounds::above(Some((a, cap.depth())));
    // t1 in the plane of the axis and +z, pointing up: a circle point's height is
    // a.z cos σ + t1.z sin σ cos ψ, visible over one interval of ψ about 0.
    let t1 = (DVec3::Z - a * a.z).try_normalize().unwrap_or(DVec3::X);
    let t2 = a.cross(t1);
    let cos_sin = DVec2::new(cap.cos_sigma, cap.sin_sigma);
    let half = visible_half_azimuth(a.z * cap.cos_sigma, t1.z * cap.sin_sigma)?;
    let circle = Arc::Circle {
        axis: a,
        cos_sin,
        t1,
        t2,
        from: -half,
        sweep: 2.0 * half,
    };
    let cut = half < std::f64::consts::PI;
    let on_horizon = |x: DVec3| DVec3::new(x.x, x.y, 0.0).normalize();
    let corners = [on_horizon(circle.at(1.0)), on_horizon(circle.at(0.0))];
    let horizon = Arc::Line {
        a: corners[0],
        b: corners[1],
    };
    let arcs = if cut {
        vec![circle, horizon]
    } else {
        vec![circle]
    };
    let pole = if bounds.contains(focus) {
        focus
    } else {
        let (k, s) = brightest(&arcs, g);
        arcs[k].at(s)
    };
    let mut polar = Polar::new(bounds, pole, 4);
    polar.cut_both(a.cross(pole));
    if cut {
        polar.cut_both(DVec3::Z.cross(pole));
        polar.cut_foot(DVec3::Z);
        corners.iter().for_each(|&p| polar.cut_toward(p));
    }
    Some(polar)
}

/// A point well inside the cap above the surface: the zenith for a point inside the sphere,
/// the axis for a cap above the horizon, else halfway between the visible part's highest
/// point and the middle of the horizon's chord across it.
pub fn cap_middle(cap: &Cap) -> DVec3 {
    let a = cap.axis;
    if cap.encloses() {
        return DVec3::Z;
    }
    let t1 = (DVec3::Z - a * a.z).try_normalize().unwrap_or(DVec3::X);
    match visible_half_azimuth(a.z * cap.cos_sigma, t1.z * cap.sin_sigma) {
        Some(half) if half < std::f64::consts::PI => {
            let at = |psi: f64| {
                a * cap.cos_sigma + (t1 * psi.cos() + a.cross(t1) * psi.sin()) * cap.sin_sigma
            };
            let chord = DVec3::new(at(half).x, at(half).y, 0.0);
            let top = at(0.0);
            (top + chord.normalize()).normalize()
        }
        _ => a,
    }
}
