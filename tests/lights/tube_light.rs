//! Tube lights' math against independent f64 ground truth: the exact rules (the band's and the
//! polar one over the silhouette) against an integral over the capsule's surface (each direction meets
//! one front-facing point, `dω = −n·ω dA / |y|²`), the closed-form line integrals against
//! Gauss–Legendre along the segment, the LTC line against the LTC's D over a thin capsule,
//! the point limit, and every method finite and ≥ 0 at the limits (tiny, grazing, huge,
//! touching the surface, the shading point inside).

use std::f64::consts::{PI, TAU};

use glam::DVec3;
use ltc_lab::brdf::{self, Alpha, brdf_cos_aniso};
use ltc_lab::light::EmitterShading;
use ltc_lab::light::polar::{DIFFUSE_NODES, RULE_NODES};
use ltc_lab::light::tube::band::tube_band;
use ltc_lab::light::tube::line::{diffuse_line, line_irradiance, ltc_line};
use ltc_lab::light::tube::region::tube_exact;
use ltc_lab::light::tube::{Tube, TubeMethod, TubeShading, tube_light};
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::{Clipping, Ltc, Normalization};

use crate::common::capsule_integral;

const DEG: f64 = PI / 180.0;

/// The cases: above the surface, across the horizon, near its side, end-on, long and thin.
fn tubes() -> Vec<(&'static str, Tube)> {
    let t = |a: [f64; 3], b: [f64; 3], radius| Tube {
        a: DVec3::from(a),
        b: DVec3::from(b),
        radius,
    };
    vec![
        ("above", t([-0.5, 0.2, 1.0], [0.5, 0.4, 1.2], 0.15)),
        (
            "across the horizon",
            t([0.3, -0.8, -0.4], [0.6, 0.9, 0.7], 0.2),
        ),
        ("close beside", t([-1.0, 0.3, 0.35], [1.0, 0.3, 0.35], 0.25)),
        ("end-on", t([0.2, 0.1, 0.6], [0.6, 0.3, 1.8], 0.2)),
        ("long and thin", t([-3.0, 1.0, 0.8], [3.0, -1.0, 0.8], 0.02)),
    ]
}

fn view(theta_o_deg: f64) -> DVec3 {
    DVec3::from(brdf::view_from_theta(theta_o_deg * DEG))
}

#[test]
fn the_exact_rules_are_the_integral_over_the_capsules_surface() {
    // Both rules against the surface's midpoint rule at 1 200 cells a side: the polar rule
    // over the silhouette at 64 nodes, and the band's (the tube's exact method) at 64 and at
    // the renders' 12 and 8. The midpoint rule's error is O(1/n²) ≈ 1e-6 of its scale, the
    // rules' at 64 below 1e-6 where they are smooth; 2e-3 (the bound) leaves the
    // margin to f64's every case, α down to 0.1, and holds the renders' nodes too.
    let mut worst = [0.0f64; 3];
    for (name, tube) in tubes() {
        for theta_o in [0.0, 50.0, 80.0] {
            for alpha in [0.1, 0.35, 0.8] {
                let v = view(theta_o);
                let a = Alpha::isotropic(alpha);
                let rules = [
                    tube_exact(v, &tube, a, 0.04, (64, 64)),
                    tube_band(v, &tube, a, 0.04, (64, 64)),
                    tube_band(v, &tube, a, 0.04, (RULE_NODES, DIFFUSE_NODES)),
                ];
                for (lobe, pick) in [("specular", 0usize), ("diffuse", 1)] {
                    let reference = capsule_integral(&tube, 1200, |w| {
                        let l = brdf_cos_aniso(v.to_array(), w.to_array(), a, 0.04);
                        [l.specular, l.diffuse][pick]
                    });
                    for (k, rule) in rules.iter().enumerate() {
                        let got = [rule.specular, rule.diffuse][pick];
                        let error = (got - reference).abs() / reference.max(1e-12);
                        worst[k] = worst[k].max(error);
                        assert!(
                            error < 2e-3,
                            "{name}, θo {theta_o}, α {alpha}, {lobe}, rule {k}: {got:e}, surface {reference:e} ({error:.2e})"
                        );
                    }
                }
            }
        }
    }
    eprintln!(
        "against the surface, worst relative error: polar 64 {:.2e}, band 64 {:.2e}, band 12/8 {:.2e}",
        worst[0], worst[1], worst[2]
    );
}

/// A tube of random shape and place: its centre from 30° below the horizon to the zenith,
/// 0.3–3 away, its length 0–4 times that along any axis, its radius 0.1%–30% of it
/// (log-uniform); the view from θo 0 to 83°.
fn random_tube(rng: &mut ltc_lab::scene::SplitMix64) -> (DVec3, Tube, f64) {
    let theta: f64 = rng.uniform([0.0, 1.45]);
    let alpha = rng.uniform([0.05, 1.0]);
    let at = |el: f64, az: f64| DVec3::new(el.cos() * az.cos(), el.cos() * az.sin(), el.sin());
    let d = rng.uniform([0.3, 3.0]);
    let c = at(rng.uniform([-0.5, 1.5]), rng.uniform([0.0, TAU])) * d;
    let axis = at(rng.uniform([-1.5, 1.5]), rng.uniform([0.0, TAU]));
    let half = 0.5 * d * rng.uniform([0.0, 4.0]) * axis;
    let radius = 0.3 * d * 10f64.powf(rng.uniform([-3.0, 0.0]));
    let v = DVec3::new(theta.sin(), 0.0, theta.cos());
    (
        v,
        Tube {
            a: c - half,
            b: c + half,
            radius,
        },
        alpha,
    )
}

#[test]
fn the_bands_rule_converges_at_the_renders_nodes_where_the_polar_rule_does_not() {
    // On 200 random tubes the band's rule at the renders' 12 and 8 nodes against itself at
    // 64, and, where the tube is no sliver (r ≥ 1% of its distance), against the polar rule
    // at 96: two parametrizations of one integral. Over these tubes (half of them slivers) the
    // first is within 6.7e-5 (specular) and 3.3e-4 (diffuse) of the second; 2e-3 is the
    // issue's bound.
    let mut rng = ltc_lab::scene::SplitMix64(7);
    let mut worst = [0.0f64; 2];
    let mut slivers = 0;
    for _ in 0..200 {
        let (v, tube, alpha) = random_tube(&mut rng);
        if tube.encloses_origin() || tube.below_horizon() {
            continue;
        }
        let a = Alpha::isotropic(alpha);
        let sliver = tube.radius < 0.01 * tube.centre().length();
        slivers += usize::from(sliver);
        let reference = match sliver {
            true => tube_band(v, &tube, a, 0.04, (64, 64)),
            false => tube_exact(v, &tube, a, 0.04, (96, 96)),
        };
        let got = tube_band(v, &tube, a, 0.04, (RULE_NODES, DIFFUSE_NODES));
        for (k, (g, r)) in [
            (got.specular, reference.specular),
            (got.diffuse, reference.diffuse),
        ]
        .into_iter()
        .enumerate()
        {
            // Relative to the lobe, with a floor far below any light the renders show.
            let error = (g - r).abs() / r.max(1e-9);
            worst[k] = worst[k].max(error);
            assert!(
                error < 2e-3,
                "{tube:?} α {alpha}: {got:?} against {reference:?}"
            );
        }
    }
    assert!(slivers > 20, "{slivers} slivers drawn");
    eprintln!(
        "the band's rule at 12 and 8 nodes: worst {:.2e}, {:.2e} ({slivers} slivers)",
        worst[0], worst[1]
    );
    // And the sliver where the polar rule at the renders' nodes is 15–40% off (docs/design.md
    // §1.15): the band's rule at 8 nodes is its converged value.
    let tube = Tube {
        a: DVec3::new(2.584, -0.556, -5.395),
        b: DVec3::new(0.979, -1.141, 3.255),
        radius: 0.0102,
    };
    for theta in [0.0f64, 1.4] {
        let v = DVec3::new(theta.sin(), 0.0, theta.cos());
        let a = Alpha::isotropic(0.394);
        let converged = tube_band(v, &tube, a, 0.5, (64, 64));
        let polar = tube_exact(v, &tube, a, 0.5, (RULE_NODES, DIFFUSE_NODES));
        let band = tube_band(v, &tube, a, 0.5, (8, 8));
        let off = |x: f64, y: f64| (x - y).abs() / y;
        assert!(
            off(band.specular, converged.specular) < 1e-4,
            "{band:?} {converged:?}"
        );
        assert!(
            off(band.diffuse, converged.diffuse) < 1e-4,
            "{band:?} {converged:?}"
        );
        assert!(
            off(polar.diffuse, converged.diffuse) > 0.1,
            "{polar:?} {converged:?}"
        );
    }
}

#[test]
fn line_irradiance_is_the_segment_of_point_lights() {
    let gl = ltc_lab::light::polar::rule(64);
    for (name, tube) in tubes() {
        // ∫ p_z/|p|³ dℓ over the part above the surface, by 64 nodes on 4 pieces of it.
        let (a, b) = ltc_lab::light::tube::line::clip_segment(tube.a, tube.b).expect("above");
        let mut sum = 0.0;
        for piece in 0..4 {
            for &(x, w) in gl {
                let t = (piece as f64 + 0.5 * (x + 1.0)) / 4.0;
                let p = a + (b - a) * t;
                sum += w / 8.0 * p.z / p.length().powi(3);
            }
        }
        sum *= (b - a).length();
        let got = line_irradiance(tube.a, tube.b);
        assert!(
            (got - sum).abs() <= 1e-9 * sum,
            "{name}: {got:e} against {sum:e}"
        );
    }
}

#[test]
fn the_cosines_line_integral_is_a_thin_capsule_without_its_ends() {
    // A capsule of radius 1e-4 (its ends' share π r² is 1e-4 of the side's 2 r ℓ) against the
    // line integral times r: the thin limit's error is O(r/d) ≈ 3e-4.
    for (name, tube) in tubes() {
        let thin = Tube {
            radius: 1e-4,
            ..tube
        };
        let reference = capsule_integral(&thin, 1200, |w| w.z.max(0.0) / PI);
        let got = thin.radius * diffuse_line(thin.a, thin.b);
        if name == "end-on" {
            // The line through the point: the side covers no directions, the ends all.
            assert!(
                got.abs() <= 1e-3 * reference,
                "{name}: {got:e} against {reference:e}"
            );
            continue;
        }
        assert!(
            (got - reference).abs() <= 2e-3 * reference,
            "{name}: {got:e} against {reference:e}"
        );
        // The identity's LTC is the cosine itself.
        let ltc =
            thin.radius * ltc_line(&Ltc::identity(), thin.a, thin.b, Normalization::Corrected);
        assert!(
            (ltc - got).abs() <= 1e-12 * got,
            "{name}: {ltc:e} against {got:e}"
        );
    }
}

#[test]
fn an_ltc_line_is_its_d_over_a_thin_capsule() {
    // The shipped table's lobe at θo 50°, α 0.3: the LTC of D over the thin capsule against the
    // line integral by M⁻¹ with Heitz & Hill's width factor — exact for a thin cylinder but
    // for the factor's spread along the segment, within 2e-2 here.
    let v = view(50.0);
    let pair = Lut::embedded().ltc_pair(0.3, v);
    for (name, tube) in tubes() {
        let thin = Tube {
            radius: 1e-4,
            ..tube
        };
        let reference = capsule_integral(&thin, 1200, |w| {
            pair.spec
                .ltc_eval(w, Clipping::BOTH, Normalization::Corrected)
        });
        let got = thin.radius * ltc_line(&pair.spec, thin.a, thin.b, Normalization::Corrected);
        if name == "end-on" {
            assert_eq!(got, 0.0, "{name}: the line through the point");
            continue;
        }
        assert!(
            (got - reference).abs() <= 2e-2 * reference,
            "{name}: {got:e} against {reference:e}"
        );
    }
}

fn shading<'a>(
    v: DVec3,
    tube: Tube,
    alpha: f64,
    pair: &'a ltc_lab::ltc::LtcPair,
) -> TubeShading<'a> {
    TubeShading {
        pixel: EmitterShading {
            v,
            alpha: Alpha::isotropic(alpha),
            f0: 0.04,
            ltc: pair,
            clip: Clipping::BOTH,
            normalization: Normalization::Corrected,
        },
        tube,
    }
}

#[test]
fn far_away_every_method_is_the_point_light() {
    // At 1e4 its sizes the mean over the capsule differs from the centre's value by
    // O((size/d)²/α²) ≈ 1e-7; the LTC methods are the paper's point formula there.
    let v = view(40.0);
    let alpha = 0.4;
    let pair = Lut::embedded().ltc_pair(alpha, v);
    let centre = DVec3::new(0.3, -0.2, 0.9).normalize() * 1e4;
    let e = DVec3::new(1.0, 0.5, 0.2).normalize();
    let tube = Tube {
        a: centre - e * 0.5,
        b: centre + e * 0.5,
        radius: 0.1,
    };
    let s = shading(v, tube, alpha, &pair);
    let exact = tube_light(TubeMethod::Exact, &s);
    let point = ltc_lab::light::tube::tube_point(true, &s);
    for (got, want) in [
        (exact.specular, point.specular),
        (exact.diffuse, point.diffuse),
    ] {
        assert!(
            (got - want).abs() <= 1e-4 * want,
            "exact {got:e}, point {want:e}"
        );
    }
    let ltc = tube_light(TubeMethod::LtcPoint, &s);
    let line = tube_light(TubeMethod::LtcLine, &s);
    for (got, want) in [(line.specular, ltc.specular), (line.diffuse, ltc.diffuse)] {
        assert!(
            (got - want).abs() <= 1e-2 * want,
            "ltc-line {got:e}, ltc-point {want:e}"
        );
    }
}

#[test]
fn every_method_is_finite_and_not_negative_at_the_limits() {
    let t = |a: [f64; 3], b: [f64; 3], radius| Tube {
        a: DVec3::from(a),
        b: DVec3::from(b),
        radius,
    };
    let cases = [
        ("tiny", t([0.0, 0.0, 1.0], [1e-9, 0.0, 1.0], 1e-9)),
        ("huge", t([-1e5, 0.0, 3.0], [1e5, 0.0, 3.0], 2.0)),
        ("grazing", t([-1.0, 5.0, 0.01], [1.0, 5.0, 0.01], 0.02)),
        ("touching", t([-1.0, 0.0, 0.2], [1.0, 0.0, 0.2], 0.2)),
        (
            "the point inside",
            t([-1.0, 0.0, 0.1], [1.0, 0.0, 0.1], 0.3),
        ),
        ("below", t([-1.0, 0.0, -0.5], [1.0, 0.0, -0.5], 0.3)),
        ("a ball", t([0.2, 0.0, 1.0], [0.2, 0.0, 1.0], 0.4)),
        (
            "standing on its end",
            t([0.5, 0.0, 0.0], [0.5, 0.0, 2.0], 0.1),
        ),
    ];
    for theta_o in [0.0, 70.0, 89.0] {
        for alpha in [1e-3, 0.2, 1.0] {
            let v = view(theta_o);
            let pair = Lut::embedded().ltc_pair(alpha, v);
            for (name, tube) in cases {
                let s = shading(v, tube, alpha, &pair);
                for m in TubeMethod::ALL {
                    let l = tube_light(m, &s);
                    assert!(
                        l.specular.is_finite()
                            && l.diffuse.is_finite()
                            && l.specular >= 0.0
                            && l.diffuse >= 0.0,
                        "{name}, {}, θo {theta_o}, α {alpha}: {l:?}",
                        m.name()
                    );
                    if name == "below" {
                        assert_eq!((l.specular, l.diffuse), (0.0, 0.0), "{name}, {}", m.name());
                    }
                }
            }
        }
    }
}

#[test]
fn the_point_inside_sees_the_hemisphere() {
    // Inside the capsule every direction above meets it: the rule's integral is the BRDF's
    // over the hemisphere, here by the midpoint rule in (θ, φ) at 1 000 cells a side (the
    // integrand is smooth at α = 0.5: its error is O(1/n²) ≈ 1e-6).
    let v = view(30.0);
    let tube = Tube {
        a: DVec3::new(-1.0, 0.0, 0.1),
        b: DVec3::new(1.0, 0.0, 0.1),
        radius: 0.3,
    };
    let a = Alpha::isotropic(0.5);
    let inside = tube_exact(v, &tube, a, 0.04, (64, 64));
    let n = 1000;
    let h = 1.0 / n as f64;
    let [mut specular, mut diffuse] = [0.0; 2];
    for i in 0..n {
        let theta = 0.5 * PI * (i as f64 + 0.5) * h;
        for j in 0..n {
            let phi = 2.0 * PI * (j as f64 + 0.5) * h;
            let w = DVec3::new(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            );
            let l = brdf_cos_aniso(v.to_array(), w.to_array(), a, 0.04);
            let dw = theta.sin() * 0.5 * PI * 2.0 * PI * h * h;
            specular += l.specular * dw;
            diffuse += l.diffuse * dw;
        }
    }
    // The band's rule over the hemisphere (what the exact method and its shader twin take
    // inside) at the renders' nodes: within 1e-3 of it, the lobe's error bound of §1.14.
    let band = tube_band(v, &tube, a, 0.04, (RULE_NODES, DIFFUSE_NODES));
    for (got, want) in [
        (inside.specular, specular),
        (inside.diffuse, diffuse),
        (band.specular, specular),
        (band.diffuse, diffuse),
    ] {
        assert!(
            (got - want).abs() <= 1e-4 * want.max(1e-3),
            "rule {got:e}, hemisphere {want:e}"
        );
    }
}

#[test]
fn the_bands_hemisphere_converges_at_the_renders_nodes() {
    // Inside the capsule the band's rule takes the hemisphere with longitude about z; against
    // the polar rule at 64 nodes (region::tube_exact, another parametrization), from a sharp
    // lobe (α 0.3) to a rough one, θo up to 60°. Beyond, its 12 nodes are 0.9% off at θo 85°
    // (α 0.3), 1.6% at α 0.1 (θo 60°) and 3.4% at 0.02 (θo 30°): the band's limit inside a
    // capsule, where a reference takes the polar rule (`tube_light_with`). Measured: within 4.1e-4; the
    // bound is §1.14's 1e-3 of the renders' rule.
    let tube = Tube {
        a: DVec3::new(-1.0, 0.0, 0.1),
        b: DVec3::new(1.0, 0.0, 0.1),
        radius: 0.3,
    };
    let mut worst = 0.0f64;
    for theta in [0.0, 30.0, 60.0] {
        for alpha in [0.3, 0.6, 1.0] {
            let v = view(theta);
            let a = Alpha::isotropic(alpha);
            let want = tube_exact(v, &tube, a, 0.04, (64, 64));
            let got = tube_band(v, &tube, a, 0.04, (RULE_NODES, DIFFUSE_NODES));
            for (g, w) in [(got.specular, want.specular), (got.diffuse, want.diffuse)] {
                let error = (g - w).abs() / w.max(1e-6);
                worst = worst.max(error);
                assert!(error < 1e-3, "θ {theta} α {alpha}: band {g:e}, polar {w:e}");
            }
        }
    }
    eprintln!("the band's hemisphere at the renders' nodes: worst {worst:.2e}");
}

/// The tube's error table (`measure::emitter_error`, 100 cases a cell): every cell finite and
/// ≥ 0, and its methods ranked as their construction says. Small and high, the LTC line is
/// the point light, whose diffuse error is the table's own fit (0.9% at 30–90°, docs/design.md
/// §4.9): both under 3%, which leaves the 100 cases' sampling room. At 1 sr high up the line's
/// width and ends beat the centre as a point (measured 4.5–5% against 46–48% at 1000 cases:
/// asserted as under half). HDRP's tube has no ends, which hold about a fifth of a random
/// tube's light (its lengths 0 to 20 radii): above 15° it is behind the LTC line's diffuse.
#[test]
fn the_tube_error_table_ranks_its_methods() {
    use ltc_lab::light::ShapeKind;
    use ltc_lab::measure::emitter_error::{ALPHAS, emitter_errors};
    use ltc_lab::render::ShapeMethod;
    let rows = emitter_errors(ShapeKind::Tube, Lut::embedded(), 100, 7);
    assert_eq!(rows.len(), 4 * 4 * ALPHAS.len());
    let diffuse = |r: &ltc_lab::measure::emitter_error::EmitterError, m: TubeMethod| {
        let m = ShapeMethod::Tube(m);
        r.methods.iter().find(|(n, _)| *n == m).expect("measured").1[1]
    };
    for r in &rows {
        for (m, e) in &r.methods {
            assert!(e.iter().all(|x| x.is_finite() && *x >= 0.0), "{r:?}: {m:?}");
        }
        let (line, point) = (
            diffuse(r, TubeMethod::LtcLine),
            diffuse(r, TubeMethod::LtcPoint),
        );
        if r.band[0] >= 30.0 && r.solid_angle == 0.001 {
            assert!(line < 0.03 && point < 0.03, "{r:?}");
        }
        if r.band[0] >= 30.0 && r.solid_angle == 1.0 {
            assert!(line < 0.5 * point, "{r:?}");
        }
        if r.band[0] >= 15.0 {
            assert!(diffuse(r, TubeMethod::HdrpTube) > line, "{r:?}");
        }
    }
}
