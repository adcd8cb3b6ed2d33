// The paper's LTC for point lights WITHOUT the case-2 clamp: a port that forgot one line.
// Where the light is above the surface but M⁻¹ l falls below the cosine's horizon (grazing
// views, rough surfaces: the paper's Figure 2, case 2), D turns negative and the plane shows
// dark light. Beside `ltc` with case 2 off, the difference view is black to f32's rounding.

const PI: f32 = 3.14159265358979;

// D(l) = ω'.z |det M⁻¹| / (π |ω'|⁴) with ω' = M⁻¹ l: the cosine's density seen
// through the table's matrix, case 1 (l below the surface) 0 and case 2 left out: the
// artifact.
fn ltc_density(m_inv: mat3x3<f32>, l: vec3<f32>) -> f32 {
    if l.z <= 0.0 {
        return 0.0;
    }
    let w = m_inv * l;
    let len2 = dot(w, w);
    return w.z * abs(determinant(m_inv)) / (PI * len2 * len2);
}

fn method_point(pixel: MethodPixel, light: MethodPoint) -> MethodRadiance {
    let u = light.position - pixel.position;
    let d = length(u);
    if d < 1e-6 {
        return MethodRadiance(vec3<f32>(0.0), vec3<f32>(0.0));
    }
    let to_light = u / d;
    // Into the shading frame, where the table's matrices live.
    let l = vec3<f32>(dot(to_light, pixel.t1), dot(to_light, pixel.t2), dot(to_light, pixel.n));
    let irradiance = light.intensity / (d * d);
    let specular = irradiance * (pixel.spec_magnitude * ltc_density(pixel.spec_minv, l));
    let diffuse = irradiance * pixel.base_color * (pixel.diff_magnitude * ltc_density(pixel.diff_minv, l));
    return MethodRadiance(specular, diffuse);
}
