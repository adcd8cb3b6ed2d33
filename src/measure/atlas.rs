//! The error atlas: where the LTC fails for point lights. Heat maps of the table's `err`
//! channels over (r, θo), and the error of one light orbiting a shading point as a function
//! of its elevation and azimuth, for chosen (θo, α); with CSVs of both. And for lights with a
//! size, each method's error by angular radius and elevation band (docs/design.md §4.9).

use std::path::Path;

use glam::DVec3;

use crate::brdf::brdf_cos;
use crate::error::Result;
use crate::files::Outputs;
use crate::ltc::lut::{Channel, Lut};
use crate::ltc::remedy::Horizon;
use crate::ltc::{Clipping, Normalization};
use crate::measure::horizon;

/// The (θo in degrees, α) pairs whose orbit maps the atlas draws: a smooth surface seen from
/// near normal to grazing, and the paper's α = 0.27 at a steep view.
pub const ORBITS: [(f64, f64); 4] = [(20.0, 0.1), (45.0, 0.27), (70.0, 0.27), (85.0, 0.5)];

/// Steps of the orbit grid: 2° in elevation (−90..90), 4° in azimuth (0..360).
const ELEVATIONS: usize = 91;
const AZIMUTHS: usize = 91;

/// F0 of the orbit maps (a dielectric).
const ORBIT_F0: f64 = 0.04;

/// One direction of an orbit: the exact and LTC radiance of a unit-irradiance light there
/// (base colour 1, F0 = 0.04, both clipping rules) and their relative difference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrbitSample {
    pub elevation_deg: f64,
    pub azimuth_deg: f64,
    pub brdf: f64,
    pub ltc: f64,
    pub rel_err: f64,
}

/// The orbit of one light around a point seen at θo on a surface of roughness α. The
/// relative difference is taken over `max(brdf, 1% of the orbit's brightest)`, the floor
/// of `metrics::RELATIVE_FLOOR` in spirit: directions that barely light the point would
/// otherwise dominate with huge ratios of tiny numbers.
pub fn orbit(lut: &Lut, theta_o_deg: f64, alpha: f64) -> Vec<OrbitSample> {
    let t = theta_o_deg.to_radians().min(crate::ltc::lut::THETA_MAX);
    let v = DVec3::new(t.sin(), 0.0, t.cos());
    let pair = lut.ltc_pair(alpha, v);
    let mut samples: Vec<OrbitSample> = (0..ELEVATIONS)
        .flat_map(|e| (0..AZIMUTHS).map(move |a| (e, a)))
        .map(|(e, a)| {
            let elevation = -90.0 + 180.0 * e as f64 / (ELEVATIONS - 1) as f64;
            let azimuth = 360.0 * a as f64 / (AZIMUTHS - 1) as f64;
            let (el, az) = (elevation.to_radians(), azimuth.to_radians());
            let l = DVec3::new(el.cos() * az.cos(), el.cos() * az.sin(), el.sin());
            let exact = brdf_cos(v.to_array(), l.to_array(), alpha, ORBIT_F0);
            let approx = pair.ltc_lobes(l, ORBIT_F0, Clipping::BOTH, Normalization::Corrected);
            OrbitSample {
                elevation_deg: elevation,
                azimuth_deg: azimuth,
                brdf: exact.specular + exact.diffuse,
                ltc: approx.specular + approx.diffuse,
                rel_err: 0.0,
            }
        })
        .collect();
    let floor = 1e-2 * samples.iter().map(|s| s.brdf).fold(0.0, f64::max);
    for s in &mut samples {
        s.rel_err = (s.ltc - s.brdf).abs() / s.brdf.max(floor).max(f64::MIN_POSITIVE);
    }
    samples
}

/// The summary's lines for the error by light elevation.
fn horizon_lines(remedy: Horizon, bands: &[horizon::BandError]) -> Vec<String> {
    let each = |f: &dyn Fn(&horizon::BandError) -> String| {
        bands.iter().map(f).collect::<Vec<_>>().join(" ")
    };
    let mut lines = Vec::new();
    if remedy == Horizon::Eq30 {
        let names = each(&|b| format!("{:.0}–{:.0}°", b.band[0], b.band[1]));
        lines.push(format!(
            " a light by its elevation above the surface ({names}), per horizon remedy:"
        ));
    }
    lines.push(format!(
        "   {:<15} specular {}  diffuse {}  LTC/BRDF specular energy {}",
        remedy.name(),
        each(&|b| format!("{:5.1}%", 100.0 * b.specular)),
        each(&|b| format!("{:4.1}%", 100.0 * b.diffuse)),
        each(&|b| format!("{:.2}", b.specular_energy)),
    ));
    lines
}

/// What the atlas found, for the command line's summary.
#[derive(Clone, Debug, PartialEq)]
pub struct AtlasSummary {
    pub lines: Vec<String>,
}

/// The files of the atlas.
pub fn atlas_files() -> Vec<String> {
    let mut names: Vec<String> = [
        "spec_err.png",
        "diff_err.png",
        "cells.csv",
        "orbits.csv",
        "horizon.csv",
        "spheres.csv",
        "spheres.png",
        "shapes.csv",
        "shapes.png",
    ]
    .map(String::from)
    .into();
    names.extend(ORBITS.map(|(theta, alpha)| orbit_file(theta, alpha)));
    names
}

fn orbit_file(theta: f64, alpha: f64) -> String {
    format!("orbit_{theta:.0}_{alpha}.png")
}

/// Cases per (angular radius, band) of the atlas's sphere measure: 2 000 put each figure within
/// a few percent of itself (its seeds' spread, docs/design.md §4.9) in seconds; the design's
/// table takes 40 000.
pub const SPHERE_CASES: usize = 2_000;

/// Cases per (solid angle, band) of the atlas's rect and disk measure: 300, the design notes'
/// tables' count (docs/design.md §1.11, §1.12), with the exact rules at `SHAPE_NODES`.
pub const SHAPE_CASES: usize = 300;

/// Nodes of the exact rules in the atlas's rect and disk measure: 32 a triangle (a piece) keep
/// their error far under the methods' (64 against 128 differ by 1e-5 of a cell's sum, §1.11),
/// at a quarter of 64's cost.
pub const SHAPE_NODES: usize = 32;

/// Writes `spec_err.png`, `diff_err.png`, `cells.csv`, per orbit `orbit_T_A.png` plus
/// `orbits.csv`, the error by light elevation `horizon.csv`, the sphere lights' errors by
/// angular radius and band `spheres.csv` and `spheres.png`, and the rect and disk lights' by
/// solid angle and band `shapes.csv` and `shapes.png` into `dir` (made if missing), all of
/// them or none.
pub fn write_atlas(lut: &Lut, dir: &Path) -> Result<AtlasSummary> {
    let names = atlas_files();
    let mut out = Outputs::new(dir, &names.iter().map(String::as_str).collect::<Vec<_>>())?;
    let n = lut.size;
    // Cell edges halfway between the centres, in the LUT's own axes mapped to r and θo.
    let mid = |k: f64| (k / (n - 1) as f64).clamp(0.0, 1.0);
    let r_edges: Vec<f64> = (0..=n).map(|k| mid(k as f64 - 0.5)).collect();
    let theta_edges: Vec<f64> = (0..=n)
        .map(|k| {
            let s = mid(k as f64 - 0.5);
            (1.0 - s * s).clamp(-1.0, 1.0).acos().to_degrees()
        })
        .collect();
    let mut lines = Vec::new();
    for (channel, file, name) in [
        (Channel::SpecErr, "spec_err.png", "specular"),
        (Channel::DiffErr, "diff_err.png", "diffuse"),
    ] {
        let png = crate::plot::heat_map_png(
            file,
            &format!("{name} pointwise error ∫|n·D − f·cos| / ∫ f·cos per cell"),
            ("r = √α", &r_edges),
            ("θo (degrees)", &theta_edges),
            |i, j| f64::from(lut.cell(i, j).get(channel)),
        )?;
        out.stage(file, &png)?;
        // The worst view-angle bands, for the summary.
        for (lo, hi) in [
            (0.0, 30.0),
            (30.0, 60.0),
            (60.0, 75.0),
            (75.0, 85.0),
            (85.0, 90.1),
        ] {
            let cells: Vec<(f64, usize, usize)> = (0..n)
                .flat_map(|j| (0..n).map(move |i| (i, j)))
                .filter(|&(_, j)| (lo..hi).contains(&lut.theta_o(j).to_degrees()))
                .map(|(i, j)| (f64::from(lut.cell(i, j).get(channel)), i, j))
                .collect();
            if let Some(&(worst, i, j)) = cells.iter().max_by(|a, b| a.0.total_cmp(&b.0)) {
                let mean = cells.iter().map(|c| c.0).sum::<f64>() / cells.len() as f64;
                lines.push(format!(
                    "{name:>8} θo {lo:>4.0}–{hi:<4.0}°: mean {:5.1}%, worst {:6.1}% at α = {:.4}, θo = {:.1}°",
                    100.0 * mean,
                    100.0 * worst,
                    lut.alpha(i),
                    lut.theta_o(j).to_degrees()
                ));
            }
        }
    }
    let mut cells = String::from("i,j,alpha,theta_o,spec_err,diff_err\n");
    for j in 0..n {
        for i in 0..n {
            let c = lut.cell(i, j);
            cells.push_str(&format!(
                "{i},{j},{},{},{},{}\n",
                lut.alpha(i),
                lut.theta_o(j).to_degrees(),
                c.get(Channel::SpecErr),
                c.get(Channel::DiffErr)
            ));
        }
    }
    out.stage("cells.csv", cells.as_bytes())?;
    let az_edges: Vec<f64> = (0..=AZIMUTHS)
        .map(|k| (k as f64 - 0.5) * 360.0 / (AZIMUTHS - 1) as f64)
        .collect();
    let el_edges: Vec<f64> = (0..=ELEVATIONS)
        .map(|k| -90.0 + (k as f64 - 0.5) * 180.0 / (ELEVATIONS - 1) as f64)
        .collect();
    let mut orbits = String::from("theta_o,alpha,elevation,azimuth,brdf,ltc,rel_err\n");
    for (theta, alpha) in ORBITS {
        let samples = orbit(lut, theta, alpha);
        let file = orbit_file(theta, alpha);
        let png = crate::plot::heat_map_png(
            &file,
            &format!("one light orbiting a point: θo = {theta}°, α = {alpha} (v toward azimuth 0)"),
            ("light azimuth (degrees)", &az_edges),
            ("light elevation (degrees)", &el_edges),
            |a, e| samples[e * AZIMUTHS + a].rel_err,
        )?;
        out.stage(&file, &png)?;
        for s in &samples {
            orbits.push_str(&format!(
                "{theta},{alpha},{},{},{:e},{:e},{:e}\n",
                s.elevation_deg, s.azimuth_deg, s.brdf, s.ltc, s.rel_err
            ));
        }
        let lit: Vec<&OrbitSample> = samples.iter().filter(|s| s.brdf > 0.0).collect();
        let worst = lit.iter().max_by(|a, b| a.rel_err.total_cmp(&b.rel_err));
        // Energy-weighted mean: the error a light following the lobe sees on average.
        let weighted = lit.iter().map(|s| s.rel_err * s.brdf).sum::<f64>()
            / lit.iter().map(|s| s.brdf).sum::<f64>().max(1e-300);
        if let Some(w) = worst {
            lines.push(format!(
                "   orbit θo = {theta}°, α = {alpha}: brightness-weighted mean error {:.1}%, worst {:.0}% at elevation {:.0}°, azimuth {:.0}°",
                100.0 * weighted,
                100.0 * w.rel_err,
                w.elevation_deg,
                w.azimuth_deg
            ));
        }
    }
    out.stage("orbits.csv", orbits.as_bytes())?;
    let mut table = String::from("rules,band,cases,specular,diffuse,specular_energy\n");
    for remedy in Horizon::ALL {
        let (_, bands) = horizon::remedy_errors(lut, remedy, horizon::CASES, horizon::SEED);
        lines.extend(horizon_lines(remedy, &bands));
        table.push_str(&horizon::csv_rows(&format!("{},", remedy.name()), &bands));
    }
    out.stage("horizon.csv", table.as_bytes())?;
    let (csv, png, sphere_lines) = spheres(lut)?;
    out.stage("spheres.csv", csv.as_bytes())?;
    out.stage("spheres.png", &png)?;
    lines.extend(sphere_lines);
    let (csv, png, shape_lines) = shapes(lut)?;
    out.stage("shapes.csv", csv.as_bytes())?;
    out.stage("shapes.png", &png)?;
    lines.extend(shape_lines);
    out.commit()?;
    Ok(AtlasSummary { lines })
}

/// The sphere lights' errors (`sphere_error`): the CSV, a chart of the specular error against
/// the angular radius per band with a line per method, and the summary's lines (where the
/// point formula stops holding).
fn spheres(lut: &Lut) -> Result<(String, Vec<u8>, Vec<String>)> {
    use crate::measure::sphere_error::{
        APPROXIMATIONS, MEASURE_NODES, RADII_DEG, csv_rows, sphere_errors,
    };
    let errors = sphere_errors(lut, &RADII_DEG, SPHERE_CASES, horizon::SEED, MEASURE_NODES);
    let csv = format!(
        "radius_deg,band,cases,method,specular,diffuse\n{}",
        csv_rows(&errors)
    );
    let panels: Vec<(String, Vec<crate::plot::Series>)> = horizon::BANDS
        .iter()
        .map(|band| {
            let series = APPROXIMATIONS
                .iter()
                .enumerate()
                .map(|(m, method)| crate::plot::Series {
                    label: method.name().to_string(),
                    points: errors
                        .iter()
                        .filter(|e| e.band == *band)
                        .map(|e| (e.radius_deg, 100.0 * e.specular[m]))
                        .collect(),
                })
                .collect();
            (
                format!("centre {}–{}° above the surface", band[0], band[1]),
                series,
            )
        })
        .collect();
    let png = crate::plot::line_panels_png(
        "spheres.png",
        &format!(
            "sphere lights: specular Σ|method − exact| / Σ exact ({SPHERE_CASES} cases a point)"
        ),
        ("angular radius σ (degrees)", "specular error (%)"),
        &panels,
    )?;
    let lines = errors
        .iter()
        .filter(|e| e.radius_deg == 10.0)
        .map(|e| {
            format!(
                "  spheres σ = 10°, centre {:>2}–{:<2}° up: specular ltc-point {:5.1}%, ltc-disk {:5.1}%, representative-point {:5.1}%",
                e.band[0],
                e.band[1],
                100.0 * e.specular[0],
                100.0 * e.specular[1],
                100.0 * e.specular[2]
            )
        })
        .collect();
    Ok((csv, png, lines))
}

/// The rect and disk lights' errors (`shape_error`): the CSV, a chart of the specular error
/// against the solid angle per band with a line per (shape, method), and the summary's lines
/// (across the horizon, where the methods part).
fn shapes(lut: &Lut) -> Result<(String, Vec<u8>, Vec<String>)> {
    use crate::measure::shape_error::{DISK_METHODS, RECT_METHODS, csv_rows, shape_errors};
    let errors = shape_errors(lut, SHAPE_CASES, horizon::SEED, SHAPE_NODES, false);
    let csv = format!(
        "solid_angle_sr,band,cases,shape,method,specular,diffuse\n{}",
        csv_rows(&errors)
    );
    let names: Vec<String> = RECT_METHODS
        .iter()
        .map(|m| format!("rect {}", m.name()))
        .chain(DISK_METHODS.iter().map(|m| format!("disk {}", m.name())))
        .collect();
    let bands = crate::measure::shape_error::BANDS;
    let panels: Vec<(String, Vec<crate::plot::Series>)> = bands
        .iter()
        .map(|band| {
            let series = names
                .iter()
                .enumerate()
                .map(|(m, name)| crate::plot::Series {
                    label: name.clone(),
                    points: errors
                        .iter()
                        .filter(|e| e.band == *band)
                        .map(|e| {
                            let figures = e.rects.iter().chain(&e.disks).nth(m).expect("a column");
                            // 1e-3 sr at 1 … 1 sr at 4: the sizes are decades apart.
                            (e.solid_angle.log10() + 4.0, 100.0 * figures[0])
                        })
                        .collect(),
                })
                .collect();
            (
                format!("centre {}–{}° above the surface", band[0], band[1]),
                series,
            )
        })
        .collect();
    let png = crate::plot::line_panels_png(
        "shapes.png",
        &format!(
            "rect and disk lights: specular Σ|method − exact| / Σ exact ({SHAPE_CASES} cases a point)"
        ),
        (
            "solid angle, log10(sr) + 4 (1: 0.001 sr … 4: 1 sr)",
            "specular error (%)",
        ),
        &panels,
    )?;
    let lines = errors
        .iter()
        .filter(|e| e.solid_angle == 0.1)
        .map(|e| {
            format!(
                "  rects and disks of 0.1 sr, centre {:>2}–{:<2}° up: specular ltc-polygon {:5.1}%, ltc-proxy {:5.1}%, ltc-disk {:5.1}%",
                e.band[0],
                e.band[1],
                100.0 * e.rects[0][0],
                100.0 * e.rects[1][0],
                100.0 * e.disks[0][0]
            )
        })
        .collect();
    Ok((csv, png, lines))
}
