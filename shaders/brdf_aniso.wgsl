// Anisotropic GGX (docs/design.md §1.13), mirroring src/brdf/aniso.rs function by function
// (same names): α along the shading frame's x (the tangent) and y (the bitangent), in
// `alpha.x` and `alpha.y`; every vector in the tangent frame (n = +z). Composed after
// brdf.wgsl (uses PI, f_schlick, fd_burley, Dots).

// The material is anisotropic: shaded in its tangent's frame by these terms, its specular
// lobe's LTC from a 4D table (ltc_aniso.wgsl). A pipeline constant: isotropic pipelines
// compile none of it, and shade exactly as before.
override ANISO: bool = false;

// Both exact lobes (specular, diffuse) toward unit l with l.z > 0, for unit v with v.z > 0 in
// the shading frame: the isotropic terms where the material is isotropic, the anisotropic
// ones where it is not (src/brdf/aniso.rs brdf_cos_aniso). Every exact rule calls this.
fn exact_lobes(v: vec3<f32>, l: vec3<f32>, alpha: vec2<f32>, f0: f32) -> vec2<f32> {
    if ANISO {
        return brdf_cos_aniso(v, l, alpha, f0);
    }
    let d = dots_new(v, l);
    return vec2<f32>(specular_cos(d, alpha.x, f0), diffuse_cos(d, alpha.x));
}

// Anisotropic GGX normal distribution, Heitz 2014 eq. 85: 1/(π αx αy ((h.x/αx)² +
// (h.y/αy)² + h.z²)²), zero for h.z ≤ 0.
fn d_ggx_aniso(h: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if h.z <= 0.0 {
        return 0.0;
    }
    let s = h.xy / alpha;
    let k = dot(s, s) + h.z * h.z;
    return 1.0 / (PI * alpha.x * alpha.y * k * k);
}

// Smith's Λ for anisotropic GGX, Heitz 2014 eq. 86; for w.z > 0.
fn lambda_ggx_aniso(w: vec3<f32>, alpha: vec2<f32>) -> f32 {
    let s = w.xy * alpha;
    let a2_tan2 = dot(s, s) / (w.z * w.z);
    return (-1.0 + sqrt(1.0 + a2_tan2)) * 0.5;
}

// Height-correlated Smith masking-shadowing with the anisotropic Λ, Heitz 2014 eq. 99.
fn g2_correlated_aniso(v: vec3<f32>, l: vec3<f32>, alpha: vec2<f32>) -> f32 {
    if v.z <= 0.0 || l.z <= 0.0 {
        return 0.0;
    }
    return 1.0 / (1.0 + lambda_ggx_aniso(v, alpha) + lambda_ggx_aniso(l, alpha));
}

// D F G / (4 n·v n·l) · n·l with n·l cancelled, h the unit half vector (src/brdf/aniso.rs
// specular_cos_aniso).
fn specular_cos_aniso(v: vec3<f32>, l: vec3<f32>, h: vec3<f32>, alpha: vec2<f32>, f0: f32) -> f32 {
    let v_h = dot(v, h);
    let l_h = dot(l, h);
    if v.z <= 0.0 || l.z <= 0.0 || v_h <= 0.0 || l_h <= 0.0 {
        return 0.0;
    }
    return d_ggx_aniso(h, alpha) * f_schlick(f0, v_h) * g2_correlated_aniso(v, l, alpha)
        / (4.0 * v.z);
}

// Both exact lobes (specular, diffuse) of an anisotropic material toward unit l, for unit v
// with v.z > 0 and l.z > 0 (src/brdf/aniso.rs brdf_cos_aniso's anisotropic arm): Burley's
// diffuse at the mean α (Alpha::diffuse).
fn brdf_cos_aniso(v: vec3<f32>, l: vec3<f32>, alpha: vec2<f32>, f0: f32) -> vec2<f32> {
    let h = normalize(v + l);
    let diffuse = fd_burley(v.z, l.z, dot(l, h), 0.5 * (alpha.x + alpha.y)) * l.z;
    return vec2<f32>(specular_cos_aniso(v, l, h, alpha, f0), diffuse);
}
