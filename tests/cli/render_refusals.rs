//! `ltc-lab render` refusing what it cannot do, before any work and in a line a person
//! reads: malformed scenes, images and tables beyond the GPU's limits, no adapter at all,
//! and no driver chatter ahead of the message.

use std::path::Path;

use crate::gpu_common::gpu;
use crate::{
    assert_no_panic, assert_refused, corrupt_lut, edited_scene, exe, ltc_lab, preset, stderr,
};

use crate::render::render_cpu;

/// A change to a preset's text.
type Edit = Box<dyn Fn(&str) -> String>;

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
        aniso: None,
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
