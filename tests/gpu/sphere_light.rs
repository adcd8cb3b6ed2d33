//! Lights with a size on the GPU (shaders/sphere_light.wgsl) against the f64 CPU methods
//! (src/light/sphere/mod.rs) — the exact integral with the GPU's rule, the LTC disk and the
//! representative point — measured directly on random spheres: cut by the horizon, below it,
//! enclosing the point, from a tenth of a degree to 60°.

use crate::gpu_common::{
    PROBE_LTC, condition, gpu, gpu_frame, lights_probe_source, pack_pair, run_probe,
};
use glam::DVec3;
use ltc_lab::brdf::view_from_theta;
use ltc_lab::light::sphere::cap::Cap;
use ltc_lab::light::sphere::{
    SphereShading, sphere_ltc_disk, sphere_representative_point, sphere_rule,
};
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::{Clipping, LtcPair, Normalization};
use ltc_lab::measure::parity::RADIANCE_TOLERANCE;
use ltc_lab::scene::SplitMix64;

const PROBE: &str = "
@group(0) @binding(0) var<storage, read> probe_in: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> probe_out: array<vec4<f32>>;
const PER_CASE: u32 = 11u;
@compute @workgroup_size(64)
fn probe(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if i >= arrayLength(&probe_in) / PER_CASE {
        return;
    }
    let k = PER_CASE * i;
    let a = probe_in[k];
    let b = probe_in[k + 1u];
    let c = probe_in[k + 2u];
    let pair = LtcPair(probe_ltc(k + 3u), probe_ltc(k + 7u));
    let s = SphereShading(a.xyz, b.xyz, 1.0, -1.0, a.w, vec2<f32>(b.w), c.x, CLIP_HORIZON | CLIP_TRANSFORMED,
        NORMALIZATION_CORRECTED);
    let cap = cap_of_sphere(s.u, s.radius);
    let disk = sphere_ltc_disk(s, pair, cap);
    probe_out[2u * i] = vec4<f32>(disk, sphere_representative_point(s, cap));
    probe_out[2u * i + 1u] = vec4<f32>(sphere_rule(s, cap), 0.0, 0.0);
}
";

/// One case: the view, the centre's offset, the radius, α, F0 and the LTCs at (θo, α).
struct Case {
    v: DVec3,
    u: DVec3,
    radius: f64,
    alpha: f64,
    f0: f64,
    pair: LtcPair,
}

fn draw(rng: &mut SplitMix64, lut: &Lut) -> Case {
    let theta_o = rng.uniform([0.0, 85.0_f64.to_radians()]);
    let alpha = rng.uniform([0.02, 1.0]);
    let v = DVec3::from(view_from_theta(theta_o));
    let elevation = rng.uniform([-30.0_f64.to_radians(), std::f64::consts::FRAC_PI_2]);
    let azimuth = rng.uniform([0.0, std::f64::consts::TAU]);
    let d = rng.uniform([0.3, 3.0]);
    let dir = DVec3::new(
        elevation.cos() * azimuth.cos(),
        elevation.cos() * azimuth.sin(),
        elevation.sin(),
    );
    // From a tenth of a degree to 60°, and one case in ten enclosing the point.
    let sigma = rng.uniform([0.1_f64.to_radians(), 60.0_f64.to_radians()]);
    let radius = if rng.uniform([0.0, 1.0]) < 0.1 {
        1.5 * d
    } else {
        d * sigma.sin()
    };
    Case {
        v,
        u: dir * d,
        radius,
        alpha,
        f0: rng.uniform([0.0, 1.0]),
        pair: lut.ltc_pair(alpha, v),
    }
}

/// The case as the probe reads it: 11 vec4s.
fn pack(c: &Case) -> Vec<[f32; 4]> {
    let f = |x: f64| x as f32;
    let mut out = vec![
        [f(c.v.x), f(c.v.y), f(c.v.z), f(c.radius)],
        [f(c.u.x), f(c.u.y), f(c.u.z), f(c.alpha)],
        [f(c.f0), 0.0, 0.0, 0.0],
    ];
    out.extend(pack_pair(&c.pair));
    out
}

/// The probe `tail` composed after the sphere lights' shaders, run over `input`.
fn probe(tail: &str, input: &[[f32; 4]], outputs: usize) -> Vec<[f32; 4]> {
    let source = lights_probe_source(tail);
    run_probe(&source, &[], bytemuck::cast_slice(input), &[], outputs)
}

#[test]
fn gpu_sphere_lights_match_the_cpu_methods() {
    if gpu().is_none() {
        return;
    }
    let lut = Lut::embedded();
    let mut rng = SplitMix64(32);
    let cases: Vec<Case> = (0..4096).map(|_| draw(&mut rng, lut)).collect();
    let input: Vec<[f32; 4]> = cases.iter().flat_map(pack).collect();
    let got = probe(&[PROBE, PROBE_LTC].concat(), &input, 2 * cases.len());
    let want: Vec<[f64; 6]> = cases
        .iter()
        .map(|c| {
            let s = SphereShading {
                v: c.v,
                u: c.u,
                intensity: 1.0,
                range: f64::INFINITY,
                radius: c.radius,
                alpha: ltc_lab::brdf::Alpha::isotropic(c.alpha),
                f0: c.f0,
                ltc: &c.pair,
                clip: Clipping::BOTH,
                normalization: Normalization::Corrected,
            };
            let cap = Cap::of_sphere(c.u, c.radius).unwrap();
            let (disk, rep) = (
                sphere_ltc_disk(&s, &cap),
                sphere_representative_point(&s, &cap),
            );
            let exact = sphere_rule(&s, &cap);
            [
                disk.specular,
                disk.diffuse,
                rep.specular,
                rep.diffuse,
                exact.specular,
                exact.diffuse,
            ]
        })
        .collect();
    let names = [
        "ltc-disk specular",
        "ltc-disk diffuse",
        "representative specular",
        "representative diffuse",
        "exact specular",
        "exact diffuse",
    ];
    let got: Vec<[f32; 6]> = got
        .chunks(2)
        .map(|p| [p[0][0], p[0][1], p[0][2], p[0][3], p[1][0], p[1][1]])
        .collect();
    for (k, name) in names.iter().enumerate() {
        // §4.2's floor: 1% of the column's mean, so that a near-black case is judged on the
        // scale of the light it is part of.
        let floor = 0.01 * want.iter().map(|w| w[k].abs()).sum::<f64>() / want.len() as f64;
        let mut worst = (0.0f64, 0usize);
        for (i, (w, g)) in want.iter().zip(&got).enumerate() {
            let g = f64::from(g[k]);
            assert!(g.is_finite() && g >= 0.0, "{name} case {i}: {g}");
            let err = (g - w[k]).abs() / w[k].abs().max(floor);
            let c = &cases[i];
            let lobe = if k % 2 == 0 {
                &c.pair.spec
            } else {
                &c.pair.diff
            };
            let sin_sigma = (c.radius / c.u.length()).min(1.0);
            // The render's parity tolerance (`parity::RADIANCE_TOLERANCE`), plus what f32
            // rounding is amplified by here. For a cap: a direction rounded by ε moves its cut
            // by ε/sin σ of its width, and the LTC disk's M⁻¹ stretches directions by up to
            // its condition number κ (bounded by ‖M⁻¹‖·‖M‖ in Frobenius norms). For the
            // representative point's specular lobe, evaluated at one direction: at the peak,
            // D's denominator is α² + (1 − n·h)(1 + n·h), and n·h carries a rounding of a few
            // ε, so 1/α². Each chain has some sixteen roundings (B, its adjugate, Q's
            // products, the root, the null vector, the clipped integral; or the half vector
            // and D, G, F); 64 is four times that. Lavapipe needs 15 of the cap's factor.
            let amplification = match k {
                0 | 1 => condition(lobe) / sin_sigma,
                2 => 1.0 / (c.alpha * c.alpha),
                _ => 1.0 / sin_sigma,
            };
            let bound = RADIANCE_TOLERANCE + 64.0 * f64::from(f32::EPSILON) * amplification;
            assert!(
                err <= bound,
                "{name} case {i} (α {}, σ {:.1}°): gpu {g} cpu {} ({err:.2e} > {bound:.2e})",
                c.alpha,
                sin_sigma.asin().to_degrees(),
                w[k]
            );
            if err > worst.0 {
                worst = (err, i);
            }
        }
        eprintln!("{name}: worst {:.2e} (case {})", worst.0, worst.1);
    }
}

const ARC_PROBE: &str = "
@group(0) @binding(0) var<storage, read> probe_in: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> probe_out: array<vec4<f32>>;
@compute @workgroup_size(64)
fn probe(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if i >= arrayLength(&probe_in) {
        return;
    }
    let x = probe_in[i];
    probe_out[i] = vec4<f32>(atan_precise(x.x), acos_precise(x.y), 0.0, 0.0);
}
";

/// The shaders' own arctangent and arccosine, which the clipped integral leans on, within a
/// few ulps of f64's: the fit's 2.1e-8 (a third of an ulp) and some four roundings. Checked
/// over [0, 1e4] and [−1, 1], where WGSL's own are allowed 4096 ulps.
#[test]
fn gpu_precise_arctangents_are_within_a_few_ulps() {
    if gpu().is_none() {
        return;
    }
    let input: Vec<[f32; 4]> = (0..8192)
        .map(|k| {
            let t = k as f32 / 8191.0;
            [1e4 * t * t * t, 2.0 * t - 1.0, 0.0, 0.0]
        })
        .collect();
    let got = probe(ARC_PROBE, &input, input.len());
    let ulp = f64::from(f32::EPSILON);
    for (x, g) in input.iter().zip(&got) {
        let atan = f64::from(x[0]).atan();
        let acos = f64::from(x[1]).acos();
        assert!(
            (f64::from(g[0]) - atan).abs() <= 8.0 * ulp * atan.max(1e-30),
            "atan {}: {} vs {atan}",
            x[0],
            g[0]
        );
        // acos near 1 is √(2(1 − y)) and inherits the rounding of 1 − y, half an ulp of 1.
        assert!(
            (f64::from(g[1]) - acos).abs() <= 8.0 * ulp * acos.max(1e-3),
            "acos {}: {} vs {acos}",
            x[1],
            g[1]
        );
    }
}

/// Renders of sphere lights, each way a side shades them, GPU against the CPU reference: a
/// light above the plane, one cut by the horizon, a large one, a small one, one whose sphere
/// reaches the plane's far edge. The same tolerance as the point lights' renders
/// (`RADIANCE_TOLERANCE` of max(reference, floor)): the sphere methods are a few dozen f32
/// operations per light more than the point formula, the exact one the same 8-node rule on
/// both sides, and the probe above bounds each method's f32 error per light well inside it
/// for caps of these sizes (σ from 1° to 40°).
#[test]
fn gpu_renders_of_sphere_lights_match_the_cpu() {
    use ltc_lab::light::sphere::SphereMethod;
    use ltc_lab::render::{Method, RenderSettings, View};
    use ltc_lab::scene::{Light, preset};
    if gpu().is_none() {
        return;
    }
    let light = |position: [f64; 3], radius: f64| Light {
        position,
        color: [1.0, 0.8, 0.6],
        intensity: 0.2,
        range: None,
        shape: ltc_lab::light::Shape::of_radius(radius),
    };
    let mut scene = preset("paper-100");
    scene.lights = vec![
        light([0.3, 0.2, 0.4], 0.1),
        light([-0.5, 0.4, 0.05], 0.15),
        light([0.0, -0.6, 0.8], 0.3),
        light([0.8, -0.2, 0.25], 0.02),
        light([-1.2, -1.0, 0.3], 0.25),
    ];
    let (w, h) = (48, 40);
    for method in [Method::Brdf, Method::Ltc, Method::LtcFast] {
        for sphere in SphereMethod::ALL {
            let s = RenderSettings {
                a: ltc_lab::render::ShapeMethods::approximations()
                    .with(method)
                    .with(sphere),
                ..RenderSettings::single(w, h, method)
            };
            let cpu = ltc_lab::cpu::render(&scene, Lut::embedded(), &s);
            let gpu = gpu_frame(&scene, &s);
            crate::gpu_common::assert_close(
                &format!("{} {}", method.name(), sphere.name()),
                &gpu,
                &cpu,
            );
        }
    }
    // The split the lab opens with: LTC disks against the exact integral.
    let s = RenderSettings::compare(w, h, View::Split);
    let cpu = ltc_lab::cpu::render(&scene, Lut::embedded(), &s);
    let gpu = gpu_frame(&scene, &s);
    crate::gpu_common::assert_close("split", &gpu, &cpu);
}

/// The failure presets (a sphere cut by the horizon, one touching the plane, discs seen
/// edge-on, ltc_code's black spots) on the GPU: every sphere method gives a finite,
/// non-negative image that agrees with the CPU's within the tolerance of the test above.
#[test]
fn gpu_failure_presets_are_finite_and_match_the_cpu() {
    use ltc_lab::light::sphere::SphereMethod;
    use ltc_lab::render::{Method, RenderSettings};
    use ltc_lab::scene::{SPHERE_PRESETS, preset};
    if gpu().is_none() {
        return;
    }
    for (name, _) in SPHERE_PRESETS {
        let scene = preset(name);
        for sphere in SphereMethod::ALL {
            let s = RenderSettings {
                a: ltc_lab::render::ShapeMethods::approximations()
                    .with(Method::LtcFast)
                    .with(sphere),
                ..RenderSettings::single(48, 40, Method::LtcFast)
            };
            let gpu = gpu_frame(&scene, &s);
            let what = format!("{name} {}", sphere.name());
            assert_eq!(gpu.first_invalid(s.rules.clipping), None, "{what}");
            let cpu = ltc_lab::cpu::render(&scene, Lut::embedded(), &s);
            crate::gpu_common::assert_close(&what, &gpu, &cpu);
        }
    }
}

/// A far, tiny sphere — radius 1e-4 at 1e4 above the plane, both inside their documented
/// ranges, sin σ = 1e-8 — is its point light by every sphere method, on the CPU and the GPU:
/// the exact integral rendered it black (its cap's 1 − cos σ lost to rounding). The CPU's
/// sized render is the point light's to 1e-9 (below `POINT_LIMIT_SIN_SIGMA` both are the same
/// formula); the GPU's is within the parity tolerance of the CPU's point render, and lit.
#[test]
fn a_far_tiny_sphere_renders_as_its_point_light() {
    use ltc_lab::light::sphere::SphereMethod;
    use ltc_lab::render::{Method, RenderSettings};
    use ltc_lab::scene::{Light, preset};
    let with_radius = |radius: f64| {
        let mut scene = preset("paper-100");
        scene.lights = vec![Light {
            position: [0.0, 0.0, 1e4],
            color: [1.0, 1.0, 1.0],
            intensity: 1e6,
            range: None,
            shape: ltc_lab::light::Shape::of_radius(radius),
        }];
        scene
    };
    let (tiny, point) = (with_radius(1e-4), with_radius(0.0));
    for method in [Method::Brdf, Method::LtcFast] {
        for sphere in SphereMethod::ALL {
            let s = RenderSettings {
                a: ltc_lab::render::ShapeMethods::approximations()
                    .with(method)
                    .with(sphere),
                ..RenderSettings::single(32, 24, method)
            };
            let what = format!("{} {}", method.name(), sphere.name());
            // A sized light's point limit is its sphere method's: the exact point light for
            // the exact integral and the representative point, the paper's formula for the
            // LTC ones, whatever the side's point method.
            let limit = match sphere {
                SphereMethod::Exact | SphereMethod::RepresentativePoint => Method::Brdf,
                SphereMethod::LtcPoint | SphereMethod::LtcDisk => Method::Ltc,
            };
            let cpu_point = ltc_lab::cpu::render(&point, Lut::embedded(), &s.alone(limit));
            let cpu_tiny = ltc_lab::cpu::render(&tiny, Lut::embedded(), &s);
            let peak = cpu_point
                .pixels
                .iter()
                .map(|p| p.max_element())
                .fold(0.0, f64::max);
            assert!(peak > 0.0, "{what}: the point light lights nothing");
            for (a, b) in cpu_tiny.pixels.iter().zip(&cpu_point.pixels) {
                assert!(
                    (*a - *b).abs().max_element() <= 1e-9 * peak,
                    "{what}: {a} vs {b}"
                );
            }
            if gpu().is_some() {
                crate::gpu_common::assert_close(&what, &gpu_frame(&tiny, &s), &cpu_point);
            }
        }
    }
}
