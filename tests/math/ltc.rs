//! LTC evaluation: it is a distribution (∫ D = 1), the identity gives the clamped cosine,
//! scaling M⁻¹ changes nothing, and each clipping rule does exactly what docs/design.md §1 says.

use crate::common::sphere_integral;
use glam::{DMat3, DQuat, DVec3};
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::{ClipCase, Clipping, Ltc, Normalization, mat3_from_rows};
use proptest::prelude::*;

/// D with only the transform's own clamp: the distribution as defined.
fn density(ltc: &Ltc, l: DVec3) -> f64 {
    ltc.ltc_eval(l, Clipping::CASE2, Normalization::Corrected)
}

/// ∫ D over the sphere, the quadrature centred on D's peak direction M·z.
fn total(ltc: &Ltc) -> f64 {
    sphere_integral(ltc.brdf_from_cos * DVec3::Z, 600, |l| density(ltc, l))
}

#[test]
fn fitted_distributions_integrate_to_one() {
    for lut in [Lut::embedded(), Lut::embedded_point()] {
        fitted_distributions_of(lut);
    }
}

fn fitted_distributions_of(lut: &Lut) {
    // Cells with α ≥ 0.04 (column ≥ 13): narrower lobes need a finer quadrature than 600
    // steps. Grazing rows included.
    for j in (0..lut.size).step_by(9).chain([lut.size - 1]) {
        for i in (13..lut.size).step_by(10).chain([lut.size - 1]) {
            let pair = lut.sample(lut.alpha(i), lut.theta_o(j).cos()).ltc_pair();
            for (name, ltc) in [("spec", pair.spec), ("diff", pair.diff)] {
                let t = total(&ltc);
                // Midpoint quadrature of a smooth integrand with 600×1200 nodes: error ≪ 1e-3.
                assert!((t - 1.0).abs() < 1e-3, "∫D = {t} for {name} at i={i} j={j}");
            }
        }
    }
}

/// A uniformly random rotation: a quaternion uniform in the 4-ball (cube sampling with
/// rejection), normalized — uniform on SO(3).
fn rotation() -> impl Strategy<Value = DQuat> {
    proptest::array::uniform4(-1.0f64..1.0)
        .prop_filter("inside the unit ball", |q| {
            let n2: f64 = q.iter().map(|x| x * x).sum();
            n2 > 1e-3 && n2 <= 1.0
        })
        .prop_map(|q| DQuat::from_array(q).normalize())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    /// Any invertible matrix gives a distribution. Built as `R1 · diag(s) · R2` with random
    /// rotations and singular values in [0.5, 2], ± for reflections: every invertible matrix
    /// with condition number ≤ 4. That bound keeps D's peak (D_max/D_min ≤ κ⁴ = 256) within
    /// the 600-step quadrature's resolution.
    #[test]
    fn random_matrices_integrate_to_one(a1 in rotation(), a2 in rotation(),
            s in proptest::array::uniform3(0.5f64..2.0), flip in proptest::bool::ANY) {
        let sign = if flip { -1.0 } else { 1.0 };
        let cos_from_brdf = DMat3::from_quat(a1) * DMat3::from_diagonal(DVec3::new(s[0], s[1], sign * s[2])) * DMat3::from_quat(a2);
        let ltc = Ltc::from_cos_from_brdf(cos_from_brdf, 1.0, 0.0);
        let t = total(&ltc);
        prop_assert!((t - 1.0).abs() < 1e-3, "∫D = {t} for M⁻¹ = {cos_from_brdf}");
    }

    /// Identity M: D is the clamped cosine max(z, 0)/π, exactly.
    #[test]
    fn identity_is_the_clamped_cosine(theta in 0.0f64..std::f64::consts::PI, phi in 0.0f64..std::f64::consts::TAU) {
        let l = DVec3::new(theta.sin() * phi.cos(), theta.sin() * phi.sin(), theta.cos());
        let d = Ltc::identity().ltc_eval(l, Clipping::BOTH, Normalization::Corrected);
        let expected = l.z.max(0.0) / std::f64::consts::PI;
        prop_assert!((d - expected).abs() <= 1e-15, "{d} vs {expected}");
    }

    /// D(ω) is invariant under M⁻¹ → s M⁻¹ (why a normalized M⁻¹ can be stored).
    #[test]
    fn scaling_the_inverse_changes_nothing(s in 1e-3f64..1e3, theta in 0.0f64..1.57, phi in 0.0f64..std::f64::consts::TAU) {
        let lut = Lut::embedded();
        let pair = lut.sample(0.3, 0.6).ltc_pair();
        let l = DVec3::new(theta.sin() * phi.cos(), theta.sin() * phi.sin(), theta.cos());
        for ltc in [pair.spec, pair.diff] {
            let scaled = Ltc::from_cos_from_brdf(ltc.cos_from_brdf * s, ltc.norm, ltc.fresnel);
            let (a, b) = (density(&ltc, l), density(&scaled, l));
            // s enters as s · s³ / (s²)² = 1: a few roundings, 1e-12 relative.
            prop_assert!((a - b).abs() <= 1e-12 * a.abs().max(1e-300), "{a} vs {b}");
        }
    }
}

/// A tilted lobe like a fitted specular one at grazing view: `m20 < 0` lifts directions with
/// x < 0 and pushes those with x > 0 down.
fn tilted() -> Ltc {
    Ltc::from_cos_from_brdf(
        mat3_from_rows([[1.0, 0.0, 0.3], [0.0, 1.0, 0.0], [-0.5, 0.0, 0.6]]),
        0.8,
        0.1,
    )
}

#[test]
fn case_1_light_below_the_horizon_glows_only_without_the_horizon_rule() {
    let ltc = tilted();
    // Below the horizon (z < 0) yet (M⁻¹l).z = 0.5·0.9 − 0.6·0.1 > 0.
    let l = DVec3::new(-0.9, 0.0, -0.1).normalize();
    assert_eq!(ltc.clip_case(l), ClipCase::Lifted);
    assert!((ltc.cos_from_brdf * l).z > 0.0);
    assert_eq!(
        ltc.ltc_eval(l, Clipping::BOTH, Normalization::Corrected),
        0.0
    );
    assert_eq!(
        ltc.ltc_eval(l, Clipping::CASE1, Normalization::Corrected),
        0.0
    );
    assert!(ltc.ltc_eval(l, Clipping::CASE2, Normalization::Corrected) > 0.0);
    assert!(ltc.ltc_eval(l, Clipping::NONE, Normalization::Corrected) > 0.0);
}

#[test]
fn case_2_light_pushed_below_is_negative_only_without_the_transformed_rule() {
    let ltc = tilted();
    // Above the horizon, but (M⁻¹l).z = −0.5·0.95 + 0.6·0.2 < 0.
    let l = DVec3::new(0.95, 0.0, 0.2).normalize();
    assert_eq!(ltc.clip_case(l), ClipCase::PushedBelow);
    assert_eq!(
        ltc.ltc_eval(l, Clipping::BOTH, Normalization::Corrected),
        0.0
    );
    assert_eq!(
        ltc.ltc_eval(l, Clipping::CASE2, Normalization::Corrected),
        0.0
    );
    assert!(ltc.ltc_eval(l, Clipping::CASE1, Normalization::Corrected) < 0.0);
    assert!(ltc.ltc_eval(l, Clipping::NONE, Normalization::Corrected) < 0.0);
}

#[test]
fn a_light_below_that_stays_below_is_removed_by_either_rule_and_negative_by_none() {
    let ltc = tilted();
    // Below (z < 0) and (M⁻¹l).z = −0.5·0.1 − 0.6·0.9 < 0: it stays below.
    let l = DVec3::new(0.1, 0.0, -0.9).normalize();
    assert!((ltc.cos_from_brdf * l).z < 0.0);
    assert_eq!(ltc.clip_case(l), ClipCase::StaysBelow);
    for c in [Clipping::BOTH, Clipping::CASE1, Clipping::CASE2] {
        assert_eq!(ltc.ltc_eval(l, c, Normalization::Corrected), 0.0);
    }
    assert!(ltc.ltc_eval(l, Clipping::NONE, Normalization::Corrected) < 0.0);
}

#[test]
fn visible_light_is_unaffected_by_clipping() {
    let ltc = tilted();
    let l = DVec3::new(-0.2, 0.1, 0.9).normalize();
    assert_eq!(ltc.clip_case(l), ClipCase::Visible);
    let d = ltc.ltc_eval(l, Clipping::BOTH, Normalization::Corrected);
    assert!(d > 0.0);
    for c in [Clipping::CASE1, Clipping::CASE2, Clipping::NONE] {
        assert_eq!(ltc.ltc_eval(l, c, Normalization::Corrected), d);
    }
}

#[test]
fn paper_literal_drops_one_over_pi_and_the_magnitudes() {
    let lut = Lut::embedded();
    let pair = lut.sample(0.27, 0.7).ltc_pair();
    let l = DVec3::new(-0.3, 0.2, 0.9).normalize();
    let f0 = 0.04;
    let c = pair.ltc_lobes(l, f0, Clipping::BOTH, Normalization::Corrected);
    let p = pair.ltc_lobes(l, f0, Clipping::BOTH, Normalization::PaperLiteral);
    let pi = std::f64::consts::PI;
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
    assert!(rel(p.specular, c.specular * pi / pair.spec_magnitude(f0)) < 1e-12);
    assert!(rel(p.diffuse, c.diffuse * pi / pair.diff.norm) < 1e-12);
}
