//! The command line, one file per subcommand: every subcommand on good input, and on each bad
//! input seen so far — one line on stderr naming the input, exit code 2, no output file, no
//! panic; a closed pipe ends quietly; a machine failure exits 1.

#[path = "../common/mod.rs"]
mod common;
#[path = "../gpu_common/mod.rs"]
mod gpu_common;

mod bench;
mod encoding;
mod eval;
mod fit;
mod lab;
mod lut;
mod method_file;
mod render;
mod render_names;
mod render_refusals;
mod study;
mod study_scene;

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Command, ExitStatus, Output, Stdio};

pub fn exe() -> Command {
    Command::new(env!("CARGO_BIN_EXE_ltc-lab"))
}

pub fn ltc_lab(args: &[&str]) -> Output {
    exe().args(args).output().unwrap()
}

/// Runs in `dir` (for default output names, which are relative to the working directory).
pub fn ltc_lab_in(dir: &Path, args: &[&str]) -> Output {
    exe().current_dir(dir).args(args).output().unwrap()
}

pub fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// No panic reached the user (a panic prints "panicked at" and exits 101).
pub fn assert_no_panic(code: Option<i32>, err: &str) {
    assert!(!err.contains("panicked"), "a panic: {err}");
    assert_ne!(code, Some(101), "a panic: {err}");
}

/// Exit code 2 and exactly one line on stderr that names `what`.
pub fn assert_refused(o: &Output, what: &str) {
    let err = stderr(o);
    assert_no_panic(o.status.code(), &err);
    assert_eq!(o.status.code(), Some(2), "stderr: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "not one line: {err}");
    assert!(err.contains(what), "'{what}' not named in: {err}");
    assert!(
        o.stdout.is_empty(),
        "partial stdout: {}",
        String::from_utf8_lossy(&o.stdout)
    );
}

pub fn preset(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("assets/scenes")
        .join(name)
        .display()
        .to_string()
}

pub fn corrupt_lut(dir: &Path) -> PathBuf {
    let bytes = std::fs::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("luts/ltc.exr")).unwrap();
    let p = dir.join("corrupt.exr");
    std::fs::write(&p, &bytes[..bytes.len() / 3]).unwrap();
    p
}

/// Reads the first line of the command's output, then closes the pipe (as `| head -1` does)
/// and waits: the exit status and stderr.
pub fn first_line_then_close(args: &[&str]) -> (String, ExitStatus, String) {
    let mut child = exe()
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut line = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut line)
        .unwrap();
    // The reader is dropped: the pipe is closed with most of the output unread.
    let out = child.wait_with_output().unwrap();
    (
        line,
        out.status,
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Runs with standard output on `/dev/full`, where every write fails with "no space left".
pub fn into_dev_full(args: &[&str]) -> Output {
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    exe().args(args).stdout(full).output().unwrap()
}

/// A scene file in `dir`: the figure2-normal preset with `edit` applied.
pub fn edited_scene(dir: &Path, name: &str, edit: impl Fn(&str) -> String) -> PathBuf {
    let good = std::fs::read_to_string(preset("figure2-normal.toml")).unwrap();
    let text = edit(&good);
    assert_ne!(text, good, "{name}: the edit changes nothing");
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// The f32 RGB pixels of an EXR written by `render`.
pub fn exr_pixels(path: &Path) -> Vec<[f32; 3]> {
    use exr::prelude::*;
    let image = read_first_rgba_layer_from_file(
        path,
        |size, _| {
            (
                size.width(),
                vec![[0.0f32; 3]; size.width() * size.height()],
            )
        },
        |(w, pixels): &mut (usize, Vec<[f32; 3]>), pos, (r, g, b, _): (f32, f32, f32, f32)| {
            pixels[pos.y() * *w + pos.x()] = [r, g, b];
        },
    )
    .unwrap();
    image.layer_data.channel_data.pixels.1
}

/// The rows of a `horizon.csv` in `dir` (header dropped), each as its fields, with the index
/// of its `specular` column.
pub fn horizon_rows(dir: &Path) -> (Vec<Vec<String>>, usize) {
    let text = std::fs::read_to_string(dir.join("horizon.csv")).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let specular = header.iter().position(|&c| c == "specular").unwrap();
    let rows = lines
        .map(|l| l.split(',').map(String::from).collect())
        .collect();
    (rows, specular)
}

/// The `specular` error of a `horizon.csv` row.
pub fn specular(row: &[String], column: usize) -> f64 {
    row[column].parse().unwrap()
}
