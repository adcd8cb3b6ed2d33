//! Lights with a size (docs/design.md §1.10): the cap quadrature against closed forms and
//! against itself with twice the nodes; each method's limit as the sphere shrinks to a point;
//! the LTC disk's cone algebra against the same LTC integrated over the cap by quadrature.

use glam::{DMat3, DVec3};
use ltc_lab::brdf::{self, Lobes};
use ltc_lab::light::sphere::cap::Cap;
use ltc_lab::light::sphere::disk::{ltc_disk, negative_eigenvalue, transformed_cone};
use ltc_lab::light::sphere::quadrature::{cap_integral, gauss_legendre};
use ltc_lab::light::sphere::{
    EXACT_NODES, POINT_LIMIT_SIN_SIGMA, SphereMethod, SphereShading, sphere_exact, sphere_light,
    sphere_rule,
};
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::sphere::{clipped_cap_projected_solid_angle, illuminance_sphere};
use ltc_lab::ltc::{Clipping, Ltc, LtcPair, Normalization};
use ltc_lab::measure::horizon::band_errors;
use ltc_lab::measure::sphere_error::{MEASURE_NODES, sphere_errors};

const DEG: f64 = std::f64::consts::PI / 180.0;

fn axis_at(elevation_deg: f64, azimuth_deg: f64) -> DVec3 {
    let (e, a) = (elevation_deg * DEG, azimuth_deg * DEG);
    DVec3::new(e.cos() * a.cos(), e.cos() * a.sin(), e.sin())
}

#[test]
fn gauss_legendre_integrates_polynomials_to_degree_2n_minus_1() {
    let rule = gauss_legendre(8);
    for k in 0..16 {
        let sum: f64 = rule.iter().map(|&(x, w)| w * x.powi(k)).sum();
        let exact = if k % 2 == 0 {
            2.0 / (k as f64 + 1.0)
        } else {
            0.0
        };
        // Exact in exact arithmetic; 1e-14 is a few ulps of the sum's terms.
        assert!((sum - exact).abs() < 1e-14, "x^{k}: {sum} vs {exact}");
    }
}

/// The projected solid angle of a cap, by the quadrature, against Snyder's closed form in
/// both its forms.
#[test]
fn the_cap_quadrature_matches_the_closed_form_cut_by_the_horizon() {
    let mut worst: f64 = 0.0;
    for sigma_deg in [0.5, 5.0, 20.0, 45.0, 80.0, 90.0] {
        for elevation in [
            -89.0, -60.0, -20.0, -3.0, 0.0, 2.0, 10.0, 30.0, 60.0, 89.5, 90.0,
        ] {
            let axis = axis_at(elevation, 30.0);
            let sigma: f64 = sigma_deg * DEG;
            let [got] = cap_integral(axis, 1.0 - sigma.cos(), 32, |l| [l.z.max(0.0)]);
            let want = clipped_cap_projected_solid_angle((90.0 - elevation) * DEG, sigma);
            let other = illuminance_sphere((elevation * DEG).sin(), sigma.sin().powi(2));
            for value in [want, other] {
                let err = (got - value).abs() / (std::f64::consts::PI * sigma.sin().powi(2));
                worst = worst.max(err);
            }
        }
    }
    // With the horizon's cut placed exactly and the nodes clustered at each piece's ends,
    // every piece's integrand is smooth and 32 nodes converge to about 1e-10 of the
    // unclipped cap's π sin²σ (geometric convergence; 16 nodes give about 1e-6). 1e-8 leaves
    // room for the closed form's own rounding near the horizon (its asin of near-1 values).
    eprintln!("cap quadrature: worst {worst:.2e}");
    assert!(worst < 1e-8, "worst {worst:e}");
}

#[test]
fn the_whole_upper_hemisphere_projects_to_pi() {
    let [got] = cap_integral(DVec3::new(0.3, -0.2, 0.9).normalize(), 2.0, 16, |l| [l.z]);
    assert!((got - std::f64::consts::PI).abs() < 1e-12, "{got}");
}

/// A fitted-looking LTC: `M⁻¹` of ltc_code's zero pattern with the given entries.
fn ltc(a: f64, b: f64, c: f64, d: f64) -> Ltc {
    let m_inv = DMat3::from_cols(
        DVec3::new(a, 0.0, d),
        DVec3::new(0.0, c, 0.0),
        DVec3::new(b, 0.0, 1.0),
    );
    Ltc::from_cos_from_brdf(m_inv, 1.0, 0.0)
}

/// The negative eigenvalue of a form with one, at scales from 1e-6 to 1e6: a negative root of
/// det(q − eI).
#[test]
fn the_negative_eigenvalue_is_a_root_of_the_characteristic_cubic() {
    for (k, scale) in [(0.0, 1.0), (1e-4, 1.0), (-0.3, 1e6), (2.0, 1e-6)] {
        let m = DMat3::from_cols_array(&[2.0, 0.3, -0.7, 0.3, 1.5 + k, 0.2, -0.7, 0.2, -0.5 - k])
            * scale;
        let e3 = negative_eigenvalue(m, m.determinant());
        assert!(e3 < 0.0);
        let shifted = m - DMat3::from_diagonal(DVec3::splat(e3));
        // The determinant's rounding is about ε‖m‖³; its derivative at the root about ‖m‖².
        let norm = m.col(0).length() + m.col(1).length() + m.col(2).length();
        assert!(shifted.determinant().abs() <= 1e-12 * norm.powi(3), "{e3}");
    }
}

/// The cone algebra of `ltc_disk` is exact: with no clipping, it equals the signed LTC
/// integrated over the cap by quadrature, for caps wholly above the surface.
#[test]
fn the_ltc_disk_is_the_ltc_integrated_over_the_cap() {
    let ltcs = [
        ltc(1.0, 0.0, 1.0, 0.0),
        ltc(3.0, 0.4, 2.5, -0.3),
        ltc(0.3, -0.8, 0.5, 0.6),
        ltc(8.0, 2.0, 6.0, -1.5),
    ];
    let mut worst: f64 = 0.0;
    for lobe in &ltcs {
        for sigma_deg in [0.25, 2.0, 10.0, 25.0] {
            for (elevation, azimuth) in [(45.0, 0.0), (70.0, 120.0), (30.0, 200.0), (88.0, 10.0)] {
                let sigma: f64 = sigma_deg * DEG;
                if elevation * DEG <= sigma {
                    continue;
                }
                let cap = Cap {
                    axis: axis_at(elevation, azimuth),
                    sin_sigma: sigma.sin(),
                    cos_sigma: sigma.cos(),
                };
                for case2 in [false, true] {
                    let clip = Clipping {
                        case1: false,
                        case2,
                    };
                    let got = ltc_disk(lobe, &cap, case2, Normalization::Corrected);
                    let [want] = cap_integral(cap.axis, cap.depth(), 96, |l| {
                        [lobe.ltc_eval(l, clip, Normalization::Corrected)]
                    });
                    let err = (got - want).abs() / want.abs().max(1e-300);
                    // With case 2's clipping the disk's cut is that of the sphere of the same
                    // form factor, an approximation; where neither that sphere nor the cone
                    // itself is cut, and without the clipping, the cone algebra is exact.
                    if !case2 || nothing_is_cut(lobe, &cap) {
                        worst = worst.max(err);
                    }
                }
            }
        }
    }
    // The cone's root (Newton's, to f64's rounding) and its form factor are exact to about
    // 1e-14; the quadrature of these peaked lobes at 96 nodes agrees to about 1e-12 (48 nodes: 1e-6, on
    // the most anisotropic matrix). 1e-8 is far below any error the methods are compared by.
    eprintln!("cone algebra: worst {worst:.2e}");
    assert!(worst < 1e-8, "worst {worst:e}");
}

/// True where the cap's image under `M⁻¹` lies wholly above the clamped cosine's horizon
/// (by its rim: the image is a convex cone), and so does the sphere of the same form factor.
fn nothing_is_cut(lobe: &Ltc, cap: &Cap) -> bool {
    let (axis, form_factor) = transformed_cone(lobe, cap);
    let (t, b) = cap.axis.any_orthonormal_pair();
    axis.z > 0.0
        && axis.z * axis.z >= form_factor
        && (0..360).all(|k| {
            let phi = (k as f64) * DEG;
            let rim = cap.axis * cap.cos_sigma + (t * phi.cos() + b * phi.sin()) * cap.sin_sigma;
            (lobe.cos_from_brdf * rim).z > 0.0
        })
}

/// A sphere light at (θo, α), with the shipped table's LTCs there, both rules.
fn shading(
    theta_o_deg: f64,
    alpha: f64,
    u: DVec3,
    radius: f64,
    pair: &LtcPair,
) -> SphereShading<'_> {
    SphereShading {
        v: DVec3::from(brdf::view_from_theta(theta_o_deg * DEG)),
        u,
        intensity: 2.0,
        range: 3.0,
        radius,
        alpha: brdf::Alpha::isotropic(alpha),
        f0: 0.04,
        ltc: pair,
        clip: Clipping::BOTH,
        normalization: Normalization::Corrected,
    }
}

fn pair_at(theta_o_deg: f64, alpha: f64) -> LtcPair {
    Lut::embedded().ltc_pair(alpha, DVec3::from(brdf::view_from_theta(theta_o_deg * DEG)))
}

/// Each sphere of angular radius in `sigmas_deg` at unit distance toward each (elevation,
/// azimuth) of `positions` (degrees), seen at θo 0, 45° and 80° with each α: `f(α, s, cap)`.
fn for_each_cap(
    alphas: &[f64],
    sigmas_deg: &[f64],
    positions: &[(f64, f64)],
    mut f: impl FnMut(f64, &SphereShading<'_>, &Cap),
) {
    for theta_o in [0.0, 45.0, 80.0] {
        for &alpha in alphas {
            let pair = pair_at(theta_o, alpha);
            for &sigma_deg in sigmas_deg {
                for &(elevation, azimuth) in positions {
                    let radius = (sigma_deg * DEG).sin();
                    let s = shading(theta_o, alpha, axis_at(elevation, azimuth), radius, &pair);
                    let cap = Cap::of_sphere(s.u, s.radius).expect("a radius above 0");
                    f(alpha, &s, &cap);
                }
            }
        }
    }
}

/// The exact method's rule, against itself with twice the nodes, over the sizes and
/// roughnesses the lab measures (`sphere_error`): `EXACT_NODES`'s and `MEASURE_NODES`'s
/// documented bounds.
#[test]
fn the_exact_method_converges_within_its_documented_bound() {
    let mut worst: f64 = 0.0;
    let positions = [(2.0, 180.0), (20.0, 0.0), (20.0, 90.0), (60.0, 180.0)];
    for_each_cap(
        &[0.05, 0.3, 1.0],
        &[2.0, 10.0, 30.0],
        &positions,
        |_, s, cap| {
            let b = sphere_exact(s, cap, 2 * EXACT_NODES);
            for (nodes, bound) in [(EXACT_NODES, 1e-6), (MEASURE_NODES, 1e-4)] {
                let a = sphere_exact(s, cap, nodes);
                for (x, y) in [(a.specular, b.specular), (a.diffuse, b.diffuse)] {
                    worst = worst.max((x - y).abs() / y.abs().max(1e-300) / bound);
                }
            }
        },
    );
    assert!(worst < 1.0, "worst {worst:e} of the bound");
}

fn close(a: Lobes<f64>, b: Lobes<f64>, tol: f64) -> bool {
    let rel = |x: f64, y: f64| (x - y).abs() <= tol * y.abs().max(1e-300);
    rel(a.specular, b.specular) && rel(a.diffuse, b.diffuse)
}

/// With r = 0 every method is the point light's own formula, bit for bit.
#[test]
fn a_radius_of_zero_is_the_point_light() {
    let pair = pair_at(40.0, 0.3);
    let s = shading(40.0, 0.3, DVec3::new(0.4, -0.3, 0.8), 0.0, &pair);
    let point_exact = brdf::point_light_exact(s.v.to_array(), s.u.to_array(), 2.0, 3.0, 0.3, 0.04);
    let d = s.u.length();
    let e = brdf::irradiance_scale(2.0, d, 3.0);
    let lobes = pair.ltc_lobes(s.u / d, 0.04, Clipping::BOTH, Normalization::Corrected);
    let point_ltc = Lobes {
        specular: e * lobes.specular,
        diffuse: e * lobes.diffuse,
    };
    assert_eq!(sphere_light(SphereMethod::Exact, &s), point_exact);
    assert_eq!(
        sphere_light(SphereMethod::RepresentativePoint, &s),
        point_exact
    );
    assert_eq!(sphere_light(SphereMethod::LtcPoint, &s), point_ltc);
    assert_eq!(sphere_light(SphereMethod::LtcDisk, &s), point_ltc);
}

/// As the sphere shrinks, each method tends to its point formula: the exact integral and
/// the representative point to the exact point light, the LTC disk to the LTC at the centre.
#[test]
fn a_shrinking_sphere_tends_to_its_point_light() {
    for (theta_o, alpha) in [(0.0, 0.2), (50.0, 0.5), (75.0, 1.0)] {
        let pair = pair_at(theta_o, alpha);
        for u in [DVec3::new(0.3, 0.1, 0.9), DVec3::new(-0.8, 0.2, 0.3)] {
            let point = shading(theta_o, alpha, u, 0.0, &pair);
            // σ ≈ 1e-4 rad: a cap's mean differs from its centre's value by O((σ/α)²) ≤ 2.5e-7
            // here (the first-order term cancels over the symmetric cap); the representative
            // point moves by O(σ) and its energy factor is 1 − O(σ/α): 1e-3 covers both.
            let small = shading(theta_o, alpha, u, 1e-4 * u.length(), &pair);
            let at = |m, s: &SphereShading<'_>| sphere_light(m, s);
            assert!(close(
                at(SphereMethod::Exact, &small),
                at(SphereMethod::Exact, &point),
                1e-5
            ));
            assert!(close(
                at(SphereMethod::LtcDisk, &small),
                at(SphereMethod::LtcPoint, &point),
                1e-5
            ));
            assert!(close(
                at(SphereMethod::RepresentativePoint, &small),
                at(SphereMethod::Exact, &point),
                1e-3
            ));
        }
    }
}

/// The failure cases on purpose: spheres cut by the horizon, below it, touching and
/// enclosing the point, seen at grazing views. Every method stays finite and, with both
/// rules on, never negative.
#[test]
fn spheres_anywhere_give_finite_non_negative_light() {
    for theta_o in [0.0, 60.0, 89.0] {
        for alpha in [1e-4, 0.05, 0.5, 1.0] {
            let pair = pair_at(theta_o, alpha);
            for (elevation, azimuth, d) in [
                (-30.0, 0.0, 1.0),
                (-5.0, 180.0, 1.0),
                (0.0, 90.0, 1.0),
                (3.0, 0.0, 1.0),
                (89.0, 0.0, 0.5),
                (45.0, 180.0, 0.2),
                (10.0, 0.0, 0.1),
                (-60.0, 0.0, 0.05),
                (90.0, 0.0, 0.0),
                (20.0, 90.0, 1.0 + 1e-15),
            ] {
                for radius in [0.0, 0.01, 0.2, 0.3, 1.0] {
                    let s = shading(
                        theta_o,
                        alpha,
                        axis_at(elevation, azimuth) * d,
                        radius,
                        &pair,
                    );
                    for method in SphereMethod::ALL {
                        let l = sphere_light(method, &s);
                        for x in [l.specular, l.diffuse] {
                            assert!(
                                x.is_finite() && x >= 0.0,
                                "{} at θo {theta_o} α {alpha} {elevation}°/{azimuth}° d {d} r {radius}: {l:?}",
                                method.name()
                            );
                        }
                    }
                }
            }
        }
    }
}

/// What the measure of `sphere_error` must show, whatever the exact figures: at half a
/// degree the LTC methods carry the point light's own error (§4.7's, same cases); the
/// representative point, an exact BRDF at a moved point, is far better there; from 10° the
/// LTC disk beats the point formula in every band, and at 30° the representative point is
/// worse than the disk by more than half. The sums move between seeds (at 4 000 cases the
/// worst figure by up to half itself, typically by a few %), so only wide margins are
/// asserted; seeds 22, 23 and 24 all pass at these 2 000 cases.
#[test]
fn the_methods_errors_by_size_and_band_keep_their_order() {
    let lut = Lut::embedded();
    let cases = 2000;
    let errors = sphere_errors(lut, &[0.5, 10.0, 30.0], cases, 22, MEASURE_NODES);
    let points = band_errors(lut, &Default::default(), cases, 22);
    let at = |radius: f64, band: [f64; 2]| {
        *errors
            .iter()
            .find(|e| e.radius_deg == radius && e.band == band)
            .unwrap()
    };
    let [point, disk, representative] = [0, 1, 2];
    for p in &points {
        let e = at(0.5, p.band);
        // Half a degree moves a case's exact value by O((σ/α)²), at most 3% at α = 0.05 and
        // far less for most cases: 0.02 of the band's error is that bound's share.
        for m in [point, disk] {
            assert!((e.specular[m] - p.specular).abs() < 0.02, "{e:?} vs {p:?}");
            assert!((e.diffuse[m] - p.diffuse).abs() < 0.02, "{e:?} vs {p:?}");
        }
        assert!(
            e.specular[representative] < 0.5 * e.specular[point],
            "{e:?}"
        );
        for radius in [10.0, 30.0] {
            let e = at(radius, p.band);
            assert!(e.specular[disk] < e.specular[point], "{e:?}");
            assert!(e.diffuse[disk] <= e.diffuse[point], "{e:?}");
        }
        let e = at(30.0, p.band);
        assert!(e.specular[representative] > 2.0 * e.specular[disk], "{e:?}");
        assert!(at(30.0, p.band).specular[disk] < at(10.0, p.band).specular[disk]);
    }
}

/// The renders' rule (`sphere_rule`, docs/design.md §1.14) against `EXACT_NODES`: within the
/// 1e-3 a reference drawn as ground truth is held to (§1.14) for the specular lobe and 1e-6 for
/// the diffuse one, for caps to 30° anywhere above or across the horizon and α from 0.05
/// (measured: 3.4e-4 at α = 0.05, and 1e-11; the rule is f64 arithmetic, the same everywhere).
#[test]
fn the_renders_rule_is_within_its_documented_bound() {
    let (mut worst_spec, mut worst_diff): (f64, f64) = (0.0, 0.0);
    let positions = [
        (2.0, 180.0),
        (20.0, 0.0),
        (20.0, 90.0),
        (60.0, 180.0),
        (-3.0, 30.0),
    ];
    let alphas = [0.05, 0.2, 0.5, 1.0];
    for_each_cap(
        &alphas,
        &[0.5, 2.0, 10.0, 30.0],
        &positions,
        |alpha, s, cap| {
            let want = sphere_exact(s, cap, EXACT_NODES);
            let got = sphere_rule(s, cap);
            let rel = |x: f64, y: f64| (x - y).abs() / y.abs().max(1e-300);
            let _ = alpha;
            worst_spec = worst_spec.max(rel(got.specular, want.specular));
            worst_diff = worst_diff.max(rel(got.diffuse, want.diffuse));
        },
    );
    eprintln!("the renders' rule: worst specular {worst_spec:.2e}, diffuse {worst_diff:.2e}");
    assert!(
        worst_spec < 1e-3 && worst_diff < 1e-6,
        "{worst_spec:e} {worst_diff:e}"
    );
}

/// Spheres too small to matter, down to the smallest f64 radii: every method stays finite
/// and non-negative and gives its point light to 1% — the exact integral and the
/// representative point the exact point light, the LTC disk and the LTC point the paper's
/// formula at the centre. Below σ = 1e-4° = 1.7e-6 rad a cap's mean differs from its centre's
/// value by O((σ/α)²) ≤ 3e-10 at these α, and the representative point's energy factor by
/// O(σ/α) ≤ 9e-6: 1% leaves room only for a formula that cancels or overflows (the exact
/// integral lost 1 − cos σ to rounding: 28% low at 1e-6°, 7200× at 1e-8°, then 0 or NaN;
/// the disk reached 4e201 at 1e-100° and inf below 1e-153°).
#[test]
fn tiny_spheres_down_to_the_smallest_radii_are_their_point_lights() {
    // Every half decade from 1e-4° to 1e-12°, either side of the point limit, then every
    // fourth decade to 1e-300°, and the smallest normal and subnormal f64.
    let mut sizes: Vec<f64> = (8..=24)
        .map(|k| 10f64.powf(-0.5 * f64::from(k)) * DEG)
        .collect();
    sizes.extend((16..=300).step_by(4).map(|k| 10f64.powi(-k) * DEG));
    let limit = POINT_LIMIT_SIN_SIGMA.asin();
    sizes.extend([
        limit * (1.0 - 1e-9),
        limit * (1.0 + 1e-9),
        f64::MIN_POSITIVE,
        4.9e-324,
    ]);
    for (theta_o, alpha) in [(0.0, 0.2), (50.0, 0.5), (75.0, 1.0)] {
        let pair = pair_at(theta_o, alpha);
        for u in [
            DVec3::new(0.3, 0.1, 0.9),
            DVec3::new(-0.8, 0.2, 0.3),
            DVec3::new(0.1, -0.2, 2.5),
        ] {
            let point = shading(theta_o, alpha, u, 0.0, &pair);
            for &sigma in &sizes {
                let radius = sigma.sin() * u.length();
                let s = shading(theta_o, alpha, u, radius, &pair);
                for method in SphereMethod::ALL {
                    let limit = match method {
                        SphereMethod::Exact | SphereMethod::RepresentativePoint => {
                            SphereMethod::Exact
                        }
                        SphereMethod::LtcPoint | SphereMethod::LtcDisk => SphereMethod::LtcPoint,
                    };
                    let got = sphere_light(method, &s);
                    let want = sphere_light(limit, &point);
                    for (x, y) in [(got.specular, want.specular), (got.diffuse, want.diffuse)] {
                        assert!(
                            x.is_finite() && x >= 0.0 && (x - y).abs() <= 0.01 * y,
                            "{} at σ = {:e}°, u {u}, θo {theta_o}, α {alpha}: {x:e} against the point's {y:e}",
                            method.name(),
                            sigma / DEG
                        );
                    }
                }
            }
        }
    }
}
