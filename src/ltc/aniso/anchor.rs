//! The I3D 2022 tables (Kt, Heitz, Dupuy and Narayanan, "Bringing Linearly Transformed Cosines
//! to Anisotropic GGX"; `luts/i3d2022/`, MIT licence) read as an engine reads them: NumPy
//! `.npy` arrays of f32 of shape `(A, B, T, P, 3, 3)`, one forward matrix `M` per node, not
//! normalized, on their linear axes (`AnisoAxes::I3dAlphaXY`, `I3dAlphaLambda`). They hold
//! no magnitudes: a table read from them takes the lab's at the same points, as an engine
//! takes its magnitudes from a table of its own (docs/design.md §2.9).

use crate::error::{Error, Result};
use crate::ltc::aniso::{AnisoAxes, AnisoCell, AnisoLut, Stored};

/// `luts/i3d2022/alphax_alphay_theta_phi.npy`, embedded.
pub const ALPHA_XY_NPY: &[u8] = include_bytes!("../../../luts/i3d2022/alphax_alphay_theta_phi.npy");

/// `luts/i3d2022/alpha_lambda_theta_phi.npy`, embedded.
pub const ALPHA_LAMBDA_NPY: &[u8] =
    include_bytes!("../../../luts/i3d2022/alpha_lambda_theta_phi.npy");

/// The most nodes per axis a `.npy` table may claim (64⁴ matrices are 600 MB of f32), checked
/// before anything is allocated.
pub const MAX_NODES_PER_AXIS: usize = 64;

/// The NumPy format's magic string (NumPy's `format.py`, "NPY format" v1.0–3.0).
const MAGIC: &[u8] = b"\x93NUMPY";

/// Reads a `.npy` 4D table of forward matrices; `name` names it in errors.
pub fn read_npy(bytes: &[u8], name: &str, axes: AnisoAxes) -> Result<AnisoLut> {
    let bad = |why: String| Error::input(name, why);
    let (header, data) = split_header(bytes).map_err(bad)?;
    let shape = parse_header(header).map_err(bad)?;
    let dims = match shape.as_slice() {
        &[a, b, t, p, 3, 3] => [a, b, t, p],
        other => return Err(bad(format!("shape {other:?}: expected (A, B, T, P, 3, 3)"))),
    };
    if dims.iter().any(|&n| !(2..=MAX_NODES_PER_AXIS).contains(&n)) {
        return Err(bad(format!(
            "shape {dims:?}: each axis must hold 2 to {MAX_NODES_PER_AXIS} nodes"
        )));
    }
    let count = dims.iter().product::<usize>();
    if data.len() != count * 9 * 4 {
        return Err(bad(format!(
            "{} bytes of data for {count} matrices of f32 ({} expected)",
            data.len(),
            count * 36
        )));
    }
    let value = |k: usize| f32::from_le_bytes(data[4 * k..4 * k + 4].try_into().expect("4 bytes"));
    let mut lut = AnisoLut {
        axes,
        dims,
        stored: Stored::BrdfFromCos,
        cells: Vec::with_capacity(count),
    };
    for k in crate::ltc::aniso::all_nodes(dims) {
        // C order: the file's first index is α_x (our a), its fourth φ (our p).
        let [a, b, t, p] = k;
        let base = (((a * dims[1] + b) * dims[2] + t) * dims[3] + p) * 9;
        let m: [f32; 9] = std::array::from_fn(|e| value(base + e));
        if m.iter().any(|x| !x.is_finite()) {
            return Err(bad(format!("node {k:?} holds a non-finite entry")));
        }
        lut.cells.push(AnisoCell {
            m,
            norm: f32::NAN,
            fresnel: f32::NAN,
            err: f32::NAN,
        });
    }
    Ok(lut)
}

/// The header text and the data after it, from the magic and the header's length.
fn split_header(bytes: &[u8]) -> std::result::Result<(&str, &[u8]), String> {
    if bytes.len() < 10 || &bytes[..6] != MAGIC {
        return Err("not a NumPy .npy file (no \\x93NUMPY magic)".into());
    }
    let (len, start): (usize, usize) = match bytes[6] {
        1 => (usize::from(u16::from_le_bytes([bytes[8], bytes[9]])), 10),
        2 | 3 if bytes.len() >= 12 => (
            u32::from_le_bytes(bytes[8..12].try_into().expect("4 bytes")) as usize,
            12,
        ),
        v => return Err(format!(".npy format version {v} is not read")),
    };
    let end = start
        .checked_add(len)
        .filter(|&e| e <= bytes.len())
        .ok_or("the header runs past the end of the file")?;
    let header = std::str::from_utf8(&bytes[start..end]).map_err(|_| "the header is not text")?;
    Ok((header, &bytes[end..]))
}

/// The shape from a header such as `{'descr': '<f4', 'fortran_order': False, 'shape': (8, 8,
/// 8, 8, 3, 3), }`: little-endian f32 in C order only.
fn parse_header(header: &str) -> std::result::Result<Vec<usize>, String> {
    let field = |key: &str| {
        let at = header
            .find(&format!("'{key}':"))
            .ok_or(format!("the header has no '{key}'"))?;
        Ok::<&str, String>(header[at + key.len() + 3..].trim_start())
    };
    if !field("descr")?.starts_with("'<f4'") {
        return Err("the data is not little-endian f32 ('<f4')".into());
    }
    if !field("fortran_order")?.starts_with("False") {
        return Err("the data is in Fortran order; C order is read".into());
    }
    let shape = field("shape")?;
    let inner = shape
        .strip_prefix('(')
        .and_then(|s| s.split_once(')'))
        .ok_or("the shape is not a tuple")?
        .0;
    inner
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|s| s.parse::<usize>().map_err(|_| format!("shape entry '{s}'")))
        .collect()
}

/// The two published tables, each with its magnitudes read from `magnitudes` (the lab's table)
/// at its own nodes.
pub fn shipped(axes: AnisoAxes, magnitudes: &AnisoLut) -> AnisoLut {
    let (bytes, name) = match axes {
        AnisoAxes::I3dAlphaLambda => (ALPHA_LAMBDA_NPY, "luts/i3d2022/alpha_lambda_theta_phi.npy"),
        _ => (ALPHA_XY_NPY, "luts/i3d2022/alphax_alphay_theta_phi.npy"),
    };
    let mut lut =
        read_npy(bytes, name, axes).expect("the embedded tables are checked by the tests");
    lut.take_magnitudes(magnitudes);
    lut
}

impl AnisoLut {
    /// Each node's magnitudes read from `other` at the node's material and view.
    pub fn take_magnitudes(&mut self, other: &AnisoLut) {
        let nodes: Vec<[usize; 4]> = self.nodes().collect();
        for k in nodes {
            let q = self.node(k);
            let folded = other.axes.fold(q.alpha, q.view());
            let s = other.sample(&folded.point);
            let index = self.index(k);
            let cell = &mut self.cells[index];
            cell.norm = s.norm as f32;
            cell.fresnel = s.fresnel as f32;
        }
    }
}
