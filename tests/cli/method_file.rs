//! A method file from anyone, through the command line (docs/design.md §5.13–§5.14): a FIFO
//! is refused at once, a feature the device lacks and an array past its bound are refused at
//! their line, and a file that spends its whole loop budget on every light of a 65 536-light
//! scene renders in many submissions, or stops naming itself and how far it got.

use std::path::Path;
use std::time::{Duration, Instant};

use crate::gpu_common::gpu;
use crate::{assert_no_panic, assert_refused, ltc_lab, preset, stderr};

const SIGNATURE: &str = "fn method_point(pixel: MethodPixel, light: MethodPoint) -> MethodRadiance";

fn write_file(dir: &Path, name: &str, body: &str) -> String {
    let path = dir.join(name);
    std::fs::write(
        &path,
        format!("{SIGNATURE} {{\n{body}\n    return MethodRadiance(vec3<f32>(0.0), vec3<f32>(0.0));\n}}\n"),
    )
    .unwrap();
    path.to_str().unwrap().to_string()
}

fn render_file(file: &str, out: &Path) -> std::process::Output {
    ltc_lab(&[
        "render",
        "--scene",
        &preset("figure2-normal.toml"),
        "--method",
        "file",
        "--method-file",
        file,
        "--size",
        "32x32",
        "--out",
        out.to_str().unwrap(),
    ])
}

/// A FIFO in place of a method file or a scene is refused at once, naming it, instead of
/// waiting for a writer for ever.
#[cfg(unix)]
#[test]
fn a_fifo_is_refused_at_once() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("mine.wgsl");
    nix::unistd::mkfifo(&fifo, nix::sys::stat::Mode::S_IRWXU).unwrap();
    let fifo = fifo.to_str().unwrap();
    let start = Instant::now();
    let out = dir.path().join("out.png");
    for args in [
        vec![
            "render",
            "--scene",
            fifo,
            "--method",
            "ltc",
            "--cpu",
            "--out",
            out.to_str().unwrap(),
        ],
        vec![
            "bench",
            "--method-file",
            fifo,
            "--lights",
            "1",
            "--size",
            "16x16",
        ],
        vec!["lab", "--method-file", fifo],
    ] {
        let o = ltc_lab(&args);
        assert_refused(&o, fifo);
        assert!(stderr(&o).contains("FIFO"), "{args:?}: {}", stderr(&o));
    }
    assert!(start.elapsed() < Duration::from_secs(60));
    assert!(!out.exists());
}

/// `f64` reads as WGSL but the device was not asked for SHADER_F64: refused at its line, by
/// name, exit 2. An array past its bound likewise, before any device.
#[test]
fn what_the_device_lacks_and_arrays_past_their_bound_are_refused_at_their_line() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.png");
    let huge = write_file(
        dir.path(),
        "huge.wgsl",
        "    var a: array<f32, 100000000>;\n    a[0] = 1.0;",
    );
    let o = render_file(&huge, &out);
    assert_refused(&o, "huge.wgsl");
    assert!(stderr(&o).contains("line 2"), "{}", stderr(&o));
    if gpu().is_none() {
        return;
    }
    let f64_file = write_file(dir.path(), "f64.wgsl", "    let x: f64 = 1.0lf;");
    let o = render_file(&f64_file, &out);
    let err = stderr(&o);
    assert_no_panic(o.status.code(), &err);
    // After the file's work line (`render` says it before the device opens).
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("line 2"), "{err}");
    assert!(
        err.contains("`f64` needs SHADER_F64, which this device does not have"),
        "{err}"
    );
    assert!(!out.exists());
}

/// Every light of a 65 536-light scene spending the file's whole budget (16 384 steps, not
/// one past it): many submissions, each under the bound, then the image; or, where one
/// submission takes past 2 s (a slow device), exit 2 naming the file and how far it got. One
/// pixel shades, so the test stays short on a CPU driver.
#[test]
fn a_file_at_its_worst_on_65536_lights_renders_in_many_submissions() {
    if gpu().is_none() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let file = write_file(
        dir.path(),
        "worst.wgsl",
        "    var x = 0.0;\n    for (var i = 0u; i < 16384u; i++) { x += 1e-9; }\n    if x < 0.0 { return MethodRadiance(vec3<f32>(x), vec3<f32>(0.0)); }",
    );
    let o = render_many(dir.path(), &file, 65_536);
    let err = stderr(&o);
    assert_no_panic(o.status.code(), &err);
    // llvmpipe ends a shader's loops past 65 024 lights: refused by name before any work
    // (docs/design.md §5.10); the same file then on as many lights as it takes.
    let o = if err.contains("do not fit in one shader invocation") {
        assert_eq!(o.status.code(), Some(2), "{err}");
        render_many(dir.path(), &file, 65_024)
    } else {
        o
    };
    let err = stderr(&o);
    let submissions = err
        .split_whitespace()
        .skip_while(|w| *w != "render:")
        .nth(1)
        .and_then(|n| n.parse::<usize>().ok());
    match o.status.code() {
        Some(0) => {
            assert!(submissions.is_some_and(|n| n > 10), "{err}");
            assert!(dir.path().join("out.exr").exists());
        }
        Some(2) => {
            assert!(
                err.contains("worst.wgsl") && err.contains("stopped after"),
                "{err}"
            );
        }
        code => panic!("exit {code:?}: {err}"),
    }
}

/// `render` of `file` on `count` unranged lights of paper-100 at one pixel.
fn render_many(dir: &Path, file: &str, count: usize) -> std::process::Output {
    let scene = std::fs::read_to_string(preset("paper-100.toml"))
        .unwrap()
        .replace("count = 100", &format!("count = {count}"))
        .replace("range = 2.0\n", "");
    let scene_path = dir.join("many.toml");
    std::fs::write(&scene_path, scene).unwrap();
    let out = dir.join("out.exr");
    let _ = std::fs::remove_file(&out);
    ltc_lab(&[
        "render",
        "--scene",
        scene_path.to_str().unwrap(),
        "--method",
        "file",
        "--method-file",
        file,
        "--size",
        "1x1",
        "--out",
        out.to_str().unwrap(),
    ])
}
