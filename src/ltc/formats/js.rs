//! ltc_code's JavaScript arrays (`fit/export.h`, `writeJS` → `results/ltc.js`):
//! `var g_ltc_1 = [` then four numbers per cell, `];`, and the same for `g_ltc_2`. three.js
//! copies the same arrays as `LTC_MAT_1` and `LTC_MAT_2` (`RectAreaLightTexturesLib.js`).

use crate::error::{Error, Result, number};
use crate::ltc::formats::Header;
use crate::ltc::formats::packing::Packed;
use crate::ltc::lut::check_size;

/// The arrays' names: ltc_code's, then three.js's.
const NAMES: [[&str; 2]; 2] = [["g_ltc_1", "g_ltc_2"], ["LTC_MAT_1", "LTC_MAT_2"]];

/// Whether `text` looks like the JavaScript tables (for recognising a file by its content).
pub fn looks_like(text: &str) -> bool {
    NAMES.iter().flatten().any(|n| text.contains(n))
}

/// Reads both arrays; errors name the file and say what is wrong.
pub fn read(text: &str, name: &str) -> Result<Packed> {
    let names = NAMES
        .iter()
        .find(|pair| text.contains(pair[0]))
        .ok_or_else(|| Error::input(name, "no array g_ltc_1 (ltc_code's first texture)"))?;
    let tex1 = array(text, names[0], name)?;
    let tex2 = array(text, names[1], name).map_err(|e| {
        Error::input(
            name,
            format!("{} (ltc_code's second texture, the magnitudes)", e.message),
        )
    })?;
    let size = square_side(tex1.len(), names[0], name)?;
    if tex2.len() != tex1.len() {
        return Err(Error::input(
            name,
            format!(
                "{} holds {} cells but {} holds {}: both textures have one texel per cell",
                names[0],
                tex1.len(),
                names[1],
                tex2.len()
            ),
        ));
    }
    Ok(Packed { size, tex1, tex2 })
}

/// The side of a square table of `cells` cells (at least 2×2, at most `MAX_SIZE`²).
pub fn square_side(cells: usize, what: &str, name: &str) -> Result<usize> {
    let n = (cells as f64).sqrt().round() as usize;
    if n.checked_mul(n) != Some(cells) {
        return Err(Error::input(
            name,
            format!("{what} holds {cells} cells, not the N×N (N ≥ 2) of a table"),
        ));
    }
    check_size(n, n).map_err(|m| Error::input(name, format!("{what}: {m}")))
}

/// The numbers between `<array> = [` and `]`, four to a cell.
fn array(text: &str, array: &str, name: &str) -> Result<Vec<[f32; 4]>> {
    let start = text
        .find(array)
        .ok_or_else(|| Error::input(name, format!("no array {array}")))?;
    let rest = &text[start + array.len()..];
    let open = rest
        .find('[')
        .ok_or_else(|| Error::input(name, format!("{array} has no '['")))?;
    let body = &rest[open + 1..];
    let close = body
        .find(']')
        .ok_or_else(|| Error::input(name, format!("{array} has no closing ']'")))?;
    let numbers = body[..close]
        .split([',', ' ', '\n', '\r', '\t'])
        .filter(|t| !t.is_empty())
        .enumerate()
        .map(|(k, t)| {
            t.parse::<f32>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| {
                    Error::input(
                        name,
                        format!("{array} entry {k}: '{t}' is not a finite number"),
                    )
                })
        })
        .collect::<Result<Vec<f32>>>()?;
    if numbers.len() % 4 != 0 {
        return Err(Error::input(
            name,
            format!("{array} holds {} numbers, not four per cell", numbers.len()),
        ));
    }
    Ok(numbers
        .chunks_exact(4)
        .map(|c| [c[0], c[1], c[2], c[3]])
        .collect())
}

/// The arrays as ltc_code writes them, after a comment header.
pub fn write(p: &Packed, header: &Header) -> String {
    let mut out = header.comment("// ");
    for (array, texels) in [("g_ltc_1", &p.tex1), ("g_ltc_2", &p.tex2)] {
        out.push_str(&format!("var {array} = [\n"));
        for t in texels {
            out.push_str(&format!(
                "{}, {}, {}, {}, \n",
                number(t[0]),
                number(t[1]),
                number(t[2]),
                number(t[3])
            ));
        }
        out.push_str("];\n");
    }
    out
}
