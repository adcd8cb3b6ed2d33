//! Every emitter on the GPU (each shape's `<shape>_emitter_lobes`, which shaders/emitter.wgsl's
//! `emitter_lobes` calls with the side's method) against the f64 CPU methods (`ShapeMethod::emitter_lobes`, each
//! shape's module's), measured directly on random lights of each shape — across the horizon,
//! below it, facing away, edge-on and end-on, from 0.1° to some 90° across, a tube holding the
//! point — then renders of each shape's failure presets by every method, GPU against CPU. The
//! probe, the packing and the comparison are one for every shape; a shape brings its draw and
//! what amplifies f32 rounding in each of its methods (`Emitter`).

use crate::gpu_common::{
    PROBE_LTC, condition, direction, gpu, lights_probe_source, pack_pair, run_probe,
};
use glam::DVec3;
use ltc_lab::brdf::{Alpha, view_from_theta};
use ltc_lab::gpu::light::{method_constant, second_element};
use ltc_lab::light::disk::{Disk, DiskMethod};
use ltc_lab::light::rect::{Rect, RectMethod};
use ltc_lab::light::tube::{Tube, TubeMethod};
use ltc_lab::light::{EmitterShading, ExactRule, Shape, ShapeKind};
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::{Clipping, Ltc, LtcPair, Normalization};
use ltc_lab::measure::parity::RADIANCE_TOLERANCE;
use ltc_lab::render::ShapeMethod;
use ltc_lab::scene::SplitMix64;

/// The most methods a shape has: the probe runs codes 0..METHODS for every case (a code past
/// a shape's last gives its default arm, which nothing reads).
const METHODS: usize = 5;

/// The probe of one shape, `SHAPE` its name: every method of it at each case.
const PROBE: &str = "
@group(0) @binding(0) var<storage, read> probe_in: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> probe_out: array<vec4<f32>>;
const PER_CASE: u32 = 12u;
const METHODS: u32 = 5u;
@compute @workgroup_size(64)
fn probe(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if i >= arrayLength(&probe_in) / PER_CASE {
        return;
    }
    let k = PER_CASE * i;
    let a = probe_in[k];
    let b = probe_in[k + 1u];
    let dims = mat2x4<f32>(probe_in[k + 2u], probe_in[k + 3u]);
    let pair = LtcPair(probe_ltc(k + 4u), probe_ltc(k + 8u));
    let pixel = EmitterShading(a.xyz, vec2<f32>(a.w), b.w, CLIP_HORIZON | CLIP_TRANSFORMED,
        NORMALIZATION_CORRECTED);
    let identity = mat3x3<f32>(vec3<f32>(1.0, 0.0, 0.0), vec3<f32>(0.0, 1.0, 0.0),
        vec3<f32>(0.0, 0.0, 1.0));
    for (var m = 0u; m < METHODS; m++) {
        let lobes = SHAPE_emitter_lobes(m, dims, b.xyz, identity, pixel, pair);
        probe_out[METHODS * i + m] = vec4<f32>(lobes, 0.0);
    }
}
";

/// One case: the view, α, F0, the LTCs at (θo, α), and the light with its centre, all in
/// the shading frame.
struct Case {
    v: DVec3,
    alpha: f64,
    f0: f64,
    pair: LtcPair,
    light: (Shape, DVec3),
}

/// A shape's probe: the seed and count of its cases, its draw (after the view and α, before
/// F0) and what amplifies f32 rounding in each of its methods for one lobe, beside the
/// render's parity tolerance.
struct Emitter {
    kind: ShapeKind,
    seed: u64,
    cases: usize,
    draw: fn(&mut SplitMix64) -> (Shape, DVec3),
    amplification: fn(&Case, ShapeMethod, &Ltc) -> f64,
    /// What amplifies f32 rounding in the area, from the dimensions as the shader maps them.
    area_amplification: fn(&Case) -> f64,
}

fn draw(rng: &mut SplitMix64, lut: &Lut, e: &Emitter) -> Case {
    let theta_o = rng.uniform([0.0, 85.0_f64.to_radians()]);
    let alpha = rng.uniform([0.05, 1.0]);
    let v = DVec3::from(view_from_theta(theta_o));
    let light = (e.draw)(rng);
    Case {
        v,
        alpha,
        f0: rng.uniform([0.0, 1.0]),
        pair: lut.ltc_pair(alpha, v),
        light,
    }
}

/// A unit normal from `centre` tilted from facing the origin toward edge-on, its tilt's
/// elevation at least `least_elevation_deg` (90°: facing it), and one case in ten facing away.
fn normal_toward_origin(rng: &mut SplitMix64, centre: DVec3, least_elevation_deg: f64) -> DVec3 {
    let tilt = direction(
        rng.uniform([
            least_elevation_deg.to_radians(),
            std::f64::consts::FRAC_PI_2,
        ]),
        rng.uniform([0.0, std::f64::consts::TAU]),
    );
    let w = -centre.normalize();
    let (t1, t2) = w.any_orthonormal_pair();
    let normal = (t1 * tilt.x + t2 * tilt.y + w * tilt.z).normalize();
    if rng.uniform([0.0, 1.0]) < 0.1 {
        -normal
    } else {
        normal
    }
}

/// A centre from 30° below the horizon to the zenith, 0.3 to 3 from the point.
fn centre_about(rng: &mut SplitMix64) -> DVec3 {
    let elevation = rng.uniform([-30.0_f64.to_radians(), std::f64::consts::FRAC_PI_2]);
    let azimuth = rng.uniform([0.0, std::f64::consts::TAU]);
    direction(elevation, azimuth) * rng.uniform([0.3, 3.0])
}

/// Rects: the normal within 70° of facing the point, the half-edges from 0.1% to 100% of the
/// distance, log-uniform, of aspect up to 4.
fn draw_rect(rng: &mut SplitMix64) -> (Shape, DVec3) {
    let centre = centre_about(rng);
    let normal = normal_toward_origin(rng, centre, 20.0);
    let (e1, e2) = normal.any_orthonormal_pair();
    let size = centre.length() * 10f64.powf(rng.uniform([-3.0, 0.0]));
    let aspect = rng.uniform([0.25, 1.0]);
    let shape = Shape::Rect {
        half_u: e1 * size,
        half_v: e2 * size * aspect,
    };
    (shape, centre)
}

/// Disks: the normal from facing the point to edge-on, the radius from 0.1% to 100% of the
/// distance, log-uniform.
fn draw_disk(rng: &mut SplitMix64) -> (Shape, DVec3) {
    let centre = centre_about(rng);
    let normal = normal_toward_origin(rng, centre, 0.0);
    let radius = centre.length() * 10f64.powf(rng.uniform([-3.0, 0.0]));
    (Shape::Disk { normal, radius }, centre)
}

/// Tubes: the centre from 20° below the horizon, the axis any way (some end-on, some across
/// the horizon), its length from none to four times its distance, its radius from 0.1% to 30%
/// of the distance, log-uniform (some slivers); one case in twenty holds the point (a capsule
/// lying on the surface, seen from within).
fn draw_tube(rng: &mut SplitMix64) -> (Shape, DVec3) {
    let elevation = rng.uniform([-20.0_f64.to_radians(), std::f64::consts::FRAC_PI_2]);
    let d = rng.uniform([0.3, 3.0]);
    let centre = direction(elevation, rng.uniform([0.0, std::f64::consts::TAU])) * d;
    let axis = direction(
        rng.uniform([-1.0, 1.0f64]).asin(),
        rng.uniform([0.0, std::f64::consts::TAU]),
    );
    let half_axis = axis * (d * rng.uniform([0.0, 2.0]));
    let mut radius = 0.3 * d * 10f64.powf(rng.uniform([-3.0, 0.0]));
    if rng.uniform([0.0, 1.0]) < 0.05 {
        radius = 1.2 * tube_of((Shape::Tube { half_axis, radius }, centre)).distance_to_segment();
    }
    (Shape::Tube { half_axis, radius }, centre)
}

fn rect_of((shape, centre): (Shape, DVec3)) -> Rect {
    let (u, v) = shape.half_edges().expect("a rect");
    Rect { centre, u, v }
}

fn disk_of((shape, centre): (Shape, DVec3)) -> Disk {
    let Shape::Disk { normal, radius } = shape else {
        panic!("a disk")
    };
    Disk {
        centre,
        normal,
        radius,
    }
}

fn tube_of((shape, centre): (Shape, DVec3)) -> Tube {
    let Shape::Tube { half_axis, radius } = shape else {
        panic!("a tube")
    };
    Tube {
        a: centre - half_axis,
        b: centre + half_axis,
        radius,
    }
}

// What amplifies f32 rounding, each beside the render's parity tolerance. For every shape
// the exact rule samples the lobe at directions good to a few ε, which moves a GGX peak by
// ε/α², and the LTC's methods carry its condition number κ (M⁻¹ stretches the shape by up to
// κ). Each chain has some sixteen roundings; `assert_probe_matches` allows 64, four times that.

/// Rects: the edge formula sums terms of size s/d to a value of size (s/d)², each term good
/// to a few ε of itself: ε·d/s of the value. Clipped, a cut point carries the rounding of the
/// edge it cuts, of order one beside the sliver it leaves: one κ more.
fn rect_amplification(c: &Case, m: ShapeMethod, lobe: &Ltc) -> f64 {
    let s_over_d = rect_of(c.light).angular_size().min(1.0);
    match m {
        ShapeMethod::Rect(RectMethod::Exact) => 1.0 / (c.alpha * c.alpha),
        ShapeMethod::Rect(RectMethod::LtcPoint) => condition(lobe),
        _ => condition(lobe) * (1.0 / s_over_d + 1.0),
    }
}

/// Disks: the cone's algebra (as the sphere's LTC disk's, tests/gpu/sphere_light.rs) for a
/// small or edge-on disk by the ratio of its thickness seen from the point to its distance
/// (the ellipse's short axis `r |cos θe| / d`, how near B is to singular).
fn disk_amplification(c: &Case, m: ShapeMethod, lobe: &Ltc) -> f64 {
    let disk = disk_of(c.light);
    let cos_e = disk.normal.dot(disk.centre.normalize()).abs();
    let thin = (disk.angular_size() * cos_e).clamp(1e-6, 1.0);
    match m {
        ShapeMethod::Disk(DiskMethod::Exact) => 1.0 / (c.alpha * c.alpha),
        ShapeMethod::Disk(DiskMethod::LtcPoint) => condition(lobe),
        _ => condition(lobe) * (1.0 / thin + 1.0),
    }
}

/// Tubes: the line's width factor, for a sliver, by the ratio of its distance to its radius
/// (how near the mapped cross product is to rounding); the representative point's place on
/// the segment, `(c a·w − a·e)/(1 − c²)` with `c = e·w`, by `1/(1 − c²)` where the segment
/// runs nearly along the mirror ray `w`.
fn tube_amplification(c: &Case, m: ShapeMethod, lobe: &Ltc) -> f64 {
    let tube = tube_of(c.light);
    let thin = (tube.radius / tube.centre().length()).clamp(1e-6, 1.0);
    let along = tube.axis().dot(ltc_lab::light::polar::mirror(c.v));
    let parallel = 1.0 / (1.0 - along * along).max(1e-6);
    match m {
        ShapeMethod::Tube(TubeMethod::Exact) => 1.0 / (c.alpha * c.alpha),
        ShapeMethod::Tube(TubeMethod::RepresentativePoint) => parallel / (c.alpha * c.alpha),
        ShapeMethod::Tube(TubeMethod::LtcPoint) => condition(lobe),
        _ => condition(lobe) * (1.0 / thin + 1.0),
    }
}

/// A rect's and a disk's areas are products of their mapped dimensions: a few ε of themselves.
fn no_area_amplification(_: &Case) -> f64 {
    1.0
}

/// A tube's length is `|b − a|` of its ends `c ± h`, each good to ε|c|: `ε (|c| + |h|)/|h|` of it.
fn tube_area_amplification(c: &Case) -> f64 {
    let Shape::Tube { half_axis, .. } = c.light.0 else {
        panic!("a tube")
    };
    (c.light.1.length() + half_axis.length()) / half_axis.length().max(1e-12)
}

const RECTS: Emitter = Emitter {
    kind: ShapeKind::Rect,
    seed: 41,
    cases: 4096,
    draw: draw_rect,
    amplification: rect_amplification,
    area_amplification: no_area_amplification,
};

const DISKS: Emitter = Emitter {
    kind: ShapeKind::Disk,
    seed: 43,
    cases: 4096,
    draw: draw_disk,
    amplification: disk_amplification,
    area_amplification: no_area_amplification,
};

const TUBES: Emitter = Emitter {
    kind: ShapeKind::Tube,
    seed: 53,
    cases: 2048,
    draw: draw_tube,
    amplification: tube_amplification,
    area_amplification: tube_area_amplification,
};

/// The case as the probe reads it: 12 vec4s — (v, α), (centre, F0), the light buffer's
/// second element (the dimensions `<shape>_emitter_lobes` reads), then the pair.
fn pack(c: &Case) -> Vec<[f32; 4]> {
    let f = |x: f64| x as f32;
    let v4 = |v: DVec3, w: f64| [f(v.x), f(v.y), f(v.z), f(w)];
    let mut out = vec![v4(c.v, c.alpha), v4(c.light.1, c.f0)];
    out.extend(second_element(c.light.0).expect("an emitter has a second element"));
    out.extend(pack_pair(&c.pair));
    out
}

/// The CPU's lobes and area of `c` by `m` at the renders' exact rule.
fn cpu_lobes(c: &Case, m: ShapeMethod) -> [f64; 3] {
    let s = EmitterShading {
        v: c.v,
        alpha: Alpha::isotropic(c.alpha),
        f0: c.f0,
        ltc: &c.pair,
        clip: Clipping::BOTH,
        normalization: Normalization::Corrected,
    };
    let (lobes, area) = m
        .emitter_lobes(c.light, &|x| x, &s, ExactRule::Render)
        .expect("an emitter's own method");
    [lobes.specular, lobes.diffuse, area]
}

/// `e`'s cases by every method of its shape, GPU against CPU: finite, never negative, within
/// the render's parity tolerance plus 64 ε times the method's amplification, relative to the
/// larger of the CPU's value and §4.2's floor (1% of the column's mean, so that a near-black
/// case is judged on the scale of the light it is part of); the area to f32's rounding.
fn assert_probe_matches(e: &Emitter) -> Vec<Case> {
    let lut = Lut::embedded();
    let mut rng = SplitMix64(e.seed);
    let cases: Vec<Case> = (0..e.cases).map(|_| draw(&mut rng, lut, e)).collect();
    let input: Vec<[f32; 4]> = cases.iter().flat_map(pack).collect();
    let probe = PROBE.replace("SHAPE", e.kind.name());
    let source = lights_probe_source(&[&probe, PROBE_LTC].concat());
    let got = run_probe(
        &source,
        &[],
        bytemuck::cast_slice(&input),
        &[],
        METHODS * cases.len(),
    );
    for m in ShapeMethod::all(e.kind) {
        let code = method_constant(m)
            .expect("an emitter's method has a code")
            .0 as usize;
        let want: Vec<[f64; 3]> = cases.iter().map(|c| cpu_lobes(c, m)).collect();
        let gpu = |i: usize| got[METHODS * i + code].map(f64::from);
        for (i, w) in want.iter().enumerate() {
            // f32's rounding of the packed dimensions and of the area's few products (some
            // eight roundings; 16 is twice that), times what amplifies it.
            let area_error = (gpu(i)[2] - w[2]).abs() / w[2];
            let area_bound = 16.0 * f64::from(f32::EPSILON) * (e.area_amplification)(&cases[i]);
            assert!(
                area_error <= area_bound,
                "{} case {i}: area {} not {} ({area_error:.2e} > {area_bound:.2e})",
                m.name(),
                gpu(i)[2],
                w[2]
            );
        }
        for (lobe_at, lobe_name) in ["specular", "diffuse"].iter().enumerate() {
            let name = format!("{} {} {lobe_name}", e.kind.name(), m.name());
            let floor =
                0.01 * want.iter().map(|w| w[lobe_at].abs()).sum::<f64>() / want.len() as f64;
            let mut worst = (0.0f64, 0usize);
            for (i, (w, c)) in want.iter().zip(&cases).enumerate() {
                let g = gpu(i)[lobe_at];
                assert!(g.is_finite() && g >= 0.0, "{name} case {i}: {g}");
                let err = (g - w[lobe_at]).abs() / w[lobe_at].abs().max(floor);
                let lobe = [&c.pair.spec, &c.pair.diff][lobe_at];
                let amplification = (e.amplification)(c, m, lobe);
                let bound = RADIANCE_TOLERANCE + 64.0 * f64::from(f32::EPSILON) * amplification;
                assert!(
                    err <= bound,
                    "{name} case {i} (α {}, v {:?}, {:?}): gpu {g} cpu {} ({err:.2e} > {bound:.2e})",
                    c.alpha,
                    c.v,
                    c.light,
                    w[lobe_at]
                );
                if err > worst.0 {
                    worst = (err, i);
                }
            }
            eprintln!("{name}: worst {:.2e} (case {})", worst.0, worst.1);
        }
    }
    cases
}

#[test]
fn gpu_rect_lights_match_the_cpu_methods() {
    if gpu().is_some() {
        assert_probe_matches(&RECTS);
    }
}

#[test]
fn gpu_disk_lights_match_the_cpu_methods() {
    if gpu().is_some() {
        assert_probe_matches(&DISKS);
    }
}

#[test]
fn gpu_tube_lights_match_the_cpu_methods() {
    if gpu().is_none() {
        return;
    }
    let cases = assert_probe_matches(&TUBES);
    // The draw reaches what it says: capsules holding the point, and slivers.
    let tubes: Vec<Tube> = cases.iter().map(|c| tube_of(c.light)).collect();
    let inside = tubes.iter().filter(|t| t.encloses_origin()).count();
    let slivers = tubes
        .iter()
        .filter(|t| t.radius < 0.01 * t.centre().length())
        .count();
    assert!(
        inside > 10 && slivers > 100,
        "{inside} inside, {slivers} slivers"
    );
}

// Each emitter's failure presets (a rect leaning over the horizon, crossing the plane,
// edge-on, facing away, touching the surface, behind it, tiny, filling the sky; a disk across
// the horizon, behind the surface, edge-on; a tube across the horizon, standing on the plane,
// long and thin, tiny) rendered by every method of its shape beside each point form, GPU
// against the CPU (`assert_shape_presets_match`): finite, never negative, and within the
// renders' parity tolerance (the probes above bound each method's f32 error per light well
// inside it). A test a shape, so that they run side by side.

#[test]
fn gpu_renders_of_rect_lights_match_the_cpu() {
    if gpu().is_some() {
        crate::gpu_common::assert_shape_presets_match(ShapeKind::Rect);
    }
}

#[test]
fn gpu_renders_of_disk_lights_match_the_cpu() {
    if gpu().is_some() {
        crate::gpu_common::assert_shape_presets_match(ShapeKind::Disk);
    }
}

#[test]
fn gpu_renders_of_tube_lights_match_the_cpu() {
    if gpu().is_some() {
        crate::gpu_common::assert_shape_presets_match(ShapeKind::Tube);
    }
}
