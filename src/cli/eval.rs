//! `ltc-lab eval`: the exact lobes and their LTC approximation for the cases of a CSV file.

use std::path::PathBuf;

use ltc_lab::error::{Error, Result};
use ltc_lab::files::read_text;
use ltc_lab::measure::eval::{Light, evaluate, header_of, parse_cases};

use ltc_lab::ltc::remedy::Horizon;

use super::{EncodingArgs, HORIZON_HELP, LutArgs, horizon_parser, print};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// A CSV with the header theta_o,alpha,lx,ly,lz,f0: theta_o in degrees (0–90), alpha the
    /// GGX α in (0, 1], l the unit light direction in the shading frame (n = +z, v in the
    /// xz-plane), f0 in [0, 1]. Output on stdout: those columns plus brdf_spec,brdf_diffuse,
    /// ltc_spec,ltc_diffuse — each f·cos for a unit-irradiance light and base colour 1, the
    /// LTC through the LUT's bilinear sampler with both clipping rules (eq. 30) and the
    /// --horizon remedy. With a seventh column, sigma (degrees, 0–90), each light is a sphere of
    /// that angular radius at unit distance with unit intensity, and the output columns are
    /// both lobes by exact, ltc-point, ltc-disk and representative-point (docs/design.md §1.10).
    /// With the header theta_o,alpha,f0,cx,cy,cz,ux,uy,uz,vx,vy,vz each row is a rect light of
    /// radiance 1 (centre and half-edge vectors in the shading frame, emitting toward u × v),
    /// and the columns are both lobes by exact, ltc-polygon, ltc-proxy, ltc-proxy-fast and
    /// ltc-point (docs/design.md §1.11). With theta_o,alpha,f0,cx,cy,cz,nx,ny,nz,radius each
    /// row is a disk of radiance 1 (centre, normal toward the side it lights, radius), by
    /// exact, ltc-disk and ltc-point (§1.12). With theta_o,alpha,f0,ax,ay,az,bx,by,bz,radius
    /// each row is a tube (a capsule) of radiance 1 about the segment from a to b, by exact,
    /// ltc-line, hdrp-tube, representative-point and ltc-point (§1.15). An anisotropic material (§1.13) replaces
    /// theta_o,alpha by theta_o,phi_o,alpha_x,alpha_y in any of these headers: the view at
    /// (θo, φo) in the frame whose x axis is the tangent, along which alpha_x acts, every
    /// vector in that frame; its point rows' columns are exact_spec,ltc_spec,exact_diffuse,
    /// ltc_diffuse.
    #[arg(long)]
    cases: PathBuf,
    #[command(flatten)]
    lut: LutArgs,
    #[arg(long, value_parser = horizon_parser(), default_value = "eq30", help = HORIZON_HELP)]
    horizon: Horizon,
    #[command(flatten)]
    encoding: EncodingArgs,
}

pub fn run(a: &Args) -> Result<()> {
    let text = read_text(&a.cases, ltc_lab::measure::eval::MAX_FILE_BYTES)?;
    let cases = parse_cases(&text, &a.cases.display().to_string())?;
    a.lut.check_horizon(a.horizon)?;
    if cases.kind.light != Light::Point && a.horizon != Horizon::Eq30 {
        return Err(Error::input(
            "--horizon",
            "the horizon remedies are for point lights; sphere and rect lights take eq30",
        ));
    }
    let lut = a.encoding.apply(a.lut.load_for(a.horizon)?);
    let mut out = header_of(cases.kind) + "\n";
    for c in &cases.rows {
        out.push_str(&evaluate(c, &lut, a.horizon.rule()));
        out.push('\n');
    }
    print(&out)
}
