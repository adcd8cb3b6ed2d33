//! `ltc-lab study`: its two files land together, in a directory made for them, and a default
//! directory never replaces an earlier study.

use ltc_lab::gpu::renderer::PlaneRenderer;

use crate::gpu_common::gpu;
use crate::{assert_refused, ltc_lab, ltc_lab_in, stderr};

/// A small study: its horizon.csv from the 20,000 cases a band that the lab's elevation
/// chart draws (app::clipping::elevation::CASES), against the default million; what the
/// tests read of it (the lowest band over twice the highest's error, 0 under exact-band) is
/// a margin far wider than 20,000 cases' spread, and the draw is seeded.
const SMALL: [&str; 10] = [
    "--size",
    "24x16",
    "--lights",
    "8",
    "--alpha",
    "0.27",
    "--frames",
    "1",
    "--horizon-cases",
    "20000",
];

/// The same study of one variant beside the reference, for the tests of where its files go
/// (each variant is a pipeline to compile, and the fitted tables' variants a fit).
const FEW: [&str; 2] = ["--variants", "ltc"];

#[test]
fn study_writes_every_variant_and_the_pareto_chart() {
    if gpu().is_none() {
        return;
    }
    let root = tempfile::tempdir().unwrap();
    let dir = root.path().join("made/for/it");
    let mut args = vec!["study", "--out", dir.to_str().unwrap()];
    args.extend(SMALL);
    let o = ltc_lab(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let rows = ltc_lab::measure::study::read_csv(&dir.join("study.csv")).unwrap();
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
    if gpu().unwrap().ctx.has_f16() {
        expected.extend(["ltc-f16", "ltc-f16-pairs"]);
    }
    // Every horizon remedy on ltc-fast, by default.
    expected.extend([
        "ltc-fast-arrival-fit",
        "ltc-fast-constrained-fit",
        "ltc-fast-nl-fit",
        "ltc-fast-exact-band",
    ]);
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
    let png = image::open(dir.join("study.png")).unwrap().to_rgb8();
    assert!(
        png.width() >= 800 && png.pixels().filter(|p| p.0 != [255, 255, 255]).count() > 10_000,
        "blank chart"
    );
    // The error by light elevation of its table under each remedy and of the point fit,
    // four bands each; the lowest the worst under eq30, exact under exact-band.
    let (rows, k) = crate::horizon_rows(&dir);
    assert_eq!(rows.len(), 6 * 4, "{rows:?}");
    let named: Vec<(&str, &str)> = rows
        .chunks(4)
        .map(|t| (t[0][0].as_str(), t[0][1].as_str()))
        .collect();
    assert_eq!(
        named,
        [
            ("classic", "eq30"),
            ("arrival", "arrival-fit"),
            ("constrained", "constrained-fit"),
            ("classic", "nl-fit"),
            ("classic", "exact-band"),
            ("point", "eq30"),
        ]
    );
    for table in [&rows[0..4], &rows[20..24]] {
        let low_worse = crate::specular(&table[0], k) > 2.0 * crate::specular(&table[3], k);
        assert!(low_worse, "{rows:?}");
    }
    assert_eq!(
        crate::specular(&rows[16], k),
        0.0,
        "exact-band's 0–5°: {rows:?}"
    );
}

/// With `--rect-half-edge`, `--disk-radius` and `--size-for tube=R` every light is also a
/// rect, then a disk, then a tube, by each of the shape's methods against the shape's own
/// exact image: its `exact` variant is the reference (error 0), the others differ from it, and
/// the point limit by far the most on rects this close to the plane (the lights sit 0.05–0.6
/// above it, the rects 0.1 wide). Each shape's failure preset (rect-horizon, disk-limits,
/// tube-limits) is studied beside them, as given;
/// `--encodings` adds a variant per encoding of the table, shaded as `ltc`.
#[test]
fn study_measures_each_sized_method_against_its_exact_image() {
    if gpu().is_none() {
        return;
    }
    let root = tempfile::tempdir().unwrap();
    let dir = root.path().join("sized");
    let mut args = vec!["study", "--out", dir.to_str().unwrap(), "--horizon", "eq30"];
    args.extend(SMALL);
    args.extend(["--rect-half-edge", "0.05", "--disk-radius", "0.05"]);
    args.extend(["--size-for", "tube=0.02"]);
    args.extend(["--encodings", "f32,unorm8-8"]);
    args.extend(FEW);
    let o = ltc_lab(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let rows = ltc_lab::measure::study::read_csv(&dir.join("study.csv")).unwrap();
    let sized: Vec<&str> = rows
        .iter()
        .map(|r| r.variant.as_str())
        .filter(|v| ["rect-", "disk-", "tube-"].iter().any(|s| v.starts_with(s)))
        .filter(|v| !v.contains('@'))
        .collect();
    assert_eq!(
        sized,
        [
            "rect-exact",
            "rect-ltc-polygon",
            "rect-ltc-proxy",
            "rect-ltc-proxy-fast",
            "rect-ltc-point",
            "disk-exact",
            "disk-ltc-disk",
            "disk-ltc-point",
            "tube-exact",
            "tube-ltc-line",
            "tube-hdrp-tube",
            "tube-representative-point",
            "tube-ltc-point",
        ]
    );
    let err = |v: &str| rows.iter().find(|r| r.variant == v).unwrap().rel_rmse;
    assert_eq!(err("rect-exact"), 0.0);
    assert_eq!(err("disk-exact"), 0.0);
    assert_eq!(err("tube-exact"), 0.0);
    for v in sized.iter().filter(|v| !v.ends_with("-exact")) {
        assert!(err(v).is_finite() && err(v) > 0.0, "{v}: {}", err(v));
    }
    assert!(err("rect-ltc-point") > 2.0 * err("rect-ltc-polygon"));
    // Each encoding of the table shaded as ltc is, in the same run: f32 is the table itself
    // (the same image, the same error to the bit), an 8² 8-bit table another image.
    assert_eq!(err("ltc-table-f32").to_bits(), err("ltc").to_bits());
    let byte = err("ltc-table-unorm8-8");
    assert!(byte.is_finite() && byte != err("ltc"), "{byte}");
    // The chart, reading the study, plots each encoding as a point of the ltc form.
    let chart = ltc_lab::app::chart::measure::Measurement::from_study(&rows, "study.csv");
    let point = chart
        .points
        .iter()
        .find(|p| p.label == "ltc-table-unorm8-8");
    assert_eq!(point.unwrap().method, Some(ltc_lab::render::Method::Ltc));
    assert!(err("disk-ltc-point") > 2.0 * err("disk-ltc-disk"));
    // The failure presets, each against its own exact image.
    for (preset, methods) in [
        (
            "rect-horizon",
            &[
                "rect-ltc-polygon",
                "rect-ltc-proxy",
                "rect-ltc-proxy-fast",
                "rect-ltc-point",
            ][..],
        ),
        ("disk-limits", &["disk-ltc-disk", "disk-ltc-point"][..]),
        (
            "tube-limits",
            &[
                "tube-ltc-line",
                "tube-hdrp-tube",
                "tube-representative-point",
                "tube-ltc-point",
            ][..],
        ),
    ] {
        assert_eq!(err(&format!("exact@{preset}")), 0.0);
        for m in methods {
            let e = err(&format!("{m}@{preset}"));
            assert!(e.is_finite() && e > 0.0, "{m}@{preset}: {e}");
        }
    }
}

#[test]
fn study_refuses_bad_arguments() {
    for (args, what) in [
        (vec!["--alpha", "0"], "--alpha"),
        (vec!["--alpha", "1.5"], "--alpha"),
        // Below the scene's α_min, as everywhere else (1e-100 was taken).
        (vec!["--alpha", "1e-100"], "got 1e-100"),
        (vec!["--lights", "0"], "--lights"),
        (vec!["--frames", "0"], "--frames"),
        (vec!["--frames", "10000000000"], "--frames"),
        (vec!["--rect-half-edge", "0"], "--rect-half-edge"),
        (vec!["--disk-radius", "nan"], "--disk-radius"),
        (vec!["--horizon-cases", "0"], "--horizon-cases"),
        (vec!["--horizon-cases", "1000000000"], "--horizon-cases"),
        // A name study.csv never holds, named with the ones it does.
        (
            vec!["--variants", "ltc,ltc-slow"],
            "no variant \"ltc-slow\"; the variants: brdf, brdf-fast",
        ),
    ] {
        let mut all = vec!["study", "--out", "/tmp/never-study"];
        all.extend(args);
        assert_refused(&ltc_lab(&all), what);
    }
    assert!(!std::path::Path::new("/tmp/never-study").exists());
}

/// `study --out s` where `s/study.png` is a directory: refused before anything is measured
/// or written; the earlier `s/study.csv` is untouched.
#[test]
fn study_writes_both_files_or_neither() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("study.csv"), "the earlier study").unwrap();
    std::fs::create_dir(dir.path().join("study.png")).unwrap();
    let mut args = vec!["study", "--out", dir.path().to_str().unwrap()];
    args.extend(SMALL);
    args.extend(FEW);
    assert_refused(&ltc_lab(&args), "study.png");
    assert_eq!(
        std::fs::read_to_string(dir.path().join("study.csv")).unwrap(),
        "the earlier study"
    );
}

/// More lights than the adapter shades: refused, and the directory made for the study is
/// gone again.
#[test]
fn a_refused_study_leaves_no_directory() {
    let Some(g) = gpu() else { return };
    if PlaneRenderer::max_lights(&g.ctx) >= ltc_lab::scene::MAX_LIGHTS {
        crate::gpu_common::skipped("this adapter shades every light count a scene may hold");
        return;
    }
    let too_many = (PlaneRenderer::max_lights(&g.ctx) + 1).to_string();
    let root = tempfile::tempdir().unwrap();
    let dir = root.path().join("s");
    let o = ltc_lab(&[
        "study",
        "--out",
        dir.to_str().unwrap(),
        "--size",
        "8x8",
        "--lights",
        &too_many,
        "--frames",
        "1",
    ]);
    assert_refused(&o, "--lights");
    assert!(!dir.exists(), "an empty directory was left");
}

/// With no --out, an earlier `study/` is kept and the new one goes to `study-2/`.
#[test]
fn a_default_study_directory_never_replaces_an_earlier_study() {
    if gpu().is_none() {
        return;
    }
    let cwd = tempfile::tempdir().unwrap();
    std::fs::create_dir(cwd.path().join("study")).unwrap();
    std::fs::write(cwd.path().join("study/study.csv"), "the earlier study").unwrap();
    let mut args = vec!["study"];
    args.extend(SMALL);
    args.extend(FEW);
    let o = ltc_lab_in(cwd.path(), &args);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(
        std::fs::read_to_string(cwd.path().join("study/study.csv")).unwrap(),
        "the earlier study"
    );
    assert!(
        cwd.path().join("study-2/study.png").exists(),
        "{}",
        stderr(&o)
    );
    // --variants ran the one asked for beside the reference, no other.
    let rows = ltc_lab::measure::study::read_csv(&cwd.path().join("study-2/study.csv")).unwrap();
    let names: Vec<&str> = rows.iter().map(|r| r.variant.as_str()).collect();
    assert_eq!(names, ["brdf", "ltc"]);
}

/// Sends SIGTERM (a `kill` does what a service manager or a closed terminal does).
pub fn terminate(child: &std::process::Child) {
    let sent = std::process::Command::new("kill")
        .args(["-TERM", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(sent.success(), "kill failed");
}

/// Waits until `reached` holds while `child` runs. The deadline only ends a test whose
/// child never gets there (it is far beyond what a start takes on any machine); past it, or
/// if the child ends first, the child is killed and the test fails saying `what`.
pub fn wait_until(child: &mut std::process::Child, what: &str, reached: impl Fn() -> bool) {
    use std::time::{Duration, Instant};
    let start = Instant::now();
    while !reached() {
        let ended = child.try_wait().unwrap();
        if ended.is_some() || start.elapsed() > Duration::from_secs(120) {
            let _ = child.kill();
            panic!("never saw {what} while it ran (ended: {ended:?})");
        }
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// The exit status of a child that was told to end; one that is still running after a
/// deadline far beyond any clean-up is killed, and the test fails.
pub fn wait_for_exit(child: &mut std::process::Child) -> std::process::ExitStatus {
    use std::time::{Duration, Instant};
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            return status;
        }
        if start.elapsed() > Duration::from_secs(120) {
            let _ = child.kill();
            panic!("still running after it was told to end");
        }
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// The directory a finished study says it wrote into.
fn reported_dir(err: &str) -> String {
    let (_, rest) = err.split_once("; wrote ").expect("no 'wrote' line");
    rest.split_once("/study.csv")
        .expect("no study.csv")
        .0
        .to_string()
}

/// Two studies at once without --out: each takes its own directory when it starts, so
/// neither result is lost; both hold both files.
#[test]
fn two_default_studies_at_once_get_two_directories() {
    use std::collections::BTreeSet;
    use std::process::{Child, Stdio};
    if gpu().is_none() {
        return;
    }
    let cwd = tempfile::tempdir().unwrap();
    let args = [
        "study",
        "--size",
        "32x18",
        "--lights",
        "10",
        "--alpha",
        "0.5",
        "--frames",
        "1",
        "--horizon-cases",
        "2000",
        "--variants",
        "ltc-fast",
    ];
    let runs: Vec<Child> = (0..2)
        .map(|_| {
            crate::exe()
                .current_dir(cwd.path())
                .args(args)
                .stdout(Stdio::null())
                .stderr(Stdio::piped())
                .spawn()
                .unwrap()
        })
        .collect();
    let mut dirs = BTreeSet::new();
    for r in runs {
        let o = r.wait_with_output().unwrap();
        assert!(o.status.success(), "{}", stderr(&o));
        dirs.insert(reported_dir(&stderr(&o)));
    }
    assert_eq!(dirs, BTreeSet::from(["study".into(), "study-2".into()]));
    for d in &dirs {
        let dir = cwd.path().join(d);
        assert!(
            !ltc_lab::measure::study::read_csv(&dir.join("study.csv"))
                .unwrap()
                .is_empty()
        );
        image::open(dir.join("study.png")).unwrap();
        assert_eq!(
            std::fs::read_dir(&dir).unwrap().count(),
            3,
            "{d}: extra files"
        );
    }
}

/// SIGTERM during `study --out d` removes the directory it made (a signal skips Drop, which
/// left `d` empty) and exits 130 through the handler, not by the signal. The workload is one
/// a fast GPU needs seconds for (and lavapipe minutes): the signal, sent as soon as the
/// study says it started, lands during the work.
#[test]
fn an_interrupted_study_leaves_nothing_behind() {
    use std::io::{BufRead, BufReader, Read};
    use std::process::Stdio;
    if gpu().is_none() {
        return;
    }
    let root = tempfile::tempdir().unwrap();
    let dir = root.path().join("d");
    let mut child = crate::exe()
        .args(["study", "--out", dir.to_str().unwrap()])
        .args(["--size", "640x360", "--lights", "1000", "--frames", "1000"])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut err = BufReader::new(child.stderr.take().unwrap());
    let mut seen = String::new();
    while !seen.contains("study on") {
        let mut line = String::new();
        let read = err.read_line(&mut line).unwrap();
        assert_ne!(read, 0, "the study ended before it started: {seen}");
        seen.push_str(&line);
    }
    assert!(dir.is_dir(), "the study works without its directory?");
    terminate(&child);
    let status = wait_for_exit(&mut child);
    err.read_to_string(&mut seen).unwrap();
    assert_eq!(status.code(), Some(130), "{status:?}: {seen}");
    assert!(seen.contains("interrupted"), "{seen}");
    assert!(!dir.exists(), "the interrupted study left its directory");
    assert!(
        std::fs::read_dir(root.path()).unwrap().next().is_none(),
        "temporary files left"
    );
}
