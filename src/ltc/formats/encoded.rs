//! A table in one of its encodings as an engine ships it (docs/design.md §2.10), as a C header
//! or as WGSL with its decoding: the fewest-sampler layout's texels — the eleven shader
//! channels and a zero, three RGBA texels a cell (four RGB10A2, which hold three values) — in
//! the encoding's storage, with each fixed-point channel's bias and scale. The values decode to
//! the table `Encoding::decoded` gives, which every measure shades with.

use crate::ltc::formats::Header;
use crate::ltc::formats::source::WGSL_TAPS;
use crate::ltc::lut::encoding::{SHADER_CHANNELS, half_of};
use crate::ltc::lut::{Encoding, Lut, Storage};

/// Values a cell holds: the shader channels and one zero, so that RGBA texels are whole.
pub const SLOTS: usize = 12;

/// A table's texels in an encoding's storage.
#[derive(Clone, Debug, PartialEq)]
pub struct EncodedTable {
    pub name: String,
    pub size: usize,
    pub storage: Storage,
    /// Per cell (`j·N + i`), `SLOTS` raw values: f32 bits, f16 bits, or a fixed-point
    /// value's whole steps above its channel's bias.
    pub slots: Vec<u32>,
    /// Per slot, fixed point only: value = `bias + unorm · scale`, `unorm` the steps over the
    /// storage's steps (what `unpack4x8unorm` gives), `scale = max − min`.
    pub bias: [f64; SLOTS],
    pub scale: [f64; SLOTS],
}

impl EncodedTable {
    /// `lut` in `encoding`; a formula is not a table of texels (its coefficients are its
    /// data), and is refused.
    pub fn new(lut: &Lut, encoding: Encoding) -> Result<Self, String> {
        if encoding.formula.is_some() {
            return Err(format!(
                "{} is a formula: its texels are made at run time; export a table encoding",
                encoding.name()
            ));
        }
        let table = encoding.prepared(lut);
        let cells = table.cells.len();
        let mut slots = vec![0u32; cells * SLOTS];
        let (mut bias, mut scale) = ([0.0; SLOTS], [0.0; SLOTS]);
        for (k, &c) in SHADER_CHANNELS.iter().enumerate() {
            let values: Vec<f64> = table.cells.iter().map(|cell| cell.shaded(c)).collect();
            let raw: Vec<u32> = match encoding.storage {
                Storage::F32 => values.iter().map(|&v| (v as f32).to_bits()).collect(),
                Storage::F16 => values
                    .iter()
                    .map(|&v| half_of(v).to_bits().into())
                    .collect(),
                Storage::Unorm8 | Storage::Unorm10 => {
                    let q = encoding.storage.quantized(&values).expect("fixed point");
                    bias[k] = q.bias;
                    scale[k] = q.step * encoding.storage.steps().unwrap_or(1.0);
                    q.steps
                }
            };
            for (cell, r) in raw.into_iter().enumerate() {
                slots[cell * SLOTS + k] = r;
            }
        }
        Ok(Self {
            name: encoding.name(),
            size: table.size,
            storage: encoding.storage,
            slots,
            bias,
            scale,
        })
    }

    /// Texels a cell: the layers of the texture array.
    pub fn layers(&self) -> usize {
        SLOTS.div_ceil(self.storage.values_per_texel())
    }

    /// The texels as the words a shader reads, layer by layer within each cell: f32 bits
    /// (four words a texel), two f16 a word (two words a texel), four 8-bit values a word (R
    /// lowest), or RGB10A2 (R in bits 0–9, G 10–19, B 20–29).
    pub fn words(&self) -> Vec<u32> {
        let cells = self.slots.chunks(SLOTS);
        match self.storage {
            Storage::F32 => self.slots.clone(),
            Storage::F16 => self.slots.chunks(2).map(|p| p[0] | (p[1] << 16)).collect(),
            Storage::Unorm8 => self
                .slots
                .chunks(4)
                .map(|p| p[0] | (p[1] << 8) | (p[2] << 16) | (p[3] << 24))
                .collect(),
            Storage::Unorm10 => cells
                .flat_map(|cell| cell.chunks(3).map(|p| p[0] | (p[1] << 10) | (p[2] << 20)))
                .collect(),
        }
    }

    /// The export's comment: the table's header and what the data is, as `//` lines (C and
    /// WGSL both).
    fn comment(&self, header: &Header) -> String {
        let lines = self.describe().into_iter().map(|l| format!("// {l}\n"));
        header.origin("// ") + &lines.collect::<String>() + "\n"
    }

    /// The lines of what the data is.
    fn describe(&self) -> Vec<String> {
        let names: Vec<&str> = SHADER_CHANNELS.iter().map(|c| c.name()).collect();
        vec![
            format!(
                "encoding: {} ({} values, {} texels a cell as layers; docs/design.md §2.10)",
                self.name,
                self.storage.name(),
                self.layers()
            ),
            format!("values a cell, in order: {}, 0", names.join(", ")),
            "spec.norm and spec.fresnel carry spec.scale; M^-1 = mat3(vec3(m00, 0, m20), \
             vec3(0, 1, 0), vec3(m02, 0, m22)) (columns)"
                .into(),
        ]
    }
}

/// The words as hexadecimal literals (C and WGSL both read `0x…u`), eight a line.
fn word_lines(words: &[u32]) -> String {
    let line = |l: &[u32]| {
        let w: Vec<String> = l.iter().map(|w| format!("0x{w:08x}u")).collect();
        format!("    {},\n", w.join(", "))
    };
    words.chunks(8).map(line).collect()
}

/// A C header: the words, and for fixed point each value's bias and scale.
pub fn c_header(t: &EncodedTable, header: &Header) -> String {
    let mut out = t.comment(header);
    let n = t.size;
    out += &format!(
        "#pragma once\n#include <stdint.h>\n\n#define LTC_ENCODED_SIZE {n}\n#define LTC_ENCODED_LAYERS {}\n\n",
        t.layers()
    );
    let words = t.words();
    out += &format!(
        "static const uint32_t g_ltc_encoded[{}] = {{\n",
        words.len()
    );
    out += &word_lines(&words);
    out += "};\n";
    if t.storage.steps().is_some() {
        for (name, values) in [("bias", &t.bias), ("scale", &t.scale)] {
            let v: Vec<String> = values.iter().map(|&x| format!("{:e}f", x as f32)).collect();
            out += &format!(
                "\n// value = bias + unorm * scale, unorm = steps / {}\nstatic const float g_ltc_{name}[{SLOTS}] = {{ {} }};\n",
                t.storage.steps().unwrap_or(1.0),
                v.join(", ")
            );
        }
    }
    out
}

/// WGSL: the words as a `const` array, each fixed-point value's bias and scale, and
/// `ltc_encoded_lookup(alpha, cos_theta_o)`, the twelve values bilinearly filtered with
/// clamp-to-edge addressing as `lut_sample_uv` in the lab's shaders filters them.
pub fn wgsl(t: &EncodedTable, header: &Header) -> String {
    let mut out = t.comment(header);
    let words = t.words();
    out += &format!(
        "const LTC_ENCODED_SIZE: u32 = {}u;\nconst LTC_ENCODED = array<u32, {}>(\n",
        t.size,
        words.len()
    );
    out += &word_lines(&words);
    out += ");\n\n";
    let array = |values: &[f64; SLOTS]| {
        let v: Vec<String> = values.iter().map(|&x| format!("{:e}", x as f32)).collect();
        format!("array<f32, {SLOTS}>({})", v.join(", "))
    };
    out += &format!(
        "const LTC_ENCODED_BIAS = {};\nconst LTC_ENCODED_SCALE = {};\n\n",
        array(&t.bias),
        array(&t.scale)
    );
    out += &format!("{}\n{WGSL_TAPS}{WGSL_LOOKUP}", wgsl_cell(t.storage));
    out
}

/// `ltc_encoded_cell(i, j)`: one cell's twelve values, decoded from the words.
fn wgsl_cell(storage: Storage) -> String {
    let body = match storage {
        Storage::F32 => {
            "    let base = (j * LTC_ENCODED_SIZE + i) * 12u;\n    \
             for (var k = 0u; k < 12u; k++) { v[k] = bitcast<f32>(LTC_ENCODED[base + k]); }\n"
        }
        Storage::F16 => {
            "    let base = (j * LTC_ENCODED_SIZE + i) * 6u;\n    \
             for (var k = 0u; k < 6u; k++) {\n        \
             let h = unpack2x16float(LTC_ENCODED[base + k]);\n        \
             v[2u * k] = h.x;\n        v[2u * k + 1u] = h.y;\n    }\n"
        }
        Storage::Unorm8 => {
            "    let base = (j * LTC_ENCODED_SIZE + i) * 3u;\n    \
             for (var k = 0u; k < 3u; k++) {\n        \
             let u = unpack4x8unorm(LTC_ENCODED[base + k]);\n        \
             for (var c = 0u; c < 4u; c++) {\n            \
             v[4u * k + c] = LTC_ENCODED_BIAS[4u * k + c] + u[c] * LTC_ENCODED_SCALE[4u * k + c];\n        \
             }\n    }\n"
        }
        Storage::Unorm10 => {
            "    let base = (j * LTC_ENCODED_SIZE + i) * 4u;\n    \
             for (var k = 0u; k < 4u; k++) {\n        \
             let w = LTC_ENCODED[base + k];\n        \
             for (var c = 0u; c < 3u; c++) {\n            \
             let u = f32((w >> (10u * c)) & 0x3ffu) / 1023.0;\n            \
             v[3u * k + c] = LTC_ENCODED_BIAS[3u * k + c] + u * LTC_ENCODED_SCALE[3u * k + c];\n        \
             }\n    }\n"
        }
    };
    format!(
        "// One cell's twelve values (the channels of the header, then 0).\n\
         fn ltc_encoded_cell(i: u32, j: u32) -> array<f32, 12> {{\n    \
         var v: array<f32, 12>;\n{body}    return v;\n}}\n"
    )
}

/// The lookup: the twelve values at the four texels `ltc_taps` names, filtered.
const WGSL_LOOKUP: &str = r#"fn ltc_encoded_lookup(alpha: f32, cos_theta_o: f32) -> array<f32, 12> {
    let t = ltc_taps(alpha, cos_theta_o, LTC_ENCODED_SIZE);
    let a = ltc_encoded_cell(t.i.x, t.j.x);
    let b = ltc_encoded_cell(t.i.y, t.j.x);
    let c = ltc_encoded_cell(t.i.x, t.j.y);
    let d = ltc_encoded_cell(t.i.y, t.j.y);
    var v: array<f32, 12>;
    for (var k = 0u; k < 12u; k++) {
        v[k] = mix(mix(a[k], b[k], t.f.x), mix(c[k], d[k], t.f.x), t.f.y);
    }
    return v;
}
"#;
