//! `ltc-lab eval`: light directions from a CSV file, evaluated with the exact lobes and their
//! LTC approximation through the LUT (docs/design.md §6); with a `sigma` column, each light is
//! a sphere of that angular radius, shaded by the four methods of docs/design.md §1.10; with
//! the rect header, each row is a rect light shaded by the methods of §1.11.

use glam::DVec3;

use crate::brdf::{brdf_cos, view_from_theta};
use crate::cpu::LtcPixel;
use crate::error::{Error, Result, number};
use crate::light::rect::{Rect, RectMethod, RectShading, rect_light};
use crate::light::sphere::{SphereMethod, SphereShading, sphere_light};
use crate::ltc::lut::{ALPHA_MIN, Lut, THETA_MAX};
use crate::ltc::remedy::HorizonRule;
use crate::ltc::{Clipping, Normalization};
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
    lobe_columns(&SphereMethod::ALL.map(SphereMethod::name))
}

/// `<name>_spec,<name>_diffuse` for each method name, `-` written `_`.
fn lobe_columns(names: &[&str]) -> String {
    names
        .iter()
        .map(|n| {
            let name = n.replace('-', "_");
            format!("{name}_spec,{name}_diffuse")
        })
        .collect::<Vec<_>>()
        .join(",")
}

/// The header of rect lights: θo, α, F0, then the rect's centre and two half-edge vectors in
/// the shading frame (radiance 1, emitting toward `u × v`).
pub const RECT_HEADER: &str = "theta_o,alpha,f0,cx,cy,cz,ux,uy,uz,vx,vy,vz";

/// The columns `evaluate` adds for a rect: both lobes by each method of `RectMethod::ALL`.
pub fn rect_output_columns() -> String {
    lobe_columns(&RectMethod::ALL.map(RectMethod::name))
}

/// The output's header for input whose rows are spheres or not.
pub fn output_header(spheres: bool) -> String {
    match spheres {
        true => format!("{SPHERE_HEADER},{}", sphere_output_columns()),
        false => format!("{HEADER},{OUTPUT_COLUMNS}"),
    }
}

/// The output's header for a file of `kind`.
pub fn header_of(kind: Kind) -> String {
    match kind {
        Kind::Points => output_header(false),
        Kind::Spheres => output_header(true),
        Kind::Rects => format!("{RECT_HEADER},{}", rect_output_columns()),
    }
}

/// What a file's rows are, by its header.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Points,
    Spheres,
    Rects,
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
    /// The rect, where the file's rows are rects (`l` is then its centre's direction).
    pub rect: Option<Rect>,
}

/// A file's cases, all points or all spheres (by its header).
#[derive(Clone, Debug, PartialEq)]
pub struct Cases {
    pub spheres: bool,
    pub kind: Kind,
    pub rows: Vec<Case>,
}

/// Parses the CSV text of `name`; every error names the file and the line.
pub fn parse_cases(text: &str, name: &str) -> Result<Cases> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines = text.lines().enumerate();
    let header = lines.next().map(|(_, h)| h.trim().replace(' ', ""));
    let kind = match header.as_deref() {
        Some(HEADER) => Kind::Points,
        Some(SPHERE_HEADER) => Kind::Spheres,
        Some(RECT_HEADER) => Kind::Rects,
        _ => {
            return Err(Error::input(
                format!("{name} line 1"),
                format!("the header must be '{HEADER}', '{SPHERE_HEADER}' or '{RECT_HEADER}'"),
            ));
        }
    };
    let spheres = kind == Kind::Spheres;
    let rows = lines.filter(|(_, line)| !line.trim().is_empty());
    let mut cases = Vec::new();
    for (k, line) in rows {
        if cases.len() == MAX_ROWS {
            return Err(Error::input(
                format!("{name} line {}", k + 1),
                format!("more than {MAX_ROWS} cases: split the file"),
            ));
        }
        let at = format!("{name} line {}", k + 1);
        cases.push(match kind {
            Kind::Rects => parse_rect(line, &at)?,
            _ => parse_case(line, &at, spheres)?,
        });
    }
    Ok(Cases {
        spheres,
        kind,
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
        rect: None,
    })
}

/// A rect's row: θo, α and F0 checked as a point's; its centre and half-edges finite, its
/// centre not at the shading point, its edges neither zero nor parallel.
fn parse_rect(line: &str, at: &str) -> Result<Case> {
    let fields: Vec<&str> = line.split(',').map(str::trim).collect();
    if fields.len() != 12 {
        return Err(Error::input(
            at,
            format!("expected 12 values, found {}", fields.len()),
        ));
    }
    let mut v = [0.0; 12];
    for (x, f) in v.iter_mut().zip(&fields) {
        *x = f
            .parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| Error::input(at, format!("'{f}' is not a finite number")))?;
    }
    let [theta_o, alpha, f0, cx, cy, cz, ux, uy, uz, vx, vy, vz] = v;
    // θo, α and F0 by the point rows' own checks: a point row of the same values.
    let point = format!("{theta_o},{alpha},0,0,1,{f0}");
    let checked = parse_case(&point, at, false)?;
    let rect = Rect {
        centre: DVec3::new(cx, cy, cz),
        u: DVec3::new(ux, uy, uz),
        v: DVec3::new(vx, vy, vz),
    };
    // Sizes from 1e-9 (a rect that small is its point light to far below f64's rounding of
    // the BRDF) to 1e6 (the scene's coordinates' bound), relative to nothing: in scene units.
    let sizes = [rect.centre.length(), rect.u.length(), rect.v.length()];
    if sizes.iter().any(|&s| !(1e-9..=1e6).contains(&s)) {
        return Err(Error::input(
            at,
            "the centre's distance and each half-edge's length must be in [1e-9, 1e6]",
        ));
    }
    if rect.normal().length() <= 1e-12 * sizes[1] * sizes[2] {
        return Err(Error::input(at, "u and v are parallel: not a rect"));
    }
    Ok(Case {
        text: fields.join(","),
        l: rect.centre.normalize(),
        rect: Some(rect),
        ..checked
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
    if let Some(rect) = c.rect {
        return evaluate_rect(c, lut, v, rect);
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

/// A rect's row: of radiance 1, both lobes by each method with the lab's rules.
fn evaluate_rect(c: &Case, lut: &Lut, v: DVec3, rect: Rect) -> String {
    let pair = lut.ltc_pair(c.alpha, v);
    let s = RectShading {
        v,
        rect,
        alpha: c.alpha,
        f0: c.f0,
        ltc: &pair,
        clip: Clipping::BOTH,
        normalization: Normalization::Corrected,
    };
    let mut row = c.text.clone();
    for method in RectMethod::ALL {
        let lobes = rect_light(method, &s);
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
