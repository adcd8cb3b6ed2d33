//! `ltc-lab eval`.

use ltc_lab::brdf::{brdf_cos, view_from_theta};

use crate::{
    assert_no_panic, assert_refused, corrupt_lut, first_line_then_close, into_dev_full, ltc_lab,
    stderr,
};

const CASES: &str = "theta_o,alpha,lx,ly,lz,f0\n\
    0,0.27,0,0,1,0.04\n\
    60,0.5,-0.6,0.2,0.7745966692414834,1\n\
    89,0.01,0.3,0.1,-0.9486832980505138,0\n";

#[test]
fn eval_prints_one_row_per_case() {
    let dir = tempfile::tempdir().unwrap();
    let cases = dir.path().join("cases.csv");
    // Spreadsheets save CSV with a UTF-8 byte-order mark: it is accepted.
    std::fs::write(&cases, format!("\u{feff}{CASES}")).unwrap();
    let o = ltc_lab(&["eval", "--cases", cases.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let rows = numbers(&text);
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

/// `--horizon` picks the remedy. exact-band gives the exact lobes for a light 10°
/// above the surface and eq. 30's LTC for one at 60°; a fitted remedy is its own table, and
/// naming another table beside it is refused.
#[test]
fn eval_shades_with_the_horizon_remedy() {
    let dir = tempfile::tempdir().unwrap();
    let cases = dir.path().join("cases.csv");
    let (low, high) = (10f64.to_radians(), 60f64.to_radians());
    std::fs::write(
        &cases,
        format!(
            "theta_o,alpha,lx,ly,lz,f0\n45,0.3,{},0,{},0.04\n45,0.3,{},0,{},0.04\n",
            -low.cos(),
            low.sin(),
            -high.cos(),
            high.sin()
        ),
    )
    .unwrap();
    let run = |extra: &[&str]| {
        let mut args = vec!["eval", "--cases", cases.to_str().unwrap()];
        args.extend(extra);
        let o = ltc_lab(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        numbers(&String::from_utf8(o.stdout).unwrap())
    };
    let (eq30, band) = (run(&[]), run(&["--horizon", "exact-band"]));
    // Below 15°: the exact lobes to the bit; eq. 30's LTC is off there.
    assert_eq!(&band[0][8..], &band[0][6..8]);
    assert!(
        (eq30[0][8] - eq30[0][6]).abs() > 0.01 * eq30[0][6],
        "{eq30:?}"
    );
    // Above it: eq. 30's LTC unchanged.
    assert_eq!(band[1], eq30[1]);
    // constrained-fit is the constrained table: the same as --table constrained.
    let fitted = run(&["--horizon", "constrained-fit"]);
    assert_eq!(fitted, run(&["--table", "constrained"]));
    assert_ne!(fitted, eq30);
    let o = ltc_lab(&[
        "eval",
        "--cases",
        cases.to_str().unwrap(),
        "--horizon",
        "constrained-fit",
        "--table",
        "point",
    ]);
    assert_refused(&o, "--horizon");
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
fn eval_refuses_a_corrupt_lut() {
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
}

/// Many cases, so that the output outgrows a pipe's buffer (64 KiB on Linux).
fn many_cases(dir: &std::path::Path) -> String {
    let cases = dir.join("many.csv");
    let mut text = String::from("theta_o,alpha,lx,ly,lz,f0\n");
    for k in 0..3000 {
        text.push_str(&format!("{},0.27,0,0,1,0.04\n", k % 90));
    }
    std::fs::write(&cases, text).unwrap();
    cases.display().to_string()
}

/// `eval … | head -1`: the reader leaves; eval ends quietly, with success.
#[test]
fn eval_ends_quietly_on_a_closed_pipe() {
    let dir = tempfile::tempdir().unwrap();
    let cases = many_cases(dir.path());
    let (line, status, err) = first_line_then_close(&["eval", "--cases", &cases]);
    assert!(line.starts_with("theta_o,alpha"), "{line}");
    assert_no_panic(status.code(), &err);
    assert!(status.success(), "{status}: {err}");
    assert!(err.is_empty(), "{err}");
}

/// `eval … > /dev/full`: one line saying so, exit 1 (the machine's failure, not the input's).
#[test]
fn eval_reports_a_full_disk_without_a_backtrace() {
    let dir = tempfile::tempdir().unwrap();
    let cases = many_cases(dir.path());
    let o = into_dev_full(&["eval", "--cases", &cases]);
    let err = stderr(&o);
    assert_no_panic(o.status.code(), &err);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(err.contains("no space left"), "{err}");
}

/// `eval --lut` on a table in ltc_code's JavaScript layout, written here as ltc_code's
/// `writeJS` writes it (2×2 cells, distinct entries), gives the values that layout defines:
/// `M⁻¹ = mat3(vec3(t1.x, 0, t1.y), vec3(0, 1, 0), vec3(t1.z, 0, t1.w))` (columns),
/// `D = max((M⁻¹l).z, 0) |det M⁻¹| / (π |M⁻¹l|⁴)`, times `F0·t2.x + (1 − F0)·t2.y`, with
/// the docs/design.md §2 lookup (at r = 0.5 the two columns' average). The diffuse lobe is the
/// embedded table's.
#[test]
fn eval_with_an_ltc_code_table_follows_that_layouts_definition() {
    let dir = tempfile::tempdir().unwrap();
    let tex1 = [
        [1.0, 0.0, 0.0, 0.0002],
        [0.9, 0.2, -0.1, 1.1],
        [1.0, 0.0, 0.0, 0.0002],
        [0.8, 0.3, -0.2, 1.2],
    ];
    let tex2 = [
        [1.0, 0.001, 0.0, 0.0],
        [0.5, 0.05, 0.0, 1.0],
        [0.9, 0.01, 0.0, 0.0],
        [0.6, 0.04, 0.0, 1.0],
    ];
    let line = |t: &[f64; 4]| format!("{}, {}, {}, {}, \n", t[0], t[1], t[2], t[3]);
    let js = format!(
        "var g_ltc_1 = [\n{}];\nvar g_ltc_2 = [{}];\n",
        tex1.iter().map(line).collect::<String>(),
        tex2.iter().map(line).collect::<String>()
    );
    let table = dir.path().join("tiny.js");
    std::fs::write(&table, js).unwrap();
    let cases = dir.path().join("cases.csv");
    std::fs::write(
        &cases,
        "theta_o,alpha,lx,ly,lz,f0\n0,1,0.6,0,0.8,0.5\n0,0.25,0,0.28,0.96,0.2\n0,1,-0.6,0,0.8,0.5\n",
    )
    .unwrap();
    let o = ltc_lab(&[
        "eval",
        "--cases",
        cases.to_str().unwrap(),
        "--lut",
        table.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("diffuse lobe is the embedded"),
        "{}",
        stderr(&o)
    );
    let rows: Vec<Vec<f64>> = String::from_utf8(o.stdout)
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    let mix = |a: [f64; 4], b: [f64; 4], f: f64| {
        std::array::from_fn::<f64, 4, _>(|c| a[c] * (1.0 - f) + b[c] * f)
    };
    // (θo = 0, r = 1): cell (1, 0); (r = 0.5): halfway between cells (0, 0) and (1, 0).
    let texels = [
        (tex1[1], tex2[1]),
        (mix(tex1[0], tex1[1], 0.5), mix(tex2[0], tex2[1], 0.5)),
        (tex1[1], tex2[1]),
    ];
    for (row, (t1, t2)) in rows.iter().zip(texels) {
        let (l, f0) = ([row[2], row[3], row[4]], row[5]);
        // M⁻¹ l with columns (t1.x, 0, t1.y), (0, 1, 0), (t1.z, 0, t1.w).
        let w = [
            t1[0] * l[0] + t1[2] * l[2],
            l[1],
            t1[1] * l[0] + t1[3] * l[2],
        ];
        let det = t1[0] * t1[3] - t1[2] * t1[1];
        let q = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
        let d = w[2].max(0.0) * det.abs() / (std::f64::consts::PI * q * q);
        let want = (f0 * t2[0] + (1.0 - f0) * t2[1]) * d;
        // The table's f32 entries (exact for these decimals to 6e-8 relative) in f64.
        assert!(
            (row[8] - want).abs() <= 1e-6 * want,
            "{row:?}: ltc_spec {} against {want}",
            row[8]
        );
    }
    // A mirrored light sees a different value: the m02/m20 entries are not symmetric.
    assert!((rows[0][8] - rows[2][8]).abs() > 1e-3 * rows[0][8]);
}

/// α is taken over the range the rest of the program takes (the scene's and the tables'
/// [1e-4, 1]): at its smallest, the mirror direction gives finite values; below it, a row is
/// refused naming its line (α = 1e-100 once wrote inf and NaN with exit 0). The inputs are
/// echoed as the file wrote them (α = 1e-200 was echoed as 200 zeros).
#[test]
fn eval_takes_the_programs_alpha_range_and_echoes_its_inputs_as_written() {
    let dir = tempfile::tempdir().unwrap();
    let cases = dir.path().join("cases.csv");
    // θo = 30°: v = (sin 30°, 0, cos 30°), its mirror direction l = (−sin 30°, 0, cos 30°).
    let rows = [
        "30,1e-4,-0.5,0,0.8660254037844386,0.04",
        "30,0.50,-0.5,0.0,0.86603,1.0",
    ];
    std::fs::write(
        &cases,
        format!("theta_o,alpha,lx,ly,lz,f0\n{}\n{}\n", rows[0], rows[1]),
    )
    .unwrap();
    let o = ltc_lab(&["eval", "--cases", cases.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    for (line, row) in text.lines().skip(1).zip(rows) {
        assert!(
            line.starts_with(&format!("{row},")),
            "{line} does not echo {row}"
        );
        let values: Vec<f64> = line
            .split(',')
            .skip(6)
            .map(|x| x.parse().unwrap())
            .collect();
        assert!(values.iter().all(|x| x.is_finite()), "{line}");
    }
    // At α = 1e-4 the mirror direction sees GGX's peak (D = 1/(πα²) ≈ 3e7), finite and equal
    // to the f64 reference (as in `eval_prints_one_row_per_case`).
    let peak: f64 = text
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .nth(6)
        .unwrap()
        .parse()
        .unwrap();
    let theta = 30f64.to_radians();
    let reference = brdf_cos(
        view_from_theta(theta),
        [-theta.sin(), 0.0, theta.cos()],
        1e-4,
        0.04,
    );
    assert!(
        (peak - reference.specular).abs() <= 1e-9 * reference.specular && peak > 1e5,
        "{peak} against {}",
        reference.specular
    );
    for alpha in ["1e-100", "1e-200", "0.00005"] {
        std::fs::write(
            &cases,
            format!("theta_o,alpha,lx,ly,lz,f0\n30,{alpha},-0.5,0,0.8660254037844386,0.04\n"),
        )
        .unwrap();
        let o = ltc_lab(&["eval", "--cases", cases.to_str().unwrap()]);
        assert_refused(&o, "line 2");
        assert!(
            stderr(&o).contains(&format!("got {alpha}")),
            "{}",
            stderr(&o)
        );
        assert!(stderr(&o).len() < 200, "{}", stderr(&o));
    }
}

/// With a `sigma` column each light is a sphere: at σ = 0 every method is the point light's
/// formula (the exact ones `brdf_*`, the LTC ones `ltc_*` of the same case as a point); at
/// σ = 10° the point formula at the centre is unchanged while the exact integral moves.
#[test]
fn eval_shades_sphere_lights_by_each_method() {
    let dir = tempfile::tempdir().unwrap();
    let (points, spheres) = (dir.path().join("p.csv"), dir.path().join("s.csv"));
    let l = "-0.6,0.2,0.7745966692414834";
    std::fs::write(
        &points,
        format!("theta_o,alpha,lx,ly,lz,f0\n60,0.5,{l},0.04\n"),
    )
    .unwrap();
    std::fs::write(
        &spheres,
        format!("theta_o,alpha,lx,ly,lz,f0,sigma\n60,0.5,{l},0.04,0\n60,0.5,{l},0.04,10\n"),
    )
    .unwrap();
    let p = ltc_lab(&["eval", "--cases", points.to_str().unwrap()]);
    let s = ltc_lab(&["eval", "--cases", spheres.to_str().unwrap()]);
    assert!(p.status.success() && s.status.success(), "{}", stderr(&s));
    let text = String::from_utf8(s.stdout).unwrap();
    assert!(
        text.starts_with("theta_o,alpha,lx,ly,lz,f0,sigma,exact_spec,exact_diffuse,ltc_point_spec")
    );
    let point = &numbers(&String::from_utf8(p.stdout).unwrap())[0];
    let rows = numbers(&text);
    let (at0, at10) = (&rows[0][7..], &rows[1][7..]);
    // Printed with `{:e}` (shortest round-trip), so equal values print equal.
    assert_eq!([at0[0], at0[1]], [point[6], point[7]]);
    assert_eq!([at0[2], at0[3]], [point[8], point[9]]);
    assert_eq!([at0[4], at0[5]], [point[8], point[9]]);
    assert_eq!([at0[6], at0[7]], [point[6], point[7]]);
    assert_eq!([at10[2], at10[3]], [at0[2], at0[3]]);
    assert_ne!(at10[0], at0[0]);
    assert!(at10.iter().all(|x| x.is_finite() && *x >= 0.0), "{at10:?}");
    // The remedies are point lights' only: refused by name beside spheres.
    let o = ltc_lab(&[
        "eval",
        "--cases",
        spheres.to_str().unwrap(),
        "--horizon",
        "nl-fit",
    ]);
    assert_refused(&o, "--horizon");
}

/// The rows of eval's output after its header, as numbers.
pub fn numbers(text: &str) -> Vec<Vec<f64>> {
    text.lines()
        .skip(1)
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect()
}

/// Rect lights (radiance 1, centre and half-edges in the shading frame): `exact` and
/// `ltc_polygon` against an independent f64 reference — the midpoint rule over a 300 × 300
/// grid of the rect's area, of `f cos` and of the LTC's own `m D` (both continuous across
/// the horizon, where `n·l` and the clamped cosine go to 0; the rule's error is O(h²), ~1e-5
/// here) — to the 2e-3 the methods are held to; every method's value finite and ≥ 0; a rect
/// facing away 0; a tiny rect its oriented point light (`L·A·cos θe`, to 1e-3).
#[test]
fn eval_shades_rect_lights_against_an_independent_reference() {
    use glam::DVec3;
    use ltc_lab::ltc::lut::Lut;
    use ltc_lab::ltc::{Clipping, Normalization};
    let dir = tempfile::tempdir().unwrap();
    let cases = dir.path().join("rects.csv");
    // θo, α, F0, centre, u, v. The third crosses the horizon; the fourth faces away; the fifth
    // is tiny.
    let rows = [
        "0,0.3,0.04,0,0,1,0.3,0,0,0,-0.3,0",
        "45,0.5,0.5,0.4,-0.2,0.8,0.25,0,0.1,0,-0.3,0",
        "60,0.4,0.04,-0.9,0.1,0.1,0,0.4,0,0,0,0.3",
        "30,0.3,0.04,0,0,1,0.3,0,0,0,0.3,0",
        "20,0.4,0.04,0.2,0.1,0.9,0.0005,0,0,0,-0.0005,0",
    ];
    std::fs::write(
        &cases,
        format!(
            "theta_o,alpha,f0,cx,cy,cz,ux,uy,uz,vx,vy,vz\n{}\n",
            rows.join("\n")
        ),
    )
    .unwrap();
    let o = ltc_lab(&["eval", "--cases", cases.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    assert_eq!(
        text.lines().next().unwrap(),
        "theta_o,alpha,f0,cx,cy,cz,ux,uy,uz,vx,vy,vz,exact_spec,exact_diffuse,ltc_polygon_spec,ltc_polygon_diffuse,ltc_proxy_spec,ltc_proxy_diffuse,ltc_proxy_fast_spec,ltc_proxy_fast_diffuse,ltc_point_spec,ltc_point_diffuse"
    );
    let out = numbers(&text);
    assert_eq!(out.len(), rows.len());
    for r in &out {
        assert!(r[12..].iter().all(|x| x.is_finite() && *x >= 0.0), "{r:?}");
    }
    let lut = Lut::embedded();
    for r in &out[..3] {
        let v = DVec3::from(view_from_theta(r[0].to_radians()));
        let (alpha, f0) = (r[1], r[2]);
        let [c, u, w] = [3, 6, 9].map(|k| DVec3::new(r[k], r[k + 1], r[k + 2]));
        let pair = lut.ltc_pair(alpha, v);
        let n = 300;
        let mut want = [0.0; 4];
        for i in 0..n {
            for j in 0..n {
                let s = -1.0 + (2.0 * i as f64 + 1.0) / n as f64;
                let t = -1.0 + (2.0 * j as f64 + 1.0) / n as f64;
                let x = c + u * s + w * t;
                let d2 = x.length_squared();
                let l = x / d2.sqrt();
                // dω = cos θx dA / d², dA = |u × w| ds dt over [-1, 1]².
                let dw = (u.cross(w).normalize().dot(l)).abs() / d2
                    * u.cross(w).length()
                    * (2.0 / n as f64).powi(2);
                if l.z <= 0.0 {
                    continue;
                }
                let f = brdf_cos(v.to_array(), l.to_array(), alpha, f0);
                let rule = (Clipping::BOTH, Normalization::Corrected);
                want[0] += f.specular * dw;
                want[1] += f.diffuse * dw;
                want[2] += pair.spec_magnitude(f0) * pair.spec.ltc_eval(l, rule.0, rule.1) * dw;
                want[3] += pair.diff.magnitude() * pair.diff.ltc_eval(l, rule.0, rule.1) * dw;
            }
        }
        for (k, want) in want.into_iter().enumerate() {
            let got = r[12 + k];
            assert!(
                (got - want).abs() <= 2e-3 * want,
                "row {r:?}, column {}: {got} vs {want}",
                12 + k
            );
        }
    }
    // Facing away: nothing, by every method.
    assert!(out[3][12..].iter().all(|&x| x == 0.0), "{:?}", out[3]);
    // Tiny: every method is the oriented point light, the exact ones the BRDF's and the LTC
    // ones the LTC's at the centre (ltc_point, the limit itself).
    let tiny = &out[4];
    for (k, limit) in [
        (12, 12),
        (13, 13),
        (14, 20),
        (15, 21),
        (16, 20),
        (17, 21),
        (18, 20),
        (19, 21),
    ] {
        let (x, y) = (tiny[k], if k < 14 { tiny[k] } else { tiny[limit] });
        assert!((x - y).abs() <= 1e-3 * y, "column {k}: {x} vs {y}");
    }
    let v = view_from_theta(20f64.to_radians());
    let c = DVec3::new(0.2, 0.1, 0.9);
    let d = c.length();
    let point = brdf_cos(v, (c / d).to_array(), 0.4, 0.04);
    let area_cos = 4.0 * 0.0005 * 0.0005 * (c.z / d);
    for (x, y) in [(tiny[12], point.specular), (tiny[13], point.diffuse)] {
        let y = y * area_cos / (d * d);
        assert!((x - y).abs() <= 1e-3 * y, "{x} vs {y}");
    }
}

/// Tube rows: the header names the segment's ends and the radius, the columns are both lobes
/// by every tube method, and `exact` is the BRDF over the capsule's directions, against an
/// independent f64 integral over its surface (`common::capsule_integral`, 1 200 cells a side:
/// its error O(1/n²) ≈ 1e-6) within the 2e-3.
#[test]
fn eval_shades_tubes_by_every_method() {
    use glam::DVec3;
    use ltc_lab::light::tube::Tube;
    let dir = tempfile::tempdir().unwrap();
    let cases = dir.path().join("tubes.csv");
    std::fs::write(
        &cases,
        "theta_o,alpha,f0,ax,ay,az,bx,by,bz,radius\n\
         30,0.3,0.04,-0.5,0.2,1,0.5,0.4,1.2,0.15\n\
         70,0.5,1,0.3,-0.8,-0.4,0.6,0.9,0.7,0.2\n\
         0,0.2,0.04,-1,0.3,-2,1,0.3,-2,0.25\n",
    )
    .unwrap();
    let o = ltc_lab(&["eval", "--cases", cases.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = String::from_utf8(o.stdout).unwrap();
    let methods = [
        "exact",
        "ltc_line",
        "hdrp_tube",
        "representative_point",
        "ltc_point",
    ];
    let columns: Vec<String> = methods
        .iter()
        .flat_map(|m| [format!("{m}_spec"), format!("{m}_diffuse")])
        .collect();
    assert_eq!(
        text.lines().next().unwrap(),
        format!(
            "theta_o,alpha,f0,ax,ay,az,bx,by,bz,radius,{}",
            columns.join(",")
        )
    );
    let rows = numbers(&text);
    assert_eq!(rows.len(), 3);
    for r in &rows[..2] {
        let v = DVec3::from(view_from_theta(r[0].to_radians()));
        let tube = Tube {
            a: DVec3::new(r[3], r[4], r[5]),
            b: DVec3::new(r[6], r[7], r[8]),
            radius: r[9],
        };
        for (k, lobe) in [(10, 0), (11, 1)] {
            let reference = crate::common::capsule_integral(&tube, 1200, |w| {
                let l = brdf_cos(v.to_array(), w.to_array(), r[1], r[2]);
                [l.specular, l.diffuse][lobe]
            });
            assert!(
                (r[k] - reference).abs() <= 2e-3 * reference,
                "{r:?}: column {k} {} against {reference:e}",
                r[k]
            );
        }
        assert!(r[10..].iter().all(|x| x.is_finite() && *x >= 0.0), "{r:?}");
    }
    // A tube below the surface: nothing, by every method.
    assert!(rows[2][10..].iter().all(|&x| x == 0.0), "{:?}", rows[2]);
    // A row of no radius is refused, naming its line.
    std::fs::write(
        &cases,
        "theta_o,alpha,f0,ax,ay,az,bx,by,bz,radius\n0,0.2,0.04,0,0,1,1,0,1,0\n",
    )
    .unwrap();
    let o = ltc_lab(&["eval", "--cases", cases.to_str().unwrap()]);
    assert_refused(&o, "tubes.csv line 2");
}
