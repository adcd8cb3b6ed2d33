// Shades the plane z = 0 seen by the camera into a storage texture, one thread per pixel,
// lights read in workgroup-shared tiles of 256 (DESIGN §4). Composed after brdf.wgsl and
// ltc.wgsl. The CPU reference is src/cpu.rs; the Rust side of this file is src/gpu/plane.rs.

// Shading methods (src/render.rs Method; src/gpu/plane.rs method_constant).
const METHOD_BRDF: u32 = 0u;      // the exact BRDF as DESIGN §1 writes it
const METHOD_BRDF_FAST: u32 = 1u; // the same, with Filament's V_SmithGGXCorrelated
const METHOD_LTC: u32 = 2u;       // the paper's LTC: normalize l, rotate, M⁻¹ l per lobe
const METHOD_LTC_FAST: u32 = 3u;  // per-pixel M⁻¹·tangent_from_world, unnormalized u, eq. 27
const METHOD_LTC_F16: u32 = 4u;   // ltc-fast with M⁻¹l and D in f16 (ltc_f16.wgsl)

// What a pixel shows (src/render.rs View; View::B is B shaded as the single A).
const VIEW_SINGLE: u32 = 0u; // method A
const VIEW_SPLIT: u32 = 1u;  // A left of the divider, B right of it
const VIEW_DIFF: u32 = 2u;   // |A − B| / max(B, floor) on luminance

// Pipeline constants: each combination is its own pipeline, so the light loop has no
// per-light branch on the method.
override METHOD_A: u32 = METHOD_LTC;
override METHOD_B: u32 = METHOD_BRDF;
override VIEW: u32 = VIEW_SINGLE;

// Must match src/gpu/plane.rs Params (checked by tests/shaders.rs).
struct Params {
    eye: vec4<f32>,        // xyz camera position
    forward: vec4<f32>,    // xyz unit view direction
    right: vec4<f32>,      // xyz unit
    up: vec4<f32>,         // xyz unit
    base_color: vec4<f32>, // rgb diffuse albedo
    alpha: f32,
    f0: f32,
    tan_half_fov: f32,
    aspect: f32,
    half_size: f32,
    divider: f32,          // first pixel column of B in the split view
    rel_floor: f32,        // the diff view's floor under B's luminance (src/metrics.rs)
    _pad0: f32,
    width: u32,
    height: u32,
    light_count: u32,
    lut_size: u32,
    clip: u32,
    normalization: u32,
    _pad1: u32,
    _pad2: u32,
}

// Must match src/gpu/plane.rs GpuLight: position and range (≤ 0: infinite), colour × intensity.
struct GpuLight {
    position_range: vec4<f32>,
    intensity: vec4<f32>,
}

@group(0) @binding(0) var<uniform> params: Params;
@group(0) @binding(1) var<storage, read> lights: array<GpuLight>;
@group(0) @binding(3) var output: texture_storage_2d<rgba32float, write>;

const TILE: u32 = 256u;
var<workgroup> tile: array<GpuLight, TILE>;

// A visible point of the plane and everything per pixel that the methods need.
struct Pixel {
    on_plane: bool,
    x: vec3<f32>,          // world position
    v: vec3<f32>,          // unit, toward the camera (world; n = +z)
    t1: vec3<f32>,         // shading frame (src/render.rs ShadingFrame)
    t2: vec3<f32>,
    pair: LtcPair,
    // ltc-fast: M⁻¹ · tangent_from_world per lobe, and the factors pulled out of the sum.
    spec_from_world: mat3x3<f32>,
    diff_from_world: mat3x3<f32>,
    spec_factor: f32,
    diff_factor: f32,
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
    var p: Pixel;
    p.on_plane = false;
    let size = vec2<f32>(f32(params.width), f32(params.height));
    let s = (vec2<f32>(px) + 0.5) / size * 2.0 - 1.0;
    let dir = normalize(params.forward.xyz
        + s.x * params.tan_half_fov * params.aspect * params.right.xyz
        - s.y * params.tan_half_fov * params.up.xyz);
    if dir.z == 0.0 {
        return p;
    }
    let t = -params.eye.z / dir.z;
    let x = params.eye.xyz + t * dir;
    if t <= 0.0 || abs(x.x) > params.half_size || abs(x.y) > params.half_size {
        return p;
    }
    p.on_plane = true;
    p.x = x;
    p.v = normalize(params.eye.xyz - x);
    let tangential = vec2<f32>(p.v.x, p.v.y);
    let len = length(tangential);
    // At normal view any tangent will do (src/render.rs ShadingFrame::new).
    p.t1 = select(vec3<f32>(1.0, 0.0, 0.0), vec3<f32>(tangential / len, 0.0), len > 0.0);
    p.t2 = cross(vec3<f32>(0.0, 0.0, 1.0), p.t1);
    return p;
}

// Per-pixel set-up of every method used by this pipeline.
fn prepare(p_in: Pixel) -> Pixel {
    var p = p_in;
    if !p.on_plane {
        return p;
    }
    p.pair = lut_ltc_pair(params.alpha, p.v.z, params.lut_size);
    // tangent_from_world has rows t1, t2, n; WGSL builds from columns, hence the transpose.
    let tangent_from_world = transpose(mat3x3<f32>(p.t1, p.t2, vec3<f32>(0.0, 0.0, 1.0)));
    p.spec_from_world = p.pair.spec.cos_from_brdf * tangent_from_world;
    p.diff_from_world = p.pair.diff.cos_from_brdf * tangent_from_world;
    if params.normalization == NORMALIZATION_PAPER_LITERAL {
        p.spec_factor = p.pair.spec.det_cos_from_brdf;
        p.diff_factor = p.pair.diff.det_cos_from_brdf;
    } else {
        p.spec_factor = p.pair.spec.det_cos_from_brdf / PI * spec_magnitude(p.pair, params.f0);
        p.diff_factor = p.pair.diff.det_cos_from_brdf / PI * magnitude(p.pair.diff);
    }
    p.a2 = params.alpha * params.alpha;
    p.view_factor = sqrt(p.v.z * p.v.z * (1.0 - p.a2) + p.a2);
    return p;
}

// The exact BRDF as DESIGN §1 writes it: normalize, half vector, each term by its function.
fn add_brdf(s: ptr<function, Sums>, p: Pixel, light: GpuLight) {
    let u = light.position_range.xyz - p.x;
    let d = length(u);
    let e = irradiance_scale(1.0, d, light.position_range.w);
    let l = u / d;
    if e <= 0.0 || l.z <= 0.0 {
        return;
    }
    let dots = dots_new(p.v, l);
    (*s).spec += light.intensity.rgb * (e * specular_cos(dots, params.alpha, params.f0));
    (*s).diff += light.intensity.rgb * (e * diffuse_cos(dots, params.alpha));
}

// The same BRDF, simplified: d² without a root for E, V_SmithGGXCorrelated for G/(4 n·v n·l).
fn add_brdf_fast(s: ptr<function, Sums>, p: Pixel, light: GpuLight) {
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
fn add_ltc(s: ptr<function, Sums>, p: Pixel, light: GpuLight) {
    let u = light.position_range.xyz - p.x;
    let d = length(u);
    let e = irradiance_scale(1.0, d, light.position_range.w);
    if e <= 0.0 {
        return;
    }
    let lw = u / d;
    let l = vec3<f32>(dot(lw, p.t1), dot(lw, p.t2), lw.z);
    var spec_weight = spec_magnitude(p.pair, params.f0);
    var diff_weight = magnitude(p.pair.diff);
    if params.normalization == NORMALIZATION_PAPER_LITERAL {
        spec_weight = 1.0;
        diff_weight = 1.0;
    }
    let ds = ltc_eval(p.pair.spec, l, params.clip, params.normalization);
    let dd = ltc_eval(p.pair.diff, l, params.clip, params.normalization);
    (*s).spec += light.intensity.rgb * (e * spec_weight * ds);
    (*s).diff += light.intensity.rgb * (e * diff_weight * dd);
}

// LTC with the rotation folded into M⁻¹, the unnormalized u = p − x and eq. 27's factoring:
// E·D = I w(d) d (A u).z / |A u|⁴ · |det M⁻¹|/π — one square root per light.
fn add_ltc_fast(s: ptr<function, Sums>, p: Pixel, light: GpuLight) {
    let u = light.position_range.xyz - p.x;
    let d2 = dot(u, u);
    if d2 < MIN_LIGHT_DISTANCE * MIN_LIGHT_DISTANCE || ((params.clip & CLIP_HORIZON) != 0u && u.z <= 0.0) {
        return;
    }
    let scale = window_falloff_d2(d2, light.position_range.w) * sqrt(d2);
    let ws = p.spec_from_world * u;
    let wd = p.diff_from_world * u;
    let transformed = (params.clip & CLIP_TRANSFORMED) != 0u;
    let qs = dot(ws, ws);
    let qd = dot(wd, wd);
    let zs = select(ws.z, max(ws.z, 0.0), transformed);
    let zd = select(wd.z, max(wd.z, 0.0), transformed);
    (*s).spec += light.intensity.rgb * (scale * zs / (qs * qs));
    (*s).diff += light.intensity.rgb * (scale * zd / (qd * qd));
}

fn add_light(method: u32, s: ptr<function, Sums>, p: Pixel, light: GpuLight) {
    switch method {
        case METHOD_BRDF: { add_brdf(s, p, light); }
        case METHOD_BRDF_FAST: { add_brdf_fast(s, p, light); }
        case METHOD_LTC: { add_ltc(s, p, light); }
        case METHOD_LTC_F16: { add_ltc_f16(s, p, light); }
        default: { add_ltc_fast(s, p, light); }
    }
}

// The largest finite f32. A light of intensity 1e30 next to the surface overflows f32; the
// sums saturate here instead, so that a zero factor (black base colour, F0 = 0 on a mirror)
// times them stays 0 rather than NaN, and the diff view never subtracts two infinities.
const F32_MAX: f32 = 3.40282347e38;

fn saturate_finite(x: vec3<f32>) -> vec3<f32> {
    return clamp(x, vec3<f32>(-F32_MAX), vec3<f32>(F32_MAX));
}

// Radiance from the sums: ltc-fast applies the factors pulled out of its sum here.
fn finish(method: u32, sums: Sums, p: Pixel) -> vec3<f32> {
    let s = Sums(saturate_finite(sums.spec), saturate_finite(sums.diff));
    if method == METHOD_LTC_FAST || method == METHOD_LTC_F16 {
        return saturate_finite(p.spec_factor * s.spec + params.base_color.rgb * (p.diff_factor * s.diff));
    }
    return saturate_finite(s.spec + params.base_color.rgb * s.diff);
}

// Rec. 709 luminance (src/metrics.rs).
fn luminance(c: vec3<f32>) -> f32 {
    return dot(c, vec3<f32>(0.2126, 0.7152, 0.0722));
}

@compute @workgroup_size(16, 16, 1)
fn shade(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(local_invocation_index) li: u32) {
    let inside = gid.x < params.width && gid.y < params.height;
    var p: Pixel;
    p.on_plane = false;
    if inside {
        p = prepare(surface_point(gid.xy));
    }
    let use_a = VIEW != VIEW_SPLIT || f32(gid.x) < params.divider;
    let use_b = VIEW == VIEW_DIFF || (VIEW == VIEW_SPLIT && !use_a);
    var a = Sums(vec3<f32>(0.0), vec3<f32>(0.0));
    var b = Sums(vec3<f32>(0.0), vec3<f32>(0.0));
    // Every thread of the workgroup loads one light of each tile, pixel or not: the loop
    // bound is uniform, so the barriers are too.
    for (var base = 0u; base < params.light_count; base += TILE) {
        if base + li < params.light_count {
            tile[li] = lights[base + li];
        }
        workgroupBarrier();
        let n = min(TILE, params.light_count - base);
        // Seen from below (v.z ≤ 0) the one-sided plane is black, as on the CPU.
        if p.on_plane && p.v.z > 0.0 {
            for (var k = 0u; k < n; k++) {
                if use_a {
                    add_light(METHOD_A, &a, p, tile[k]);
                }
                if use_b {
                    add_light(METHOD_B, &b, p, tile[k]);
                }
            }
        }
        workgroupBarrier();
    }
    if !inside {
        return;
    }
    var out = vec4<f32>(0.0);
    if p.on_plane {
        let la = finish(METHOD_A, a, p);
        let lb = finish(METHOD_B, b, p);
        if VIEW == VIEW_DIFF {
            let ref_lum = luminance(lb);
            let rel = min(abs(luminance(la) - ref_lum) / max(ref_lum, params.rel_floor), F32_MAX);
            out = vec4<f32>(rel, rel, rel, 1.0);
        } else {
            out = vec4<f32>(select(lb, la, use_a), 1.0);
        }
    }
    textureStore(output, vec2<i32>(gid.xy), out);
}
