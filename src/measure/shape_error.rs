//! Rect and disk lights, measured (docs/design.md §1.11, §1.12): each LTC method's error
//! against the exact integral, by the light's solid angle and the elevation of its centre,
//! over views θo from 0 to 80° and roughnesses α 0.1 to 0.8 — Σ|method − exact| / Σ exact
//! per lobe. A rect and a disk of the same solid angle are drawn at the same place and tilt,
//! so the two shapes' methods are compared on the same lights. `lut --atlas` writes it
//! (`shapes.csv`, `shapes.png`); `examples/shape_errors.rs` prints the design notes' tables.

use glam::DVec3;
use rayon::prelude::*;

use crate::brdf::{Alpha, Lobes, view_from_theta};
use crate::light::EmitterShading;
use crate::light::disk::{Disk, DiskMethod, DiskShading, disk_exact, disk_light};
use crate::light::rect::form::tilted_frame;
use crate::light::rect::{Rect, RectMethod, RectShading, rect_exact, rect_light};
use crate::ltc::lut::Lut;
use crate::scene::SplitMix64;

/// Solid angles of the lights (sr, approximately: `A cos θe / d²`).
pub const SIZES: [f64; 4] = [0.001, 0.01, 0.1, 1.0];

/// Elevation bands of the light's centre, degrees; the first, [-5, 5], is across the horizon
/// for every size here.
pub const BANDS: [[f64; 2]; 4] = [[-5.0, 5.0], [5.0, 15.0], [15.0, 30.0], [30.0, 90.0]];

/// F0 of every case (a dielectric).
pub const F0: f64 = 0.04;

/// The rect methods measured (every one but the reference), in the columns' order.
pub const RECT_METHODS: [RectMethod; 4] = [
    RectMethod::LtcPolygon,
    RectMethod::LtcProxy,
    RectMethod::LtcProxyFast,
    RectMethod::LtcPoint,
];

/// The disk methods measured, in the columns' order.
pub const DISK_METHODS: [DiskMethod; 2] = [DiskMethod::LtcDisk, DiskMethod::LtcPoint];

/// One size and band: each shape's Σ|method − exact| / Σ exact per lobe (`[specular,
/// diffuse]`), and the exact rules' worst relative difference from twice their nodes.
#[derive(Clone, Debug, PartialEq)]
pub struct ShapeError {
    pub solid_angle: f64,
    pub band: [f64; 2],
    pub cases: usize,
    pub rects: [[f64; 2]; 4],
    pub disks: [[f64; 2]; 2],
    /// The exact rules against twice their nodes, on the same measure: Σ|rule − finer| /
    /// Σ finer over both lobes (rects, disks), where `finer` was asked for.
    pub rule: Option<[f64; 2]>,
}

/// A rect and a disk of about `omega` sr each, facing the origin from the direction at
/// `elevation`, `azimuth` (degrees), tilted alike: a tilt of up to 45° and an aspect of 1 to 3.
pub fn lights(rng: &mut SplitMix64, omega: f64, elevation: f64, azimuth: f64) -> (Rect, Disk) {
    let (se, ce) = elevation.to_radians().sin_cos();
    let (sa, ca) = azimuth.to_radians().sin_cos();
    let centre = DVec3::new(ce * ca, ce * sa, se);
    // The rect's plane and draws, `rect::form::error_sample`'s; the disk at the same tilt.
    let (t1, t2, cos_e) = tilted_frame(&mut |r| rng.uniform(r), centre);
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
        normal: t1.cross(t2),
        radius: (omega / cos_e / std::f64::consts::PI).sqrt(),
    };
    (rect, disk)
}

/// Every (size, band) cell over `cases` cases, seeded; the exact rules with `nodes` nodes,
/// and where `finer`, each also against `2 × nodes` (the rules' own error).
pub fn shape_errors(
    lut: &Lut,
    cases: usize,
    seed: u64,
    nodes: usize,
    finer: bool,
) -> Vec<ShapeError> {
    let cells: Vec<(usize, usize)> = (0..SIZES.len())
        .flat_map(|s| (0..BANDS.len()).map(move |b| (s, b)))
        .collect();
    cells
        .par_iter()
        .map(|&(s, b)| {
            cell(
                lut,
                (SIZES[s], BANDS[b]),
                (cases, seed, nodes, finer),
                s * 4 + b,
            )
        })
        .collect()
}

/// `|x − y|` summed over the two lobes, and `y` so summed.
fn apart(x: Lobes<f64>, y: Lobes<f64>) -> [f64; 2] {
    [
        (x.specular - y.specular).abs() + (x.diffuse - y.diffuse).abs(),
        y.specular + y.diffuse,
    ]
}

fn cell(
    lut: &Lut,
    (omega, band): (f64, [f64; 2]),
    (cases, seed, nodes, finer): (usize, u64, usize, bool),
    index: usize,
) -> ShapeError {
    let mut rng = SplitMix64(seed.wrapping_add(index as u64));
    // Σ|method − exact| per method and lobe, and Σ exact per lobe, per shape.
    let mut rect_err = [[0.0f64; 2]; 4];
    let mut disk_err = [[0.0f64; 2]; 2];
    let (mut rect_total, mut disk_total) = ([0.0f64; 2], [0.0f64; 2]);
    // Σ|rule − finer| and Σ finer, per shape.
    let mut rule = [[0.0f64; 2]; 2];
    let mut finer_by = |k: usize, x: Lobes<f64>, y: Lobes<f64>| {
        let [d, t] = apart(x, y);
        rule[k][0] += d;
        rule[k][1] += t;
    };
    let add = |err: &mut [f64; 2], got: Lobes<f64>, exact: Lobes<f64>| {
        err[0] += (got.specular - exact.specular).abs();
        err[1] += (got.diffuse - exact.diffuse).abs();
    };
    for _ in 0..cases {
        let theta_o = rng.uniform([0.0, 80.0]);
        let alpha = rng.uniform([0.1, 0.8]);
        let v = DVec3::from(view_from_theta(theta_o.to_radians()));
        let (elevation, azimuth) = (rng.uniform(band), rng.uniform([0.0, 360.0]));
        let (rect, disk) = lights(&mut rng, omega, elevation, azimuth);
        let pair = lut.ltc_pair(alpha, v);
        let s = RectShading {
            pixel: EmitterShading::corrected(v, Alpha::isotropic(alpha), F0, &pair),
            rect,
        };
        let exact = rect_exact(v, &rect, Alpha::isotropic(alpha), F0, nodes);
        if finer {
            finer_by(
                0,
                exact,
                rect_exact(v, &rect, Alpha::isotropic(alpha), F0, 2 * nodes),
            );
        }
        rect_total[0] += exact.specular;
        rect_total[1] += exact.diffuse;
        for (e, &m) in rect_err.iter_mut().zip(&RECT_METHODS) {
            add(e, rect_light(m, &s), exact);
        }
        let s = DiskShading {
            pixel: EmitterShading::corrected(v, Alpha::isotropic(alpha), F0, &pair),
            disk,
        };
        let exact = disk_exact(v, &disk, Alpha::isotropic(alpha), F0, nodes);
        if finer {
            finer_by(
                1,
                exact,
                disk_exact(v, &disk, Alpha::isotropic(alpha), F0, 2 * nodes),
            );
        }
        disk_total[0] += exact.specular;
        disk_total[1] += exact.diffuse;
        for (e, &m) in disk_err.iter_mut().zip(&DISK_METHODS) {
            add(e, disk_light(m, &s), exact);
        }
    }
    let ratio = |e: [f64; 2], t: [f64; 2]| [0, 1].map(|k| e[k] / t[k].max(1e-300));
    ShapeError {
        solid_angle: omega,
        band,
        cases,
        rects: rect_err.map(|e| ratio(e, rect_total)),
        disks: disk_err.map(|e| ratio(e, disk_total)),
        rule: finer.then_some(rule.map(|[d, t]| d / t.max(1e-300))),
    }
}

/// The figures as CSV rows (`solid_angle_sr,band,cases,shape,method,specular,diffuse`), a
/// method per row; the band as `lo..hi` degrees (its first is below 0: `-5..5`).
pub fn csv_rows(errors: &[ShapeError]) -> String {
    let mut out = String::new();
    for e in errors {
        let rows = RECT_METHODS
            .iter()
            .map(|m| ("rect", m.name()))
            .zip(e.rects)
            .chain(DISK_METHODS.iter().map(|m| ("disk", m.name())).zip(e.disks));
        for ((shape, method), [specular, diffuse]) in rows {
            out += &format!(
                "{},{}..{},{},{shape},{method},{specular:.6},{diffuse:.6}\n",
                e.solid_angle, e.band[0], e.band[1], e.cases
            );
        }
    }
    out
}
