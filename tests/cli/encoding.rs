//! The table's encodings (docs/design.md §2.10): `eval --encoding`, `lut --encode`,
//! `lut --encodings` and `lut --layouts`.

use ltc_lab::ltc::lut::Lut;

use crate::eval::numbers;
use crate::{assert_no_panic, assert_refused, ltc_lab, stderr};

/// `--encoding` shades with the table as an engine storing it so reads it back (docs/design.md
/// §2.10): f32 is the table itself, to the bit; every encoding gives finite values and leaves
/// the exact columns alone; f16 stays within 1e-3 of f32 from α = 0.2 up and is past it near
/// α → 0, where `M⁻¹`'s entries grow like 1/α and a lobe amplifies their rounding (measured
/// 4.6e-3 at α = 0.01); 8 bits over a channel's range lose the small entries there outright;
/// and resampling costs more the smaller the table. The decoding is f64 arithmetic on the
/// CPU, the same on every machine: the bounds hold the measured values (0.97e-3 at α ≥ 0.2
/// for f16; 100% for unorm8 at α = 0.01) with the margins written beside them.
#[test]
fn eval_shades_with_the_table_as_an_encoding_reads_it() {
    let dir = tempfile::tempdir().unwrap();
    let cases = dir.path().join("cases.csv");
    let mut text = String::from("theta_o,alpha,lx,ly,lz,f0\n");
    for theta in [0, 40, 75, 89] {
        for alpha in [0.01, 0.05, 0.2, 0.4, 0.7, 1.0] {
            // Lights high, low, behind, and 5° below the mirror direction (where a sharp
            // lobe's value is large enough to weigh).
            let near_mirror = 85.0 - f64::from(theta);
            for (elevation, azimuth) in [
                (80f64, 180f64),
                (30.0, 0.0),
                (15.0, 180.0),
                (near_mirror, 180.0),
            ] {
                let (e, a) = (elevation.to_radians(), azimuth.to_radians());
                text += &format!(
                    "{theta},{alpha},{},{},{},0.04\n",
                    e.cos() * a.cos(),
                    e.cos() * a.sin(),
                    e.sin()
                );
            }
        }
    }
    std::fs::write(&cases, text).unwrap();
    let eval = |encoding: Option<&str>| {
        let mut args = vec!["eval", "--cases", cases.to_str().unwrap()];
        args.extend(encoding.iter().flat_map(|e| ["--encoding", e]));
        let o = ltc_lab(&args);
        assert!(o.status.success(), "{encoding:?}: {}", stderr(&o));
        String::from_utf8(o.stdout).unwrap()
    };
    let table = eval(None);
    assert_eq!(eval(Some("f32")), table, "f32 is not the table itself");
    let base = numbers(&table);
    // The largest relative change of the LTC columns among rows of α in `alphas`.
    let worst = |rows: &[Vec<f64>], alphas: std::ops::RangeInclusive<f64>| {
        let mut worst = 0f64;
        for (r, b) in rows.iter().zip(&base) {
            assert_eq!(r[..8], b[..8], "the exact columns changed");
            assert!(r.iter().all(|x| x.is_finite()), "{r:?}");
            for col in [8, 9] {
                if alphas.contains(&b[1]) && b[col] > 1e-9 {
                    worst = worst.max((r[col] - b[col]).abs() / b[col]);
                }
            }
        }
        worst
    };
    let half = numbers(&eval(Some("f16")));
    assert!(
        worst(&half, 0.2..=1.0) <= 1e-3,
        "f16: {}",
        worst(&half, 0.2..=1.0)
    );
    assert!(
        worst(&half, 0.01..=0.01) > 1e-3,
        "f16 near α → 0 no longer fails: pin it anew"
    );
    let byte = numbers(&eval(Some("unorm8")));
    assert!(worst(&byte, 0.01..=0.01) > 0.5, "unorm8 near α → 0");
    let sized: Vec<f64> = ["f32-32", "f32-16", "f32-8"]
        .map(|e| worst(&numbers(&eval(Some(e))), 0.2..=1.0))
        .to_vec();
    assert!(sized[0] < sized[1] && sized[1] < sized[2], "{sized:?}");
    // A size the encodings do not have is refused, naming the flag and the value.
    let o = ltc_lab(&[
        "eval",
        "--cases",
        cases.to_str().unwrap(),
        "--encoding",
        "f16-99",
    ]);
    let err = stderr(&o);
    assert_no_panic(o.status.code(), &err);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("--encoding") && err.contains("99"), "{err}");
}

/// `lut --encode NAME --out FILE.exr` writes the table as that encoding gives it back, and
/// shading with the file (`--lut`) is shading with `--encoding NAME`, to the bit; the file is
/// the encoding's size. What is not a table's place is refused, naming it.
#[test]
fn lut_encode_writes_what_eval_encoding_shades_with() {
    let dir = tempfile::tempdir().unwrap();
    let cases = dir.path().join("cases.csv");
    std::fs::write(
        &cases,
        "theta_o,alpha,lx,ly,lz,f0\n0,0.27,0,0,1,0.04\n\
         60,0.5,-0.6,0.2,0.7745966692414834,1\n\
         40,0.05,-0.7071067811865476,0,0.7071067811865475,0.04\n",
    )
    .unwrap();
    let cases = cases.to_str().unwrap();
    for (name, size) in [("f16", 64), ("unorm8-16", 16), ("f32-8", 8), ("cheb28", 64)] {
        let file = dir.path().join(format!("{name}.exr"));
        let o = ltc_lab(&["lut", "--encode", name, "--out", file.to_str().unwrap()]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let table = Lut::read(&file).unwrap();
        assert_eq!(table.size, size, "{name}");
        let by_file = ltc_lab(&["eval", "--cases", cases, "--lut", file.to_str().unwrap()]);
        let by_name = ltc_lab(&["eval", "--cases", cases, "--encoding", name]);
        assert!(by_file.status.success() && by_name.status.success());
        assert_eq!(by_file.stdout, by_name.stdout, "{name}");
    }
    // A table no reader takes is not written: a series that rings near the table's edges
    // turns M⁻¹ inside out there (cheb16: 2 cells), 8 bits round α → 0's entries to 0.
    for name in ["cheb16-f16", "unorm8"] {
        let out = dir.path().join(format!("{name}.exr"));
        let o = ltc_lab(&["lut", "--encode", name, "--out", out.to_str().unwrap()]);
        assert_refused(&o, "--encode");
        assert!(stderr(&o).contains("determinant"), "{}", stderr(&o));
        assert!(!out.exists(), "{name}");
    }
    let out = dir.path().join("table.txt");
    let o = ltc_lab(&["lut", "--encode", "f16", "--out", out.to_str().unwrap()]);
    assert_refused(&o, "table.txt");
    assert!(!out.exists());
    let o = ltc_lab(&["lut", "--out", dir.path().join("t.exr").to_str().unwrap()]);
    assert_refused(&o, "--out");
}

/// The rows of `lut --encodings ARGS`' CSV (header skipped), each split at its commas.
fn encodings_rows(args: &[&str]) -> Vec<Vec<String>> {
    let o = ltc_lab(&[&["lut", "--encodings"][..], args].concat());
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let split = |l: &str| l.split(',').map(String::from).collect();
    text.lines().skip(1).map(split).collect()
}

/// `lut --encodings`: a row per encoding, shape, α band and θo band; f32 at the table's size
/// adds nothing anywhere (it is the table); every figure is finite and not negative; 8 bits
/// add more than half floats near α → 0, and a smaller table adds more than a larger one.
/// The anisotropic material's rows give the 4D table's bytes; a size changes only the 2D
/// table, so the 4D table's specular lobe gains nothing from it, and 8 bits there add more
/// than half floats.
#[test]
fn lut_encodings_measures_every_encoding_on_every_shape() {
    let o = ltc_lab(&["lut", "--encodings", "--cases", "16"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "encoding,bytes,shape,alpha,theta_o,cases,added_spec,added_diff,total_spec,total_diff"
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    // 4 storages × 4 sizes, 6 shapes, 3 α bands × 3 θo bands.
    assert_eq!(rows.len(), 16 * 6 * 9);
    let value = |r: &Vec<&str>, k: usize| r[k].parse::<f64>().unwrap();
    // Σ over a storage's rows of a shape and α band of the specular error it adds.
    let added = |encoding: &str, shape: &str, alpha: &str| -> f64 {
        rows.iter()
            .filter(|r| r[0] == encoding && r[2] == shape && r[3] == alpha)
            .map(|r| value(r, 6))
            .sum()
    };
    for r in &rows {
        for k in 6..10 {
            assert!(value(r, k).is_finite() && value(r, k) >= 0.0, "{r:?}");
        }
        if r[0] == "f32" {
            assert_eq!((value(r, 6), value(r, 7)), (0.0, 0.0), "{r:?}");
        }
    }
    for shape in ["point", "sphere", "rect", "disk"] {
        assert!(added("unorm8", shape, "0.01..0.1") > added("f16", shape, "0.01..0.1"));
        // Four times the steps: a quarter of the rounding, where it is the error.
        assert!(added("unorm8", shape, "0.1..0.4") > 2.0 * added("unorm10", shape, "0.1..0.4"));
        assert!(added("f32-8", shape, "0.1..0.4") > added("f32-32", shape, "0.1..0.4"));
    }
    let bytes = |encoding: &str, shape: &str| -> usize {
        let r = rows.iter().find(|r| r[0] == encoding && r[2] == shape);
        r.unwrap()[1].parse().unwrap()
    };
    for shape in ["aniso-point", "aniso-rect"] {
        assert_eq!(bytes("f32", shape), 2 * bytes("f16", shape), "{shape}");
        // The 2D table at 8² is a 64th of its 64² bytes; the 4D table keeps its grid.
        assert_eq!(
            bytes("f16", shape),
            bytes("f16-8", shape),
            "{shape}: one 4D grid"
        );
        assert_eq!(added("f32-8", shape, "0.1..0.4"), 0.0, "{shape}");
        assert!(added("unorm8", shape, "0.01..0.1") > added("f16", shape, "0.01..0.1"));
    }
    assert_refused(&ltc_lab(&["lut", "--encodings", "--cases", "0"]), "--cases");
}

/// `render --encoding-b` compares the table with itself as an encoding decodes it, in a
/// split or a difference, so that an engineer sees f32 beside 8 bits: f32 against the table
/// is no difference at all, the same encoding on both sides none either, and an 8-bit 8²
/// table differs from the table more than an f16 64² one does (measured on 5 shapes ×
/// 9 bands, docs/design.md §2.10: f16 adds ≤ 0.07%, unorm8 at 8² some 3–6%). On the CPU, so
/// that the numbers are f64's everywhere.
#[test]
fn render_compares_two_encodings_side_by_side() {
    let dir = tempfile::tempdir().unwrap();
    let scene = crate::preset("paper-100.toml");
    let rmse = |extra: &[&str]| -> f64 {
        let out = dir.path().join("d.png");
        let mut args = vec![
            "render", "--scene", &scene, "--cpu", "--size", "48x27", "--method", "diff",
        ];
        args.extend(extra);
        args.extend(["--out", out.to_str().unwrap()]);
        let o = ltc_lab(&args);
        let err = stderr(&o);
        assert!(o.status.success(), "{extra:?}: {err}");
        std::fs::remove_file(&out).unwrap();
        // Each side's table is named, B's as its encoding.
        let b = extra.last().unwrap();
        assert!(err.contains(&format!("table classic as {b})")), "{err}");
        let after = err
            .split("relative RMSE ")
            .nth(1)
            .unwrap_or_else(|| panic!("{extra:?}: no RMSE said: {err}"));
        after.split('%').next().unwrap().parse().unwrap()
    };
    assert_eq!(rmse(&["--encoding-b", "f32"]), 0.0);
    assert_eq!(
        rmse(&["--encoding", "unorm8", "--encoding-b", "unorm8"]),
        0.0
    );
    let (f16, unorm8) = (
        rmse(&["--encoding-b", "f16"]),
        rmse(&["--encoding-b", "unorm8-8"]),
    );
    assert!(
        unorm8 > 0.0 && unorm8 > f16,
        "f16 {f16}%, unorm8-8 {unorm8}%"
    );

    // A split of f32 | f32 is the table's own image, column for column.
    let render = |name: &str, extra: &[&str]| {
        let out = dir.path().join(name);
        let mut args = vec!["render", "--scene", &scene, "--cpu", "--size", "48x27"];
        args.extend(extra);
        args.extend(["--out", out.to_str().unwrap()]);
        let o = ltc_lab(&args);
        assert!(o.status.success(), "{extra:?}: {}", stderr(&o));
        crate::exr_pixels(&out)
    };
    assert_eq!(
        render("split.exr", &["--method", "split", "--encoding-b", "f32"]),
        render("ltc.exr", &["--method", "ltc"])
    );

    // One side alone has nothing to compare.
    let o = ltc_lab(&[
        "render",
        "--scene",
        &scene,
        "--cpu",
        "--size",
        "8x8",
        "--method",
        "ltc",
        "--encoding-b",
        "f32",
        "--out",
        dir.path().join("x.png").to_str().unwrap(),
    ]);
    assert_refused(&o, "--method");
    assert!(!dir.path().join("x.png").exists());
}

/// `bench` and `study` take `--encoding` as `eval` and `render` do, and refuse a name that
/// is none (exit 2, naming the flag and the encodings there are).
#[test]
fn every_command_with_a_table_takes_an_encoding() {
    for command in ["render", "bench", "study", "eval"] {
        let o = ltc_lab(&[command, "--encoding", "f12"]);
        assert_no_panic(o.status.code(), &stderr(&o));
        assert_eq!(o.status.code(), Some(2), "{command}: {}", stderr(&o));
        assert!(
            stderr(&o).contains("--encoding"),
            "{command}: {}",
            stderr(&o)
        );
    }
}

/// `lut --encodings --fitted 8` adds the classic table fitted at 8² (`fit --size 8`) beside
/// the shipped table resampled to 8²: an 8² table's cells sit on the 64² table's own (cell
/// `j` of 8 at `j/7 = 9j/63`), so resampling reads them as they are and fitting them again
/// gives the same cells to the fit's convergence — the two add the same error to within a
/// tenth (measured: equal to the second digit). A size that is not a smaller table's is
/// refused.
#[test]
fn lut_encodings_sets_a_fitted_small_table_beside_the_resampled_one() {
    let rows = encodings_rows(&["--cases", "16", "--fitted", "8"]);
    assert_eq!(rows.len(), 17 * 6 * 9);
    let added = |name: &str, shape: &str| -> f64 {
        rows.iter()
            .filter(|r| r[0] == name && r[2] == shape && r[3] == "0.1..0.4")
            .map(|r| r[6].parse::<f64>().unwrap())
            .sum()
    };
    for r in rows
        .iter()
        .filter(|r| r[0] == "fit-8" && !r[2].starts_with("aniso"))
    {
        assert_eq!(r[1], (8 * 8 * 11 * 4).to_string(), "{r:?}");
    }
    for shape in ["point", "sphere", "rect", "disk"] {
        let (fitted, resampled) = (added("fit-8", shape), added("f32-8", shape));
        assert!(resampled > 0.0, "{shape}");
        assert!(
            (fitted - resampled).abs() <= 0.1 * resampled,
            "{shape}: fitted {fitted}, resampled {resampled}"
        );
    }
    assert_refused(
        &ltc_lab(&["lut", "--encodings", "--cases", "16", "--fitted", "64"]),
        "--fitted",
    );
}

/// `lut --encodings --formulas`: three.js PR #34611's form measured beside the tables. A
/// Chebyshev series of degree 8 adds more than one of degree 24 on every shape where
/// α ≥ 0.1 (measured at 4 096 cases a band: 3.7% against 0.12%; over 32 cases the sums keep
/// a gap far past the 3× asserted); its bytes are its coefficients' and ranges'. A storage
/// is not a formula, and `--formulas` without a measure is refused. `--layouts` prints each
/// encoding's cost, a formula's per-lookup form with no texture.
#[test]
fn lut_encodings_measures_formulas_and_lut_layouts_costs_them() {
    let rows = encodings_rows(&["--cases", "32", "--formulas", "cheb8,cheb24,rational4"]);
    assert_eq!(rows.len(), 19 * 6 * 9);
    let added = |name: &str, shape: &str| -> f64 {
        rows.iter()
            .filter(|r| r[0] == name && r[2] == shape && r[3] != "0.01..0.1")
            .map(|r| r[6].parse::<f64>().unwrap() + r[7].parse::<f64>().unwrap())
            .sum()
    };
    for shape in ["point", "sphere", "rect", "disk"] {
        let (low, high) = (added("cheb8", shape), added("cheb24", shape));
        assert!(low > 3.0 * high, "{shape}: cheb8 {low}, cheb24 {high}");
    }
    for r in rows
        .iter()
        .filter(|r| r[0].starts_with("cheb") || r[0].starts_with("rational"))
    {
        assert!(
            r[6..].iter().all(|v| v.parse::<f64>().unwrap().is_finite()),
            "{r:?}"
        );
    }
    let cheb8 = rows.iter().find(|r| r[0] == "cheb8").unwrap();
    assert_eq!(cheb8[1], (4 * 11 * 9 * 9 + 11 * 2 * 4).to_string());
    for wrong in ["f16", "cheb0", "rational9"] {
        let o = ltc_lab(&["lut", "--encodings", "--formulas", wrong]);
        assert_no_panic(o.status.code(), &stderr(&o));
        assert_eq!(o.status.code(), Some(2), "{wrong}: {}", stderr(&o));
        assert!(stderr(&o).contains("--formulas"), "{wrong}: {}", stderr(&o));
    }
    assert_refused(&ltc_lab(&["lut", "--formulas", "cheb8"]), "--formulas");
    let o = ltc_lab(&["lut", "--layouts", "--formulas", "cheb16"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let per_lookup = text
        .lines()
        .find(|l| l.starts_with("cheb16,per-lookup,"))
        .unwrap_or_else(|| panic!("{text}"));
    assert!(per_lookup.contains(",0,0,0,0,"), "{per_lookup}");
    // eval shades with a formula's table: finite, as every encoding's.
    let dir = tempfile::tempdir().unwrap();
    let cases = dir.path().join("cases.csv");
    std::fs::write(
        &cases,
        "theta_o,alpha,lx,ly,lz,f0\n10,0.02,0.1,0,0.99498743710662,0.04\n",
    )
    .unwrap();
    let o = ltc_lab(&[
        "eval",
        "--cases",
        cases.to_str().unwrap(),
        "--encoding",
        "rational8",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let values = numbers(&String::from_utf8(o.stdout).unwrap());
    assert!(values.iter().flatten().all(|v| v.is_finite()), "{values:?}");
}

/// `lut --export c|wgsl --encode NAME` writes the encoding's texels with their decoding, or a
/// formula's coefficients with the formula (the data checked value by value in
/// tests/lut/export.rs); ltc_code's float layouts are refused, naming `--encode`, with
/// nothing written.
#[test]
fn lut_exports_an_encoding_for_engines() {
    let dir = tempfile::tempdir().unwrap();
    let export = |format: &str, name: &str, file: &str| {
        let out = dir.path().join(file);
        let args = ["lut", "--export", format, "--encode", name, "--out"];
        (
            ltc_lab(&[&args[..], &[out.to_str().unwrap()]].concat()),
            out,
        )
    };
    for (format, name, file, marker) in [
        ("wgsl", "f16", "ltc_f16.wgsl", "unpack2x16float"),
        ("c", "unorm10-32", "ltc_unorm10.h", "g_ltc_scale[12]"),
        (
            "c",
            "cheb16",
            "ltc_cheb16.h",
            "#define LTC_FORMULA_COEFFICIENTS 289",
        ),
        (
            "wgsl",
            "rational4-f16",
            "ltc_rational4.wgsl",
            "fn ltc_formula_lookup",
        ),
    ] {
        let (o, out) = export(format, name, file);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let text = std::fs::read_to_string(&out).unwrap();
        assert!(
            text.contains(marker)
                && (text.contains(&format!("encoding: {name}"))
                    || text.contains(&format!("formula: {name}"))),
            "{name}"
        );
    }
    for (format, name) in [("ltc-code-js", "f16"), ("ltc-code-dds", "cheb16")] {
        let (o, out) = export(format, name, "refused.txt");
        assert_refused(&o, "--encode");
        assert!(!out.exists(), "{format} {name}");
    }
}
