//! Ground truth for the tests: deterministic f64 quadrature over the sphere, independent of
//! the sampling code under test.
#![allow(dead_code)]

use std::f64::consts::PI;

use glam::{DMat3, DVec3};

/// `∫ f(ω) dω` over the whole sphere, by the midpoint rule in (t, φ) around `centre`, with
/// polar angle `θ = π t³` so that samples crowd toward `centre` where peaked integrands
/// (narrow lobes) live: the angular step near the centre is ~3π t² / n, i.e. it resolves a
/// lobe of width w with n ≳ (π / w)^(1/3) · n_φ-independent sampling. `n` steps in t, `2n`
/// in φ.
pub fn sphere_integral(centre: DVec3, n: usize, f: impl Fn(DVec3) -> f64) -> f64 {
    let z = centre.normalize();
    let x = if z.x.abs() < 0.9 { DVec3::X } else { DVec3::Y };
    let x = (x - z * z.dot(x)).normalize();
    let frame = DMat3::from_cols(x, z.cross(x), z);
    let n_phi = 2 * n;
    let dphi = std::f64::consts::TAU / n_phi as f64;
    let mut sum = 0.0;
    for i in 0..n {
        let t = (i as f64 + 0.5) / n as f64;
        let theta = std::f64::consts::PI * t * t * t;
        let dtheta = 3.0 * std::f64::consts::PI * t * t / n as f64;
        let (st, ct) = theta.sin_cos();
        let mut ring = 0.0;
        for k in 0..n_phi {
            let phi = (k as f64 + 0.5) * dphi;
            let w = frame * DVec3::new(st * phi.cos(), st * phi.sin(), ct);
            ring += f(w);
        }
        sum += ring * st * dtheta * dphi;
    }
    sum
}

/// The mirror direction of `v` about `+z`, where a specular lobe peaks.
pub fn mirror(v: DVec3) -> DVec3 {
    DVec3::new(-v.x, -v.y, v.z)
}

/// `(sin θ, 0, cos θ)`.
pub fn view(theta_degrees: f64) -> DVec3 {
    let t = theta_degrees.to_radians();
    DVec3::new(t.sin(), 0.0, t.cos())
}

/// A black spot: a pixel the exact integral lights (above 5% of the image's mean) that a
/// method leaves at under 1e-3 of that — ltc_code's artifact, where its cubic's NaN turned a
/// lit pixel black. Where the lab's methods are wrong they are wrong by tens of percent
/// (docs/design.md §1.10's and §1.11's tables), not by a factor of a thousand.
pub fn black_spots(frame: &ltc_lab::render::Frame, exact: &ltc_lab::render::Frame) -> usize {
    use ltc_lab::metrics::luminance;
    let mean = exact.pixels.iter().map(|&p| luminance(p)).sum::<f64>() / exact.pixels.len() as f64;
    frame
        .pixels
        .iter()
        .zip(&exact.pixels)
        .filter(|&(&x, &y)| luminance(y) > 0.05 * mean && luminance(x) < 1e-3 * luminance(y))
        .count()
}

/// Parses and validates WGSL with naga (every capability allowed: an export's own checks
/// are for its consumer's device), panicking with naga's report naming `what`.
pub fn validate_wgsl(src: &str, what: &str) {
    let module = naga::front::wgsl::parse_str(src)
        .unwrap_or_else(|e| panic!("{what} does not parse:\n{}", e.emit_to_string(src)));
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::all(),
    )
    .validate(&module)
    .unwrap_or_else(|e| panic!("{what} does not validate:\n{}", e.emit_to_string(src)));
}

/// `∫ g(ω) dω` over the directions that meet a capsule (`tube`), above the surface, as an integral over its
/// front-facing surface by the midpoint rule, `n × n` cells on the cylinder and on each end's
/// half sphere. The integrand is continuous (`g` carries the cosine, which is 0 at the
/// horizon; `−n·ω` is 0 on the silhouette), so the rule's error falls as `1/n²`.
pub fn capsule_integral(
    tube: &ltc_lab::light::tube::Tube,
    n: usize,
    g: impl Fn(DVec3) -> f64,
) -> f64 {
    let e = tube.axis();
    let (u1, u2) = e.any_orthonormal_pair();
    let r = tube.radius;
    let weight = |y: DVec3, normal: DVec3| {
        let d2 = y.length_squared();
        let w = y / d2.sqrt();
        let facing = -normal.dot(w);
        if facing <= 0.0 || w.z <= 0.0 {
            0.0
        } else {
            g(w) * facing / d2
        }
    };
    let h = 1.0 / n as f64;
    let mut total = 0.0;
    for i in 0..n {
        let phi = 2.0 * PI * (i as f64 + 0.5) * h;
        let radial = u1 * phi.cos() + u2 * phi.sin();
        for j in 0..n {
            let s = tube.length() * (j as f64 + 0.5) * h;
            total +=
                weight(tube.a + e * s + radial * r, radial) * r * tube.length() * 2.0 * PI * h * h;
            let theta = 0.5 * PI * (j as f64 + 0.5) * h;
            let area = r * r * theta.sin() * 0.5 * PI * 2.0 * PI * h * h;
            for (end, outward) in [(tube.a, -e), (tube.b, e)] {
                let m = outward * theta.cos() + radial * theta.sin();
                total += weight(end + m * r, m) * area;
            }
        }
    }
    total
}
