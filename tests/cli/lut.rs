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
        4 + ltc_lab::ltc::lut::Channel::COUNT
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
    // The error by light elevation: four bands under each of the five remedies; under eq30
    // the lowest far worse than the highest.
    let (rows, k) = crate::horizon_rows(&dir);
    assert_eq!(rows.len(), 5 * 4, "{rows:?}");
    let low_worse = crate::specular(&rows[0], k) > 2.0 * crate::specular(&rows[3], k);
    assert!(
        rows[0][0] == "eq30" && rows[0][1] == "0-5" && low_worse,
        "{rows:?}"
    );
    assert!(summary.contains("0–5° 5–15° 15–30° 30–90°"), "{summary}");
    assert!(summary.contains("exact-band"), "{summary}");
    // Lights with a size: each approximation per angular radius and band, and the chart.
    let spheres = std::fs::read_to_string(dir.join("spheres.csv")).unwrap();
    let rows: Vec<Vec<&str>> = spheres
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(rows.len(), 7 * 4 * 3, "radii × bands × methods");
    let error = |radius: &str, band: &str, method: &str| -> f64 {
        let r = rows
            .iter()
            .find(|r| r[0] == radius && r[1] == band && r[3] == method);
        r.unwrap_or_else(|| panic!("{radius} {band} {method}"))[4]
            .parse()
            .unwrap()
    };
    // A 30° sphere high above the surface: the disk far better than the point formula
    // (docs/design.md §4.9: 11% against 39% at 40 000 cases).
    assert!(error("30", "30-90", "ltc-disk") < 0.5 * error("30", "30-90", "ltc-point"));
    // The representative point is exact for a point light.
    assert!(error("0", "30-90", "representative-point") < 1e-9);
    let chart = image::open(dir.join("spheres.png")).unwrap().to_rgb8();
    assert!(
        chart.pixels().filter(|p| p.0 != [255, 255, 255]).count() > 20_000,
        "blank chart"
    );
    assert!(summary.contains("spheres σ = 10°"), "{summary}");
    // Rects and disks: each method per solid angle and band, and the chart.
    let shapes = std::fs::read_to_string(dir.join("shapes.csv")).unwrap();
    let rows: Vec<Vec<&str>> = shapes
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(rows.len(), 4 * 4 * (4 + 2), "sizes × bands × methods");
    let error = |size: &str, band: &str, shape: &str, method: &str| -> f64 {
        let r = rows
            .iter()
            .find(|r| r[0] == size && r[1] == band && r[3] == shape && r[4] == method);
        r.unwrap_or_else(|| panic!("{size} {band} {shape} {method}"))[5]
            .parse()
            .unwrap()
    };
    // 1 sr high above the surface: the polygon and the LTC disk far better than their point
    // limits (docs/design.md §1.11, §1.12: 11% and 12% against 76% and 59% at 300 cases);
    // small, every rect method is the table's own error, the same within a percent.
    assert!(
        error("1", "30..90", "rect", "ltc-polygon")
            < 0.5 * error("1", "30..90", "rect", "ltc-point")
    );
    assert!(
        error("1", "30..90", "disk", "ltc-disk") < 0.5 * error("1", "30..90", "disk", "ltc-point")
    );
    let small = |m| error("0.001", "30..90", "rect", m);
    assert!((small("ltc-proxy") - small("ltc-polygon")).abs() < 0.01);
    let chart = image::open(dir.join("shapes.png")).unwrap().to_rgb8();
    assert!(
        chart.pixels().filter(|p| p.0 != [255, 255, 255]).count() > 20_000,
        "blank chart"
    );
    assert!(summary.contains("rects and disks of 0.1 sr"), "{summary}");
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 13, "stray files");
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

/// `lut --export aniso-texture`: the 4D table's three volumes (8⁴ nodes × 3 RGBA32F texels)
/// and its lookup, into a directory made for them; the same bytes from a second run (the
/// files named by --out are the user's to replace).
#[test]
fn lut_exports_the_4d_table_as_textures() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("aniso");
    let args = [
        "lut",
        "--export",
        "aniso-texture",
        "--out",
        out.to_str().unwrap(),
    ];
    let o = ltc_lab(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let bytes = std::fs::read(out.join("ltc_aniso.bin")).unwrap();
    assert_eq!(bytes.len(), 3 * 8 * 8 * 8 * 8 * 16);
    assert!(stderr(&o).contains("196608 bytes"), "{}", stderr(&o));
    let wgsl = std::fs::read_to_string(out.join("ltc_aniso.wgsl")).unwrap();
    assert!(wgsl.contains("fn aniso_ltc(") && wgsl.contains("the lab's 4D table"));
    let again = ltc_lab(&args);
    assert!(again.status.success(), "{}", stderr(&again));
    assert_eq!(std::fs::read(out.join("ltc_aniso.bin")).unwrap(), bytes);
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

/// One DDS texture whose header claims `side × side` texels of `fourcc` (113 = RGBA16F,
/// 116 = RGBA32F) over a 32 KiB body of zeros.
fn dds_claiming(side: u32, fourcc: u32) -> Vec<u8> {
    let mut header = [0u32; 31];
    header[0] = 124;
    header[1] = 0x100F;
    header[2] = side;
    header[3] = side;
    header[5] = 1;
    header[6] = 1;
    header[18] = 32;
    header[19] = 0x4; // DDPF_FOURCC
    header[20] = fourcc;
    header[26] = 0x1000;
    let mut bytes = b"DDS ".to_vec();
    bytes.extend(header.iter().flat_map(|w| w.to_le_bytes()));
    bytes.resize(bytes.len() + 32 * 1024, 0);
    bytes
}

/// A DDS pair claiming 2^30×2^30 RGBA32F or 2^31×2^31 RGBA16F over 32 KiB (whose byte count
/// wrapped to 0 and then panicked) is refused before any allocation, naming the file and the
/// limit, with its sidecar header and without.
#[test]
fn lut_refuses_dds_textures_that_claim_more_than_the_limit() {
    let dir = tempfile::tempdir().unwrap();
    for (side, fourcc) in [(1u32 << 30, 116u32), (1 << 31, 113), (4097, 116)] {
        for sidecar in [true, false] {
            let pair = dir.path().join(format!("{side}-{fourcc}-{sidecar}"));
            std::fs::create_dir(&pair).unwrap();
            for f in ["ltc_1.dds", "ltc_2.dds"] {
                std::fs::write(pair.join(f), dds_claiming(side, fourcc)).unwrap();
            }
            if sidecar {
                std::fs::write(pair.join("ltc_dds.txt"), "alpha_min: 1e-4\n").unwrap();
            }
            let first = pair.join("ltc_1.dds");
            let o = ltc_lab(&["lut", "--lut", first.to_str().unwrap()]);
            assert_refused(&o, first.to_str().unwrap());
            assert!(stderr(&o).contains("at most 4096×4096"), "{}", stderr(&o));
        }
    }
}

/// `bytes` (an EXR) with its data window rewritten to `(0, 0)–(last, last)`.
fn exr_claiming(bytes: &[u8], last: i32) -> Vec<u8> {
    let key = b"dataWindow\0box2i\0";
    let at = bytes
        .windows(key.len())
        .position(|w| w == key)
        .expect("an EXR header has a data window")
        + key.len()
        + 4; // the attribute's size
    let mut out = bytes.to_vec();
    for (k, v) in [0, 0, last, last].into_iter().enumerate() {
        out[at + 4 * k..at + 4 * k + 4].copy_from_slice(&v.to_le_bytes());
    }
    out
}

/// An EXR table whose header claims 100000² over a 4×4 body (which aborted allocating 40 GB)
/// is refused naming the limit; one that claims 4096² (within the limit) over the same body
/// is refused for the chunks it cannot hold, before they are allocated.
#[test]
fn lut_refuses_an_exr_whose_header_claims_more_than_its_body() {
    let shipped = Lut::embedded();
    let small = Lut {
        nl_terms: Default::default(),
        aniso: None,
        size: 4,
        alpha_min: shipped.alpha_min,
        cells: (0..16)
            .map(|k| *shipped.cell(k % 4 * 21, k / 4 * 21))
            .collect(),
    };
    let bytes = small.to_exr_bytes();
    assert_eq!(
        Lut::from_exr_bytes(&bytes, "small").unwrap(),
        small,
        "the body itself is a good table"
    );
    let dir = tempfile::tempdir().unwrap();
    for (last, said) in [(99_999, "at most 4096×4096"), (4095, "chunks")] {
        let p = dir.path().join(format!("claims-{last}.exr"));
        std::fs::write(&p, exr_claiming(&bytes, last)).unwrap();
        let o = ltc_lab(&["lut", "--lut", p.to_str().unwrap()]);
        assert_refused(&o, p.to_str().unwrap());
        assert!(stderr(&o).contains(said), "{}", stderr(&o));
    }
}

/// The point table exported for ltc_code shades what the lab shades: `eval --table point` and
/// `eval --lut exported.js` agree at grazing views, where the fitted scale varies most from
/// cell to cell (they differed by up to 6.6e-4 while the native table filtered the scale and
/// the magnitudes apart and multiplied after). Tolerance 1e-6 relative: the export rounds
/// each cell's product scale × magnitude to f32 once (≤ 2^-24 ≈ 6e-8 relative), a bilinear
/// blend of positive values keeps that relative bound, and the matrices are the same f32s.
#[test]
fn an_exported_point_table_shades_as_the_point_table() {
    let dir = tempfile::tempdir().unwrap();
    let js = dir.path().join("point.js");
    export_js(&["--table", "point"], &js);
    let mut cases = String::from("theta_o,alpha,lx,ly,lz,f0\n");
    for theta_o in [60.0, 78.0, 83.0, 84.5, 86.0, 88.0] {
        for alpha in [0.03, 0.1, 0.27, 0.55, 0.9] {
            for elevation in [5.0_f64, 20.0, 45.0, 80.0] {
                for (azimuth, f0) in [(180.0_f64, 0.04), (150.0, 1.0), (0.0, 0.5)] {
                    let (e, a) = (elevation.to_radians(), azimuth.to_radians());
                    let l = [e.cos() * a.cos(), e.cos() * a.sin(), e.sin()];
                    cases.push_str(&format!(
                        "{theta_o},{alpha},{},{},{},{f0}\n",
                        l[0], l[1], l[2]
                    ));
                }
            }
        }
    }
    let csv = dir.path().join("grazing.csv");
    std::fs::write(&csv, cases).unwrap();
    let ltc_spec = |lut: &[&str]| -> Vec<f64> {
        let mut args = vec!["eval", "--cases", csv.to_str().unwrap()];
        args.extend_from_slice(lut);
        let o = ltc_lab(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        String::from_utf8(o.stdout)
            .unwrap()
            .lines()
            .skip(1)
            .map(|l| l.split(',').nth(8).unwrap().parse().unwrap())
            .collect()
    };
    let native = ltc_spec(&["--table", "point"]);
    let exported = ltc_spec(&["--lut", js.to_str().unwrap()]);
    assert_eq!(native.len(), 6 * 5 * 4 * 3);
    let lit = native.iter().filter(|&&x| x > 0.0).count();
    assert!(lit > native.len() / 2, "only {lit} cases lit");
    for (k, (a, b)) in native.iter().zip(&exported).enumerate() {
        assert!(
            (a - b).abs() <= 1e-6 * a.abs(),
            "case {k}: point table {a:e}, its export {b:e}"
        );
    }
}

/// A table in ltc_code's layout is not measured to shade with it: `eval` does not measure
/// its spec.err (`lut --dump`, which shows it, does, and every cell gets a measurement
/// close to the one the classic fit stored for the same lobe).
#[test]
fn an_imported_table_is_measured_only_where_its_error_is_shown() {
    let dir = tempfile::tempdir().unwrap();
    let js = dir.path().join("classic.js");
    export_js(&[], &js);
    let o = ltc_lab(&["lut", "--dump", "--lut", js.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let column = 4 + Channel::SpecErr as usize;
    let shipped = Lut::embedded();
    let mut rows = 0;
    for line in text.lines().skip(1) {
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        let stored = f64::from(
            shipped
                .cell(v[0] as usize, v[1] as usize)
                .get(Channel::SpecErr),
        );
        // The same estimator (64² strata) on the same lobe, except that the fit measured its
        // f64 matrix and the export holds f32: at α ≤ 2.5e-4 (columns 0 and 1), where the lobe
        // is as narrow as f32's steps in M⁻¹'s ~1/α entries allow, that moves the error by up to
        // 1.3e-4 and 2% (measured); elsewhere far less. Bound: 3% + 5e-4.
        assert!(
            (v[column] - stored).abs() <= 0.03 * stored + 5e-4,
            "cell ({}, {}): measured {}, stored {stored}",
            v[0],
            v[1],
            v[column]
        );
        rows += 1;
    }
    assert_eq!(rows, 64 * 64);
}

/// Two outputs of one command never name the same path: an export into the atlas directory
/// itself (or onto one of its files) is refused before anything is written.
#[test]
fn lut_refuses_an_export_onto_its_atlas() {
    let dir = tempfile::tempdir().unwrap();
    let atlas = dir.path().join("atlas");
    for out in [atlas.clone(), atlas.join("spec_err.png")] {
        let o = ltc_lab(&[
            "lut",
            "--export",
            "c",
            "--out",
            out.to_str().unwrap(),
            "--atlas",
            atlas.to_str().unwrap(),
        ]);
        assert_refused(&o, "--out");
        assert!(!atlas.exists(), "the atlas was written");
    }
}

/// `lut <table> --export ltc-code-js --out <out>`, which must succeed.
fn export_js(table: &[&str], out: &std::path::Path) {
    let mut args = vec!["lut"];
    args.extend_from_slice(table);
    args.extend(["--export", "ltc-code-js", "--out", out.to_str().unwrap()]);
    let o = ltc_lab(&args);
    assert!(o.status.success(), "{}", stderr(&o));
}
