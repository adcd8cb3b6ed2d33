//! A rect's directions above the surface as a region of the renders' exact rule
//! (docs/design.md §1.14; `rect_rule` in shaders/rect_light.wgsl): the specular lobe by the
//! polar rule about the mirror direction (or the edges' brightest point where the rect does
//! not hold it), the diffuse lobe by the fan from the corners' mean.

use glam::DVec3;

use crate::brdf::{Alpha, Lobes, brdf_cos_aniso};
use crate::light::boundary::{Arc, brightest};
use crate::light::fan::fan_integral;
use crate::light::polar::{Bounds, DIFFUSE_NODES, Lobe, Polar, mirror, rule_nodes};
use crate::light::rect::{Rect, clip_horizon};

/// The exact radiance of a rect of unit radiance toward `v`, per lobe (base colour 1), by
/// the renders' rule.
pub fn rect_rule(v: DVec3, rect: &Rect, alpha: Alpha<f64>, f0: f64) -> Lobes<f64> {
    if !rect.faces_origin() {
        return Lobes::default();
    }
    let above = clip_horizon(&rect.corners());
    let corners: Vec<DVec3> = above.iter().filter_map(|p| p.try_normalize()).collect();
    if corners.len() < 3 {
        return Lobes::default();
    }
    let middle = corners.iter().sum::<DVec3>().normalize();
    let lobes = |l: DVec3| brdf_cos_aniso(v.to_array(), l.to_array(), alpha, f0);
    let polar = polygon_polar(&corners, middle, |l| lobes(l).specular, mirror(v));
    let lobe = Lobe::specular(polar.pole, v, (alpha.x, alpha.y)).within(&polar.bounds, middle);
    Lobes {
        specular: polar.integral(&lobe, rule_nodes(alpha), |l| lobes(l).specular),
        diffuse: fan_integral(&corners, middle, DIFFUSE_NODES, |l| lobes(l).diffuse),
    }
}

/// The convex spherical polygon of unit `corners` (in order; `middle` inside it) as a polar
/// region: its edges' great circles, its pole at `focus` where it holds it, else at its
/// edges' point where `g` is largest, cut at every corner and at the feet of the
/// perpendiculars from the pole to the edges that hold them.
pub fn polygon_polar(
    corners: &[DVec3],
    middle: DVec3,
    g: impl Fn(DVec3) -> f64,
    focus: DVec3,
) -> Polar {
    let mut bounds = Bounds::default();
    let mut edges = Vec::with_capacity(corners.len());
    for k in 0..corners.len() {
        let (a, b) = (corners[k], corners[(k + 1) % corners.len()]);
        if let Some(n) = a.cross(b).try_normalize() {
            bounds.push(if n.dot(middle) < 0.0 { -n } else { n });
            edges.push(Arc::Line { a, b });
        }
    }
    let pole = if bounds.contains(focus) {
        focus
    } else {
        let (k, s) = brightest(&edges, g);
        edges[k].at(s)
    };
    let mut polar = Polar::new(bounds, pole, 2);
    for &p in corners {
        polar.cut_toward(p);
    }
    for (edge, &n) in edges.iter().zip(&bounds.planes) {
        let Arc::Line { a, b } = *edge else { continue };
        // Where the foot leaves the edge it is the corner, whose cut is there already: the cut
        // set moves continuously with the pole.
        if let Some(foot) = (pole - n * n.dot(pole)).try_normalize() {
            let turn = a.cross(b);
            if a.cross(foot).dot(turn) > 0.0 && foot.cross(b).dot(turn) > 0.0 {
                polar.cut_foot(n);
            }
        }
    }
    polar
}
