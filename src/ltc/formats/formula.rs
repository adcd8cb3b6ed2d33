//! A formula in place of the table, as source for an engine (docs/design.md §2.10): each
//! shader channel's coefficients (f32) and the range it is clamped into, as a C header, or as
//! WGSL with the formula itself. `ltc_formula_cell(i, j)` gives the texels an engine rebuilds
//! at load, as three.js PR #34611 rebuilds its textures — what the lab measures as the
//! encoding — and `ltc_formula_lookup(alpha, cos_theta_o)` is the per-lookup layout, the
//! formula read at the point itself with no texture (smoother than the rebuilt table read
//! bilinearly, by the table's own interpolation error).

use crate::ltc::formats::Header;
use crate::ltc::lut::encoding::SHADER_CHANNELS;
use crate::ltc::lut::formula::{FittedFormula, Formula};
use crate::ltc::lut::{Encoding, Lut};

/// A formula fitted to a table, with what an engine needs to rebuild it: the table's size
/// and the storage its texels are rebuilt into.
pub struct FormulaSource {
    pub name: String,
    pub fitted: FittedFormula,
    /// Cells a side of the table it is rebuilt into.
    pub size: usize,
    pub storage: &'static str,
}

impl FormulaSource {
    /// `encoding`'s formula fitted to `lut` (`None` where the encoding is no formula).
    pub fn new(lut: &Lut, encoding: Encoding) -> Option<Self> {
        let formula = encoding.formula?;
        Some(Self {
            name: encoding.name(),
            fitted: formula.fitted(lut),
            size: lut.size,
            storage: encoding.storage.name(),
        })
    }

    /// Coefficients a channel.
    fn per_channel(&self) -> usize {
        self.fitted.formula.coefficients_per_channel()
    }

    /// Every channel's coefficients, channel after channel, as the f32 an engine holds.
    fn coefficients(&self) -> Vec<f32> {
        let all = self.fitted.channels.iter().flat_map(|c| &c.coefficients);
        all.map(|&c| c as f32).collect()
    }

    /// Every channel's clamp range, `lo, hi` after each other.
    fn ranges(&self) -> Vec<f32> {
        let all = self.fitted.channels.iter().flat_map(|c| c.range);
        all.map(|x| x as f32).collect()
    }

    /// The `//` lines saying what the data is (C and WGSL both).
    fn comment(&self, header: &Header) -> String {
        let names: Vec<&str> = SHADER_CHANNELS.iter().map(|c| c.name()).collect();
        let n = self.size;
        let form = match self.fitted.formula {
            Formula::Chebyshev(d) => format!(
                "channel = sum over a, b <= {d} of c[a * {} + b] T_a(2r - 1) T_b(2s - 1), \
                 T Chebyshev's (T_0 = 1, T_1 = x, T_k+1 = 2x T_k - T_k-1)",
                d + 1
            ),
            Formula::Rational(d) => format!(
                "channel = P / Q over the products T_a(2r - 1) T_b(2s - 1), a + b <= {d}, in \
                 the order a = 0..{d}, b = 0..{d}-a: P's coefficients for every product, then \
                 Q's for every product but the first (Q's constant is 1)"
            ),
        };
        let lines = [
            format!(
                "formula: {} ({} coefficients a channel, f32; docs/design.md §2.10)",
                self.name,
                self.per_channel()
            ),
            format!("channels, in order: {}", names.join(", ")),
            form,
            "then clamped into the channel's [lo, hi]; r = sqrt(alpha), s = sqrt(1 - cos \
             theta_o), each in [0, 1]"
                .into(),
            format!(
                "rebuild: texel (i, j) of a {n} x {n} table is the formula at r = i/{m}, s = \
                 j/{m}, stored as {} (what ltc-lab measured as {})",
                self.storage,
                self.name,
                m = n - 1
            ),
        ];
        let lines = lines.iter().map(|l| format!("// {l}\n"));
        header.origin("// ") + &lines.collect::<String>() + "\n"
    }
}

/// The numbers as literals valid in C (with `suffix` `f`) and WGSL (none), eight a line.
fn number_lines(values: &[f32], suffix: &str) -> String {
    let line = |l: &[f32]| {
        let v: Vec<String> = l.iter().map(|x| format!("{x:e}{suffix}")).collect();
        format!("    {},\n", v.join(", "))
    };
    values.chunks(8).map(line).collect()
}

/// A C header: the coefficients and the ranges.
pub fn c_header(f: &FormulaSource, header: &Header) -> String {
    let (kind, degree) = kind_and_degree(f.fitted.formula);
    let mut out = f.comment(header);
    out += &format!(
        "#pragma once\n\n#define LTC_FORMULA_{kind} 1\n#define LTC_FORMULA_DEGREE {degree}\n\
         #define LTC_FORMULA_COEFFICIENTS {}\n#define LTC_FORMULA_TABLE_SIZE {}\n\n",
        f.per_channel(),
        f.size
    );
    let channels = SHADER_CHANNELS.len();
    out += &format!(
        "static const float g_ltc_formula[{channels} * LTC_FORMULA_COEFFICIENTS] = {{\n{}}};\n\n",
        number_lines(&f.coefficients(), "f")
    );
    out += &format!(
        "static const float g_ltc_formula_range[{channels} * 2] = {{\n{}}};\n",
        number_lines(&f.ranges(), "f")
    );
    out
}

/// The formula's kind as a C macro's name, and its degree.
fn kind_and_degree(formula: Formula) -> (&'static str, usize) {
    match formula {
        Formula::Chebyshev(d) => ("CHEBYSHEV", d),
        Formula::Rational(d) => ("RATIONAL", d),
    }
}

/// WGSL: the coefficients and ranges as `const` arrays, and the formula's functions.
pub fn wgsl(f: &FormulaSource, header: &Header) -> String {
    let (_, degree) = kind_and_degree(f.fitted.formula);
    let channels = SHADER_CHANNELS.len();
    let mut out = f.comment(header);
    out += &format!(
        "const LTC_FORMULA_TERMS: u32 = {}u;\nconst LTC_FORMULA_COEFFICIENTS: u32 = {}u;\n\
         const LTC_FORMULA_TABLE_SIZE: u32 = {}u;\n\n",
        degree + 1,
        f.per_channel(),
        f.size
    );
    out += &format!(
        "const LTC_FORMULA = array<f32, {}>(\n{});\n\n",
        channels * f.per_channel(),
        number_lines(&f.coefficients(), "")
    );
    out += &format!(
        "const LTC_FORMULA_RANGE = array<f32, {}>(\n{});\n\n",
        2 * channels,
        number_lines(&f.ranges(), "")
    );
    out += &wgsl_terms(degree);
    out += match f.fitted.formula {
        Formula::Chebyshev(_) => WGSL_CHEBYSHEV,
        Formula::Rational(_) => WGSL_RATIONAL,
    };
    out += WGSL_CELL_AND_LOOKUP;
    out
}

/// `ltc_formula_terms(x)`: `T_0(x) … T_D(x)` by the recurrence.
fn wgsl_terms(degree: usize) -> String {
    format!(
        "fn ltc_formula_terms(x: f32) -> array<f32, {n}> {{\n    \
         var t: array<f32, {n}>;\n    t[0] = 1.0;\n    t[1] = x;\n    \
         for (var k = 2u; k < {n}u; k++) {{ t[k] = 2.0 * x * t[k - 1u] - t[k - 2u]; }}\n    \
         return t;\n}}\n\n",
        // Two terms at least, so that `t[1]` exists at degree 1 (and the loop is empty).
        n = (degree + 1).max(2)
    )
}

/// Channel `k` of a Chebyshev series at `(r, s)`, clamped.
const WGSL_CHEBYSHEV: &str = r#"fn ltc_formula_channel(k: u32, r: f32, s: f32) -> f32 {
    let tr = ltc_formula_terms(2.0 * r - 1.0);
    let ts = ltc_formula_terms(2.0 * s - 1.0);
    let base = k * LTC_FORMULA_COEFFICIENTS;
    var sum = 0.0;
    for (var a = 0u; a < LTC_FORMULA_TERMS; a++) {
        for (var b = 0u; b < LTC_FORMULA_TERMS; b++) {
            sum += LTC_FORMULA[base + a * LTC_FORMULA_TERMS + b] * tr[a] * ts[b];
        }
    }
    return clamp(sum, LTC_FORMULA_RANGE[2u * k], LTC_FORMULA_RANGE[2u * k + 1u]);
}

"#;

/// Channel `k` of a rational function at `(r, s)`, clamped.
const WGSL_RATIONAL: &str = r#"fn ltc_formula_channel(k: u32, r: f32, s: f32) -> f32 {
    let tr = ltc_formula_terms(2.0 * r - 1.0);
    let ts = ltc_formula_terms(2.0 * s - 1.0);
    let base = k * LTC_FORMULA_COEFFICIENTS;
    // P's coefficients, one a product; Q's follow, the first product's left out.
    let products = (LTC_FORMULA_COEFFICIENTS + 1u) / 2u;
    var p = 0.0;
    var q = 1.0;
    var n = 0u;
    for (var a = 0u; a < LTC_FORMULA_TERMS; a++) {
        for (var b = 0u; a + b < LTC_FORMULA_TERMS; b++) {
            let phi = tr[a] * ts[b];
            p += LTC_FORMULA[base + n] * phi;
            if n > 0u {
                q += LTC_FORMULA[base + products + n - 1u] * phi;
            }
            n++;
        }
    }
    return clamp(p / q, LTC_FORMULA_RANGE[2u * k], LTC_FORMULA_RANGE[2u * k + 1u]);
}

"#;

/// The rebuilt texels and the per-lookup form.
const WGSL_CELL_AND_LOOKUP: &str = r#"// Texel (i, j) of the table rebuilt at load: the channels in order, then 0.
fn ltc_formula_cell(i: u32, j: u32) -> array<f32, 12> {
    let last = f32(LTC_FORMULA_TABLE_SIZE - 1u);
    var v: array<f32, 12>;
    for (var k = 0u; k < 11u; k++) {
        v[k] = ltc_formula_channel(k, f32(i) / last, f32(j) / last);
    }
    return v;
}

// The formula at the point itself (no texture): the per-lookup layout.
fn ltc_formula_lookup(alpha: f32, cos_theta_o: f32) -> array<f32, 12> {
    let r = clamp(sqrt(max(alpha, 0.0)), 0.0, 1.0);
    let s = sqrt(1.0 - clamp(cos_theta_o, 0.0, 1.0));
    var v: array<f32, 12>;
    for (var k = 0u; k < 11u; k++) {
        v[k] = ltc_formula_channel(k, r, s);
    }
    return v;
}
"#;
