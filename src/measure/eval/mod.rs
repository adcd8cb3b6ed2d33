//! `ltc-lab eval`: light directions from a CSV file, evaluated with the exact lobes and their
//! LTC approximation through the LUT (docs/design.md §6). The header says what each row is:
//! a point light, or a sphere (§1.10), a rect (§1.11), a disk (§1.12) or a tube (§1.15)
//! shaded by each of its methods; and the material isotropic (`alpha`, the view in the xz-plane) or anisotropic
//! (`alpha_x`, `alpha_y`, the view at azimuth `phi_o` from the tangent, §1.13).

mod cases;

use glam::DVec3;

use crate::brdf::{Lobes, brdf_cos_aniso};
use crate::cpu::LtcPixel;
use crate::light::disk::{Disk, DiskMethod, DiskShading, disk_light};
use crate::light::rect::{Rect, RectMethod, RectShading, rect_light};
use crate::light::sphere::{SphereMethod, SphereShading, sphere_light};
use crate::light::tube::{Tube, TubeMethod, TubeShading, tube_light};
use crate::ltc::lut::{Lut, THETA_MAX};
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
        lobe_pairs(RectMethod::ALL.map(|m| rect_light(m, &s)))
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
        lobe_pairs(DiskMethod::ALL.map(|m| disk_light(m, &s)))
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
        lobe_pairs(TubeMethod::ALL.map(|m| tube_light(m, &s)))
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
