//! Rect lights on the GPU (shaders/rect_light.wgsl) against the f64 CPU methods
//! (src/light/rect/mod.rs) — the exact rule with the GPU's nodes, the LTC over the polygon,
//! the proxy and three.js's form of it, the oriented point — measured directly on random
//! rects: across the horizon, below it, facing away, from 0.1° to some 90° across; then
//! renders of the failure preset by every method, GPU against CPU.

use crate::gpu_common::{
    METHOD_CODES, PROBE_LTC, condition, direction, gpu, lights_probe_source, pack_pair, run_probe,
};
use glam::DVec3;
use ltc_lab::brdf::view_from_theta;
use ltc_lab::light::ExactRule;
use ltc_lab::light::rect::{Rect, RectMethod, RectShading, rect_light_with};
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::{Clipping, LtcPair, Normalization};
use ltc_lab::measure::parity::RADIANCE_TOLERANCE;
use ltc_lab::scene::SplitMix64;

const PROBE: &str = "
@group(0) @binding(0) var<storage, read> probe_in: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> probe_out: array<vec4<f32>>;
const PER_CASE: u32 = 12u;
@compute @workgroup_size(64)
fn probe(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if i >= arrayLength(&probe_in) / PER_CASE {
        return;
    }
    let k = PER_CASE * i;
    let a = probe_in[k];
    let b = probe_in[k + 1u];
    let rect = Rect(b.xyz, probe_in[k + 2u].xyz, probe_in[k + 3u].xyz);
    let pair = LtcPair(probe_ltc(k + 4u), probe_ltc(k + 8u));
    let s = RectShading(a.xyz, rect, vec2<f32>(a.w), b.w, CLIP_HORIZON | CLIP_TRANSFORMED,
        NORMALIZATION_CORRECTED);
    var out: array<f32, 12>;
    for (var m = 0u; m < 5u; m++) {
        let lobes = rect_light(m, s, pair);
        out[2u * m] = lobes.x;
        out[2u * m + 1u] = lobes.y;
    }
    for (var j = 0u; j < 3u; j++) {
        probe_out[3u * i + j] = vec4<f32>(out[4u * j], out[4u * j + 1u], out[4u * j + 2u], out[4u * j + 3u]);
    }
}
";

/// One case: the view, the rect, α, F0 and the LTCs at (θo, α).
struct Case {
    v: DVec3,
    rect: Rect,
    alpha: f64,
    f0: f64,
    pair: LtcPair,
}

fn draw(rng: &mut SplitMix64, lut: &Lut) -> Case {
    let theta_o = rng.uniform([0.0, 85.0_f64.to_radians()]);
    let alpha = rng.uniform([0.05, 1.0]);
    let v = DVec3::from(view_from_theta(theta_o));
    let elevation = rng.uniform([-30.0_f64.to_radians(), std::f64::consts::FRAC_PI_2]);
    let azimuth = rng.uniform([0.0, std::f64::consts::TAU]);
    let d = rng.uniform([0.3, 3.0]);
    let centre = direction(elevation, azimuth) * d;
    // Its normal within 70° of the direction to the origin (one case in ten facing away),
    // its half-edges from 0.1% to 100% of the distance, log-uniform, of aspect up to 4.
    let tilt = direction(
        rng.uniform([20.0_f64.to_radians(), std::f64::consts::FRAC_PI_2]),
        rng.uniform([0.0, std::f64::consts::TAU]),
    );
    let w = -centre.normalize();
    let (t1, t2) = w.any_orthonormal_pair();
    let mut normal = (t1 * tilt.x + t2 * tilt.y + w * tilt.z).normalize();
    if rng.uniform([0.0, 1.0]) < 0.1 {
        normal = -normal;
    }
    let (e1, e2) = normal.any_orthonormal_pair();
    let size = d * 10f64.powf(rng.uniform([-3.0, 0.0]));
    let aspect = rng.uniform([0.25, 1.0]);
    Case {
        v,
        rect: Rect {
            centre,
            u: e1 * size,
            v: e2 * size * aspect,
        },
        alpha,
        f0: rng.uniform([0.0, 1.0]),
        pair: lut.ltc_pair(alpha, v),
    }
}

/// The case as the probe reads it: 12 vec4s.
fn pack(c: &Case) -> Vec<[f32; 4]> {
    let f = |x: f64| x as f32;
    let v4 = |v: DVec3, w: f64| [f(v.x), f(v.y), f(v.z), f(w)];
    let mut out = vec![
        v4(c.v, c.alpha),
        v4(c.rect.centre, c.f0),
        v4(c.rect.u, 0.0),
        v4(c.rect.v, 0.0),
    ];
    out.extend(pack_pair(&c.pair));
    out
}

#[test]
fn gpu_rect_lights_match_the_cpu_methods() {
    if gpu().is_none() {
        return;
    }
    let lut = Lut::embedded();
    let mut rng = SplitMix64(41);
    let cases: Vec<Case> = (0..4096).map(|_| draw(&mut rng, lut)).collect();
    let input: Vec<[f32; 4]> = cases.iter().flat_map(pack).collect();
    let source = lights_probe_source(&[METHOD_CODES, PROBE, PROBE_LTC].concat());
    let got = run_probe(
        &source,
        &[],
        bytemuck::cast_slice(&input),
        &[],
        3 * cases.len(),
    );
    let want: Vec<[f64; 10]> = cases
        .iter()
        .map(|c| {
            let s = RectShading {
                v: c.v,
                rect: c.rect,
                alpha: ltc_lab::brdf::Alpha::isotropic(c.alpha),
                f0: c.f0,
                ltc: &c.pair,
                clip: Clipping::BOTH,
                normalization: Normalization::Corrected,
            };
            let mut out = [0.0; 10];
            for m in RectMethod::ALL {
                let lobes = rect_light_with(m, &s, ExactRule::Render);
                out[2 * m.index()] = lobes.specular;
                out[2 * m.index() + 1] = lobes.diffuse;
            }
            out
        })
        .collect();
    let got: Vec<[f32; 12]> = got
        .chunks(3)
        .map(|p| {
            let mut out = [0.0; 12];
            for (j, v) in p.iter().enumerate() {
                out[4 * j..4 * j + 4].copy_from_slice(v);
            }
            out
        })
        .collect();
    for m in RectMethod::ALL {
        for (lobe_at, lobe_name) in ["specular", "diffuse"].iter().enumerate() {
            let k = 2 * m.index() + lobe_at;
            let name = format!("{} {lobe_name}", m.name());
            // §4.2's floor: 1% of the column's mean, so that a near-black case is judged on
            // the scale of the light it is part of.
            let floor = 0.01 * want.iter().map(|w| w[k].abs()).sum::<f64>() / want.len() as f64;
            let mut worst = (0.0f64, 0usize);
            for (i, (w, g)) in want.iter().zip(&got).enumerate() {
                let g = f64::from(g[k]);
                assert!(g.is_finite() && g >= 0.0, "{name} case {i}: {g}");
                let err = (g - w[k]).abs() / w[k].abs().max(floor);
                let c = &cases[i];
                let lobe = if lobe_at == 0 {
                    &c.pair.spec
                } else {
                    &c.pair.diff
                };
                // The render's parity tolerance, plus what f32 rounding is amplified by. The
                // edge formula sums terms of size s/d to a value of size (s/d)², each term
                // good to a few ε of itself: ε·d/s of the value, after M⁻¹ stretched the
                // polygon by up to its condition number κ. The exact rule samples the lobe at
                // directions good to a few ε, which moves a GGX peak by ε/α². Clipped, a cut
                // point carries the rounding of the edge it cuts, of order one beside the
                // sliver it leaves: one κ more. Each chain has some sixteen roundings; 64 is
                // four times that.
                let s_over_d = c.rect.angular_size().min(1.0);
                let amplification = match m {
                    RectMethod::Exact => 1.0 / (c.alpha * c.alpha),
                    RectMethod::LtcPoint => condition(lobe),
                    _ => condition(lobe) * (1.0 / s_over_d + 1.0),
                };
                let bound = RADIANCE_TOLERANCE + 64.0 * f64::from(f32::EPSILON) * amplification;
                assert!(
                    err <= bound,
                    "{name} case {i} (α {}, s/d {s_over_d:.1e}): gpu {g} cpu {} ({err:.2e} > {bound:.2e})",
                    c.alpha,
                    w[k]
                );
                if err > worst.0 {
                    worst = (err, i);
                }
            }
            eprintln!("{name}: worst {:.2e} (case {})", worst.0, worst.1);
        }
    }
}

/// The rect failure presets (leaning over the horizon, crossing the plane, edge-on, facing
/// away, touching the surface, behind it, tiny, filling the sky) rendered by every rect method beside each point form, GPU
/// against the CPU: finite, never negative, and within the renders' parity tolerance (the
/// probe above bounds each method's f32 error per light well inside it for rects of these
/// sizes, s/d above 0.1).
#[test]
fn gpu_renders_of_rect_lights_match_the_cpu() {
    if gpu().is_none() {
        return;
    }
    crate::gpu_common::assert_shape_presets_match(ltc_lab::light::ShapeKind::Rect);
}
