//! `ltc-lab fit --aniso`: the anisotropic GGX table (docs/design.md §2.9), fitted node by
//! node with a progress bar, a checkpoint kept beside the output as it goes, and `--resume`
//! to go on from it.

use std::path::{Path, PathBuf};
use std::time::Instant;

use ltc_lab::error::{Error, Result};
use ltc_lab::files::{read_bytes, write_atomically};
use ltc_lab::ltc::aniso::fit::{
    AnisoFitSettings, FitState, MAX_CHECKPOINT_BYTES, fit_aniso_table, node_visits,
};
use ltc_lab::ltc::lut::Lut;

use super::{ANISO_SIZES, Args, checked_size, output};

/// The shipped 4D table's path.
pub const DEFAULT_OUT: &str = "luts/ltc_aniso.exr";

/// The checkpoint of a fit writing `out`.
fn checkpoint_path(out: &Path) -> PathBuf {
    let mut name = out.as_os_str().to_owned();
    name.push(".checkpoint");
    PathBuf::from(name)
}

pub fn run(a: &Args) -> Result<()> {
    let n = checked_size(a.size.unwrap_or(8), &ANISO_SIZES)?;
    let settings = AnisoFitSettings {
        dims: [n; 4],
        ..AnisoFitSettings::default()
    };
    let checkpoint = checkpoint_path(a.out.as_deref().unwrap_or(Path::new(DEFAULT_OUT)));
    let name = checkpoint.display().to_string();
    let resume = match (a.resume, checkpoint.exists()) {
        (true, true) => {
            let bytes = read_bytes(&checkpoint, MAX_CHECKPOINT_BYTES)?;
            Some(FitState::from_bytes(&bytes, &name, &settings)?)
        }
        (true, false) => {
            return Err(Error::input(&name, "no checkpoint to resume from"));
        }
        (false, true) => {
            return Err(Error::input(
                &name,
                "an interrupted fit left this checkpoint: pass --resume to go on from it, or remove it",
            ));
        }
        (false, false) => None,
    };
    let out = output(a, Path::new(DEFAULT_OUT))?;
    let bar = crate::cli::progress_bar("fitting", node_visits(&settings));
    if let Some(state) = &resume {
        bar.set_position(state.visits_done(&settings) as u64);
    }
    let start = Instant::now();
    let warned = std::sync::Once::new();
    let lut = fit_aniso_table(
        Lut::embedded_point(),
        &settings,
        resume,
        &|| bar.inc(1),
        &|state| {
            // A checkpoint that cannot be written costs only the resume: say so once, go on.
            if let Err(e) = write_atomically(&checkpoint, &state.to_bytes()) {
                warned.call_once(|| bar.suspend(|| eprintln!("warning: {e}; the fit goes on")));
            }
        },
    );
    let seconds = start.elapsed().as_secs_f64();
    bar.finish_and_clear();
    let written = out.write(&lut.to_exr_bytes())?;
    // Done: the checkpoint has served (a fit resumed from it would start from the end).
    let _ = std::fs::remove_file(&checkpoint);
    let [na, nb, nt, np] = settings.dims;
    eprintln!(
        "fitted {na}×{nb}×{nt}×{np} nodes in {seconds:.1} s on {} threads; wrote {}",
        rayon::current_num_threads(),
        written.display()
    );
    let errs: Vec<f64> = lut.cells.iter().map(|c| f64::from(c.err)).collect();
    let mean = errs.iter().sum::<f64>() / errs.len() as f64;
    let (worst, k) = errs.iter().enumerate().fold(
        (0.0, 0),
        |acc, (k, &e)| if e > acc.0 { (e, k) } else { acc },
    );
    let node = lut.nodes().nth(k).expect("a node");
    let q = lut.node(node);
    eprintln!(
        "  lobe error mean {mean:.4}  max {worst:.4} at α = ({:.4}, {:.4}), θo = {:.1}°, φo = {:.1}°",
        q.alpha.x,
        q.alpha.y,
        q.theta.to_degrees(),
        q.phi.to_degrees()
    );
    Ok(())
}
