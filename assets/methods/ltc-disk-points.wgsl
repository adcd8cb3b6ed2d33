// Every point light as a disk of one fixed radius facing the shading point, shaded by the LTC
// disk of Heitz & Hill 2017 ("Real-Time Line- and Disk-Light Shading with Linearly
// Transformed Cosines"): the shape of Bevy's pull request #23400, which moved its point
// lights to an LTC disk. Written here from the paper: the disk's cone through M⁻¹ is an
// elliptical cone, whose form factor and axis come from the eigenvalues of its quadric, and
// the horizon is the closed form of a sphere of the same vector form factor. Near a light
// the disk is wider than a point's lobe; far away it is the point formula again.

// Every point light's disk, in metres.
const RADIUS: f32 = 0.05;
const PI: f32 = 3.14159265358979;

// The eigenvalues of a symmetric 3×3 matrix, largest first (Smith 1961: the trigonometric
// roots of its characteristic cubic).
fn eigenvalues(a: mat3x3<f32>) -> vec3<f32> {
    let off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    let q = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
    let diag = vec3<f32>(a[0][0], a[1][1], a[2][2]) - q;
    let p = sqrt((dot(diag, diag) + 2.0 * off) / 6.0);
    let b = (a - mat3x3<f32>(q, 0.0, 0.0, 0.0, q, 0.0, 0.0, 0.0, q)) * (1.0 / p);
    let phi = acos(clamp(0.5 * determinant(b), -1.0, 1.0)) / 3.0;
    let e1 = q + 2.0 * p * cos(phi);
    let e3 = q + 2.0 * p * cos(phi + 2.0 * PI / 3.0);
    return vec3<f32>(e1, 3.0 * q - e1 - e3, e3);
}

// x xᵀ.
fn outer(x: vec3<f32>) -> mat3x3<f32> {
    return mat3x3<f32>(x * x.x, x * x.y, x * x.z);
}

// A unit vector in the null space of a rank-2 symmetric matrix: its rows' longest cross product.
fn null_vector(m: mat3x3<f32>) -> vec3<f32> {
    let c01 = cross(m[0], m[1]);
    let c02 = cross(m[0], m[2]);
    let c12 = cross(m[1], m[2]);
    var v = c01;
    if dot(c02, c02) > dot(v, v) {
        v = c02;
    }
    if dot(c12, c12) > dot(v, v) {
        v = c12;
    }
    return normalize(v);
}

// The form factor above the horizon of the sphere cap whose vector form factor is f (Hill's
// closed form, as three.js's LTC_ClippedSphereFormFactor).
fn clipped_sphere(f: vec3<f32>) -> f32 {
    let l = length(f);
    return max((l * l + f.z) / (l + 1.0), 0.0);
}

// ∫ D over the disk of centre c and half-axes v1, v2 (the shading frame) for the lobe m_inv:
// B = M⁻¹ [v1 v2 c]; the cone's quadric Q = B⁻ᵀ diag(1, 1, −1) B⁻¹ has two positive
// eigenvalues e1, e2 and a negative e3; its form factor is −e3 / √((e1 − e3)(e2 − e3)) about
// the null vector of Q − e3 I.
fn disk_integral(m_inv: mat3x3<f32>, c: vec3<f32>, v1: vec3<f32>, v2: vec3<f32>) -> f32 {
    let b = m_inv * mat3x3<f32>(v1, v2, c);
    let det = dot(b[0], cross(b[1], b[2]));
    let x0 = cross(b[1], b[2]) / det;
    let x1 = cross(b[2], b[0]) / det;
    let x2 = cross(b[0], b[1]) / det;
    let q = outer(x0) + outer(x1) - outer(x2);
    let e = eigenvalues(q);
    // The small negative root again from det Q = −1/det(B)² = e1 e2 e3: exact where a far
    // disk's e3 is lost beside e1 and e2 in f32.
    let e3 = -1.0 / (det * det * e.x * e.y);
    var axis = null_vector(q - mat3x3<f32>(e3, 0.0, 0.0, 0.0, e3, 0.0, 0.0, 0.0, e3));
    if dot(axis, m_inv * c) < 0.0 {
        axis = -axis;
    }
    let form_factor = -e3 / sqrt((e.x - e3) * (e.y - e3));
    return clipped_sphere(axis * form_factor);
}

// Two unit vectors completing unit n to an orthonormal frame (Duff et al. 2017).
fn orthonormal_pair(n: vec3<f32>) -> mat2x3<f32> {
    let s = select(-1.0, 1.0, n.z >= 0.0);
    let a = -1.0 / (s + n.z);
    let b = n.x * n.y * a;
    return mat2x3<f32>(vec3<f32>(1.0 + s * n.x * n.x * a, s * b, -s * n.x), vec3<f32>(b, s + n.y * n.y * a, -n.y));
}

fn method_point(pixel: MethodPixel, light: MethodPoint) -> MethodRadiance {
    let frame = transpose(mat3x3<f32>(pixel.t1, pixel.t2, pixel.n));
    let c = frame * (light.position - pixel.position);
    let d = length(c);
    // On the light, or the whole disk below the surface.
    if d < 1e-6 || c.z <= -RADIUS {
        return MethodRadiance(vec3<f32>(0.0), vec3<f32>(0.0));
    }
    let axes = orthonormal_pair(c / d);
    let v1 = axes[0] * RADIUS;
    let v2 = axes[1] * RADIUS;
    // The disk emits intensity / (π r²) as radiance: far away, the point light again.
    let radiance = light.intensity / (PI * RADIUS * RADIUS);
    let specular = radiance * (pixel.spec_magnitude * disk_integral(pixel.spec_minv, c, v1, v2));
    let diffuse = radiance * pixel.base_color * (pixel.diff_magnitude * disk_integral(pixel.diff_minv, c, v1, v2));
    return MethodRadiance(specular, diffuse);
}
