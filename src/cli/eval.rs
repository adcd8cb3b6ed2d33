//! `ltc-lab eval`: the exact lobes and their LTC approximation for the cases of a CSV file.

use std::path::PathBuf;

use ltc_lab::error::{Error, Result};
use ltc_lab::files::read_text;
use ltc_lab::light::ShapeKind;
use ltc_lab::measure::eval::{Kind, evaluate, header_of, parse_cases};
use ltc_lab::render::ShapeMethod;

use ltc_lab::ltc::remedy::Horizon;

use super::{EncodingArgs, HORIZON_HELP, LutArgs, horizon_parser, print};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// A CSV of cases, its header saying what each row is (`cases_help`).
    #[arg(long, help = cases_help())]
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
    if cases.kind.light != ShapeKind::Point && a.horizon != Horizon::Eq30 {
        return Err(Error::input(
            "--horizon",
            "the horizon remedies are for point lights; lights with a size take eq30",
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

/// `--cases`' help: the point rows' header and columns, the sphere's seventh column, and each
/// emitter's header (`ShapeKind::eval_form`) with its methods, in `ShapeKind::ALL`'s order.
fn cases_help() -> String {
    let mut help = String::from(
        "A CSV with the header theta_o,alpha,lx,ly,lz,f0: theta_o in degrees (0–90), alpha the \
         GGX α in (0, 1], l the unit light direction in the shading frame (n = +z, v in the \
         xz-plane), f0 in [0, 1]. Output on stdout: those columns plus brdf_spec,brdf_diffuse,\
         ltc_spec,ltc_diffuse — each f·cos for a unit-irradiance light and base colour 1, the \
         LTC through the LUT's bilinear sampler with both clipping rules (eq. 30) and the \
         --horizon remedy. With a seventh column, sigma (degrees, 0–90), each light is a sphere \
         of that angular radius at unit distance with unit intensity, and the output columns \
         are both lobes by each sphere method (docs/design.md §1.10).",
    );
    for kind in ShapeKind::ALL
        .into_iter()
        .filter(|k| k.eval_form().is_some())
    {
        let header = Kind {
            light: kind,
            anisotropic: false,
        }
        .header();
        let methods: Vec<_> = ShapeMethod::all(kind)
            .into_iter()
            .map(ShapeMethod::name)
            .collect();
        help += &format!(
            " With the header {header} each row is {} of radiance 1, its vectors in the shading \
             frame, and the columns are both lobes by {}.",
            kind.light_noun(),
            methods.join(", ")
        );
    }
    help + " An anisotropic material (docs/design.md §1.13) replaces theta_o,alpha by \
            theta_o,phi_o,alpha_x,alpha_y in any of these headers: the view at (θo, φo) in the \
            frame whose x axis is the tangent, along which alpha_x acts, every vector in that \
            frame; its point rows' columns are exact_spec,ltc_spec,exact_diffuse,ltc_diffuse."
}
