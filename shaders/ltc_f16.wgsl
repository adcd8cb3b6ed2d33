// LTC in half precision (shader-f16): ltc-fast's per-pixel matrix and eq. 27's factoring,
// with M⁻¹·l and the rational function of D evaluated in f16. Composed last, after
// `enable f16;` is put in front of the whole module (src/gpu/ltc_f16.rs); the light vector,
// its length and the falloff stay in f32, which f16's range (6.5e4) could not hold, and each
// term is summed in f32.

// One light: M⁻¹l and D in f16.
fn add_ltc_f16(s: ptr<function, Sums>, p: Pixel, ltc: LtcShading, light: GpuLight) {
    let u = light.position_range.xyz - p.x;
    let d2 = dot(u, u);
    if d2 < MIN_LIGHT_DISTANCE * MIN_LIGHT_DISTANCE || ((params.clip & CLIP_HORIZON) != 0u && u.z <= 0.0) {
        return;
    }
    // E·D for a unit l: I w(d)/d² · (A l).z / |A l|⁴ (the |det M⁻¹|/π factor is the pixel's).
    let e = window_falloff_d2(d2, light.position_range.w) / d2;
    // Out of range a light adds exactly nothing, as in f32 (and not 0 · an f16 overflow).
    if e <= 0.0 {
        return;
    }
    let l = vec3<f16>(u * inverseSqrt(d2));
    let ws = mat3x3<f16>(ltc.spec_from_world) * l;
    let wd = mat3x3<f16>(ltc.diff_from_world) * l;
    let transformed = (params.clip & CLIP_TRANSFORMED) != 0u;
    let zs = select(ws.z, max(ws.z, 0.0h), transformed);
    let zd = select(wd.z, max(wd.z, 0.0h), transformed);
    let qs = dot(ws, ws);
    let qd = dot(wd, wd);
    (*s).spec += light.intensity.rgb * (e * f32(zs / (qs * qs)));
    (*s).diff += light.intensity.rgb * (e * f32(zd / (qd * qd)));
}

// M l for two lights in the lanes of (lx, ly, lz): row r is Σ_c m[c][r] l_c (WGSL's m[c] is
// column c).
fn transform_pair(m: mat3x3<f16>, lx: vec2<f16>, ly: vec2<f16>, lz: vec2<f16>) -> array<vec2<f16>, 3> {
    return array<vec2<f16>, 3>(
        m[0].x * lx + m[1].x * ly + m[2].x * lz,
        m[0].y * lx + m[1].y * ly + m[2].y * lz,
        m[0].z * lx + m[1].z * ly + m[2].z * lz,
    );
}

// D(l) · (its clipping) for both lanes: (M l).z / |M l|⁴.
fn ltc_d_pair(w: array<vec2<f16>, 3>, transformed: bool) -> vec2<f16> {
    let z = select(w[2], max(w[2], vec2<f16>(0.0h)), transformed);
    let q = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    return z / (q * q);
}

// Lights j and j + 1 of the workgroup's load in the two lanes of vec2<f16>: the form measured
// fastest on the reference H100 (1.46× f32 ltc-fast, docs/design.md §4.5). Positions are
// relative to the workgroup's centre in f32 (`shared_relative`, made once per light at the
// load), the falloff per light in f32; the direction, M⁻¹l and D of both lights in f16 lanes.
// Lanes that add nothing (at the shading point, below the horizon, out of range, or no second
// light) are selected away, never multiplied, so an f16 overflow there cannot reach the sums.
fn add_ltc_f16_pair(s: ptr<function, Sums>, p: Pixel, ltc: LtcShading, x_relative: vec3<f32>, j: u32, second: bool) {
    let u0 = shared_relative[j] - x_relative;
    let u1 = shared_relative[j + 1u] - x_relative;
    let d2 = vec2<f32>(dot(u0, u0), dot(u1, u1));
    let range = vec2<f32>(shared_lights[j].position_range.w, shared_lights[j + 1u].position_range.w);
    let e = vec2<f32>(window_falloff_d2(d2.x, range.x), window_falloff_d2(d2.y, range.y)) / d2;
    var live = d2 >= vec2<f32>(MIN_LIGHT_DISTANCE * MIN_LIGHT_DISTANCE) & e > vec2<f32>(0.0)
        & vec2<bool>(true, second);
    if (params.clip & CLIP_HORIZON) != 0u {
        live = live & vec2<f32>(u0.z, u1.z) > vec2<f32>(0.0);
    }
    let inv_d = inverseSqrt(d2);
    let lx = vec2<f16>(vec2<f32>(u0.x, u1.x) * inv_d);
    let ly = vec2<f16>(vec2<f32>(u0.y, u1.y) * inv_d);
    let lz = vec2<f16>(vec2<f32>(u0.z, u1.z) * inv_d);
    let transformed = (params.clip & CLIP_TRANSFORMED) != 0u;
    let ds = ltc_d_pair(transform_pair(mat3x3<f16>(ltc.spec_from_world), lx, ly, lz), transformed);
    let dd = ltc_d_pair(transform_pair(mat3x3<f16>(ltc.diff_from_world), lx, ly, lz), transformed);
    let es = select(vec2<f32>(0.0), e * vec2<f32>(ds), live);
    let ed = select(vec2<f32>(0.0), e * vec2<f32>(dd), live);
    // In light order, as the one-light forms sum.
    (*s).spec += shared_lights[j].intensity.rgb * es.x;
    (*s).diff += shared_lights[j].intensity.rgb * ed.x;
    if second {
        (*s).spec += shared_lights[j + 1u].intensity.rgb * es.y;
        (*s).diff += shared_lights[j + 1u].intensity.rgb * ed.y;
    }
}
