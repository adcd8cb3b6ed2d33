//! An encoding exported for engines (docs/design.md §2.10, `lut --export c|wgsl --encode NAME`):
//! the data, decoded as the format defines it (a formula: its coefficients evaluated), is the
//! table every measure shades with, and the WGSL validates.

use ltc_lab::ltc::formats::Header;
use ltc_lab::ltc::formats::encoded::{EncodedTable, SLOTS, c_header, wgsl};
use ltc_lab::ltc::formats::formula::{self, FormulaSource};
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

/// `T_0(x) … T_d(x)`, written here from Chebyshev's recurrence as the export's comment states it.
fn chebyshev(d: usize, x: f64) -> Vec<f64> {
    let mut t = vec![1.0, x];
    for k in 2..=d {
        t.push(2.0 * x * t[k - 1] - t[k - 2]);
    }
    t
}

/// One channel of an exported formula at `(r, s)` from its coefficients, as the header's
/// comment defines it (a series, or `P / Q` over the products `a + b ≤ D` in the order it
/// names), before the clamp; and a bound on the f32 rounding of the coefficients there (the
/// products are at most 1: Σ|c| · 2⁻²⁴, divided by `|Q|` for a ratio, with `|value|` times
/// `Q`'s own).
fn formula_at(rational: bool, d: usize, c: &[f64], r: f64, s: f64) -> (f64, f64) {
    let (tr, ts) = (chebyshev(d, 2.0 * r - 1.0), chebyshev(d, 2.0 * s - 1.0));
    let ulp = 2f64.powi(-24);
    if !rational {
        let mut sum = 0.0;
        for a in 0..=d {
            for b in 0..=d {
                sum += c[a * (d + 1) + b] * tr[a] * ts[b];
            }
        }
        return (sum, c.iter().map(|x| x.abs()).sum::<f64>() * ulp);
    }
    let products: Vec<f64> = (0..=d)
        .flat_map(|a| (0..=d - a).map(move |b| (a, b)))
        .map(|(a, b)| tr[a] * ts[b])
        .collect();
    let n = products.len();
    let p: f64 = c[..n].iter().zip(&products).map(|(c, x)| c * x).sum();
    let q = 1.0
        + c[n..]
            .iter()
            .zip(&products[1..])
            .map(|(c, x)| c * x)
            .sum::<f64>();
    let sum_abs = |c: &[f64]| c.iter().map(|x| x.abs()).sum::<f64>();
    let value = p / q;
    (
        value,
        (sum_abs(&c[..n]) + value.abs() * sum_abs(&c[n..])) * ulp / q.abs(),
    )
}

/// A formula exported: its C header's coefficients, evaluated as its comment says and clamped
/// into each channel's range, rebuild the table every measure shades with (`decoded`) —
/// within the f32 rounding of the coefficients (`formula_at`'s bound) and of the lab's own
/// values (2⁻²⁴), and for a half-float rebuild within one f16 step of the value (a rounding
/// that lands on the other side of a half step; subnormal values have f16's smallest step). The WGSL validates (naga) with both its
/// rebuild and its per-lookup form called.
#[test]
fn an_exported_formula_rebuilds_the_table_measured() {
    let lut = Lut::embedded();
    let header = Header::new(lut, "test", Some(Table::Classic));
    for (name, rational, d) in [
        ("cheb6", false, 6),
        ("cheb16-f16", false, 16),
        ("rational3", true, 3),
    ] {
        let e = Encoding::parse(name).unwrap();
        let source = FormulaSource::new(lut, e).unwrap();
        let text = formula::c_header(&source, &header);
        let floats = |array: &str| -> Vec<f64> {
            c_array(&text, array)
                .iter()
                .map(|x| x.trim_end_matches('f').parse().unwrap())
                .collect()
        };
        let (coefficients, ranges) = (floats("g_ltc_formula["), floats("g_ltc_formula_range["));
        let per_channel = coefficients.len() / SHADER_CHANNELS.len();
        let decoded = e.decoded(lut);
        let n = lut.size;
        for (index, cell) in decoded.cells.iter().enumerate() {
            let (r, s) = ((index % n) as f64 / 63.0, (index / n) as f64 / 63.0);
            for (k, &c) in SHADER_CHANNELS.iter().enumerate() {
                let own = &coefficients[k * per_channel..(k + 1) * per_channel];
                let (value, rounding) = formula_at(rational, d, own, r, s);
                let value = value.clamp(ranges[2 * k], ranges[2 * k + 1]);
                let want = cell.shaded(c);
                let storage = match e.storage {
                    // One step: 2⁻¹⁰ of the value, or f16's subnormal step 2⁻²⁴.
                    Storage::F16 => (want.abs() * 2f64.powi(-10)).max(2f64.powi(-24)),
                    _ => 0.0,
                };
                let tolerance = rounding + 2f64.powi(-24) * want.abs() + storage;
                assert!(
                    (value - want).abs() <= tolerance,
                    "{name} cell {index} {}: {value} against {want}",
                    c.name()
                );
            }
        }
        let source = formula::wgsl(&source, &header);
        let probe = "@compute @workgroup_size(1) fn main() { \
                     let v = ltc_formula_lookup(0.3, 0.5); let c = ltc_formula_cell(3u, 60u); \
                     _ = v; _ = c; }";
        crate::common::validate_wgsl(&format!("{source}\n{probe}"), name);
    }
}
