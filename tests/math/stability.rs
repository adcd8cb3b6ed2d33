//! Stability, property-based: no NaN or infinity and nothing negative — in the exact BRDF,
//! the LTC path and the renderer — for θo up to 90°, α from α_min to 1, lights on the
//! horizon, below the surface, at the shading point, extremely far and extremely bright.

use glam::DVec3;
use ltc_lab::brdf::{brdf_cos, point_light_exact};
use ltc_lab::cpu::render;
use ltc_lab::ltc::lut::ALPHA_MIN;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::{Clipping, Normalization};
use ltc_lab::render::{Method, RenderSettings, View};
use ltc_lab::scene::{Camera, Light, Material, Plane, Scene};
use proptest::prelude::*;

fn theta_o() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(0.0),
        Just(90.0f64.to_radians()),
        0.0f64..=90.0f64.to_radians()
    ]
}

fn alpha() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(ALPHA_MIN),
        Just(1.0),
        (ALPHA_MIN.ln()..=0.0).prop_map(f64::exp)
    ]
}

/// Light elevations in [−90°, 90°], with the horizon and the poles themselves.
fn elevation() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(0.0),
        Just(-90.0),
        Just(90.0),
        Just(1e-9),
        Just(-1e-9),
        -90.0f64..=90.0
    ]
    .prop_map(f64::to_radians)
}

/// Distances from the shading point to the light: at it, next to it, far away.
fn distance() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(0.0),
        Just(1e-300),
        Just(1e-9),
        Just(1e4),
        (1e-4f64.ln()..=1e4f64.ln()).prop_map(f64::exp)
    ]
}

fn intensity() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(0.0),
        Just(1e30),
        (1e-6f64.ln()..=1e30f64.ln()).prop_map(f64::exp)
    ]
}

fn direction(elevation: f64, azimuth: f64) -> DVec3 {
    DVec3::new(
        elevation.cos() * azimuth.cos(),
        elevation.cos() * azimuth.sin(),
        elevation.sin(),
    )
}

fn ok(x: f64) -> bool {
    x.is_finite() && x >= 0.0
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn exact_brdf_is_finite_and_non_negative(t in theta_o(), a in alpha(), e in elevation(),
            az in 0.0f64..std::f64::consts::TAU, f0 in 0.0f64..=1.0, d in distance(), i in intensity(),
            range in prop_oneof![Just(f64::INFINITY), 1e-3f64..1e3]) {
        let v = [t.sin(), 0.0, t.cos()];
        let l = direction(e, az);
        let b = brdf_cos(v, l.to_array(), a, f0);
        prop_assert!(ok(b.specular) && ok(b.diffuse), "{b:?}");
        let b32 = brdf_cos(v.map(|x| x as f32), l.as_vec3().to_array(), a as f32, f0 as f32);
        prop_assert!(ok(f64::from(b32.specular)) && ok(f64::from(b32.diffuse)), "{b32:?}");
        let r = point_light_exact(v, (l * d).to_array(), i, range, a, f0);
        prop_assert!(ok(r.specular) && ok(r.diffuse), "{r:?} at d={d} I={i}");
    }

    #[test]
    fn ltc_path_is_finite_and_non_negative(t in theta_o(), a in alpha(), e in elevation(),
            az in 0.0f64..std::f64::consts::TAU, f0 in 0.0f64..=1.0) {
        for lut in [Lut::embedded(), Lut::embedded_point()] {
        let v = DVec3::new(t.sin(), 0.0, t.cos());
        let pair = lut.ltc_pair(a, v);
        let l = direction(e, az);
        for n in [Normalization::Corrected, Normalization::PaperLiteral] {
            let x = pair.ltc_lobes(l, f0, Clipping::BOTH, n);
            prop_assert!(ok(x.specular) && ok(x.diffuse), "{x:?}");
            if l.z <= 0.0 {
                // The horizon rule: nothing from below the surface.
                prop_assert!(x.specular == 0.0 && x.diffuse == 0.0);
            }
        }
        // Without clipping values may be negative (case 2), but never NaN or infinite.
        let x = pair.ltc_lobes(l, f0, Clipping::NONE, Normalization::Corrected);
        prop_assert!(x.specular.is_finite() && x.diffuse.is_finite());
        }
    }
}

fn light() -> impl Strategy<Value = Light> {
    let coordinate = prop_oneof![Just(0.0), Just(1e4), Just(-1e4), -3.0f64..3.0];
    let height = prop_oneof![
        Just(0.0),
        Just(-0.158731),
        Just(1e-9),
        Just(-1e-9),
        Just(1e4),
        -1.0f64..2.0
    ];
    (
        coordinate.clone(),
        coordinate,
        height,
        intensity(),
        prop_oneof![Just(None), (1e-3f64..10.0).prop_map(Some)],
    )
        .prop_map(|(x, y, z, intensity, range)| Light {
            position: [x, y, z],
            color: [1.0, 0.5, 0.25],
            intensity,
            range,
            shape: ltc_lab::light::Shape::of_radius(0.0),
        })
}

fn scene(alpha: f64, lights: Vec<Light>) -> Scene {
    Scene {
        plane: Plane { half_size: 2.0 },
        material: Material {
            base_color: [0.8, 0.8, 0.8],
            f0: 0.04,
            alpha,
            ..Material::default()
        },
        // A low camera, so that the far plane is seen at grazing angles.
        camera: Camera {
            position: [0.0, -3.0, 0.3],
            target: [0.0, 1.0, 0.0],
            fov_y_degrees: 60.0,
        },
        lights,
        random_lights: None,
        exposure: 1.0,
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn renderer_is_finite_and_non_negative(a in alpha(), lights in proptest::collection::vec(light(), 0..4)) {
        let s = scene(a, lights);
        let lut = Lut::embedded();
        for view in [View::A, View::B, View::Split, View::Diff] {
            let frame = render(&s, lut, &RenderSettings::compare(12, 12, view));
            for p in &frame.pixels {
                prop_assert!(ok(p.x) && ok(p.y) && ok(p.z), "{view:?}: {p:?}");
            }
        }
    }

    #[test]
    fn lights_below_the_plane_light_nothing_with_clipping(a in alpha(), x in -2.0f64..2.0,
            y in -2.0f64..2.0, depth in prop_oneof![Just(0.158731), 1e-9f64..10.0]) {
        let s = scene(a, vec![Light { position: [x, y, -depth], color: [1.0; 3], intensity: 1e3, range: None, shape: ltc_lab::light::Shape::of_radius(0.0) }]);
        for method in [Method::Brdf, Method::Ltc] {
            let frame = render(&s, Lut::embedded(), &RenderSettings::single(10, 10, method));
            prop_assert!(frame.pixels.iter().all(|p| *p == DVec3::ZERO), "{method:?}");
        }
    }
}
