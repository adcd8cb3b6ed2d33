//! `ltc-lab eval`: light directions from a CSV file, evaluated with the exact lobes and their
//! LTC approximation through the LUT (docs/design.md §6).

use glam::DVec3;

use crate::brdf::{brdf_cos, view_from_theta};
use crate::cpu::LtcPixel;
use crate::error::{Error, Result, number};
use crate::ltc::lut::{ALPHA_MIN, Lut, THETA_MAX};
use crate::ltc::remedy::HorizonRule;
use crate::render::LtcRules;

/// The input's header: θo in degrees, α, the unit light direction in the shading frame, F0.
pub const HEADER: &str = "theta_o,alpha,lx,ly,lz,f0";

/// The columns `evaluate` adds.
pub const OUTPUT_COLUMNS: &str = "brdf_spec,brdf_diffuse,ltc_spec,ltc_diffuse";

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
}

/// Parses the CSV text of `name`; every error names the file and the line.
pub fn parse_cases(text: &str, name: &str) -> Result<Vec<Case>> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines = text.lines().enumerate();
    let header = lines.next().map(|(_, h)| h.trim().replace(' ', ""));
    if header.as_deref() != Some(HEADER) {
        return Err(Error::input(
            format!("{name} line 1"),
            format!("the header must be '{HEADER}'"),
        ));
    }
    let rows = lines.filter(|(_, line)| !line.trim().is_empty());
    let mut cases = Vec::new();
    for (k, line) in rows {
        if cases.len() == MAX_ROWS {
            return Err(Error::input(
                format!("{name} line {}", k + 1),
                format!("more than {MAX_ROWS} cases: split the file"),
            ));
        }
        cases.push(parse_case(line, &format!("{name} line {}", k + 1))?);
    }
    Ok(cases)
}

fn parse_case(line: &str, at: &str) -> Result<Case> {
    let fields: Vec<&str> = line.split(',').map(str::trim).collect();
    if fields.len() != 6 {
        return Err(Error::input(
            at,
            format!("expected 6 values, found {}", fields.len()),
        ));
    }
    let mut v = [0.0; 6];
    for (x, f) in v.iter_mut().zip(&fields) {
        *x = f
            .parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| Error::input(at, format!("'{f}' is not a finite number")))?;
    }
    let [theta_o, alpha, lx, ly, lz, f0] = v;
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
    })
}

/// The case's row of output: its columns as read, then `f·cos` of both lobes for a unit-irradiance
/// light and base colour 1, exact and through the LUT's bilinear sampler with both clipping
/// rules (eq. 30) and the horizon rule `horizon`. The grazing row is ltc_code's `THETA_MAX`.
pub fn evaluate(c: &Case, lut: &Lut, horizon: HorizonRule) -> String {
    let theta = c.theta_o_degrees.to_radians().min(THETA_MAX);
    let v = DVec3::from(view_from_theta(theta));
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

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(rows: &str) -> Result<Vec<Case>> {
        parse_cases(&format!("{HEADER}\n{rows}"), "cases.csv")
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
        assert_eq!(parse_cases(&text, "bom.csv").unwrap().len(), 1);
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
}
