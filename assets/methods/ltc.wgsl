// The paper's LTC for point lights (Heitz et al. 2016, eq. 30), with the 1/π and each lobe's
// magnitude that the lab's design restores: the lab's own `ltc`, written as a method file.
// Load it beside `ltc` and the difference view is black to f32's rounding; change one line
// and see what that line does. Spheres, rects and disks are left to the lab's methods.

const PI: f32 = 3.14159265358979;

// D(l) = max(ω'.z, 0) |det M⁻¹| / (π |ω'|⁴) with ω' = M⁻¹ l: the cosine's density seen
// through the table's matrix. Case 1 (l below the surface) and case 2 (ω' below the cosine's
// horizon) are both 0.
fn ltc_density(m_inv: mat3x3<f32>, l: vec3<f32>) -> f32 {
    if l.z <= 0.0 {
        return 0.0;
    }
    let w = m_inv * l;
    if w.z <= 0.0 {
        return 0.0;
    }
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
