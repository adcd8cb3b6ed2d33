//! `ltc-lab study`: every shading variant timed and measured against the exact image, and
//! the error by light elevation of its tables; `study.csv`, the Pareto chart `study.png` and
//! `horizon.csv` land together or not at all.

use std::path::{Path, PathBuf};
use std::time::Instant;

use ltc_lab::error::{Error, Result, number};
use ltc_lab::files::Outputs;
use ltc_lab::gpu::GpuContext;
use ltc_lab::horizon;
use ltc_lab::ltc::Clipping;
use ltc_lab::ltc::lut::{ALPHA_MIN, Lut};
use ltc_lab::study;

use super::{CullArgs, LutArgs, Range, check_frames_and_lights, parse_size, print};

/// The directory `study` writes into unless told otherwise.
const DEFAULT_DIR: &str = "study";
const FILES: [&str; 3] = ["study.csv", "study.png", "horizon.csv"];

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Directory for study.csv, study.png and horizon.csv (made if missing; files in it are
    /// replaced). Default: ./study, or the first of study-2, study-3… that holds none, taken
    /// when the study starts so that two studies at once never share one.
    #[arg(long)]
    out: Option<PathBuf>,
    #[arg(long, default_value = "320x180", value_parser = parse_size)]
    size: (usize, usize),
    #[arg(long, value_delimiter = ',', default_value = "100,1000")]
    lights: Vec<usize>,
    #[arg(long, value_delimiter = ',', default_value = "0.1,0.27,0.6")]
    alpha: Vec<f64>,
    /// Timed frames per variant (median, after one warm-up).
    #[arg(long, default_value_t = 5)]
    frames: usize,
    #[command(flatten)]
    culling: CullArgs,
    /// The table of the variants that shade with the shipped one (ltc, ltc-fast, ltc-paper,
    /// ltc-nearest, ltc-f16).
    #[command(flatten)]
    lut: LutArgs,
}

pub fn run(a: &Args) -> Result<()> {
    check_frames_and_lights(a.frames, &a.lights)?;
    // The scene's range: a material below α_min is refused everywhere else.
    let alphas = ALPHA_MIN..=1.0;
    if let Some(&alpha) = a.alpha.iter().find(|x| !alphas.contains(*x)) {
        return Err(Error::input(
            "--alpha",
            format!(
                "each α must be in [{}, 1], got {}",
                number(ALPHA_MIN),
                number(alpha)
            ),
        ));
    }
    let lut = a.lut.load()?;
    let mut out = match &a.out {
        Some(d) => Outputs::new(d, &FILES)?,
        None => Outputs::claim_free_directory(Path::new(DEFAULT_DIR), &FILES)?,
    };
    let dir = out.dir().to_path_buf();
    let ctx = GpuContext::new()?;
    ltc_lab::bench::check(&ctx, &a.lights, a.size).map_err(super::flag_of)?;
    let device = ctx.describe();
    eprintln!("study on {device}");
    let start = Instant::now();
    let settings = study::StudySettings {
        size: a.size,
        lights: a.lights.clone(),
        alphas: a.alpha.clone(),
        frames: a.frames,
        culls: a.culling.cull.clone(),
        range: Range::or_default(a.culling.range),
    };
    let rows = study::run(&ctx, &lut, &settings, |r| {
        eprintln!(
            "  α {:<5} {:>6} lights cull {:>3} {:>13}: {:9.3} ms, rel RMSE {:.2e}, p99 {:.2e}",
            r.alpha,
            r.lights,
            if r.cull { "on" } else { "off" },
            r.variant,
            r.ms_median,
            r.rel_rmse,
            r.p99_rel_err
        );
    })?;
    let csv = study::csv(&rows);
    out.stage("study.csv", csv.as_bytes())?;
    out.stage("study.png", &study::pareto_png(&rows, &ctx.info.name)?)?;
    out.stage("horizon.csv", horizon_csv(&lut, &a.lut.name()).as_bytes())?;
    out.commit()?;
    eprintln!(
        "study done in {:.0} s; wrote {}/study.csv, study.png and horizon.csv",
        start.elapsed().as_secs_f64(),
        dir.display()
    );
    print(&csv)
}

/// The error by light elevation (docs/design.md §4.7) of the study's two tables: `lut`, which
/// `ltc`, `ltc-fast`, `ltc-paper`, `ltc-nearest` and `ltc-f16` shade with (named `name`), and
/// the point fit of `ltc-point` and `ltc-fast-point`; with eq. 30's rules.
fn horizon_csv(lut: &Lut, name: &str) -> String {
    let mut text = String::from("table,rules,band,cases,specular,diffuse,specular_energy\n");
    // A path may hold a comma: the CSV's own separator.
    let name = name.replace(',', ";");
    for (table, lut) in [(name.as_str(), lut), ("point", Lut::embedded_point())] {
        let bands = horizon::band_errors(lut, Clipping::BOTH, horizon::CASES, horizon::SEED);
        text.push_str(&horizon::csv_rows(&format!("{table},eq30,"), &bands));
    }
    text
}
