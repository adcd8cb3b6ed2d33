//! `ltc-lab lut`: the summary, the dump, the atlas, and tables no fit could have made.

use ltc_lab::ltc::lut::{Channel, Lut};

use crate::{assert_no_panic, assert_refused, corrupt_lut, first_line_then_close, ltc_lab, stderr};

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

/// `lut --dump | head -1` (800 KB of output into a closed pipe): quiet success.
#[test]
fn lut_dump_ends_quietly_on_a_closed_pipe() {
    let (line, status, err) = first_line_then_close(&["lut", "--dump"]);
    assert!(line.starts_with("i,j,alpha"), "{line}");
    assert_no_panic(status.code(), &err);
    assert!(status.success() && err.is_empty(), "{status}: {err}");
}

#[test]
fn lut_refuses_a_corrupt_file() {
    let dir = tempfile::tempdir().unwrap();
    let lut = corrupt_lut(dir.path());
    assert_refused(
        &ltc_lab(&["lut", "--dump", "--lut", lut.to_str().unwrap()]),
        "corrupt.exr",
    );
}

/// Finite but absurd values (seen passing before: the GPU then wrote −3.4e38 and `eval`
/// gave negative radiance) are refused with the channel, the cell and the accepted range.
#[test]
fn lut_refuses_values_no_fit_produces() {
    let dir = tempfile::tempdir().unwrap();
    for (k, (edits, what)) in [
        (
            vec![(Channel::SpecM00, 3e38f32), (Channel::SpecM22, 3e38)],
            "spec.m00",
        ),
        (vec![(Channel::SpecNorm, 3e38)], "spec.norm"),
        (vec![(Channel::SpecFresnel, -5.0)], "spec.fresnel"),
        (vec![(Channel::DiffNorm, 0.0)], "diff.norm"),
        (vec![(Channel::SpecErr, -0.1)], "spec.err"),
    ]
    .into_iter()
    .enumerate()
    {
        let mut lut = Lut::embedded().clone();
        for (c, x) in edits {
            lut.cells[100].0[c as usize] = x;
        }
        let path = dir.path().join(format!("absurd{k}.exr"));
        std::fs::write(&path, lut.to_exr_bytes()).unwrap();
        let o = ltc_lab(&["lut", "--lut", path.to_str().unwrap()]);
        assert_refused(&o, what);
        assert_refused(&o, &format!("absurd{k}.exr"));
        assert!(stderr(&o).contains("(i=36, j=1)"), "{}", stderr(&o));
    }
}

#[test]
fn atlas_writes_heat_maps_and_csvs_into_a_new_directory() {
    let root = tempfile::tempdir().unwrap();
    // `lut --atlas DIR` makes DIR (and its parents) if it is missing.
    let dir = root.path().join("new/atlas");
    let o = ltc_lab(&["lut", "--atlas", dir.to_str().unwrap()]);
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
        let img = image::open(dir.join(f)).unwrap().to_rgb8();
        assert!(
            img.pixels().filter(|p| p.0 != [255, 255, 255]).count() > 50_000,
            "{f} is blank"
        );
    }
    let cells = std::fs::read_to_string(dir.join("cells.csv")).unwrap();
    assert_eq!(cells.lines().count(), 1 + 64 * 64);
    let orbits = std::fs::read_to_string(dir.join("orbits.csv")).unwrap();
    assert_eq!(orbits.lines().count(), 1 + 4 * 91 * 91);
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 8, "stray files");
}

/// A failure leaves nothing behind: not the files written before it, not a directory made
/// for them.
#[test]
fn atlas_writes_all_its_files_or_none() {
    let root = tempfile::tempdir().unwrap();
    let dir = root.path().join("atlas");
    std::fs::create_dir(&dir).unwrap();
    std::fs::create_dir(dir.join("orbits.csv")).unwrap();
    let o = ltc_lab(&["lut", "--atlas", dir.to_str().unwrap()]);
    assert_refused(&o, "orbits.csv");
    assert_eq!(
        std::fs::read_dir(&dir).unwrap().count(),
        1,
        "files left behind"
    );
    // Under a file, the directory cannot be made: refused, nothing made.
    let file = root.path().join("plain");
    std::fs::write(&file, "x").unwrap();
    let o = ltc_lab(&["lut", "--atlas", file.join("atlas").to_str().unwrap()]);
    assert_refused(&o, "plain");
}

/// `lut --export`: each format written where asked, with its header; ltc_code's DDS pair at
/// the sizes ltc_code's own files have (128-byte header + 64² texels of 8 or 16 bytes).
#[test]
fn lut_exports_every_format() {
    let dir = tempfile::tempdir().unwrap();
    let js = dir.path().join("ltc.js");
    let o = ltc_lab(&[
        "lut",
        "--table",
        "point",
        "--export",
        "ltc-code-js",
        "--out",
        js.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&js).unwrap();
    assert!(
        text.contains("fit objective: the point-light fit"),
        "no header"
    );
    assert!(text.contains("var g_ltc_1 = [") && text.contains("var g_ltc_2 = ["));
    for (precision, bytes) in [("f16", 128 + 64 * 64 * 8), ("f32", 128 + 64 * 64 * 16)] {
        let out = dir.path().join(precision);
        let o = ltc_lab(&[
            "lut",
            "--export",
            "ltc-code-dds",
            "--precision",
            precision,
            "--out",
            out.to_str().unwrap(),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        for f in ["ltc_1.dds", "ltc_2.dds"] {
            assert_eq!(std::fs::metadata(out.join(f)).unwrap().len(), bytes);
        }
        assert!(
            std::fs::read_to_string(out.join("ltc_dds.txt"))
                .unwrap()
                .contains("alpha_min")
        );
    }
    let header = dir.path().join("ltc.h");
    let o = ltc_lab(&["lut", "--export", "c", "--out", header.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    compiles_as_c(&header);
    let wgsl = dir.path().join("ltc.wgsl");
    let o = ltc_lab(&["lut", "--export", "wgsl", "--out", wgsl.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        std::fs::read_to_string(&wgsl)
            .unwrap()
            .contains("fn ltc_lookup(")
    );
    // --export needs --out, and the format must be one of the four.
    assert_eq!(ltc_lab(&["lut", "--export", "c"]).status.code(), Some(2));
    assert_eq!(
        ltc_lab(&["lut", "--export", "png", "--out", "/tmp/x"])
            .status
            .code(),
        Some(2)
    );
}

/// The C header compiles (where the machine has a C compiler: `cc`, as Debian's gcc).
fn compiles_as_c(header: &std::path::Path) {
    let dir = header.parent().unwrap();
    let main = dir.join("main.c");
    std::fs::write(
        &main,
        "#include \"ltc.h\"\nint main(void) { return g_ltc_1[3] > 0.0f && g_ltc_2[4 * LTC_LUT_SIZE] >= 0.0f ? 0 : 1; }\n",
    )
    .unwrap();
    match std::process::Command::new("cc")
        .args(["-std=c99", "-Wall", "-Werror", "-fsyntax-only"])
        .arg(&main)
        .output()
    {
        Ok(o) => assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr)),
        Err(e) => crate::gpu_common::skipped(&format!(
            "the C header is not compiled: no C compiler ({e})"
        )),
    }
}

/// A table in ltc_code's layout is used as its own and says what it lacks: the note names
/// the embedded diffuse lobe; a file that is not a table is refused.
#[test]
fn lut_reads_ltc_codes_layouts_and_says_what_they_lack() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("pair");
    let o = ltc_lab(&[
        "lut",
        "--export",
        "ltc-code-dds",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    for given in [out.clone(), out.join("ltc_1.dds"), out.join("ltc_2.dds")] {
        let o = ltc_lab(&["lut", "--lut", given.to_str().unwrap()]);
        assert!(o.status.success(), "{}", stderr(&o));
        assert!(
            stderr(&o).contains("the diffuse lobe is the embedded classic table's"),
            "{}",
            stderr(&o)
        );
        assert!(String::from_utf8_lossy(&o.stdout).contains("64×64"));
    }
    let bad = dir.path().join("square.js");
    std::fs::write(
        &bad,
        "var g_ltc_1 = [1, 0, 0, 1];\nvar g_ltc_2 = [1, 0, 0, 1];\n",
    )
    .unwrap();
    assert_refused(
        &ltc_lab(&["lut", "--lut", bad.to_str().unwrap()]),
        "square.js",
    );
}
