// Disk lights (docs/design.md §1.12), mirroring src/light/disk/mod.rs and
// src/light/disk/quadrature.rs by name. Composed after sphere_light.wgsl (the cone's algebra,
// gl8, sincos_precise, mirror) and rect_light.wgsl (atan2_precise).

// The light buffer's code for a disk (src/gpu/light/mod.rs shape_constant).
const SHAPE_DISK: u32 = 3u;

// How a side shades a disk (src/light/disk/mod.rs DiskMethod; disk_light.rs disk_constant).
const DISK_EXACT: u32 = 0u;     // the BRDF over the disk above the surface
const DISK_LTC_DISK: u32 = 1u;  // Heitz & Hill 2017: the disk's cone mapped by M⁻¹
const DISK_LTC_POINT: u32 = 2u; // the centre as an oriented point light

// Some light is a disk, and how A and B shade disks (constants, as rect_light.wgsl's).
override DISKS: bool = false;
override DISK_A: u32 = DISK_LTC_DISK;
override DISK_B: u32 = DISK_EXACT;

// A disk: centre, unit normal (the side it emits toward) and radius, in the shading frame.
struct Disk {
    centre: vec3<f32>,
    normal: vec3<f32>,
    radius: f32,
}

// DISK_POINT_LIMIT: below this r/|c| a disk is shaded as its oriented point light.
const DISK_POINT_LIMIT: f32 = 1e-7;

// Nodes a dimension and piece of the renders' exact rule (src/light/disk/mod.rs RENDER_NODES).
const DISK_RENDER_NODES: u32 = 12u;

fn disk_area(d: Disk) -> f32 {
    return PI * d.radius * d.radius;
}

fn disk_faces_origin(d: Disk) -> bool {
    return dot(d.centre, d.normal) < 0.0;
}

fn disk_angular_size(d: Disk) -> f32 {
    return d.radius / length(d.centre);
}

// Disk::below_horizon: its highest point, c_z + r √(1 − n_z²), at or below the surface.
fn disk_below_horizon(d: Disk) -> bool {
    return d.centre.z + d.radius * sqrt(max(1.0 - d.normal.z * d.normal.z, 0.0)) <= 0.0;
}

// Disk::point_irradiance: A cos θe / d² at unit radiance.
fn disk_point_irradiance(d: Disk) -> f32 {
    let d2 = dot(d.centre, d.centre);
    let cos_e = -dot(d.normal, d.centre) / sqrt(d2);
    return disk_area(d) * max(cos_e, 0.0) / d2;
}

// Disk::half_axes: two perpendicular radii in its plane.
fn disk_half_axes(d: Disk) -> mat2x3<f32> {
    let frame = orthonormal_pair(d.normal);
    return mat2x3<f32>(frame[0] * d.radius, frame[1] * d.radius);
}

// Segment: the part of a disk above the surface in plane coordinates in radii along f1 (where
// the height grows) and f2 = n × f1: x² + y² ≤ 1, x ≥ x0; x0 ≥ 1 where none is.
struct Segment {
    f1: vec3<f32>,
    f2: vec3<f32>,
    x0: f32,
}

// Segment::above.
fn segment_above(d: Disk) -> Segment {
    let n = d.normal;
    let up = vec3<f32>(0.0, 0.0, 1.0) - n * n.z;
    let k = length(up);
    var f1 = orthonormal_pair(n)[0];
    var x0 = 1.0;
    if k > 0.0 {
        f1 = up / k;
        x0 = max(-d.centre.z / (d.radius * k), -1.0);
    } else if d.centre.z > 0.0 {
        x0 = -1.0;
    }
    return Segment(f1, cross(n, f1), x0);
}

// Segment::point: the point at plane coordinates q.
fn segment_point(seg: Segment, d: Disk, q: vec2<f32>) -> vec3<f32> {
    return d.centre + (seg.f1 * q.x + seg.f2 * q.y) * d.radius;
}

// Segment::hit_inside: where the ray along `dir` meets the disk's plane, in plane
// coordinates (xy), z = 1 if inside the segment.
fn segment_hit_inside(seg: Segment, d: Disk, dir: vec3<f32>) -> vec3<f32> {
    let along = dot(dir, d.normal);
    if along == 0.0 {
        return vec3<f32>(0.0);
    }
    let t = dot(d.centre, d.normal) / along;
    if t <= 0.0 {
        return vec3<f32>(0.0);
    }
    let offset = dir * t - d.centre;
    let q = vec2<f32>(dot(offset, seg.f1), dot(offset, seg.f2)) / d.radius;
    return vec3<f32>(q, select(0.0, 1.0, dot(q, q) < 1.0 && q.x > seg.x0));
}

// atan2 over the whole circle, by atan2_precise: the angle in [−π, π].
fn atan2_full(y: f32, x: f32) -> f32 {
    let a = atan2_precise(abs(y), x);
    return select(a, -a, y < 0.0);
}

// Segment::pieces: four (first angle, width) about `apex`, the last reaching the chord where
// the segment has one (x0 > −1), every other the arc.
fn segment_pieces(seg: Segment, apex: vec2<f32>) -> array<vec2<f32>, 4> {
    if seg.x0 <= -1.0 {
        return array<vec2<f32>, 4>(
            vec2<f32>(0.0, 0.5 * PI),
            vec2<f32>(0.5 * PI, 0.5 * PI),
            vec2<f32>(PI, 0.5 * PI),
            vec2<f32>(1.5 * PI, 0.5 * PI),
        );
    }
    let y1 = sqrt(max(1.0 - seg.x0 * seg.x0, 0.0));
    let upper = atan2_full(y1 - apex.y, seg.x0 - apex.x);
    let lower = atan2_full(-y1 - apex.y, seg.x0 - apex.x);
    var arc = upper - lower;
    if arc < 0.0 {
        arc += 2.0 * PI;
    }
    let third = arc / 3.0;
    return array<vec2<f32>, 4>(
        vec2<f32>(lower, third),
        vec2<f32>(lower + third, third),
        vec2<f32>(lower + 2.0 * third, third),
        vec2<f32>(upper, 2.0 * PI - arc),
    );
}

// Segment::reach: the distance from `apex` along unit `d` to the arc, or to the chord.
fn segment_reach(seg: Segment, apex: vec2<f32>, d: vec2<f32>, chord: bool) -> f32 {
    if chord {
        return max((seg.x0 - apex.x) / d.x, 0.0);
    }
    let b = dot(apex, d);
    return -b + sqrt(max(b * b + 1.0 - dot(apex, apex), 0.0));
}

// One disk of unit radiance at one shading point (src/light/disk/mod.rs DiskShading).
struct DiskShading {
    pixel: EmitterShading,
    disk: Disk,
}

// disk_emitter_lobes: a disk's unit-radiance lobes by `method` (DISK_*) and its area, for
// emitter.wgsl's emitter_lobes (src/light/disk/mod.rs emitter_lobes): centred at `centre`, its
// unit normal and radius `dims[0]`, mapped to the shading frame by `to_frame`.
fn disk_emitter_lobes(
    method: u32,
    dims: mat2x4<f32>,
    centre: vec3<f32>,
    to_frame: mat3x3<f32>,
    pixel: EmitterShading,
    pair: LtcPair,
) -> vec3<f32> {
    let disk = Disk(to_frame * centre, to_frame * dims[0].xyz, dims[0].w);
    return vec3<f32>(disk_light(method, DiskShading(pixel, disk), pair), disk_area(disk));
}

// disk_point: the oriented point light at the centre — the exact point light for the exact
// method, the paper's point formula for the LTC ones.
fn disk_point(s: DiskShading, pair: LtcPair, exact: bool) -> vec2<f32> {
    let l = normalize(s.disk.centre);
    return emitter_shading_point_light(s.pixel, pair, l, disk_point_irradiance(s.disk), exact);
}

// disk_exact: ∫ f cos dω over the disk above the surface at unit radiance, by
// disk_integral_about's rule with DISK_RENDER_NODES per dimension and piece (src/light/disk/
// mod.rs RENDER_NODES): polar about the mirror direction's hit where it is inside, else the
// segment's middle, in the four pieces of segment_pieces.
fn disk_exact(s: DiskShading) -> vec2<f32> {
    let d = s.disk;
    let seg = segment_above(d);
    if seg.x0 >= 1.0 {
        return vec2<f32>(0.0);
    }
    let hit = segment_hit_inside(seg, d, mirror(s.pixel.v));
    var apex = vec2<f32>(0.5 * (seg.x0 + 1.0), 0.0);
    if hit.z > 0.0 {
        apex = hit.xy;
    }
    let pieces = segment_pieces(seg, apex);
    let r2 = d.radius * d.radius;
    var sum = vec2<f32>(0.0);
    for (var p = 0u; p < 4u; p++) {
        let chord = p == 3u && seg.x0 > -1.0;
        let start = pieces[p].x;
        let width = pieces[p].y;
        for (var i = 0u; i < DISK_RENDER_NODES; i++) {
            let ns = rule(DISK_RENDER_NODES, i);
            var phi = start + 0.5 * width * (ns.x + 1.0);
            if phi > PI {
                phi -= 2.0 * PI;
            }
            let sc = sincos_precise(phi);
            let dir = vec2<f32>(sc.y, sc.x);
            let reach = segment_reach(seg, apex, dir, chord);
            for (var j = 0u; j < DISK_RENDER_NODES; j++) {
                let nt = rule(DISK_RENDER_NODES, j);
                let rho = 0.5 * reach * (nt.x + 1.0);
                let x = segment_point(seg, d, apex + dir * rho);
                let len2 = dot(x, x);
                if len2 > 0.0 {
                    let len = sqrt(len2);
                    let l = x / len;
                    if l.z > 0.0 {
                        let weight = 0.25 * ns.y * nt.y * width * reach * rho * r2
                            * abs(dot(x, d.normal)) / (len * len2);
                        sum += weight * exact_lobes(s.pixel.v, l, s.pixel.alpha, s.pixel.f0);
                    }
                }
            }
        }
    }
    return sum;
}

// disk_ltc: both lobes by Heitz & Hill's LTC over the disk's cone (ltc_disk_light), made for
// both lobes at once; with case 1 a disk wholly below the surface gives 0.
fn disk_ltc(s: DiskShading, pair: LtcPair) -> vec2<f32> {
    if (s.pixel.clip & CLIP_HORIZON) != 0u && disk_below_horizon(s.disk) {
        return vec2<f32>(0.0);
    }
    let axes = disk_half_axes(s.disk);
    let cones = cone_images(pair, mat3x3<f32>(axes[0], axes[1], s.disk.centre), s.disk.centre);
    let case2 = (s.pixel.clip & CLIP_TRANSFORMED) != 0u;
    let lobes = vec2<f32>(
        ltc_disk_light(pair.spec, s.disk, cones[0], case2, s.pixel.normalization),
        ltc_disk_light(pair.diff, s.disk, cones[1], case2, s.pixel.normalization),
    );
    return lobe_weights(pair, s.pixel.f0, s.pixel.normalization) * lobes;
}

// ltc_disk_light: ∫ D(ω) dω over a disk's cone, given its image under M⁻¹; the hemisphere
// behind its normal where the cone is too wide for its algebra.
fn ltc_disk_light(ltc: Ltc, d: Disk, transformed: vec4<f32>, case2: bool, normalization: u32) -> f32 {
    var cone = transformed;
    if !cone_usable(cone) {
        cone = hemisphere(ltc, -d.normal);
    }
    return cone_integral(cone, case2, normalization);
}

// disk_light: both lobes of a disk of unit radiance by `method` (DISK_*): 0
// facing away, its point light below DISK_POINT_LIMIT.
fn disk_light(method: u32, s: DiskShading, pair: LtcPair) -> vec2<f32> {
    if !disk_faces_origin(s.disk) {
        return vec2<f32>(0.0);
    }
    if disk_angular_size(s.disk) < DISK_POINT_LIMIT {
        return disk_point(s, pair, method == DISK_EXACT);
    }
    switch method {
        case DISK_EXACT: { return disk_exact(s); }
        case DISK_LTC_DISK: { return disk_ltc(s, pair); }
        default: { return disk_point(s, pair, false); }
    }
}
