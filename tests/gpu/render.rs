//! The GPU renderer's ways of getting an image, against each other and the CPU (lavapipe in
//! CI): tiled culling gives the unculled image to the bit; a render summed in chunks across
//! submissions gives the one-shot image to the bit; a second table reaches method B as on the
//! CPU; the f16 pairs stay finite and within half precision; a read-back that never waits (the
//! browser's) gives the waiting one's frame.

use crate::gpu_common::{assert_close, bits, gpu};
use glam::DVec3;
use ltc_lab::cpu::render;
use ltc_lab::gpu::plane::ShaderChecks;
use ltc_lab::gpu::renderer::PlaneRenderer;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::{Clipping, Normalization};
use ltc_lab::metrics::{luminance, relative_floor};
use ltc_lab::render::{Frame, LtcRules, Method, RenderSettings, Tables, View};
use ltc_lab::scene::{Light, RandomLights, Scene, generate_lights, preset};

const W: usize = 64;
const H: usize = 40;

/// The methods this adapter runs.
fn methods() -> Vec<Method> {
    let f16 = gpu().is_some_and(|g| g.ctx.has_f16());
    Method::F32
        .into_iter()
        .chain(Method::F16)
        .filter(|m| f16 || !m.needs_f16())
        .collect()
}

/// paper-100's view with lights meant to trouble the binning: `count` random lights of range
/// `range`; lights on the footprint corners of the 4×3 tiles (their discs straddle tile
/// edges); lights behind the camera whose range reaches the plane in view; a few of infinite
/// range.
fn binning_scene(range: f64, count: usize) -> Scene {
    let mut scene = preset("paper-100");
    scene.lights = generate_lights(
        &RandomLights {
            count,
            seed: 3,
            height: [0.02, 0.8],
            intensity: [0.02, 0.2],
            range: Some(range),
            radius: 0.0,
        },
        scene.plane.half_size,
    );
    let light = |position: [f64; 3], range: Option<f64>| Light {
        position,
        color: [1.0, 0.8, 0.6],
        intensity: 0.1,
        range,
        shape: ltc_lab::light::Shape::of_radius(0.0),
    };
    for ty in 0..=H / 16 {
        for tx in 0..=W / 16 {
            let (eye, dir) = scene.camera_ray((tx * 16) as f64, (ty * 16) as f64, W, H);
            let t = -eye.z / dir.z;
            if dir.z < 0.0 && t > 0.0 {
                let p = eye + t * dir;
                scene.lights.push(light([p.x, p.y, 0.1], Some(0.3)));
            }
        }
    }
    // The camera is at (0, −3.4, 2.8): these are behind it, yet reach the near plane.
    for x in [-1.0, 0.0, 1.5] {
        scene.lights.push(light([x, -4.5, 0.5], Some(3.5)));
    }
    scene.lights.push(light([0.5, 0.5, 1.0], None));
    scene.material.alpha = 0.3;
    scene
}

fn frame(r: &mut PlaneRenderer, scene: &Scene, s: &RenderSettings) -> Frame {
    r.render(&gpu().unwrap().ctx, scene, s).unwrap().0
}

/// Every light culled from a tile adds exactly 0 at each of its pixels (its range does not
/// reach them), and the kept ones are summed in the same order: the culled image is the
/// unculled one to the bit, for every method, view and range. The lists must also really
/// be shorter than every light in every tile, or the check would be empty.
#[test]
fn culled_images_equal_unculled_ones_exactly() {
    let Some(g) = gpu() else { return };
    let mut r = g.renderer.lock().unwrap();
    for range in [0.1, 0.5, 2.0] {
        let scene = binning_scene(range, 300);
        for method in methods() {
            for view in [View::A, View::Split, View::Diff] {
                let mut s = RenderSettings::single(W, H, method);
                s.view = view;
                s.b.set(if method == Method::Brdf {
                    Method::Ltc
                } else {
                    Method::Brdf
                });
                s.cull = false;
                let unculled = frame(&mut r, &scene, &s);
                s.cull = true;
                let mut render = r.begin(&g.ctx, &scene, &s, None).unwrap();
                render.poison(&g.ctx);
                render.run(&g.ctx, &mut |_| {}).unwrap();
                let culled = render.read(&g.ctx).unwrap();
                let (kept, all) = render.tile_entries(&g.ctx).expect("a culled render");
                assert!(
                    kept > 0 && kept < all,
                    "range {range}: {kept} of {all} kept"
                );
                assert!(
                    bits(&culled) == bits(&unculled),
                    "{} {view:?} range {range}: culled differs from unculled",
                    method.name()
                );
                assert!(culled.pixels.iter().any(|p| p.x > 0.0), "a black image");
            }
        }
    }
}

/// Summing a render in chunks, each its own submission with the sums kept in between, gives
/// the one-shot image to the bit: the same f32 operations in the same order, the sums stored
/// and loaded exactly (tolerance 0, derived: f32 storage is exact).
#[test]
fn a_render_summed_in_chunks_is_the_one_shot_render() {
    let Some(g) = gpu() else { return };
    let mut r = g.renderer.lock().unwrap();
    let scene = binning_scene(0.5, 700);
    let n = scene.lights.len();
    for method in [Method::Brdf, Method::LtcFast, Method::Ltc] {
        for (view, cull) in [(View::A, false), (View::Diff, true), (View::Split, true)] {
            // A and B differ, so that the difference view is not 0 whatever is summed.
            let other = if method == Method::Brdf {
                Method::LtcFast
            } else {
                Method::Brdf
            };
            let s = RenderSettings {
                view,
                cull,
                b: RenderSettings::single(W, H, method).b.with(other),
                ..RenderSettings::single(W, H, method)
            };
            let whole = frame(&mut r, &scene, &s);
            let mut render = r.begin(&g.ctx, &scene, &s, None).unwrap();
            // Chunks of uneven size, one not a multiple of the 256-light load.
            for range in [0..1, 1..300, 300..301, 301..n] {
                render.step(&g.ctx, range);
                let _ = g.ctx.device.poll(wgpu::PollType::wait_indefinitely());
            }
            let chunked = render.read(&g.ctx).unwrap();
            assert!(
                bits(&chunked) == bits(&whole),
                "{} {view:?} cull {cull}: the chunked image differs",
                method.name()
            );
            // The first entries alone give another image (the chunks are really summed;
            // a culled tile's list may be shorter than half the lights).
            let mut render = r
                .begin(&g.ctx, &scene, &s, Some(render.into_kept()))
                .unwrap();
            render.step(&g.ctx, 0..3);
            assert!(
                bits(&render.read(&g.ctx).unwrap()) != bits(&whole),
                "{} {view:?} cull {cull}: three entries give the whole image",
                method.name()
            );
        }
    }
}

/// Two tables compared: LTC with the classic table against LTC with the point table, split,
/// difference and B alone, on the GPU against the CPU with the same two tables (the parity
/// tolerance of tests/gpu/parity.rs, same arithmetic).
#[test]
fn a_second_table_reaches_method_b_as_on_the_cpu() {
    let Some(g) = gpu() else { return };
    let (classic, point) = (Lut::embedded(), Lut::embedded_point());
    let mut r = PlaneRenderer::new(&g.ctx, classic, ShaderChecks::Checked).unwrap();
    r.set_tables(&g.ctx, classic, Some(point)).unwrap();
    let tables = Tables {
        a: classic,
        b: point,
    };
    let mut scene = preset("paper-100");
    // A specular material, where the two fits differ most.
    scene.material.base_color = [0.05; 3];
    scene.material.f0 = 0.9;
    for method in [Method::Ltc, Method::LtcFast] {
        for view in [View::Split, View::B] {
            let s = RenderSettings {
                b: RenderSettings::single(W, H, method).b.with(method),
                view,
                b_reads_table_b: true,
                ..RenderSettings::single(W, H, method)
            };
            let gpu = r.render(&g.ctx, &scene, &s).unwrap().0;
            let cpu = render(&scene, tables, &s);
            assert_close(&format!("{} {view:?} tables", method.name()), &gpu, &cpu);
        }
        // B alone with the point table is the point table's image, not the classic one's.
        let alone = RenderSettings {
            b: RenderSettings::single(W, H, method).b.with(method),
            view: View::B,
            b_reads_table_b: true,
            ..RenderSettings::single(W, H, method)
        };
        let b = r.render(&g.ctx, &scene, &alone).unwrap().0;
        let point_image = render(&scene, point, &RenderSettings::single(W, H, method));
        let classic_image = render(&scene, classic, &RenderSettings::single(W, H, method));
        assert_close("B alone = point", &b, &point_image);
        assert_ne!(point_image.pixels, classic_image.pixels);
    }
    // The difference of the two tables on the GPU is the CPU's to the diff bound.
    let diff = RenderSettings {
        b: RenderSettings::single(W, H, Method::Ltc)
            .b
            .with(Method::Ltc),
        view: View::Diff,
        b_reads_table_b: true,
        ..RenderSettings::single(W, H, Method::Ltc)
    };
    let gpu_diff = r.render(&g.ctx, &scene, &diff).unwrap().0;
    let cpu_diff = render(&scene, tables, &diff);
    for (k, (g, c)) in gpu_diff.pixels.iter().zip(&cpu_diff.pixels).enumerate() {
        let bound = crate::gpu_common::diff_tolerance(c.x);
        assert!(
            (g.x - c.x).abs() <= bound,
            "pixel {k}: gpu {} cpu {}",
            g.x,
            c.x
        );
    }
    assert!(
        cpu_diff.pixels.iter().any(|p| p.x > 1e-3),
        "the tables do not differ"
    );
    // Without a second table, asking for one is refused.
    let mut plain = PlaneRenderer::new(&g.ctx, classic, ShaderChecks::Checked).unwrap();
    assert!(plain.render(&g.ctx, &scene, &diff).is_err());
}

/// ltc-f16-pairs against the f64 LTC, as tests/gpu/parity.rs checks ltc-f16: f16 keeps 11
/// significant bits (4.9e-4 per operation, ~10 operations in M⁻¹l and |w|⁴), so each term is
/// good to ~5e-3; 1e-2 of the reference luminance (floor: 1% of the mean). α ≥ 0.12, where
/// M⁻¹l stays within f16's range. And no NaN or inf at any α, with either clipping.
#[test]
fn f16_pairs_are_finite_and_within_half_precision() {
    let Some(g) = gpu() else { return };
    if !g.ctx.has_f16() {
        crate::gpu_common::skipped(&format!(
            "{} has no SHADER_F16; ltc-f16-pairs is not offered there",
            g.ctx.info.name
        ));
        return;
    }
    let mut r = g.renderer.lock().unwrap();
    for (range, count) in [(0.5, 301), (2.0, 1000)] {
        let scene = binning_scene(range, count);
        let cpu = render(
            &scene,
            Lut::embedded(),
            &RenderSettings::single(W, H, Method::Ltc),
        );
        let gpu = frame(
            &mut r,
            &scene,
            &RenderSettings::single(W, H, Method::LtcF16Pairs),
        );
        let floor = relative_floor(&cpu, &cpu);
        let worst = (0..cpu.pixels.len())
            .filter(|&k| gpu.on_plane[k] && cpu.on_plane[k])
            .map(|k| {
                (gpu.pixels[k] - cpu.pixels[k]).abs().max_element()
                    / luminance(cpu.pixels[k].abs()).max(floor)
            })
            .fold(0.0, f64::max);
        assert!(
            worst <= 1e-2,
            "range {range}: ltc-f16-pairs differs by {worst:.2e}"
        );
        assert!(worst > 0.0, "f16 identical to f64?");
    }
    for alpha in [ltc_lab::ltc::lut::ALPHA_MIN, 0.27, 1.0] {
        for clip in [Clipping::BOTH, Clipping::NONE] {
            let mut scene = binning_scene(0.5, 200);
            scene.material.alpha = alpha;
            let s = RenderSettings {
                rules: LtcRules {
                    clipping: clip,
                    normalization: Normalization::Corrected,
                    ..LtcRules::default()
                },
                ..RenderSettings::single(W, H, Method::LtcF16Pairs)
            };
            let f = frame(&mut r, &scene, &s);
            assert!(
                f.pixels.iter().all(|p| p.is_finite()),
                "α {alpha} {clip:?}: a non-finite pixel"
            );
        }
    }
    // The pairs sum two lights at once: an odd count leaves one to the one-light form.
    let one = binning_scene(0.5, 0);
    let f = frame(
        &mut r,
        &one,
        &RenderSettings::single(W, H, Method::LtcF16Pairs),
    );
    assert!(f.pixels.iter().all(|p| p.is_finite()) && f.pixels.iter().any(|p| *p != DVec3::ZERO));
}

/// The library speaks of values, the CLI of flags: a refused image size or light count says
/// which value and which limit, and names no flag (the lab's window once showed an error
/// about `--size`).
#[test]
fn limits_name_the_value_not_a_flag() {
    use ltc_lab::gpu::limits::Limited;
    let Some(g) = crate::gpu_common::gpu() else {
        return;
    };
    let side = g.ctx.limits.max_texture_dimension_2d as usize + 1;
    let too_many = ltc_lab::gpu::renderer::PlaneRenderer::max_lights(&g.ctx) + 1;
    for (lights, size, value) in [
        (1, (side, 8), Limited::ImageSize),
        (too_many, (8, 8), Limited::LightCount),
    ] {
        let e = ltc_lab::measure::bench::check(&g.ctx, &[lights], size).unwrap_err();
        assert_eq!(e.value, value, "{e}");
        let text = ltc_lab::error::Error::from(e).to_string();
        assert!(
            text.starts_with(value.name()) && !text.contains("--"),
            "{text}"
        );
    }
}

/// A read-back that never waits (the browser's) gives the frame the waiting one
/// gives, to the bit: `try_take` says `None` or the texels, and once the device has finished
/// (polled here, as the browser's event loop does for it) it has them.
#[test]
fn a_read_in_steps_is_the_waiting_read() {
    let Some(g) = gpu() else { return };
    let mut r = PlaneRenderer::new(&g.ctx, Lut::embedded(), ShaderChecks::Checked).unwrap();
    let scene = preset("paper-100");
    let mut render = r
        .begin(
            &g.ctx,
            &scene,
            &RenderSettings::single(W, H, Method::LtcFast),
            None,
        )
        .unwrap();
    render.run(&g.ctx, &mut |_| {}).unwrap();
    let waited = render.read(&g.ctx).unwrap();
    let pending = render.start_read(&g.ctx);
    let mut texels = pending.try_take(&g.ctx);
    // Each poll without waiting lets the device finish a little more; a bound keeps a broken
    // mapping from hanging the test (lavapipe maps this 10 kB copy within a few polls).
    for _ in 0..10_000 {
        if texels.is_some() {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(1));
        texels = pending.try_take(&g.ctx);
    }
    let stepped = render.frame_of(&texels.expect("the read-back never landed"));
    assert_eq!(bits(&stepped), bits(&waited));
    assert_eq!(stepped.on_plane, waited.on_plane);
}
