//! A capsule's silhouette above the surface as a region of the polar rule (docs/design.md
//! §1.15). The capsule is the convex hull of its two end balls, so the directions it covers
//! are the hull of their two caps: the caps and the spherical quadrilateral between the two
//! great circles tangent to both (the planes through the shading point along the axis, at the
//! radius from it) and the chords joining each cap's tangent points. Each is convex and their
//! union is, so along a meridian from a pole inside it the union ends where the last piece
//! does; the horizon then cuts it.

use glam::DVec3;

use crate::brdf::{Alpha, Lobes, brdf_cos_aniso};
use crate::light::polar::{Bounds, Lobe, Polar, Region, cap_meridian, mirror, plane_meridian};
use crate::light::tube::Tube;

/// The pieces of a capsule's directions (none of them cut by the horizon).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Silhouette {
    /// Each end ball's cap: its axis and depth `1 − cos σ`.
    pub caps: [(DVec3, f64); 2],
    /// The quadrilateral's four inward normals, where the shading point is outside the
    /// cylinder about the axis (inside it one cap holds the other).
    pub band: Option<[DVec3; 4]>,
    /// The four tangent points, where the boundary passes from a cap to a great circle.
    pub tangents: [DVec3; 4],
}

impl Silhouette {
    /// The silhouette of `tube` (`None` where the origin is inside it).
    pub fn of(tube: &Tube) -> Option<Self> {
        if tube.encloses_origin() {
            return None;
        }
        let r = tube.radius;
        let cap = |p: DVec3| {
            let d = p.length();
            let sin = (r / d).min(1.0);
            (p / d, sin * sin / (1.0 + (1.0 - sin * sin).sqrt()))
        };
        let e = tube.axis();
        let across = tube.a - e * tube.a.dot(e);
        let rho = across.length();
        let mut band = None;
        let mut tangents = [
            tube.a.normalize(),
            tube.b.normalize(),
            tube.a.normalize(),
            tube.b.normalize(),
        ];
        if rho > r * (1.0 + 1e-9) && tube.length() > 0.0 {
            let out = across / rho;
            let side = e.cross(out);
            let (cos, sin) = (r / rho, (1.0 - (r / rho).powi(2)).sqrt());
            let n = [out * cos + side * sin, out * cos - side * sin];
            let touch = |p: DVec3, k: usize| p - n[k] * r;
            let (ta, tb) = (
                [touch(tube.a, 0), touch(tube.a, 1)],
                [touch(tube.b, 0), touch(tube.b, 1)],
            );
            let chord = |p: [DVec3; 2], toward: [DVec3; 2]| {
                let m = p[0].cross(p[1]).normalize_or_zero();
                if m.dot(toward[0] + toward[1]) < 0.0 {
                    -m
                } else {
                    m
                }
            };
            band = Some([n[0], n[1], chord(ta, tb), chord(tb, ta)]);
            tangents = [ta[0], ta[1], tb[0], tb[1]].map(DVec3::normalize);
        }
        Some(Self {
            caps: [cap(tube.a), cap(tube.b)],
            band,
            tangents,
        })
    }

    /// Whether the unit `x` is in it (above the surface or not).
    pub fn contains(&self, x: DVec3) -> bool {
        self.caps
            .iter()
            .any(|&(axis, depth)| 0.5 * (x - axis).length_squared() <= depth)
            || self.band.is_some_and(|b| b.iter().all(|n| n.dot(x) >= 0.0))
    }
}

/// The silhouette above the surface, as the polar rule reads it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AboveSurface(pub Silhouette);

impl Region for AboveSurface {
    fn meridian(&self, c: DVec3, d: DVec3) -> Option<(f64, f64)> {
        let s = &self.0;
        let mut pieces = s
            .caps
            .iter()
            .filter_map(|&(axis, depth)| cap_meridian(c, d, axis, depth))
            .collect::<Vec<_>>();
        if let Some(band) = s.band {
            let mut lo: f64 = 0.0;
            let mut hi = f64::INFINITY;
            let inside = band.iter().all(|n| {
                plane_meridian(n.dot(c), n.dot(d)).is_some_and(|(l, h)| {
                    lo = lo.max(l);
                    hi = hi.min(h);
                    true
                })
            });
            if inside && hi > lo {
                pieces.push((lo, hi));
            }
        }
        let lo = pieces.iter().map(|p| p.0).reduce(f64::min)?;
        let hi = pieces.iter().map(|p| p.1).reduce(f64::max)?;
        let (hl, hh) = plane_meridian(c.z, d.z)?;
        let (lo, hi) = (lo.max(hl), hi.min(hh));
        (hi > lo).then_some((lo, hi))
    }
}

/// A direction inside the capsule's silhouette and above the surface (`None` where none is):
/// toward its centre where that is above, else toward a point inside it above its higher
/// end, at `(r + max(−z, 0))/2` over the end's height `z`.
pub fn middle(tube: &Tube) -> Option<DVec3> {
    if tube.below_horizon() {
        return None;
    }
    let c = tube.centre();
    if c.z > 0.25 * tube.radius {
        return Some(c.normalize());
    }
    let top = if tube.a.z > tube.b.z { tube.a } else { tube.b };
    let lift = 0.5 * (tube.radius + (-top.z).max(0.0));
    (top + DVec3::Z * lift).try_normalize()
}

/// The directions along the horizon where it crosses the silhouette's boundary (the pieces
/// of the rule are cut there), in closed form: where each cap's circle and each tangent great
/// circle meets the horizon, kept where that point is on the union's boundary (inside no other
/// piece; the chords lie inside their caps). A convex region within a hemisphere crosses a
/// great circle twice at most; a point counted twice where two pieces meet makes a piece of
/// no width, which the rule drops. At most `MAX_HORIZON_CORNERS`.
pub fn horizon_corners(s: &Silhouette) -> Vec<DVec3> {
    let inside_cap = |x: DVec3, k: usize| {
        let (axis, depth) = s.caps[k];
        0.5 * (x - axis).length_squared() < depth
    };
    // Inside the band: strictly (off its boundary), or within it but for the plane `on`, which
    // the point lies on (where rounding would put it either side).
    let in_band = |x: DVec3, strict: bool, on: Option<usize>| {
        s.band.is_some_and(|b| {
            b.iter().enumerate().all(|(k, n)| match strict {
                true => n.dot(x) > 0.0,
                false => on == Some(k) || n.dot(x) >= 0.0,
            })
        })
    };
    let mut corners = Vec::new();
    for k in 0..2 {
        let (axis, depth) = s.caps[k];
        let cos_sigma = 1.0 - depth;
        let h = axis.truncate().length();
        if h <= 0.0 || h < cos_sigma.abs() {
            continue;
        }
        let (mid, half) = (
            axis.y.atan2(axis.x),
            (cos_sigma / h).clamp(-1.0, 1.0).acos(),
        );
        for psi in [mid - half, mid + half] {
            let x = DVec3::new(psi.cos(), psi.sin(), 0.0);
            if !inside_cap(x, 1 - k) && !in_band(x, true, None) {
                corners.push(x);
            }
        }
    }
    if let Some(band) = s.band {
        for (k, n) in band[..2].iter().enumerate() {
            let Some(x) = n.cross(DVec3::Z).try_normalize() else {
                continue;
            };
            for x in [x, -x] {
                if in_band(x, false, Some(k)) && !inside_cap(x, 0) && !inside_cap(x, 1) {
                    corners.push(x);
                }
            }
        }
    }
    corners.truncate(MAX_HORIZON_CORNERS);
    corners
}

/// `horizon_corners`' most: two crossings, each found at most twice where two pieces meet.
pub const MAX_HORIZON_CORNERS: usize = 4;

/// The exact integrals `∫ f cos dω` over the capsule's silhouette above the surface toward
/// `v`, per lobe (base colour 1, unit radiance), `(specular, diffuse)` nodes a dimension and
/// piece: about the mirror direction where the silhouette holds it, else about the point a
/// tenth of the way back from where the great circle from its middle toward the mirror
/// direction leaves it; cut at the tangent points, the horizon's corners and its foot. A point
/// inside the capsule sees the upper hemisphere.
pub fn tube_exact(
    v: DVec3,
    tube: &Tube,
    alpha: Alpha<f64>,
    f0: f64,
    (n, n_diffuse): (usize, usize),
) -> Lobes<f64> {
    let lobes = |l: DVec3| brdf_cos_aniso(v.to_array(), l.to_array(), alpha, f0);
    let focus = mirror(v);
    let Some(silhouette) = Silhouette::of(tube) else {
        let mut polar = Polar::new(Bounds::above(None), focus, 4);
        polar.cut_both(DVec3::Z.cross(focus));
        polar.cut_foot(DVec3::Z);
        let lobe = Lobe::specular(focus, v, (alpha.x, alpha.y));
        return Lobes {
            specular: polar.integral(&lobe, n, |l| lobes(l).specular),
            diffuse: polar.integral(&Lobe::round(focus), n_diffuse, |l| lobes(l).diffuse),
        };
    };
    let Some(middle) = middle(tube) else {
        return Lobes::default();
    };
    let region = AboveSurface(silhouette);
    let pole = if focus.z > 0.0 && silhouette.contains(focus) {
        focus
    } else {
        crate::light::polar::toward(middle, focus)
            .and_then(|d| region.meridian(middle, d))
            .map_or(middle, |(_, hi)| {
                let u = 0.9 * 2.0 * hi.atan();
                let d = crate::light::polar::toward(middle, focus).unwrap_or(DVec3::X);
                middle * u.cos() + d * u.sin()
            })
    };
    let mut polar = Polar::new(region, pole, 4);
    silhouette
        .tangents
        .iter()
        .for_each(|&p| polar.cut_toward(p));
    let corners = horizon_corners(&silhouette);
    if !corners.is_empty() {
        polar.cut_foot(DVec3::Z);
    }
    corners.iter().for_each(|&p| polar.cut_toward(p));
    let lobe = Lobe::specular(pole, v, (alpha.x, alpha.y)).within(&region, middle);
    Lobes {
        specular: polar.integral(&lobe, n, |l| lobes(l).specular),
        diffuse: polar.integral(&Lobe::round(pole), n_diffuse, |l| lobes(l).diffuse),
    }
}
