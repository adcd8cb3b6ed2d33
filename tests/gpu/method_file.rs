//! A method loaded from a WGSL file (docs/design.md §5.13) rendered on the GPU: a file equal
//! to the lab's `ltc` gives the CPU reference's `ltc` image; the artifact example gives the
//! image of `ltc` without case 2, negative light and all; a loop that never ends is stopped
//! and named, and the renderer goes on; the other examples shade finite light.

use crate::gpu_common::{assert_close, gpu};
use ltc_lab::cpu;
use ltc_lab::error::ErrorKind;
use ltc_lab::gpu::method_file::MethodFile;
use ltc_lab::gpu::plane::ShaderChecks;
use ltc_lab::gpu::renderer::PlaneRenderer;
use ltc_lab::light::rect::RectMethod;
use ltc_lab::ltc::Clipping;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::metrics::luminance;
use ltc_lab::render::{Frame, Method, RenderSettings};
use ltc_lab::scene::{Scene, preset};

const SIZE: (usize, usize) = (96, 64);

fn shipped(name: &str) -> MethodFile {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("assets/methods")
        .join(name);
    MethodFile::read(&path).unwrap()
}

/// A renderer of its own (the shared one keeps its module), holding `file`.
fn renderer_with(file: MethodFile) -> Option<PlaneRenderer> {
    let g = gpu()?;
    let mut r = PlaneRenderer::new(&g.ctx, Lut::embedded(), ShaderChecks::Checked).unwrap();
    r.set_method_file(&g.ctx, Some(file)).unwrap();
    Some(r)
}

fn settings(method: Method, clipping: Clipping) -> RenderSettings {
    let mut s = RenderSettings::single(SIZE.0, SIZE.1, method);
    s.rules.clipping = clipping;
    s
}

fn render(r: &mut PlaneRenderer, scene: &Scene, s: &RenderSettings) -> Frame {
    r.render(&gpu().unwrap().ctx, scene, s).unwrap().0
}

#[test]
fn a_file_equal_to_ltc_gives_the_labs_ltc_image() {
    let Some(mut r) = renderer_with(shipped("ltc.wgsl")) else {
        return;
    };
    for name in [
        "paper-100",
        "figure2-normal",
        "figure2-case1",
        "figure2-case2",
    ] {
        let scene = preset(name);
        let file = render(&mut r, &scene, &settings(Method::File, Clipping::BOTH));
        let reference = cpu::render(
            &scene,
            Lut::embedded(),
            &settings(Method::Ltc, Clipping::BOTH),
        );
        assert_close(name, &file, &reference);
    }
}

#[test]
fn the_artifact_example_is_ltc_without_case_2() {
    let Some(mut r) = renderer_with(shipped("no-case2.wgsl")) else {
        return;
    };
    let scene = preset("figure2-case2");
    let file = render(&mut r, &scene, &settings(Method::File, Clipping::BOTH));
    // The file's own rules, whatever the lab's clipping says: case 1 only.
    let without = cpu::render(
        &scene,
        Lut::embedded(),
        &settings(Method::Ltc, Clipping::CASE1),
    );
    assert_close("no-case2.wgsl", &file, &without);
    let with = cpu::render(
        &scene,
        Lut::embedded(),
        &settings(Method::Ltc, Clipping::BOTH),
    );
    let negative = |f: &Frame| f.pixels.iter().filter(|p| luminance(**p) < 0.0).count();
    assert_eq!(
        negative(&with),
        0,
        "the lab's ltc never sums negative light"
    );
    // More than a speck of rounding: the artifact covers a band of the image.
    assert!(
        negative(&file) > SIZE.0 * SIZE.1 / 100,
        "the artifact: negative light on {} pixels",
        negative(&file)
    );
}

#[test]
fn a_loop_that_never_ends_is_stopped_and_named() {
    let src = "fn method_point(pixel: MethodPixel, light: MethodPoint) -> MethodRadiance {\n    var x = 0.0;\n    loop { x += 1.0; }\n    return MethodRadiance(vec3<f32>(x), vec3<f32>(0.0));\n}\n";
    let file = MethodFile::from_source("forever.wgsl", src).unwrap();
    let Some(mut r) = renderer_with(file) else {
        return;
    };
    let g = gpu().unwrap();
    let scene = preset("figure2-normal");
    // Matched, not expect_err: a frame's Debug would print every pixel.
    let Err(e) = r.render(&g.ctx, &scene, &settings(Method::File, Clipping::BOTH)) else {
        panic!("a loop that never ends was not stopped");
    };
    assert_eq!(
        (e.kind, e.input.as_str()),
        (ErrorKind::Input, "forever.wgsl")
    );
    assert!(e.message.contains("stopped"), "{e}");
    // The device goes on: the lab's own method renders, unmarked, in the same buffers.
    let ltc = render(&mut r, &scene, &settings(Method::Ltc, Clipping::BOTH));
    let reference = cpu::render(
        &scene,
        Lut::embedded(),
        &settings(Method::Ltc, Clipping::BOTH),
    );
    assert_close("ltc after a stop", &ltc, &reference);
}

#[test]
fn the_disk_and_rect_examples_shade_finite_light() {
    for (file, presets) in [
        (
            "ltc-disk-points.wgsl",
            ["paper-100", "figure2-case2", "sphere-touching"],
        ),
        (
            "threejs-rect.wgsl",
            ["rect-ceiling", "rect-horizon", "rect-limits"],
        ),
    ] {
        let Some(mut r) = renderer_with(shipped(file)) else {
            return;
        };
        for name in presets {
            let f = render(
                &mut r,
                &preset(name),
                &settings(Method::File, Clipping::BOTH),
            );
            let bad = f
                .pixels
                .iter()
                .find(|p| !p.is_finite() || p.min_element() < 0.0);
            assert!(bad.is_none(), "{file} on {name}: {bad:?}");
            assert!(
                f.pixels.iter().any(|p| luminance(*p) > 0.0),
                "{file} on {name}: black"
            );
        }
    }
}

#[test]
fn the_rect_example_is_the_labs_proxy_within_its_edge_fit() {
    let Some(mut r) = renderer_with(shipped("threejs-rect.wgsl")) else {
        return;
    };
    // three.js's rational fit of θ/(2π sin θ) against the function itself, in f64.
    let fit = |x: f64| {
        let y = x.abs();
        let v = (0.8543985 + (0.4965155 + 0.0145206 * y) * y) / (3.4175940 + (4.1616724 + y) * y);
        if x > 0.0 {
            v
        } else {
            0.5 / (1.0 - x * x).max(1e-7).sqrt() - v
        }
    };
    let worst_fit = (1..2000)
        .map(|k| -1.0 + f64::from(k) / 1000.0)
        .map(|x: f64| {
            let t = x.acos();
            (fit(x) / (t / t.sin() / (2.0 * std::f64::consts::PI)) - 1.0).abs()
        })
        .fold(0.0, f64::max);
    for name in ["rect-ceiling", "rect-horizon"] {
        let scene = preset(name);
        let file = render(&mut r, &scene, &settings(Method::File, Clipping::BOTH));
        let mut s = settings(Method::Ltc, Clipping::BOTH);
        s.a.set(RectMethod::LtcProxyFast);
        let lab = cpu::render(&scene, Lut::embedded(), &s);
        let floor = ltc_lab::metrics::relative_floor(&lab, &lab);
        let worst = (0..lab.pixels.len())
            .filter(|&k| lab.on_plane[k] && file.on_plane[k])
            .map(|k| {
                (file.pixels[k] - lab.pixels[k]).abs().max_element()
                    / luminance(lab.pixels[k]).max(floor)
            })
            .fold(0.0, f64::max);
        // Each edge's factor is off by at most the fit's error; the edges' sum may cancel (at
        // most doubling that, relatively, for a rect seen from its lit side) and the clipped
        // sphere's (l² + z)/(l + 1) moves at most twice as fast as l, relatively: 4× the fit.
        // Beyond it, the GPU's f32 against the CPU's f64 as in every render (the parity
        // tolerance, which says where it comes from). Measured on lavapipe: 2.1e-5 and
        // 3.6e-5, against a bound of 2.06e-4.
        let bound = 4.0 * worst_fit + ltc_lab::measure::parity::RADIANCE_TOLERANCE;
        assert!(
            worst > 0.0 && worst < bound,
            "{name}: {worst:.2e} against the fit's {worst_fit:.2e}"
        );
    }
}

/// The pixel inspector's values of a file, evaluated on the GPU at one point, are the CPU
/// reference's LTC of each light there, for the file equal to `ltc`: to the renders' parity
/// tolerance, relative to each light or to 1% of the mean light (where a light adds ~0, as
/// the renders' floor).
#[test]
fn the_inspectors_values_of_a_file_are_each_lights_ltc() {
    let Some(mut r) = renderer_with(shipped("ltc.wgsl")) else {
        return;
    };
    let g = gpu().unwrap();
    let scene = preset("paper-100");
    let s = RenderSettings::single(320, 180, Method::File);
    for at in [[0.5, 0.6], [0.2, 0.9], [0.8, 0.45]] {
        let values = r
            .probe_file(&g.ctx, &scene, &s, at)
            .unwrap()
            .expect("on the plane");
        let p = scene
            .surface_point_at(at[0] * 320.0, at[1] * 180.0, 320, 180)
            .unwrap();
        let terms = ltc_lab::pixel::pixel_terms(
            &scene,
            (Lut::embedded(), None),
            &p,
            &s.rules,
            (&s.a, &s.b),
        )
        .unwrap();
        assert_eq!(values.len(), terms.terms.len());
        let mean = terms.terms.iter().map(|t| luminance(t.ltc)).sum::<f64>() / values.len() as f64;
        for (gpu, t) in values.iter().zip(&terms.terms) {
            let bound =
                ltc_lab::measure::parity::RADIANCE_TOLERANCE * luminance(t.ltc).max(0.01 * mean);
            assert!(
                (*gpu - t.ltc).abs().max_element() <= bound,
                "light {} at {at:?}: gpu {gpu} cpu {}",
                t.index,
                t.ltc
            );
        }
    }
    // Off the plane: no values.
    assert!(
        r.probe_file(&g.ctx, &scene, &s, [0.5, 0.01])
            .unwrap()
            .is_none()
    );
}

/// A file's `method_tube` is called for each tube with its centre, half axis, radius and
/// intensity (windowed at the centre, as a point's): a file giving back the intensity as
/// specular and (r, |half_axis|, 0) as diffuse renders its point image of the same lights as
/// points, plus the sum of (r, |half_axis|, 0) at every pixel of the plane it sees.
#[test]
fn a_files_tube_function_sees_each_tube() {
    let source = "fn method_point(pixel: MethodPixel, light: MethodPoint) -> MethodRadiance {\n    return MethodRadiance(light.intensity, vec3<f32>(0.0));\n}\nfn method_tube(pixel: MethodPixel, light: MethodTube) -> MethodRadiance {\n    return MethodRadiance(light.intensity, vec3<f32>(light.radius, length(light.half_axis), 0.0));\n}\n";
    let file = MethodFile::from_source("tube-fields.wgsl", source).unwrap();
    assert_eq!(file.shapes(), "point, tube");
    let Some(mut r) = renderer_with(file) else {
        return;
    };
    let tubes = preset("tube-limits");
    let mut points = tubes.clone();
    let mut sum = glam::DVec3::ZERO;
    for l in &mut points.lights {
        let ltc_lab::light::Shape::Tube { half_axis, radius } = l.shape else {
            panic!("tube-limits holds tubes only");
        };
        sum += glam::DVec3::new(radius, half_axis.length(), 0.0);
        l.shape = ltc_lab::light::Shape::Point;
    }
    let s = settings(Method::File, Clipping::BOTH);
    let (tube_frame, point_frame) = (render(&mut r, &tubes, &s), render(&mut r, &points, &s));
    assert!(
        point_frame.pixels.iter().any(|p| luminance(*p) > 0.0),
        "the point image is black"
    );
    // f32 sums of a few terms of size ≤ 10: some 1e-5 of them.
    let mut seen = 0;
    for (i, (t, p)) in tube_frame
        .pixels
        .iter()
        .zip(&point_frame.pixels)
        .enumerate()
    {
        let d = *t - *p;
        if d.abs().max_element() < 1e-4 {
            continue;
        }
        assert!(
            (d - sum).abs().max_element() < 1e-4 * (1.0 + p.max_element()),
            "pixel {i}: {d} not {sum}"
        );
        seen += 1;
    }
    assert!(
        seen > SIZE.0 * SIZE.1 / 4,
        "{seen} pixels saw the tubes' fields"
    );
}
