// Lights with a size (docs/design.md §1.10), mirroring src/ltc/sphere.rs (Cap and the
// illuminance of a cap), src/light/sphere/disk.rs, src/light/sphere/quadrature.rs and src/light/sphere/mod.rs by name.
// Composed after brdf.wgsl and ltc.wgsl (uses PI, Ltc, LtcPair, ltc_eval's constants and the
// BRDF terms).

// How a side shades a sphere (src/light/sphere/mod.rs SphereMethod; sphere_light.rs
// sphere_constant).
const SPHERE_EXACT: u32 = 0u;                // the BRDF over the cap
const SPHERE_LTC_POINT: u32 = 1u;            // the paper's point formula at the centre
const SPHERE_LTC_DISK: u32 = 2u;             // Heitz & Hill 2017's LTC disk
const SPHERE_REPRESENTATIVE_POINT: u32 = 3u; // Karis 2013

// How A and B shade the lights with a size: constants, so that a pipeline holds only the
// sphere methods it uses (the exact one's loops would weigh on every other's registers).
override SPHERE_A: u32 = SPHERE_LTC_DISK;
override SPHERE_B: u32 = SPHERE_EXACT;

// Cap: the directions a sphere covers seen from the shading point; cos_sigma = −1 where the
// point is inside the sphere (every direction sees it).
struct Cap {
    axis: vec3<f32>,
    sin_sigma: f32,
    cos_sigma: f32,
}

// Cap::of_sphere for r > 0: √((d − r)(d + r)) keeps cos σ accurate for a small light.
fn cap_of_sphere(u: vec3<f32>, r: f32) -> Cap {
    let d = length(u);
    var axis = vec3<f32>(0.0, 0.0, 1.0);
    if d > 0.0 {
        axis = u / d;
    }
    if d <= r {
        return Cap(axis, 1.0, -1.0);
    }
    return Cap(axis, r / d, sqrt((d - r) * (d + r)) / d);
}

fn cap_encloses(cap: Cap) -> bool {
    return cap.cos_sigma <= -1.0;
}

// Cap::below_horizon: no direction of the cap is above the surface.
fn cap_below_horizon(cap: Cap) -> bool {
    return !cap_encloses(cap) && cap.axis.z <= -cap.sin_sigma;
}

// Cap::illuminance: ∫ max(ω.z, 0) dω over the cap.
fn cap_illuminance(cap: Cap) -> f32 {
    if cap_encloses(cap) {
        return PI;
    }
    return illuminance_sphere(cap.axis.z, cap.sin_sigma * cap.sin_sigma);
}

// illuminance_sphere: ∫ max(ω.z, 0) dω over a cap of sin²σ whose axis has cos θ with the
// normal, cut by the horizon (Snyder's integral as Lagarde & de Rousiers 2014 write it;
// src/ltc/sphere.rs). Its terms cancel from O(σ) for a small cap straddling the horizon, so
// its arccosine and arctangent are the precise ones below, not WGSL's.
fn illuminance_sphere(cos_theta: f32, sin2_sigma: f32) -> f32 {
    if cos_theta * cos_theta >= sin2_sigma {
        return PI * sin2_sigma * max(cos_theta, 0.0);
    }
    let sin_theta = sqrt(max(1.0 - cos_theta * cos_theta, 0.0));
    let x = sqrt(max(1.0 / sin2_sigma - 1.0, 0.0));
    let y = clamp(-x * cos_theta / sin_theta, -1.0, 1.0);
    let z = sin_theta * sqrt(1.0 - y * y);
    var beside = PI / 2.0;
    if x > 0.0 {
        beside = atan_precise(z / x);
    }
    return max((cos_theta * acos_precise(y) - x * z) * sin2_sigma + beside, 0.0);
}

// An arctangent of x ≥ 0 within a few f32 ulps (WGSL allows its atan 4096 ulps, and its acos
// inherits that). Reduced by tan π/8 and tan 3π/8 to |t| ≤ tan π/8, then t + t³ p(t²): p is
// the least-squares fit of (atan t − t)/t³ in t² on [0, tan π/8] made for this file (relative
// error 2.1e-8 before rounding; tests/gpu/sphere_light.rs measures the f32 function).
fn atan_precise(x: f32) -> f32 {
    var base = 0.0;
    var t = x;
    if x > 2.4142135 {
        base = PI / 2.0;
        t = -1.0 / x;
    } else if x > 0.41421357 {
        base = PI / 4.0;
        t = (x - 1.0) / (x + 1.0);
    }
    let z = t * t;
    let p = -3.333296723e-1 + z * (1.997827404e-1 + z * (-1.388290811e-1 + z * 8.068712687e-2));
    return base + t + t * z * p;
}

// An arccosine within a few f32 ulps: 2 atan √((1 − y)/(1 + y)).
fn acos_precise(y: f32) -> f32 {
    if y <= -1.0 {
        return PI;
    }
    return 2.0 * atan_precise(sqrt(max(1.0 - y, 0.0) / (1.0 + y)));
}

// f32's machine epsilon, 2⁻²³.
const F32_EPSILON: f32 = 1.1920929e-7;

// negative_eigenvalue: the root of f(e) = det(q − eI) = det − c₁e + tr·e² − e³ in
// [−‖q‖, 0], by Newton's method from det/c₁ with bisection where a step would leave the
// bracket (src/light/sphere/disk.rs; no trigonometry, whose WGSL error bounds are too loose here).
fn negative_eigenvalue(q: mat3x3<f32>, det: f32) -> f32 {
    let trace = q[0][0] + q[1][1] + q[2][2];
    let c1 = q[0][0] * q[1][1] - q[1][0] * q[0][1] + q[0][0] * q[2][2] - q[2][0] * q[0][2]
        + q[1][1] * q[2][2] - q[2][1] * q[1][2];
    let norm = sqrt(dot(q[0], q[0]) + dot(q[1], q[1]) + dot(q[2], q[2]));
    var lo = -norm;
    var hi = 0.0;
    var x = 0.5 * lo;
    if c1 > 0.0 && det / c1 > lo && det / c1 < hi {
        x = det / c1;
    }
    // From det/c₁ Newton settles in a few steps; 24 bound a bisection in f32.
    for (var k = 0; k < 24; k++) {
        let fx = det - x * (c1 - x * (trace - x));
        // f(x) within its own rounding (a few ε of its terms' sizes): f32 holds no better
        // root. Waiting for a step of 0 instead takes 3 to 32 steps (over 14 for one cap in
        // seven) where rounding keeps f(x) from settling; this test, 2 to 9
        // (examples/newton_steps.rs, the benchmark's caps).
        let noise = 4.0 * F32_EPSILON * (abs(det) + abs(x * c1) + abs(x * x * trace) + abs(x * x * x));
        if abs(fx) <= noise {
            break;
        }
        if fx > 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let step = x - fx / (-c1 + x * (2.0 * trace - 3.0 * x));
        var next = 0.5 * (lo + hi);
        if step > lo && step < hi {
            next = step;
        }
        if next == x {
            break;
        }
        x = next;
    }
    return x;
}

// negative_eigenvalue of two matrices at once, lane by lane the same steps: a lane stops
// where the scalar search would, and stays.
fn negative_eigenvalues(q0: mat3x3<f32>, q1: mat3x3<f32>, det: vec2<f32>) -> vec2<f32> {
    let trace = vec2<f32>(q0[0][0] + q0[1][1] + q0[2][2], q1[0][0] + q1[1][1] + q1[2][2]);
    let c1 = vec2<f32>(
        q0[0][0] * q0[1][1] - q0[1][0] * q0[0][1] + q0[0][0] * q0[2][2] - q0[2][0] * q0[0][2]
            + q0[1][1] * q0[2][2] - q0[2][1] * q0[1][2],
        q1[0][0] * q1[1][1] - q1[1][0] * q1[0][1] + q1[0][0] * q1[2][2] - q1[2][0] * q1[0][2]
            + q1[1][1] * q1[2][2] - q1[2][1] * q1[1][2],
    );
    let norm = sqrt(vec2<f32>(
        dot(q0[0], q0[0]) + dot(q0[1], q0[1]) + dot(q0[2], q0[2]),
        dot(q1[0], q1[0]) + dot(q1[1], q1[1]) + dot(q1[2], q1[2]),
    ));
    var lo = -norm;
    var hi = vec2<f32>(0.0);
    let guess = det / c1;
    var x = select(0.5 * lo, guess, (c1 > vec2<f32>(0.0)) & (guess > lo) & (guess < hi));
    var done = vec2<bool>(false);
    for (var k = 0; k < 24; k++) {
        let fx = det - x * (c1 - x * (trace - x));
        let noise = 4.0 * F32_EPSILON * (abs(det) + abs(x * c1) + abs(x * x * trace) + abs(x * x * x));
        done = done | (abs(fx) <= noise);
        if all(done) {
            break;
        }
        lo = select(lo, x, (fx > vec2<f32>(0.0)) & !done);
        hi = select(hi, x, (fx <= vec2<f32>(0.0)) & !done);
        let step = x - fx / (-c1 + x * (2.0 * trace - 3.0 * x));
        var next = select(0.5 * (lo + hi), step, (step > lo) & (step < hi));
        next = select(next, x, done);
        done = done | (next == x);
        x = next;
    }
    return x;
}

// The adjugate of m (m⁻¹ · det m): M up to a positive or negative scale, which the cone's
// quadratic form does not see (src/light/sphere/disk.rs takes M itself; the table holds M⁻¹ only).
fn adjugate(m: mat3x3<f32>) -> mat3x3<f32> {
    // The rows of m are the columns of its transpose; adj's columns are their cross products.
    let r = transpose(m);
    return mat3x3<f32>(cross(r[1], r[2]), cross(r[2], r[0]), cross(r[0], r[1]));
}

// transformed_cone: the axis (xyz) and form factor (w) of the cap's image under M⁻¹
// (src/light/sphere/disk.rs), the cone over the ellipse of B = M⁻¹ [sin σ t₁, sin σ t₂, cos σ a].
fn transformed_cone(ltc: Ltc, cap: Cap) -> vec4<f32> {
    return cone_image(ltc, cap_basis(cap), cap.axis);
}

// cone_image: the axis (xyz, oriented as M⁻¹ towards) and form factor (w) of the image under
// M⁻¹ of the cone over the ellipse [V₁ V₂ C] of `basis`: Q = B⁻ᵀ diag(1, 1, −1) B⁻¹ with
// B = M⁻¹ basis, det Q = −1/det(B)², and (e₁ − e₃)(e₂ − e₃) = det/e₃ − e₃(tr − e₃) + e₃²
// (src/light/sphere/disk.rs). The shader makes both lobes' at once (`cone_images`).
fn cone_image(ltc: Ltc, basis: mat3x3<f32>, towards: vec3<f32>) -> vec4<f32> {
    let quadric = cone_quadric(ltc, basis);
    let e3 = negative_eigenvalue(quadric.q, quadric.det);
    return cone_of(quadric, e3, ltc.cos_from_brdf, towards);
}

// Both lobes' cone_image, their Newton iterations in one loop (the lanes of a vec2): a light
// costs the longer of the two searches, not their sum.
fn cone_images(pair: LtcPair, basis: mat3x3<f32>, towards: vec3<f32>) -> array<vec4<f32>, 2> {
    let spec = cone_quadric(pair.spec, basis);
    let diff = cone_quadric(pair.diff, basis);
    let e3 = negative_eigenvalues(spec.q, diff.q, vec2<f32>(spec.det, diff.det));
    return array<vec4<f32>, 2>(
        cone_of(spec, e3.x, pair.spec.cos_from_brdf, towards),
        cone_of(diff, e3.y, pair.diff.cos_from_brdf, towards),
    );
}

// A cone's quadratic form Q and det Q.
struct Quadric {
    q: mat3x3<f32>,
    det: f32,
}

// The cap's image's Q. M⁻¹ is first scaled to entries of at most 1 (the cone does not see its
// scale). Q is summed from B⁻¹'s rows, xᵢ = (b₁ × b₂, b₂ × b₀, b₀ × b₁)ᵢ / det B, as
// x₀x₀ᵀ + x₁x₁ᵀ − x₂x₂ᵀ: the same matrix for a third of the products of B⁻ᵀ diag(1, 1, −1) B⁻¹.
fn cone_quadric(ltc: Ltc, basis: mat3x3<f32>) -> Quadric {
    let m_inv = ltc.cos_from_brdf;
    let corners = abs(vec4<f32>(m_inv[0].x, m_inv[0].z, m_inv[2].x, m_inv[2].z));
    let big = max(max(max(corners.x, corners.y), max(corners.z, corners.w)), abs(m_inv[1].y));
    let b = (m_inv * (1.0 / big)) * basis;
    let r0 = cross(b[1], b[2]);
    let inv_det = 1.0 / dot(b[0], r0);
    let x0 = r0 * inv_det;
    let x1 = cross(b[2], b[0]) * inv_det;
    let x2 = cross(b[0], b[1]) * inv_det;
    let q = mat3x3<f32>(x0 * x0.x + x1 * x1.x - x2 * x2.x, x0 * x0.y + x1 * x1.y - x2 * x2.y,
        x0 * x0.z + x1 * x1.z - x2 * x2.z);
    return Quadric(q, -(inv_det * inv_det));
}

// The cone's axis (oriented as M⁻¹a) and form factor, from Q and its negative eigenvalue.
fn cone_of(quadric: Quadric, e3: f32, m_inv: mat3x3<f32>, a: vec3<f32>) -> vec4<f32> {
    let q = quadric.q;
    let trace = q[0][0] + q[1][1] + q[2][2];
    let spread = quadric.det / e3 - e3 * (trace - e3) + e3 * e3;
    var axis = null_vector(q - mat3x3<f32>(e3, 0.0, 0.0, 0.0, e3, 0.0, 0.0, 0.0, e3));
    if dot(axis, m_inv * a) < 0.0 {
        axis = -axis;
    }
    return vec4<f32>(axis, -e3 / sqrt(spread));
}

// null_vector: a unit vector in the null space of a rank-2 symmetric matrix, the longest cross
// product of two of its rows (src/light/sphere/disk.rs).
fn null_vector(m: mat3x3<f32>) -> vec3<f32> {
    let r = transpose(m);
    let c01 = cross(r[0], r[1]);
    let c02 = cross(r[0], r[2]);
    let c12 = cross(r[1], r[2]);
    var v = c01;
    if dot(c02, c02) > dot(v, v) {
        v = c02;
    }
    if dot(c12, c12) > dot(v, v) {
        v = c12;
    }
    return normalize(v);
}

// Two unit vectors completing unit n to an orthonormal frame (Duff et al. 2017, "Building an
// orthonormal basis, revisited"); any pair serves, the cap being round about n.
fn orthonormal_pair(n: vec3<f32>) -> mat2x3<f32> {
    let sign = select(-1.0, 1.0, n.z >= 0.0);
    let a = -1.0 / (sign + n.z);
    let b = n.x * n.y * a;
    return mat2x3<f32>(
        vec3<f32>(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x),
        vec3<f32>(b, sign + n.y * n.y * a, -n.y),
    );
}

// The cap's cone as its disc's half-axes and centre, [sin σ t₁, sin σ t₂, cos σ a] (the
// columns of B before M⁻¹; any t₁, t₂ serve, the cap being round): shared by both lobes.
fn cap_basis(cap: Cap) -> mat3x3<f32> {
    let frame = orthonormal_pair(cap.axis);
    return mat3x3<f32>(frame[0] * cap.sin_sigma, frame[1] * cap.sin_sigma, cap.axis * cap.cos_sigma);
}

// ltc_disk: ∫ D(ω) dω over the cap (Heitz & Hill 2017), case 2 through the sphere of the same
// vector form factor; the hemisphere about Mᵀz inside the sphere or where the cone is
// degenerate.
// The shader passes the cap's transformed cone, made for both lobes at once
// (`cone_images`; unread where the cap encloses the point).
fn ltc_disk(ltc: Ltc, cap: Cap, transformed: vec4<f32>, case2: bool, normalization: u32) -> f32 {
    // The hemisphere about p maps to the one about Mᵀp, of form factor 1: the upper hemisphere
    // inside the sphere, the one about the axis where the cone opened too far for its algebra.
    var cone = transformed;
    if cap_encloses(cap) {
        cone = hemisphere(ltc, vec3<f32>(0.0, 0.0, 1.0));
    } else if !cone_usable(cone) {
        cone = hemisphere(ltc, cap.axis);
    }
    return cone_integral(cone, case2, normalization);
}

// Whether a cone's axis and form factor are finite numbers (its algebra did not break down).
fn cone_usable(cone: vec4<f32>) -> bool {
    return all(abs(cone) < vec4<f32>(3.4e38)) && cone.w == cone.w;
}

// hemisphere: the image under M⁻¹ of the hemisphere about p, the one about Mᵀp of form
// factor 1 (src/light/sphere/disk.rs).
fn hemisphere(ltc: Ltc, p: vec3<f32>) -> vec4<f32> {
    // adj(M⁻¹) = det(M⁻¹) M: the sign of the determinant restores Mᵀp's direction.
    let m_t = transpose(adjugate(ltc.cos_from_brdf)) * sign(determinant(ltc.cos_from_brdf));
    return vec4<f32>(normalize(m_t * p), 1.0);
}

// cone_integral: the clamped cosine over a cone of this axis (xyz) and form factor (w), case 2
// through the sphere of the same vector form factor, else the signed F·z.
fn cone_integral(cone: vec4<f32>, case2: bool, normalization: u32) -> f32 {
    var integral = cone.w * cone.z;
    if case2 {
        integral = illuminance_sphere(cone.z, clamp(cone.w, 0.0, 1.0)) / PI;
    }
    if normalization == NORMALIZATION_PAPER_LITERAL {
        return integral * PI;
    }
    return integral;
}

// sphere_radiance: L = I / (π r²).
fn sphere_radiance(intensity: f32, r: f32) -> f32 {
    return intensity / (PI * r * r);
}

// One sphere light at one shading point (src/light/sphere/mod.rs SphereShading; range ≤ 0 is
// an infinite range, as for point lights).
struct SphereShading {
    v: vec3<f32>,
    u: vec3<f32>,
    intensity: f32,
    range: f32,
    radius: f32,
    alpha: vec2<f32>,
    f0: f32,
    clip: u32,
    normalization: u32,
}

// sphere_ltc_point: the paper's point formula at the centre (eq. 30 corrected), both lobes.
fn sphere_ltc_point(s: SphereShading, pair: LtcPair) -> vec2<f32> {
    let d = length(s.u);
    let e = irradiance_scale(s.intensity, d, s.range);
    if e <= 0.0 {
        return vec2<f32>(0.0);
    }
    let weights = lobe_weights(pair, s.f0, s.normalization);
    let l = s.u / d;
    let lobes = vec2<f32>(
        ltc_eval(pair.spec, l, s.clip, s.normalization),
        ltc_eval(pair.diff, l, s.clip, s.normalization),
    );
    return e * weights * lobes;
}

// POINT_LIMIT_SIN_SIGMA: below this sin σ a sphere is shaded as its point light (src/light/sphere/mod.rs).
const POINT_LIMIT_SIN_SIGMA: f32 = 1e-7;

// sphere_point: a sphere below POINT_LIMIT_SIN_SIGMA as its point light — the exact point light
// for the exact methods (`exact`: the exact integral and the representative point), the
// paper's formula at the centre for the LTC ones.
fn sphere_point(s: SphereShading, pair: LtcPair, exact: bool) -> vec2<f32> {
    if !exact {
        return sphere_ltc_point(s, pair);
    }
    let d = length(s.u);
    let e = irradiance_scale(s.intensity, d, s.range);
    let l = s.u / d;
    if e <= 0.0 || l.z <= 0.0 {
        return vec2<f32>(0.0);
    }
    return e * exact_lobes(s.v, l, s.alpha, s.f0);
}

// sphere_ltc_disk: both lobes (specular, diffuse) by the LTC disk.
fn sphere_ltc_disk(s: SphereShading, pair: LtcPair, cap: Cap) -> vec2<f32> {
    if (s.clip & CLIP_HORIZON) != 0u && cap_below_horizon(cap) {
        return vec2<f32>(0.0);
    }
    let d2 = dot(s.u, s.u);
    let scale = window_falloff_d2(d2, s.range) * sphere_radiance(s.intensity, s.radius);
    let weights = lobe_weights(pair, s.f0, s.normalization);
    let case2 = (s.clip & CLIP_TRANSFORMED) != 0u;
    var cones = array<vec4<f32>, 2>(vec4<f32>(0.0), vec4<f32>(0.0));
    if !cap_encloses(cap) {
        cones = cone_images(pair, cap_basis(cap), cap.axis);
    }
    let lobes = vec2<f32>(
        ltc_disk(pair.spec, cap, cones[0], case2, s.normalization),
        ltc_disk(pair.diff, cap, cones[1], case2, s.normalization),
    );
    return scale * weights * lobes;
}

// sphere_representative_point: Karis 2013 in Unreal's form (src/light/sphere/mod.rs).
fn sphere_representative_point(s: SphereShading, cap: Cap) -> vec2<f32> {
    let d = length(s.u);
    let w = window_falloff_d2(d * d, s.range);
    let reflected = mirror(s.v);
    let centre_to_ray = reflected * dot(s.u, reflected) - s.u;
    let reach = length(centre_to_ray);
    var closest = s.u + centre_to_ray;
    if reach > s.radius {
        closest = s.u + centre_to_ray * (s.radius / reach);
    }
    var l = reflected;
    if dot(closest, closest) > 0.0 {
        l = normalize(closest);
    }
    let energy = widening_energy(s.alpha, min(s.radius / max(d, MIN_LIGHT_DISTANCE), 1.0));
    let dr = max(d, s.radius);
    var specular = 0.0;
    if l.z > 0.0 {
        specular = exact_lobes(s.v, l, s.alpha, s.f0).x;
    }
    let diffuse = fd_toward(s.v, cap.axis, 0.5 * (s.alpha.x + s.alpha.y))
        * sphere_radiance(s.intensity, s.radius) * cap_illuminance(cap);
    return vec2<f32>(w * s.intensity / (dr * dr) * energy * specular, w * diffuse);
}

// widening_energy: Karis's energy normalization (α/α')² for a lobe widened by `spread`,
// (α_x/α_x')(α_y/α_y') for an anisotropic one (src/light/sphere/mod.rs).
fn widening_energy(alpha: vec2<f32>, spread: f32) -> f32 {
    if ANISO {
        let wide = min(alpha + 0.5 * spread, vec2<f32>(1.0));
        return (alpha.x / wide.x) * (alpha.y / wide.y);
    }
    let alpha_wide = min(alpha.x + 0.5 * spread, 1.0);
    return (alpha.x / alpha_wide) * (alpha.x / alpha_wide);
}

// fd_toward: Burley's diffuse toward a direction that may lie below the horizon (n·l at 0).
fn fd_toward(v: vec3<f32>, l: vec3<f32>, alpha: f32) -> f32 {
    let sum = v + l;
    if dot(sum, sum) <= 0.0 {
        return 0.0;
    }
    let h = normalize(sum);
    return fd_burley(v.z, max(l.z, 0.0), dot(l, h), alpha);
}

// sin and cos of φ in [−π, π] within a few ulps (WGSL allows 2⁻¹¹ absolute, which would move a
// sharp lobe's sample directions): reduced by π/2 in two parts (Cody & Waite), then Taylor
// polynomials to degree 9 and 10 on |r| ≤ π/4 (truncation below 2e-9).
fn sincos_precise(phi: f32) -> vec2<f32> {
    let k = round(phi / (PI / 2.0));
    let r = (phi - k * 1.5707963705062866) + k * 4.371139e-8;
    let z = r * r;
    let s = r * (1.0 + z * (-1.0 / 6.0 + z * (1.0 / 120.0 + z * (-1.0 / 5040.0 + z / 362880.0))));
    let c = 1.0
        + z * (-0.5 + z * (1.0 / 24.0 + z * (-1.0 / 720.0 + z * (1.0 / 40320.0 - z / 3628800.0))));
    // k is in −2…2; the remainder of a negative integer is undefined in GLSL, so it is taken
    // of k + 4.
    let q = u32(k + 4.0) % 4u;
    if q == 0u {
        return vec2<f32>(s, c);
    }
    if q == 1u {
        return vec2<f32>(c, -s);
    }
    if q == 2u {
        return vec2<f32>(-s, -c);
    }
    return vec2<f32>(-c, s);
}

// visible_half_azimuth: the half-width of the azimuths where c + k cos φ > 0 (k ≥ 0), −1
// where there are none (src/light/sphere/quadrature.rs).
fn visible_half_azimuth(c: f32, k: f32) -> f32 {
    if c >= k {
        return PI;
    }
    if c <= -k {
        return -1.0;
    }
    return acos_precise(clamp(-c / k, -1.0, 1.0));
}

// sphere_rule: w(d) · L · ∫ f cos dω over the cap above the surface by the renders' rule
// (src/light/sphere/mod.rs sphere_rule, docs/design.md §1.14).
fn sphere_rule(s: SphereShading, cap: Cap) -> vec2<f32> {
    let d2 = dot(s.u, s.u);
    return window_falloff_d2(d2, s.range) * sphere_radiance(s.intensity, s.radius)
        * cap_rule(s.v, cap, s.alpha, s.f0);
}

// cap_rule: both lobes over the cap above the surface at unit radiance by the polar rule
// (src/light/sphere/region.rs).
fn cap_rule(v: vec3<f32>, cap: Cap, alpha: vec2<f32>, f0: f32) -> vec2<f32> {
    if cap_below_horizon(cap) {
        return vec2<f32>(0.0);
    }
    let polar = cap_polar(cap, mirror(v), v, alpha, f0);
    if polar.pole.z < -1.0 {
        return vec2<f32>(0.0);
    }
    let lobes = array<Lobe, 2>(
        lobe_within(lobe_specular(polar.pole, v, alpha), polar.bounds, cap_middle(cap)),
        lobe_round(polar.pole),
    );
    // Both lobes from one call of the rule (see polar_piece).
    var out = vec2<f32>(0.0);
    for (var which = 0u; which < 2u; which++) {
        let n = select(DIFFUSE_NODES, rule_nodes(alpha), which == 0u);
        out[which] = polar_integral(polar, lobes[which], n, v, alpha, f0, which);
    }
    return out;
}

// cap_polar: the cap above the surface as a polar region, its pole at focus where the cap
// holds it, else at its boundary's brightest point; cut where the horizon meets the circle,
// along the circle and the horizon as they pass the pole and toward the horizon's foot
// (src/light/sphere/region.rs). A pole below −1 says no part of the cap is visible.
fn cap_polar(cap: Cap, focus: vec3<f32>, v: vec3<f32>, alpha: vec2<f32>, f0: f32) -> Polar {
    let zenith = vec3<f32>(0.0, 0.0, 1.0);
    if cap_encloses(cap) {
        var polar = polar_new(bounds_above(vec4<f32>(0.0, 0.0, 0.0, -1.0)), focus, 4u);
        polar_cut_both(&polar, cross(zenith, focus));
        polar_cut_foot(&polar, zenith);
        return polar;
    }
    let a = cap.axis;
    let depth = cap.sin_sigma * cap.sin_sigma / (1.0 + cap.cos_sigma);
    let bounds = bounds_above(vec4<f32>(a, depth));
    let t1 = cap_up(cap);
    let t2 = cross(a, t1);
    let half = visible_half_azimuth(a.z * cap.cos_sigma, t1.z * cap.sin_sigma);
    if half < 0.0 {
        return polar_new(bounds, vec3<f32>(0.0, 0.0, -2.0), 4u);
    }
    var arcs: array<Arc, 5>;
    arcs[0] = Arc(a, t1, t2, vec4<f32>(cap.cos_sigma, cap.sin_sigma, -half, 2.0 * half));
    let cut = half < PI;
    let e0 = arc_at(arcs[0], 1.0);
    let e1 = arc_at(arcs[0], 0.0);
    let c0 = normalize(vec3<f32>(e0.xy, 0.0));
    let c1 = normalize(vec3<f32>(e1.xy, 0.0));
    arcs[1] = Arc(c0, c1, vec3<f32>(0.0), vec4<f32>(0.0));
    var pole = focus;
    if !bounds_contains(bounds, focus) {
        let best = brightest(arcs, select(1u, 2u, cut), v, alpha, f0);
        pole = arc_at(arcs[u32(best.x)], best.y);
    }
    var polar = polar_new(bounds, pole, 4u);
    polar_cut_both(&polar, cross(a, pole));
    if cut {
        polar_cut_both(&polar, cross(zenith, pole));
        polar_cut_foot(&polar, zenith);
        polar_cut_toward(&polar, c0);
        polar_cut_toward(&polar, c1);
    }
    return polar;
}

// The unit vector in the plane of the cap's axis and +z, pointing up (+x where the axis is
// vertical): a circle point's height is a.z cos σ + t1.z sin σ cos ψ.
fn cap_up(cap: Cap) -> vec3<f32> {
    let up = vec3<f32>(0.0, 0.0, 1.0) - cap.axis * cap.axis.z;
    if dot(up, up) > 0.0 {
        return normalize(up);
    }
    return vec3<f32>(1.0, 0.0, 0.0);
}

// cap_middle: a point well inside the cap above the surface (src/light/sphere/region.rs).
fn cap_middle(cap: Cap) -> vec3<f32> {
    let a = cap.axis;
    if cap_encloses(cap) {
        return vec3<f32>(0.0, 0.0, 1.0);
    }
    let t1 = cap_up(cap);
    let half = visible_half_azimuth(a.z * cap.cos_sigma, t1.z * cap.sin_sigma);
    if half < 0.0 || half >= PI {
        return a;
    }
    let arc = Arc(a, t1, cross(a, t1), vec4<f32>(cap.cos_sigma, cap.sin_sigma, 0.0, half));
    let edge = arc_at(arc, 1.0);
    let top = arc_at(arc, 0.0);
    return normalize(top + normalize(vec3<f32>(edge.xy, 0.0)));
}
