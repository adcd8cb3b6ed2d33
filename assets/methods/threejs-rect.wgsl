// Rect lights as three.js shades them (src/renderers/shaders/ShaderChunk/
// lights_physical_pars_fragment.glsl.js, LTC_Evaluate; after Hill & Heitz 2016, "Real-Time
// Area Lighting: a Journey from Research to Production"): the rect's corners through M⁻¹,
// normalized, summed edge by edge with a rational fit of θ/(2π sin θ), and the vector form
// factor clipped at the horizon by the closed form of a sphere of the same form factor —
// never the polygon. Written here for the lab's frame (t2 = n × t1), which three.js negates
// (and winds its corners to match). Points, spheres and disks are left to the lab.

// θ n̂ / (2π) of one edge of unit corners: three.js's rational fit of θ / sin θ / (2π) on
// x = cos θ, exact at 1/(2π) for x = 1 and 1/4 for x = 0 (its constants as three.js has them).
fn edge_form_factor(a: vec3<f32>, b: vec3<f32>) -> vec3<f32> {
    let x = dot(a, b);
    let y = abs(x);
    let p = 0.8543985 + (0.4965155 + 0.0145206 * y) * y;
    let q = 3.4175940 + (4.1616724 + y) * y;
    let v = p / q;
    var theta_sintheta = v;
    if x <= 0.0 {
        theta_sintheta = 0.5 * inverseSqrt(max(1.0 - x * x, 1e-7)) - v;
    }
    return cross(a, b) * theta_sintheta;
}

// LTC_ClippedSphereFormFactor: the form factor above the horizon of the sphere cap whose
// vector form factor is f (Hill's closed form).
fn clipped_sphere(f: vec3<f32>) -> f32 {
    let l = length(f);
    return max((l * l + f.z) / (l + 1.0), 0.0);
}

// ∫ D over the rect for one lobe: its corners (relative to the pixel, in the shading frame)
// through m_inv, normalized, and the clipped sphere of their vector form factor.
fn rect_integral(m_inv: mat3x3<f32>, corners: array<vec3<f32>, 4>) -> f32 {
    var c = corners;
    for (var i = 0; i < 4; i++) {
        c[i] = normalize(m_inv * c[i]);
    }
    var f = vec3<f32>(0.0);
    for (var i = 0; i < 4; i++) {
        f += edge_form_factor(c[i], c[(i + 1) % 4]);
    }
    // M⁻¹ with a negative determinant turns the polygon over.
    return clipped_sphere(f * sign(determinant(m_inv)));
}

fn method_rect(pixel: MethodPixel, light: MethodRect) -> MethodRadiance {
    let normal = cross(light.half_u, light.half_v);
    let to_pixel = pixel.position - light.centre;
    // Behind the rect: it emits toward half_u × half_v only.
    if dot(normal, to_pixel) <= 0.0 {
        return MethodRadiance(vec3<f32>(0.0), vec3<f32>(0.0));
    }
    let frame = transpose(mat3x3<f32>(pixel.t1, pixel.t2, pixel.n));
    let c = light.centre - pixel.position;
    // Wound clockwise about the emitting normal, so that seen from the lit side the
    // vector form factor points at the rect.
    let corners = array<vec3<f32>, 4>(
        frame * (c - light.half_u - light.half_v),
        frame * (c - light.half_u + light.half_v),
        frame * (c + light.half_u + light.half_v),
        frame * (c + light.half_u - light.half_v),
    );
    let area = 4.0 * length(light.half_u) * length(light.half_v);
    let radiance = light.intensity / area;
    let specular = radiance * (pixel.spec_magnitude * rect_integral(pixel.spec_minv, corners));
    let diffuse = radiance * pixel.base_color * (pixel.diff_magnitude * rect_integral(pixel.diff_minv, corners));
    return MethodRadiance(specular, diffuse);
}
