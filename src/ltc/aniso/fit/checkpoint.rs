//! Where a 4D fit stands (docs/design.md §2.9), kept in a file so that an interrupted fit
//! goes on where it stopped: the sweep under way, the first sweep's jobs done, and every
//! node's `M⁻¹` so far. The file names the settings it was made with, and is refused under
//! any others.

use crate::error::{Error, Result};
use crate::ltc::aniso::fit::{AnisoFitSettings, index};

/// The first line of a checkpoint file.
const MAGIC: &str = "ltc-lab anisotropic fit checkpoint 1";

/// The most bytes a checkpoint file may hold (`files::read_bytes`): a 64⁴ fit's matrices
/// are 1.2 GB of f64; the lab's fits are far smaller (an 8⁴ one is 295 kB).
pub const MAX_CHECKPOINT_BYTES: u64 = 2 << 30;

/// The state of a fit between its steps.
#[derive(Clone, Debug, PartialEq)]
pub struct FitState {
    /// The settings, as text: a checkpoint resumes only the same fit.
    pub settings: String,
    /// The sweep under way: 0 the first, then the refinements, then the interpolation sweeps.
    pub sweep: usize,
    /// The first sweep's jobs done, one per `(r, θ)`.
    pub jobs_done: Vec<bool>,
    /// Each node's `M⁻¹` so far, row-major, in the table's order (zero where the first sweep
    /// has not been).
    pub matrices: Vec<[f64; 9]>,
}

impl FitState {
    /// A fit not yet begun.
    pub fn new(settings: &AnisoFitSettings) -> Self {
        let [na, _, nt, _] = settings.dims;
        Self {
            settings: format!("{settings:?}"),
            sweep: 0,
            jobs_done: vec![false; na * nt],
            matrices: vec![[0.0; 9]; settings.dims.iter().product()],
        }
    }

    /// Records the first sweep's job `job` (one `(r, θ)`): its nodes `(q, φ)`, φ fastest.
    pub fn finish_job(&mut self, job: usize, column: &[[f64; 9]], dims: [usize; 4]) {
        let [na, nb, _, np] = dims;
        let (a, t) = (job % na, job / na);
        for b in 0..nb {
            for p in 0..np {
                self.matrices[index(dims, [a, b, t, p])] = column[b * np + p];
            }
        }
        self.jobs_done[job] = true;
    }

    /// How many of a whole fit's node visits (`fit::node_visits`) are done.
    pub fn visits_done(&self, settings: &AnisoFitSettings) -> usize {
        let [_, nb, _, np] = settings.dims;
        let nodes: usize = settings.dims.iter().product();
        match self.sweep {
            0 => self.jobs_done.iter().filter(|&&d| d).count() * nb * np,
            s => s * nodes,
        }
    }

    /// The file's bytes: a text header, then the matrices as little-endian f64.
    pub fn to_bytes(&self) -> Vec<u8> {
        let jobs: String = self
            .jobs_done
            .iter()
            .map(|&d| if d { '1' } else { '0' })
            .collect();
        let mut out = format!(
            "{MAGIC}\nsettings {}\nsweep {}\njobs {jobs}\ndata\n",
            self.settings, self.sweep
        )
        .into_bytes();
        for m in &self.matrices {
            for x in m {
                out.extend_from_slice(&x.to_le_bytes());
            }
        }
        out
    }

    /// Reads a checkpoint of a fit with `settings`; `name` names it in errors.
    pub fn from_bytes(bytes: &[u8], name: &str, settings: &AnisoFitSettings) -> Result<Self> {
        let bad = |why: String| Error::input(name, why);
        let expected = Self::new(settings);
        let mut rest = bytes;
        let mut line = |what: &str| -> Result<String> {
            let end = rest
                .iter()
                .position(|&b| b == b'\n')
                .ok_or_else(|| bad(format!("cut short before its {what}")))?;
            let text = std::str::from_utf8(&rest[..end])
                .map_err(|_| bad(format!("its {what} is not text")))?
                .to_string();
            rest = &rest[end + 1..];
            Ok(text)
        };
        if line("first line")? != MAGIC {
            return Err(bad("not a checkpoint of `ltc-lab fit --aniso`".into()));
        }
        let field = |text: String, key: &str| -> Result<String> {
            text.strip_prefix(&format!("{key} "))
                .map(str::to_string)
                .ok_or_else(|| bad(format!("expected its '{key}' line")))
        };
        let saved = field(line("settings")?, "settings")?;
        if saved != expected.settings {
            return Err(bad(format!(
                "it is of another fit ({saved}); this fit's settings are {}: remove it to start over",
                expected.settings
            )));
        }
        let sweep: usize = field(line("sweep")?, "sweep")?
            .parse()
            .map_err(|_| bad("its sweep is not a number".into()))?;
        let last = settings.refinements + settings.interpolation_sweeps + 1;
        if sweep > last {
            return Err(bad(format!(
                "its sweep {sweep} is past the fit's last ({last})"
            )));
        }
        let jobs = field(line("jobs")?, "jobs")?;
        if jobs.len() != expected.jobs_done.len() || jobs.chars().any(|c| c != '0' && c != '1') {
            return Err(bad("its jobs line is not one 0 or 1 per job".into()));
        }
        if line("data line")? != "data" {
            return Err(bad("expected its 'data' line".into()));
        }
        let data = rest;
        if data.len() != expected.matrices.len() * 72 {
            return Err(bad(format!(
                "{} bytes of matrices where {} nodes take {}",
                data.len(),
                expected.matrices.len(),
                expected.matrices.len() * 72
            )));
        }
        let value =
            |k: usize| f64::from_le_bytes(data[8 * k..8 * k + 8].try_into().expect("8 bytes"));
        let matrices: Vec<[f64; 9]> = (0..expected.matrices.len())
            .map(|n| std::array::from_fn(|e| value(9 * n + e)))
            .collect();
        if matrices.iter().flatten().any(|x| !x.is_finite()) {
            return Err(bad("a matrix entry is not finite".into()));
        }
        Ok(Self {
            settings: expected.settings,
            sweep,
            jobs_done: jobs.chars().map(|c| c == '1').collect(),
            matrices,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_checkpoint_reads_back_and_refuses_another_fit_or_a_bad_file() {
        let settings = AnisoFitSettings {
            dims: [2, 3, 2, 2],
            ..AnisoFitSettings::default()
        };
        let mut state = FitState::new(&settings);
        state.finish_job(1, &vec![[1.5; 9]; 6], settings.dims);
        state.sweep = 0;
        let bytes = state.to_bytes();
        assert_eq!(FitState::from_bytes(&bytes, "c", &settings).unwrap(), state);
        let other = AnisoFitSettings {
            refinements: 5,
            ..settings
        };
        let e = FitState::from_bytes(&bytes, "c", &other).unwrap_err();
        assert!(e.message.contains("another fit"), "{e}");
        let e = FitState::from_bytes(&bytes[..bytes.len() - 3], "c", &settings).unwrap_err();
        assert!(e.message.contains("bytes of matrices"), "{e}");
        let e = FitState::from_bytes(b"hello\n", "c", &settings).unwrap_err();
        assert!(e.message.contains("not a checkpoint"), "{e}");
        let mut nan = bytes.clone();
        let n = nan.len();
        nan[n - 8..].copy_from_slice(&f64::NAN.to_le_bytes());
        assert!(FitState::from_bytes(&nan, "c", &settings).is_err());
    }
}
