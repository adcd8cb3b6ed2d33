//! `ltc-lab lut`: a table's summary, every cell as CSV, or the error atlas.

use std::path::PathBuf;

use ltc_lab::error::Result;
use ltc_lab::ltc::lut::CHANNEL_NAMES;

use super::{LutArgs, print};

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
}

pub fn run(a: &Args) -> Result<()> {
    let lut = a.lut.load()?;
    if let Some(dir) = &a.atlas {
        let summary = ltc_lab::atlas::write_atlas(&lut, dir)?;
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
            CHANNEL_NAMES.join(" ")
        ));
    }
    let mut out = format!("i,j,alpha,theta_o,{}\n", CHANNEL_NAMES.join(","));
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
