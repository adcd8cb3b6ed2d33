//! A table as a file (docs/design.md §2.5): one OpenEXR layer of N×N f32 pixels, a channel per
//! `Channel`, α_min in a header attribute; its size checked before anything is allocated.

use std::io::Cursor;
use std::path::Path;

use exr::prelude::*;

use crate::error::{Error, Result};
use crate::files::write_atomically;
use crate::ltc::lut::{Channel, Lut, LutCell};

/// The largest table this program reads, in cells per side, checked before anything is
/// allocated: 4096² cells hold 940 MB as f32 (14 channels), 64 times the shipped 64² per axis
/// and 4 times the largest `ltc-lab fit` makes (1024); a file that claims more is refused.
pub const MAX_SIZE: usize = 4096;

/// Refuses a table side outside `2..=MAX_SIZE`, naming what claimed it.
pub fn check_size(width: usize, height: usize) -> std::result::Result<usize, String> {
    if width != height || width < 2 {
        return Err(format!(
            "the table is {width}×{height}: a table is square, at least 2×2"
        ));
    }
    if width > MAX_SIZE {
        return Err(format!(
            "the table claims {width}×{width} cells: this program reads tables of at most {MAX_SIZE}×{MAX_SIZE}"
        ));
    }
    Ok(width)
}

/// The fewest bytes an OpenEXR chunk takes: its 8-byte entry in the offset table, and its
/// y coordinate and data size (4 bytes each) before any data.
const EXR_MIN_CHUNK_BYTES: usize = 16;

/// The header attribute that records α_min (the `alpha` of column 0).
const ALPHA_MIN_ATTRIBUTE: &str = "ltc.alpha_min";

/// What an EXR's header claims, checked before its pixels are allocated: every layer within
/// `MAX_SIZE`, and the file long enough for the chunks it declares (a header claiming 100000²
/// over a 4×4 body would otherwise allocate 40 GB first).
fn check_exr_header(bytes: &[u8]) -> std::result::Result<(), String> {
    // Unreadable headers are left to the full reader, which says what is wrong.
    let Ok(meta) = exr::meta::MetaData::read_from_buffered(Cursor::new(bytes), false) else {
        return Ok(());
    };
    let mut chunks = 0usize;
    for header in &meta.headers {
        let size = header.layer_size;
        check_size(size.width(), size.height())?;
        chunks = chunks.saturating_add(header.chunk_count);
    }
    let least = chunks.saturating_mul(EXR_MIN_CHUNK_BYTES);
    if bytes.len() < least {
        return Err(format!(
            "its header declares {chunks} chunks (at least {least} bytes) but the file holds {} bytes: it is cut short or its header is wrong",
            bytes.len()
        ));
    }
    Ok(())
}

impl Lut {
    /// Reads and validates a LUT file; errors name the file.
    pub fn read(path: &Path) -> Result<Lut> {
        let name = path.display().to_string();
        let bytes = crate::files::read_bytes(path, super::MAX_FILE_BYTES)?;
        Lut::from_exr_bytes(&bytes, &name)
    }

    pub fn from_exr_bytes(bytes: &[u8], name: &str) -> Result<Lut> {
        let bad = |m: String| Error::input(name, m);
        check_exr_header(bytes).map_err(bad)?;
        let image = read()
            .no_deep_data()
            .largest_resolution_level()
            .all_channels()
            .first_valid_layer()
            .all_attributes()
            .from_buffered(Cursor::new(bytes))
            .map_err(|e| bad(format!("not a readable OpenEXR LTC table ({e})")))?;
        let layer = &image.layer_data;
        let (w, h) = (layer.size.width(), layer.size.height());
        check_size(w, h).map_err(bad)?;
        // Written as f64 by this project; another writer may use f32.
        let alpha_min = match layer.attributes.other.get(&Text::from(ALPHA_MIN_ATTRIBUTE)) {
            Some(AttributeValue::F64(a)) => *a,
            Some(AttributeValue::F32(a)) => f64::from(*a),
            Some(other) => {
                return Err(bad(format!(
                    "attribute {ALPHA_MIN_ATTRIBUTE} is not a number ({other:?})"
                )));
            }
            None => return Err(bad(format!("attribute {ALPHA_MIN_ATTRIBUTE} is missing"))),
        };
        if !(alpha_min > 0.0 && alpha_min < 1.0) {
            return Err(bad(format!(
                "attribute {ALPHA_MIN_ATTRIBUTE} must be in (0, 1), got {}",
                crate::error::number(alpha_min)
            )));
        }
        let mut cells = vec![LutCell([0.0; Channel::COUNT]); w * h];
        for c in Channel::ALL {
            let Some(channel) = layer
                .channel_data
                .list
                .iter()
                .find(|ch| ch.name == *c.name())
            else {
                // docs/design.md §2.4's 13 channels make a complete table: without the point
                // fit's scale, the magnitudes are used as they are.
                if c == Channel::SpecScale {
                    cells.iter_mut().for_each(|cell| cell.0[c as usize] = 1.0);
                    continue;
                }
                return Err(bad(format!("channel {} is missing", c.name())));
            };
            let FlatSamples::F32(samples) = &channel.sample_data else {
                return Err(bad(format!("channel {} is not 32-bit float", c.name())));
            };
            for (k, &x) in samples.iter().enumerate() {
                if !x.is_finite() {
                    return Err(bad(format!(
                        "channel {} at cell (i={}, j={}) is {x}",
                        c.name(),
                        k % w,
                        k / w
                    )));
                }
                cells[k].0[c as usize] = x;
            }
        }
        let lut = Lut {
            nl_terms: Default::default(),
            aniso: None,
            size: w,
            alpha_min,
            cells,
        };
        lut.validate().map_err(bad)?;
        Ok(lut)
    }

    pub fn to_exr_bytes(&self) -> Vec<u8> {
        let n = self.size;
        let channels = Channel::ALL
            .iter()
            .map(|&c| {
                AnyChannel::new(
                    c.name(),
                    FlatSamples::F32(self.cells.iter().map(|cell| cell.get(c)).collect()),
                )
            })
            .collect();
        let mut attributes = LayerAttributes::named("ltc");
        attributes.other.insert(
            Text::from(ALPHA_MIN_ATTRIBUTE),
            AttributeValue::F64(self.alpha_min),
        );
        crate::ltc::exr_bytes::layer_bytes((n, n), attributes, channels)
    }

    /// Writes the table to `path` (atomically: no partial file on failure).
    pub fn write(&self, path: &Path) -> Result<()> {
        write_atomically(path, &self.to_exr_bytes())
    }
}
