//! `ltc-lab eval`: light directions from a CSV file, evaluated with the exact lobes and their
//! LTC approximation through the LUT (docs/design.md §6); with a `sigma` column, each light is
//! a sphere of that angular radius, shaded by the four methods of docs/design.md §1.10.

use glam::DVec3;

use crate::brdf::{brdf_cos, view_from_theta};
use crate::cpu::LtcPixel;
use crate::error::{Error, Result, number};
use crate::light::sphere::{SphereMethod, SphereShading, sphere_light};
use crate::ltc::lut::{ALPHA_MIN, Lut, THETA_MAX};
use crate::ltc::remedy::HorizonRule;
use crate::render::LtcRules;

/// The most bytes of a cases CSV this program reads (`files::read_text`): ~60 bytes a case,
/// four million cases.
pub const MAX_FILE_BYTES: u64 = 256 << 20;

/// The input's header: θo in degrees, α, the unit light direction in the shading frame, F0.
pub const HEADER: &str = "theta_o,alpha,lx,ly,lz,f0";

/// The columns `evaluate` adds.
pub const OUTPUT_COLUMNS: &str = "brdf_spec,brdf_diffuse,ltc_spec,ltc_diffuse";

/// The header of sphere lights: a seventh column, the sphere's angular radius σ in degrees,
/// 0–90 (a sphere of radius sin σ at unit distance toward `l`; 90: it touches the point).
pub const SPHERE_HEADER: &str = "theta_o,alpha,lx,ly,lz,f0,sigma";

/// The columns `evaluate` adds for a sphere: both lobes by each method of
/// `SphereMethod::ALL`, in its order, named after it (`exact_spec,exact_diffuse,ltc_point_spec,…`).
pub fn sphere_output_columns() -> String {
    SphereMethod::ALL
        .map(|m| {
            let name = m.name().replace('-', "_");
            format!("{name}_spec,{name}_diffuse")
        })
        .join(",")
}

/// The output's header for input whose rows are spheres or not.
pub fn output_header(spheres: bool) -> String {
    match spheres {
        true => format!("{SPHERE_HEADER},{}", sphere_output_columns()),
        false => format!("{HEADER},{OUTPUT_COLUMNS}"),
    }
}

/// How far from unit length `l` may be: CSV values typed with 4 decimals are off by ~1e-4.
pub const UNIT_TOLERANCE: f64 = 1e-3;

/// The most rows `eval` takes: a million cases is a few seconds of work and ~100 MB of
/// output; a larger file is more likely a mistake than a question.
pub const MAX_ROWS: usize = 1_000_000;

/// One validated row.
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    /// The row's six values as the file wrote them, echoed in the output unchanged.
    pub text: String,
    pub theta_o_degrees: f64,
    pub alpha: f64,
    /// Unit length (normalized after the check).
    pub l: DVec3,
    pub f0: f64,
    /// The sphere's angular radius in degrees, where the file has a `sigma` column.
    pub sigma_degrees: Option<f64>,
}

/// A file's cases, all points or all spheres (by its header).
#[derive(Clone, Debug, PartialEq)]
pub struct Cases {
    pub spheres: bool,
    pub rows: Vec<Case>,
}

/// Parses the CSV text of `name`; every error names the file and the line.
pub fn parse_cases(text: &str, name: &str) -> Result<Cases> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines = text.lines().enumerate();
    let header = lines.next().map(|(_, h)| h.trim().replace(' ', ""));
    let spheres = match header.as_deref() {
        Some(HEADER) => false,
        Some(SPHERE_HEADER) => true,
        _ => {
            return Err(Error::input(
                format!("{name} line 1"),
                format!("the header must be '{HEADER}' or '{SPHERE_HEADER}'"),
            ));
        }
    };
    let rows = lines.filter(|(_, line)| !line.trim().is_empty());
    let mut cases = Vec::new();
    for (k, line) in rows {
        if cases.len() == MAX_ROWS {
            return Err(Error::input(
                format!("{name} line {}", k + 1),
                format!("more than {MAX_ROWS} cases: split the file"),
            ));
        }
        cases.push(parse_case(
            line,
            &format!("{name} line {}", k + 1),
            spheres,
        )?);
    }
    Ok(Cases {
        spheres,
        rows: cases,
    })
}

fn parse_case(line: &str, at: &str, sphere: bool) -> Result<Case> {
    let fields: Vec<&str> = line.split(',').map(str::trim).collect();
    let count = if sphere { 7 } else { 6 };
    if fields.len() != count {
        return Err(Error::input(
            at,
            format!("expected {count} values, found {}", fields.len()),
        ));
    }
    let mut v = [0.0; 7];
    for (x, f) in v.iter_mut().zip(&fields) {
        *x = f
            .parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| Error::input(at, format!("'{f}' is not a finite number")))?;
    }
    let [theta_o, alpha, lx, ly, lz, f0, sigma] = v;
    if !(0.0..=90.0).contains(&theta_o) {
        return Err(Error::input(
            at,
            format!("theta_o must be in [0, 90] degrees, got {}", fields[0]),
        ));
    }
    // The scene's range (and the tables' α_min): below it D's peak 1/(πα²) outgrows f64 at
    // the mirror direction (α = 1e-200 gave inf and NaN).
    if !(ALPHA_MIN..=1.0).contains(&alpha) {
        return Err(Error::input(
            at,
            format!(
                "alpha must be in [{}, 1], got {}",
                number(ALPHA_MIN),
                fields[1]
            ),
        ));
    }
    if !(0.0..=1.0).contains(&f0) {
        return Err(Error::input(
            at,
            format!("f0 must be in [0, 1], got {}", fields[5]),
        ));
    }
    if sphere && !(0.0..=90.0).contains(&sigma) {
        return Err(Error::input(
            at,
            format!("sigma must be in [0, 90] degrees, got {}", fields[6]),
        ));
    }
    let l = DVec3::new(lx, ly, lz);
    if (l.length() - 1.0).abs() > UNIT_TOLERANCE {
        return Err(Error::input(
            at,
            format!("l must be unit length, |l| = {}", number(l.length())),
        ));
    }
    Ok(Case {
        text: fields.join(","),
        theta_o_degrees: theta_o,
        alpha,
        l: l.normalize(),
        f0,
        sigma_degrees: sphere.then_some(sigma),
    })
}

/// The case's row of output: its columns as read, then `f·cos` of both lobes for a unit-irradiance
/// light and base colour 1, exact and through the LUT's bilinear sampler with both clipping
/// rules (eq. 30) and the horizon rule `horizon`. The grazing row is ltc_code's `THETA_MAX`.
pub fn evaluate(c: &Case, lut: &Lut, horizon: HorizonRule) -> String {
    let theta = c.theta_o_degrees.to_radians().min(THETA_MAX);
    let v = DVec3::from(view_from_theta(theta));
    if let Some(sigma) = c.sigma_degrees {
        return evaluate_sphere(c, lut, v, sigma);
    }
    let exact = brdf_cos(v.to_array(), c.l.to_array(), c.alpha, c.f0);
    let rules = LtcRules {
        horizon,
        ..LtcRules::default()
    };
    let px = LtcPixel::new(lut, c.alpha, v, &rules);
    let approx = px.lobes(c.l, c.f0, &rules, || exact);
    format!(
        "{},{:e},{:e},{:e},{:e}",
        c.text, exact.specular, exact.diffuse, approx.specular, approx.diffuse
    )
}

/// A sphere's row: of unit intensity at unit distance toward `l` (so that σ = 0 is the point
/// columns' unit-irradiance light), both lobes by each method with both clipping rules.
fn evaluate_sphere(c: &Case, lut: &Lut, v: DVec3, sigma_degrees: f64) -> String {
    let pair = lut.ltc_pair(c.alpha, v);
    let s = SphereShading::unit(v, c.l, sigma_degrees, c.alpha, c.f0, &pair);
    let mut row = c.text.clone();
    for method in SphereMethod::ALL {
        let lobes = sphere_light(method, &s);
        row += &format!(",{:e},{:e}", lobes.specular, lobes.diffuse);
    }
    row
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(rows: &str) -> Result<Vec<Case>> {
        parse_cases(&format!("{HEADER}\n{rows}"), "cases.csv").map(|c| c.rows)
    }

    #[test]
    fn good_rows_parse_blank_lines_are_skipped_and_l_is_normalized() {
        let cases = parse("0,0.27,0,0,1,0.04\n\n60, 0.5, 0.6, 0, 0.8004, 1\n").unwrap();
        assert_eq!(cases.len(), 2);
        assert_eq!(cases[0].l, DVec3::Z);
        assert!((cases[1].l.length() - 1.0).abs() < 1e-15);
        assert_eq!(cases[1].theta_o_degrees, 60.0);
    }

    #[test]
    fn a_byte_order_mark_before_the_header_is_accepted() {
        let text = format!("\u{feff}{HEADER}\n0,0.27,0,0,1,0.04\n");
        assert_eq!(parse_cases(&text, "bom.csv").unwrap().rows.len(), 1);
    }

    #[test]
    fn each_bad_row_is_refused_naming_its_line() {
        for (row, what) in [
            ("0,0.27,0,0,1", "expected 6 values"),
            ("0,nan,0,0,1,0.04", "'nan'"),
            ("0,inf,0,0,1,0.04", "'inf'"),
            ("0,0,0,0,1,0.04", "alpha"),
            ("0,1e-100,0,0,1,0.04", "got 1e-100"),
            (
                "0,0.00005,0,0,1,0.04",
                "alpha must be in [0.0001, 1], got 0.00005",
            ),
            ("0,-0.5,0,0,1,0.04", "alpha"),
            ("95,0.3,0,0,1,0.04", "theta_o"),
            ("-1,0.3,0,0,1,0.04", "theta_o"),
            ("0,0.3,0,0,1,1.5", "f0"),
            ("0,0.3,0,0,2,0.04", "unit length"),
            ("0,0.3,0,zero,1,0.04", "'zero'"),
        ] {
            let e = parse(&format!("0,0.3,0,0,1,0.04\n{row}\n")).unwrap_err();
            assert_eq!(e.input, "cases.csv line 3", "{row}");
            assert!(e.message.contains(what), "{row}: {e}");
        }
        let e = parse_cases("a,b\n", "x.csv").unwrap_err();
        assert!(e.to_string().contains("x.csv line 1") && e.message.contains("header"));
    }

    #[test]
    fn sphere_rows_take_a_sigma_in_degrees() {
        let sphere = |row: &str| parse_cases(&format!("{SPHERE_HEADER}\n{row}\n"), "s.csv");
        let cases = sphere("30,0.3,0,0,1,0.04,10").unwrap();
        assert!(cases.spheres);
        assert_eq!(cases.rows[0].sigma_degrees, Some(10.0));
        for (row, what) in [
            ("30,0.3,0,0,1,0.04", "expected 7 values"),
            ("30,0.3,0,0,1,0.04,-1", "sigma must be in [0, 90]"),
            ("30,0.3,0,0,1,0.04,91", "sigma"),
            ("30,0.3,0,0,1,0.04,nan", "'nan'"),
        ] {
            let e = sphere(row).unwrap_err();
            assert_eq!(e.input, "s.csv line 2", "{row}");
            assert!(e.message.contains(what), "{row}: {e}");
        }
    }
}
