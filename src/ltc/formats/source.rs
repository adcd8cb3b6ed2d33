//! The table as source code for an engine: a C header with both textures as float arrays,
//! and WGSL with two `const` arrays and the lookup of docs/design.md §2 (the same addressing and
//! bilinear filtering as `shaders/ltc.wgsl`, clamp-to-edge).

use crate::ltc::formats::Header;
use crate::ltc::formats::packing::Packed;

/// A float literal valid in C (with the `f` suffix) and WGSL: always with an exponent, so
/// that `0` and `1` read as floats in both, and the shortest text that reads back exactly.
fn literal(x: f32) -> String {
    format!("{x:e}")
}

/// `static const float g_ltc_1[N * N * 4]`, `g_ltc_2[…]`: four floats per cell, ltc_code's
/// order and packing.
pub fn c_header(p: &Packed, header: &Header) -> String {
    let n = p.size;
    let mut out = header.comment("// ");
    out.push_str(&format!("#pragma once\n\n#define LTC_LUT_SIZE {n}\n\n"));
    for (array, texels) in [("g_ltc_1", &p.tex1), ("g_ltc_2", &p.tex2)] {
        out.push_str(&format!(
            "static const float {array}[LTC_LUT_SIZE * LTC_LUT_SIZE * 4] = {{\n"
        ));
        for t in texels {
            let [a, b, c, d] = t.map(|x| format!("{}f", literal(x)));
            out.push_str(&format!("    {a}, {b}, {c}, {d},\n"));
        }
        out.push_str("};\n\n");
    }
    out
}

/// `const LTC_1`, `const LTC_2` and `ltc_lookup(alpha, cos_theta_o)`, with `ltc_cos_from_brdf`
/// to rebuild M⁻¹ from a filtered texel.
pub fn wgsl(p: &Packed, header: &Header) -> String {
    let n = p.size;
    let mut out = header.comment("// ");
    out.push_str(&format!("const LTC_LUT_SIZE: u32 = {n}u;\n\n"));
    for (array, texels) in [("LTC_1", &p.tex1), ("LTC_2", &p.tex2)] {
        out.push_str(&format!("const {array} = array<vec4<f32>, {}>(\n", n * n));
        for t in texels {
            let [a, b, c, d] = t.map(literal);
            out.push_str(&format!("    vec4<f32>({a}, {b}, {c}, {d}),\n"));
        }
        out.push_str(");\n\n");
    }
    out.push_str(WGSL_TAPS);
    out.push_str(WGSL_LOOKUP);
    out
}

/// Where a lookup reads, as `lut_sample_uv` and `lut_uv` in the lab's shaders address: the
/// four texels' columns and rows and the bilinear weights (every WGSL export's).
pub const WGSL_TAPS: &str = r#"// uv = (sqrt(alpha), sqrt(1 - cos theta_o)) * (N - 1)/N + 0.5/N, then bilinear filtering with
// clamp-to-edge addressing, texel centres at (k + 1/2)/N: the columns i, rows j and weights f.
struct LtcTaps {
    i: vec2<u32>,
    j: vec2<u32>,
    f: vec2<f32>,
}

fn ltc_taps(alpha: f32, cos_theta_o: f32, size: u32) -> LtcTaps {
    let n = f32(size);
    let rs = vec2<f32>(sqrt(max(alpha, 0.0)), sqrt(1.0 - clamp(cos_theta_o, 0.0, 1.0)));
    let x = (rs * ((n - 1.0) / n) + 0.5 / n) * n - 0.5;
    let x0 = floor(x);
    let last = n - 1.0;
    let i = vec2<u32>(u32(clamp(x0.x, 0.0, last)), u32(clamp(x0.x + 1.0, 0.0, last)));
    let j = vec2<u32>(u32(clamp(x0.y, 0.0, last)), u32(clamp(x0.y + 1.0, 0.0, last)));
    return LtcTaps(i, j, x - x0);
}

"#;

/// The lookup, as `lut_sample_uv` and `lut_uv` in `shaders/ltc.wgsl` do it.
const WGSL_LOOKUP: &str = r#"// One filtered texel of both textures.
struct LtcTexel {
    tex1: vec4<f32>,
    tex2: vec4<f32>,
}

fn ltc_texel(i: u32, j: u32) -> LtcTexel {
    let k = j * LTC_LUT_SIZE + i;
    return LtcTexel(LTC_1[k], LTC_2[k]);
}

fn ltc_lookup(alpha: f32, cos_theta_o: f32) -> LtcTexel {
    let t = ltc_taps(alpha, cos_theta_o, LTC_LUT_SIZE);
    let a = ltc_texel(t.i.x, t.j.x);
    let b = ltc_texel(t.i.y, t.j.x);
    let c = ltc_texel(t.i.x, t.j.y);
    let d = ltc_texel(t.i.y, t.j.y);
    return LtcTexel(
        mix(mix(a.tex1, b.tex1, t.f.x), mix(c.tex1, d.tex1, t.f.x), t.f.y),
        mix(mix(a.tex2, b.tex2, t.f.x), mix(c.tex2, d.tex2, t.f.x), t.f.y),
    );
}

// M^-1 (cos_from_brdf) from tex1, in the shading frame (n = +z, v in the xz-plane).
fn ltc_cos_from_brdf(t: LtcTexel) -> mat3x3<f32> {
    return mat3x3<f32>(
        vec3<f32>(t.tex1.x, 0.0, t.tex1.y),
        vec3<f32>(0.0, 1.0, 0.0),
        vec3<f32>(t.tex1.z, 0.0, t.tex1.w),
    );
}
"#;
