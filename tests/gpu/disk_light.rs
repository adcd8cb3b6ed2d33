//! Disk lights on the GPU (shaders/disk_light.wgsl) against the f64 CPU methods
//! (src/light/disk/mod.rs) — the exact rule with the GPU's nodes, the LTC disk, the oriented
//! point — measured directly on random disks: across the horizon, below it, facing away,
//! edge-on, from 0.1° to some 90° across; then renders of the failure preset by every
//! method, GPU against CPU.

use crate::gpu_common::{
    PROBE_LTC, condition, direction, gpu, lights_probe_source, pack_pair, run_probe,
};
use glam::DVec3;
use ltc_lab::brdf::view_from_theta;
use ltc_lab::light::ExactRule;
use ltc_lab::light::disk::{Disk, DiskMethod, DiskShading, disk_light_with};
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::{Clipping, LtcPair, Normalization};
use ltc_lab::measure::parity::RADIANCE_TOLERANCE;
use ltc_lab::scene::SplitMix64;

const PROBE: &str = "
@group(0) @binding(0) var<storage, read> probe_in: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> probe_out: array<vec4<f32>>;
const PER_CASE: u32 = 11u;
const DISK_EXACT: u32 = 0u;
const DISK_LTC_DISK: u32 = 1u;
const DISK_LTC_POINT: u32 = 2u;
const RECT_EXACT: u32 = 0u;
const RECT_LTC_POLYGON: u32 = 1u;
const RECT_LTC_PROXY: u32 = 2u;
const RECT_LTC_PROXY_FAST: u32 = 3u;
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
    let disk = Disk(b.xyz, c.xyz, c.w);
    let pair = LtcPair(probe_ltc(k + 3u), probe_ltc(k + 7u));
    let s = DiskShading(a.xyz, disk, vec2<f32>(a.w), b.w, CLIP_HORIZON | CLIP_TRANSFORMED,
        NORMALIZATION_CORRECTED);
    let exact = disk_light(DISK_EXACT, s, pair);
    let ltc = disk_light(DISK_LTC_DISK, s, pair);
    let point = disk_light(DISK_LTC_POINT, s, pair);
    probe_out[2u * i] = vec4<f32>(exact, ltc);
    probe_out[2u * i + 1u] = vec4<f32>(point, 0.0, 0.0);
}
";

/// One case: the view, the disk, α, F0 and the LTCs at (θo, α).
struct Case {
    v: DVec3,
    disk: Disk,
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
    // Its normal from facing the origin to edge-on (one case in ten facing away), its radius
    // from 0.1% to 100% of the distance, log-uniform.
    let tilt = direction(
        rng.uniform([0.0, std::f64::consts::FRAC_PI_2]),
        rng.uniform([0.0, std::f64::consts::TAU]),
    );
    let w = -centre.normalize();
    let (t1, t2) = w.any_orthonormal_pair();
    let mut normal = (t1 * tilt.x + t2 * tilt.y + w * tilt.z).normalize();
    if rng.uniform([0.0, 1.0]) < 0.1 {
        normal = -normal;
    }
    Case {
        v,
        disk: Disk {
            centre,
            normal,
            radius: d * 10f64.powf(rng.uniform([-3.0, 0.0])),
        },
        alpha,
        f0: rng.uniform([0.0, 1.0]),
        pair: lut.ltc_pair(alpha, v),
    }
}

/// The case as the probe reads it: 11 vec4s.
fn pack(c: &Case) -> Vec<[f32; 4]> {
    let f = |x: f64| x as f32;
    let v4 = |v: DVec3, w: f64| [f(v.x), f(v.y), f(v.z), f(w)];
    let mut out = vec![
        v4(c.v, c.alpha),
        v4(c.disk.centre, c.f0),
        v4(c.disk.normal, c.disk.radius),
    ];
    out.extend(pack_pair(&c.pair));
    out
}

#[test]
fn gpu_disk_lights_match_the_cpu_methods() {
    if gpu().is_none() {
        return;
    }
    let lut = Lut::embedded();
    let mut rng = SplitMix64(43);
    let cases: Vec<Case> = (0..4096).map(|_| draw(&mut rng, lut)).collect();
    let input: Vec<[f32; 4]> = cases.iter().flat_map(pack).collect();
    let source = lights_probe_source(&[PROBE, PROBE_LTC].concat());
    let got = run_probe(
        &source,
        &[],
        bytemuck::cast_slice(&input),
        &[],
        2 * cases.len(),
    );
    let want: Vec<[f64; 6]> = cases
        .iter()
        .map(|c| {
            let s = DiskShading {
                v: c.v,
                disk: c.disk,
                alpha: ltc_lab::brdf::Alpha::isotropic(c.alpha),
                f0: c.f0,
                ltc: &c.pair,
                clip: Clipping::BOTH,
                normalization: Normalization::Corrected,
            };
            let mut out = [0.0; 6];
            for m in DiskMethod::ALL {
                let lobes = disk_light_with(m, &s, ExactRule::Render);
                out[2 * m.index()] = lobes.specular;
                out[2 * m.index() + 1] = lobes.diffuse;
            }
            out
        })
        .collect();
    for m in DiskMethod::ALL {
        for (lobe_at, lobe_name) in ["specular", "diffuse"].iter().enumerate() {
            let k = 2 * m.index() + lobe_at;
            let name = format!("{} {lobe_name}", m.name());
            // §4.2's floor: 1% of the column's mean, so that a near-black case is judged on
            // the scale of the light it is part of.
            let floor = 0.01 * want.iter().map(|w| w[k].abs()).sum::<f64>() / want.len() as f64;
            let mut worst = (0.0f64, 0usize);
            for (i, w) in want.iter().enumerate() {
                let g = f64::from(got[2 * i + k / 4][k % 4]);
                assert!(g.is_finite() && g >= 0.0, "{name} case {i}: {g}");
                let err = (g - w[k]).abs() / w[k].abs().max(floor);
                let c = &cases[i];
                let lobe = if lobe_at == 0 {
                    &c.pair.spec
                } else {
                    &c.pair.diff
                };
                // The render's parity tolerance, plus what f32 rounding is amplified by: the
                // exact rule samples the lobe at directions good to a few ε, which moves a GGX
                // peak by ε/α²; the cone's algebra carries the LTC's condition number κ (as
                // the sphere's LTC disk does, tests/gpu/sphere_light.rs) and, for a small or
                // edge-on disk, the ratio of its thickness seen from the point to its distance
                // (the ellipse's short axis `r |cos θe| / d`, how near B is to singular). Each
                // chain has some sixteen roundings; 64 is four times that.
                let cos_e = c.disk.normal.dot(c.disk.centre.normalize()).abs();
                let thin = (c.disk.angular_size() * cos_e).clamp(1e-6, 1.0);
                let amplification = match m {
                    DiskMethod::Exact => 1.0 / (c.alpha * c.alpha),
                    DiskMethod::LtcPoint => condition(lobe),
                    DiskMethod::LtcDisk => condition(lobe) * (1.0 / thin + 1.0),
                };
                let bound = RADIANCE_TOLERANCE + 64.0 * f64::from(f32::EPSILON) * amplification;
                assert!(
                    err <= bound,
                    "{name} case {i} (α {}, r/d {:.1e}, cos θe {cos_e:.2}): gpu {g} cpu {} ({err:.2e} > {bound:.2e})",
                    c.alpha,
                    c.disk.angular_size(),
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

/// The disk failure preset (across the horizon, behind the surface, edge-on, filling the sky,
/// tiny) rendered by every disk method beside each point form, GPU against the CPU: finite,
/// never negative, and within the renders' parity tolerance.
#[test]
fn gpu_renders_of_disk_lights_match_the_cpu() {
    if gpu().is_none() {
        return;
    }
    crate::gpu_common::assert_shape_presets_match(ltc_lab::light::ShapeKind::Disk);
}
