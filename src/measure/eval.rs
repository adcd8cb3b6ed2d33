//! `ltc-lab eval`: light directions from a CSV file, evaluated with the exact lobes and their
//! LTC approximation through the LUT (docs/design.md §6). The header says what each row is:
//! a point light, or a sphere (§1.10), a rect (§1.11), a disk (§1.12) or a tube (§1.15)
//! shaded by each of its methods; and the material isotropic (`alpha`, the view in the xz-plane) or anisotropic
//! (`alpha_x`, `alpha_y`, the view at azimuth `phi_o` from the tangent, §1.13).

use glam::DVec3;

use crate::brdf::{Alpha, brdf_cos_aniso};
use crate::cpu::LtcPixel;
use crate::error::{Error, Result, number};
use crate::light::disk::{Disk, DiskMethod, DiskShading, disk_light};
use crate::light::rect::{Rect, RectMethod, RectShading, rect_light};
use crate::light::sphere::{SphereMethod, SphereShading, sphere_light};
use crate::light::tube::{Tube, TubeMethod, TubeShading, tube_light};
use crate::ltc::lut::{ALPHA_MIN, Lut, THETA_MAX};
use crate::ltc::remedy::HorizonRule;
use crate::ltc::{Clipping, Normalization};
use crate::render::{Gloss, LtcRules};

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

/// The header of rect lights: θo, α, F0, then the rect's centre and two half-edge vectors in
/// the shading frame (radiance 1, emitting toward `u × v`).
pub const RECT_HEADER: &str = "theta_o,alpha,f0,cx,cy,cz,ux,uy,uz,vx,vy,vz";

/// The header of disk lights: θo, α, F0, then the disk's centre and normal (the side it
/// emits toward; any length) in the shading frame and its radius (radiance 1).
pub const DISK_HEADER: &str = "theta_o,alpha,f0,cx,cy,cz,nx,ny,nz,radius";

/// The header of tube lights: θo, α, F0, then the segment's ends `a` and `b` in the shading
/// frame and the capsule's radius (radiance 1).
pub const TUBE_HEADER: &str = "theta_o,alpha,f0,ax,ay,az,bx,by,bz,radius";

/// The header of point lights on an anisotropic material (docs/design.md §1.13): the view at
/// `(θo, φo)` in the frame whose x axis is the tangent, along which `alpha_x` acts; `l` a
/// unit vector in that frame.
pub const ANISO_HEADER: &str = "theta_o,phi_o,alpha_x,alpha_y,lx,ly,lz,f0";

/// The columns `evaluate` adds for an anisotropic point light (the point columns' meanings).
pub const ANISO_OUTPUT_COLUMNS: &str = "exact_spec,ltc_spec,exact_diffuse,ltc_diffuse";

/// What the material and view columns of a header are: isotropic, or anisotropic.
const ISO_MATERIAL: &str = "theta_o,alpha";
const ANISO_MATERIAL: &str = "theta_o,phi_o,alpha_x,alpha_y";

/// The light a row holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Light {
    Point,
    Sphere,
    Rect,
    Disk,
    Tube,
}

/// What a file's rows are, by its header: the light, and whether the material is anisotropic.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Kind {
    pub light: Light,
    pub anisotropic: bool,
}

impl Kind {
    /// Every kind of file.
    pub const ALL: [Kind; 10] = {
        let lights = [
            Light::Point,
            Light::Sphere,
            Light::Rect,
            Light::Disk,
            Light::Tube,
        ];
        let mut all = [Kind {
            light: Light::Point,
            anisotropic: false,
        }; 10];
        let mut k = 0;
        while k < 10 {
            all[k] = Kind {
                light: lights[k % 5],
                anisotropic: k >= 5,
            };
            k += 1;
        }
        all
    };

    /// Its input header.
    pub fn header(self) -> String {
        let material = if self.anisotropic {
            ANISO_MATERIAL
        } else {
            ISO_MATERIAL
        };
        let light = match self.light {
            Light::Point => "lx,ly,lz,f0",
            Light::Sphere => "lx,ly,lz,f0,sigma",
            Light::Rect => "f0,cx,cy,cz,ux,uy,uz,vx,vy,vz",
            Light::Disk => "f0,cx,cy,cz,nx,ny,nz,radius",
            Light::Tube => "f0,ax,ay,az,bx,by,bz,radius",
        };
        format!("{material},{light}")
    }

    /// The columns `evaluate` adds.
    pub fn output_columns(self) -> String {
        match (self.light, self.anisotropic) {
            (Light::Point, false) => OUTPUT_COLUMNS.to_string(),
            (Light::Point, true) => ANISO_OUTPUT_COLUMNS.to_string(),
            (Light::Sphere, _) => sphere_output_columns(),
            (Light::Rect, _) => rect_output_columns(),
            (Light::Disk, _) => disk_output_columns(),
            (Light::Tube, _) => lobe_columns(&TubeMethod::ALL.map(TubeMethod::name)),
        }
    }
}

/// The columns `evaluate` adds for a sphere: both lobes by each method of
/// `SphereMethod::ALL`, in its order, named after it (`exact_spec,exact_diffuse,ltc_point_spec,…`).
pub fn sphere_output_columns() -> String {
    lobe_columns(&SphereMethod::ALL.map(SphereMethod::name))
}

/// The columns `evaluate` adds for a rect: both lobes by each method of `RectMethod::ALL`.
pub fn rect_output_columns() -> String {
    lobe_columns(&RectMethod::ALL.map(RectMethod::name))
}

/// The columns `evaluate` adds for a disk: both lobes by each method of `DiskMethod::ALL`.
pub fn disk_output_columns() -> String {
    lobe_columns(&DiskMethod::ALL.map(DiskMethod::name))
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

/// The output's header for input whose rows are spheres or not.
pub fn output_header(spheres: bool) -> String {
    header_of(Kind {
        light: if spheres { Light::Sphere } else { Light::Point },
        anisotropic: false,
    })
}

/// The output's header for a file of `kind`.
pub fn header_of(kind: Kind) -> String {
    format!("{},{}", kind.header(), kind.output_columns())
}

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

/// The case's row of output: its columns as read, then `f·cos` of both lobes for a
/// unit-irradiance light (a sized light of unit intensity or radiance) and base colour 1,
/// exact and through the tables' samplers with both clipping rules (eq. 30) and, for point
/// lights, the horizon rule `horizon`. The grazing row is ltc_code's `THETA_MAX`. An
/// anisotropic row's vectors are in its tangent frame; one with `alpha_x = alpha_y` is the
/// isotropic row of the same view, to the bit.
pub fn evaluate(c: &Case, lut: &Lut, horizon: HorizonRule) -> String {
    let (st, ct) = c.theta_o_degrees.to_radians().min(THETA_MAX).sin_cos();
    let (sp, cp) = c.phi_o_degrees.to_radians().sin_cos();
    let view = DVec3::new(st * cp, st * sp, ct);
    let gloss = Gloss {
        alpha: c.roughness(),
        tangent: DVec3::X,
    };
    let rules = LtcRules {
        horizon,
        ..LtcRules::default()
    };
    // The row's frame is the world here; the pixel's frame is the view's (isotropic) or the
    // tangent's (anisotropic), which are the row's own for an isotropic row.
    let px = LtcPixel::new(lut, &gloss, view, &rules);
    let to_frame = |w: DVec3| px.frame.tangent_from_world(w);
    let v = to_frame(view);
    let lobes: Vec<[f64; 2]> = if let Some(sigma) = c.sigma_degrees {
        let s = SphereShading::unit(v, to_frame(c.l), sigma, gloss.alpha, c.f0, &px.pair);
        SphereMethod::ALL
            .map(|m| sphere_light(m, &s))
            .iter()
            .map(|l| [l.specular, l.diffuse])
            .collect()
    } else if let Some(rect) = c.rect {
        let s = RectShading {
            v,
            rect: Rect {
                centre: to_frame(rect.centre),
                u: to_frame(rect.u),
                v: to_frame(rect.v),
            },
            alpha: gloss.alpha,
            f0: c.f0,
            ltc: &px.pair,
            clip: Clipping::BOTH,
            normalization: Normalization::Corrected,
        };
        RectMethod::ALL
            .map(|m| rect_light(m, &s))
            .iter()
            .map(|l| [l.specular, l.diffuse])
            .collect()
    } else if let Some(disk) = c.disk {
        let s = DiskShading {
            v,
            disk: Disk {
                centre: to_frame(disk.centre),
                normal: to_frame(disk.normal),
                radius: disk.radius,
            },
            alpha: gloss.alpha,
            f0: c.f0,
            ltc: &px.pair,
            clip: Clipping::BOTH,
            normalization: Normalization::Corrected,
        };
        DiskMethod::ALL
            .map(|m| disk_light(m, &s))
            .iter()
            .map(|l| [l.specular, l.diffuse])
            .collect()
    } else if let Some(tube) = c.tube {
        let s = TubeShading {
            v,
            tube: Tube {
                a: to_frame(tube.a),
                b: to_frame(tube.b),
                radius: tube.radius,
            },
            alpha: gloss.alpha,
            f0: c.f0,
            ltc: &px.pair,
            clip: Clipping::BOTH,
            normalization: Normalization::Corrected,
        };
        TubeMethod::ALL
            .map(|m| tube_light(m, &s))
            .iter()
            .map(|l| [l.specular, l.diffuse])
            .collect()
    } else {
        let l = to_frame(c.l);
        let exact = brdf_cos_aniso(v.to_array(), l.to_array(), gloss.alpha, c.f0);
        let approx = px.lobes(l, c.f0, &rules, || exact);
        if c.anisotropic {
            // The anisotropic rows' order: exact and LTC of each lobe.
            vec![
                [exact.specular, approx.specular],
                [exact.diffuse, approx.diffuse],
            ]
        } else {
            vec![
                [exact.specular, exact.diffuse],
                [approx.specular, approx.diffuse],
            ]
        }
    };
    let mut row = c.text.clone();
    for [a, b] in lobes {
        row += &format!(",{a:e},{b:e}");
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
