//! Disk lights' math against independent f64 ground truth: the exact rule against the closed
//! form of a parallel disk and Lambert's edge formula over a fine inscribed polygon, the LTC
//! disk against the LTC's D integrated over the polygon, the point limit, a disk facing away,
//! the rule's convergence on sharp lobes, and every method finite and ≥ 0 at the limits.

use std::f64::consts::PI;

use glam::DVec3;
use ltc_lab::brdf::{self, Alpha, brdf_cos};
use ltc_lab::light::EmitterShading;
use ltc_lab::light::disk::{
    Disk, DiskMethod, DiskShading, RENDER_NODES, disk_exact, disk_integral_about, disk_light,
    disk_light_with, ltc_disk_light,
};
use ltc_lab::light::rect::{clip_horizon, polygon_form_factor, polygon_integral};
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::{Clipping, Normalization};
use ltc_lab::scene::SplitMix64;

const DEG: f64 = PI / 180.0;

/// A disk of radius `r` at `centre` whose normal is tilted by `tilt` degrees about x from the
/// direction to the origin.
fn facing(centre: DVec3, r: f64, tilt: f64) -> Disk {
    let w = -centre.normalize();
    let (t1, _) = w.any_orthonormal_pair();
    let normal = (w * (tilt * DEG).cos() + t1 * (tilt * DEG).sin()).normalize();
    let disk = Disk {
        centre,
        normal,
        radius: r,
    };
    assert!(disk.faces_origin());
    disk
}

fn disks() -> Vec<Disk> {
    vec![
        facing(DVec3::new(0.0, 0.0, 1.0), 0.2, 0.0),
        facing(DVec3::new(0.5, -0.3, 0.8), 0.4, 25.0),
        facing(DVec3::new(-0.7, 0.2, 0.4), 0.6, -30.0),
        // Crossing the horizon.
        facing(DVec3::new(0.9, 0.1, 0.1), 0.5, 10.0),
        facing(DVec3::new(-0.2, 0.8, -0.05), 0.3, 0.0),
        // Large and near: much of the sky.
        facing(DVec3::new(0.1, 0.0, 0.3), 1.5, 5.0),
    ]
}

/// The disk as the `n`-gon inscribed in its rim, counter-clockwise about its normal.
fn inscribed(disk: &Disk, n: usize) -> Vec<DVec3> {
    let (e1, e2) = disk.half_axes();
    (0..n)
        .map(|k| {
            let t = 2.0 * PI * k as f64 / n as f64;
            disk.centre + e1 * t.cos() + e2 * t.sin()
        })
        .collect()
}

/// A disk parallel to the surface at height `h` above the point, centred on its normal: its
/// form factor is `r² / (r² + h²)` (the classic closed form). The rule's integrand,
/// `h²/(h² + ρ²)²` over the area, is smooth but peaked within `h` of the centre: 32 nodes a
/// piece leave 3e-9 where `r = 15 h`, rounding elsewhere; 1e-8 is the bound.
#[test]
fn the_rule_gives_a_parallel_disks_closed_form() {
    for (r, h) in [(0.1, 1.0), (1.0, 1.0), (3.0, 0.2), (1e-3, 2.0)] {
        let disk = Disk {
            centre: DVec3::new(0.0, 0.0, h),
            normal: DVec3::NEG_Z,
            radius: r,
        };
        let [got] = disk_integral_about(&disk, 32, None, |l| [l.z / PI]);
        let want = r * r / (r * r + h * h);
        assert!(
            (got - want).abs() <= 1e-8 * want,
            "r {r} h {h}: {got} vs {want}"
        );
    }
}

/// The clamped cosine over the disk's part above the surface against Lambert's edge formula
/// over the inscribed 4096-gon clipped at the horizon: the polygon misses a sliver of the
/// disk of relative area `π²/(6·4096²)` ≈ 1e-7, so 1e-6 of the value is the bound (the rule's
/// own error is ~1e-12 at 32 nodes).
#[test]
fn the_rule_is_the_cosine_integral_over_the_disk_above_the_surface() {
    for disk in disks() {
        let polygon = clip_horizon(&inscribed(&disk, 4096));
        let want = polygon_form_factor(&polygon);
        let [got] = disk_integral_about(&disk, 32, None, |l| [l.z.max(0.0) / PI]);
        assert!(got >= 0.0 && want > 0.0, "{disk:?}: {got} {want}");
        assert!(
            (got - want).abs() <= 1e-6 * want,
            "{disk:?}: {got} vs {want}"
        );
    }
}

/// The exact method (the BRDF over the disk) against the rect's own rule (Duffy fans, a
/// different quadrature) over the inscribed 512-gon: the polygon misses ~6e-6 of the disk's
/// area; with each rule's error under 1e-7 at 64 nodes for α ≥ 0.2, 5e-5 is the bound.
#[test]
fn the_exact_method_is_the_brdf_over_the_disk() {
    for (theta_o, alpha) in [(0.0, 0.3), (40.0, 0.5), (70.0, 0.2)] {
        let v = DVec3::from(brdf::view_from_theta(theta_o * DEG));
        for disk in disks() {
            let got = disk_exact(v, &disk, Alpha::isotropic(alpha), 0.04, 64);
            let polygon = clip_horizon(&inscribed(&disk, 512));
            let want = polygon_integral(&polygon, 64, |l| {
                let f = brdf_cos(v.to_array(), l.to_array(), alpha, 0.04);
                [f.specular, f.diffuse]
            });
            for (g, w) in [(got.specular, want[0]), (got.diffuse, want[1])] {
                assert!(
                    (g - w).abs() <= 5e-5 * w.abs().max(1e-12),
                    "θo {theta_o} α {alpha} {disk:?}: {g} vs {w}"
                );
            }
        }
    }
}

/// Heitz & Hill's LTC disk is `∫ D` over the disk where nothing is cut (the disk and its image
/// under `M⁻¹` above both horizons): the elliptical cone's form factor is exact there. Against
/// `D` integrated pointwise over the inscribed 1024-gon (1e-6 of area missing; the quadrature
/// good to ~1e-9 on these smooth lobes): 1e-5 relative.
#[test]
fn ltc_disk_is_d_integrated_over_the_disk_where_nothing_is_cut() {
    let lut = Lut::embedded();
    let n = Normalization::Corrected;
    let mut compared = 0;
    for (theta_o, alpha) in [(0.0, 0.3), (30.0, 0.5), (60.0, 0.8)] {
        let v = DVec3::from(brdf::view_from_theta(theta_o * DEG));
        let pair = lut.ltc_pair(alpha, v);
        for disk in disks().into_iter().take(3) {
            for ltc in [&pair.spec, &pair.diff] {
                let polygon = inscribed(&disk, 1024);
                // Nothing cut: every rim point's image is above the cosine's horizon.
                if polygon.iter().any(|&p| (ltc.cos_from_brdf * p).z <= 0.0) {
                    continue;
                }
                let got = ltc_disk_light(ltc, &disk, false, n);
                let [want] =
                    polygon_integral(&polygon, 64, |l| [ltc.ltc_eval(l, Clipping::BOTH, n)]);
                assert!(
                    (got - want).abs() <= 1e-5 * want,
                    "θo {theta_o} α {alpha} {disk:?}: {got} vs {want}"
                );
                compared += 1;
            }
        }
    }
    // Most of the 18 (lobe, disk, view) cases have nothing cut.
    assert!(compared >= 12, "only {compared} cases compared");
}

/// A disk far smaller than its distance is its oriented point light, `f cos · L A cos θe / d²`
/// (r/d = 5e-4: the BRDF's variation over it is O((r/d)²/α²) ≈ 2e-6).
#[test]
fn a_tiny_disk_is_its_oriented_point_light() {
    let v = DVec3::from(brdf::view_from_theta(30.0 * DEG));
    for centre in [DVec3::new(0.3, 0.2, 0.9), DVec3::new(-0.6, 0.1, 0.5)] {
        let disk = facing(centre, 5e-4 * centre.length(), 20.0);
        let got = disk_exact(v, &disk, Alpha::isotropic(0.4), 0.04, 8);
        let d = centre.length();
        let scale = disk.area() * disk.normal.dot(-centre / d) / (d * d);
        let point = brdf_cos(v.to_array(), (centre / d).to_array(), 0.4, 0.04);
        for (x, y) in [(got.specular, point.specular), (got.diffuse, point.diffuse)] {
            assert!(
                (x - y * scale).abs() <= 1e-4 * y * scale,
                "{x} vs {}",
                y * scale
            );
        }
    }
}

/// A disk facing away lights nothing by every method; turned over, it lights.
#[test]
fn a_disk_facing_away_lights_nothing() {
    let lut = Lut::embedded();
    let v = DVec3::from(brdf::view_from_theta(20.0 * DEG));
    let pair = lut.ltc_pair(0.3, v);
    let disk = facing(DVec3::new(0.2, 0.1, 1.0), 0.3, 0.0);
    let away = Disk {
        normal: -disk.normal,
        ..disk
    };
    for method in DiskMethod::ALL {
        let s = |disk| DiskShading {
            pixel: EmitterShading {
                v,
                alpha: Alpha::isotropic(0.3),
                f0: 0.04,
                ltc: &pair,
                clip: Clipping::BOTH,
                normalization: Normalization::Corrected,
            },
            disk,
        };
        assert_eq!(disk_light(method, &s(away)), brdf::Lobes::default());
        assert!(
            disk_light(method, &s(disk)).diffuse > 0.0,
            "{}",
            method.name()
        );
    }
}

/// The exact rule on sharp lobes: with the mirror direction inside the disk the pieces meet at
/// its hit, and 64 nodes a piece agree with 256 to 1e-3 down to α = 0.002.
#[test]
fn the_exact_rule_converges_on_sharp_lobes() {
    let v = DVec3::from(brdf::view_from_theta(35.0 * DEG));
    let mirror = DVec3::new(-v.x, -v.y, v.z);
    let disk = facing(mirror * 1.5 + DVec3::new(0.05, 0.02, 0.0), 0.5, 15.0);
    for alpha in [0.002, 0.02, 0.2] {
        let coarse = disk_exact(v, &disk, Alpha::isotropic(alpha), 0.04, 64);
        let fine = disk_exact(v, &disk, Alpha::isotropic(alpha), 0.04, 256);
        assert!(
            (coarse.specular - fine.specular).abs() <= 1e-3 * fine.specular,
            "α {alpha}: {} vs {}",
            coarse.specular,
            fine.specular
        );
    }
}

/// The renders' rule (8 nodes a piece) against 64: within 2% on the specular lobe for
/// α ≥ 0.2 and 1e-3 on the diffuse one, the sphere's budget, for disks no wider than their
/// distance (docs/design.md §1.12). A disk filling most of the sky (r = 5 d) is beyond it: the
/// area's `1/|x|²` peaks at the disk's foot while the pieces meet at the mirror direction's
/// hit, and the rule is up to 13% off there (the 64-node rule is the reference).
#[test]
fn the_renders_rule_is_within_its_stated_bound() {
    for theta_o in [0.0, 50.0, 80.0] {
        let v = DVec3::from(brdf::view_from_theta(theta_o * DEG));
        the_renders_rule_at(v);
    }
}

fn the_renders_rule_at(v: DVec3) {
    for alpha in [0.2, 0.5, 1.0] {
        for disk in disks()
            .into_iter()
            .filter(|d| d.radius <= d.centre.length())
        {
            let coarse = disk_exact(v, &disk, Alpha::isotropic(alpha), 0.04, RENDER_NODES);
            let fine = disk_exact(v, &disk, Alpha::isotropic(alpha), 0.04, 64);
            assert!(
                (coarse.specular - fine.specular).abs() <= 0.02 * fine.specular,
                "α {alpha} {disk:?}: {} vs {}",
                coarse.specular,
                fine.specular
            );
            assert!(
                (coarse.diffuse - fine.diffuse).abs() <= 1e-3 * fine.diffuse,
                "α {alpha} {disk:?}: {} vs {}",
                coarse.diffuse,
                fine.diffuse
            );
        }
    }
}

/// Every method, every clipping rule, on random disks from 1e-6 to 10 times their distance,
/// at every elevation (below the surface, across it, edge-on, touching): finite and ≥ 0 with
/// case 1 on (off, the signed integral may be negative: the leak the lab shows).
#[test]
fn every_method_is_finite_and_non_negative_at_the_limits() {
    let lut = Lut::embedded();
    let mut rng = SplitMix64(12);
    for _ in 0..3000 {
        let theta_o = rng.uniform([0.0, 89.0]) * DEG;
        let alpha = rng.uniform([0.01, 1.0]);
        let v = DVec3::from(brdf::view_from_theta(theta_o));
        let pair = lut.ltc_pair(alpha, v);
        let elevation = rng.uniform([-0.5, 0.5]) * PI;
        let azimuth = rng.uniform([0.0, 2.0 * PI]);
        let d = 10f64.powf(rng.uniform([-3.0, 1.0]));
        let centre = DVec3::new(
            elevation.cos() * azimuth.cos(),
            elevation.cos() * azimuth.sin(),
            elevation.sin(),
        ) * d;
        let normal = DVec3::new(
            rng.uniform([-1.0, 1.0]),
            rng.uniform([-1.0, 1.0]),
            rng.uniform([-1.0, 1.0]),
        )
        .normalize();
        let disk = Disk {
            centre,
            normal,
            radius: d * 10f64.powf(rng.uniform([-6.0, 1.0])),
        };
        for clip in [
            Clipping::BOTH,
            Clipping {
                case1: true,
                case2: false,
            },
        ] {
            let s = DiskShading {
                pixel: EmitterShading {
                    v,
                    alpha: Alpha::isotropic(alpha),
                    f0: 0.04,
                    ltc: &pair,
                    clip,
                    normalization: Normalization::Corrected,
                },
                disk,
            };
            for method in DiskMethod::ALL {
                let lobes = disk_light_with(method, &s, ltc_lab::light::ExactRule::Render);
                for x in [lobes.specular, lobes.diffuse] {
                    let ok =
                        x.is_finite() && (x >= 0.0 || (!clip.case2 && method != DiskMethod::Exact));
                    assert!(ok, "{} {clip:?} {disk:?} α {alpha}: {x}", method.name());
                }
            }
        }
    }
}
