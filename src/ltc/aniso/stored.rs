//! What a 4D table's nodes hold, and how a value read between them becomes `M⁻¹`
//! (docs/design.md §2.9). Each kind is nine numbers a node, blended linearly by the lookup;
//! they differ in what the blend means. The lab's table holds `MirrorPole`, the one whose
//! every blend is a proper lobe.

use glam::{DMat3, DVec3};

use crate::ltc::aniso::canonical;
use crate::ltc::{mat3_from_rows, mat3_rows};

/// What a table's nodes hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum Stored {
    /// `M⁻¹` (`cos_from_brdf`) by rows, as the 2D table: blended, it shades as it is.
    CosFromBrdf,
    /// `M` (`brdf_from_cos`) by rows, as I3D 2022's: blended, then inverted per pixel.
    BrdfFromCos,
    /// `M` in the node's mirror frame, `Fᵀ M` (`mirror_frame`): blended, turned back by the
    /// mirror frame of the point read, inverted per pixel.
    MirrorFromCos,
    /// `M` in the mirror frame as its axis and its shape (`pole_and_shape`): the axis `n`
    /// where the cosine's pole goes (`M`'s third column, unit) and `U = F(n)ᵀ M` in the axis's
    /// frame, whose third column is then `(0, 0, u₂₂)`, with an upper-left block symmetric
    /// positive definite and `u₂₂ = 1`: rows `[n.x n.y n.z] [u₀₀ u₀₁ u₁₁] [u₂₀ u₂₁ u₂₂]`.
    /// Blended, `n` is normalized and `M = F_w F(n) U`: a blend of such `U` keeps its block
    /// positive definite and `u₂₂ = 1`, so its determinant is at least the corners'
    /// geometric mean (`log det` is concave on positive definite matrices) — no blend is
    /// singular or mirrored, where no blend of the axes vanishes, which `poles_agree` asks
    /// of each cell.
    MirrorPole,
}

impl Stored {
    pub const ALL: [Self; 4] = [
        Self::CosFromBrdf,
        Self::BrdfFromCos,
        Self::MirrorFromCos,
        Self::MirrorPole,
    ];

    /// What a node whose unit view is `w` (table frame) stores for a fitted `M⁻¹`, as a
    /// matrix of its nine numbers by rows.
    pub fn store(self, cos_from_brdf: DMat3, w: DVec3) -> DMat3 {
        match self {
            Self::CosFromBrdf => canonical::canonical(cos_from_brdf),
            Self::BrdfFromCos => canonical::canonical_forward(cos_from_brdf.inverse()),
            Self::MirrorFromCos => {
                canonical::canonical_forward(mirror_frame(w).transpose() * cos_from_brdf.inverse())
            }
            Self::MirrorPole => {
                pole_and_shape(mirror_frame(w).transpose() * cos_from_brdf.inverse())
            }
        }
    }

    /// `M⁻¹` at the unit view `w` (table frame) from what the table holds there (a node's
    /// value or a blend).
    pub fn cos_from_brdf(self, stored: DMat3, w: DVec3) -> DMat3 {
        match self {
            Self::CosFromBrdf => stored,
            Self::BrdfFromCos => stored.inverse(),
            Self::MirrorFromCos => (mirror_frame(w) * stored).inverse(),
            Self::MirrorPole => (mirror_frame(w) * from_pole_and_shape(stored)).inverse(),
        }
    }

    /// Why a node's nine numbers cannot be blended into a proper lobe, if they cannot: a
    /// positive determinant for the matrix kinds; for `MirrorPole`, a pole leaning toward the
    /// mirror direction and a shape with a positive definite block and `u₂₂ > 0`.
    pub fn check(self, stored: DMat3) -> Result<(), &'static str> {
        match self {
            Self::MirrorPole => {
                let r = mat3_rows(stored);
                let n = DVec3::from_array(r[0]);
                let [u00, u01, u11] = r[1];
                // Far from −z: `turn_z_to` turns z onto it by the shorter way.
                if !(n.length() > 0.0 && n.z > -0.9 * n.length()) {
                    return Err("its axis points away from the mirror direction");
                }
                if !(u00 > 0.0 && u00 * u11 - u01 * u01 > 0.0 && r[2][2] > 0.0) {
                    return Err("its shape is not positive definite");
                }
                Ok(())
            }
            _ if stored.determinant() > 0.0 => Ok(()),
            _ => Err("the stored matrix is singular or mirrored"),
        }
    }
}

/// Whether a cell's nine-number corners (`MirrorPole`) have poles in one open hemisphere:
/// some direction `d` with `nₖ·d > 0` for every pole, found by the perceptron's updates from
/// their mean (which end within `PERCEPTRON_STEPS` wherever the poles sit well inside a
/// hemisphere). Then every blend `Σ wₖ nₖ` has a positive component along `d`, and never
/// vanishes. For the other kinds there is nothing to ask.
pub fn poles_agree(kind: Stored, corners: &[DMat3]) -> bool {
    if kind != Stored::MirrorPole {
        return true;
    }
    let poles: Vec<DVec3> = corners
        .iter()
        .map(|m| DVec3::from_array(mat3_rows(*m)[0]).normalize_or_zero())
        .collect();
    let mut d = poles.iter().fold(DVec3::ZERO, |a, n| a + *n);
    for _ in 0..PERCEPTRON_STEPS {
        match poles.iter().find(|n| n.dot(d) <= 0.0) {
            None => return true,
            Some(n) => d += *n,
        }
    }
    false
}

/// How many corrections `poles_agree` tries: a cell of 16 poles within a hemisphere with a
/// margin of a degree is separated in far fewer (the perceptron's bound, `1/margin²`).
const PERCEPTRON_STEPS: usize = 4096;

/// The rotation that takes `z` to the unit vector `d` (`d.z > −1`): a turn about `z × d`,
/// Rodrigues' formula with `s = z × d = (−d.y, d.x, 0)`: `R = d.z I + [s]× + s sᵀ/(1 + d.z)` —
/// no angle computed (as in WGSL, whose sine and cosine are only 2⁻¹¹ accurate).
pub fn turn_z_to(d: DVec3) -> DMat3 {
    let s = DVec3::new(-d.y, d.x, 0.0);
    let cross = DMat3::from_cols(
        DVec3::new(0.0, s.z, -s.y),
        DVec3::new(-s.z, 0.0, s.x),
        DVec3::new(s.y, -s.x, 0.0),
    );
    let outer = DMat3::from_cols(s * s.x, s * s.y, s * s.z);
    DMat3::IDENTITY * d.z + cross + outer * (1.0 + d.z).recip()
}

/// The rotation that takes `z` to the mirror direction `(−w.x, −w.y, w.z)` of the unit view
/// `w` (the table's frame): the identity at normal view. A lobe as narrow as a mirror's lies
/// along it, so its `M` in this frame barely changes from node to node: blended there, the
/// lobe's direction comes out exact instead of blended.
pub fn mirror_frame(w: DVec3) -> DMat3 {
    turn_z_to(DVec3::new(-w.x, -w.y, w.z))
}

/// `MirrorPole`'s nine numbers for a forward `M` (in the mirror frame).
pub fn pole_and_shape(brdf_from_cos: DMat3) -> DMat3 {
    let m = canonical::proper(brdf_from_cos.inverse()).inverse();
    let n = m.z_axis.normalize();
    // In the axis's frame the third column is (0, 0, |c₃|); the right turn that makes the
    // upper-left block its symmetric positive definite polar factor (`canonical::turned`,
    // on the right) leaves it so.
    let u = canonical::turned((turn_z_to(n).transpose() * m).transpose()).transpose();
    let u = u * u.z_axis.z.recip();
    let r = mat3_rows(u);
    mat3_from_rows([
        n.to_array(),
        [r[0][0], r[0][1], r[1][1]],
        [r[2][0], r[2][1], r[2][2]],
    ])
}

/// `M` (in the mirror frame) from `MirrorPole`'s nine numbers or a blend of them.
pub fn from_pole_and_shape(stored: DMat3) -> DMat3 {
    let r = mat3_rows(stored);
    let n = DVec3::from_array(r[0]).normalize();
    let [u00, u01, u11] = r[1];
    let [u20, u21, u22] = r[2];
    let u = mat3_from_rows([[u00, u01, 0.0], [u01, u11, 0.0], [u20, u21, u22]]);
    turn_z_to(n) * u
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_pole_form_is_the_same_lobe() {
        let m = mat3_from_rows([[0.4, 0.1, -0.3], [-0.05, 0.2, 0.1], [0.1, 0.05, 0.9]]);
        let back = from_pole_and_shape(pole_and_shape(m));
        // The same lobe: equal up to a turn about z on the right and a positive scale, so
        // `M⁻¹ l` has the same direction for every l.
        for l in [
            DVec3::Z,
            DVec3::new(0.3, 0.2, 0.9).normalize(),
            DVec3::new(-0.5, 0.1, 0.5).normalize(),
        ] {
            let (a, b) = (
                (m.inverse() * l).normalize(),
                (back.inverse() * l).normalize(),
            );
            assert!(
                (a.z - b.z).abs() < 1e-12
                    && (a.x * a.x + a.y * a.y - b.x * b.x - b.y * b.y).abs() < 1e-12
            );
        }
        assert!(Stored::MirrorPole.check(pole_and_shape(m)).is_ok());
        assert!(
            (turn_z_to(DVec3::new(0.6, 0.0, 0.8)) * DVec3::Z - DVec3::new(0.6, 0.0, 0.8)).length()
                < 1e-15
        );
    }
}
