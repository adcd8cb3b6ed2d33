// LTC evaluation, the LUT sampler and the horizon rules, mirroring src/ltc/mod.rs,
// src/ltc/lut/sample.rs, src/ltc/nl_fit.rs and src/ltc/remedy.rs (same names). Composed after
// brdf.wgsl (uses PI).

// Clipping rule bits (src/ltc/mod.rs Clipping).
const CLIP_HORIZON: u32 = 1u;
const CLIP_TRANSFORMED: u32 = 2u;
// src/ltc/mod.rs Normalization.
const NORMALIZATION_CORRECTED: u32 = 0u;
const NORMALIZATION_PAPER_LITERAL: u32 = 1u;

// The LUT as pack_lut packs it (src/gpu/ltc.rs): per cell four vec4s —
// [spec m00 m02 m20 m22], [diff m00 m02 m20 m22],
// [scale·spec.norm scale·spec.fresnel diff.norm spec.scale] (the products filtered, as an
// exported table stores them), and the nl-fit correction [spec c0 c1, diff c0 c1].
@group(0) @binding(2) var<storage, read> lut: array<vec4<f32>>;

const LUT_VEC4S_PER_CELL: u32 = 4u;

// src/ltc/remedy.rs HorizonRule.
const HORIZON_EQ30: u32 = 0u;
const HORIZON_NL_FIT: u32 = 1u;
const HORIZON_EXACT_BAND: u32 = 2u;
// EXACT_BAND_Z: sin 15°.
const EXACT_BAND_Z: f32 = 0.25881904;
// NL_BAND_Z: sin 30°.
const NL_BAND_Z: f32 = 0.5;

// Read the nearest cell instead of filtering (the `ltc-nearest` variant; src/render/mod.rs LutFilter).
override LUT_NEAREST: bool = false;

// One lobe: M⁻¹ (cos_from_brdf), |det M⁻¹|, its magnitudes and the fitted scale on them.
struct Ltc {
    cos_from_brdf: mat3x3<f32>,
    det_cos_from_brdf: f32,
    norm: f32,
    fresnel: f32,
    scale: f32,
}

struct LtcPair {
    spec: Ltc,
    diff: Ltc,
}

// Ltc::ltc_eval: D(l) = max(ω'.z, 0)|det M⁻¹| / (π (ω'·ω')²), ω' = M⁻¹ l, with the chosen
// clipping rules; the paper-literal normalization drops the 1/π.
fn ltc_eval(ltc: Ltc, l: vec3<f32>, clip: u32, normalization: u32) -> f32 {
    if (clip & CLIP_HORIZON) != 0u && l.z <= 0.0 {
        return 0.0;
    }
    let w = ltc.cos_from_brdf * l;
    if (clip & CLIP_TRANSFORMED) != 0u && w.z <= 0.0 {
        return 0.0;
    }
    let len2 = dot(w, w);
    if len2 <= 0.0 {
        return 0.0;
    }
    let d = w.z * ltc.det_cos_from_brdf / (len2 * len2);
    if normalization == NORMALIZATION_PAPER_LITERAL {
        return d;
    }
    return d / PI;
}

// M⁻¹ = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]] from its four stored entries.
fn cos_from_brdf_from_entries(m: vec4<f32>) -> mat3x3<f32> {
    // WGSL matrices are built from columns.
    return mat3x3<f32>(
        vec3<f32>(m.x, 0.0, m.z),
        vec3<f32>(0.0, 1.0, 0.0),
        vec3<f32>(m.y, 0.0, m.w),
    );
}

// One texel of the table: its first three vec4s (the fourth is read by nl_sample_*).
struct LutTexel {
    spec_m: vec4<f32>,
    diff_m: vec4<f32>,
    norms: vec4<f32>,
}

// Texel (i, j) of the table of `size` cells per side that starts at vec4 `base` (table A at 0;
// table B, where two tables are compared, after it).
fn lut_texel(i: u32, j: u32, size: u32, base: u32) -> LutTexel {
    let k = base + (j * size + i) * LUT_VEC4S_PER_CELL;
    return LutTexel(lut[k], lut[k + 1u], lut[k + 2u]);
}

// The two texels along each axis (clamped into the table) and the weights of the second.
struct Taps {
    i: vec2<u32>,
    j: vec2<u32>,
    f: vec2<f32>,
}

// lut::bilinear_taps on both axes at uv, for a table of `size` cells per side.
fn bilinear_taps(uv: vec2<f32>, size: u32) -> Taps {
    let x = uv * f32(size) - 0.5;
    let x0 = floor(x);
    let last = f32(size - 1u);
    let i = vec2<u32>(u32(clamp(x0.x, 0.0, last)), u32(clamp(x0.x + 1.0, 0.0, last)));
    let j = vec2<u32>(u32(clamp(x0.y, 0.0, last)), u32(clamp(x0.y + 1.0, 0.0, last)));
    return Taps(i, j, x - x0);
}

// Lut::sample_uv: bilinear filtering with clamp-to-edge addressing, done in the shader so
// that it is the CPU sampler exactly (hardware filtering uses 8-bit weights on many GPUs).
fn lut_sample_uv(uv: vec2<f32>, size: u32, base: u32) -> LutTexel {
    let t = bilinear_taps(uv, size);
    let f = t.f;
    let a = lut_texel(t.i.x, t.j.x, size, base);
    let b = lut_texel(t.i.y, t.j.x, size, base);
    let c = lut_texel(t.i.x, t.j.y, size, base);
    let d = lut_texel(t.i.y, t.j.y, size, base);
    return LutTexel(
        mix(mix(a.spec_m, b.spec_m, f.x), mix(c.spec_m, d.spec_m, f.x), f.y),
        mix(mix(a.diff_m, b.diff_m, f.x), mix(c.diff_m, d.diff_m, f.x), f.y),
        mix(mix(a.norms, b.norms, f.x), mix(c.norms, d.norms, f.x), f.y),
    );
}

// nl_fit::nl_sample_uv: the nl-fit correction filtered as lut_sample_uv filters the cells.
fn nl_sample_uv(uv: vec2<f32>, size: u32, base: u32) -> vec4<f32> {
    let t = bilinear_taps(uv, size);
    let at = base + 3u;
    let a = lut[at + (t.j.x * size + t.i.x) * LUT_VEC4S_PER_CELL];
    let b = lut[at + (t.j.x * size + t.i.y) * LUT_VEC4S_PER_CELL];
    let c = lut[at + (t.j.y * size + t.i.x) * LUT_VEC4S_PER_CELL];
    let d = lut[at + (t.j.y * size + t.i.y) * LUT_VEC4S_PER_CELL];
    return mix(mix(a, b, t.f.x), mix(c, d, t.f.x), t.f.y);
}

// nl_fit::nl_sample_nearest: the correction of the cell whose texel contains uv.
fn nl_sample_nearest(uv: vec2<f32>, size: u32, base: u32) -> vec4<f32> {
    let k = vec2<u32>(clamp(floor(uv * f32(size)), vec2<f32>(0.0), vec2<f32>(f32(size - 1u))));
    return lut[base + (k.y * size + k.x) * LUT_VEC4S_PER_CELL + 3u];
}

// The nl-fit correction at (α, cos θo), read as the table is (nearest or bilinear).
fn lut_nl_terms(alpha: f32, cos_theta_o: f32, size: u32, base: u32) -> vec4<f32> {
    let uv = lut_uv(alpha, cos_theta_o, size);
    if LUT_NEAREST {
        return nl_sample_nearest(uv, size, base);
    }
    return nl_sample_uv(uv, size, base);
}

// nl_fit::nl_weight: w(z) = max(0, 1 + t (c0 + c1 t)), t = max(0, 1 − z / NL_BAND_Z).
fn nl_weight(c: vec2<f32>, z: f32) -> f32 {
    let t = max(1.0 - z / NL_BAND_Z, 0.0);
    return max(1.0 + t * (c.x + c.y * t), 0.0);
}

// remedy::in_exact_band: 0 < n·l < EXACT_BAND_Z.
fn in_exact_band(z: f32) -> bool {
    return z > 0.0 && z < EXACT_BAND_Z;
}

// Lut::sample_nearest: the cell whose texel contains uv.
fn lut_sample_nearest(uv: vec2<f32>, size: u32, base: u32) -> LutTexel {
    let k = vec2<u32>(clamp(floor(uv * f32(size)), vec2<f32>(0.0), vec2<f32>(f32(size - 1u))));
    return lut_texel(k.x, k.y, size, base);
}

// Lut::uv: (r, sqrt(1 − cos θo)) · (N−1)/N + 0.5/N, r = sqrt(α).
fn lut_uv(alpha: f32, cos_theta_o: f32, size: u32) -> vec2<f32> {
    let n = f32(size);
    let rs = vec2<f32>(sqrt(max(alpha, 0.0)), sqrt(1.0 - clamp(cos_theta_o, 0.0, 1.0)));
    return rs * ((n - 1.0) / n) + 0.5 / n;
}

// Lut::ltc_pair: both lobes at (α, cos θo); the specular magnitudes divided by the filtered
// scale, as LutSample::ltc_pair does, so that scale × norm is the filtered product.
fn lut_ltc_pair(alpha: f32, cos_theta_o: f32, size: u32, base: u32) -> LtcPair {
    let uv = lut_uv(alpha, cos_theta_o, size);
    var t: LutTexel;
    if LUT_NEAREST {
        t = lut_sample_nearest(uv, size, base);
    } else {
        t = lut_sample_uv(uv, size, base);
    }
    let spec = cos_from_brdf_from_entries(t.spec_m);
    let diff = cos_from_brdf_from_entries(t.diff_m);
    return LtcPair(
        Ltc(spec, abs(determinant(spec)), t.norms.x / t.norms.w, t.norms.y / t.norms.w, t.norms.w),
        Ltc(diff, abs(determinant(diff)), t.norms.z, 0.0, 1.0),
    );
}

// LtcPair::spec_magnitude: F0 n_s + (1 − F0) f_s, times the fitted scale.
fn spec_magnitude(pair: LtcPair, f0: f32) -> f32 {
    return pair.spec.scale * (f0 * pair.spec.norm + (1.0 - f0) * pair.spec.fresnel);
}

// Ltc::magnitude: scale × norm (the diffuse lobe's magnitude).
fn magnitude(ltc: Ltc) -> f32 {
    return ltc.scale * ltc.norm;
}

// lobe_weights: each lobe's magnitude (specular, diffuse), by which a light with a size
// scales its integrals of D — none under the paper-literal normalization (src/ltc/mod.rs
// LtcPair::lobe_weights).
fn lobe_weights(pair: LtcPair, f0: f32, normalization: u32) -> vec2<f32> {
    if normalization == NORMALIZATION_PAPER_LITERAL {
        return vec2<f32>(1.0);
    }
    return vec2<f32>(spec_magnitude(pair, f0), magnitude(pair.diff));
}

// LtcPair::ltc_lobes: both lobes' LTC toward unit l at unit irradiance, each times its
// magnitude (none under the paper-literal normalization).
fn ltc_lobes(pair: LtcPair, l: vec3<f32>, f0: f32, clip: u32, normalization: u32) -> vec2<f32> {
    let lobes = vec2<f32>(
        ltc_eval(pair.spec, l, clip, normalization),
        ltc_eval(pair.diff, l, clip, normalization),
    );
    return lobe_weights(pair, f0, normalization) * lobes;
}

// point_lobes: a point light's lobes toward unit l at unit irradiance — the exact BRDF (0
// below the surface) or the LTC — the limit of every light with a size (src/light/mod.rs).
fn point_lobes(
    v: vec3<f32>,
    l: vec3<f32>,
    alpha: vec2<f32>,
    f0: f32,
    pair: LtcPair,
    clip: u32,
    normalization: u32,
    exact: bool,
) -> vec2<f32> {
    if !exact {
        return ltc_lobes(pair, l, f0, clip, normalization);
    }
    if l.z <= 0.0 {
        return vec2<f32>(0.0);
    }
    return exact_lobes(v, l, alpha, f0);
}
