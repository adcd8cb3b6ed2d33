//! The command line: every subcommand on good input, and on a corrupt LUT, a malformed
//! scene and a bad CSV row — one line on stderr naming the input, exit 2, no output file.

mod gpu_common;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use ltc_lab::brdf::{brdf_cos, view_from_theta};
use ltc_lab::ltc::lut::Lut;

fn ltc_lab(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ltc-lab"))
        .args(args)
        .output()
        .unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Exit code 2 and exactly one line on stderr that names `what`.
fn assert_refused(o: &Output, what: &str) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(2), "stderr: {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "not one line: {err}");
    assert!(err.contains(what), "'{what}' not named in: {err}");
    assert!(
        o.stdout.is_empty(),
        "partial stdout: {}",
        String::from_utf8_lossy(&o.stdout)
    );
}

fn preset(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("assets/scenes")
        .join(name)
        .display()
        .to_string()
}

fn corrupt_lut(dir: &Path) -> PathBuf {
    let bytes = std::fs::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("luts/ltc.exr")).unwrap();
    let p = dir.join("corrupt.exr");
    std::fs::write(&p, &bytes[..bytes.len() / 3]).unwrap();
    p
}

#[test]
fn fit_writes_a_readable_table() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("small.exr");
    let o = ltc_lab(&["fit", "--size", "4", "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("spec.err"),
        "no summary: {}",
        stderr(&o)
    );
    assert_eq!(Lut::read(&out).unwrap().size, 4);
}

#[test]
fn fit_refuses_bad_arguments() {
    assert_refused(
        &ltc_lab(&["fit", "--size", "1", "--out", "/tmp/never.exr"]),
        "--size",
    );
    let o = ltc_lab(&["fit", "--size", "2", "--out", "/nonexistent-dir/x.exr"]);
    assert_refused(&o, "/nonexistent-dir/x.exr");
}

const CASES: &str = "theta_o,alpha,lx,ly,lz,f0\n\
    0,0.27,0,0,1,0.04\n\
    60,0.5,-0.6,0.2,0.7745966692414834,1\n\
    89,0.01,0.3,0.1,-0.9486832980505138,0\n";

#[test]
fn eval_prints_one_row_per_case() {
    let dir = tempfile::tempdir().unwrap();
    let cases = dir.path().join("cases.csv");
    std::fs::write(&cases, CASES).unwrap();
    let o = ltc_lab(&["eval", "--cases", cases.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(
        text.lines().next().unwrap(),
        "theta_o,alpha,lx,ly,lz,f0,brdf_spec,brdf_diffuse,ltc_spec,ltc_diffuse"
    );
    assert_eq!(rows.len(), 3);
    for r in &rows {
        let v = view_from_theta(r[0].to_radians());
        let b = brdf_cos(v, [r[2], r[3], r[4]], r[1], r[5]);
        assert!((r[6] - b.specular).abs() <= 1e-12 * b.specular.abs().max(1.0));
        assert!((r[7] - b.diffuse).abs() <= 1e-12);
        assert!(r[8] >= 0.0 && r[9] >= 0.0);
    }
    // The light below the horizon: zero both ways (eq. 30's clipping).
    assert_eq!(&rows[2][6..], &[0.0; 4]);
    // At normal view on a rough surface the LTC is within the pointwise error of the table.
    assert!((rows[0][9] - rows[0][7]).abs() < 0.05 * rows[0][7]);
}

#[test]
fn eval_refuses_bad_rows_naming_the_line() {
    let dir = tempfile::tempdir().unwrap();
    let cases = dir.path().join("bad.csv");
    for (row, what) in [
        ("0,0.27,0,0,1", "line 3"),
        ("0,nan,0,0,1,0.04", "line 3"),
        ("0,0,0,0,1,0.04", "alpha"),
        ("0,-0.5,0,0,1,0.04", "alpha"),
        ("95,0.3,0,0,1,0.04", "theta_o"),
        ("0,0.3,0,0,2,0.04", "unit length"),
        ("0,0.3,0,zero,1,0.04", "'zero'"),
    ] {
        std::fs::write(
            &cases,
            format!("theta_o,alpha,lx,ly,lz,f0\n0,0.3,0,0,1,0.04\n{row}\n"),
        )
        .unwrap();
        let o = ltc_lab(&["eval", "--cases", cases.to_str().unwrap()]);
        assert_refused(&o, what);
        assert_refused(&o, "bad.csv");
    }
    std::fs::write(&cases, "a,b\n").unwrap();
    assert_refused(
        &ltc_lab(&["eval", "--cases", cases.to_str().unwrap()]),
        "header",
    );
    assert_refused(
        &ltc_lab(&["eval", "--cases", "/nonexistent.csv"]),
        "/nonexistent.csv",
    );
}

#[test]
fn eval_and_lut_refuse_a_corrupt_lut() {
    let dir = tempfile::tempdir().unwrap();
    let lut = corrupt_lut(dir.path());
    let cases = dir.path().join("cases.csv");
    std::fs::write(&cases, CASES).unwrap();
    assert_refused(
        &ltc_lab(&[
            "eval",
            "--cases",
            cases.to_str().unwrap(),
            "--lut",
            lut.to_str().unwrap(),
        ]),
        "corrupt.exr",
    );
    assert_refused(
        &ltc_lab(&["lut", "--dump", "--lut", lut.to_str().unwrap()]),
        "corrupt.exr",
    );
}

#[test]
fn lut_dump_lists_every_cell() {
    let o = ltc_lab(&["lut", "--dump"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    assert!(header.starts_with("i,j,alpha,theta_o,spec.m00,spec.m02,spec.m20,spec.m22,spec.norm"));
    assert_eq!(
        header.split(',').count(),
        4 + ltc_lab::ltc::lut::CHANNEL_COUNT
    );
    assert_eq!(lines.clone().count(), 64 * 64);
    let last: Vec<f64> = lines
        .last()
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    assert_eq!((last[0], last[1], last[2]), (63.0, 63.0, 1.0));
    let summary = ltc_lab(&["lut"]);
    assert!(String::from_utf8_lossy(&summary.stdout).contains("64×64"));
}

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

#[test]
fn render_refuses_malformed_scenes_and_leaves_no_file() {
    let dir = tempfile::tempdir().unwrap();
    let good = std::fs::read_to_string(preset("figure2-normal.toml")).unwrap();
    let out = dir.path().join("out.png");
    for (k, (text, what)) in [
        (good.replace("alpha = 0.5", "alpha = nan"), "material.alpha"),
        (good.replace("alpha = 0.5", "alpha = 0"), "material.alpha"),
        (
            good.replace("intensity = 1.0", "intensity = -1.0"),
            "lights[0]",
        ),
        (
            good.replace("half_size = 2.0", "half_size = 2.0\nsize = 3"),
            "unknown field",
        ),
        (good.replace("[camera]", "[camera"), "line"),
        (
            good.lines()
                .filter(|l| !l.starts_with("fov_y_degrees"))
                .collect::<Vec<_>>()
                .join("\n"),
            "fov_y_degrees",
        ),
    ]
    .into_iter()
    .enumerate()
    {
        assert_ne!(text, good, "case {k} does not change the preset");
        let scene = dir.path().join(format!("bad{k}.toml"));
        std::fs::write(&scene, text).unwrap();
        let o = ltc_lab(&[
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
        ]);
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
    ] {
        let scene = preset("figure2-normal.toml");
        let mut all = vec!["render", "--cpu", "--scene", &scene, "--method", "ltc"];
        all.extend(args);
        let o = ltc_lab(&all);
        assert_eq!(o.status.code(), Some(2), "{all:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(what), "{all:?}: {}", stderr(&o));
    }
    assert!(!Path::new("/tmp/x.bmp").exists());
}

#[test]
fn render_on_the_gpu_by_default() {
    if gpu_common::gpu().is_none() {
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

#[test]
fn bench_prints_the_table_and_writes_the_csv() {
    if gpu_common::gpu().is_none() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("bench.csv");
    let o = ltc_lab(&[
        "bench",
        "--lights",
        "10,20",
        "--size",
        "32x16",
        "--frames",
        "2",
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let table = String::from_utf8(o.stdout).unwrap();
    assert!(table.contains("| ltc-fast | 20 | 32×16 |"), "{table}");
    assert!(table.contains("ltc-fast / brdf"), "{table}");
    assert!(
        table.contains("| 5000 | 2 | 5 |"),
        "the paper's figures: {table}"
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "method,lights,width,height,frames,ms_median,ms_min,ms_max,fps,glightpx_per_s"
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 8, "4 methods × 2 light counts");
    for r in &rows {
        assert_eq!(r.len(), 10);
        let (median, min, max): (f64, f64, f64) = (
            r[5].parse().unwrap(),
            r[6].parse().unwrap(),
            r[7].parse().unwrap(),
        );
        assert!(min > 0.0 && min <= median && median <= max, "{r:?}");
        // fps and G light-px/s follow from the median.
        let fps: f64 = r[8].parse().unwrap();
        assert!((fps - 1e3 / median).abs() <= 1e-3 * fps + 1e-3, "{r:?}");
    }
}

#[test]
fn bench_refuses_bad_arguments() {
    assert_refused(&ltc_lab(&["bench", "--frames", "0"]), "--frames");
    assert_refused(&ltc_lab(&["bench", "--lights", "0"]), "--lights");
    assert_refused(
        &ltc_lab(&["bench", "--csv", "/nonexistent-dir/b.csv"]),
        "/nonexistent-dir/b.csv",
    );
}

#[test]
fn study_writes_every_variant_and_the_pareto_chart() {
    if gpu_common::gpu().is_none() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let o = ltc_lab(&[
        "study",
        "--out",
        dir.path().to_str().unwrap(),
        "--size",
        "24x16",
        "--lights",
        "8",
        "--alpha",
        "0.27",
        "--frames",
        "1",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let rows = ltc_lab::study::read_csv(&dir.path().join("study.csv")).unwrap();
    let names: Vec<&str> = rows.iter().map(|r| r.variant.as_str()).collect();
    let mut expected = vec![
        "brdf",
        "brdf-fast",
        "ltc",
        "ltc-fast",
        "ltc-paper",
        "ltc-nearest",
        "ltc-lut16",
        "ltc-lut32",
        "ltc-point",
        "ltc-fast-point",
    ];
    if gpu_common::gpu().unwrap().ctx.has_f16() {
        expected.push("ltc-f16");
    }
    assert_eq!(names, expected);
    for r in &rows {
        assert!(
            r.ms_median > 0.0 && (r.lights, r.width, r.height) == (8, 24, 16),
            "{r:?}"
        );
    }
    // The reference is the exact image itself; every LTC variant differs from it, the
    // paper-literal one by far the most (it drops 1/π and the magnitudes).
    assert_eq!(rows[0].rel_rmse, 0.0);
    let err = |v: &str| rows.iter().find(|r| r.variant == v).unwrap().rel_rmse;
    assert!(err("ltc") > 0.0 && err("ltc-paper") > 10.0 * err("ltc"));
    // ltc and ltc-fast are the same approximation: the same error to f32 rounding.
    assert!((err("ltc") - err("ltc-fast")).abs() <= 1e-3 * err("ltc"));
    let png = image::open(dir.path().join("study.png")).unwrap().to_rgb8();
    assert!(
        png.width() >= 800 && png.pixels().filter(|p| p.0 != [255, 255, 255]).count() > 10_000,
        "blank chart"
    );
}

#[test]
fn study_refuses_bad_arguments() {
    for (args, what) in [
        (vec!["--alpha", "0"], "--alpha"),
        (vec!["--alpha", "1.5"], "--alpha"),
        (vec!["--lights", "0"], "--lights"),
        (vec!["--frames", "0"], "--frames"),
    ] {
        let mut all = vec!["study", "--out", "/tmp/never-study"];
        all.extend(args);
        assert_refused(&ltc_lab(&all), what);
    }
}

#[test]
fn atlas_writes_heat_maps_and_csvs() {
    let dir = tempfile::tempdir().unwrap();
    let o = ltc_lab(&["lut", "--atlas", dir.path().to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let summary = String::from_utf8(o.stdout).unwrap();
    assert!(
        summary.contains("specular θo") && summary.contains("orbit θo = 70°"),
        "{summary}"
    );
    for f in [
        "spec_err.png",
        "diff_err.png",
        "orbit_20_0.1.png",
        "orbit_45_0.27.png",
        "orbit_70_0.27.png",
        "orbit_85_0.5.png",
    ] {
        let img = image::open(dir.path().join(f)).unwrap().to_rgb8();
        assert!(
            img.pixels().filter(|p| p.0 != [255, 255, 255]).count() > 50_000,
            "{f} is blank"
        );
    }
    let cells = std::fs::read_to_string(dir.path().join("cells.csv")).unwrap();
    assert_eq!(cells.lines().count(), 1 + 64 * 64);
    let orbits = std::fs::read_to_string(dir.path().join("orbits.csv")).unwrap();
    assert_eq!(orbits.lines().count(), 1 + 4 * 91 * 91);
    assert_refused(
        &ltc_lab(&["lut", "--atlas", "/nonexistent-atlas-dir"]),
        "/nonexistent-atlas-dir",
    );
}
