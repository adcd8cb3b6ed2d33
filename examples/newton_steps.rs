//! How many Newton steps the shaders' `negative_eigenvalue` takes in f32 (docs/design.md
//! §1.10), by its two stopping rules: a step of 0 (the f64 reference's rule) and `f(x)` within
//! its own rounding (shaders/sphere_light.wgsl's). Caps of the benchmark's spheres (radius
//! 0.05 at 0.06–2 from the point, elevations 1–86°) under both lobes at α 0.27.
//! `cargo run --release --example newton_steps`.

use glam::{DMat3, DVec3};
use ltc_lab::light::sphere::cap::Cap;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::scene::SplitMix64;

/// Steps to a step of 0 and to the rounding rule, from det/c₁, in f32.
fn steps(q: DMat3, det: f64) -> (usize, usize) {
    let e = |r: usize, c: usize| q.col(c)[r] as f32;
    let det = det as f32;
    let trace = e(0, 0) + e(1, 1) + e(2, 2);
    let c1 = e(0, 0) * e(1, 1) - e(0, 1) * e(1, 0) + e(0, 0) * e(2, 2) - e(0, 2) * e(2, 0)
        + e(1, 1) * e(2, 2)
        - e(1, 2) * e(2, 1);
    let norm = (0..3)
        .map(|c| q.col(c).length_squared())
        .sum::<f64>()
        .sqrt() as f32;
    let (mut lo, mut hi) = (-norm, 0.0f32);
    let mut x = if c1 > 0.0 { det / c1 } else { 0.5 * lo };
    if !(x > lo && x < hi) {
        x = 0.5 * (lo + hi);
    }
    let mut rounding_rule = None;
    for k in 1..=64 {
        let fx = det - x * (c1 - x * (trace - x));
        let noise = 4.0
            * f32::EPSILON
            * (det.abs() + (x * c1).abs() + (x * x * trace).abs() + (x * x * x).abs());
        if fx.abs() <= noise {
            rounding_rule.get_or_insert(k);
        }
        if fx > 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let step = x - fx / (-c1 + x * (2.0 * trace - 3.0 * x));
        let next = if step > lo && step < hi {
            step
        } else {
            0.5 * (lo + hi)
        };
        if next == x {
            return (k, rounding_rule.unwrap_or(k));
        }
        x = next;
    }
    (64, rounding_rule.unwrap_or(64))
}

fn main() {
    let lut = Lut::embedded();
    let mut rng = SplitMix64(3);
    let (mut zero, mut rounding) = (vec![0usize; 65], vec![0usize; 65]);
    for _ in 0..20_000 {
        let theta_o: f64 = rng.uniform([0.0, 1.5]);
        let v = DVec3::new(theta_o.sin(), 0.0, theta_o.cos());
        let pair = lut.ltc_pair(0.27, v);
        let (el, az, d) = (
            rng.uniform([0.02, 1.5]),
            rng.uniform([0.0, std::f64::consts::TAU]),
            rng.uniform([0.06, 2.0]),
        );
        let u = DVec3::new(el.cos() * az.cos(), el.cos() * az.sin(), el.sin()) * d;
        let Some(cap) = Cap::of_sphere(u, 0.05).filter(|c| !c.encloses()) else {
            continue;
        };
        for ltc in [&pair.spec, &pair.diff] {
            let (t1, t2) = cap.axis.any_orthonormal_pair();
            let (s, c) = (cap.sin_sigma, cap.cos_sigma);
            let b = ltc.cos_from_brdf * DMat3::from_cols(t1 * s, t2 * s, cap.axis * c);
            let b_inv = b.inverse();
            let q = b_inv.transpose() * DMat3::from_diagonal(DVec3::new(1.0, 1.0, -1.0)) * b_inv;
            let (z, r) = steps(q, -1.0 / b.determinant().powi(2));
            zero[z] += 1;
            rounding[r] += 1;
        }
    }
    println!("steps | to a step of 0 | to f(x) within its rounding");
    for k in 0..=64 {
        if zero[k] + rounding[k] > 0 {
            println!("{k} | {} | {}", zero[k], rounding[k]);
        }
    }
}
