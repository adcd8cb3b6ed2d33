// The anisotropic table's lookup (docs/design.md §2.9), mirroring src/ltc/aniso/ (the
// Rust names in brackets): the fold of a material and a view into the table's quarter
// (AnisoAxes::fold), the axes' coordinates (AnisoAxes::coordinates), quadrilinear
// interpolation in the shader (AnisoLut::sample), the stored matrix turned into M⁻¹
// (Stored::cos_from_brdf, mirror_frame, canonical::proper) and the lobe in the tangent frame
// (AnisoLut::ltc). Composed after ltc.wgsl and sphere_light.wgsl (uses Ltc, atan_precise,
// acos_precise); its Rust side is src/gpu/ltc_aniso/mod.rs.

// AnisoAxes (src/gpu/ltc_aniso/mod.rs axes_constant).
const AXES_LAB: u32 = 0u;
const AXES_I3D_ALPHA_XY: u32 = 1u;
const AXES_I3D_ALPHA_LAMBDA: u32 = 2u;

// Stored (src/gpu/ltc_aniso/mod.rs stored_constant).
const STORED_COS_FROM_BRDF: u32 = 0u;
const STORED_BRDF_FROM_COS: u32 = 1u;
const STORED_MIRROR_FROM_COS: u32 = 2u;
const STORED_MIRROR_POLE: u32 = 3u;

// src/ltc/lut/axes.rs ALPHA_MIN and THETA_MAX; src/ltc/aniso/axes.rs I3D_THETA_MAX's and
// I3D_ALPHA_MIN's values.
const ANISO_ALPHA_MIN: f32 = 1e-4;
const COS_THETA_MAX: f32 = 0.0007963267; // cos(1.57)
const I3D_THETA_MAX: f32 = 1.5706392; // 0.9999 · π/2
const I3D_ALPHA_MIN: f32 = 1e-4;

// Three vec4s a node (src/gpu/ltc_aniso/mod.rs pack_aniso): [m00 m01 m02 m10] [m11 m12 m20 m21]
// [m22 norm fresnel 0], the stored matrix by rows, nodes in AnisoLut::index's order.
const ANISO_VEC4S_PER_NODE: u32 = 3u;

// A 4D table in the LUT buffer: its first vec4, its node counts (a, b, t, p), its axes and
// what it stores.
struct AnisoTable {
    base: u32,
    dims: vec4<u32>,
    axes: u32,
    stored: u32,
}

// A material and a view folded into a table's quarter: the roughness (x the larger where the
// axes need it), the view there (unit), and table_from_tangent.
struct Folded {
    alpha: vec2<f32>,
    w: vec3<f32>,
    table_from_tangent: mat3x3<f32>,
}

// AnisoAxes::fold: a quarter turn where the axes keep α_x the larger and the material is
// rougher along its bitangent, then the mirrors of x and y that bring v into the first
// quadrant.
fn aniso_fold(axes: u32, alpha: vec2<f32>, v: vec3<f32>) -> Folded {
    var f: Folded;
    f.alpha = alpha;
    var turn = mat3x3<f32>(vec3<f32>(1.0, 0.0, 0.0), vec3<f32>(0.0, 1.0, 0.0), vec3<f32>(0.0, 0.0, 1.0));
    if axes != AXES_I3D_ALPHA_XY && alpha.y > alpha.x {
        // x' = y, y' = −x (columns: the images of x, y, z).
        turn = mat3x3<f32>(vec3<f32>(0.0, -1.0, 0.0), vec3<f32>(1.0, 0.0, 0.0), vec3<f32>(0.0, 0.0, 1.0));
        f.alpha = alpha.yx;
    }
    let w = turn * v;
    let signs = select(vec3<f32>(1.0), vec3<f32>(-1.0, -1.0, 1.0), vec3<bool>(w.x < 0.0, w.y < 0.0, false));
    let mirror = mat3x3<f32>(vec3<f32>(signs.x, 0.0, 0.0), vec3<f32>(0.0, signs.y, 0.0), vec3<f32>(0.0, 0.0, 1.0));
    f.w = mirror * w;
    f.table_from_tangent = mirror * turn;
    return f;
}

// atan2(y, x) for x, y ≥ 0, by atan_precise: the folded view's azimuth in [0, π/2].
fn azimuth_first_quadrant(y: f32, x: f32) -> f32 {
    if x <= 0.0 && y <= 0.0 {
        return 0.0;
    }
    if y <= x {
        return atan_precise(y / x);
    }
    return 0.5 * PI - atan_precise(x / y);
}

// axes.rs first_interval: a linear axis of nodes k · step whose first node was raised to
// `first`.
fn first_interval(x: f32, first: f32, step: f32) -> f32 {
    if x >= step || first >= step {
        return x;
    }
    return step * (x - first) / (step - first);
}

// AnisoAxes::coordinates: each axis in [0, 1] between its first and last node.
fn aniso_coordinates(axes: u32, f: Folded) -> vec4<f32> {
    let phi = azimuth_first_quadrant(f.w.y, f.w.x) / (0.5 * PI);
    var c: vec4<f32>;
    if axes == AXES_LAB {
        c = vec4<f32>(
            sqrt(max((f.alpha.x - ANISO_ALPHA_MIN) / (1.0 - ANISO_ALPHA_MIN), 0.0)),
            sqrt(max((f.alpha.y - ANISO_ALPHA_MIN) / max(f.alpha.x - ANISO_ALPHA_MIN, 1e-30), 0.0)),
            sqrt(max((1.0 - f.w.z) / (1.0 - COS_THETA_MAX), 0.0)),
            phi,
        );
    } else {
        let theta = acos_precise(clamp(f.w.z, -1.0, 1.0)) / I3D_THETA_MAX;
        let ax = first_interval(f.alpha.x, I3D_ALPHA_MIN, 1.0 / 7.0);
        var b = first_interval(f.alpha.y, I3D_ALPHA_MIN, 1.0 / 7.0);
        if axes == AXES_I3D_ALPHA_LAMBDA {
            b = first_interval(f.alpha.y / f.alpha.x, I3D_ALPHA_MIN / f.alpha.x, 1.0 / 7.0);
        }
        c = vec4<f32>(ax, b, theta, phi);
    }
    return clamp(c, vec4<f32>(0.0), vec4<f32>(1.0));
}

// The table's nine numbers at a point (AnisoLut::sample's matrix, by its rows) and its
// magnitudes.
struct AnisoSample {
    r0: vec3<f32>,
    r1: vec3<f32>,
    r2: vec3<f32>,
    norm: f32,
    fresnel: f32,
}

// AnisoLut::sample: quadrilinear interpolation with clamp-to-edge addressing, each axis by
// lut::bilinear_taps at the node coordinate's texel coordinate.
fn aniso_sample(t: AnisoTable, c: vec4<f32>) -> AnisoSample {
    let n = vec4<f32>(t.dims);
    let x = (c * (n - 1.0) / n + 0.5 / n) * n - 0.5;
    let x0 = floor(x);
    let last = n - 1.0;
    let k0 = vec4<u32>(clamp(x0, vec4<f32>(0.0), last));
    let k1 = vec4<u32>(clamp(x0 + 1.0, vec4<f32>(0.0), last));
    let f = x - x0;
    var rows = array<vec4<f32>, 3>(vec4<f32>(0.0), vec4<f32>(0.0), vec4<f32>(0.0));
    for (var corner = 0u; corner < 16u; corner++) {
        let far = vec4<bool>((corner & 1u) != 0u, (corner & 2u) != 0u, (corner & 4u) != 0u, (corner & 8u) != 0u);
        let k = select(k0, k1, far);
        let w4 = select(1.0 - f, f, far);
        let w = w4.x * w4.y * w4.z * w4.w;
        let node = ((k.w * t.dims.z + k.z) * t.dims.y + k.y) * t.dims.x + k.x;
        let at = t.base + node * ANISO_VEC4S_PER_NODE;
        rows[0] += w * lut[at];
        rows[1] += w * lut[at + 1u];
        rows[2] += w * lut[at + 2u];
    }
    let r = rows;
    return AnisoSample(
        vec3<f32>(r[0].x, r[0].y, r[0].z),
        vec3<f32>(r[0].w, r[1].x, r[1].y),
        vec3<f32>(r[1].z, r[1].w, r[2].x),
        r[2].y,
        r[2].z,
    );
}

// The inverse of a 3×3 matrix by its adjugate: rows b × c, c × a, a × b over the
// determinant (a, b, c its columns).
fn inverse3(m: mat3x3<f32>) -> mat3x3<f32> {
    let a = m[0];
    let b = m[1];
    let c = m[2];
    let det = dot(a, cross(b, c));
    return transpose(mat3x3<f32>(cross(b, c), cross(c, a), cross(a, b))) * (1.0 / det);
}

// turn_z_to: the turn that takes z to the unit vector d (d.z > −1), by Rodrigues' formula
// with s = z × d = (−d.y, d.x, 0): d.z I + [s]× + s sᵀ/(1 + d.z).
fn turn_z_to(d: vec3<f32>) -> mat3x3<f32> {
    let s = vec3<f32>(-d.y, d.x, 0.0);
    let k = 1.0 / (1.0 + d.z);
    return mat3x3<f32>(
        vec3<f32>(d.z + s.x * s.x * k, s.y * s.x * k, -s.y),
        vec3<f32>(s.x * s.y * k, d.z + s.y * s.y * k, s.x),
        vec3<f32>(s.y, -s.x, d.z),
    );
}

// mirror_frame: the turn that takes z to the mirror direction of the unit view w (the
// table's frame).
fn mirror_frame(w: vec3<f32>) -> mat3x3<f32> {
    return turn_z_to(vec3<f32>(-w.x, -w.y, w.z));
}

// stored::from_pole_and_shape: M (in the mirror frame) from an axis n (rows[0], any length)
// and a shape [u00 u01 u11] [u20 u21 u22]: F(n) · [[u00 u01 0] [u01 u11 0] [u20 u21 u22]].
fn from_pole_and_shape(s: AnisoSample) -> mat3x3<f32> {
    let u = mat3x3<f32>(
        vec3<f32>(s.r1.x, s.r1.y, s.r2.x),
        vec3<f32>(s.r1.y, s.r1.z, s.r2.y),
        vec3<f32>(0.0, 0.0, s.r2.z),
    );
    return turn_z_to(normalize(s.r0)) * u;
}

// Stored::cos_from_brdf: M⁻¹ from what the table holds at the folded view w.
fn aniso_cos_from_brdf(stored: u32, s: AnisoSample, w: vec3<f32>) -> mat3x3<f32> {
    // The nine numbers as a matrix by rows (WGSL builds matrices from columns).
    let m = transpose(mat3x3<f32>(s.r0, s.r1, s.r2));
    if stored == STORED_COS_FROM_BRDF {
        return m;
    }
    if stored == STORED_BRDF_FROM_COS {
        return inverse3(m);
    }
    if stored == STORED_MIRROR_FROM_COS {
        return inverse3(mirror_frame(w) * m);
    }
    return inverse3(mirror_frame(w) * from_pole_and_shape(s));
}

// canonical::proper: the same lobe with a positive determinant (mirrored through the
// xz-plane where it was negative).
fn proper(m: mat3x3<f32>) -> mat3x3<f32> {
    if determinant(m) < 0.0 {
        // MIRROR_Y · M flips the second row: in columns, each column's y.
        return mat3x3<f32>(m[0] * vec3<f32>(1.0, -1.0, 1.0), m[1] * vec3<f32>(1.0, -1.0, 1.0), m[2] * vec3<f32>(1.0, -1.0, 1.0));
    }
    return m;
}

// AnisoLut::ltc: the specular lobe for a material and a unit view v in the tangent frame
// (v.z > 0), acting on the tangent frame's directions: Sᵀ M⁻¹ S with S the fold.
fn aniso_ltc(t: AnisoTable, alpha: vec2<f32>, v: vec3<f32>) -> Ltc {
    let f = aniso_fold(t.axes, alpha, v);
    let s = aniso_sample(t, aniso_coordinates(t.axes, f));
    let s_fold = f.table_from_tangent;
    let m = proper(transpose(s_fold) * aniso_cos_from_brdf(t.stored, s, f.w) * s_fold);
    return Ltc(m, abs(determinant(m)), s.norm, s.fresnel, 1.0);
}
