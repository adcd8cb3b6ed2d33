//! One matrix among the equivalent ones (docs/design.md §2.9). The clamped cosine is
//! symmetric about z, so `M⁻¹` and `Q M⁻¹` give the same lobe for every orthogonal `Q` that
//! fixes z (a turn about z, a mirror through a plane holding z), and so do `M⁻¹` and `c M⁻¹`
//! for every `c > 0` (docs/design.md §1.4). A table whose neighbouring nodes picked different
//! members of their classes would interpolate between unrelated matrices — through singular
//! ones where their turns differ by a half turn. The lab fixes the three free choices by rules
//! that are continuous in the matrix: the sign of the determinant, the turn, the scale.

use glam::{DMat3, DVec3};

use crate::ltc::{mat3_from_rows, mat3_rows};

/// The mirror through the xz-plane: it fixes z, so `MIRROR_Y · M⁻¹` is the same lobe.
const MIRROR_Y: DMat3 = DMat3::from_cols(DVec3::X, DVec3::NEG_Y, DVec3::Z);

/// The equivalent `M⁻¹` with a positive determinant (mirrored through the xz-plane where it
/// was negative): the polygon methods' edge sums take their sign from it.
pub fn proper(cos_from_brdf: DMat3) -> DMat3 {
    if cos_from_brdf.determinant() < 0.0 {
        MIRROR_Y * cos_from_brdf
    } else {
        cos_from_brdf
    }
}

/// The turn about z, applied on the left, that makes the upper-left 2×2 block of `M⁻¹`
/// symmetric with the largest trace: `β = atan2(m01 − m10, m00 + m11)`. Of the turns that make
/// the block symmetric (β and β + π) it is the one nearest the identity, which is what
/// keeps neighbouring nodes' choices together; an isotropic lobe's stored form (a diagonal
/// block) is its own canonical form.
pub fn turned(cos_from_brdf: DMat3) -> DMat3 {
    let r = mat3_rows(cos_from_brdf);
    let beta = (r[0][1] - r[1][0]).atan2(r[0][0] + r[1][1]);
    let (s, c) = beta.sin_cos();
    let row = |k: usize| DVec3::from_array(r[k]);
    let (r0, r1) = (c * row(0) - s * row(1), s * row(0) + c * row(1));
    mat3_from_rows([r0.to_array(), r1.to_array(), r[2]])
}

/// `M⁻¹` divided by `|det M⁻¹|^(1/3)`: the scale whose interpolation treats every node's
/// lobe alike, wide or narrow (dividing by the middle entry, as the 2D table does, weighs a
/// node by how narrow its lobe is along y).
pub fn unit_determinant(cos_from_brdf: DMat3) -> DMat3 {
    let det = cos_from_brdf.determinant().abs();
    if det > 0.0 && det.is_finite() {
        cos_from_brdf * det.cbrt().recip()
    } else {
        cos_from_brdf
    }
}

/// The canonical form of `M⁻¹`: proper, turned, of unit determinant.
pub fn canonical(cos_from_brdf: DMat3) -> DMat3 {
    unit_determinant(turned(proper(cos_from_brdf)))
}

/// The canonical form of a forward `M` (the same three choices made on the right, where
/// `M` has its freedom: `M Q`), its third column — where the cosine's pole goes, the lobe's
/// axis — of unit length.
pub fn canonical_forward(brdf_from_cos: DMat3) -> DMat3 {
    let m = turned(proper(brdf_from_cos.transpose())).transpose();
    m * m.z_axis.length().recip()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rotation_z(beta: f64) -> DMat3 {
        DMat3::from_rotation_z(beta)
    }

    #[test]
    fn every_equivalent_matrix_has_one_canonical_form() {
        let m = mat3_from_rows([[2.0, 0.3, -0.7], [0.1, 0.5, 0.2], [0.4, -0.2, 1.1]]);
        let c = canonical(m);
        for beta in [0.3, 2.0, 3.1, -1.4] {
            for scale in [0.01, 1.0, 300.0] {
                for mirror in [DMat3::IDENTITY, MIRROR_Y] {
                    let other = canonical(mirror * rotation_z(beta) * m * scale);
                    // Rounding of a few operations on entries of size 1: 1e-12.
                    assert!(
                        (other - c).to_cols_array().iter().all(|d| d.abs() < 1e-12),
                        "{other} vs {c}"
                    );
                }
            }
        }
        let r = mat3_rows(c);
        assert!((r[0][1] - r[1][0]).abs() < 1e-12 && r[0][0] + r[1][1] > 0.0);
        assert!((c.determinant() - 1.0).abs() < 1e-12);
    }
}
