//! The LUT filtered on the GPU (ltc.wgsl `lut_sample_uv`, in-shader bilinear) against the CPU
//! sampler, measured directly at uv points over and beyond the table.

use crate::gpu_common::{gpu, run_probe};
use ltc_lab::gpu::{brdf, ltc};
use ltc_lab::ltc::lut::{Channel, Lut};
use ltc_lab::scene::SplitMix64;

const PROBE: &str = "
@group(0) @binding(0) var<storage, read> probe_uv: array<vec2<f32>>;
@group(0) @binding(1) var<storage, read_write> probe_out: array<vec4<f32>>;
override LUT_SIZE: u32 = 64u;
@compute @workgroup_size(64)
fn probe(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if i >= arrayLength(&probe_uv) {
        return;
    }
    let t = lut_sample_uv(probe_uv[i], LUT_SIZE, 0u);
    probe_out[3u * i] = t.spec_m;
    probe_out[3u * i + 1u] = t.diff_m;
    probe_out[3u * i + 2u] = t.norms;
}
";

#[test]
fn gpu_lut_filtering_matches_the_cpu_sampler() {
    if gpu().is_none() {
        return;
    }
    // The point table: every channel varies there, the fitted spec.scale included.
    let lut = Lut::embedded_point();
    // Random points over the table and 10% beyond each edge (clamp-to-edge), plus centres.
    let mut rng = SplitMix64(11);
    let mut uv: Vec<[f32; 2]> = (0..4096)
        .map(|_| {
            [
                rng.uniform([-0.1, 1.1]) as f32,
                rng.uniform([-0.1, 1.1]) as f32,
            ]
        })
        .collect();
    uv.extend((0..64).map(|k| [(k as f32 + 0.5) / 64.0, (k as f32 + 0.5) / 64.0]));
    let source = [
        brdf::SOURCE,
        ltc_lab::gpu::brdf_aniso::SOURCE,
        ltc::SOURCE,
        PROBE,
    ]
    .join("\n");
    let packed = ltc::pack_lut(lut, false);
    let got = run_probe(
        &source,
        &[("LUT_SIZE", lut.size as f64)],
        bytemuck::cast_slice(&uv),
        &[bytemuck::cast_slice(&packed)],
        uv.len() * 3,
    );
    use Channel::*;
    let channels = [
        [SpecM00, SpecM02, SpecM20, SpecM22],
        [DiffM00, DiffM02, DiffM20, DiffM22],
    ];
    let mut worst: f64 = 0.0;
    for (k, p) in uv.iter().enumerate() {
        let cpu = lut.sample_uv(f64::from(p[0]), f64::from(p[1]));
        let mut check = |gpu: f32, c: Channel| {
            let want = cpu.get(c);
            worst = worst.max((f64::from(gpu) - want).abs() / want.abs().max(1.0));
        };
        for (v, cs) in channels.iter().enumerate() {
            for (e, &c) in cs.iter().enumerate() {
                check(got[3 * k + v][e], c);
            }
        }
        check(got[3 * k + 2][0], SpecNorm);
        check(got[3 * k + 2][1], SpecFresnel);
        check(got[3 * k + 2][2], DiffNorm);
        check(got[3 * k + 2][3], SpecScale);
    }
    eprintln!(
        "GPU LUT filtering: worst difference from the CPU sampler {worst:.2e} (relative, or absolute below 1)"
    );
    // The same arithmetic in f32 instead of f64: uv rounded to f32 (6e-8) times N = 64 moves
    // the blend weight by ~4e-6, times neighbouring-cell differences (≤ 1 in the steepest
    // entries at small α): ~4e-6; the blend itself adds a few ulps. 1.7e-7 measured on lavapipe; 1e-5 bounds it on GPUs that
    // contract or order the blend differently.
    assert!(
        worst < 1e-5,
        "GPU LUT filtering differs from the CPU sampler by {worst:e}"
    );
}
