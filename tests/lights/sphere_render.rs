//! Lights with a size in renders (the CPU reference, src/cpu/mod.rs): a radius of zero changes
//! nothing, a shrinking sphere becomes its point light in every method, bad radii are refused
//! by name, and the failure presets give finite, non-negative images without black spots.

use crate::common::black_spots;
use ltc_lab::cpu::render;
use ltc_lab::light::sphere::SphereMethod;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::metrics::luminance;
use ltc_lab::render::{Frame, Method, RenderSettings};
use ltc_lab::scene::{MIN_RADIUS, PRESETS, SPHERE_PRESETS, Scene, preset};

const W: usize = 48;
const H: usize = 40;

fn side(method: Method, sphere: SphereMethod) -> RenderSettings {
    RenderSettings {
        a: ltc_lab::render::ShapeMethods::approximations()
            .with(method)
            .with(sphere),
        ..RenderSettings::single(W, H, method)
    }
}

/// paper-100 with a few of its lights, each given `radius`.
fn sized(radius: f64) -> Scene {
    let mut s = preset("paper-100");
    s.lights.truncate(12);
    for l in &mut s.lights {
        l.shape = ltc_lab::light::Shape::of_radius(radius);
    }
    s
}

#[test]
fn a_radius_of_zero_changes_nothing() {
    // Written out, a point light has no radius line: saved scenes and links stay as they were.
    for (name, _) in PRESETS {
        assert!(!preset(name).to_toml().contains("radius"), "{name}");
    }
    let text = |extra: &str| {
        format!(
            "[plane]\nhalf_size = 2.0\n[material]\nbase_color = [0.5, 0.5, 0.5]\nf0 = 0.04\nalpha = 0.27\n[camera]\nposition = [0.0, -3.4, 2.8]\ntarget = [0.0, -0.1, 0.0]\nfov_y_degrees = 40.0\n[[lights]]\nposition = [0.2, 0.1, 0.3]\nintensity = 0.2\n{extra}"
        )
    };
    let plain = Scene::from_toml(&text(""), "plain").unwrap();
    let zero = Scene::from_toml(&text("radius = 0.0\n"), "zero").unwrap();
    assert_eq!(plain, zero);
    // Whatever the sphere methods, a point light is shaded by the side's point method alone.
    for method in [Method::Brdf, Method::Ltc] {
        let point = render(
            &plain,
            Lut::embedded(),
            &RenderSettings::single(W, H, method),
        );
        for sphere in SphereMethod::ALL {
            let s = side(method, sphere);
            assert_eq!(
                render(&zero, Lut::embedded(), &s),
                point,
                "{}",
                sphere.name()
            );
        }
    }
}

/// The largest difference between two radiance frames per pixel, relative to the reference's
/// pixel (floored at 1% of its mean luminance, where a pixel is near black).
fn relative_per_pixel(a: &Frame, reference: &Frame) -> f64 {
    let mean =
        reference.pixels.iter().map(|&p| luminance(p)).sum::<f64>() / reference.pixels.len() as f64;
    a.pixels
        .iter()
        .zip(&reference.pixels)
        .map(|(&x, &y)| (luminance(x) - luminance(y)).abs() / luminance(y).max(0.01 * mean))
        .fold(0.0, f64::max)
}

/// At the smallest radius (1e-4, σ ≤ 2e-3 rad at paper-100's nearest light, 0.05 away) every
/// method is its point light, per pixel: ltc-point is the paper's formula itself (its factors
/// multiplied in another order: f64 rounding, 1e-12); the LTC disk and the cap integral differ
/// from the value at the centre by O(σ²) of the lobe's curvature (α = 0.27: (σ/α)² ≈ 6e-5,
/// 1e-3 holds it); the representative point's energy normalization (α/α')², α' = α + r/2d,
/// lowers the specular lobe by about r/(α d) ≤ 1e-4/(0.27 · 0.05) = 7.4e-3 (1e-2 holds it).
#[test]
fn a_shrinking_sphere_becomes_its_point_light_in_every_method() {
    let (points, spheres) = (sized(0.0), sized(MIN_RADIUS));
    let lut = Lut::embedded();
    let ltc = render(&points, lut, &RenderSettings::single(W, H, Method::Ltc));
    let exact = render(&points, lut, &RenderSettings::single(W, H, Method::Brdf));
    for (sphere, point, tol) in [
        (SphereMethod::LtcPoint, &ltc, 1e-12),
        (SphereMethod::LtcDisk, &ltc, 1e-3),
        (SphereMethod::Exact, &exact, 1e-3),
        (SphereMethod::RepresentativePoint, &exact, 1e-2),
    ] {
        let frame = render(&spheres, lut, &side(Method::Ltc, sphere));
        let d = relative_per_pixel(&frame, point);
        assert!(d <= tol, "{}: {d:e}", sphere.name());
    }
    // A real size does change the picture (the comparison above could not pass vacuously).
    let big = render(&sized(0.2), lut, &side(Method::Ltc, SphereMethod::Exact));
    assert!(relative_per_pixel(&big, &exact) > 0.05);
}

#[test]
fn bad_radii_are_refused_by_name() {
    let base = "[plane]\nhalf_size = 2.0\n[material]\nbase_color = [0.5, 0.5, 0.5]\nf0 = 0.04\nalpha = 0.27\n[camera]\nposition = [0.0, -3.4, 2.8]\ntarget = [0.0, -0.1, 0.0]\nfov_y_degrees = 40.0\n";
    for bad in ["nan", "-0.1", "1e-5", "1e7", "inf"] {
        let text = format!(
            "{base}[[lights]]\nposition = [0.0, 0.0, 1.0]\nintensity = 1.0\nradius = {bad}\n"
        );
        let e = Scene::from_toml(&text, "s.toml").unwrap_err().to_string();
        assert!(e.contains("lights[0].radius"), "{bad}: {e}");
        let text = format!(
            "{base}[random_lights]\ncount = 2\nseed = 1\nheight = [0.1, 1.0]\nintensity = [1.0, 2.0]\nradius = {bad}\n"
        );
        let e = Scene::from_toml(&text, "s.toml").unwrap_err().to_string();
        assert!(e.contains("random_lights.radius"), "{bad}: {e}");
    }
}

#[test]
fn the_failure_presets_give_finite_non_negative_images_without_black_spots() {
    let lut = Lut::embedded();
    for (name, _) in SPHERE_PRESETS {
        let scene = preset(name);
        assert!(
            scene
                .lights
                .iter()
                .all(|l| l.shape != ltc_lab::light::Shape::Point),
            "{name}"
        );
        let exact = render(&scene, lut, &side(Method::Brdf, SphereMethod::Exact));
        for sphere in SphereMethod::ALL {
            let s = side(Method::Ltc, sphere);
            let frame = render(&scene, lut, &s);
            let what = format!("{name} {}", sphere.name());
            assert_eq!(frame.first_invalid(s.rules.clipping), None, "{what}");
            if sphere != SphereMethod::LtcPoint {
                // The point formula does leave lit pixels black: under a sphere cut by the
                // horizon its centre is below the surface.
                assert_eq!(black_spots(&frame, &exact), 0, "{what}");
            }
        }
    }
}
