//! Anisotropic materials on the GPU against the CPU reference: the 4D table's lookup
//! (ltc_aniso.wgsl `aniso_ltc`) against `AnisoLut::ltc` on random materials and views, for
//! the lab's table and I3D 2022's; and renders of every light shape by every method on
//! brushed metal, at the renders' parity tolerance.

use crate::gpu_common::{assert_close, gpu, run_probe};
use glam::DVec3;
use ltc_lab::brdf::Alpha;
use ltc_lab::cpu::render;
use ltc_lab::gpu::{brdf, brdf_aniso, ltc, ltc_aniso};
use ltc_lab::light::ShapeKind;
use ltc_lab::ltc::aniso::anchor::shipped;
use ltc_lab::ltc::aniso::{AnisoAxes, AnisoLut};
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::{Clipping, Normalization};
use ltc_lab::render::{Method, RenderSettings, ShapeMethod};
use ltc_lab::scene::{Scene, SplitMix64, preset};

const PROBE: &str = "
struct ProbeIn {
    alpha: vec2<f32>,
    pad: vec2<f32>,
    v: vec4<f32>,
}
@group(0) @binding(0) var<storage, read> probe_in: array<ProbeIn>;
@group(0) @binding(1) var<storage, read_write> probe_out: array<vec4<f32>>;
override BASE: u32 = 0u;
override AXES: u32 = 0u;
override STORED: u32 = 0u;
override N: u32 = 8u;
@compute @workgroup_size(64)
fn probe(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    if i >= arrayLength(&probe_in) {
        return;
    }
    let table = AnisoTable(BASE, vec4<u32>(N), AXES, STORED);
    let l = aniso_ltc(table, probe_in[i].alpha, probe_in[i].v.xyz);
    probe_out[4u * i] = vec4<f32>(l.cos_from_brdf[0], l.norm);
    probe_out[4u * i + 1u] = vec4<f32>(l.cos_from_brdf[1], l.fresnel);
    probe_out[4u * i + 2u] = vec4<f32>(l.cos_from_brdf[2], l.det_cos_from_brdf);
    probe_out[4u * i + 3u] = vec4<f32>(0.0);
}
";

/// D of an M⁻¹ at l, up to its scale (compared after dividing by the peak).
fn d(m: glam::DMat3, l: DVec3) -> f64 {
    let w = m * l;
    (w.z.max(0.0) * m.determinant().abs()) / w.length_squared().powi(2)
}

#[test]
fn the_gpu_lookup_is_the_cpu_lookup() {
    if gpu().is_none() {
        return;
    }
    let ours = AnisoLut::shipped();
    let xy = shipped(AnisoAxes::I3dAlphaXY, ours);
    let lambda = shipped(AnisoAxes::I3dAlphaLambda, ours);
    let mut rng = SplitMix64(5);
    let cases: Vec<(Alpha<f64>, DVec3)> = (0..2048)
        .map(|_| {
            let a = Alpha {
                x: rng.uniform([0.02, 1.0]),
                y: rng.uniform([0.02, 1.0]),
            };
            let (t, p) = (
                rng.uniform([0.0, 1.5]),
                rng.uniform([0.0, std::f64::consts::TAU]),
            );
            (a, DVec3::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos()))
        })
        .collect();
    let input: Vec<[f32; 8]> = cases
        .iter()
        .map(|(a, v)| {
            [
                a.x as f32, a.y as f32, 0.0, 0.0, v.x as f32, v.y as f32, v.z as f32, 0.0,
            ]
        })
        .collect();
    let source = [
        brdf::SOURCE,
        brdf_aniso::SOURCE,
        ltc::SOURCE,
        ltc_aniso::SOURCE,
        &ltc_lab::gpu::light::sources(),
        PROBE,
    ]
    .join("\n");
    let probes: Vec<DVec3> = (0..32)
        .map(|k| {
            let (t, p) = (
                1.5 * ((k % 4) as f64 + 0.5) / 4.0,
                std::f64::consts::TAU * (k / 4) as f64 / 8.0,
            );
            DVec3::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos())
        })
        .collect();
    for table in [ours, &xy, &lambda] {
        let packed = ltc_aniso::pack_aniso(table);
        let constants = [
            ("BASE", 0.0),
            ("AXES", f64::from(ltc_aniso::axes_constant(table.axes).0)),
            (
                "STORED",
                f64::from(ltc_aniso::stored_constant(table.stored).0),
            ),
            ("N", 8.0),
        ];
        let got = run_probe(
            &source,
            &constants,
            bytemuck::cast_slice(&input),
            &[bytemuck::cast_slice(&packed)],
            4 * cases.len(),
        );
        let mut worst: f64 = 0.0;
        for (k, (alpha, v)) in cases.iter().enumerate() {
            let cpu = table.ltc(*alpha, *v);
            let col = |c: usize| {
                DVec3::new(
                    f64::from(got[4 * k + c][0]),
                    f64::from(got[4 * k + c][1]),
                    f64::from(got[4 * k + c][2]),
                )
            };
            let m = glam::DMat3::from_cols(col(0), col(1), col(2));
            let peak = probes
                .iter()
                .map(|&l| d(cpu.cos_from_brdf, l))
                .fold(1e-300, f64::max);
            for &l in &probes {
                worst = worst.max((d(m, l) - d(cpu.cos_from_brdf, l)).abs() / peak);
            }
            let norm = f64::from(got[4 * k][3]);
            assert!(
                (norm - cpu.norm).abs() < 1e-5,
                "norm {norm} vs {}",
                cpu.norm
            );
        }
        eprintln!(
            "GPU 4D lookup of {:?}: worst D difference {worst:.2e} of the peak",
            table.axes
        );
        // f32 interpolation of entries of size ≤ 1e2 (a 1:50 lobe's), an f32 inverse whose
        // rounding the matrix's condition (≤ 1e3 at α ≥ 0.02) amplifies, and D's fourth
        // power of |M⁻¹l|: 6e-8 · 1e3 · 4 ≈ 2.4e-4 of the peak; 1e-3 bounds it.
        assert!(worst < 1e-3, "{:?}: worst {worst:e}", table.axes);
    }
}

/// A brushed plane with a light of every shape, near and far, one across the horizon.
fn every_shape() -> Scene {
    let mut scene = preset("brushed-rect");
    let rect = scene.lights[0];
    let mut lights = vec![rect];
    for (k, spheres) in preset("brushed-spheres").lights.into_iter().enumerate() {
        let mut l = spheres;
        l.position[0] += 0.3 * k as f64;
        lights.push(l);
    }
    // The first two lights of each other emitter's first failure preset.
    for kind in [ShapeKind::Disk, ShapeKind::Tube] {
        let (first, _) = ltc_lab::scene::shape_presets(kind)[0];
        lights.extend(preset(first).lights.into_iter().take(2));
    }
    let mut point = lights[1];
    point.shape = ltc_lab::light::Shape::Point;
    point.position = [0.3, 0.4, 0.5];
    lights.push(point);
    scene.lights = lights;
    scene.material.tangent_degrees = 20.0;
    scene
}

#[test]
fn anisotropic_renders_match_the_cpu_by_every_method() {
    if gpu().is_none() {
        return;
    }
    let g = gpu().unwrap();
    let (w, h) = (40, 32);
    let scenes = [
        ("brushed-rect", preset("brushed-rect")),
        ("brushed-spheres", preset("brushed-spheres")),
        ("every shape", every_shape()),
    ];
    for (name, scene) in &scenes {
        assert!(scene.material.is_anisotropic());
        for method in Method::F32 {
            // The sized lights' methods are a side's whatever its point method: every
            // variant once, under ltc-fast, on the scene of every shape (which holds the
            // brushed presets' rect and spheres: each variant a pipeline of every shape's
            // method, minutes of compiling on llvmpipe); the other point methods, and the
            // presets, with the defaults.
            let variants = if method == Method::LtcFast && *name == "every shape" {
                0..5
            } else {
                0..1
            };
            for k in variants {
                let mut s = RenderSettings::single(w, h, method);
                for kind in ShapeKind::ALL
                    .into_iter()
                    .filter(|&k| k != ShapeKind::Point)
                {
                    let all = ShapeMethod::all(kind);
                    s.a = s.a.with(all[k % all.len()]);
                }
                if k == 4 {
                    s.rules.clipping = Clipping::NONE;
                    s.rules.normalization = Normalization::PaperLiteral;
                }
                let cpu = render(scene, Lut::embedded(), &s);
                let gpu = g
                    .renderer
                    .lock()
                    .unwrap()
                    .render(&g.ctx, scene, &s)
                    .unwrap()
                    .0;
                assert_close(&format!("{name} {} variant {k}", method.name()), &gpu, &cpu);
            }
        }
    }
}
