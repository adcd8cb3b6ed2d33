//! Tube lights (docs/design.md §1.15): a capsule — a segment and a radius — of uniform
//! radiance, in the shading frame (`n = +z`, the shading point at the origin). The exact
//! integral runs over the capsule's silhouette (`region`); Heitz & Hill 2017's LTC line and
//! HDRP's tube are the line integral of `line`; Karis 2013's representative point and the
//! centre as a point light are the approximations measured beside them. The exact method
//! integrates by `band` (longitude and latitude about the segment's plane), which converges
//! over a long thin tube at the renders' nodes; `region`'s polar rule is its check.

pub mod band;
pub mod form;
pub mod line;
pub mod region;

use std::f64::consts::PI;

use glam::DVec3;

use crate::brdf::{self, Lobes, MIN_LIGHT_DISTANCE};
use crate::light::polar::{DIFFUSE_NODES, mirror, rule_nodes};
use crate::light::sphere::{fd_toward, widening_energy};
use crate::light::{EmitterLobes, EmitterShading, ExactRule};
use crate::named::named_enum;

pub use form::{
    BENCH_LENGTH, EVAL_COLUMNS, PRESETS, SIZES, VECTORS, bench_shape, bench_title, eval_row,
    outline,
};

/// A capsule: the segment from `a` to `b` swept by a ball of `radius`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tube {
    pub a: DVec3,
    pub b: DVec3,
    pub radius: f64,
}

impl Tube {
    /// The segment's length.
    pub fn length(&self) -> f64 {
        (self.b - self.a).length()
    }

    /// The unit direction from `a` to `b` (`x` for a segment of no length: a sphere).
    pub fn axis(&self) -> DVec3 {
        (self.b - self.a).try_normalize().unwrap_or(DVec3::X)
    }

    /// The segment's middle.
    pub fn centre(&self) -> DVec3 {
        0.5 * (self.a + self.b)
    }

    /// Its surface's area, `2π r ℓ + 4π r²`, over which the light's intensity spreads.
    pub fn area(&self) -> f64 {
        2.0 * PI * self.radius * self.length() + 4.0 * PI * self.radius * self.radius
    }

    /// Its silhouette's area seen along the unit `w`: `2 r ℓ sin β + π r²` (`β` between `w`
    /// and the axis): the rectangle of the cylinder and the two half discs of its ends.
    pub fn projected_area(&self, w: DVec3) -> f64 {
        let sin_beta = self.axis().cross(w).length().min(1.0);
        2.0 * self.radius * self.length() * sin_beta + PI * self.radius * self.radius
    }

    /// The point of the segment nearest the ray from the origin along unit `w`, by its
    /// distance `s` from `a`. The distance to the ray is convex in `s`, so its least value on
    /// `[0, ℓ]` is at an end, where it is stationary — where the lines are nearest (the ray's
    /// `t > 0`) or where the segment is nearest the origin (`t = 0`) — or at the kink between
    /// those two forms, where the segment crosses the plane `p·w = 0`: with the kink among the
    /// candidates, and each stationary point only where its form holds, the least of them is
    /// the minimum itself, so that no two candidates of nearly one distance (a choice f32
    /// rounding flips, `√ε` of the length apart) stand apart.
    pub fn nearest_to_ray(&self, w: DVec3) -> f64 {
        let (e, len) = (self.axis(), self.length());
        let dist2 = |s: f64| ray_distance2(self.a + e * s, w);
        let cos = e.dot(w);
        // Each stationary point where its form holds: near the minimum the distance is flat,
        // and one form's stationary point read by the other's would tie with the minimum to
        // rounding while lying elsewhere.
        let t = |s: f64| (self.a + e * s).dot(w);
        let lines = (1.0 - cos * cos > 1e-12)
            .then(|| (cos * self.a.dot(w) - self.a.dot(e)) / (1.0 - cos * cos))
            .filter(|&s| t(s) >= 0.0);
        let origin = Some(-self.a.dot(e)).filter(|&s| t(s) <= 0.0);
        let kink = (cos != 0.0).then(|| -self.a.dot(w) / cos);
        [Some(0.0), Some(len), lines, origin, kink]
            .into_iter()
            .flatten()
            .map(|s| s.clamp(0.0, len))
            .min_by(|&s, &t| dist2(s).total_cmp(&dist2(t)))
            .unwrap_or(0.0)
    }

    /// Whether the ray from the origin along unit `w` meets the capsule.
    pub fn hit(&self, w: DVec3) -> bool {
        let p = self.a + self.axis() * self.nearest_to_ray(w);
        ray_distance2(p, w) <= self.radius * self.radius
    }

    /// The distance from the origin to the segment.
    pub fn distance_to_segment(&self) -> f64 {
        let s = (-self.a.dot(self.axis())).clamp(0.0, self.length());
        (self.a + self.axis() * s).length()
    }

    /// Whether the shading point is inside it (it sees the capsule all around).
    pub fn encloses_origin(&self) -> bool {
        self.distance_to_segment() <= self.radius
    }

    /// Whether no point of it is above the surface.
    pub fn below_horizon(&self) -> bool {
        self.a.z.max(self.b.z) + self.radius <= 0.0
    }

    /// `(r + ℓ/2) / |c|`: a bound on the angle it subtends (`TUBE_POINT_LIMIT`).
    pub fn angular_size(&self) -> f64 {
        (self.radius + 0.5 * self.length()) / self.centre().length()
    }
}

/// The squared distance from `p` to the ray from the origin along unit `w`, as the offset
/// from its nearest point (not `|p|² − (p·w)²`, which cancels where the ray passes close).
pub fn ray_distance2(p: DVec3, w: DVec3) -> f64 {
    (p - w * p.dot(w).max(0.0)).length_squared()
}

named_enum! {
    /// The ways a tube light is shaded (docs/design.md §1.15).
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
    pub enum TubeMethod {
        /// The BRDF integrated over the capsule's silhouette above the surface.
        Exact = "exact",
        /// Heitz & Hill 2017: the segment's line integral by `M⁻¹`, widened by the radius,
        /// with the ends as points (their end caps, here half spheres).
        LtcLine = "ltc-line",
        /// Unity HDRP's tube: the same line integral, widened by the radius, without ends.
        HdrpTube = "hdrp-tube",
        /// Karis 2013's representative point on the segment, then on its ball.
        RepresentativePoint = "representative-point",
        /// The centre as a point light of intensity `L` times the silhouette's area.
        LtcPoint = "ltc-point",
    }
}

impl TubeMethod {
    /// One line for a reader of the lab or the command line.
    pub fn describe(self) -> &'static str {
        match self {
            Self::Exact => {
                "The BRDF integrated over the capsule's silhouette above the surface: the reference"
            }
            Self::LtcLine => {
                "Heitz & Hill 2017: the segment's LTC line integral times the radius, the half-sphere ends as points"
            }
            Self::HdrpTube => "Unity HDRP's tube: the LTC line integral times the radius, no ends",
            Self::RepresentativePoint => {
                "Karis 2013: the segment's point nearest the mirror ray, then its ball's, with energy normalization (Unreal)"
            }
            Self::LtcPoint => {
                "The centre as a point light of intensity L times the silhouette's area"
            }
        }
    }
}

/// Nodes per dimension and piece of `TubeMethod::Exact` in `tube_light` (the band's rule):
/// tests/lights/tube_light.rs holds it to an integral over the capsule's surface.
pub const EXACT_NODES: usize = 64;

/// Below this `angular_size` every method shades a tube as its point light, as a rect is below
/// `rect::RECT_POINT_LIMIT` and for its reason: the shader's band rule places its cuts by f32
/// longitudes, good to some `2⁻²⁴` radians, which is `2⁻²⁴/s` of a span `s` (6e-5 here), while
/// the point light differs from the tube by `O(s²)` of the lobe's curvature (1e-6 here).
pub const TUBE_POINT_LIMIT: f64 = 1e-3;

/// One tube light of unit radiance at one shading point: everything the methods read.
#[derive(Clone, Copy, Debug)]
pub struct TubeShading<'a> {
    /// The view, the material, the LTC lobes and the rules (every emitter's).
    pub pixel: EmitterShading<'a>,
    pub tube: Tube,
}

/// A tube's unit-radiance lobes by `method` and the area its radiance `4I/A` divides by, a
/// quarter of the capsule's (`EmitterLobes`): centred at `centre` from the shading point with
/// `half_axis` (world, mapped to the shading frame by `to_frame`) and `radius`, the exact
/// method by `rule`.
pub fn emitter_lobes(
    method: TubeMethod,
    (centre, half_axis, radius): (DVec3, DVec3, f64),
    to_frame: &dyn Fn(DVec3) -> DVec3,
    s: &EmitterShading<'_>,
    rule: ExactRule,
) -> EmitterLobes {
    let tube = Tube {
        a: to_frame(centre - half_axis),
        b: to_frame(centre + half_axis),
        radius,
    };
    let shading = TubeShading { pixel: *s, tube };
    (tube_light_with(method, &shading, rule), 0.25 * tube.area())
}

/// The radiance toward `v` of a tube of unit radiance, per lobe (base colour 1), the exact
/// method by `EXACT_NODES`.
pub fn tube_light(method: TubeMethod, s: &TubeShading<'_>) -> Lobes<f64> {
    tube_light_with(method, s, ExactRule::Nodes(EXACT_NODES))
}

/// `tube_light` with the exact method by `rule`: the band's rule (`band`) at its nodes, or at
/// the renders' (`polar::rule_nodes`, `polar::DIFFUSE_NODES`).
pub fn tube_light_with(method: TubeMethod, s: &TubeShading<'_>, rule: ExactRule) -> Lobes<f64> {
    if s.tube.below_horizon() {
        return Lobes::default();
    }
    if s.tube.angular_size() < TUBE_POINT_LIMIT {
        return tube_point(method == TubeMethod::Exact, s);
    }
    match method {
        TubeMethod::Exact => {
            // The band's rule: at the renders' nodes within 3.3e-4 of its converged value over
            // random tubes, half of them slivers, where the polar rule is 15–40% off
            // (tests/lights/tube_light.rs).
            // Inside the capsule a reference takes the polar rule over the hemisphere, and the
            // renders the band's (the shader's twin, one rule to compile): at 12 nodes that is
            // within 1e-3 for α ≥ 0.3 and θo ≤ 60°, but 0.9% off at θo 85°, 1.6% at α 0.1 and
            // 3.4% at 0.02 (tests/lights/tube_light.rs): a limit left to fix.
            match rule {
                ExactRule::Nodes(n) if s.tube.encloses_origin() => {
                    region::tube_exact(s.pixel.v, &s.tube, s.pixel.alpha, s.pixel.f0, (n, n))
                }
                ExactRule::Nodes(n) => {
                    band::tube_band(s.pixel.v, &s.tube, s.pixel.alpha, s.pixel.f0, (n, n))
                }
                ExactRule::Render => {
                    let nodes = (rule_nodes(s.pixel.alpha), DIFFUSE_NODES);
                    band::tube_band(s.pixel.v, &s.tube, s.pixel.alpha, s.pixel.f0, nodes)
                }
            }
        }
        TubeMethod::LtcLine => line::tube_ltc_line(s, true),
        TubeMethod::HdrpTube => line::tube_ltc_line(s, false),
        TubeMethod::RepresentativePoint => tube_representative_point(s),
        TubeMethod::LtcPoint => tube_point(false, s),
    }
}

/// The tube as a point light at its centre of intensity `L A⊥` (`projected_area` toward the
/// shading point): the exact point light for the exact method, the paper's formula else.
pub fn tube_point(exact: bool, s: &TubeShading<'_>) -> Lobes<f64> {
    let c = s.tube.centre();
    let d2 = c.length_squared().max(s.tube.radius * s.tube.radius);
    let l = c.normalize();
    let e = s.tube.projected_area(l) / d2;
    s.pixel.point_light(exact, l, e)
}

/// Karis 2013 ("Real Shading in Unreal Engine 4", tube lights): the specular lobe at the point
/// of the segment nearest the mirror ray, moved to its ball's point nearest the ray as for a
/// sphere, lit with the tube's broadside intensity `L (2 r ℓ + π r²)`; its peak lowered by the
/// sphere's normalization `(α/α')²` for the radius and the line's `α'/α''` for the half length
/// (`α'' = saturate(α' + ½ saturate(ℓ/2d))`, the sphere's form along one axis). The diffuse
/// lobe is the segment's irradiance in closed form across the width `2r` (`line_irradiance`)
/// plus the two half-sphere ends as a disc `π r²` at the centre, by Burley toward the centre.
pub fn tube_representative_point(s: &TubeShading<'_>) -> Lobes<f64> {
    let t = &s.tube;
    let r = t.radius;
    let reflected = mirror(s.pixel.v);
    let on_segment = t.a + t.axis() * t.nearest_to_ray(reflected);
    let to_ray = reflected * on_segment.dot(reflected) - on_segment;
    let reach = to_ray.length();
    let closest = on_segment + to_ray * (r / reach).min(1.0);
    let l = closest.try_normalize().unwrap_or(reflected);
    let d = on_segment.length().max(MIN_LIGHT_DISTANCE);
    let sphere = widening_energy(s.pixel.alpha, (r / d).min(1.0));
    let wide = |a: f64| (a + 0.5 * (r / d).min(1.0)).min(1.0);
    let line = |a: f64| wide(a) / (wide(a) + 0.5 * (0.5 * t.length() / d).min(1.0)).min(1.0);
    let energy = sphere * line(s.pixel.alpha.x.max(s.pixel.alpha.y));
    let intensity = 2.0 * r * t.length() + PI * r * r;
    let specular = brdf::brdf_cos_aniso(
        s.pixel.v.to_array(),
        l.to_array(),
        s.pixel.alpha,
        s.pixel.f0,
    )
    .specular;
    let c = t.centre();
    let c2 = c.length_squared().max(r * r);
    let irradiance =
        2.0 * r * line::line_irradiance(t.a, t.b) + PI * r * r * (c.z / c.length()).max(0.0) / c2;
    let diffuse = fd_toward(s.pixel.v, c.normalize(), s.pixel.alpha.diffuse()) * irradiance;
    Lobes {
        specular: intensity / d.max(r).powi(2) * energy * specular,
        diffuse,
    }
}
