//! GPU against the CPU reference (lavapipe in CI): the four presets and a random 1000-light
//! scene agree per pixel for every method, clipping rule and normalization; `ltc` and
//! `ltc-fast` agree to f32 rounding; the point table agrees too; no NaN reaches the image in
//! the stability cases.

use crate::gpu_common::{assert_close, diff_tolerance, gpu};
use glam::DVec3;
use ltc_lab::cpu::render;
use ltc_lab::gpu::plane::ShaderChecks;
use ltc_lab::gpu::renderer::PlaneRenderer;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::{Clipping, Normalization};
use ltc_lab::metrics::{luminance, relative_floor};
use ltc_lab::render::{Frame, LutFilter, Method, RenderSettings, View};
use ltc_lab::scene::{Light, RandomLights, Scene, generate_lights};

const W: usize = 48;
const H: usize = 40;

/// A shipped preset (embedded in the library from `assets/scenes/`; loading the files
/// themselves is tests/math/presets.rs's subject).
fn preset(name: &str) -> Scene {
    ltc_lab::scene::preset(name.trim_end_matches(".toml"))
}

fn scenes() -> Vec<(String, Scene)> {
    let mut v: Vec<(String, Scene)> = [
        "paper-100",
        "figure2-normal",
        "figure2-case1",
        "figure2-case2",
    ]
    .iter()
    .map(|n| (n.to_string(), preset(&format!("{n}.toml"))))
    .collect();
    let mut random = preset("paper-100.toml");
    random.lights = generate_lights(
        &RandomLights {
            count: 1000,
            seed: 7,
            height: [0.02, 1.0],
            intensity: [0.001, 0.01],
            range: Some(1.5),
            radius: 0.0,
        },
        random.plane.half_size,
    );
    random.material.alpha = 0.12;
    random.material.f0 = 0.5;
    v.push(("random-1000".into(), random));
    v
}

const CLIPS: [Clipping; 4] = [
    Clipping::BOTH,
    Clipping::CASE1,
    Clipping::CASE2,
    Clipping::NONE,
];
const NORMALIZATIONS: [Normalization; 2] = [Normalization::Corrected, Normalization::PaperLiteral];

fn cpu_frame(scene: &Scene, method: Method, clip: Clipping, normalization: Normalization) -> Frame {
    let mut s = RenderSettings::single(W, H, method);
    s.rules.clipping = clip;
    s.rules.normalization = normalization;
    render(scene, Lut::embedded(), &s)
}

fn gpu_frame(scene: &Scene, s: &RenderSettings) -> Frame {
    let g = gpu().unwrap();
    let mut r = g.renderer.lock().unwrap();
    r.render(&g.ctx, scene, s).unwrap().0
}

#[test]
fn gpu_matches_cpu_for_every_method_clip_and_normalization() {
    if gpu().is_none() {
        return;
    }
    for (name, scene) in scenes() {
        for method in Method::F32 {
            let combos: Vec<(Clipping, Normalization)> = if method.is_ltc() {
                CLIPS
                    .iter()
                    .flat_map(|&c| NORMALIZATIONS.map(|n| (c, n)))
                    .collect()
            } else {
                vec![(Clipping::BOTH, Normalization::Corrected)]
            };
            for (clip, normalization) in combos {
                // The same settings for both: the CPU shades the literal form of each method.
                let mut s = RenderSettings::single(W, H, method);
                s.rules.clipping = clip;
                s.rules.normalization = normalization;
                let cpu = render(&scene, Lut::embedded(), &s);
                let gpu = gpu_frame(&scene, &s);
                assert_close(
                    &format!("{name} {} {clip:?} {normalization:?}", method.name()),
                    &gpu,
                    &cpu,
                );
            }
        }
    }
}

/// ltc-f16 against the f64 LTC: f16 keeps 11 significant bits (relative rounding 4.9e-4 per
/// operation, ~10 operations in M⁻¹l and |w|⁴), so each term is good to ~5e-3; terms of one
/// sign average out in the sum. 1e-2 of the reference luminance (floor: 1% of the mean).
/// Scenes with α ≥ 0.12: at α near α_min, M⁻¹l spans more than f16's range (the study
/// measures that). Not figure2-case2: its light lies 0.01 over the plane, so n·l is ~1e-3
/// at most pixels and f16's absolute rounding of a unit vector's z (2.4e-4) is a 10–20%
/// error of it — outside the per-term bound above by construction.
#[test]
fn gpu_f16_ltc_matches_cpu_to_half_precision() {
    let Some(g) = gpu() else { return };
    if !g.ctx.has_f16() {
        crate::gpu_common::skipped(&format!(
            "{} has no SHADER_F16; ltc-f16 is not offered there",
            g.ctx.info.name
        ));
        return;
    }
    for (name, scene) in scenes().into_iter().filter(|(n, _)| *n != "figure2-case2") {
        let cpu = cpu_frame(
            &scene,
            Method::Ltc,
            Clipping::BOTH,
            Normalization::Corrected,
        );
        let gpu = gpu_frame(&scene, &RenderSettings::single(W, H, Method::LtcF16));
        let floor = relative_floor(&cpu, &cpu);
        let worst = (0..cpu.pixels.len())
            .filter(|&k| gpu.on_plane[k] && cpu.on_plane[k])
            .map(|k| {
                (gpu.pixels[k] - cpu.pixels[k]).abs().max_element()
                    / luminance(cpu.pixels[k].abs()).max(floor)
            })
            .fold(0.0, f64::max);
        assert!(worst <= 1e-2, "{name}: ltc-f16 differs by {worst:.2e}");
        assert!(
            worst > 0.0 || name == "figure2-case1",
            "{name}: f16 identical to f64?"
        );
    }
}

#[test]
fn gpu_nearest_lut_lookup_matches_cpu() {
    if gpu().is_none() {
        return;
    }
    for (name, scene) in scenes() {
        let mut cs = RenderSettings::single(W, H, Method::Ltc);
        cs.rules.filter = LutFilter::Nearest;
        let cpu = render(&scene, Lut::embedded(), &cs);
        for method in [Method::Ltc, Method::LtcFast] {
            let mut s = RenderSettings::single(W, H, method);
            s.rules.filter = LutFilter::Nearest;
            assert_close(
                &format!("{name} {} nearest", method.name()),
                &gpu_frame(&scene, &s),
                &cpu,
            );
        }
        // And the nearest lookup is a different image from the bilinear one.
        let bilinear = cpu_frame(
            &scene,
            Method::Ltc,
            Clipping::BOTH,
            Normalization::Corrected,
        );
        if name == "paper-100" {
            assert_ne!(bilinear.pixels, cpu.pixels);
        }
    }
}

#[test]
fn gpu_split_and_diff_views_match_cpu() {
    if gpu().is_none() {
        return;
    }
    for (name, scene) in scenes() {
        // One settings value for both renderers: LTC | BRDF, then their difference.
        let mut s = RenderSettings::compare(W, H, View::Split);
        s.divider = 0.35;
        let cpu = render(&scene, Lut::embedded(), &s);
        let gpu = gpu_frame(&scene, &s);
        assert_eq!(gpu.divider, cpu.divider);
        assert_close(&format!("{name} split"), &gpu, &cpu);

        s.view = View::Diff;
        let cpu = render(&scene, Lut::embedded(), &s);
        let gpu = gpu_frame(&scene, &s);
        for k in 0..cpu.pixels.len() {
            if gpu.on_plane[k] && cpu.on_plane[k] {
                let (g, c) = (gpu.pixels[k].x, cpu.pixels[k].x);
                let bound = diff_tolerance(c);
                assert!(
                    (g - c).abs() <= bound,
                    "{name} diff pixel {k}: gpu {g} cpu {c} (bound {bound:.2e})"
                );
            }
        }
    }
}

#[test]
fn ltc_and_ltc_fast_agree_to_f32_rounding() {
    if gpu().is_none() {
        return;
    }
    for (name, scene) in scenes() {
        for clip in CLIPS {
            let mut s = RenderSettings::single(W, H, Method::Ltc);
            s.rules.clipping = clip;
            let a = gpu_frame(&scene, &s);
            s.a.set(Method::LtcFast);
            let b = gpu_frame(&scene, &s);
            let floor = relative_floor(&a, &a);
            for k in 0..a.pixels.len() {
                let scale = luminance(a.pixels[k].abs()).max(floor);
                let err = (a.pixels[k] - b.pixels[k]).abs().max_element() / scale;
                // Two f32 orderings of the same sum: each term differs by a few ulps (f32's
                // unit roundoff is 6e-8, ~20 operations per term), 1.9e-6 measured on
                // lavapipe — except where (M⁻¹l).z = m20 lx + m22 lz nearly cancels, which
                // amplifies rounding by |M⁻¹l| / (M⁻¹l).z: the case-1 glow without the horizon
                // rule lives there (5e-5 measured). 1e-4 covers both.
                assert!(
                    err <= 1e-4,
                    "{name} {clip:?} pixel {k}: {:?} vs {:?}",
                    a.pixels[k],
                    b.pixels[k]
                );
            }
        }
    }
}

/// The stability cases (docs/design.md §4), on the GPU: lights on the horizon, below the
/// surface, at a shading point, extremely far and extremely bright, α from α_min to 1, a
/// grazing camera, black base colour and F0 = 0 (zero factors against overflowing sums).
#[test]
fn no_nan_reaches_the_image() {
    let Some(g) = gpu() else { return };
    let light = |p: [f64; 3], intensity: f64, range: Option<f64>| Light {
        position: p,
        color: [1.0, 0.0, 0.5],
        intensity,
        range,
        shape: ltc_lab::light::Shape::of_radius(0.0),
    };
    let lights = vec![
        light([0.5, 0.5, 0.0], 1.0, None),
        light([0.0, 0.0, -0.158731], 1e3, None),
        light([0.0, 0.0, 0.0], 1e30, None),
        light([0.3, -1.0, 1e-7], 1e30, Some(0.5)),
        light([1e4, 1e4, 1e4], 1e30, None),
        light([-1.0, 1.0, 0.2], 1e-30, Some(1e-3)),
    ];
    let mut scene = preset("paper-100.toml");
    scene.lights = lights;
    scene.camera.position = [0.0, -3.0, 0.05];
    scene.camera.target = [0.0, 1.0, 0.0];
    for alpha in [ltc_lab::ltc::lut::ALPHA_MIN, 0.27, 1.0] {
        for (base, f0) in [([0.0; 3], 0.0), ([1.0; 3], 1.0)] {
            scene.material.alpha = alpha;
            scene.material.base_color = base;
            scene.material.f0 = f0;
            for method in Method::F32 {
                for view in [View::A, View::Split, View::Diff] {
                    for clip in [Clipping::BOTH, Clipping::NONE] {
                        let mut s = RenderSettings::single(W, H, method);
                        s.view = view;
                        s.rules.clipping = clip;
                        let mut r = g.renderer.lock().unwrap();
                        let frame = r.render(&g.ctx, &scene, &s).unwrap().0;
                        let bad = frame.pixels.iter().filter(|p| p.is_nan()).count();
                        assert_eq!(
                            bad,
                            0,
                            "{} {view:?} {clip:?} α={alpha} base={base:?}: {bad} NaN pixels",
                            method.name()
                        );
                        if clip == Clipping::BOTH && view != View::Diff {
                            assert!(
                                frame.pixels.iter().all(|p| p.min_element() >= 0.0),
                                "negative radiance"
                            );
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn light_counts_zero_one_and_too_many() {
    let Some(g) = gpu() else { return };
    let mut scene = preset("figure2-normal.toml");
    let s = RenderSettings::single(16, 16, Method::LtcFast);
    let mut r = g.renderer.lock().unwrap();
    scene.lights.clear();
    let (frame, _) = r.render(&g.ctx, &scene, &s).unwrap();
    assert!(
        frame.pixels.iter().all(|p| *p == DVec3::ZERO),
        "no lights, no light"
    );
    scene.lights = preset("figure2-normal.toml").lights;
    let (frame, _) = r.render(&g.ctx, &scene, &s).unwrap();
    assert!(frame.pixels.iter().any(|p| p.x > 0.0));
    let max = PlaneRenderer::max_lights(&g.ctx);
    assert!(
        max >= 20_000,
        "the lab's 20 000-light slider must fit: {max}"
    );
    PlaneRenderer::check_light_count(&g.ctx, max).unwrap();
    let light_bytes = std::mem::size_of::<ltc_lab::gpu::scene::GpuLight>();
    assert!(max <= ltc_lab::gpu::limits::buffer_max_lights(&g.ctx, light_bytes));
    let err = PlaneRenderer::check_light_count(&g.ctx, max + 1)
        .expect_err("one light too many is refused");
    assert!(err.to_string().contains("do not fit"), "{err}");
}

/// The point-light table on the GPU against the CPU with the same table: its fitted
/// `spec.scale` (packed into the LUT's fourth magnitude slot) reaches the shader's specular
/// magnitude as it reaches the CPU's. Same tolerance as above (same arithmetic).
#[test]
fn gpu_matches_cpu_with_the_point_table() {
    let Some(g) = gpu() else { return };
    let point = Lut::embedded_point();
    let mut renderer = PlaneRenderer::new(&g.ctx, point, ShaderChecks::Checked).unwrap();
    for (name, scene) in scenes() {
        for method in [Method::Ltc, Method::LtcFast] {
            let s = RenderSettings::single(W, H, method);
            let gpu = renderer.render(&g.ctx, &scene, &s).unwrap().0;
            let cpu = render(&scene, point, &RenderSettings::single(W, H, Method::Ltc));
            assert_close(&format!("{name} {} point table", method.name()), &gpu, &cpu);
            // And the table matters: the classic one gives a different image where the
            // specular lobe is lit (figure2-case1 lights only from below the horizon).
            let classic = render(
                &scene,
                Lut::embedded(),
                &RenderSettings::single(W, H, Method::Ltc),
            );
            assert!(
                name != "paper-100"
                    || cpu
                        .pixels
                        .iter()
                        .zip(&classic.pixels)
                        .any(|(p, c)| (*p - *c).abs().max_element() > 1e-3 * c.abs().max_element()),
                "{name}: the point table renders the classic table's image"
            );
        }
    }
}

/// Every horizon remedy on the GPU against the CPU reference, `ltc` and `ltc-fast`,
/// each with its own table (arrival-fit, constrained-fit) or rule (nl-fit, exact-band). Same
/// tolerance as above: the remedies add per light a few f32 operations (the nl-fit weight, the
/// exact BRDF divided by ltc-fast's factors), whose rounding is of the order of the LTC's own.
/// `exact-band` switches between two formulas at n·l = sin 15°, where f32 and f64 may decide
/// differently: a pixel with a light within 1e-5 of that edge (f32's n·l is good to ~1e-6
/// there: 1e-7 relative on a hit point 5 units out, over distances down to 0.5) is left out
/// of that comparison. With n·l spread over ~1 at each pixel, a pixel has such a light with
/// probability ~2e-5 per light, 2% with random-1000's lights: under 5% is asserted.
#[test]
fn gpu_matches_cpu_for_every_horizon_remedy() {
    use ltc_lab::ltc::remedy::{EXACT_BAND_Z, Horizon};
    let Some(g) = gpu() else { return };
    for (name, scene) in scenes() {
        let near_edge = near_band_edge(&scene);
        let left_out = near_edge.iter().filter(|&&n| n).count();
        assert!(
            left_out * 20 <= W * H,
            "{name}: {left_out} pixels near the band's edge"
        );
        for remedy in Horizon::ALL {
            let lut = remedy.table().map_or(Lut::embedded(), Lut::shipped);
            let mut renderer = PlaneRenderer::new(&g.ctx, lut, ShaderChecks::Checked).unwrap();
            // Both GPU forms against the one CPU image of `ltc` (the CPU has one LTC form).
            let mut s = RenderSettings::single(W, H, Method::Ltc);
            s.rules.horizon = remedy.rule();
            let cpu = render(&scene, lut, &s);
            for method in [Method::Ltc, Method::LtcFast] {
                s.a = s.a.with(method);
                let mut gpu = renderer.render(&g.ctx, &scene, &s).unwrap().0;
                if remedy == Horizon::ExactBand {
                    for (k, _) in near_edge.iter().enumerate().filter(|(_, n)| **n) {
                        gpu.pixels[k] = cpu.pixels[k];
                    }
                }
                assert_close(
                    &format!("{name} {} {}", method.name(), remedy.name()),
                    &gpu,
                    &cpu,
                );
            }
        }
    }
    /// Per pixel: whether a light's n·l is within 1e-5 of `EXACT_BAND_Z`.
    fn near_band_edge(scene: &Scene) -> Vec<bool> {
        (0..H)
            .flat_map(|y| (0..W).map(move |x| (x, y)))
            .map(|(x, y)| {
                scene.surface_point(x, y, W, H).is_some_and(|p| {
                    scene.lights.iter().any(|l| {
                        let u = (DVec3::from(l.position) - p.position).normalize();
                        (u.z - EXACT_BAND_Z).abs() < 1e-5
                    })
                })
            })
            .collect()
    }
}
