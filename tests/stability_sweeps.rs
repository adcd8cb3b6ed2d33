//! The stability suite: sweeps, not single points, where the methods fail. θo over [0, 90°],
//! α over [α_min, 1], the light's elevation over [−90°, 90°], its distance over [1e-4, 1e4]
//! and its intensity up to 1e30 — on the CPU and on the GPU (lavapipe in CI): no NaN or
//! infinity, nothing negative, and no LTC light from below the horizon with clipping on.
//! Also the LUT sampler at and beyond the table's edges, the fitter on its hardest cells, and
//! light counts 0, 1 and the GPU buffer's maximum.

mod gpu_common;

use glam::DVec3;
use ltc_lab::brdf::{irradiance_scale, point_light_exact};
use ltc_lab::gpu::renderer::PlaneRenderer;
use ltc_lab::ltc::fit::{CellProblem, FitSettings, FitStrata};
use ltc_lab::ltc::lobe::Lobe;
use ltc_lab::ltc::lut::ALPHA_MIN;
use ltc_lab::ltc::lut::{Channel, Lut};
use ltc_lab::ltc::{Clipping, Normalization};
use ltc_lab::render::{Method, RenderSettings, View};
use ltc_lab::scene::{Camera, Light, Material, Plane, Scene};

fn sweep(lo: f64, hi: f64, n: usize) -> impl Iterator<Item = f64> + Clone {
    (0..n).map(move |k| lo + (hi - lo) * k as f64 / (n - 1) as f64)
}

fn log_sweep(lo: f64, hi: f64, n: usize) -> impl Iterator<Item = f64> + Clone {
    sweep(lo.ln(), hi.ln(), n).map(f64::exp)
}

/// 19 view angles × 13 roughnesses × 37 elevations × 8 azimuths × 9 distances × 4
/// intensities: 2.6 million light evaluations per path.
#[test]
fn cpu_sweep_is_finite_non_negative_and_dark_below_the_horizon() {
    let lut = Lut::embedded();
    let distances: Vec<f64> = log_sweep(1e-4, 1e4, 9).collect();
    let intensities = [1e-6, 1.0, 1e15, 1e30];
    let mut evaluations = 0usize;
    for theta in sweep(0.0, 90.0, 19) {
        let t = theta.to_radians();
        let v = DVec3::new(t.sin(), 0.0, t.cos());
        for alpha in log_sweep(ALPHA_MIN, 1.0, 13) {
            let pair = lut.ltc_pair(alpha, v);
            for elevation in sweep(-90.0, 90.0, 37) {
                for azimuth in sweep(0.0, 315.0, 8) {
                    let (el, az) = (f64::to_radians(elevation), f64::to_radians(azimuth));
                    let l = DVec3::new(el.cos() * az.cos(), el.cos() * az.sin(), el.sin());
                    let ltc = pair.ltc_lobes(l, 0.04, Clipping::BOTH, Normalization::Corrected);
                    for &d in &distances {
                        for &i in &intensities {
                            let exact = point_light_exact(
                                v.to_array(),
                                (l * d).to_array(),
                                i,
                                f64::INFINITY,
                                alpha,
                                0.04,
                            );
                            let e = irradiance_scale(i, d, f64::INFINITY);
                            let approx = [e * ltc.specular, e * ltc.diffuse];
                            for x in [exact.specular, exact.diffuse, approx[0], approx[1]] {
                                assert!(
                                    x.is_finite() && x >= 0.0,
                                    "{x} at θo={theta} α={alpha} el={elevation} d={d} I={i}"
                                );
                            }
                            if l.z <= 0.0 {
                                assert_eq!(
                                    approx,
                                    [0.0, 0.0],
                                    "LTC light from below at el={elevation}"
                                );
                            }
                            evaluations += 1;
                        }
                    }
                }
            }
        }
    }
    assert_eq!(evaluations, 19 * 13 * 37 * 8 * 9 * 4);
}

#[test]
fn lut_sampler_at_and_beyond_the_edges() {
    let lut = Lut::embedded();
    let (lo, hi): (Vec<f64>, Vec<f64>) = (0..Channel::COUNT)
        .map(|c| {
            lut.cells
                .iter()
                .map(|cell| f64::from(cell.0[c]))
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
                    (a.min(x), b.max(x))
                })
        })
        .unzip();
    for u in sweep(-1.0, 2.0, 61).chain([f64::NAN, f64::INFINITY, f64::NEG_INFINITY]) {
        for v in sweep(-1.0, 2.0, 61).chain([f64::NAN, 1e300]) {
            let s = lut.sample_uv(u, v);
            for c in 0..Channel::COUNT {
                // Bilinear weights are convex: a sample never leaves its channel's range.
                assert!(
                    s.0[c].is_finite() && s.0[c] >= lo[c] - 1e-12 && s.0[c] <= hi[c] + 1e-12,
                    "channel {c} at uv ({u}, {v}): {}",
                    s.0[c]
                );
            }
        }
    }
    for alpha in [-1.0, 0.0, 1e-12, ALPHA_MIN, 1.0, 5.0, f64::NAN] {
        for cos in [-1.0, 0.0, 1e-9, 1.0, 3.0, f64::NAN] {
            assert!(
                lut.sample(alpha, cos).0.iter().all(|x| x.is_finite()),
                "α={alpha} cos={cos}"
            );
        }
    }
}

#[test]
fn fitter_on_grazing_and_alpha_min_cells_is_finite_within_its_limit() {
    let settings = FitSettings {
        size: 64,
        ..FitSettings::default()
    };
    let strata = FitStrata::new(&settings);
    let n = settings.size;
    for lobe in Lobe::ALL {
        for (i, j) in [
            (0, 0),
            (0, n - 1),
            (1, n - 1),
            (n - 1, n - 1),
            (0, n / 2),
            (n / 2, n - 1),
        ] {
            let problem = CellProblem::new(lobe, i, j, &settings, &strata);
            let fit = problem.fit([1.0, 1.0, 0.0], &settings, &strata, |_, f| {
                assert!(f.is_finite());
                ltc_lab::ltc::nelder_mead::CONTINUE
            });
            assert!(fit.iterations <= settings.max_iterations);
            assert!(
                fit.objective.is_finite() && fit.objective >= 0.0,
                "{lobe:?} ({i}, {j}): {}",
                fit.objective
            );
            assert!(
                fit.ltc.det_cos_from_brdf.is_finite() && fit.ltc.det_cos_from_brdf > 0.0,
                "{lobe:?} ({i}, {j})"
            );
            assert!(fit.params.m.iter().all(|m| m.is_finite()));
        }
    }
}

fn gpu_scene(alpha: f64, camera_height: f64, lights: Vec<Light>) -> Scene {
    Scene {
        plane: Plane { half_size: 2.0 },
        material: Material {
            base_color: [0.8; 3],
            f0: 0.04,
            alpha,
            ..Material::default()
        },
        camera: Camera {
            position: [0.0, -3.0, camera_height],
            target: [0.0, 0.5, 0.0],
            fov_y_degrees: 60.0,
        },
        lights,
        random_lights: None,
        exposure: 1.0,
    }
}

/// Lights over a hemisphere-and-below around the plane's centre at every distance and
/// intensity of the sweep, seen from steep to grazing cameras, at α from α_min to 1.
#[test]
fn gpu_sweep_is_finite_non_negative_and_dark_below() {
    let Some(g) = gpu_common::gpu() else { return };
    let mut lights = Vec::new();
    for elevation in sweep(-90.0, 90.0, 13) {
        for d in log_sweep(1e-4, 1e4, 5) {
            for intensity in [1e-6, 1.0, 1e30] {
                let el = f64::to_radians(elevation);
                let p = DVec3::new(el.cos(), 0.3, el.sin()) * d;
                lights.push(Light {
                    position: p.to_array(),
                    color: [1.0, 0.6, 0.3],
                    intensity,
                    range: None,
                    shape: ltc_lab::light::Shape::of_radius(0.0),
                });
            }
        }
    }
    let mut r = g.renderer.lock().unwrap();
    for alpha in log_sweep(ALPHA_MIN, 1.0, 4) {
        for camera_height in [3.0, 0.5, 0.02] {
            let scene = gpu_scene(alpha, camera_height, lights.clone());
            for method in Method::F32 {
                let mut s = RenderSettings::single(32, 24, method);
                for view in [View::A, View::Diff] {
                    s.view = view;
                    let frame = r.render(&g.ctx, &scene, &s).unwrap().0;
                    for p in &frame.pixels {
                        assert!(
                            p.is_finite() && p.min_element() >= 0.0,
                            "{} {view:?} α={alpha} h={camera_height}: {p}",
                            method.name()
                        );
                    }
                }
            }
            // With clipping on, LTC light from below the plane only is exactly zero.
            let below: Vec<Light> = lights
                .iter()
                .filter(|l| l.position[2] < 0.0)
                .copied()
                .collect();
            let scene = gpu_scene(alpha, camera_height, below);
            for method in [Method::Ltc, Method::LtcFast] {
                let frame = r
                    .render(&g.ctx, &scene, &RenderSettings::single(32, 24, method))
                    .unwrap()
                    .0;
                assert!(
                    frame.pixels.iter().all(|p| *p == DVec3::ZERO),
                    "{} lit from below",
                    method.name()
                );
            }
        }
    }
}

/// Light counts 0, 1 and the maximum the device shades (`PlaneRenderer::max_lights`: the
/// storage buffer's capacity, or lavapipe's shader loop limit, 65 024 lights), capped at
/// 2²² so that a 2 GiB binding on a big GPU does not need 4 GB of host memory here. The
/// maximum must add up linearly; one more light is refused with a clear error.
#[test]
fn gpu_light_counts_zero_one_and_the_maximum() {
    let Some(g) = gpu_common::gpu() else { return };
    let max = PlaneRenderer::max_lights(&g.ctx).min(1 << 22);
    let mut r = g.renderer.lock().unwrap();
    let light = Light {
        position: [0.0, 0.0, 0.5],
        color: [1.0; 3],
        intensity: 1e-6,
        range: None,
        shape: ltc_lab::light::Shape::of_radius(0.0),
    };
    let brightest = |count: usize, r: &mut PlaneRenderer| {
        let scene = gpu_scene(0.27, 3.0, vec![light; count]);
        let frame = r
            .render(
                &g.ctx,
                &scene,
                &RenderSettings::single(4, 3, Method::LtcFast),
            )
            .unwrap()
            .0;
        assert!(
            frame
                .pixels
                .iter()
                .all(|p| p.is_finite() && p.min_element() >= 0.0),
            "{count} lights"
        );
        frame.pixels.iter().map(|p| p.x).fold(0.0, f64::max)
    };
    assert_eq!(brightest(0, &mut r), 0.0);
    let one = brightest(1, &mut r);
    assert!(one > 0.0);
    // Identical lights summed in f32: relative rounding up to count × 6e-8 (4e-3 at 65 000;
    // the sum of a 4M-light buffer would stall far earlier, hence the cap above).
    let many = brightest(max, &mut r);
    assert!(
        (many / one / max as f64 - 1.0).abs() < 1e-2,
        "{max} lights give {many}, one gives {one}"
    );
    if PlaneRenderer::max_lights(&g.ctx) < 1 << 22 {
        let err = PlaneRenderer::check_light_count(&g.ctx, PlaneRenderer::max_lights(&g.ctx) + 1)
            .unwrap_err();
        assert!(err.to_string().contains("lights do not fit"), "{err}");
    }
}
