//! The cases of an `eval` CSV: its rows by its header's kind, each value checked where it
//! enters (finite, in range) and every error naming the file and the line.

use glam::DVec3;

use crate::brdf::Alpha;
use crate::error::{Error, Result, number};
use crate::light::disk::Disk;
use crate::light::rect::Rect;
use crate::light::tube::Tube;
use crate::ltc::lut::ALPHA_MIN;
use crate::measure::eval::{Kind, Light};
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
    /// The rect, where the file's rows are rects.
    pub rect: Option<Rect>,
    /// The disk, where the file's rows are disks.
    pub disk: Option<Disk>,
    /// The tube, where the file's rows are tubes.
    pub tube: Option<Tube>,
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
        spheres: kind.light == Light::Sphere,
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
        rect: None,
        disk: None,
        tube: None,
        anisotropic: kind.anisotropic,
    };
    match kind.light {
        Light::Point | Light::Sphere => {
            let l = row.vector("lx", "ly", "lz");
            if (l.length() - 1.0).abs() > UNIT_TOLERANCE {
                return Err(Error::input(
                    at,
                    format!("l must be unit length, |l| = {}", number(l.length())),
                ));
            }
            case.l = l.normalize();
            if kind.light == Light::Sphere {
                let sigma =
                    row.within("sigma", 0.0..=90.0, at, "sigma must be in [0, 90] degrees")?;
                case.sigma_degrees = Some(sigma);
            }
        }
        Light::Rect => {
            let rect = Rect {
                centre: row.vector("cx", "cy", "cz"),
                u: row.vector("ux", "uy", "uz"),
                v: row.vector("vx", "vy", "vz"),
            };
            // Sizes from 1e-9 (a rect that small is its point light to far below f64's
            // rounding of the BRDF) to 1e6 (the scene's coordinates' bound), in scene units.
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
            case.l = rect.centre.normalize();
            case.rect = Some(rect);
        }
        Light::Disk => {
            let centre = row.vector("cx", "cy", "cz");
            let normal = row.vector("nx", "ny", "nz");
            let radius = row.get("radius");
            // The rect rows' bounds on the centre's distance and the size; a normal as the
            // scene file takes one (at least `scene::MIN_NORMAL` long).
            if ![centre.length(), radius]
                .iter()
                .all(|s| (1e-9..=1e6).contains(s))
            {
                return Err(Error::input(
                    at,
                    "the centre's distance and the radius must be in [1e-9, 1e6]",
                ));
            }
            if !(normal.length() >= crate::scene::MIN_NORMAL && normal.length() <= 1e6) {
                return Err(Error::input(
                    at,
                    format!(
                        "the normal must be {} to 1e6 long",
                        number(crate::scene::MIN_NORMAL)
                    ),
                ));
            }
            case.l = centre.normalize();
            case.disk = Some(Disk {
                centre,
                normal: normal.normalize(),
                radius,
            });
        }
        Light::Tube => {
            let (a, b) = (row.vector("ax", "ay", "az"), row.vector("bx", "by", "bz"));
            let radius = row.get("radius");
            // The rect rows' bounds on distances and sizes, for each end and the radius; a
            // segment of no length is a ball.
            if ![a.length(), b.length(), radius]
                .iter()
                .all(|s| (1e-9..=1e6).contains(s))
            {
                return Err(Error::input(
                    at,
                    "each end's distance and the radius must be in [1e-9, 1e6]",
                ));
            }
            case.l = (0.5 * (a + b)).try_normalize().unwrap_or(DVec3::Z);
            case.tube = Some(Tube { a, b, radius });
        }
    }
    Ok(case)
}
