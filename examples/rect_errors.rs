//! Rect lights, measured (docs/design.md §1.11): each LTC method's error against the exact
//! integral, by the rect's solid angle and the elevation of its centre, over views θo from 0
//! to 80° and roughnesses α 0.1 to 0.8, as the Markdown tables of the design notes.
//!
//! `cargo run --release --example rect_errors [CASES] [SEED]` (defaults 300 a cell and 7):
//! random square-to-oblong rects facing the point (tilted up to 45°), radiance 1, F0 0.04.
//! The exact integral's own error is measured too: 64 nodes a triangle against 128.

use glam::DVec3;
use ltc_lab::brdf::view_from_theta;
use ltc_lab::light::rect::{Rect, RectMethod, RectShading, rect_exact, rect_light};
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::{Clipping, Normalization};
use ltc_lab::scene::SplitMix64;

/// Solid angles of the rects (sr, approximately: `A cos θe / d²`).
const SIZES: [f64; 4] = [0.001, 0.01, 0.1, 1.0];

/// Elevation bands of the rect's centre, degrees; the first, [-5, 5], is across the horizon
/// for every size here.
const BANDS: [[f64; 2]; 4] = [[-5.0, 5.0], [5.0, 15.0], [15.0, 30.0], [30.0, 90.0]];

/// A rect of about `omega` sr facing the origin from the direction at `elevation`, `azimuth`.
fn rect(rng: &mut SplitMix64, omega: f64, elevation: f64, azimuth: f64) -> Rect {
    let (se, ce) = elevation.to_radians().sin_cos();
    let (sa, ca) = azimuth.to_radians().sin_cos();
    let centre = DVec3::new(ce * ca, ce * sa, se);
    let w = -centre;
    let a = if w.z.abs() < 0.9 { DVec3::Z } else { DVec3::X };
    let t1 = a.cross(w).normalize();
    let t2 = w.cross(t1);
    // A tilt of up to 45° about t1, and an aspect of 1 to 3.
    let tilt = rng.uniform([-45.0f64, 45.0]).to_radians();
    let t2 = t2 * tilt.cos() + w * tilt.sin();
    let normal = t1.cross(t2);
    let cos_e = normal.dot(w).abs();
    let aspect = rng.uniform([1.0, 3.0]);
    // Area A = 4 hu hv with hu = aspect · hv and A cos θe = omega (d = 1).
    let hv = (omega / cos_e / (4.0 * aspect)).sqrt();
    Rect {
        centre,
        u: t1 * (aspect * hv),
        v: t2 * hv,
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let cases: usize = args.next().map_or(Ok(300), |a| a.parse())?;
    let seed: u64 = args.next().map_or(Ok(7), |a| a.parse())?;
    let lut = Lut::embedded();
    let methods = &RectMethod::ALL[1..];
    let mut rng = SplitMix64(seed);
    let mut rows = Vec::new();
    let mut worst_rule: f64 = 0.0;
    for &omega in &SIZES {
        for band in BANDS {
            // Σ|method − exact| and Σ exact per lobe, per method.
            let mut err = vec![[0.0f64; 2]; methods.len()];
            let mut total = [0.0f64; 2];
            for _ in 0..cases {
                let theta_o = rng.uniform([0.0, 80.0]);
                let alpha = rng.uniform([0.1, 0.8]);
                let v = DVec3::from(view_from_theta(theta_o.to_radians()));
                let (elevation, azimuth) = (rng.uniform(band), rng.uniform([0.0, 360.0]));
                let r = rect(&mut rng, omega, elevation, azimuth);
                let pair = lut.ltc_pair(alpha, v);
                let s = RectShading {
                    v,
                    rect: r,
                    alpha,
                    f0: 0.04,
                    ltc: &pair,
                    clip: Clipping::BOTH,
                    normalization: Normalization::Corrected,
                };
                let exact = rect_light(RectMethod::Exact, &s);
                let finer = rect_exact(v, &r, alpha, 0.04, 128);
                for (x, y) in [
                    (exact.specular, finer.specular),
                    (exact.diffuse, finer.diffuse),
                ] {
                    if y > 1e-12 {
                        worst_rule = worst_rule.max((x - y).abs() / y);
                    }
                }
                total[0] += exact.specular;
                total[1] += exact.diffuse;
                for (e, &m) in err.iter_mut().zip(methods) {
                    let got = rect_light(m, &s);
                    e[0] += (got.specular - exact.specular).abs();
                    e[1] += (got.diffuse - exact.diffuse).abs();
                }
            }
            rows.push((omega, band, err, total));
        }
    }
    for (lobe, k) in [("specular", 0), ("diffuse", 1)] {
        println!("\n{lobe}: Σ|method − exact| / Σ exact, {cases} cases a cell, seed {seed}\n");
        let names: Vec<&str> = methods.iter().map(|m| m.name()).collect();
        println!(
            "| solid angle | centre's elevation | {} |",
            names.join(" | ")
        );
        println!("|---:|---|{}", "---:|".repeat(methods.len()));
        for (omega, band, err, total) in &rows {
            let cells: Vec<String> = err
                .iter()
                .map(|e| format!("{:.1}%", 100.0 * e[k] / total[k].max(1e-300)))
                .collect();
            println!(
                "| {omega} sr | {}–{}° | {} |",
                band[0],
                band[1],
                cells.join(" | ")
            );
        }
    }
    println!(
        "\nThe exact rule, 64 nodes a triangle against 128: worst relative difference {worst_rule:.1e}"
    );
    Ok(())
}
