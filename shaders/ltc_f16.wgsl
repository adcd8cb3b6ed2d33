// LTC in half precision (shader-f16): ltc-fast's per-pixel matrix and eq. 27's factoring,
// with M⁻¹·l and the rational function of D evaluated in f16. Composed last, after
// `enable f16;` is put in front of the whole module (src/gpu/ltc_f16.rs); the light vector,
// its length and the falloff stay in f32, which f16's range (6.5e4) could not hold, and each
// term is summed in f32.

fn add_ltc_f16(s: ptr<function, Sums>, p: Pixel, light: GpuLight) {
    let u = light.position_range.xyz - p.x;
    let d2 = dot(u, u);
    if d2 < MIN_LIGHT_DISTANCE * MIN_LIGHT_DISTANCE || ((params.clip & CLIP_HORIZON) != 0u && u.z <= 0.0) {
        return;
    }
    // E·D for a unit l: I w(d)/d² · (A l).z / |A l|⁴ (the |det M⁻¹|/π factor is p's).
    let e = window_falloff_d2(d2, light.position_range.w) / d2;
    let l = vec3<f16>(u * inverseSqrt(d2));
    let ws = mat3x3<f16>(p.spec_from_world) * l;
    let wd = mat3x3<f16>(p.diff_from_world) * l;
    let transformed = (params.clip & CLIP_TRANSFORMED) != 0u;
    let zs = select(ws.z, max(ws.z, 0.0h), transformed);
    let zd = select(wd.z, max(wd.z, 0.0h), transformed);
    let qs = dot(ws, ws);
    let qd = dot(wd, wd);
    (*s).spec += light.intensity.rgb * (e * f32(zs / (qs * qs)));
    (*s).diff += light.intensity.rgb * (e * f32(zd / (qd * qd)));
}
