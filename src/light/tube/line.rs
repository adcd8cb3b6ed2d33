//! Line integrals for tube lights (docs/design.md §1.15): the clamped cosine over a thin
//! cylinder about a segment in closed form (Heitz & Hill 2017, "Real-Time Line- and
//! Disk-Light Shading with Linearly Transformed Cosines", and ltc_code's line demo), mapped by
//! `M⁻¹` with their width factor; and the segment's irradiance as a line of point lights
//! (Karis 2013).

use std::f64::consts::PI;

use glam::DVec3;

use crate::brdf::Lobes;
use crate::light::tube::TubeShading;
use crate::ltc::{Ltc, Normalization};

/// The part of the segment `p1 p2` at or above `z = 0`; `None` where none is.
pub fn clip_segment(p1: DVec3, p2: DVec3) -> Option<(DVec3, DVec3)> {
    if p1.z <= 0.0 && p2.z <= 0.0 {
        return None;
    }
    let cut =
        |below: DVec3, above: DVec3| below + (above - below) * (below.z / (below.z - above.z));
    let cut_below = |p: DVec3, q: DVec3| if p.z < 0.0 { cut(p, q) } else { p };
    Some((cut_below(p1, p2), cut_below(p2, p1)))
}

/// `∫ cos θ / π dω` over a cylinder of radius 1 (thin beside its distance) about the segment
/// `p1 p2`, the part above the horizon: `(1/π) ∫ 2 p_z sin β / |p|³ dℓ`, in closed form about
/// the foot `p₀` of the origin on the segment's line (distance `d`):
/// `F_po(d, ℓ) p₀_z + F_wt(d, ℓ) t_z` between the ends' `ℓ`, with
/// `F_po = ℓ/(d(d² + ℓ²)) + atan(ℓ/d)/d²` and `F_wt = ℓ²/(d(d² + ℓ²))`. Each difference is
/// taken in a form that does not cancel where the line passes close (`d ≪ ℓ`, where both ends'
/// terms near `1/d`), so that an f32 twin in a shader keeps it too.
pub fn diffuse_line(p1: DVec3, p2: DVec3) -> f64 {
    let Some((p1, p2)) = clip_segment(p1, p2) else {
        return 0.0;
    };
    let Some(t) = (p2 - p1).try_normalize() else {
        return 0.0;
    };
    let (l1, l2) = (p1.dot(t), p2.dot(t));
    let foot = p1 - t * l1;
    let d = foot.length();
    if d <= 0.0 {
        // The origin on the line: the cylinder seen end-on covers no solid angle in the limit.
        return 0.0;
    }
    let (d2, q1, q2) = (d * d, d * d + l1 * l1, d * d + l2 * l2);
    let f_po =
        (l2 - l1) * (d2 - l1 * l2) / (d * q1 * q2) + ((l2 - l1) * d).atan2(d2 + l1 * l2) / d2;
    let f_wt = d * (l2 - l1) * (l2 + l1) / (q1 * q2);
    (f_po * foot.z + f_wt * t.z) / PI
}

/// `∫ D dω` of the LTC over a cylinder of radius 1 about `p1 p2` (Heitz & Hill 2017): the
/// cosine's line integral over the segment mapped by `M⁻¹`, times the width factor
/// `1/|Mᵀ o|` (`M = brdf_from_cos`) that the mapping gives the cylinder across the plane of
/// the segment and the shading point (normal `o`). Paper-literal normalization drops D's 1/π,
/// as `ltc_eval` does.
pub fn ltc_line(ltc: &Ltc, p1: DVec3, p2: DVec3, normalization: Normalization) -> f64 {
    // A segment whose line passes through the shading point (seen end-on, to rounding) is
    // a cylinder of no solid angle; its plane with the point is rounding.
    let cross = p1.cross(p2);
    if cross.length() <= END_ON * p1.length() * p2.length() {
        return 0.0;
    }
    // `1/|Mᵀ o|` with `o = p1 × p2 / |p1 × p2|`: as `cof(M⁻¹) = det(M⁻¹) Mᵀ` and
    // `cof(A)(p1 × p2) = A p1 × A p2`, it is `|det M⁻¹| |p1 × p2| / |M⁻¹ p1 × M⁻¹ p2|`,
    // without M (a shader's `Ltc` holds M⁻¹ alone).
    let m = ltc.cos_from_brdf;
    let mapped = (m * p1).cross(m * p2).length();
    if mapped.is_nan() || mapped <= 0.0 {
        return 0.0;
    }
    let width = m.determinant().abs() * cross.length() / mapped;
    // HDRP's guard: rounding can leave a line nearly through the point a little below 0.
    let value = (width * diffuse_line(m * p1, m * p2)).max(0.0);
    match normalization {
        Normalization::Corrected => value,
        Normalization::PaperLiteral => PI * value,
    }
}

/// `sin` of the angle between a segment's ends below which `ltc_line` takes it as seen
/// end-on: f64's rounding of a cross product of unit vectors is ~1e-16, and a line this close
/// to the point subtends a cylinder of radius `r` at most `r·1e-9/d` wide.
pub const END_ON: f64 = 1e-9;

/// `∫ p_z / |p|³ dℓ` over the part of the segment `a b` above the surface: the irradiance of a
/// line of point lights of unit intensity per length, in closed form (`∫₀¹ p/|p|³ dt` for
/// `p = a + t (b − a)` is `(â + b̂) / (|a| |b| + a·b)`), its denominator as
/// `| |b| a + |a| b |² / (2 |a| |b|)`, which does not cancel where the segment passes close.
pub fn line_irradiance(a: DVec3, b: DVec3) -> f64 {
    let Some((a, b)) = clip_segment(a, b) else {
        return 0.0;
    };
    let (la, lb) = (a.length(), b.length());
    let denom = (a * lb + b * la).length_squared() / (2.0 * la * lb);
    if denom.is_nan() || denom <= 0.0 {
        return 0.0;
    }
    (b - a).length() * (a.z / la + b.z / lb) / denom
}

/// The LTC line methods of a tube (radiance 1): each lobe's `ltc_line` times the radius and,
/// with `ends`, the two half-sphere ends as points of their silhouettes' areas
/// `½ π r² (1 + cos γ)` (`γ` between the end's outward axis and the way to the shading point),
/// the sum at most 1 as ltc_code clamps it; times the lobe's magnitude. Without `ends` (HDRP's
/// tube) nothing clamps it.
pub fn tube_ltc_line(s: &TubeShading<'_>, ends: bool) -> Lobes<f64> {
    let t = &s.tube;
    // Case 1 clips the segment at the surface before `M⁻¹` can lift a part below it.
    let segment = match s.pixel.clip.case1 {
        true => clip_segment(t.a, t.b),
        false => Some((t.a, t.b)),
    };
    let lobe = |ltc: &Ltc| {
        let line = segment.map_or(0.0, |(a, b)| {
            t.radius * ltc_line(ltc, a, b, s.pixel.normalization)
        });
        if !ends {
            return line;
        }
        let end = |p: DVec3, outward: DVec3| {
            let w = p.normalize();
            let area = 0.5 * PI * t.radius * t.radius * (1.0 - outward.dot(w));
            area * ltc.ltc_eval(w, s.pixel.clip, s.pixel.normalization)
                / p.length_squared().max(t.radius * t.radius)
        };
        let total = line + end(t.a, -t.axis()) + end(t.b, t.axis());
        match s.pixel.normalization {
            Normalization::Corrected => total.min(1.0),
            Normalization::PaperLiteral => total.min(PI),
        }
    };
    let (spec_weight, diff_weight) = s.pixel.ltc.lobe_weights(s.pixel.f0, s.pixel.normalization);
    Lobes {
        specular: spec_weight * lobe(&s.pixel.ltc.spec),
        diffuse: diff_weight * lobe(&s.pixel.ltc.diff),
    }
}
