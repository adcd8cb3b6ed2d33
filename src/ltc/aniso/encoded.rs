//! The 4D table in a storage (docs/design.md §2.10): each node's nine stored numbers and its
//! two magnitudes stored as an engine would store them (f16, or fixed point over each value's
//! own range with a scale and a bias) and read back. An encoding's size and formula are the 2D
//! table's; the 4D table keeps its own grid, as no engine resamples it.

use crate::ltc::aniso::{AnisoCell, AnisoLut};
use crate::ltc::lut::Lut;
use crate::ltc::lut::storage::{Storage, store};

/// Values a node holds for the shader: the stored matrix's nine and the two magnitudes (the
/// node's error is the lab's, not shaded).
pub const NODE_VALUES: usize = 11;

/// A node's shaded values, in `NODE_VALUES`' order.
fn values(c: &AnisoCell) -> [f64; NODE_VALUES] {
    std::array::from_fn(|k| match k {
        0..9 => f64::from(c.m[k]),
        9 => f64::from(c.norm),
        _ => f64::from(c.fresnel),
    })
}

/// `aniso` as `storage` gives it back: each of a node's values stored and read, over every
/// node (a fixed-point value's range is its own across the table). f32 is `aniso` itself.
pub fn stored_in(aniso: &AnisoLut, storage: Storage) -> AnisoLut {
    let mut out = aniso.clone();
    if storage == Storage::F32 {
        return out;
    }
    for k in 0..NODE_VALUES {
        let column: Vec<f64> = aniso.cells.iter().map(|c| values(c)[k]).collect();
        for (cell, v) in out.cells.iter_mut().zip(store(storage, &column)) {
            let v = v as f32;
            match k {
                0..9 => cell.m[k] = v,
                9 => cell.norm = v,
                _ => cell.fresnel = v,
            }
        }
    }
    out
}

/// `lut` with its 4D table in `storage` (the 2D table as it is).
pub fn with_aniso_stored(lut: Lut, storage: Storage) -> Lut {
    if storage == Storage::F32 {
        return lut;
    }
    let aniso = stored_in(lut.aniso(), storage);
    lut.with_aniso(std::sync::Arc::new(aniso))
}

/// Bytes an engine stores for a 4D table of `dims` nodes in `storage`: every node's values at
/// the storage's width, and for fixed point a scale and a bias (f32) per value.
pub fn bytes(dims: [usize; 4], storage: Storage) -> usize {
    let nodes: usize = dims.iter().product();
    let ranges = match storage.steps() {
        Some(_) => NODE_VALUES * 2 * 4,
        None => 0,
    };
    nodes * storage.bytes_of(NODE_VALUES) + ranges
}

/// Nodes whose stored numbers no longer make a proper lobe (`Stored::check`: for the lab's
/// table a pole turned away or a shape no longer positive definite), as a storage's rounding
/// can leave them.
pub fn improper_nodes(aniso: &AnisoLut) -> usize {
    aniso
        .cells
        .iter()
        .filter(|c| aniso.stored.check(c.matrix()).is_err())
        .count()
}
