//! `ltc-lab render`: every preset and method, refused scenes, default names that never
//! replace a file, images that are always finite, and the GPU's limits checked up front.

use std::path::Path;

use crate::gpu_common::gpu;
use crate::{
    assert_no_panic, assert_refused, corrupt_lut, edited_scene, exe, exr_pixels, ltc_lab,
    ltc_lab_in, preset, stderr,
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

/// A change to a preset's text.
type Edit = Box<dyn Fn(&str) -> String>;

fn render_cpu(scene: &Path, out: &Path) -> std::process::Output {
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

#[test]
fn render_refuses_malformed_scenes_and_leaves_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.png");
    let cases: Vec<(Edit, &str)> = vec![
        (
            Box::new(|g| g.replace("alpha = 0.5", "alpha = nan")),
            "material.alpha",
        ),
        (
            Box::new(|g| g.replace("alpha = 0.5", "alpha = 0")),
            "material.alpha",
        ),
        (
            Box::new(|g| g.replace("alpha = 0.5", "alpha = 1e-30")),
            "material.alpha",
        ),
        (
            Box::new(|g| g.replace("intensity = 1.0", "intensity = -1.0")),
            "lights[0]",
        ),
        (
            Box::new(|g| g.replace("half_size = 2.0", "half_size = 2.0\nsize = 3")),
            "unknown field",
        ),
        (Box::new(|g| g.replace("[camera]", "[camera")), "line"),
        (
            Box::new(|g| {
                g.lines()
                    .filter(|l| !l.starts_with("fov_y_degrees"))
                    .collect::<Vec<_>>()
                    .join("\n")
            }),
            "fov_y_degrees",
        ),
        // Extra array elements were dropped without a word: a fourth colour channel, a
        // five-element position, a three-element [min, max].
        (
            Box::new(|g| {
                g.replace(
                    "base_color = [0.8, 0.8, 0.8]",
                    "base_color = [0.8,0.8,0.8,0.1]",
                )
            }),
            "exactly 3",
        ),
        (
            Box::new(|g| {
                g.replace(
                    "position = [0.0, -3.4, 2.8]",
                    "position = [0.0, -3.4, 2.8, 1.0, 2.0]",
                )
            }),
            "exactly 3",
        ),
        (
            Box::new(|g| g.replace("base_color = [0.8, 0.8, 0.8]", "base_color = [0.8, 0.8]")),
            "exactly 3",
        ),
        (
            Box::new(|g| {
                format!(
                    "{g}\n[random_lights]\ncount = 3\nseed = 1\nheight = [0.1, 1.0, 7.0]\nintensity = [1.0, 2.0]\n"
                )
            }),
            "exactly 2",
        ),
        // Values whose images could not be finite (NaN positions, f32 overflow).
        (
            Box::new(|g| {
                format!(
                    "{g}\n[random_lights]\ncount = 3\nseed = 1\nheight = [-1e308, 1e308]\nintensity = [1.0, 2.0]\n"
                )
            }),
            "random_lights.height",
        ),
        (
            Box::new(|g| g.replace("intensity = 1.0", "intensity = 1e300")),
            "lights[0]",
        ),
        (
            Box::new(|g| g.replace("position = [0.0, 0.0, 1.0]", "position = [0.0, 0.0, 1e300]")),
            "lights[0].position",
        ),
        // A camera below the one-sided plane sees nothing (and the GPU saw negative light).
        (
            Box::new(|g| {
                g.replace(
                    "position = [0.0, -3.4, 2.8]",
                    "position = [0.0, -3.4, -2.8]",
                )
            }),
            "camera.position",
        ),
    ];
    for (k, (edit, what)) in cases.into_iter().enumerate() {
        let scene = edited_scene(dir.path(), &format!("bad{k}.toml"), edit);
        let o = render_cpu(&scene, &out);
        assert_refused(&o, what);
        assert_refused(&o, &format!("bad{k}.toml"));
        assert!(!out.exists(), "a partial output was left behind");
    }
    let lut = corrupt_lut(dir.path());
    let o = ltc_lab(&[
        "render",
        "--cpu",
        "--scene",
        &preset("figure2-normal.toml"),
        "--method",
        "ltc",
        "--size",
        "8x8",
        "--out",
        out.to_str().unwrap(),
        "--lut",
        lut.to_str().unwrap(),
    ]);
    assert_refused(&o, "corrupt.exr");
    assert!(!out.exists());
    for (args, what) in [
        (vec!["--size", "0x8"], "0x8"),
        (vec!["--size", "big"], "big"),
        (vec!["--divider", "1.5"], "--divider"),
        (vec!["--out", "/tmp/x.bmp"], "/tmp/x.bmp"),
        (
            vec!["--out", "/nonexistent-dir/x.png"],
            "/nonexistent-dir/x.png",
        ),
        (vec!["--clip", "some"], "some"),
    ] {
        let scene = preset("figure2-normal.toml");
        let mut all = vec!["render", "--cpu", "--scene", &scene, "--method", "ltc"];
        all.extend(args);
        let o = ltc_lab(&all);
        assert_eq!(o.status.code(), Some(2), "{all:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(what), "{all:?}: {}", stderr(&o));
    }
    assert!(!Path::new("/tmp/x.bmp").exists());
    let o = ltc_lab(&[
        "render",
        "--cpu",
        "--scene",
        &preset("figure2-normal.toml"),
        "--method",
        "ltc-slow",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("ltc-slow"), "{}", stderr(&o));
}

/// With no --out, `<scene>-<method>.png` is taken only if free; else the next free
/// `-2`, `-3`… Two runs at once each get their own file.
#[test]
fn a_default_output_name_never_replaces_a_file() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "render",
        "--cpu",
        "--scene",
        &preset("figure2-normal.toml"),
        "--method",
        "ltc",
        "--size",
        "8x8",
    ];
    std::fs::write(dir.path().join("figure2-normal-ltc.png"), b"mine").unwrap();
    let o = ltc_lab_in(dir.path(), &args);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("figure2-normal-ltc-2.png"),
        "{}",
        stderr(&o)
    );
    assert_eq!(
        std::fs::read(dir.path().join("figure2-normal-ltc.png")).unwrap(),
        b"mine"
    );
    let runs: Vec<_> = (0..2)
        .map(|_| exe().current_dir(dir.path()).args(args).spawn().unwrap())
        .collect();
    for mut r in runs {
        assert!(r.wait().unwrap().success());
    }
    for name in [
        "figure2-normal-ltc-2.png",
        "figure2-normal-ltc-3.png",
        "figure2-normal-ltc-4.png",
    ] {
        assert_eq!(
            image::open(dir.path().join(name)).unwrap().width(),
            8,
            "{name}"
        );
    }
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

/// An image beyond what the adapter holds (seen: a panic on wgpu's 2 GiB buffer limit) is
/// refused before any work, naming the limit.
#[test]
fn an_image_too_large_for_the_gpu_is_refused_naming_the_limit() {
    let Some(g) = gpu() else { return };
    let max_side = g.ctx.limits.max_texture_dimension_2d as usize;
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("big.png");
    let size = if max_side < 16384 {
        format!("{}x8", max_side + 1)
    } else {
        "16384x16384".into()
    };
    let o = ltc_lab(&[
        "render",
        "--scene",
        &preset("paper-100.toml"),
        "--method",
        "ltc",
        "--size",
        &size,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_refused(&o, "--size");
    assert!(
        stderr(&o).contains("max_buffer_size") || stderr(&o).contains("max_texture_dimension_2d"),
        "{}",
        stderr(&o)
    );
    assert!(!out.exists());
}

/// A valid table too large for one storage binding (seen: a panic on
/// `max_storage_buffer_binding_size` with a 2048² table) is refused naming the limit.
#[test]
fn a_table_too_large_for_the_gpu_is_refused_naming_the_limit() {
    let Some(g) = gpu() else { return };
    let limit = g
        .ctx
        .limits
        .max_storage_buffer_binding_size
        .min(g.ctx.limits.max_buffer_size);
    // 48 bytes per cell on the GPU (three vec4<f32>, src/gpu/ltc.rs).
    let n = ((limit / 48) as f64).sqrt() as usize + 1;
    if n > 2048 {
        crate::gpu_common::skipped(&format!(
            "a table beyond this adapter's {limit}-byte storage binding has {n}² cells, too large to write in a test"
        ));
        return;
    }
    let cell = ltc_lab::ltc::lut::Lut::embedded().cells[0];
    let big = ltc_lab::ltc::lut::Lut {
        nl_terms: Default::default(),
        size: n,
        alpha_min: 1e-4,
        cells: vec![cell; n * n],
    };
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("big.exr");
    big.write(&path).unwrap();
    let out = dir.path().join("out.png");
    let o = ltc_lab(&[
        "render",
        "--scene",
        &preset("paper-100.toml"),
        "--method",
        "ltc",
        "--size",
        "8x8",
        "--lut",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_refused(&o, "max_storage_buffer_binding_size");
    assert!(!out.exists());
}

/// No adapter at all (wgpu asked for a backend this build lacks): exit 1, the machine's
/// failure, with a hint; never a panic.
#[test]
fn no_adapter_is_the_machine_failing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("x.png");
    let o = exe()
        .env("WGPU_BACKEND", "metal")
        .args([
            "render",
            "--scene",
            &preset("paper-100.toml"),
            "--method",
            "ltc",
            "--size",
            "8x8",
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    let err = stderr(&o);
    assert_no_panic(o.status.code(), &err);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("no adapter") && err.contains("--cpu"), "{err}");
    assert!(!out.exists());
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

/// A refused scene says so in a line a person reads: `plane.half_size = 0` printed f64's
/// smallest positive number in full (a 417-character message).
#[test]
fn a_refused_scene_prints_numbers_as_people_write_them() {
    let dir = tempfile::tempdir().unwrap();
    let scene = edited_scene(dir.path(), "flat.toml", |t| {
        t.lines()
            .map(|l| {
                if l.starts_with("half_size") {
                    "half_size = 0.0"
                } else {
                    l
                }
            })
            .collect::<Vec<_>>()
            .join("\n")
    });
    let o = ltc_lab(&[
        "render",
        "--cpu",
        "--scene",
        scene.to_str().unwrap(),
        "--method",
        "ltc",
        "--out",
        dir.path().join("x.png").to_str().unwrap(),
    ]);
    assert_refused(&o, "plane.half_size must be in (0, ");
    assert!(stderr(&o).len() < 160, "{}", stderr(&o));
}

/// Spawns a default-named CPU render of `scene` in `dir`, its stderr piped.
fn spawn_default_render(dir: &Path, scene: &Path) -> std::process::Child {
    exe()
        .current_dir(dir)
        .args([
            "render", "--cpu", "--method", "ltc", "--size", "8x8", "--scene",
        ])
        .arg(scene)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap()
}

/// A FIFO for a scene: a render reading it waits until the test writes the scene, which
/// holds the render at a known point without any timing.
fn scene_fifo(dir: &Path, name: &str) -> std::path::PathBuf {
    let fifo = dir.join(name);
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap();
    assert!(made.success());
    fifo
}

/// The default name is taken when the render starts, before it reads its scene (it was
/// taken only when the image was written): while the render waits on a FIFO for its scene,
/// its empty claim is there and a second render of that name writes `-2`. Filled, the
/// claim is the image the render reports.
#[test]
fn a_default_render_claims_its_name_at_the_start() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = scene_fifo(dir.path(), "held.toml");
    let claimed = dir.path().join("held-ltc.png");
    let mut first = spawn_default_render(dir.path(), &fifo);
    crate::study::wait_until(&mut first, "held-ltc.png claimed", || claimed.exists());
    // Another scene of the same name, which does not wait.
    std::fs::create_dir(dir.path().join("other")).unwrap();
    let same_name = dir.path().join("other/held.toml");
    std::fs::copy(preset("figure2-normal.toml"), &same_name).unwrap();
    let second = spawn_default_render(dir.path(), &same_name)
        .wait_with_output()
        .unwrap();
    // The scene is given before anything is asserted, so that a failure leaves no render
    // waiting for ever.
    std::fs::write(&fifo, std::fs::read(preset("figure2-normal.toml")).unwrap()).unwrap();
    let first = first.wait_with_output().unwrap();
    for (o, name) in [(&second, "held-ltc-2.png"), (&first, "held-ltc.png")] {
        assert!(o.status.success(), "{}", stderr(o));
        assert!(
            stderr(o).contains(&format!("wrote {name}")),
            "{}",
            stderr(o)
        );
    }
    for name in ["held-ltc.png", "held-ltc-2.png"] {
        assert_eq!(
            image::open(dir.path().join(name)).unwrap().width(),
            8,
            "{name}"
        );
    }
}

/// A claim that is never filled goes again: on a refused scene, and on SIGTERM (exit 130
/// through the handler) while the render waits for its scene.
#[test]
fn an_unfilled_default_name_is_removed() {
    let dir = tempfile::tempdir().unwrap();
    let bad = edited_scene(dir.path(), "bad.toml", |g| {
        g.replace("alpha = 0.5", "alpha = 0")
    });
    let o = spawn_default_render(dir.path(), &bad)
        .wait_with_output()
        .unwrap();
    assert_refused(&o, "bad.toml");
    assert!(!dir.path().join("bad-ltc.png").exists(), "the claim stayed");
    let fifo = scene_fifo(dir.path(), "held.toml");
    let claimed = dir.path().join("held-ltc.png");
    let mut child = spawn_default_render(dir.path(), &fifo);
    crate::study::wait_until(&mut child, "held-ltc.png claimed", || claimed.exists());
    crate::study::terminate(&child);
    let status = crate::study::wait_for_exit(&mut child);
    let o = child.wait_with_output().unwrap();
    assert_eq!(status.code(), Some(130), "{}", stderr(&o));
    assert!(stderr(&o).contains("interrupted"), "{}", stderr(&o));
    assert!(!claimed.exists(), "the interrupted render left its claim");
}

/// Where `XDG_RUNTIME_DIR` is not set (a container, an SSH session, `env -i`), no driver
/// chatter comes ahead of the program's own message: Mesa's device-select layer made
/// libwayland print "error: XDG_RUNTIME_DIR is invalid or not set in the environment." twice
/// before every GPU command's output, and a refusal was three lines instead of one.
#[test]
fn no_driver_chatter_without_a_runtime_directory() {
    let Some(g) = gpu() else { return };
    // Beyond the GPU's limits but not --size's (as in the test above).
    let max_side = g.ctx.limits.max_texture_dimension_2d as usize;
    let size = if max_side < 16384 {
        format!("{}x8", max_side + 1)
    } else {
        "16384x16384".into()
    };
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("x.png");
    let o = exe()
        .env_remove("XDG_RUNTIME_DIR")
        .args([
            "render",
            "--scene",
            &preset("figure2-normal.toml"),
            "--method",
            "ltc",
            "--size",
            &size,
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert_refused(&o, "--size");
    let ok = exe()
        .env_remove("XDG_RUNTIME_DIR")
        .args([
            "render",
            "--scene",
            &preset("figure2-normal.toml"),
            "--method",
            "ltc",
            "--size",
            "8x8",
            "--out",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(ok.status.success(), "{}", stderr(&ok));
    assert!(
        stderr(&ok).starts_with("rendered "),
        "something came first: {}",
        stderr(&ok)
    );
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
            sphere_a: ltc_lab::sphere_light::SphereMethod::from_name(sphere).unwrap(),
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
