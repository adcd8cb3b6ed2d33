//! The cases of an `eval` CSV: its rows by its header's kind, each value checked where it
//! enters (finite, in range) and every error naming the file and the line.

use glam::DVec3;

use crate::brdf::Alpha;
use crate::error::{Error, Result, number};
use crate::light::{Shape, ShapeKind};
use crate::ltc::lut::ALPHA_MIN;
use crate::measure::eval::Kind;
/// How far from unit length `l` may be: CSV values typed with 4 decimals are off by ~1e-4.
pub const UNIT_TOLERANCE: f64 = 1e-3;

/// The most rows `eval` takes: a million cases is a few seconds of work and ~100 MB of
/// output; a larger file is more likely a mistake than a question.
pub const MAX_ROWS: usize = 1_000_000;

/// One validated row.
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    /// The row's values as the file wrote them, echoed in the output unchanged.
    pub text: String,
    pub theta_o_degrees: f64,
    /// The view's azimuth from the tangent, degrees (0 for an isotropic row).
    pub phi_o_degrees: f64,
    /// α (α along the tangent for an anisotropic row).
    pub alpha: f64,
    /// α along the bitangent (`alpha` for an isotropic row).
    pub alpha_y: f64,
    /// Unit length (normalized after the check); a rect's or a disk's centre's direction.
    pub l: DVec3,
    pub f0: f64,
    /// The sphere's angular radius in degrees, where the file has a `sigma` column.
    pub sigma_degrees: Option<f64>,
    /// The emitter, where the file's rows are one (`ShapeKind::eval_form`): its shape and its
    /// centre, in the row's frame.
    pub emitter: Option<(Shape, DVec3)>,
    /// Whether the row is of an anisotropic header (its columns' order differs).
    pub anisotropic: bool,
}

impl Case {
    /// The row's material.
    pub fn roughness(&self) -> Alpha<f64> {
        Alpha {
            x: self.alpha,
            y: self.alpha_y,
        }
    }
}

/// A file's cases, all of one kind (by its header).
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
    let Some(kind) = Kind::ALL
        .into_iter()
        .find(|k| header.as_deref() == Some(k.header().as_str()))
    else {
        let headers: Vec<String> = Kind::ALL
            .iter()
            .map(|k| format!("'{}'", k.header()))
            .collect();
        return Err(Error::input(
            format!("{name} line 1"),
            format!("the header must be one of {}", headers.join(", ")),
        ));
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
        cases.push(parse_row(line, &format!("{name} line {}", k + 1), kind)?);
    }
    Ok(Cases {
        spheres: kind.light == ShapeKind::Sphere,
        kind,
        rows: cases,
    })
}

/// A row's values by its header's column names, each a finite number.
struct Row<'a> {
    names: Vec<&'a str>,
    fields: Vec<&'a str>,
    values: Vec<f64>,
}

impl Row<'_> {
    fn get(&self, name: &str) -> f64 {
        self.values[self
            .names
            .iter()
            .position(|n| *n == name)
            .expect("a header's column")]
    }

    /// The text of column `name`, for a message.
    fn text(&self, name: &str) -> &str {
        self.fields[self
            .names
            .iter()
            .position(|n| *n == name)
            .expect("a header's column")]
    }

    fn vector(&self, x: &str, y: &str, z: &str) -> DVec3 {
        DVec3::new(self.get(x), self.get(y), self.get(z))
    }

    /// `name` within `range`, or the message `what` with the file's text of it.
    fn within(
        &self,
        name: &str,
        range: std::ops::RangeInclusive<f64>,
        at: &str,
        what: &str,
    ) -> Result<f64> {
        let x = self.get(name);
        if range.contains(&x) {
            Ok(x)
        } else {
            Err(Error::input(at, format!("{what}, got {}", self.text(name))))
        }
    }
}

fn parse_row(line: &str, at: &str, kind: Kind) -> Result<Case> {
    let header = kind.header();
    let names: Vec<&str> = header.split(',').collect();
    let fields: Vec<&str> = line.split(',').map(str::trim).collect();
    if fields.len() != names.len() {
        return Err(Error::input(
            at,
            format!("expected {} values, found {}", names.len(), fields.len()),
        ));
    }
    let values = fields
        .iter()
        .map(|f| {
            f.parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| Error::input(at, format!("'{f}' is not a finite number")))
        })
        .collect::<Result<Vec<f64>>>()?;
    let row = Row {
        names,
        fields: fields.clone(),
        values,
    };
    let theta_o = row.within(
        "theta_o",
        0.0..=90.0,
        at,
        "theta_o must be in [0, 90] degrees",
    )?;
    // The scene's range (and the tables' α_min): below it D's peak 1/(πα²) outgrows f64 at
    // the mirror direction (α = 1e-200 gave inf and NaN).
    let alpha_range = |name: &str| {
        row.within(
            name,
            ALPHA_MIN..=1.0,
            at,
            &format!("{name} must be in [{}, 1]", number(ALPHA_MIN)),
        )
    };
    let (alpha, alpha_y, phi_o) = if kind.anisotropic {
        let phi = row.within(
            "phi_o",
            -360.0..=360.0,
            at,
            "phi_o must be in [-360, 360] degrees",
        )?;
        (alpha_range("alpha_x")?, alpha_range("alpha_y")?, phi)
    } else {
        let a = alpha_range("alpha")?;
        (a, a, 0.0)
    };
    let f0 = row.within("f0", 0.0..=1.0, at, "f0 must be in [0, 1]")?;
    let mut case = Case {
        text: fields.join(","),
        theta_o_degrees: theta_o,
        phi_o_degrees: phi_o,
        alpha,
        alpha_y,
        l: DVec3::Z,
        f0,
        sigma_degrees: None,
        emitter: None,
        anisotropic: kind.anisotropic,
    };
    match kind.light.eval_form() {
        None => {
            let l = row.vector("lx", "ly", "lz");
            if (l.length() - 1.0).abs() > UNIT_TOLERANCE {
                return Err(Error::input(
                    at,
                    format!("l must be unit length, |l| = {}", number(l.length())),
                ));
            }
            case.l = l.normalize();
            if kind.light == ShapeKind::Sphere {
                let sigma =
                    row.within("sigma", 0.0..=90.0, at, "sigma must be in [0, 90] degrees")?;
                case.sigma_degrees = Some(sigma);
            }
        }
        Some((_, read)) => {
            let (shape, centre) = read(&|name| row.get(name)).map_err(|m| Error::input(at, m))?;
            case.l = centre.try_normalize().unwrap_or(DVec3::Z);
            case.emitter = Some((shape, centre));
        }
    }
    Ok(case)
}
