// Shades the plane z = 0 seen by the camera, one thread per pixel and one 16×16 workgroup per
// tile, lights read in workgroup-shared loads of 256 (docs/design.md §4). A render is summed in chunks
// of each pixel's light list (all lights, or the tile's list when culling), the sums kept per
// pixel between chunks, so that the lab can spread a render over frames; `resolve` turns the
// sums into the image. Composed after brdf.wgsl, ltc.wgsl, sphere_light.wgsl,
// rect_light.wgsl, disk_light.wgsl, scene.wgsl and light_shape.wgsl (each light by its
// shape: add_light), and followed by method_file.wgsl and a method file's text. The CPU
// reference is src/cpu/mod.rs; the Rust side of this file is src/gpu/plane.rs.

// Shading methods (src/render/mod.rs Method; src/gpu/plane.rs method_constant).
const METHOD_BRDF: u32 = 0u;      // the exact BRDF as docs/design.md §1 writes it
const METHOD_BRDF_FAST: u32 = 1u; // the same, with Filament's V_SmithGGXCorrelated
const METHOD_LTC: u32 = 2u;       // the paper's LTC: normalize l, rotate, M⁻¹ l per lobe
const METHOD_LTC_FAST: u32 = 3u;  // per-pixel M⁻¹·tangent_from_world, unnormalized u, eq. 27
const METHOD_LTC_F16: u32 = 4u;   // ltc-fast with M⁻¹l and D in f16 (ltc_f16.wgsl)
const METHOD_LTC_F16_PAIRS: u32 = 5u; // the same, two lights per vec2<f16> (ltc_f16.wgsl)
const METHOD_FILE: u32 = 6u;      // a method loaded from a file (method_file.wgsl)

// What a pixel shows (src/render/mod.rs View; View::B is B shaded as the single A).
const VIEW_SINGLE: u32 = 0u; // method A
const VIEW_SPLIT: u32 = 1u;  // A left of the divider, B right of it
const VIEW_DIFF: u32 = 2u;   // |A − B| / max(B, floor) on luminance

// Pipeline constants: each combination is its own pipeline, so the light loop has no
// per-light branch on the method.
override METHOD_A: u32 = METHOD_LTC;
override METHOD_B: u32 = METHOD_BRDF;
override VIEW: u32 = VIEW_SINGLE;
// B shades with table B (two tables compared) instead of table A.
override TABLE_B: bool = false;
// What the LTC methods do for lights near the horizon (HORIZON_* of ltc.wgsl).
override HORIZON: u32 = HORIZON_EQ30;
@group(0) @binding(3) var output: texture_storage_2d<rgba32float, write>;
// Per pixel, the sums so far, kept between chunks: A's specular rgb and diffuse r; A's diffuse
// gb and B's specular rg; B's specular b and diffuse rgb (three buffers, so that each stays
// within one storage binding's limit at 16 bytes per pixel).
@group(0) @binding(4) var<storage, read_write> accum_0: array<vec4<f32>>;
@group(0) @binding(8) var<storage, read_write> accum_1: array<vec4<f32>>;
@group(0) @binding(9) var<storage, read_write> accum_2: array<vec4<f32>>;
// src/gpu/bin.rs: each tile's first list entry, the total after them; the lists.
@group(0) @binding(5) var<storage, read> tile_offsets: array<u32>;
@group(0) @binding(6) var<storage, read> tile_lights: array<u32>;
// Per tile: Σ|L_A|, Σ|L_B| (luminance) and the pixels on the plane; after them, the floor
// of the difference view (`metrics::relative_floor`).
@group(0) @binding(7) var<storage, read_write> partials: array<vec4<f32>>;

const LOAD: u32 = 256u;
var<workgroup> shared_lights: array<GpuLight, LOAD>;
// The same lights' positions relative to the workgroup's centre (f16 pairs only).
var<workgroup> shared_relative: array<vec3<f32>, LOAD>;
var<workgroup> wg_count: u32;

// One table's per-pixel state: the two lobes, and for ltc-fast M⁻¹ · tangent_from_world per
// lobe with the factors pulled out of the sum.
struct LtcShading {
    pair: LtcPair,
    spec_from_world: mat3x3<f32>,
    diff_from_world: mat3x3<f32>,
    spec_factor: f32,
    diff_factor: f32,
    // nl-fit's correction [spec c0 c1, diff c0 c1] (zero unless HORIZON is nl-fit).
    nl: vec4<f32>,
    // The lobes' magnitudes (specular with F0, diffuse) as a method file reads them, made
    // once a pixel (method_file.wgsl method_pixel).
    magnitudes: vec2<f32>,
}

// A visible point of the plane and everything per pixel that the methods need.
struct Pixel {
    on_plane: bool,
    x: vec3<f32>,          // world position
    v: vec3<f32>,          // unit, toward the camera (world; n = +z)
    t1: vec3<f32>,         // shading frame (src/render/mod.rs ShadingFrame)
    t2: vec3<f32>,
    tangent_from_world: mat3x3<f32>, // rows t1, t2, n
    v_tangent: vec3<f32>,  // v in the shading frame (the sphere methods')
    ltc_a: LtcShading,     // table A
    ltc_b: LtcShading,     // table B where TABLE_B, else table A
    // brdf-fast: α² and the per-pixel factor of V_SmithGGXCorrelated.
    a2: f32,
    view_factor: f32,
}

// Light gathered per lobe: radiance = spec + base_color · diff (after `finish`).
struct Sums {
    spec: vec3<f32>,
    diff: vec3<f32>,
}

// Scene::surface_point: the camera ray through the pixel centre, hit with the plane.
fn surface_point(px: vec2<u32>) -> Pixel {
    return surface_point_at(vec2<f32>(px) + 0.5);
}

// Scene::surface_point_at: the camera ray through the image point `pos` (pixels), hit with
// the plane.
fn surface_point_at(pos: vec2<f32>) -> Pixel {
    var p: Pixel;
    p.on_plane = false;
    let hit = plane_hit(camera_ray(pos));
    let x = hit.xyz;
    if hit.w == 0.0 || abs(x.x) > params.half_size || abs(x.y) > params.half_size {
        return p;
    }
    p.on_plane = true;
    p.x = x;
    p.v = normalize(params.eye.xyz - x);
    let tangential = vec2<f32>(p.v.x, p.v.y);
    let len = length(tangential);
    // At normal view any tangent will do (src/render/mod.rs ShadingFrame::new).
    p.t1 = select(vec3<f32>(1.0, 0.0, 0.0), vec3<f32>(tangential / len, 0.0), len > 0.0);
    if ANISO {
        // The material's tangent frame (src/render/mod.rs ShadingFrame::of).
        p.t1 = vec3<f32>(params.tangent_x, params.tangent_y, 0.0);
    }
    p.t2 = cross(vec3<f32>(0.0, 0.0, 1.0), p.t1);
    // WGSL builds a matrix from columns, hence the transpose.
    p.tangent_from_world = transpose(mat3x3<f32>(p.t1, p.t2, vec3<f32>(0.0, 0.0, 1.0)));
    p.v_tangent = p.tangent_from_world * p.v;
    return p;
}

// An anisotropic material's lobes (src/cpu/mod.rs LtcPixel::anisotropic): the specular lobe from
// the 4D table in the tangent frame; the diffuse lobe from the 2D table at Burley's α, turned
// from the view's frame into the tangent's (a tangent-frame direction has view-frame
// coordinates turned by −φ, φ the view's azimuth).
fn aniso_pair(p: Pixel, size: u32, base: u32, table: AnisoTable) -> LtcPair {
    let alpha = material_alpha();
    let spec = aniso_ltc(table, alpha, p.v_tangent);
    let diff = lut_ltc_pair(0.5 * (alpha.x + alpha.y), p.v.z, size, base).diff;
    let along = length(p.v_tangent.xy);
    var c = 1.0;
    var s = 0.0;
    if along > 0.0 {
        c = p.v_tangent.x / along;
        s = p.v_tangent.y / along;
    }
    let view_from_tangent = mat3x3<f32>(vec3<f32>(c, -s, 0.0), vec3<f32>(s, c, 0.0), vec3<f32>(0.0, 0.0, 1.0));
    let m = diff.cos_from_brdf * view_from_tangent;
    return LtcPair(spec, Ltc(m, diff.det_cos_from_brdf, diff.norm, 0.0, 1.0));
}

// One table's LtcShading at the pixel: the table of `size` cells per side at `base`, and its
// 4D table.
fn ltc_shading(p: Pixel, size: u32, base: u32, table: AnisoTable) -> LtcShading {
    var s: LtcShading;
    if ANISO {
        s.pair = aniso_pair(p, size, base, table);
    } else {
        s.pair = lut_ltc_pair(params.alpha, p.v.z, size, base);
    }
    s.spec_from_world = s.pair.spec.cos_from_brdf * p.tangent_from_world;
    s.diff_from_world = s.pair.diff.cos_from_brdf * p.tangent_from_world;
    if params.normalization == NORMALIZATION_PAPER_LITERAL {
        s.spec_factor = s.pair.spec.det_cos_from_brdf;
        s.diff_factor = s.pair.diff.det_cos_from_brdf;
    } else {
        s.spec_factor = s.pair.spec.det_cos_from_brdf / PI * spec_magnitude(s.pair, params.f0);
        s.diff_factor = s.pair.diff.det_cos_from_brdf / PI * magnitude(s.pair.diff);
    }
    s.magnitudes = lobe_weights(s.pair, params.f0, NORMALIZATION_CORRECTED);
    s.nl = vec4<f32>(0.0);
    // The correction was fitted to the 2D table's lobes: an anisotropic pixel goes without.
    if HORIZON == HORIZON_NL_FIT && !ANISO {
        s.nl = lut_nl_terms(params.alpha, p.v.z, size, base);
    }
    return s;
}

// Per-pixel set-up of every method used by this pipeline.
fn prepare(p_in: Pixel) -> Pixel {
    var p = p_in;
    if !p.on_plane {
        return p;
    }
    p.ltc_a = ltc_shading(p, params.lut_size, params.lut_base, AnisoTable(params.aniso_a.x, params.aniso_dims_a, params.aniso_a.y, params.aniso_a.z));
    if TABLE_B {
        p.ltc_b = ltc_shading(p, params.lut_size_b, params.lut_base_b, AnisoTable(params.aniso_b.x, params.aniso_dims_b, params.aniso_b.y, params.aniso_b.z));
    } else {
        p.ltc_b = p.ltc_a;
    }
    p.a2 = params.alpha * params.alpha;
    p.view_factor = sqrt(p.v.z * p.v.z * (1.0 - p.a2) + p.a2);
    return p;
}

// The exact BRDF as docs/design.md §1 writes it: normalize, half vector, each term by its function.
fn add_brdf(s: ptr<function, Sums>, p: Pixel, light: GpuLight) {
    let u = light.position_range.xyz - p.x;
    let d = length(u);
    let e = irradiance_scale(1.0, d, light.position_range.w);
    let l = u / d;
    if e <= 0.0 || l.z <= 0.0 {
        return;
    }
    if ANISO {
        // The tangent frame's BRDF (brdf_aniso.wgsl), l turned into it.
        let lobes = brdf_cos_aniso(p.v_tangent, p.tangent_from_world * l, material_alpha(), params.f0);
        (*s).spec += light.intensity.rgb * (e * lobes.x);
        (*s).diff += light.intensity.rgb * (e * lobes.y);
        return;
    }
    let dots = dots_new(p.v, l);
    (*s).spec += light.intensity.rgb * (e * specular_cos(dots, params.alpha, params.f0));
    (*s).diff += light.intensity.rgb * (e * diffuse_cos(dots, params.alpha));
}

// The same BRDF, simplified: d² without a root for E, V_SmithGGXCorrelated for G/(4 n·v n·l).
// Its shortcuts are the isotropic BRDF's: an anisotropic material takes add_brdf.
fn add_brdf_fast(s: ptr<function, Sums>, p: Pixel, light: GpuLight) {
    if ANISO {
        add_brdf(s, p, light);
        return;
    }
    let u = light.position_range.xyz - p.x;
    let d2 = dot(u, u);
    if u.z <= 0.0 || d2 < MIN_LIGHT_DISTANCE * MIN_LIGHT_DISTANCE {
        return;
    }
    let inv_d = inverseSqrt(d2);
    let l = u * inv_d;
    let e = window_falloff_d2(d2, light.position_range.w) * inv_d * inv_d;
    let h = normalize(p.v + l);
    let v_h = dot(p.v, h);
    let n_l = l.z;
    let spec = d_ggx(h.z, params.alpha)
        * v_smith_ggx_correlated(p.v.z, n_l, p.a2, p.view_factor)
        * f_schlick(params.f0, v_h) * n_l;
    (*s).spec += light.intensity.rgb * (e * spec);
    (*s).diff += light.intensity.rgb * (e * fd_burley(p.v.z, n_l, v_h, params.alpha) * n_l);
}

// The paper's LTC (eq. 30): unit l into the shading frame, then M⁻¹ l per lobe.
fn add_ltc(s: ptr<function, Sums>, p: Pixel, ltc: LtcShading, light: GpuLight) {
    let u = light.position_range.xyz - p.x;
    let d = length(u);
    let e = irradiance_scale(1.0, d, light.position_range.w);
    if e <= 0.0 {
        return;
    }
    let lw = u / d;
    let l = vec3<f32>(dot(lw, p.t1), dot(lw, p.t2), lw.z);
    var spec_weight = spec_magnitude(ltc.pair, params.f0);
    var diff_weight = magnitude(ltc.pair.diff);
    if params.normalization == NORMALIZATION_PAPER_LITERAL {
        spec_weight = 1.0;
        diff_weight = 1.0;
    }
    if HORIZON == HORIZON_EXACT_BAND && in_exact_band(l.z) {
        add_brdf(s, p, light);
        return;
    }
    var ds = ltc_eval(ltc.pair.spec, l, params.clip, params.normalization);
    var dd = ltc_eval(ltc.pair.diff, l, params.clip, params.normalization);
    if HORIZON == HORIZON_NL_FIT {
        ds *= nl_weight(ltc.nl.xy, l.z);
        dd *= nl_weight(ltc.nl.zw, l.z);
    }
    (*s).spec += light.intensity.rgb * (e * spec_weight * ds);
    (*s).diff += light.intensity.rgb * (e * diff_weight * dd);
}

// LTC with the rotation folded into M⁻¹, the unnormalized u = p − x and eq. 27's factoring:
// E·D = I w(d) d (A u).z / |A u|⁴ · |det M⁻¹|/π — one square root per light.
fn add_ltc_fast(s: ptr<function, Sums>, p: Pixel, ltc: LtcShading, light: GpuLight) {
    let u = light.position_range.xyz - p.x;
    let d2 = dot(u, u);
    if d2 < MIN_LIGHT_DISTANCE * MIN_LIGHT_DISTANCE || ((params.clip & CLIP_HORIZON) != 0u && u.z <= 0.0) {
        return;
    }
    let d = sqrt(d2);
    if HORIZON == HORIZON_EXACT_BAND && in_exact_band(u.z / d) {
        add_brdf_factored(s, p, ltc, light);
        return;
    }
    let scale = window_falloff_d2(d2, light.position_range.w) * d;
    let ws = ltc.spec_from_world * u;
    let wd = ltc.diff_from_world * u;
    let transformed = (params.clip & CLIP_TRANSFORMED) != 0u;
    let qs = dot(ws, ws);
    let qd = dot(wd, wd);
    var zs = select(ws.z, max(ws.z, 0.0), transformed);
    var zd = select(wd.z, max(wd.z, 0.0), transformed);
    if HORIZON == HORIZON_NL_FIT {
        let z = u.z / d;
        zs *= nl_weight(ltc.nl.xy, z);
        zd *= nl_weight(ltc.nl.zw, z);
    }
    (*s).spec += light.intensity.rgb * (scale * zs / (qs * qs));
    (*s).diff += light.intensity.rgb * (scale * zd / (qd * qd));
}

// The exact BRDF into ltc-fast's sums, which `finish` multiplies by the pixel's factors: divided
// by them here (they are positive for every table a fit makes: |det M⁻¹| and the magnitudes).
// brdf-fast's form: the same math as add_brdf, with fewer operations.
fn add_brdf_factored(s: ptr<function, Sums>, p: Pixel, ltc: LtcShading, light: GpuLight) {
    var exact = Sums(vec3<f32>(0.0), vec3<f32>(0.0));
    add_brdf_fast(&exact, p, light);
    (*s).spec += exact.spec / ltc.spec_factor;
    (*s).diff += exact.diff / ltc.diff_factor;
}

// Whether a method sums ltc-fast's factored terms, which `finish` multiplies by the pixel's factors.
fn is_factored(method: u32) -> bool {
    return method == METHOD_LTC_FAST || method == METHOD_LTC_F16 || method == METHOD_LTC_F16_PAIRS;
}

// A point light by the side's method.
fn add_point(method: u32, s: ptr<function, Sums>, p: Pixel, ltc: LtcShading, light: GpuLight) {
    switch method {
        case METHOD_BRDF: { add_brdf(s, p, light); }
        case METHOD_BRDF_FAST: { add_brdf_fast(s, p, light); }
        case METHOD_LTC: { add_ltc(s, p, ltc, light); }
        case METHOD_LTC_F16, METHOD_LTC_F16_PAIRS: { add_ltc_f16(s, p, ltc, light); }
        case METHOD_FILE: { add_method_fallback_point(s, p, ltc, light); }
        default: { add_ltc_fast(s, p, ltc, light); }
    }
}

// The largest finite f32. A light of intensity 1e30 next to the surface overflows f32; the
// sums saturate here instead, so that a zero factor (black base colour, F0 = 0 on a mirror)
// times them stays 0 rather than NaN, and the diff view never subtracts two infinities.
// Written in hex: the decimal 3.40282347e38 lies just above it, which Chrome's WGSL compiler
// (Tint) refuses as not representable in f32.
const F32_MAX: f32 = 0x1.fffffep+127f;

fn saturate_finite(x: vec3<f32>) -> vec3<f32> {
    return clamp(x, vec3<f32>(-F32_MAX), vec3<f32>(F32_MAX));
}

// Radiance from the sums: the ltc-fast forms apply the factors pulled out of their sum here.
fn finish(method: u32, sums: Sums, ltc: LtcShading) -> vec3<f32> {
    let s = Sums(saturate_finite(sums.spec), saturate_finite(sums.diff));
    if is_factored(method) {
        return saturate_finite(ltc.spec_factor * s.spec + params.base_color.rgb * (ltc.diff_factor * s.diff));
    }
    // A file's diffuse holds its base colour already.
    if method == METHOD_FILE {
        return saturate_finite(s.spec + s.diff);
    }
    return saturate_finite(s.spec + params.base_color.rgb * s.diff);
}

// Rec. 709 luminance (src/metrics.rs).
fn luminance(c: vec3<f32>) -> f32 {
    return dot(c, vec3<f32>(0.2126, 0.7152, 0.0722));
}

fn pixel_index(gid: vec2<u32>) -> u32 {
    return gid.y * params.width + gid.x;
}

fn load_sums(k: u32) -> array<Sums, 2> {
    let s0 = accum_0[k];
    let s1 = accum_1[k];
    let s2 = accum_2[k];
    return array<Sums, 2>(Sums(s0.xyz, vec3<f32>(s0.w, s1.xy)), Sums(vec3<f32>(s1.zw, s2.x), s2.yzw));
}

fn store_sums(k: u32, a: Sums, b: Sums) {
    accum_0[k] = vec4<f32>(a.spec, a.diff.x);
    accum_1[k] = vec4<f32>(a.diff.yz, b.spec.xy);
    accum_2[k] = vec4<f32>(b.spec.z, b.diff);
}

// Which methods a pixel sums: A, B, or both.
fn uses_a(gid: vec2<u32>) -> bool {
    return VIEW != VIEW_SPLIT || f32(gid.x) < params.divider;
}

fn uses_b(gid: vec2<u32>) -> bool {
    return VIEW == VIEW_DIFF || (VIEW == VIEW_SPLIT && !uses_a(gid));
}

// The plane point under the workgroup's centre pixel (the f16 pairs' origin), or the origin.
fn workgroup_centre(wid: vec2<u32>) -> vec3<f32> {
    let centre = vec2<f32>(wid * TILE_SIDE) + 0.5 * f32(TILE_SIDE);
    return plane_hit(camera_ray(centre)).xyz;
}

// Sums one chunk — entries [light_start, light_end) of each pixel's list — into the sums kept
// in `accum` (starting from zero at the first chunk), over a band of tile rows from
// `params.bin_row` (a render split into submissions a watchdog never sees, gpu/failures/submissions.rs).
@compute @workgroup_size(16, 16, 1)
fn shade(
    @builtin(global_invocation_id) band_gid: vec3<u32>,
    @builtin(workgroup_id) band_wid: vec3<u32>,
    @builtin(local_invocation_index) li: u32,
) {
    let gid = band_gid.xy + vec2<u32>(0u, params.bin_row * TILE_SIDE);
    let wid = band_wid.xy + vec2<u32>(0u, params.bin_row);
    let inside = gid.x < params.width && gid.y < params.height;
    // The tile's list: culled where binned and the lists fit, else every light.
    let tiles = params.tiles_x * params.tiles_y;
    let culled = params.cull != 0u && tile_offsets[tiles] <= params.tile_capacity;
    let tile = wid.y * params.tiles_x + wid.x;
    if li == 0u {
        var count = params.light_count;
        if culled {
            // The last tile's end is the total, after the offsets.
            count = tile_offsets[tile + 1u] - tile_offsets[tile];
        }
        wg_count = count;
    }
    let count = workgroupUniformLoad(&wg_count);
    // A chunk past the end of this tile's list adds nothing: the kept sums stand.
    if params.light_start > 0u && params.light_start >= count {
        return;
    }
    var p: Pixel;
    p.on_plane = false;
    if inside {
        p = prepare(surface_point(gid));
    }
    let first = tile_offsets[tile];
    var centre = vec3<f32>(0.0);
    if METHOD_A == METHOD_LTC_F16_PAIRS {
        centre = workgroup_centre(wid);
    }
    let x_relative = p.x - centre;
    let end = min(params.light_end, count);
    let use_a = uses_a(gid);
    let use_b = uses_b(gid);
    var a = Sums(vec3<f32>(0.0), vec3<f32>(0.0));
    var b = Sums(vec3<f32>(0.0), vec3<f32>(0.0));
    let k = pixel_index(gid);
    if inside && params.light_start > 0u {
        let sums = load_sums(k);
        a = sums[0];
        b = sums[1];
    }
    // Every thread of the workgroup loads one light of each load, pixel or not: the loop
    // bounds are uniform, so the barriers are too.
    for (var base = params.light_start; base < end; base += LOAD) {
        let e = base + li;
        if e < end {
            var index = e;
            if culled {
                index = tile_lights[first + e];
            }
            shared_lights[li] = lights[index];
            if METHOD_A == METHOD_LTC_F16_PAIRS {
                shared_relative[li] = lights[index].position_range.xyz - centre;
            }
        }
        workgroupBarrier();
        let n = min(LOAD, end - base);
        // Seen from below (v.z ≤ 0) the one-sided plane is black, as on the CPU.
        if p.on_plane && p.v.z > 0.0 {
            var j = 0u;
            if METHOD_A == METHOD_LTC_F16_PAIRS && use_a && !use_b && !SIZED {
                // Every light in a lane of a pair, the last one of an odd load beside a dead
                // lane: a light's arithmetic never depends on its partner, so culling (which
                // changes the pairs) gives the unculled image to the bit.
                for (; j < n; j += 2u) {
                    add_ltc_f16_pair(&a, p, p.ltc_a, x_relative, j, j + 1u < n);
                }
            }
            for (; j < n; j++) {
                if use_a {
                    add_light(METHOD_A, SIDE_A, &a, p, p.ltc_a, shared_lights[j]);
                }
                if use_b {
                    add_light(METHOD_B, SIDE_B, &b, p, p.ltc_b, shared_lights[j]);
                }
            }
        }
        workgroupBarrier();
    }
    if inside {
        store_sums(k, a, b);
    }
}

// Radiance of A and B at a pixel from its sums.
fn radiances(gid: vec2<u32>) -> array<vec3<f32>, 2> {
    let p = prepare(surface_point(gid));
    let sums = load_sums(pixel_index(gid));
    return array<vec3<f32>, 2>(finish(METHOD_A, sums[0], p.ltc_a), finish(METHOD_B, sums[1], p.ltc_b));
}

var<workgroup> wg_partials: array<vec4<f32>, 256>;

// The sum of `v` over a 256-invocation workgroup, by halving (every invocation must call it:
// it holds barriers); the same pairing order in every call, so the sums are deterministic.
fn workgroup_sum(li: u32, v: vec4<f32>) -> vec4<f32> {
    wg_partials[li] = v;
    workgroupBarrier();
    for (var d = 128u; d > 0u; d /= 2u) {
        if li < d {
            wg_partials[li] += wg_partials[li + d];
        }
        workgroupBarrier();
    }
    return wg_partials[0];
}

// Per tile (for the difference view's floor): Σ|L_A|, Σ|L_B| and the pixels on the plane.
@compute @workgroup_size(16, 16, 1)
fn reduce(
    @builtin(global_invocation_id) gid: vec3<u32>,
    @builtin(workgroup_id) wid: vec3<u32>,
    @builtin(local_invocation_index) li: u32,
) {
    var v = vec4<f32>(0.0);
    if gid.x < params.width && gid.y < params.height && surface_point(gid.xy).on_plane {
        let l = radiances(gid.xy);
        v = vec4<f32>(abs(luminance(l[0])), abs(luminance(l[1])), 1.0, 0.0);
    }
    let total = workgroup_sum(li, v);
    if li == 0u {
        partials[wid.y * params.tiles_x + wid.x] = total;
    }
}

// One workgroup: the floor, `metrics::relative_floor` — 1% of B's mean luminance, of A's
// where B is black all over — after the partial sums.
@compute @workgroup_size(256)
fn floor_of_means(@builtin(local_invocation_index) li: u32) {
    let tiles = params.tiles_x * params.tiles_y;
    var v = vec4<f32>(0.0);
    for (var t = li; t < tiles; t += 256u) {
        v += partials[t];
    }
    let s = workgroup_sum(li, v);
    if li == 0u {
        let count = max(s.z, 1.0);
        let mean = select(s.x / count, s.y / count, s.y > 0.0);
        // RELATIVE_FLOOR of src/metrics.rs, never below f32's smallest normal.
        // y: the mark of a method file stopped (add_method_radiance), kept.
        partials[tiles] = vec4<f32>(max(0.01 * mean, 0x1p-126f), partials[tiles].y, 0.0, 0.0);
    }
}

// The image from the sums: A, A | B or |A − B| / max(B, floor); alpha marks the plane.
@compute @workgroup_size(16, 16, 1)
fn resolve(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= params.width || gid.y >= params.height {
        return;
    }
    var out = vec4<f32>(0.0);
    if surface_point(gid.xy).on_plane {
        let l = radiances(gid.xy);
        if VIEW == VIEW_DIFF {
            let floor = partials[params.tiles_x * params.tiles_y].x;
            let ref_lum = luminance(l[1]);
            let rel = min(abs(luminance(l[0]) - ref_lum) / max(ref_lum, floor), F32_MAX);
            out = vec4<f32>(rel, rel, rel, 1.0);
        } else {
            out = vec4<f32>(select(l[1], l[0], uses_a(gid.xy)), 1.0);
        }
        // Alpha 2: a method file's loops were stopped somewhere (method_file.wgsl).
        if method_file_was_stopped() {
            out.w = 2.0;
        }
    }
    textureStore(output, vec2<i32>(gid.xy), out);
}
