//! `ltc-lab render`: every preset and method, images that are always finite on the CPU and
//! the GPU, two tables compared, and lights with a size.

use std::path::Path;

use crate::gpu_common::gpu;
use crate::{
    assert_no_panic, assert_refused, edited_scene, exr_pixels, ltc_lab, ltc_lab_in, preset, stderr,
};

#[test]
fn render_cpu_writes_every_preset_and_method() {
    let dir = tempfile::tempdir().unwrap();
    for scene in [
        "paper-100.toml",
        "figure2-normal.toml",
        "figure2-case1.toml",
        "figure2-case2.toml",
    ] {
        for method in ["brdf", "ltc", "split", "diff"] {
            let out = dir.path().join(format!("{scene}-{method}.png"));
            let o = ltc_lab(&[
                "render",
                "--cpu",
                "--scene",
                &preset(scene),
                "--method",
                method,
                "--size",
                "40x30",
                "--out",
                out.to_str().unwrap(),
            ]);
            assert!(o.status.success(), "{scene} {method}: {}", stderr(&o));
            let img = image::open(&out).unwrap();
            // The diff map carries its colour bar beneath the image.
            assert_eq!(img.width(), 40);
            assert!(if method == "diff" {
                img.height() > 30
            } else {
                img.height() == 30
            });
        }
    }
    let exr = dir.path().join("x.exr");
    let o = ltc_lab(&[
        "render",
        "--cpu",
        "--scene",
        &preset("figure2-normal.toml"),
        "--method",
        "brdf",
        "--size",
        "16x8",
        "--out",
        exr.to_str().unwrap(),
        "--clip",
        "none",
        "--normalization",
        "paper",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::metadata(&exr).unwrap().len() > 0);
}

pub fn render_cpu(scene: &Path, out: &Path) -> std::process::Output {
    ltc_lab(&[
        "render",
        "--cpu",
        "--scene",
        scene.to_str().unwrap(),
        "--method",
        "ltc",
        "--size",
        "8x8",
        "--out",
        out.to_str().unwrap(),
    ])
}

/// figure2-case1 without any clipping rule: the exact image is black and the LTC glows. The
/// difference map (which divides by the exact image) is finite everywhere, on the CPU and
/// on the GPU, and shows the glow.
#[test]
fn the_diff_of_an_unclipped_glow_is_finite() {
    let dir = tempfile::tempdir().unwrap();
    let scene = preset("figure2-case1.toml");
    for cpu in devices() {
        let args = ["--method", "diff", "--clip", "none"];
        let pixels = render_exr(dir.path(), &scene, &args, cpu);
        assert!(
            pixels.iter().flatten().all(|x| x.is_finite() && *x >= 0.0),
            "cpu: {cpu}: a non-finite or negative difference"
        );
        assert!(
            pixels.iter().any(|p| p[0] > 0.0),
            "cpu: {cpu}: the glow is gone"
        );
    }
}

/// The CPU (`true`), and the GPU (`false`) where there is an adapter.
fn devices() -> Vec<bool> {
    if gpu().is_some() {
        vec![true, false]
    } else {
        vec![true]
    }
}

/// Renders `scene` at 48×32 with `args`, on the CPU or the GPU, to an EXR in `dir`; its pixels.
fn render_exr(dir: &Path, scene: &str, args: &[&str], cpu: bool) -> Vec<[f32; 3]> {
    let out = dir.join(format!("out-{cpu}.exr"));
    let mut all = vec!["render", "--scene", scene, "--size", "48x32"];
    all.extend(args);
    all.extend(["--out", out.to_str().unwrap()]);
    if cpu {
        all.push("--cpu");
    }
    let o = ltc_lab(&all);
    assert!(o.status.success(), "cpu: {cpu}: {}", stderr(&o));
    exr_pixels(&out)
}

/// A range of 1e-300 rounds to 0 in f32, which the GPU's light buffer reads as "infinite":
/// such a light must light nothing there either, as on the CPU.
#[test]
fn a_tiny_range_lights_nothing_on_either_renderer() {
    let dir = tempfile::tempdir().unwrap();
    let scene = edited_scene(dir.path(), "tiny-range.toml", |g| {
        g.replace("intensity = 1.0", "intensity = 1.0\nrange = 1e-300")
    });
    for cpu in devices() {
        let pixels = render_exr(
            dir.path(),
            scene.to_str().unwrap(),
            &["--method", "brdf"],
            cpu,
        );
        assert!(
            pixels.iter().flatten().all(|&x| x == 0.0),
            "cpu: {cpu}: a light of range 1e-300 lit the plane"
        );
    }
}

#[test]
fn render_on_the_gpu_by_default() {
    if gpu().is_none() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    for method in ["brdf", "brdf-fast", "ltc", "ltc-fast", "split", "diff"] {
        let out = dir.path().join(format!("{method}.exr"));
        let o = ltc_lab(&[
            "render",
            "--scene",
            &preset("paper-100.toml"),
            "--method",
            method,
            "--size",
            "32x24",
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{method}: {}", stderr(&o));
        assert!(stderr(&o).contains("ms GPU"), "{method}: {}", stderr(&o));
        assert!(std::fs::metadata(&out).unwrap().len() > 0);
    }
}

/// `--table-b` compares two tables in the split and difference views, on either device; the
/// culled and unculled renders are the same file's pixels.
#[test]
fn render_compares_two_tables_and_culls_without_changing_the_image() {
    let dir = tempfile::tempdir().unwrap();
    let scene = preset("paper-100.toml");
    for cpu in devices() {
        let diff = render_exr(
            dir.path(),
            &scene,
            &["--method", "diff", "--table-b", "point"],
            cpu,
        );
        assert!(
            diff.iter().any(|p| p[0] > 1e-3),
            "cpu: {cpu}: the two tables agree?"
        );
        let off = render_exr(
            dir.path(),
            &scene,
            &["--method", "ltc", "--cull", "off"],
            cpu,
        );
        let on = render_exr(
            dir.path(),
            &scene,
            &["--method", "ltc", "--cull", "on"],
            cpu,
        );
        assert_eq!(off, on, "cpu: {cpu}");
    }
    let o = ltc_lab(&[
        "render",
        "--cpu",
        "--scene",
        &scene,
        "--method",
        "ltc",
        "--table-b",
        "point",
    ]);
    assert_refused(&o, "--method");
}

/// A difference map 1 to 4 pixels wide gets its colour bar inside the image (it panicked
/// with "Image index (4, 10) out of bounds"), on the CPU and the GPU.
#[test]
fn a_tiny_difference_map_is_written() {
    let dir = tempfile::tempdir().unwrap();
    for cpu in devices() {
        for width in 1..=4 {
            let out = dir.path().join(format!("diff-{width}-{cpu}.png"));
            let (size, scene) = (format!("{width}x10"), preset("figure2-case1.toml"));
            let mut args = vec![
                "render",
                "--scene",
                &scene,
                "--method",
                "diff",
                "--size",
                &size,
                "--out",
                out.to_str().unwrap(),
            ];
            if cpu {
                args.push("--cpu");
            }
            let o = ltc_lab(&args);
            assert_no_panic(o.status.code(), &stderr(&o));
            assert!(o.status.success(), "{width} px: {}", stderr(&o));
            let img = image::open(&out).unwrap();
            assert_eq!(img.width(), width);
            assert!(img.height() > 10, "no colour bar under the map");
        }
    }
}

/// A render with a horizon remedy says so in its default name, and differs from
/// eq. 30's where lights sit near the horizon (figure2-case2's light is 0.01 above the plane).
#[test]
fn a_horizon_remedy_names_its_render_and_changes_it() {
    let dir = tempfile::tempdir().unwrap();
    let render = |extra: &[&str]| {
        let scene = preset("figure2-case2.toml");
        let mut args = vec!["render", "--cpu", "--scene", &scene, "--method", "ltc"];
        args.extend(["--size", "16x16"]);
        args.extend(extra);
        let o = ltc_lab_in(dir.path(), &args);
        assert!(o.status.success(), "{}", stderr(&o));
    };
    render(&[]);
    render(&["--horizon", "exact-band"]);
    let read = |name: &str| std::fs::read(dir.path().join(name)).unwrap();
    assert_ne!(
        read("figure2-case2-ltc.png"),
        read("figure2-case2-ltc-exact-band.png")
    );
    let o = ltc_lab_in(
        dir.path(),
        &[
            "render",
            "--cpu",
            "--scene",
            &preset("figure2-case2.toml"),
            "--method",
            "ltc",
            "--horizon",
            "arrival-fit",
            "--lut",
            "missing.exr",
        ],
    );
    assert_refused(&o, "--horizon");
}

/// Lights with a size from the command line: each sphere method renders a failure preset,
/// the EXR is the CPU reference's own frame, and a method it does not know is refused.
#[test]
fn render_shades_lights_with_a_size_by_the_method_asked() {
    let dir = tempfile::tempdir().unwrap();
    let scene = preset("sphere-horizon.toml");
    let mut images = Vec::new();
    for sphere in ["exact", "ltc-point", "ltc-disk", "representative-point"] {
        let args = ["--method", "ltc", "--sphere-a", sphere];
        let pixels = render_exr(dir.path(), &scene, &args, true);
        // render_exr's size.
        let settings = ltc_lab::render::RenderSettings {
            a: ltc_lab::render::ShapeMethods::approximations()
                .with(ltc_lab::render::Method::Ltc)
                .with(ltc_lab::light::sphere::SphereMethod::from_name(sphere).unwrap()),
            ..ltc_lab::render::RenderSettings::single(48, 32, ltc_lab::render::Method::Ltc)
        };
        let scene = ltc_lab::scene::preset("sphere-horizon");
        let want = ltc_lab::cpu::render(&scene, ltc_lab::ltc::lut::Lut::embedded(), &settings);
        // The EXR holds f32: the f64 frame rounded, 2⁻²⁴ relative.
        for (got, want) in pixels.iter().zip(&want.pixels) {
            let got = glam::DVec3::from(got.map(f64::from));
            let close = (got - *want).abs().max_element() <= 1e-6 * want.abs().max_element();
            assert!(close, "{sphere}: {got} vs {want}");
        }
        images.push(pixels);
    }
    // The methods differ on these spheres.
    assert!(images.windows(2).all(|w| w[0] != w[1]));
    // clap's own refusal, which lists the methods it knows.
    let o = ltc_lab(&[
        "render",
        "--cpu",
        "--scene",
        &scene,
        "--method",
        "ltc",
        "--sphere-a",
        "disk",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("representative-point"),
        "{}",
        stderr(&o)
    );
}

/// `--method-for [SIDE:]SHAPE=METHOD` is the per-shape flags keyed by shape: the same image
/// as its alias, to the bit; two flags that disagree on one side's shape, a shape that is none
/// and a method of another shape are refused (exit 2), naming the flag.
#[test]
fn method_for_is_the_per_shape_flags_keyed_by_shape() {
    let dir = tempfile::tempdir().unwrap();
    for (scene, alias, keyed) in [
        (
            "rect-horizon.toml",
            ["--rect-a", "ltc-proxy", "--rect-b", "ltc-point"],
            [
                "--method-for",
                "rect=ltc-proxy",
                "--method-for",
                "b:rect=ltc-point",
            ],
        ),
        (
            "disk-limits.toml",
            ["--disk-a", "ltc-point", "--point-b", "ltc"],
            [
                "--method-for",
                "a:disk=ltc-point",
                "--method-for",
                "b:point=ltc",
            ],
        ),
    ] {
        let scene = preset(scene);
        let render = |flags: &[&str]| {
            let mut args = vec!["--method", "split"];
            args.extend(flags);
            render_exr(dir.path(), &scene, &args, true)
        };
        let (by_alias, by_key) = (render(&alias), render(&keyed));
        assert_eq!(by_alias, by_key, "{scene}");
        // And the flags change the image: the defaults differ from both.
        assert_ne!(render(&[]), by_key, "{scene}");
    }
    let scene = preset("rect-horizon.toml");
    let out = dir.path().join("never-written.exr");
    let run = |flags: &[&str]| {
        let mut args = vec!["render", "--cpu", "--scene", &scene, "--method", "split"];
        args.extend(flags);
        args.extend(["--out", out.to_str().unwrap()]);
        ltc_lab(&args)
    };
    // Ours: one line naming the flag and the one it disagrees with.
    let o = run(&["--rect-a", "exact", "--method-for", "rect=ltc-point"]);
    assert_refused(&o, "--method-for");
    assert!(stderr(&o).contains("--rect-a"), "{}", stderr(&o));
    // clap's, which names the flag and says what it takes.
    for (flag, named) in [
        ("cone=exact", "one of point, sphere, rect, disk, tube"),
        ("disk=ltc-polygon", "exact, ltc-disk, ltc-point"),
        ("c:rect=exact", "the side is a or b"),
    ] {
        let o = run(&["--method-for", flag]);
        assert_eq!(o.status.code(), Some(2), "{flag}: {}", stderr(&o));
        assert!(stderr(&o).contains("--method-for"), "{}", stderr(&o));
        assert!(stderr(&o).contains(named), "{flag}: {}", stderr(&o));
    }
    assert!(!out.exists());
}

/// `render --help` names every shape `--method-for` takes, each with every one of its methods
/// (the help is built from the shapes, so a new shape is in it).
#[test]
fn the_help_names_every_shape_and_its_methods() {
    let o = crate::ltc_lab(&["render", "--help"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let help = String::from_utf8_lossy(&o.stdout);
    for kind in ltc_lab::light::ShapeKind::ALL {
        assert!(
            help.contains(&format!("{} (", kind.name())),
            "{kind:?}: {help}"
        );
        for m in ltc_lab::render::ShapeMethod::all(kind) {
            assert!(help.contains(m.name()), "{kind:?} {}", m.name());
        }
    }
    assert!(help.contains("tube (exact, ltc-line"), "{help}");
}
