//! `ltc-lab eval`: light directions from a CSV file, evaluated with the exact lobes and their
//! LTC approximation through the LUT (docs/design.md §6). The header says what each row is:
//! a point light, or a light with a size (a sphere, §1.10; an emitter of its module's columns,
//! `ShapeKind::eval_form`: a rect, §1.11, a disk, §1.12…) shaded by each of its methods; and the material isotropic (`alpha`, the view in the xz-plane) or anisotropic
//! (`alpha_x`, `alpha_y`, the view at azimuth `phi_o` from the tangent, §1.13).

mod cases;

use glam::DVec3;

use crate::brdf::{Lobes, brdf_cos_aniso};
use crate::cpu::LtcPixel;
use crate::light::sphere::{SphereMethod, SphereShading, sphere_light};
use crate::light::{EmitterShading, ExactRule, ShapeKind};
use crate::ltc::lut::{Lut, THETA_MAX};
use crate::ltc::remedy::HorizonRule;
use crate::ltc::{Clipping, Normalization};
use crate::render::{Gloss, LtcRules, ShapeMethod};

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

/// The header of point lights on an anisotropic material (docs/design.md §1.13): the view at
/// `(θo, φo)` in the frame whose x axis is the tangent, along which `alpha_x` acts; `l` a
/// unit vector in that frame.
pub const ANISO_HEADER: &str = "theta_o,phi_o,alpha_x,alpha_y,lx,ly,lz,f0";

/// The columns `evaluate` adds for an anisotropic point light (the point columns' meanings).
pub const ANISO_OUTPUT_COLUMNS: &str = "exact_spec,ltc_spec,exact_diffuse,ltc_diffuse";

/// What the material and view columns of a header are: isotropic, or anisotropic.
const ISO_MATERIAL: &str = "theta_o,alpha";
const ANISO_MATERIAL: &str = "theta_o,phi_o,alpha_x,alpha_y";

/// What a file's rows are, by its header: the light's shape (a point's and a sphere's rows
/// are a direction, every other shape's its module's columns), and whether the material is
/// anisotropic.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Kind {
    pub light: ShapeKind,
    pub anisotropic: bool,
}

impl Kind {
    /// Every kind of file: each shape's, isotropic then anisotropic.
    pub const ALL: [Kind; 2 * ShapeKind::ALL.len()] = {
        let n = ShapeKind::ALL.len();
        let mut all = [Kind {
            light: ShapeKind::Point,
            anisotropic: false,
        }; 2 * ShapeKind::ALL.len()];
        let mut k = 0;
        while k < 2 * n {
            all[k] = Kind {
                light: ShapeKind::ALL[k % n],
                anisotropic: k >= n,
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
        let light = match (self.light, self.light.eval_form()) {
            (ShapeKind::Sphere, _) => "lx,ly,lz,f0,sigma",
            (_, Some((columns, _))) => return format!("{material},f0,{columns}"),
            (_, None) => "lx,ly,lz,f0",
        };
        format!("{material},{light}")
    }

    /// The columns `evaluate` adds: a point's, or both lobes by each of the shape's methods.
    pub fn output_columns(self) -> String {
        match (self.light, self.anisotropic) {
            (ShapeKind::Point, false) => OUTPUT_COLUMNS.to_string(),
            (ShapeKind::Point, true) => ANISO_OUTPUT_COLUMNS.to_string(),
            (kind, _) => {
                let names: Vec<_> = ShapeMethod::all(kind)
                    .into_iter()
                    .map(ShapeMethod::name)
                    .collect();
                lobe_columns(&names)
            }
        }
    }
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
        light: if spheres {
            ShapeKind::Sphere
        } else {
            ShapeKind::Point
        },
        anisotropic: false,
    })
}

/// The output's header for a file of `kind`.
pub fn header_of(kind: Kind) -> String {
    format!("{},{}", kind.header(), kind.output_columns())
}

pub use cases::{Case, Cases, MAX_ROWS, UNIT_TOLERANCE, parse_cases};

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
        lobe_pairs(SphereMethod::ALL.map(|m| sphere_light(m, &s)))
    } else if let Some((shape, centre)) = c.emitter {
        let s = EmitterShading {
            v,
            alpha: gloss.alpha,
            f0: c.f0,
            ltc: &px.pair,
            clip: Clipping::BOTH,
            normalization: Normalization::Corrected,
        };
        let kind = shape.kind();
        let rule = ExactRule::Nodes(kind.exact_nodes());
        ShapeMethod::all(kind)
            .into_iter()
            .filter_map(|m| m.emitter_lobes((shape, centre), &to_frame, &s, rule))
            .map(|(l, _)| [l.specular, l.diffuse])
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

/// Each method's lobes as the row's (specular, diffuse) pair, in the methods' order.
fn lobe_pairs<const N: usize>(lobes: [Lobes<f64>; N]) -> Vec<[f64; 2]> {
    lobes.iter().map(|l| [l.specular, l.diffuse]).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Result;

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
