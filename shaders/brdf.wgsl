// The exact BRDF of docs/design.md §1, mirroring src/brdf/mod.rs function by function (same names). All
// in the shading frame's terms: n = +z, so the dot products with n are z components.

const PI: f32 = 3.141592653589793;

// Distance below which a light sits on the shading point (src/brdf/mod.rs MIN_LIGHT_DISTANCE).
const MIN_LIGHT_DISTANCE: f32 = 1e-6;

struct Dots {
    n_v: f32,
    n_l: f32,
    n_h: f32,
    v_h: f32,
    l_h: f32,
}

// Dots::new for unit v and l with n_v > 0 and n_l > 0, where v + l cannot vanish.
fn dots_new(v: vec3<f32>, l: vec3<f32>) -> Dots {
    let h = normalize(v + l);
    return Dots(v.z, l.z, h.z, dot(v, h), dot(l, h));
}

// GGX normal distribution, Walter et al. 2007 eq. 33; denominator written without the f32
// cancellation at n·h = 1 (see src/brdf/mod.rs).
fn d_ggx(n_h: f32, alpha: f32) -> f32 {
    if n_h <= 0.0 {
        return 0.0;
    }
    let a2 = alpha * alpha;
    let k = n_h * n_h * a2 + (1.0 - n_h) * (1.0 + n_h);
    return a2 / (PI * k * k);
}

// Smith's Λ for GGX, Heitz 2014 eq. 72; for cos_theta > 0.
fn lambda_ggx(cos_theta: f32, alpha: f32) -> f32 {
    let c2 = cos_theta * cos_theta;
    let tan2 = max((1.0 - c2) / c2, 0.0);
    return (-1.0 + sqrt(1.0 + alpha * alpha * tan2)) * 0.5;
}

// Height-correlated Smith masking-shadowing, Heitz 2014 eq. 99.
fn g2_correlated(n_v: f32, n_l: f32, alpha: f32) -> f32 {
    if n_v <= 0.0 || n_l <= 0.0 {
        return 0.0;
    }
    return 1.0 / (1.0 + lambda_ggx(n_v, alpha) + lambda_ggx(n_l, alpha));
}

// Schlick's Fresnel, Schlick 1994 eq. 15 (the exponent on (1 − v·h), docs/design.md §1).
fn f_schlick(f0: f32, v_h: f32) -> f32 {
    let x = clamp(1.0 - v_h, 0.0, 1.0);
    let x2 = x * x;
    return f0 + (1.0 - f0) * x2 * x2 * x;
}

// Burley's diffuse for white base colour, Burley 2012 eq. 3, FD = 0.5 + 2α(l·h)².
fn fd_burley(n_v: f32, n_l: f32, l_h: f32, alpha: f32) -> f32 {
    let f90 = 0.5 + 2.0 * alpha * l_h * l_h;
    return burley_scatter(f90, n_l) * burley_scatter(f90, n_v) / PI;
}

// One factor 1 + (FD − 1)(1 − cos)⁵ of fd_burley.
fn burley_scatter(f90: f32, cos_theta: f32) -> f32 {
    let x = max(1.0 - cos_theta, 0.0);
    let x2 = x * x;
    return 1.0 + (f90 - 1.0) * x2 * x2 * x;
}

// D F G / (4 n·v n·l) · n·l, with n·l cancelled (src/brdf/mod.rs specular_cos).
fn specular_cos(d: Dots, alpha: f32, f0: f32) -> f32 {
    if d.n_v <= 0.0 || d.n_l <= 0.0 || d.v_h <= 0.0 || d.l_h <= 0.0 {
        return 0.0;
    }
    return d_ggx(d.n_h, alpha) * f_schlick(f0, d.v_h) * g2_correlated(d.n_v, d.n_l, alpha)
        / (4.0 * d.n_v);
}

// fd · n·l for base colour 1.
fn diffuse_cos(d: Dots, alpha: f32) -> f32 {
    if d.n_v <= 0.0 || d.n_l <= 0.0 {
        return 0.0;
    }
    return fd_burley(d.n_v, d.n_l, d.l_h, alpha) * d.n_l;
}

// Windowed falloff clamp(1 − (d/R)⁴, 0, 1)² (Karis 2013 eq. 9), from d² to spare the root.
// range ≤ 0 encodes an infinite range (GpuLight in src/gpu/scene.rs).
fn window_falloff_d2(d2: f32, range: f32) -> f32 {
    if range <= 0.0 {
        return 1.0;
    }
    let x2 = d2 / (range * range);
    let w = clamp(1.0 - x2 * x2, 0.0, 1.0);
    return w * w;
}

// E = I/d² · w(d) (docs/design.md §1), zero for a light at the shading point.
fn irradiance_scale(intensity: f32, d: f32, range: f32) -> f32 {
    if d < MIN_LIGHT_DISTANCE {
        return 0.0;
    }
    return intensity / (d * d) * window_falloff_d2(d * d, range);
}

// Filament's V_SmithGGXCorrelated (Lagarde 2014 eq. 72 rearranged): G2 / (4 n·v n·l) with
// the view factor sqrt(n·v²(1 − α²) + α²) passed in, computed once per pixel.
fn v_smith_ggx_correlated(n_v: f32, n_l: f32, a2: f32, view_factor: f32) -> f32 {
    let light_factor = sqrt(n_l * n_l * (1.0 - a2) + a2);
    return 0.5 / (n_l * view_factor + n_v * light_factor);
}
