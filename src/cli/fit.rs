//! `ltc-lab fit`: both lobes over an N×N (θo, α) table, written as the LUT (docs/design.md §2).

use std::path::{Path, PathBuf};
use std::time::Instant;

use ltc_lab::error::{Error, Result};
use ltc_lab::files::{Claim, check_writable, is_exr, write_atomically};
use ltc_lab::ltc::fit::{FitSettings, fit_table};
use ltc_lab::ltc::fit_point::{PointObjective, REFINEMENTS, fit_table_for};
use ltc_lab::ltc::lut::{Channel, Lut, Table};

use super::one_of;

mod aniso;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Cells per side (64 by default); with --aniso, nodes per axis of the 4D table (8).
    #[arg(long)]
    size: Option<usize>,
    /// classic: ltc_code's objective (luts/ltc.exr); point: the pointwise relative L1
    /// error a point light sees, from the classic fit (luts/ltc_point.exr); arrival: the
    /// same weighted by where lights above a plane arrive from (luts/ltc_arrival.exr);
    /// constrained: point with m20 = 0, no direction carried across the horizon
    /// (luts/ltc_constrained.exr).
    #[arg(long, value_parser = one_of(&Table::ALL, Table::name), default_value = "classic")]
    objective: Table,
    /// Where to write the table (OpenEXR, .exr); default the shipped file of the objective.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Replace the default output file if it exists (a file named with --out is replaced
    /// anyway: you named it). Without it, the default file is taken when the fit starts, so
    /// that one written meanwhile by another run is not replaced either.
    #[arg(long)]
    force: bool,
    /// Fit the anisotropic GGX table instead (docs/design.md §2.9): the specular lobe's LTC
    /// at every node of a 4D grid over (α_x, α_y, θo, φo), written to luts/ltc_aniso.exr by
    /// default. It keeps a checkpoint beside its output (OUT.checkpoint) as it goes.
    #[arg(long, conflicts_with = "objective")]
    aniso: bool,
    /// With --aniso: go on from the checkpoint an interrupted fit left (OUT.checkpoint).
    #[arg(long, requires = "aniso")]
    resume: bool,
}

/// Nodes per axis `fit --aniso` accepts: at least 2 (the axes divide by N − 1), at most 16
/// (16⁴ nodes take some ten hours on two cores; a file may hold up to 64).
const ANISO_SIZES: std::ops::RangeInclusive<usize> = 2..=16;

/// The table sizes `fit` accepts: at least 2 cells per axis (the axes divide by N − 1), at
/// most 1024 (a 1024² fit already takes hours on two cores).
const SIZES: std::ops::RangeInclusive<usize> = 2..=1024;

/// `size` checked against `sizes`.
fn checked_size(size: usize, sizes: &std::ops::RangeInclusive<usize>) -> Result<usize> {
    if sizes.contains(&size) {
        return Ok(size);
    }
    Err(Error::input(
        "--size",
        format!("must be in {}..={}, got {size}", sizes.start(), sizes.end()),
    ))
}

pub fn run(a: &Args) -> Result<()> {
    if a.aniso {
        return aniso::run(a);
    }
    let n = checked_size(a.size.unwrap_or(64), &SIZES)?;
    let out = output(a, Path::new(a.objective.path()))?;
    let settings = FitSettings {
        size: n,
        ..FitSettings::default()
    };
    let bar = super::progress_bar("fitting", 2 * n * n);
    let start = Instant::now();
    let (lut, at_limit) = match a.objective {
        Table::Classic => {
            let fitted = fit_table(&settings, &|| bar.inc(1));
            (fitted.lut, Some(fitted.at_iteration_limit))
        }
        point => {
            let objective = match point {
                Table::Arrival => PointObjective::Arrival,
                Table::Constrained => PointObjective::Constrained,
                _ => PointObjective::Lobe,
            };
            // Each point-fit sweep visits every cell (both lobes) once.
            bar.set_length((2 * (1 + REFINEMENTS) * n * n) as u64);
            // Warm start: the classic fit of the same cells (the shipped one at its size).
            let classic = if n == Lut::embedded().size {
                Lut::embedded().clone()
            } else {
                bar.inc_length((2 * n * n) as u64);
                fit_table(&settings, &|| bar.inc(1)).lut
            };
            let lut = fit_table_for(&classic, objective, &settings, &|| bar.inc(2));
            (lut, None)
        }
    };
    let seconds = start.elapsed().as_secs_f64();
    bar.finish_and_clear();
    let out = out.write(&lut.to_exr_bytes())?;
    eprintln!(
        "fitted {n}×{n} cells × 2 lobes in {seconds:.1} s on {} threads (α_min = {}); wrote {}",
        rayon::current_num_threads(),
        settings.alpha_min,
        out.display()
    );
    if let Some([spec, diff]) = at_limit {
        eprintln!(
            "  cells stopped at the {}-iteration limit: spec {spec}, diff {diff}",
            settings.max_iterations
        );
    }
    for c in [Channel::SpecErr, Channel::DiffErr] {
        let (mean, max, i, j) = channel_stats(&lut, c);
        eprintln!(
            "  {:<9} mean {mean:.4}  max {max:.4} at i={i} (α={:.4}), j={j} (θo={:.1}°)",
            c.name(),
            lut.alpha(i),
            lut.theta_o(j).to_degrees()
        );
    }
    Ok(())
}

/// Where the table goes: a file that is replaced, or the default name taken at the start.
enum Output {
    Replace(PathBuf),
    Claimed(Claim),
}

impl Output {
    /// Writes the table's bytes; the file written.
    fn write(self, bytes: &[u8]) -> Result<PathBuf> {
        match self {
            Self::Replace(path) => write_atomically(&path, bytes).map(|()| path),
            Self::Claimed(claim) => claim.fill(bytes),
        }
    }
}

/// The output, checked before the fit: an `.exr` in an existing directory; the default
/// file (`default`) is replaced only with `--force`, and is otherwise claimed now.
fn output(a: &Args, default: &Path) -> Result<Output> {
    let (out, named) = match &a.out {
        Some(p) => (p.clone(), true),
        None => (default.to_path_buf(), false),
    };
    if !is_exr(&out) {
        return Err(Error::input(
            out.display().to_string(),
            "the table is written as OpenEXR: the output must end in .exr",
        ));
    }
    check_writable(&out)?;
    if named || a.force {
        return Ok(Output::Replace(out));
    }
    match Claim::exactly(&out)? {
        Some(claim) => Ok(Output::Claimed(claim)),
        None => Err(Error::input(
            out.display().to_string(),
            "exists: name it with --out to replace it, or pass --force",
        )),
    }
}

/// Mean and maximum of a channel, with the maximum's cell.
fn channel_stats(lut: &Lut, c: Channel) -> (f64, f32, usize, usize) {
    let xs: Vec<f32> = lut.cells.iter().map(|cell| cell.get(c)).collect();
    let mean = xs.iter().map(|&x| f64::from(x)).sum::<f64>() / xs.len() as f64;
    let (k, max) = xs.iter().enumerate().fold(
        (0, f32::MIN),
        |acc, (k, &x)| {
            if x > acc.1 { (k, x) } else { acc }
        },
    );
    (mean, max, k % lut.size, k / lut.size)
}
