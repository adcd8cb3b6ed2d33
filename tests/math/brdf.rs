//! The exact BRDF: reciprocity, white-furnace bounds, and agreement of the f32 and f64 paths.

use crate::common::{mirror, sphere_integral, view};
use glam::DVec3;
use ltc_lab::brdf::{Dots, brdf_cos, diffuse_cos, specular_cos};
use proptest::prelude::*;

fn unit(theta: f64, phi: f64) -> DVec3 {
    DVec3::new(
        theta.sin() * phi.cos(),
        theta.sin() * phi.sin(),
        theta.cos(),
    )
}

proptest! {
    /// Helmholtz reciprocity: f(v, l) = f(l, v) for both lobes. Compared as f·cos / cos so
    /// that each side divides by its own cosine.
    #[test]
    fn reciprocity(tv in 0.0f64..1.5, pv in 0.0f64..std::f64::consts::TAU, tl in 0.0f64..1.5, pl in 0.0f64..std::f64::consts::TAU,
                   alpha in 1e-3f64..1.0, f0 in 0.0f64..1.0) {
        let (v, l) = (unit(tv, pv), unit(tl, pl));
        let (a, b) = (Dots::new(v.to_array(), l.to_array()), Dots::new(l.to_array(), v.to_array()));
        prop_assume!(a.is_some() && b.is_some());
        let (a, b) = (a.unwrap(), b.unwrap());
        let fs_vl = specular_cos(&a, alpha, f0) / l.z;
        let fs_lv = specular_cos(&b, alpha, f0) / v.z;
        // f64 evaluation of the same expression in two orders: 1e-9 relative is ~1e7 ulps,
        // far above rounding and far below any asymmetry a wrong term would cause.
        prop_assert!((fs_vl - fs_lv).abs() <= 1e-9 * fs_vl.abs().max(1e-300), "{fs_vl} vs {fs_lv}");
        let fd_vl = diffuse_cos(&a, alpha) / l.z;
        let fd_lv = diffuse_cos(&b, alpha) / v.z;
        prop_assert!((fd_vl - fd_lv).abs() <= 1e-9 * fd_vl.abs(), "{fd_vl} vs {fd_lv}");
    }
}

/// Directional albedo of a lobe by f64 quadrature (not the fitter's sampling).
fn albedo(v: DVec3, alpha: f64, spec: bool) -> f64 {
    let centre = if spec { mirror(v) } else { DVec3::Z };
    sphere_integral(centre, 400, |l| {
        let b = brdf_cos(v.to_array(), l.to_array(), alpha, 1.0);
        if spec { b.specular } else { b.diffuse }
    })
}

#[test]
fn white_furnace_bounds() {
    for theta in [0.0, 30.0, 60.0, 80.0, 89.0] {
        for alpha in [0.05, 0.25, 0.5, 1.0] {
            let v = view(theta);
            // Specular with F = 1: single-scattering microfacet energy, in (0, 1]: Smith's G2
            // ≤ G1 and D is normalized (∫ D (n·h) dh = 1), so no energy is created. The
            // 1e-3 slack covers the quadrature's error (checked in fit.rs against sampling).
            let s = albedo(v, alpha, true);
            assert!(
                s > 0.0 && s <= 1.0 + 1e-3,
                "spec albedo {s} at θ={theta} α={alpha}"
            );
            // Burley's diffuse is not energy conserving: each scatter factor
            // 1 + (FD − 1)(1 − cos)⁵ lies between min(1, FD) and max(1, FD), FD = 0.5 + 2α(l·h)²
            // ∈ [0.5, 0.5 + 2α], and ∫ cos/π = 1, so the albedo lies in
            // [0.25, max(1, 0.5 + 2α)²] — and in (0, 1] when FD ≤ 1 everywhere (α ≤ 0.25).
            let d = albedo(v, alpha, false);
            let hi = (0.5 + 2.0 * alpha).max(1.0).powi(2);
            assert!(
                d >= 0.25 && d <= hi + 1e-3,
                "diffuse albedo {d} at θ={theta} α={alpha}"
            );
            if alpha <= 0.25 {
                assert!(d <= 1.0 + 1e-3, "diffuse albedo {d} > 1 at α={alpha}");
            }
        }
    }
}

#[test]
fn smooth_surface_reflects_everything_at_normal_view() {
    // As α → 0, D → δ and G2 → 1: the specular albedo (F = 1) tends to 1.
    let s = albedo(view(0.0), 0.05, true);
    assert!((s - 1.0).abs() < 0.01, "{s}");
}

#[test]
fn f32_and_f64_paths_agree() {
    let mut worst: f64 = 0.0;
    for theta in (0..=17).map(|k| k as f64 * 5.0) {
        for alpha in [0.1, 0.2, 0.4, 0.7, 1.0] {
            for f0 in [0.0, 0.04, 1.0] {
                for (tl, pl) in [(0.1, 0.0), (0.6, 3.0), (1.0, 1.0), (1.4, 2.0), (0.3, 5.0)] {
                    let v = view(theta);
                    let l = unit(tl, pl);
                    let b64 = brdf_cos(v.to_array(), l.to_array(), alpha, f0);
                    let v32 = v.as_vec3().to_array();
                    let l32 = l.as_vec3().to_array();
                    let b32 = brdf_cos(v32, l32, alpha as f32, f0 as f32);
                    for (x32, x64) in [(b32.specular, b64.specular), (b32.diffuse, b64.diffuse)] {
                        let rel = (f64::from(x32) - x64).abs() / x64.abs().max(1e-6);
                        worst = worst.max(rel);
                    }
                }
            }
        }
    }
    // f32's unit roundoff is 6e-8; the inputs are rounded to f32 first, and the GGX
    // denominator (n·h)²(α² − 1) + 1 amplifies relative error by up to 1/α² = 100 at α = 0.1,
    // with some 30 operations in series: 6e-8 · 100 · 30 ≈ 2e-4.
    assert!(worst < 2e-4, "worst relative f32/f64 difference {worst}");
}

proptest! {
    /// The `brdf-fast` visibility term is the literal G2 / (4 n·v n·l), rearranged.
    #[test]
    fn filament_visibility_equals_g2_over_cosines(n_v in 1e-3f64..=1.0, n_l in 1e-3f64..=1.0, alpha in 1e-4f64..=1.0) {
        use ltc_lab::brdf::{g2_correlated, v_smith_ggx_correlated};
        let a2 = alpha * alpha;
        // The view factor as plane.wgsl computes it once per pixel.
        let view_factor = (n_v * n_v * (1.0 - a2) + a2).sqrt();
        let v = v_smith_ggx_correlated(n_v, n_l, a2, view_factor);
        let g = g2_correlated(n_v, n_l, alpha) / (4.0 * n_v * n_l);
        // Two f64 evaluations of one rational function in different orders: 1e-10.
        prop_assert!((v - g).abs() <= 1e-10 * g, "{v} vs {g}");
    }
}
