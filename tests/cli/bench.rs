//! `ltc-lab bench`.

use std::process::Stdio;

use ltc_lab::gpu::renderer::PlaneRenderer;

use crate::gpu_common::gpu;
use crate::{assert_no_panic, assert_refused, exe, ltc_lab, stderr};

#[test]
fn bench_prints_the_table_and_writes_the_csv() {
    if gpu().is_none() {
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
        "--horizon",
        "exact-band",
        "--sphere-radius",
        "0.05",
        "--rect-half-edge",
        "0.04",
        "--size-for",
        "tube=0.03",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let table = String::from_utf8(o.stdout).unwrap();
    assert!(
        table.contains("| ltc-fast | 20 | 32×16 | on | 2 |"),
        "{table}"
    );
    // Each f32 LTC form again with the remedy, and its time over eq30's.
    assert!(
        table.contains("| ltc-fast (exact-band) | 20 | 32×16 | on | 2 |"),
        "{table}"
    );
    assert!(table.contains("| method | exact-band |"), "{table}");
    assert!(table.contains("ltc-fast / brdf"), "{table}");
    assert!(
        table.contains("| 5000 | 2 | 5 |"),
        "the paper's figures: {table}"
    );
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "method,horizon,lights,width,height,frames,cull,range,in_range_fraction,ms_median,ms_min,ms_max,bin_ms,fps,glightpx_per_s,shape,shape_method,size,alpha_y"
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    // Every method with eq30, ltc and ltc-fast with exact-band too, the four sphere methods
    // on lights of radius 0.05, the five rect methods on rects of half-edge 0.04 and the five
    // tube methods on tubes of radius 0.03 (`--size-for`, beside its aliases).
    let methods = if gpu().unwrap().ctx.has_f16() { 6 } else { 4 } + 2 + 4 + 5 + 5;
    assert_eq!(rows.len(), 2 * methods, "every method × 2 light counts");
    let sized = |shape: &str| -> Vec<(&str, &str)> {
        rows.iter()
            .filter(|r| r[15] == shape)
            .map(|r| (r[16], r[17]))
            .collect()
    };
    let spheres = sized("sphere");
    assert_eq!(spheres.len(), 8, "{spheres:?}");
    assert!(spheres.iter().all(|&(_, r)| r == "0.05"), "{spheres:?}");
    let rects = sized("rect");
    assert_eq!(rects.len(), 10, "{rects:?}");
    assert!(rects.iter().all(|&(_, h)| h == "0.04"), "{rects:?}");
    assert!(rects.iter().any(|&(m, _)| m == "ltc-polygon"), "{rects:?}");
    let tubes = sized("tube");
    assert_eq!(tubes.len(), 10, "{tubes:?}");
    assert!(tubes.iter().all(|&(_, r)| r == "0.03"), "{tubes:?}");
    assert!(tubes.iter().any(|&(m, _)| m == "ltc-line"), "{tubes:?}");
    assert!(
        table.contains("| rect ltc-polygon (h = 0.04) | 20 | 32×16 | on | 2 |"),
        "{table}"
    );
    assert!(
        table.contains("| lights | cull | exact | ltc-polygon | ltc-proxy | ltc-proxy-fast | ltc-point | ltc-polygon / ltc-point |"),
        "{table}"
    );
    assert!(
        table.contains("| ltc-disk (r = 0.05) | 20 | 32×16 | on | 2 |"),
        "{table}"
    );
    assert!(
        table.contains("| lights | cull | exact | ltc-point | ltc-disk | representative-point | ltc-disk / ltc-point |"),
        "{table}"
    );
    let remedies = rows.iter().filter(|r| r[1] == "exact-band").count();
    assert_eq!(remedies, 4, "ltc and ltc-fast × 2 light counts");
    for r in &rows {
        assert_eq!(r.len(), 19);
        assert_eq!((r[6], r[7]), ("on", "2"), "{r:?}");
        let fraction: f64 = r[8].parse().unwrap();
        assert!(fraction > 0.0 && fraction <= 1.0, "{r:?}");
        let (median, min, max): (f64, f64, f64) = (
            r[9].parse().unwrap(),
            r[10].parse().unwrap(),
            r[11].parse().unwrap(),
        );
        assert!(min > 0.0 && min <= median && median <= max, "{r:?}");
        // fps and G light-px/s follow from the median.
        let fps: f64 = r[13].parse().unwrap();
        assert!((fps - 1e3 / median).abs() <= 1e-3 * fps + 1e-3, "{r:?}");
    }
}

#[test]
fn bench_refuses_bad_arguments() {
    assert_refused(&ltc_lab(&["bench", "--frames", "0"]), "--frames");
    assert_refused(&ltc_lab(&["bench", "--lights", "0"]), "--lights");
    for r in ["0", "-1", "1e-5", "nan", "1e7"] {
        let flag = format!("--sphere-radius={r}");
        assert_refused(&ltc_lab(&["bench", &flag]), "--sphere-radius");
        let flag = format!("--rect-half-edge={r}");
        assert_refused(&ltc_lab(&["bench", &flag]), "--rect-half-edge");
    }
    // `--size-for SHAPE=SIZE`: a shape with a size, a size as its aliases take, one per shape.
    for bad in [
        "tube=0",
        "tube=nan",
        "tube=1e7",
        "tube=wide",
        "tube",
        "cone=0.1",
        "point=0.1",
    ] {
        assert_refused(&ltc_lab(&["bench", "--size-for", bad]), "--size-for");
    }
    assert_refused(
        &ltc_lab(&[
            "bench",
            "--size-for",
            "sphere=0.1",
            "--sphere-radius",
            "0.2",
        ]),
        "--sphere-radius",
    );
    for y in ["0", "2", "nan"] {
        let flag = format!("--alpha-y={y}");
        assert_refused(&ltc_lab(&["bench", &flag]), "--alpha-y");
    }
    assert_refused(
        &ltc_lab(&["bench", "--csv", "/nonexistent-dir/b.csv"]),
        "/nonexistent-dir/b.csv",
    );
}

/// `--alpha-y`: every run again with the material anisotropic, right after it isotropic, in
/// the CSV's last column, and the table's ratio of the two.
#[test]
fn bench_times_an_anisotropic_material_beside_the_isotropic_one() {
    if gpu().is_none() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("bench.csv");
    let o = ltc_lab(&[
        "bench",
        "--lights",
        "4",
        "--size",
        "16x8",
        "--frames",
        "1",
        "--alpha-y",
        "0.05",
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let table = String::from_utf8(o.stdout).unwrap();
    assert!(
        table.contains("Anisotropic material (α_y = 0.05"),
        "{table}"
    );
    assert!(table.contains("| ltc-fast | 4 | on |"), "{table}");
    let text = std::fs::read_to_string(&csv).unwrap();
    let rows: Vec<Vec<&str>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    let brushed = rows.iter().filter(|r| r[18] == "0.05").count();
    let round = rows.iter().filter(|r| r[18].is_empty()).count();
    assert!(brushed > 0 && brushed == round, "{text}");
}

/// Every light count is checked before the first is measured, and the message says which
/// argument does not fit (not a "scene" the user never gave).
#[test]
fn bench_checks_every_light_count_first() {
    let Some(g) = gpu() else { return };
    let too_many = (PlaneRenderer::max_lights(&g.ctx) + 1).to_string();
    if PlaneRenderer::max_lights(&g.ctx) >= ltc_lab::scene::MAX_LIGHTS {
        crate::gpu_common::skipped("this adapter shades every light count a scene may hold");
        return;
    }
    let o = ltc_lab(&[
        "bench",
        "--lights",
        &format!("10,{too_many}"),
        "--size",
        "8x8",
        "--frames",
        "1",
    ]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("--lights") && err.contains("do not fit"),
        "{err}"
    );
    assert!(
        !err.contains("10 lights:"),
        "measured before refusing: {err}"
    );
    assert!(o.stdout.is_empty());
}

/// `bench … | true`: the reader is gone before the table is printed; bench ends quietly,
/// its CSV written.
#[test]
fn bench_ends_quietly_when_nobody_reads() {
    if gpu().is_none() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("b.csv");
    let mut child = exe()
        .args(["bench", "--lights", "4", "--size", "8x8", "--frames", "1"])
        .args(["--csv", csv.to_str().unwrap()])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_no_panic(out.status.code(), &err);
    assert!(out.status.success(), "{err}");
    assert!(csv.exists());
}

/// `--cull off,on` measures both in one run, `--range` sets every light's range, and the
/// in-range fraction falls with the range (the lights are the same).
#[test]
fn bench_measures_culled_and_unculled_with_a_range() {
    if gpu().is_none() {
        return;
    }
    let run = |range: &str| {
        let o = ltc_lab(&[
            "bench", "--lights", "64", "--size", "32x32", "--frames", "1", "--cull", "off,on",
            "--range", range,
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        String::from_utf8(o.stdout).unwrap()
    };
    let (short, long) = (run("0.3"), run("inf"));
    assert!(
        short.contains("| ltc-fast | 64 | 32×32 | off | 0.3 |"),
        "{short}"
    );
    assert!(
        short.contains("| ltc-fast | 64 | 32×32 | on | 0.3 |"),
        "{short}"
    );
    assert!(
        short.contains("Culling (unculled ms / culled ms"),
        "{short}"
    );
    assert!(
        long.contains("| brdf | 64 | 32×32 | on | inf | 100.0% |"),
        "{long}"
    );
    assert_eq!(ltc_lab(&["bench", "--range", "0"]).status.code(), Some(2));
    assert_eq!(
        ltc_lab(&["bench", "--cull", "maybe"]).status.code(),
        Some(2)
    );
}

/// Every count has a stated maximum, checked before any work: 10¹⁰ frames once aborted
/// allocating 240 GB, and 10⁹ ran for ever. Refused without an adapter too (the check comes
/// first).
#[test]
fn bench_refuses_more_frames_than_its_maximum() {
    for frames in ["10000000000", "1000000000", "10001"] {
        let o = ltc_lab(&["bench", "--frames", frames]);
        assert_refused(&o, "--frames");
        assert!(stderr(&o).contains("1..=10000"), "{}", stderr(&o));
    }
}
