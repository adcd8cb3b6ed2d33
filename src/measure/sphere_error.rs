//! Lights with a size, measured (docs/design.md §4.9): each way of shading a sphere light
//! against the exact integral over its cap, by the sphere's angular radius and by the
//! elevation of its centre, over random views and roughnesses drawn as for point lights
//! (`horizon`): Σ|method − exact| / Σ exact per lobe.

use glam::DVec3;
use rayon::prelude::*;

use crate::brdf::{Alpha, Lobes, view_from_theta};
use crate::light::sphere::cap::Cap;
use crate::light::sphere::{SphereMethod, SphereShading, sphere_exact, sphere_light};
use crate::ltc::lut::{Lut, THETA_MAX};
use crate::measure::horizon::{BANDS, F0, draw};
use crate::scene::SplitMix64;

/// The angular radii measured, degrees: the point light itself, then from a light that is
/// nearly a point to one that fills a 60° cone (a bulb a hand's width from the surface).
pub const RADII_DEG: [f64; 7] = [0.0, 0.5, 2.0, 5.0, 10.0, 20.0, 30.0];

/// Nodes of the exact method in the measure: 32 keep the rule's error under 1e-4 of each
/// case's value (tests/lights/sphere_light.rs), far below the errors measured, at a quarter of
/// `sphere_light::EXACT_NODES`'s cost.
pub const MEASURE_NODES: usize = 32;

/// The approximations, in the order of `SphereError`'s columns.
pub const APPROXIMATIONS: [SphereMethod; 3] = [
    SphereMethod::LtcPoint,
    SphereMethod::LtcDisk,
    SphereMethod::RepresentativePoint,
];

/// One angular radius and elevation band.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereError {
    pub radius_deg: f64,
    /// The centre's elevation above the surface, degrees.
    pub band: [f64; 2],
    pub cases: usize,
    /// Σ|method − exact| / Σ exact of the specular lobe, per `APPROXIMATIONS`.
    pub specular: [f64; 3],
    /// The same of the diffuse lobe.
    pub diffuse: [f64; 3],
}

/// Each (radius, band)'s error with the LTCs of `lut` and eq. 30's rules, over `cases`
/// cases (seeded: a radius's cases are the same lights as point lights in `horizon`, so at a
/// small radius the figures meet §4.7's), the exact method with `nodes` nodes.
pub fn sphere_errors(
    lut: &Lut,
    radii_deg: &[f64],
    cases: usize,
    seed: u64,
    nodes: usize,
) -> Vec<SphereError> {
    errors_by_cell(lut, radii_deg, (cases, seed, nodes), None)
}

/// The same at one view and roughness (θo in degrees, α): the lights alone are drawn, as
/// `horizon::band_errors_at` draws them.
pub fn sphere_errors_at(
    lut: &Lut,
    (theta_o_deg, alpha): (f64, f64),
    radius_deg: f64,
    (cases, seed, nodes): (usize, u64, usize),
) -> Vec<SphereError> {
    errors_by_cell(
        lut,
        &[radius_deg],
        (cases, seed, nodes),
        Some((theta_o_deg, alpha)),
    )
}

fn errors_by_cell(
    lut: &Lut,
    radii_deg: &[f64],
    (cases, seed, nodes): (usize, u64, usize),
    at: Option<(f64, f64)>,
) -> Vec<SphereError> {
    let cells: Vec<(f64, usize)> = radii_deg
        .iter()
        .flat_map(|&r| (0..BANDS.len()).map(move |k| (r, k)))
        .collect();
    cells
        .par_iter()
        .map(|&(radius_deg, k)| {
            let mut rng = SplitMix64(seed.wrapping_add(k as u64));
            let mut sums = [0.0f64; 8];
            for _ in 0..cases {
                let (drawn_theta, drawn_alpha, l) = draw(&mut rng, BANDS[k]);
                let view = at.unwrap_or((drawn_theta, drawn_alpha));
                let (want, got) = one_sphere(lut, view, l, radius_deg, nodes);
                sums[0] += want.specular;
                sums[1] += want.diffuse;
                for (m, lobes) in got.iter().enumerate() {
                    sums[2 + m] += (lobes.specular - want.specular).abs();
                    sums[5 + m] += (lobes.diffuse - want.diffuse).abs();
                }
            }
            let ratio = |a: f64, b: f64| a / b.max(1e-300);
            SphereError {
                radius_deg,
                band: BANDS[k],
                cases,
                specular: [0, 1, 2].map(|m| ratio(sums[2 + m], sums[0])),
                diffuse: [0, 1, 2].map(|m| ratio(sums[5 + m], sums[1])),
            }
        })
        .collect()
}

/// A sphere of angular radius `radius_deg` at unit distance toward `l`, with unit intensity
/// and no window, at (θo in degrees, α): the exact lobes and each approximation's.
pub fn one_sphere(
    lut: &Lut,
    (theta_o, alpha): (f64, f64),
    l: DVec3,
    radius_deg: f64,
    nodes: usize,
) -> (Lobes<f64>, [Lobes<f64>; 3]) {
    let v = DVec3::from(view_from_theta(theta_o.to_radians().min(THETA_MAX)));
    let pair = lut.ltc_pair(alpha, v);
    let s = SphereShading::unit(v, l, radius_deg, Alpha::isotropic(alpha), F0, &pair);
    let want = match Cap::of_sphere(s.u, s.radius) {
        Some(cap) => sphere_exact(&s, &cap, nodes),
        None => sphere_light(SphereMethod::Exact, &s),
    };
    (want, APPROXIMATIONS.map(|m| sphere_light(m, &s)))
}

/// The figures as CSV rows
/// (`radius_deg,band,cases,method,specular,diffuse`), a method per row.
pub fn csv_rows(errors: &[SphereError]) -> String {
    let mut out = String::new();
    for e in errors {
        for (m, method) in APPROXIMATIONS.iter().enumerate() {
            out += &format!(
                "{},{}-{},{},{},{:.6},{:.6}\n",
                e.radius_deg,
                e.band[0],
                e.band[1],
                e.cases,
                method.name(),
                e.specular[m],
                e.diffuse[m]
            );
        }
    }
    out
}
