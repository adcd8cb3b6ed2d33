//! An encoding exported for engines (docs/design.md §2.10, `lut --export c|wgsl --encode NAME`):
//! the data, decoded as the format defines it, is the table every measure shades with, and
//! the WGSL validates.

use ltc_lab::ltc::formats::Header;
use ltc_lab::ltc::formats::encoded::{EncodedTable, SLOTS, c_header, wgsl};
use ltc_lab::ltc::lut::encoding::SHADER_CHANNELS;
use ltc_lab::ltc::lut::{Encoding, Lut, Storage, Table};

/// The numbers between `{` and `}` after `name` in a C header.
fn c_array<'a>(text: &'a str, name: &str) -> Vec<&'a str> {
    let from = text.find(name).unwrap_or_else(|| panic!("no {name}"));
    let open = from + text[from..].find('{').unwrap();
    let close = open + text[open..].find('}').unwrap();
    text[open + 1..close]
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .collect()
}

/// One cell's values decoded from the words as the format says (the header's comments and
/// docs/design.md §2.10), written here from that definition rather than from the exporter:
/// f32 bits; two f16 a word, low half first; four 8-bit values a word, low byte first; RGB10A2
/// with R in the low bits; a fixed-point value `bias + (steps / max) · scale`.
fn decode(storage: Storage, words: &[u32], bias: &[f64], scale: &[f64]) -> Vec<f64> {
    let fixed = |k: usize, steps: u32, max: f64| bias[k] + f64::from(steps) / max * scale[k];
    match storage {
        Storage::F32 => words
            .iter()
            .map(|&w| f64::from(f32::from_bits(w)))
            .collect(),
        Storage::F16 => words
            .iter()
            .flat_map(|&w| [w & 0xffff, w >> 16])
            .map(|h| f64::from(half::f16::from_bits(h as u16)))
            .collect(),
        Storage::Unorm8 | Storage::Unorm10 => {
            // (bits a value, values a word)
            let (bits, per_word) = if storage == Storage::Unorm8 {
                (8, 4)
            } else {
                (10, 3)
            };
            let max = f64::from((1u32 << bits) - 1);
            words
                .iter()
                .flat_map(|&w| (0..per_word).map(move |b| (w >> (bits * b)) & ((1 << bits) - 1)))
                .enumerate()
                .map(|(k, q)| fixed(k, q, max))
                .collect()
        }
    }
}

/// Each storage at its own size and resampled: the C header's words, decoded, are the
/// decoded table's values — to the bit for floats; for fixed point within f32's rounding of
/// the bias and scale the header writes and of the lab's own sum (2⁻²² of their magnitudes
/// covers both with room). The WGSL with the same words validates (naga).
#[test]
fn an_exported_encoding_decodes_to_the_table_measured() {
    let lut = Lut::embedded();
    let header = Header::new(lut, "test", Some(Table::Classic));
    for name in ["f32", "f16-32", "unorm8", "unorm10-16"] {
        let e = Encoding::parse(name).unwrap();
        let table = EncodedTable::new(lut, e).unwrap();
        let text = c_header(&table, &header);
        let words: Vec<u32> = c_array(&text, "g_ltc_encoded[")
            .iter()
            .map(|w| u32::from_str_radix(&w[2..w.len() - 1], 16).unwrap())
            .collect();
        let floats = |array: &str| -> Vec<f64> {
            match e.storage.steps() {
                None => vec![0.0; SLOTS],
                Some(_) => c_array(&text, array)
                    .iter()
                    .map(|x| x.trim_end_matches('f').parse().unwrap())
                    .collect(),
            }
        };
        let (bias, scale) = (floats("g_ltc_bias["), floats("g_ltc_scale["));
        let decoded = e.decoded(lut);
        let per_cell = words.len() / decoded.cells.len();
        for (cell, w) in decoded.cells.iter().zip(words.chunks(per_cell)) {
            let values = decode(e.storage, w, &bias, &scale);
            assert_eq!(values.len(), SLOTS, "{name}");
            for (k, &c) in SHADER_CHANNELS.iter().enumerate() {
                let want = cell.shaded(c);
                let tolerance = match e.storage.steps() {
                    None => 0.0,
                    Some(_) => 2f64.powi(-22) * (bias[k].abs() + scale[k].abs() + want.abs()),
                };
                assert!(
                    (values[k] - want).abs() <= tolerance,
                    "{name} {}: {} against {want}",
                    c.name(),
                    values[k]
                );
            }
            assert_eq!(values[SLOTS - 1], 0.0, "{name}: the padding");
        }
        let source = wgsl(&table, &header);
        let probe = "@compute @workgroup_size(1) fn main() { let v = ltc_encoded_lookup(0.3, 0.5); _ = v; }";
        crate::common::validate_wgsl(&format!("{source}\n{probe}"), name);
    }
    assert!(EncodedTable::new(lut, Encoding::parse("cheb16").unwrap()).is_err());
}
