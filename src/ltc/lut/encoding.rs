//! A table's encoding (docs/design.md §2.10): how an engine stores the table for its shader —
//! a storage format for each value and a table size, or a formula its cells are rebuilt from —
//! and the table as that encoding gives it back, so that every measure can shade with what an
//! engine would read.

use crate::ltc::aniso::encoded::{improper_nodes, with_aniso_stored};
pub use crate::ltc::lut::channel::SHADER_CHANNELS;
use crate::ltc::lut::formula::Formula;
pub use crate::ltc::lut::storage::{Quantized, Storage, half_of, store};
use crate::ltc::lut::{Channel, Lut, LutCell};

/// The table sizes an encoding may resample to: the shipped 64² and each halving down to 8²
/// (below 8 cells the α axis no longer has a cell inside the specular range that matters).
pub const SIZES: [usize; 4] = [64, 32, 16, 8];

/// A storage and a table size (`None`: the table's own), or a formula whose values are
/// rebuilt into the table's own cells in that storage.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Encoding {
    pub storage: Storage,
    pub size: Option<usize>,
    pub formula: Option<Formula>,
}

impl Encoding {
    /// Every storage at every size of `SIZES`, for a table of `size` cells a side (its own
    /// size written as none): the encodings `lut --encodings` measures.
    pub fn tables(size: usize) -> Vec<Self> {
        Storage::ALL
            .into_iter()
            .flat_map(|storage| {
                SIZES.map(|n| Self {
                    storage,
                    size: (n != size).then_some(n),
                    formula: None,
                })
            })
            .collect()
    }

    /// `STORAGE` or `STORAGE-SIZE` (`f16`, `unorm8-16`), or `FORMULA` or `FORMULA-STORAGE`
    /// (`cheb16`, `cheb16-f16`, `rational4`); an error naming what is wrong.
    pub fn parse(text: &str) -> Result<Self, String> {
        let (head, tail) = match text.split_once('-') {
            Some((h, t)) => (h, Some(t)),
            None => (text, None),
        };
        if let Some(formula) = Formula::parse(head) {
            let formula = formula?;
            let storage = match tail {
                None => Storage::F32,
                Some(t) => Storage::from_name(t).ok_or_else(|| {
                    format!(
                        "`{text}`: a formula is rebuilt into a storage, one of {}, not `{t}`",
                        Storage::ALL.map(Storage::name).join(", ")
                    )
                })?,
            };
            return Ok(Self {
                storage,
                size: None,
                formula: Some(formula),
            });
        }
        let (storage, size) = match text.split_once('-') {
            Some((s, n)) => (s, Some(n)),
            None => (text, None),
        };
        let storage = Storage::from_name(storage).ok_or_else(|| {
            format!(
                "`{text}`: the storage is one of {} (with -SIZE, one of {:?}, to resample), or a \
                 formula, chebD or rationalD",
                Storage::ALL.map(Storage::name).join(", "),
                SIZES
            )
        })?;
        let size = match size {
            None => None,
            Some(n) => match n.parse::<usize>() {
                Ok(n) if SIZES.contains(&n) => Some(n),
                _ => return Err(format!("`{text}`: the size is one of {SIZES:?}, not `{n}`")),
            },
        };
        Ok(Self {
            storage,
            size,
            formula: None,
        })
    }

    /// Its name, as `parse` reads it.
    pub fn name(&self) -> String {
        match (self.formula, self.size) {
            (Some(f), _) if self.storage == Storage::F32 => f.name(),
            (Some(f), _) => format!("{}-{}", f.name(), self.storage.name()),
            (None, Some(n)) => format!("{}-{n}", self.storage.name()),
            (None, None) => self.storage.name().to_string(),
        }
    }

    /// Bytes an engine stores for a table of `size` cells a side in this encoding: the
    /// shader's channels at the storage's width, and a scale and a bias (f32) per channel
    /// for fixed-point values. A formula ships its coefficients (f32) and each channel's
    /// range (two f32s, its clamp) instead; the table it rebuilds at run time is not shipped.
    pub fn bytes(&self, size: usize) -> usize {
        if let Some(f) = self.formula {
            let f = f.for_size(size);
            return 4 * f.coefficients() + SHADER_CHANNELS.len() * 2 * 4;
        }
        let n = self.size.unwrap_or(size);
        let values = n * n * self.storage.cell_bytes();
        let ranges = match self.storage.steps() {
            Some(_) => SHADER_CHANNELS.len() * 2 * 4,
            None => 0,
        };
        values + ranges
    }

    /// `lut` as an engine storing it in this encoding reads it back: resampled to the size
    /// (bilinearly, as its sampler would read the full table there), then each value of the
    /// shader's channels stored and read. The errors and `spec.scale` are kept as they were
    /// (the stored magnitudes carry the scale); f32 at the table's own size is `lut` itself.
    /// A formula's table is its values at the table's own cells, then stored. The 4D table
    /// takes the storage alone, at its own grid (`aniso::encoded`).
    pub fn decoded(&self, lut: &Lut) -> Lut {
        let mut out = self.prepared(lut);
        if self.storage == Storage::F32 && self.formula.is_none() {
            return out;
        }
        // The cells change: a correction fitted to the old ones would not fit them.
        out.nl_terms = Default::default();
        for c in SHADER_CHANNELS {
            let values: Vec<f64> = out.cells.iter().map(|cell| cell.shaded(c)).collect();
            let stored = store(self.storage, &values);
            for (cell, v) in out.cells.iter_mut().zip(stored) {
                cell.set_shaded(c, v);
            }
        }
        with_aniso_stored(out, self.storage)
    }

    /// The table before its values are stored: resampled to the encoding's size, or a
    /// formula's values at the table's cells.
    pub fn prepared(&self, lut: &Lut) -> Lut {
        match (self.formula, self.size) {
            (Some(f), _) => f.fitted(lut).rebuilt(lut),
            (None, Some(n)) if n != lut.size => resampled(lut, n),
            _ => lut.clone(),
        }
    }

    /// `decoded`, with what was clamped said in words (`None` where nothing was). A formula's
    /// degree lowered to what a small table can be fitted with is said too, and
    /// cells the encoding turns inside out (a formula's ringing, 8 bits' rounding).
    pub fn decoded_saying(&self, lut: &Lut) -> (Lut, Option<String>) {
        let clamped = self.clamped(lut);
        let mut notes = Vec::new();
        if clamped > 0 {
            notes.push(format!(
                "{clamped} values of the table lie past what {} holds and were clamped to it",
                self.name()
            ));
        }
        if let Some(f) = self.formula.filter(|f| f.for_size(lut.size) != *f) {
            notes.push(format!(
                "a {}² table holds no more than {}: {} was fitted as that",
                lut.size,
                f.for_size(lut.size).name(),
                f.name()
            ));
        }
        let decoded = self.decoded(lut);
        let inside_out = decoded.inside_out_cells();
        if inside_out > 0 {
            notes.push(format!(
                "{inside_out} cells of {}'s table have an M⁻¹ flat or turned inside out \
                 (determinant ≤ 0), where its error passes the small entries near α → 0 or \
                 grazing; they are shaded as an engine would shade them",
                self.name()
            ));
        }
        let improper = improper_nodes(decoded.aniso());
        if improper > 0 {
            notes.push(format!(
                "{improper} of the 4D table's {} nodes in {} no longer hold a proper lobe (their \
                 smallest entries, near α → 0, round away); they are shaded as an engine would \
                 shade them",
                decoded.aniso().cells.len(),
                self.storage.name()
            ));
        }
        let note = (!notes.is_empty()).then(|| notes.join("; "));
        (decoded, note)
    }

    /// How many of `lut`'s shaded values lie past what the storage holds (f16's largest
    /// finite value, 65 504): `decoded` clamps them to it, and the command line says so.
    pub fn clamped(&self, lut: &Lut) -> usize {
        if self.storage != Storage::F16 {
            return 0;
        }
        let limit = f64::from(half::f16::MAX);
        lut.cells
            .iter()
            .flat_map(|cell| SHADER_CHANNELS.map(|c| cell.shaded(c)))
            .filter(|v| v.abs() > limit)
            .count()
    }
}

/// `lut` at `size` cells a side: each new cell the full table bilinearly filtered at the
/// cell's place on the axes (docs/design.md §2.3: cell `i` of any size sits at `i/(N−1)`).
pub fn resampled(lut: &Lut, size: usize) -> Lut {
    let mut cells = Vec::with_capacity(size * size);
    for j in 0..size {
        for i in 0..size {
            let at = |k: usize| k as f64 / (size - 1) as f64;
            let (u, v) = lut.uv_of_axes(at(i), at(j));
            // As the sampler filters them: the specular magnitudes as the products it
            // shades with, stored back divided by the filtered scale (set after it).
            let filtered = lut.sample_uv(u, v);
            let mut cell = LutCell(Channel::ALL.map(|c| filtered.get(c) as f32));
            for c in [Channel::SpecNorm, Channel::SpecFresnel] {
                cell.set_shaded(c, filtered.get(c));
            }
            cells.push(cell);
        }
    }
    Lut {
        size,
        alpha_min: lut.alpha_min,
        cells,
        nl_terms: Default::default(),
        aniso: lut.aniso.clone(),
    }
}
