//! Anisotropic GGX against f64 quadrature independent of the sampling code: D is normalized,
//! the weak white furnace holds for every view, the lobe is reciprocal, and with α_x = α_y
//! every term is the isotropic one to rounding.

use glam::DVec3;
use ltc_lab::brdf::aniso::{
    Alpha, d_ggx_aniso, g2_correlated_aniso, lambda_ggx_aniso, specular_cos_aniso,
};
use ltc_lab::brdf::{
    Dots, brdf_cos, brdf_cos_aniso, d_ggx, g2_correlated, lambda_ggx, specular_cos,
};
use proptest::prelude::*;

use crate::common::sphere_integral;

fn unit(theta: f64, phi: f64) -> DVec3 {
    DVec3::new(
        theta.sin() * phi.cos(),
        theta.sin() * phi.sin(),
        theta.cos(),
    )
}

/// Roughness pairs from nearly isotropic to 1:50, both orders.
const PAIRS: [(f64, f64); 6] = [
    (0.3, 0.05),
    (0.05, 0.3),
    (1.0, 0.1),
    (0.5, 0.45),
    (0.02, 0.2),
    (0.8, 0.016),
];

#[test]
fn d_integrates_to_one_over_projected_normals() {
    for (ax, ay) in PAIRS {
        let alpha = Alpha { x: ax, y: ay };
        let total = sphere_integral(DVec3::Z, 600, |h| {
            d_ggx_aniso(h.to_array(), alpha) * h.z.max(0.0)
        });
        // The rule's error on a lobe as narrow as α = 0.016 along one axis: 600 rings crowded
        // as t³ resolve it to ~1e-4 (the same rule holds the isotropic albedo to 1e-3 with
        // 400, tests/math/brdf.rs).
        assert!(
            (total - 1.0).abs() < 2e-4,
            "∫ D (h·n) dh = {total} at α = ({ax}, {ay})"
        );
    }
}

/// `∫ g(h) dω_h` over the upper hemisphere, by the change of variables GGX's slopes suggest:
/// slopes `(α_x ρ cos φ, α_y ρ sin φ)`, `h = normalize(−slope, 1)`, `dω_h = h.z³ d(slope)`,
/// `ρ² = u/(1 − u)` and `u = 1 − t²`, so `dω_h = α_x α_y h.z³ t⁻³ dt dφ`; the midpoint rule
/// in `(t, φ)` with `n × 2n` nodes. No value of D is assumed: D times this measure is smooth
/// (a constant) where D is GGX's, so a wrong D shows, and the kink of a visible-normal
/// integrand is the rule's only roughness (it converges as 1/n²).
fn slope_integral(alpha: Alpha<f64>, n: usize, g: impl Fn(DVec3) -> f64) -> f64 {
    let (dt, dphi) = (1.0 / n as f64, std::f64::consts::PI / n as f64);
    let mut sum = 0.0;
    for i in 0..n {
        let t = (i as f64 + 0.5) * dt;
        let rho = ((1.0 - t * t) / (t * t)).sqrt();
        for k in 0..2 * n {
            let phi = (k as f64 + 0.5) * dphi;
            let h =
                DVec3::new(-alpha.x * rho * phi.cos(), -alpha.y * rho * phi.sin(), 1.0).normalize();
            sum += g(h) * alpha.x * alpha.y * h.z.powi(3) / (t * t * t);
        }
    }
    sum * dt * dphi
}

#[test]
fn the_weak_white_furnace_holds_for_every_view() {
    // Heitz 2014 eq. 20: ∫ G1(v) max(v·h, 0) D(h) dh = v·n — the visible normals' projected
    // area is the surface's, for any view, exactly when Λ is D's. Measured by `slope_integral`
    // with 600 × 1200 nodes: its error at the visible kink is ~5e-8 (1/n², 1.4e-7 at 500
    // nodes in a check of the rule itself), so 1e-5 leaves room while a wrong Λ or D misses
    // by percents.
    for (ax, ay) in PAIRS {
        let alpha = Alpha { x: ax, y: ay };
        for (theta, phi) in [(0.0, 0.0), (0.5, 0.3), (1.0, 1.2), (1.3, 2.5), (1.45, 4.0)] {
            let v = unit(theta, phi);
            let g1 = 1.0 / (1.0 + lambda_ggx_aniso(v.to_array(), alpha));
            let visible = slope_integral(alpha, 600, |h| {
                g1 * v.dot(h).max(0.0) * d_ggx_aniso(h.to_array(), alpha)
            });
            assert!(
                (visible / v.z - 1.0).abs() < 1e-5,
                "{visible} vs {} at α = ({ax}, {ay}), θ = {theta}, φ = {phi}",
                v.z
            );
        }
    }
}

proptest! {
    /// α_x = α_y: every anisotropic term is its isotropic twin to rounding, and
    /// `brdf_cos_aniso` is `brdf_cos` exactly.
    #[test]
    fn isotropic_alpha_is_the_isotropic_brdf(tv in 0.0f64..1.5, pv in 0.0f64..std::f64::consts::TAU, tl in 0.0f64..1.5,
                                             pl in 0.0f64..std::f64::consts::TAU, a in 1e-3f64..1.0, f0 in 0.0f64..1.0) {
        let (v, l) = (unit(tv, pv), unit(tl, pl));
        let alpha = Alpha::isotropic(a);
        let Some(d) = Dots::new(v.to_array(), l.to_array()) else { return Ok(()) };
        let h = (v + l).normalize();
        // The two forms differ by the rounding of 1 − z² against x² + y² (D's and Λ's
        // tangential parts): relative ε/(1 − z²) ≤ 1e-16/1e-6 where they matter, and
        // absolutely tiny where 1 − z² vanishes.
        let close = |x: f64, y: f64| (x - y).abs() <= 1e-9 * y.abs() + 1e-14;
        prop_assert!(close(d_ggx_aniso(h.to_array(), alpha), d_ggx(h.z, a)));
        prop_assert!(close(lambda_ggx_aniso(v.to_array(), alpha), lambda_ggx(v.z, a)));
        prop_assert!(close(g2_correlated_aniso(v.to_array(), l.to_array(), alpha), g2_correlated(v.z, l.z, a)));
        prop_assert!(close(specular_cos_aniso(v.to_array(), l.to_array(), h.to_array(), alpha, f0), specular_cos(&d, a, f0)));
        prop_assert_eq!(brdf_cos_aniso(v.to_array(), l.to_array(), alpha, f0), brdf_cos(v.to_array(), l.to_array(), a, f0));
    }

    /// Helmholtz reciprocity of the anisotropic lobe, compared as f = f·cos / cos.
    #[test]
    fn reciprocity(tv in 0.0f64..1.5, pv in 0.0f64..std::f64::consts::TAU, tl in 0.0f64..1.5, pl in 0.0f64..std::f64::consts::TAU,
                   ax in 1e-3f64..1.0, ay in 1e-3f64..1.0, f0 in 0.0f64..1.0) {
        let (v, l) = (unit(tv, pv), unit(tl, pl));
        let alpha = Alpha { x: ax, y: ay };
        let a = brdf_cos_aniso(v.to_array(), l.to_array(), alpha, f0);
        let b = brdf_cos_aniso(l.to_array(), v.to_array(), alpha, f0);
        // f64 evaluation of one expression in two orders: far below any asymmetry.
        prop_assert!((a.specular / l.z - b.specular / v.z).abs() <= 1e-9 * (a.specular / l.z).abs().max(1e-300));
        prop_assert!((a.diffuse / l.z - b.diffuse / v.z).abs() <= 1e-9 * (a.diffuse / l.z).abs().max(1e-300));
    }
}

#[test]
fn the_specular_albedo_is_at_most_one() {
    // F = 1: single scattering loses energy, never makes it (G2 ≤ G1, D normalized).
    for (ax, ay) in PAIRS {
        let alpha = Alpha { x: ax, y: ay };
        for (theta, phi) in [(0.0, 0.0), (0.7, 0.5), (1.3, 2.0)] {
            let v = unit(theta, phi);
            let albedo = sphere_integral(DVec3::new(-v.x, -v.y, v.z), 500, |l| {
                brdf_cos_aniso(v.to_array(), l.to_array(), alpha, 1.0).specular
            });
            assert!(
                albedo > 0.0 && albedo <= 1.0 + 1e-3,
                "{albedo} at ({ax}, {ay}) θ = {theta}"
            );
        }
    }
}

#[test]
fn f32_and_f64_agree() {
    let mut worst: f64 = 0.0;
    for (ax, ay) in PAIRS {
        for (tv, pv, tl, pl) in [
            (0.3, 0.2, 0.4, 3.0),
            (1.2, 1.0, 0.9, 4.0),
            (0.8, 2.0, 0.3, 5.5),
        ] {
            let (v, l) = (unit(tv, pv), unit(tl, pl));
            let b64 = brdf_cos_aniso(v.to_array(), l.to_array(), Alpha { x: ax, y: ay }, 0.04);
            let alpha32 = Alpha {
                x: ax as f32,
                y: ay as f32,
            };
            let b32 = brdf_cos_aniso(
                v.as_vec3().to_array(),
                l.as_vec3().to_array(),
                alpha32,
                0.04f32,
            );
            for (x, y) in [(b32.specular, b64.specular), (b32.diffuse, b64.diffuse)] {
                worst = worst.max((f64::from(x) - y).abs() / y.abs().max(1e-6));
            }
        }
    }
    // tests/math/brdf.rs's bound for the isotropic path: f32's unit roundoff 6e-8, amplified by up
    // to 1/α² = 2500 at α = 0.02 through D's denominator, over ~30 operations: 5e-3.
    assert!(worst < 5e-3, "worst relative f32/f64 difference {worst}");
}
