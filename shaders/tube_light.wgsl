// Tube lights (docs/design.md §1.15), mirroring src/light/tube/ by name: the capsule
// (mod.rs), its line integrals (line.rs) and the methods; the exact one's rule is
// tube_band.wgsl. Composed after sphere_light.wgsl (atan_precise,
// acos_precise, sincos_precise, fd_toward, widening_energy), rect_light.wgsl
// (atan2_precise), disk_light.wgsl (atan2_full) and polar.wgsl (rule, rule_nodes, mirror,
// wrapped); the Rust side is src/gpu/light/tube_light.rs.

// The light buffer's code for a tube (src/gpu/light/mod.rs shape_constant).
const SHAPE_TUBE: u32 = 4u;

// How a side shades a tube (src/light/tube/mod.rs TubeMethod; tube_light.rs tube_constant).
const TUBE_EXACT: u32 = 0u;                // the BRDF over the silhouette, by the band's rule
const TUBE_LTC_LINE: u32 = 1u;             // Heitz & Hill 2017's line, widened, ends as points
const TUBE_HDRP_TUBE: u32 = 2u;            // Unity HDRP's tube: the widened line, no ends
const TUBE_REPRESENTATIVE_POINT: u32 = 3u; // Karis 2013
const TUBE_LTC_POINT: u32 = 4u;            // the centre as a point light

// Some light is a tube, and how A and B shade tubes (constants, as rect_light.wgsl's).
override TUBES: bool = false;
override TUBE_A: u32 = TUBE_LTC_LINE;
override TUBE_B: u32 = TUBE_EXACT;

// TUBE_POINT_LIMIT: below this (r + ℓ/2)/|c| a tube is shaded as its point light.
const TUBE_POINT_LIMIT: f32 = 1e-3;

// A capsule in the shading frame: the segment a b swept by a ball of `radius`.
struct Tube {
    a: vec3<f32>,
    b: vec3<f32>,
    radius: f32,
}

fn tube_length(t: Tube) -> f32 {
    return length(t.b - t.a);
}

// Tube::axis: the unit direction a → b (x for a segment of no length).
fn tube_axis(t: Tube) -> vec3<f32> {
    let d = t.b - t.a;
    if dot(d, d) > 0.0 {
        return normalize(d);
    }
    return vec3<f32>(1.0, 0.0, 0.0);
}

fn tube_centre(t: Tube) -> vec3<f32> {
    return 0.5 * (t.a + t.b);
}

// Tube::area: 2π r ℓ + 4π r².
fn tube_area(t: Tube) -> f32 {
    return 2.0 * PI * t.radius * tube_length(t) + 4.0 * PI * t.radius * t.radius;
}

// Tube::projected_area: 2 r ℓ sin β + π r² seen along unit w.
fn tube_projected_area(t: Tube, w: vec3<f32>) -> f32 {
    let sin_beta = min(length(cross(tube_axis(t), w)), 1.0);
    return 2.0 * t.radius * tube_length(t) * sin_beta + PI * t.radius * t.radius;
}

// ray_distance2: the squared distance from p to the ray from the origin along unit w.
fn ray_distance2(p: vec3<f32>, w: vec3<f32>) -> f32 {
    let off = p - w * max(dot(p, w), 0.0);
    return dot(off, off);
}

// Tube::nearest_to_ray: the distance from a of the segment's point nearest the ray along w,
// the least of the distance's values at the ends, where it is stationary and at its kink.
fn tube_nearest_to_ray(t: Tube, w: vec3<f32>) -> f32 {
    let e = tube_axis(t);
    let len = tube_length(t);
    let c = dot(e, w);
    var best = 0.0;
    var best_d2 = ray_distance2(t.a, w);
    // Each stationary point where its form holds (mod.rs says why).
    var candidates = array<f32, 4>(len, 0.0, 0.0, 0.0);
    let origin = -dot(t.a, e);
    if dot(t.a + e * origin, w) <= 0.0 {
        candidates[1] = origin;
    }
    if 1.0 - c * c > 1e-12 {
        let lines = (c * dot(t.a, w) - dot(t.a, e)) / (1.0 - c * c);
        if dot(t.a + e * lines, w) >= 0.0 {
            candidates[2] = lines;
        }
    }
    if c != 0.0 {
        candidates[3] = -dot(t.a, w) / c;
    }
    for (var k = 0u; k < 4u; k++) {
        let s = clamp(candidates[k], 0.0, len);
        let d2 = ray_distance2(t.a + e * s, w);
        if d2 < best_d2 {
            best = s;
            best_d2 = d2;
        }
    }
    return best;
}

// Tube::distance_to_segment.
fn tube_distance_to_segment(t: Tube) -> f32 {
    let s = clamp(-dot(t.a, tube_axis(t)), 0.0, tube_length(t));
    return length(t.a + tube_axis(t) * s);
}

fn tube_encloses_origin(t: Tube) -> bool {
    return tube_distance_to_segment(t) <= t.radius;
}

fn tube_below_horizon(t: Tube) -> bool {
    return max(t.a.z, t.b.z) + t.radius <= 0.0;
}

// Tube::angular_size: (r + ℓ/2)/|c|.
fn tube_angular_size(t: Tube) -> f32 {
    return (t.radius + 0.5 * tube_length(t)) / length(tube_centre(t));
}

// One tube of unit radiance at one shading point (src/light/tube/mod.rs TubeShading).
struct TubeShading {
    pixel: EmitterShading,
    tube: Tube,
}

// tube_emitter_lobes: a tube's unit-radiance lobes by `method` (TUBE_*) and the area its
// radiance 4I/A divides by, A/4, for emitter.wgsl's emitter_lobes (src/light/tube/mod.rs
// emitter_lobes): its segment centre ± `dims[0].xyz`, its radius `dims[0].w`, mapped to the
// shading frame by `to_frame`.
fn tube_emitter_lobes(
    method: u32,
    dims: mat2x4<f32>,
    centre: vec3<f32>,
    to_frame: mat3x3<f32>,
    pixel: EmitterShading,
    pair: LtcPair,
) -> vec3<f32> {
    let half_axis = dims[0].xyz;
    let tube = Tube(to_frame * (centre - half_axis), to_frame * (centre + half_axis), dims[0].w);
    return vec3<f32>(tube_light(method, TubeShading(pixel, tube), pair), 0.25 * tube_area(tube));
}

// tube_point: the centre as a point light of intensity L A⊥, exact or by the paper's formula.
fn tube_point(s: TubeShading, pair: LtcPair, exact: bool) -> vec2<f32> {
    let c = tube_centre(s.tube);
    let d2 = max(dot(c, c), s.tube.radius * s.tube.radius);
    let l = normalize(c);
    let e = tube_projected_area(s.tube, l) / d2;
    return emitter_shading_point_light(s.pixel, pair, l, e, exact);
}

// clip_segment: the part of p1 p2 at or above z = 0, as mat2x3's columns; `false` in the
// flag where none is.
struct Segment3 {
    p1: vec3<f32>,
    p2: vec3<f32>,
    above: bool,
}

fn clip_segment(p1: vec3<f32>, p2: vec3<f32>) -> Segment3 {
    if p1.z <= 0.0 && p2.z <= 0.0 {
        return Segment3(p1, p2, false);
    }
    var q1 = p1;
    var q2 = p2;
    if p1.z < 0.0 {
        q1 = p1 + (p2 - p1) * (p1.z / (p1.z - p2.z));
    }
    if p2.z < 0.0 {
        q2 = p2 + (p1 - p2) * (p2.z / (p2.z - p1.z));
    }
    return Segment3(q1, q2, true);
}

// diffuse_line: ∫ cos/π dω over a unit-radius thin cylinder about p1 p2 above the horizon, in
// the closed form that does not cancel where the line passes close (line.rs).
fn diffuse_line(p1_in: vec3<f32>, p2_in: vec3<f32>) -> f32 {
    let seg = clip_segment(p1_in, p2_in);
    if !seg.above {
        return 0.0;
    }
    let d12 = seg.p2 - seg.p1;
    if dot(d12, d12) <= 0.0 {
        return 0.0;
    }
    let t = normalize(d12);
    let l1 = dot(seg.p1, t);
    let l2 = dot(seg.p2, t);
    let foot = seg.p1 - t * l1;
    let d = length(foot);
    if d <= 0.0 {
        return 0.0;
    }
    let d2 = d * d;
    let q1 = d2 + l1 * l1;
    let q2 = d2 + l2 * l2;
    let f_po = (l2 - l1) * (d2 - l1 * l2) / (d * q1 * q2)
        + atan2_precise(max((l2 - l1) * d, 0.0), d2 + l1 * l2) / d2;
    let f_wt = d * (l2 - l1) * (l2 + l1) / (q1 * q2);
    return (f_po * foot.z + f_wt * t.z) / PI;
}

// TUBE_END_ON: line.rs's END_ON for f32, whose cross product of unit vectors rounds at ~1e-7:
// a line this close to the point subtends a cylinder of radius r at most r·1e-6/d wide.
const TUBE_END_ON: f32 = 1e-6;

// ltc_line: ∫ D dω of the LTC over a unit-radius cylinder about p1 p2: the mapped line's
// diffuse_line times the width factor |det M⁻¹| |p1 × p2| / |M⁻¹p1 × M⁻¹p2| (line.rs).
fn ltc_line(ltc: Ltc, p1: vec3<f32>, p2: vec3<f32>, normalization: u32) -> f32 {
    let c = length(cross(p1, p2));
    if c <= TUBE_END_ON * length(p1) * length(p2) {
        return 0.0;
    }
    let m1 = ltc.cos_from_brdf * p1;
    let m2 = ltc.cos_from_brdf * p2;
    let mapped = length(cross(m1, m2));
    if !(mapped > 0.0) {
        return 0.0;
    }
    let width = ltc.det_cos_from_brdf * c / mapped;
    let value = max(width * diffuse_line(m1, m2), 0.0);
    if normalization == NORMALIZATION_PAPER_LITERAL {
        return PI * value;
    }
    return value;
}

// line_irradiance: ∫ p_z/|p|³ dℓ over the segment's part above the surface (line.rs).
fn line_irradiance(a_in: vec3<f32>, b_in: vec3<f32>) -> f32 {
    let seg = clip_segment(a_in, b_in);
    if !seg.above {
        return 0.0;
    }
    let la = length(seg.p1);
    let lb = length(seg.p2);
    let sum = seg.p1 * lb + seg.p2 * la;
    let denom = dot(sum, sum) / (2.0 * la * lb);
    if !(denom > 0.0) {
        return 0.0;
    }
    return length(seg.p2 - seg.p1) * (seg.p1.z / la + seg.p2.z / lb) / denom;
}

// One lobe of tube_ltc_line: the widened line and, with `ends`, the half-sphere ends as
// points of their silhouettes' areas, the sum at most 1 (π paper-literal).
fn tube_line_lobe(s: TubeShading, ltc: Ltc, seg: Segment3, ends: bool) -> f32 {
    let t = s.tube;
    var line = 0.0;
    if seg.above {
        line = t.radius * ltc_line(ltc, seg.p1, seg.p2, s.pixel.normalization);
    }
    if !ends {
        return line;
    }
    let e = tube_axis(t);
    let r2 = t.radius * t.radius;
    let wa = normalize(t.a);
    let wb = normalize(t.b);
    let end_a = 0.5 * PI * r2 * (1.0 + dot(e, wa)) * ltc_eval(ltc, wa, s.pixel.clip, s.pixel.normalization)
        / max(dot(t.a, t.a), r2);
    let end_b = 0.5 * PI * r2 * (1.0 - dot(e, wb)) * ltc_eval(ltc, wb, s.pixel.clip, s.pixel.normalization)
        / max(dot(t.b, t.b), r2);
    let most = select(1.0, PI, s.pixel.normalization == NORMALIZATION_PAPER_LITERAL);
    return min(line + end_a + end_b, most);
}

// tube_ltc_line: both lobes by the LTC line (ends) or HDRP's tube (no ends), case 1 clipping
// the segment at the surface first.
fn tube_ltc_line(s: TubeShading, pair: LtcPair, ends: bool) -> vec2<f32> {
    var seg = Segment3(s.tube.a, s.tube.b, true);
    if (s.pixel.clip & CLIP_HORIZON) != 0u {
        seg = clip_segment(s.tube.a, s.tube.b);
    }
    let lobes = vec2<f32>(
        tube_line_lobe(s, pair.spec, seg, ends),
        tube_line_lobe(s, pair.diff, seg, ends),
    );
    return lobe_weights(pair, s.pixel.f0, s.pixel.normalization) * lobes;
}

// tube_representative_point: Karis 2013's tube (mod.rs).
fn tube_representative_point(s: TubeShading) -> vec2<f32> {
    let t = s.tube;
    let r = t.radius;
    let len = tube_length(t);
    let reflected = mirror(s.pixel.v);
    let on_segment = t.a + tube_axis(t) * tube_nearest_to_ray(t, reflected);
    let to_ray = reflected * dot(on_segment, reflected) - on_segment;
    let reach = length(to_ray);
    var closest = on_segment + to_ray;
    if reach > r {
        closest = on_segment + to_ray * (r / reach);
    }
    var l = reflected;
    if dot(closest, closest) > 0.0 {
        l = closest / sqrt(dot(closest, closest));
    }
    let d = max(length(on_segment), MIN_LIGHT_DISTANCE);
    let sphere = widening_energy(s.pixel.alpha, min(r / d, 1.0));
    let wide = min(max(s.pixel.alpha.x, s.pixel.alpha.y) + 0.5 * min(r / d, 1.0), 1.0);
    let line = wide / min(wide + 0.5 * min(0.5 * len / d, 1.0), 1.0);
    let intensity = 2.0 * r * len + PI * r * r;
    var specular = 0.0;
    if l.z > 0.0 {
        specular = exact_lobes(s.pixel.v, l, s.pixel.alpha, s.pixel.f0).x;
    }
    let c = tube_centre(t);
    let c2 = max(dot(c, c), r * r);
    let irradiance = 2.0 * r * line_irradiance(t.a, t.b) + PI * r * r * max(c.z / length(c), 0.0) / c2;
    let diffuse = fd_toward(s.pixel.v, normalize(c), 0.5 * (s.pixel.alpha.x + s.pixel.alpha.y)) * irradiance;
    let dr = max(d, r);
    return vec2<f32>(intensity / (dr * dr) * sphere * line * specular, diffuse);
}

// tube_light: both lobes of a tube of unit radiance by `method` (TUBE_*): 0 below the
// horizon, its point light below TUBE_POINT_LIMIT.
fn tube_light(method: u32, s: TubeShading, pair: LtcPair) -> vec2<f32> {
    if tube_below_horizon(s.tube) {
        return vec2<f32>(0.0);
    }
    if tube_angular_size(s.tube) < TUBE_POINT_LIMIT {
        return tube_point(s, pair, method == TUBE_EXACT);
    }
    switch method {
        case TUBE_EXACT: { return tube_band(s); }
        case TUBE_LTC_LINE: { return tube_ltc_line(s, pair, true); }
        case TUBE_HDRP_TUBE: { return tube_ltc_line(s, pair, false); }
        case TUBE_REPRESENTATIVE_POINT: { return tube_representative_point(s); }
        default: { return tube_point(s, pair, false); }
    }
}
