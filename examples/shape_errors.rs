//! Rect and disk lights, measured (docs/design.md §1.11, §1.12): each LTC method's error
//! against the exact integral, by the light's solid angle and the elevation of its centre,
//! over views θo from 0 to 80° and roughnesses α 0.1 to 0.8, as the Markdown tables of the
//! design notes.
//!
//! `cargo run --release --example shape_errors [CASES] [SEED]` (defaults 300 a cell and 7):
//! random square-to-oblong rects facing the point (tilted up to 45°) and, at the same place
//! and tilt, disks of the same solid angle; radiance 1, F0 0.04. The exact integrals' own
//! error is measured too: 64 nodes a triangle (a piece) against 128.

use glam::DVec3;
use ltc_lab::brdf::{Lobes, view_from_theta};
use ltc_lab::light::disk::{Disk, DiskMethod, DiskShading, disk_exact, disk_light};
use ltc_lab::light::rect::{Rect, RectMethod, RectShading, rect_exact, rect_light};
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::{Clipping, LtcPair, Normalization};
use ltc_lab::scene::SplitMix64;

/// Solid angles of the lights (sr, approximately: `A cos θe / d²`).
const SIZES: [f64; 4] = [0.001, 0.01, 0.1, 1.0];

/// Elevation bands of the light's centre, degrees; the first, [-5, 5], is across the horizon
/// for every size here.
const BANDS: [[f64; 2]; 4] = [[-5.0, 5.0], [5.0, 15.0], [15.0, 30.0], [30.0, 90.0]];

/// A rect and a disk of about `omega` sr each, facing the origin from the direction at
/// `elevation`, `azimuth`, tilted alike.
fn lights(rng: &mut SplitMix64, omega: f64, elevation: f64, azimuth: f64) -> (Rect, Disk) {
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
    // Area A = 4 hu hv with hu = aspect · hv and A cos θe = omega (d = 1); a disk's π r².
    let hv = (omega / cos_e / (4.0 * aspect)).sqrt();
    let rect = Rect {
        centre,
        u: t1 * (aspect * hv),
        v: t2 * hv,
    };
    let disk = Disk {
        centre,
        normal,
        radius: (omega / cos_e / std::f64::consts::PI).sqrt(),
    };
    (rect, disk)
}

/// One shape's sums over a cell: Σ|method − exact| per method and lobe, Σ exact per lobe.
struct Cell {
    err: Vec<[f64; 2]>,
    total: [f64; 2],
}

impl Cell {
    fn new(methods: usize) -> Self {
        Self {
            err: vec![[0.0; 2]; methods],
            total: [0.0; 2],
        }
    }

    fn add(&mut self, exact: Lobes<f64>, methods: impl Iterator<Item = Lobes<f64>>) {
        self.total[0] += exact.specular;
        self.total[1] += exact.diffuse;
        for (e, got) in self.err.iter_mut().zip(methods) {
            e[0] += (got.specular - exact.specular).abs();
            e[1] += (got.diffuse - exact.diffuse).abs();
        }
    }
}

/// The worst relative difference of `rule` from `finer` so far, per lobe where it is not 0.
fn worst(w: &mut f64, rule: Lobes<f64>, finer: Lobes<f64>) {
    for (x, y) in [
        (rule.specular, finer.specular),
        (rule.diffuse, finer.diffuse),
    ] {
        if y > 1e-12 {
            *w = w.max((x - y).abs() / y);
        }
    }
}

fn print(shape: &str, names: &[&str], rows: &[(f64, [f64; 2], Cell)], cases: usize, seed: u64) {
    for (lobe, k) in [("specular", 0), ("diffuse", 1)] {
        println!(
            "\n{shape}, {lobe}: Σ|method − exact| / Σ exact, {cases} cases a cell, seed {seed}\n"
        );
        println!(
            "| solid angle | centre's elevation | {} |",
            names.join(" | ")
        );
        println!("|---:|---|{}", "---:|".repeat(names.len()));
        for (omega, band, cell) in rows {
            let cells: Vec<String> = cell
                .err
                .iter()
                .map(|e| format!("{:.1}%", 100.0 * e[k] / cell.total[k].max(1e-300)))
                .collect();
            println!(
                "| {omega} sr | {}–{}° | {} |",
                band[0],
                band[1],
                cells.join(" | ")
            );
        }
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let cases: usize = args.next().map_or(Ok(300), |a| a.parse())?;
    let seed: u64 = args.next().map_or(Ok(7), |a| a.parse())?;
    let lut = Lut::embedded();
    let rect_methods = &RectMethod::ALL[1..];
    let disk_methods = &DiskMethod::ALL[1..];
    let mut rng = SplitMix64(seed);
    let (mut rect_rows, mut disk_rows) = (Vec::new(), Vec::new());
    let (mut rect_rule, mut disk_rule) = (0.0f64, 0.0f64);
    for &omega in &SIZES {
        for band in BANDS {
            let mut rects = Cell::new(rect_methods.len());
            let mut disks = Cell::new(disk_methods.len());
            for _ in 0..cases {
                let theta_o = rng.uniform([0.0, 80.0]);
                let alpha = rng.uniform([0.1, 0.8]);
                let v = DVec3::from(view_from_theta(theta_o.to_radians()));
                let (elevation, azimuth) = (rng.uniform(band), rng.uniform([0.0, 360.0]));
                let (rect, disk) = lights(&mut rng, omega, elevation, azimuth);
                let pair: LtcPair = lut.ltc_pair(alpha, v);
                let (clip, normalization) = (Clipping::BOTH, Normalization::Corrected);
                let s = RectShading {
                    v,
                    rect,
                    alpha,
                    f0: 0.04,
                    ltc: &pair,
                    clip,
                    normalization,
                };
                let exact = rect_light(RectMethod::Exact, &s);
                worst(
                    &mut rect_rule,
                    exact,
                    rect_exact(v, &rect, alpha, 0.04, 128),
                );
                rects.add(exact, rect_methods.iter().map(|&m| rect_light(m, &s)));
                let s = DiskShading {
                    v,
                    disk,
                    alpha,
                    f0: 0.04,
                    ltc: &pair,
                    clip,
                    normalization,
                };
                let exact = disk_light(DiskMethod::Exact, &s);
                worst(
                    &mut disk_rule,
                    exact,
                    disk_exact(v, &disk, alpha, 0.04, 128),
                );
                disks.add(exact, disk_methods.iter().map(|&m| disk_light(m, &s)));
            }
            rect_rows.push((omega, band, rects));
            disk_rows.push((omega, band, disks));
        }
    }
    let rect_names: Vec<&str> = rect_methods.iter().map(|m| m.name()).collect();
    let disk_names: Vec<&str> = disk_methods.iter().map(|m| m.name()).collect();
    print("rects", &rect_names, &rect_rows, cases, seed);
    print("disks", &disk_names, &disk_rows, cases, seed);
    println!(
        "\nThe exact rules, 64 nodes against 128: worst relative difference {rect_rule:.1e} (rects), {disk_rule:.1e} (disks)"
    );
    Ok(())
}
