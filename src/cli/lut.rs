//! `ltc-lab lut`: a table's summary, every cell as CSV, or the error atlas.

use std::path::PathBuf;

use ltc_lab::error::{Error, Result};
use ltc_lab::files::check_distinct;
use ltc_lab::ltc::formats::dds::Precision;
use ltc_lab::ltc::formats::{Export, Header, export};
use ltc_lab::ltc::lut::Channel;
use ltc_lab::measure::atlas::atlas_files;

use super::{LutArgs, one_of, print};

#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    lut: LutArgs,
    /// Print every cell as CSV: i,j,alpha,theta_o (degrees), then the channels.
    #[arg(long)]
    dump: bool,
    /// Write the error atlas into this directory (made if missing): heat maps of spec.err and
    /// diff.err, the error of one light orbiting a point, and their CSVs.
    #[arg(long)]
    atlas: Option<PathBuf>,
    /// Write the table in another layout: ltc-code-js (ltc_code's ltc.js), ltc-code-dds
    /// (its ltc_1.dds and ltc_2.dds), c (a header) or wgsl (const arrays and a lookup). The
    /// point table's fitted scale is folded into the magnitudes.
    #[arg(long, value_parser = one_of(&Export::ALL, Export::name), requires = "out")]
    export: Option<Export>,
    /// Where --export writes: a file, or for ltc-code-dds a directory (made if missing).
    #[arg(long, requires = "export")]
    out: Option<PathBuf>,
    /// Texels of ltc-code-dds: f16 (RGBA16F, as ltc_code writes them) or f32 (RGBA32F).
    #[arg(long, value_parser = one_of(&Precision::ALL, Precision::name), default_value = "f16")]
    precision: Precision,
}

pub fn run(a: &Args) -> Result<()> {
    check_export_beside_atlas(a)?;
    // The dump and the atlas show spec.err; the summary and an export do not need it.
    let lut = if a.dump || a.atlas.is_some() {
        a.lut.load_measured()?
    } else {
        a.lut.load()?
    };
    if let (Some(format), Some(out)) = (a.export, &a.out) {
        let shipped = a.lut.lut.is_none().then_some(a.lut.table());
        let header = Header::new(&lut, &a.lut.describe(), shipped);
        let written = export(&lut, &header, format, a.precision, out)?;
        let names: Vec<String> = written.iter().map(|p| p.display().to_string()).collect();
        eprintln!("wrote {}", names.join(", "));
        if a.atlas.is_none() && !a.dump {
            return Ok(());
        }
    }
    if a.export.is_some() && a.out.is_none() {
        return Err(Error::input("--export", "needs --out"));
    }
    if let Some(dir) = &a.atlas {
        let summary = ltc_lab::measure::atlas::write_atlas(&lut, dir)?;
        print(
            &summary
                .lines
                .iter()
                .map(|l| format!("{l}\n"))
                .collect::<String>(),
        )?;
        eprintln!("wrote the atlas into {}", dir.display());
        if !a.dump {
            return Ok(());
        }
    }
    if !a.dump {
        return print(&format!(
            "{}: {}×{} cells, α_min = {}, channels: {}\npass --dump for every cell as CSV\n",
            a.lut.describe(),
            lut.size,
            lut.size,
            lut.alpha_min,
            channel_names().join(" ")
        ));
    }
    let mut out = format!("i,j,alpha,theta_o,{}\n", channel_names().join(","));
    for j in 0..lut.size {
        for i in 0..lut.size {
            let values: Vec<String> = lut.cell(i, j).0.iter().map(f32::to_string).collect();
            out.push_str(&format!(
                "{i},{j},{},{},{}\n",
                lut.alpha(i),
                lut.theta_o(j).to_degrees(),
                values.join(",")
            ));
        }
    }
    print(&out)
}

/// A file export must be neither the atlas directory nor one of its files: one output would
/// replace the other, or fail after the first was written.
fn check_export_beside_atlas(a: &Args) -> Result<()> {
    let (Some(format), Some(out), Some(dir)) = (a.export, &a.out, &a.atlas) else {
        return Ok(());
    };
    // ltc-code-dds writes a directory of its own names, none of them an atlas file.
    if matches!(format, Export::LtcCodeDds) {
        return Ok(());
    }
    let files: Vec<PathBuf> = atlas_files().iter().map(|f| dir.join(f)).collect();
    let mut outputs = vec![("--atlas", dir.as_path())];
    outputs.extend(files.iter().map(|f| ("--atlas", f.as_path())));
    outputs.push(("--out", out.as_path()));
    check_distinct(&outputs)
}

/// The channels' names in a cell's order.
fn channel_names() -> Vec<&'static str> {
    Channel::ALL.map(Channel::name).to_vec()
}
