//! Tube lights on the GPU (shaders/tube_light.wgsl, tube_band.wgsl) against the f64 CPU methods
//! (src/light/tube/) — the band's exact rule at the renders' nodes, the LTC line, HDRP's
//! tube, the representative point and the point — measured directly on random capsules:
//! across the horizon, below it, end-on, long and thin, the point inside; then renders of the
//! failure preset by every method, GPU against CPU.

use crate::gpu_common::{
    METHOD_CODES, PROBE_LTC, condition, direction, gpu, lights_probe_source, pack_pair, run_probe,
};
use glam::DVec3;
use ltc_lab::brdf::view_from_theta;
use ltc_lab::light::ExactRule;
use ltc_lab::light::tube::{Tube, TubeMethod, TubeShading, tube_light_with};
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
    let tube = Tube(b.xyz, c.xyz, c.w);
    let pair = LtcPair(probe_ltc(k + 3u), probe_ltc(k + 7u));
    let s = TubeShading(a.xyz, tube, vec2<f32>(a.w), b.w, CLIP_HORIZON | CLIP_TRANSFORMED,
        NORMALIZATION_CORRECTED);
    for (var m = 0u; m < 5u; m++) {
        let lobes = tube_light(m, s, pair);
        probe_out[5u * i + m] = vec4<f32>(lobes, 0.0, 0.0);
    }
}
";

/// One case: the view, the capsule, α, F0 and the LTCs at (θo, α).
struct Case {
    v: DVec3,
    tube: Tube,
    alpha: f64,
    f0: f64,
    pair: LtcPair,
}

fn draw(rng: &mut SplitMix64, lut: &Lut) -> Case {
    let theta_o = rng.uniform([0.0, 85.0_f64.to_radians()]);
    let alpha = rng.uniform([0.05, 1.0]);
    let v = DVec3::from(view_from_theta(theta_o));
    let elevation = rng.uniform([-20.0_f64.to_radians(), std::f64::consts::FRAC_PI_2]);
    let d = rng.uniform([0.3, 3.0]);
    let centre = direction(elevation, rng.uniform([0.0, std::f64::consts::TAU])) * d;
    // Its axis any way (so some end-on, some across the horizon), its length from none to
    // four times its distance, its radius from 0.1% to 30% of the distance, log-uniform: some
    // slivers, some holding the point.
    let axis = direction(
        rng.uniform([-1.0, 1.0f64]).asin(),
        rng.uniform([0.0, std::f64::consts::TAU]),
    );
    let half = axis * (d * rng.uniform([0.0, 2.0]));
    let mut tube = Tube {
        a: centre - half,
        b: centre + half,
        radius: 0.3 * d * 10f64.powf(rng.uniform([-3.0, 0.0])),
    };
    // One case in twenty holds the point (a capsule lying on the surface, seen from within).
    if rng.uniform([0.0, 1.0]) < 0.05 {
        tube.radius = 1.2 * tube.distance_to_segment();
    }
    Case {
        v,
        tube,
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
        v4(c.tube.a, c.f0),
        v4(c.tube.b, c.tube.radius),
    ];
    out.extend(pack_pair(&c.pair));
    out
}

/// The CPU's lobes of every method, `[specular, diffuse]` in `TubeMethod::ALL`'s order.
fn cpu_lobes(c: &Case) -> Vec<[f64; 2]> {
    let s = TubeShading {
        v: c.v,
        tube: c.tube,
        alpha: ltc_lab::brdf::Alpha::isotropic(c.alpha),
        f0: c.f0,
        ltc: &c.pair,
        clip: Clipping::BOTH,
        normalization: Normalization::Corrected,
    };
    TubeMethod::ALL
        .map(|m| {
            let lobes = tube_light_with(m, &s, ExactRule::Render);
            [lobes.specular, lobes.diffuse]
        })
        .to_vec()
}

#[test]
fn gpu_tube_lights_match_the_cpu_methods() {
    if gpu().is_none() {
        return;
    }
    let lut = Lut::embedded();
    let mut rng = SplitMix64(53);
    let cases: Vec<Case> = (0..2048).map(|_| draw(&mut rng, lut)).collect();
    let input: Vec<[f32; 4]> = cases.iter().flat_map(pack).collect();
    let source = lights_probe_source(&[PROBE, PROBE_LTC, METHOD_CODES].concat());
    let got = run_probe(
        &source,
        &[],
        bytemuck::cast_slice(&input),
        &[],
        5 * cases.len(),
    );
    let want: Vec<Vec<[f64; 2]>> = cases.iter().map(cpu_lobes).collect();
    let inside = cases.iter().filter(|c| c.tube.encloses_origin()).count();
    let slivers = cases
        .iter()
        .filter(|c| c.tube.radius < 0.01 * c.tube.centre().length())
        .count();
    assert!(
        inside > 10 && slivers > 100,
        "{inside} inside, {slivers} slivers"
    );
    for m in TubeMethod::ALL {
        for (lobe_at, lobe_name) in ["specular", "diffuse"].iter().enumerate() {
            let name = format!("{} {lobe_name}", m.name());
            let column = |w: &Vec<[f64; 2]>| w[m.index()][lobe_at];
            // §4.2's floor: 1% of the column's mean, so that a near-black case is judged on
            // the scale of the light it is part of.
            let floor =
                0.01 * want.iter().map(|w| column(w).abs()).sum::<f64>() / want.len() as f64;
            let mut worst = (0.0f64, 0usize);
            for (i, w) in want.iter().enumerate() {
                let g = f64::from(got[5 * i + m.index()][lobe_at]);
                assert!(g.is_finite() && g >= 0.0, "{name} case {i}: {g}");
                let err = (g - column(w)).abs() / column(w).abs().max(floor);
                let c = &cases[i];
                let lobe = if lobe_at == 0 {
                    &c.pair.spec
                } else {
                    &c.pair.diff
                };
                // The render's parity tolerance, plus what f32 rounding is amplified by: the
                // exact rule and the representative point sample the lobe at directions good
                // to a few ε, which moves a GGX peak by ε/α²; the LTC's methods carry its
                // condition number κ (as the disk's do, tests/gpu/disk_light.rs) and the line's
                // width factor, for a sliver, the ratio of its distance to its radius (how
                // near the mapped cross product is to rounding). Each chain has some sixteen
                // roundings; 64 is four times that.
                let thin = (c.tube.radius / c.tube.centre().length()).clamp(1e-6, 1.0);
                // The representative point's place on the segment, `(c a·w − a·e)/(1 − c²)` with
                // `c = e·w`, rounds as `1/(1 − c²)` where the segment runs nearly along the
                // mirror ray `w`.
                let along = c.tube.axis().dot(ltc_lab::light::polar::mirror(c.v));
                let parallel = 1.0 / (1.0 - along * along).max(1e-6);
                let amplification = match m {
                    TubeMethod::Exact => 1.0 / (c.alpha * c.alpha),
                    TubeMethod::RepresentativePoint => parallel / (c.alpha * c.alpha),
                    TubeMethod::LtcPoint => condition(lobe),
                    TubeMethod::LtcLine | TubeMethod::HdrpTube => {
                        condition(lobe) * (1.0 / thin + 1.0)
                    }
                };
                let bound = RADIANCE_TOLERANCE + 64.0 * f64::from(f32::EPSILON) * amplification;
                assert!(
                    err <= bound,
                    "{name} case {i} (α {}, v {:?}, {:?}): gpu {g} cpu {} ({err:.2e} > {bound:.2e})",
                    c.alpha,
                    c.v,
                    c.tube,
                    column(w)
                );
                if err > worst.0 {
                    worst = (err, i);
                }
            }
            eprintln!("{name}: worst {:.2e} (case {})", worst.0, worst.1);
        }
    }
}

/// The tube failure preset (across the horizon, standing on the plane, long and thin, tiny)
/// rendered by every tube method beside each point form, GPU against the CPU: finite, never
/// negative, and within the renders' parity tolerance.
#[test]
fn gpu_renders_of_tube_lights_match_the_cpu() {
    if gpu().is_none() {
        return;
    }
    crate::gpu_common::assert_shape_presets_match(ltc_lab::light::ShapeKind::Tube);
}
