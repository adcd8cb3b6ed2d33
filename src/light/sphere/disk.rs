//! An LTC integrated over a cap of directions: Heitz & Hill 2017 ("Real-time line- and
//! disk-light shading with linearly transformed cosines") for the cap that a sphere light
//! covers, which is also the cone of the disc facing the point with the same solid angle
//! (docs/design.md §1.10). `M⁻¹` maps the circular cone to an elliptical one; its axis and
//! half-widths come from the negative eigenvalue of the cone's quadratic form, the clamped cosine's
//! integral over it from the form factor of an elliptical cone, and its cut by the transformed
//! horizon from the sphere of the same vector form factor (the value Heitz & Hill's second table
//! holds, here in closed form: `sphere::illuminance_sphere`).

use std::f64::consts::PI;

use glam::{DMat3, DVec3};

use crate::light::sphere::cap::Cap;
use crate::ltc::sphere::illuminance_sphere;
use crate::ltc::{Ltc, Normalization};

/// `∫ D(ω) dω` over the cap (every direction above the surface where the point is inside the
/// sphere). `case2` clips the transformed cone at the clamped cosine's horizon (eq. 30's
/// second rule); off, the integral is the signed one, and negative where the cone lies below.
pub fn ltc_disk(ltc: &Ltc, cap: &Cap, case2: bool, normalization: Normalization) -> f64 {
    let (axis, form_factor) = if cap.encloses() {
        hemisphere(ltc, DVec3::Z)
    } else {
        Some(transformed_cone(ltc, cap))
            .filter(|(axis, ff)| axis.is_finite() && ff.is_finite())
            .unwrap_or_else(|| hemisphere(ltc, cap.axis))
    };
    cone_integral(axis, form_factor, case2, normalization)
}

/// The image under `M⁻¹` of the hemisphere about `p`, as a cone's axis and form factor: the
/// one about `Mᵀp` (`(Mω')·p > 0`), of form factor 1. The upper hemisphere is the cap of a
/// point inside the sphere, and the hemisphere about the axis the limit of a cap (or a disk
/// light's cone) opened too far for its cone's algebra.
pub fn hemisphere(ltc: &Ltc, p: DVec3) -> (DVec3, f64) {
    ((ltc.brdf_from_cos.transpose() * p).normalize(), 1.0)
}

/// The clamped cosine's integral over a cone of this unit axis and form factor (the cone's
/// image under `M⁻¹`): `case2` clips it at the cosine's horizon as the sphere of the same
/// vector form factor (eq. 30's second rule); off, the signed `F·z`, negative below.
pub fn cone_integral(
    axis: DVec3,
    form_factor: f64,
    case2: bool,
    normalization: Normalization,
) -> f64 {
    let integral = if case2 {
        illuminance_sphere(axis.z, form_factor.clamp(0.0, 1.0)) / PI
    } else {
        form_factor * axis.z
    };
    match normalization {
        Normalization::Corrected => integral,
        Normalization::PaperLiteral => integral * PI,
    }
}

/// The axis and form factor `sin²σ'` of the cap's image under `M⁻¹`, an elliptical cone.
/// The cap is the cone over the disc `C + x V₁ + y V₂` (`x² + y² ≤ 1`) with `C = cos σ a` and
/// `V₁, V₂ = sin σ t₁, sin σ t₂`; `M⁻¹` takes it to the cone over the ellipse of
/// `B = M⁻¹ [V₁ V₂ C]`, which is `ω'·Q·ω' ≤ 0` with `Q = B⁻ᵀ diag(1, 1, −1) B⁻¹`, of one
/// negative eigenvalue `e₃` (the axis) and two positive ones. (Writing `Q` from `cos²σ I − aaᵀ`
/// instead leaves a small cap's width to the difference `cos²σ − |a|²`, which f32 rounds
/// away.) In the eigenframe the cone's tangent half-widths are `√(−e₃/e₁)`, `√(−e₃/e₂)`, and
/// Heitz & Hill's form factor `L₁L₂/√((1 + L₁²)(1 + L₂²))` is `−e₃/√((e₁ − e₃)(e₂ − e₃))`,
/// where `(e₁ − e₃)(e₂ − e₃) = P − e₃S + e₃²` with `P = e₁e₂ = det Q/e₃` and
/// `S = e₁ + e₂ = tr Q − e₃`: only `e₃` is needed, and `det Q = −1/det(B)²`.
pub fn transformed_cone(ltc: &Ltc, cap: &Cap) -> (DVec3, f64) {
    let a = cap.axis;
    let (t1, t2) = a.any_orthonormal_pair();
    let (s, c) = (cap.sin_sigma, cap.cos_sigma);
    cone_image(ltc, DMat3::from_cols(t1 * s, t2 * s, a * c), a)
}

/// The axis (oriented as `M⁻¹ towards`) and form factor of the image under `M⁻¹` of the cone
/// over the ellipse `C + x V₁ + y V₂` (`x² + y² ≤ 1`), `basis = [V₁ V₂ C]`: a sphere's cap
/// (`transformed_cone`) or a disk light (`light::disk`), whose half-axes and centre it is.
pub fn cone_image(ltc: &Ltc, basis: DMat3, towards: DVec3) -> (DVec3, f64) {
    let a = towards;
    let b = ltc.cos_from_brdf * basis;
    let b_inv = b.inverse();
    let q = b_inv.transpose() * DMat3::from_diagonal(DVec3::new(1.0, 1.0, -1.0)) * b_inv;
    let det = -1.0 / b.determinant().powi(2);
    let e3 = negative_eigenvalue(q, det);
    let trace = q.col(0)[0] + q.col(1)[1] + q.col(2)[2];
    let spread = det / e3 - e3 * (trace - e3) + e3 * e3;
    let axis = null_vector(q - DMat3::from_diagonal(DVec3::splat(e3)));
    let axis = if axis.dot(ltc.cos_from_brdf * a) < 0.0 {
        -axis
    } else {
        axis
    };
    (axis, -e3 / spread.sqrt())
}

/// Newton steps at most: from `det/c₁` the root is reached in a few; the bound only stops a
/// bisection that rounding keeps from settling.
const NEWTON_STEPS: usize = 64;

/// The one negative eigenvalue of a symmetric `q` with two positive ones, given `det q`
/// (computed exactly by the caller): the root of `f(e) = det(q − eI) = det − c₁e + tr·e² − e³`
/// in `[−‖q‖, 0]`, where `f` goes from positive to `det < 0`. Newton's method from `det/c₁`
/// (the root to first order when it is small), bisecting where a step would leave the
/// bracket. No trigonometry: the shaders' closed-form eigenvalues would lean on WGSL's `acos`
/// and `cos`, whose allowed errors (4096 ulps, 2⁻¹¹ absolute) are the cone's whole width for a
/// small light.
pub fn negative_eigenvalue(q: DMat3, det: f64) -> f64 {
    let e = |r: usize, c: usize| q.col(c)[r];
    let trace = e(0, 0) + e(1, 1) + e(2, 2);
    let c1 = e(0, 0) * e(1, 1) - e(0, 1) * e(1, 0) + e(0, 0) * e(2, 2) - e(0, 2) * e(2, 0)
        + e(1, 1) * e(2, 2)
        - e(1, 2) * e(2, 1);
    let f = |x: f64| det - x * (c1 - x * (trace - x));
    let df = |x: f64| -c1 + x * (2.0 * trace - 3.0 * x);
    let norm = (0..3)
        .map(|c| q.col(c).length_squared())
        .sum::<f64>()
        .sqrt();
    let (mut lo, mut hi) = (-norm, 0.0);
    let mut x = if c1 > 0.0 { det / c1 } else { 0.5 * lo };
    if !(x > lo && x < hi) {
        x = 0.5 * (lo + hi);
    }
    for _ in 0..NEWTON_STEPS {
        let fx = f(x);
        if fx > 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let step = x - fx / df(x);
        let next = if step > lo && step < hi {
            step
        } else {
            0.5 * (lo + hi)
        };
        if next == x {
            break;
        }
        x = next;
    }
    x
}

/// A unit vector in the null space of a rank-2 symmetric matrix: the longest cross product
/// of two of its rows (each is orthogonal to both rows, so to the row space).
fn null_vector(m: DMat3) -> DVec3 {
    let rows = [m.row(0), m.row(1), m.row(2)];
    [
        rows[0].cross(rows[1]),
        rows[0].cross(rows[2]),
        rows[1].cross(rows[2]),
    ]
    .into_iter()
    .max_by(|x, y| x.length_squared().total_cmp(&y.length_squared()))
    .and_then(DVec3::try_normalize)
    .unwrap_or(DVec3::Z)
}
