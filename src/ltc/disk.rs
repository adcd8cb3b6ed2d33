//! An LTC integrated over a cap of directions: Heitz & Hill 2017 ("Real-time line- and
//! disk-light shading with linearly transformed cosines") for the cap that a sphere light
//! covers, which is also the cone of the disc facing the point with the same solid angle
//! (docs/design.md §1.10). `M⁻¹` maps the circular cone to an elliptical one; its axis and
//! half-widths come from the eigenvalues of the cone's quadratic form, the clamped cosine's
//! integral over it from the form factor of an elliptical cone, and its cut by the transformed
//! horizon from the sphere of the same vector form factor (the value Heitz & Hill's second table
//! holds, `sphere::clipped_cap_projected_solid_angle`, here in closed form).

use std::f64::consts::{FRAC_PI_3, PI};

use glam::{DMat3, DVec3};

use super::sphere::{Cap, clipped_cap_projected_solid_angle};
use super::{Ltc, Normalization};

/// `∫ D(ω) dω` over the cap (every direction above the surface where the point is inside the
/// sphere). `case2` clips the transformed cone at the clamped cosine's horizon (eq. 30's
/// second rule); off, the integral is the signed one, and negative where the cone lies below.
pub fn ltc_disk(ltc: &Ltc, cap: &Cap, case2: bool, normalization: Normalization) -> f64 {
    // The upper hemisphere maps to the hemisphere about `Mᵀ z` (`(Mω')·z > 0`), whose form
    // factor is 1: the cap of a point inside the sphere, and the limit of one whose cone
    // has opened too far for its eigenvalues (`cos σ` within f64's reach of 0).
    let hemisphere = || ((ltc.brdf_from_cos.transpose() * DVec3::Z).normalize(), 1.0);
    let (axis, form_factor) = if cap.encloses() {
        hemisphere()
    } else {
        Some(transformed_cone(ltc, cap))
            .filter(|(axis, ff)| axis.is_finite() && ff.is_finite())
            .unwrap_or_else(hemisphere)
    };
    let integral = if case2 {
        let omega = axis.z.clamp(-1.0, 1.0).acos();
        clipped_cap_projected_solid_angle(omega, form_factor.clamp(0.0, 1.0).sqrt().asin()) / PI
    } else {
        form_factor * axis.z
    };
    match normalization {
        Normalization::Corrected => integral,
        Normalization::PaperLiteral => integral * PI,
    }
}

/// The axis and form factor `sin²σ'` of the cap's image under `M⁻¹`, an elliptical cone.
/// The cap is `ω·Q₀·ω ≤ 0` with `Q₀ = cos²σ I − a aᵀ`; its image is `ω'·Q·ω' ≤ 0` with
/// `Q = Mᵀ Q₀ M`, of one negative eigenvalue `e₃` (the axis) and two positive ones. In the
/// eigenframe the cone's tangent half-widths are `√(−e₃/e₁)`, `√(−e₃/e₂)`, and Heitz & Hill's
/// form factor `L₁L₂/√((1 + L₁²)(1 + L₂²))` is `−e₃/√((e₁ − e₃)(e₂ − e₃))`.
pub fn transformed_cone(ltc: &Ltc, cap: &Cap) -> (DVec3, f64) {
    let m = ltc.brdf_from_cos;
    let a = cap.axis;
    let q0 = DMat3::from_diagonal(DVec3::splat(cap.cos_sigma * cap.cos_sigma)) - outer(a, a);
    let q = m.transpose() * q0 * m;
    let [e1, e2, _] = sym3_eigenvalues(q);
    // det Q = det(M)² det Q₀ = −det(M)² sin²σ cos⁴σ, exactly; e₃ from it keeps its relative
    // accuracy for a small cap, where it is the difference of two nearly equal terms.
    let det_q0 = -(cap.sin_sigma * cap.cos_sigma * cap.cos_sigma).powi(2);
    let e3 = m.determinant().powi(2) * det_q0 / (e1 * e2);
    let axis = null_vector(q - DMat3::from_diagonal(DVec3::splat(e3)));
    let axis = if axis.dot(ltc.cos_from_brdf * a) < 0.0 {
        -axis
    } else {
        axis
    };
    let form_factor = -e3 / ((e1 - e3) * (e2 - e3)).sqrt();
    (axis, form_factor)
}

/// `a bᵀ`.
fn outer(a: DVec3, b: DVec3) -> DMat3 {
    DMat3::from_cols(a * b.x, a * b.y, a * b.z)
}

/// The eigenvalues of a symmetric 3×3 matrix, largest first, in closed form (Smith 1961,
/// "Eigenvalues of a symmetric 3 × 3 matrix", Commun. ACM 4(4)).
pub fn sym3_eigenvalues(q: DMat3) -> [f64; 3] {
    let off = q.col(1)[0].powi(2) + q.col(2)[0].powi(2) + q.col(2)[1].powi(2);
    let mean = (q.col(0)[0] + q.col(1)[1] + q.col(2)[2]) / 3.0;
    let spread = (0..3).map(|i| (q.col(i)[i] - mean).powi(2)).sum::<f64>() + 2.0 * off;
    if spread <= 0.0 {
        return [mean; 3];
    }
    let p = (spread / 6.0).sqrt();
    let b = (q - DMat3::from_diagonal(DVec3::splat(mean))) * (1.0 / p);
    let phi = (0.5 * b.determinant()).clamp(-1.0, 1.0).acos() / 3.0;
    let largest = mean + 2.0 * p * phi.cos();
    let smallest = mean + 2.0 * p * (phi + 2.0 * FRAC_PI_3).cos();
    [largest, 3.0 * mean - largest - smallest, smallest]
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
