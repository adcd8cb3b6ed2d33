//! Each encoding of the table measured on every light shape (docs/design.md §2.10): the error
//! it adds against the f32 table (Σ|encoded − f32| / Σ f32 per lobe) and its total error
//! against the exact integral (Σ|encoded − exact| / Σ exact), by shape, α band and θo band,
//! over the same drawn cases for every encoding. Each shape by the LTC method engines ship
//! for it: a point by the LTC, a sphere and a disk by `ltc-disk`, a rect by `ltc-polygon`;
//! and an anisotropic material (which reads the 4D table) under the point and the rect.
//! `lut --encodings` prints it.

use glam::DVec3;
use rayon::prelude::*;

use crate::brdf::{Alpha, Lobes, view_from_theta};
use crate::light::EmitterShading;
use crate::light::disk::{DiskMethod, DiskShading, disk_exact, disk_light};
use crate::light::rect::{RectMethod, RectShading, rect_exact, rect_light};
use crate::light::sphere::{SphereMethod, SphereShading, sphere_light};
use crate::ltc::aniso::encoded::bytes as aniso_bytes;
use crate::ltc::fit::{FitSettings, fit_table};
use crate::ltc::lut::{ALPHA_MIN, Encoding, Lut, Storage, THETA_MAX};
use crate::measure::horizon::{F0, lobes};
use crate::measure::shape_error::lights;
use crate::measure::sphere_error::one_sphere;
use crate::render::LtcRules;
use crate::scene::SplitMix64;

/// The light shapes measured, in the rows' order: on the isotropic material, then on an
/// anisotropic one.
pub const SHAPES: [&str; 6] = [
    "point",
    "sphere",
    "rect",
    "disk",
    "aniso-point",
    "aniso-rect",
];

/// The anisotropic material's α_y/α_x, drawn uniformly (its α_x is the band's α): from the
/// most brushed of §4.11's rows to isotropic.
pub const ANISO_RATIO: [f64; 2] = [0.1, 1.0];

/// The seed of the anisotropic draws is the band's, offset by this, so that the isotropic
/// shapes' cases are the ones measured before the anisotropic rows were added.
const ANISO_SEED: u64 = 0x4d5f_616e_6973_6f00;

/// α bands: near the mirror (where `M⁻¹`'s entries grow like 1/α), glossy, rough.
pub const ALPHA_BANDS: [[f64; 2]; 3] = [[0.01, 0.1], [0.1, 0.4], [0.4, 1.0]];

/// θo bands, degrees: facing, oblique, grazing.
pub const THETA_BANDS: [[f64; 2]; 3] = [[0.0, 40.0], [40.0, 70.0], [70.0, 89.0]];

/// A sphere's angular radius (degrees) and a rect's and a disk's solid angle (sr): a light
/// of a size a room holds, seen from a metre or two.
pub const SPHERE_RADIUS_DEG: f64 = 5.0;
pub const AREA_SOLID_ANGLE: f64 = 0.1;

/// Nodes of the exact rules a piece: 32 is within 1e-4 of 64 on these lights from α = 0.1 up
/// (the rules' own error, shape_error's `finer` measure, docs/design.md §1.11), far below
/// what an LTC misses; below α = 0.1 the `total` columns are not checked against finer rules.
/// The `added` columns compare tables alone and do not use the exact rules.
pub const NODES: usize = 32;

/// A table an engine might ship instead of the f32 one: an encoding of it as decoded, or a
/// table fitted at a smaller size; its name and the bytes an engine stores for its 2D table
/// and for its 4D table.
pub struct Candidate {
    pub name: String,
    pub bytes: usize,
    pub aniso_bytes: usize,
    pub lut: Lut,
}

impl Candidate {
    /// `lut` as `encoding` gives it back.
    pub fn encoded(lut: &Lut, encoding: Encoding) -> Self {
        Self {
            name: encoding.name(),
            bytes: encoding.bytes(lut.size),
            aniso_bytes: aniso_bytes(lut.aniso().dims, encoding.storage),
            lut: encoding.decoded(lut),
        }
    }

    /// The classic table fitted at `size` cells a side by `fit`'s own rule (`fit --size`),
    /// stored in f32 as the shipped table is: `fit-SIZE`. Set beside `f32-SIZE`, the shipped
    /// table resampled, it says which makes the better small table.
    pub fn fitted(size: usize) -> Self {
        let settings = FitSettings {
            size,
            ..FitSettings::default()
        };
        let lut = fit_table(&settings, &|| {}).lut;
        Self {
            name: format!("fit-{size}"),
            bytes: Encoding::default().bytes(size),
            // The 4D table it carries, in f32, as `encoded` counts its own.
            aniso_bytes: aniso_bytes(lut.aniso().dims, Storage::F32),
            lut,
        }
    }
}

/// One candidate table, shape and band: what it adds to f32's error and its total error, per
/// lobe (`[specular, diffuse]`).
#[derive(Clone, Debug, PartialEq)]
pub struct EncodingError {
    pub name: String,
    pub bytes: usize,
    pub shape: &'static str,
    pub alpha: [f64; 2],
    pub theta: [f64; 2],
    pub cases: usize,
    pub added: [f64; 2],
    pub total: [f64; 2],
}

/// Every candidate over every shape and band, `cases` cases a band (seeded), against `lut`.
pub fn encoding_errors(
    lut: &Lut,
    candidates: &[Candidate],
    cases: usize,
    seed: u64,
) -> Vec<EncodingError> {
    let bands: Vec<(usize, usize)> = (0..ALPHA_BANDS.len())
        .flat_map(|a| (0..THETA_BANDS.len()).map(move |t| (a, t)))
        .collect();
    let per_band: Vec<Vec<EncodingError>> = bands
        .par_iter()
        .map(|&(a, t)| band(lut, candidates, (a, t), cases, seed))
        .collect();
    let mut rows: Vec<EncodingError> = per_band.into_iter().flatten().collect();
    rows.sort_by_key(|r| {
        let e = candidates.iter().position(|c| c.name == r.name);
        let s = SHAPES.iter().position(|&s| s == r.shape);
        (e, s)
    });
    rows
}

/// Each shape's lobes at one case: exact, and by each table.
type Case = [(Lobes<f64>, Vec<Lobes<f64>>); SHAPES.len()];

fn band(
    lut: &Lut,
    candidates: &[Candidate],
    (a, t): (usize, usize),
    cases: usize,
    seed: u64,
) -> Vec<EncodingError> {
    let band_seed = seed.wrapping_add((a * THETA_BANDS.len() + t) as u64);
    let mut rng = SplitMix64(band_seed);
    let mut aniso_rng = SplitMix64(band_seed ^ ANISO_SEED);
    // Per shape: Σ exact, Σ f32, and per table Σ|table − f32|, Σ|table − exact| (per lobe).
    let n = SHAPES.len();
    let mut exact_sum = vec![[0.0f64; 2]; n];
    let mut f32_sum = vec![[0.0f64; 2]; n];
    let mut added = vec![vec![[0.0f64; 2]; n]; candidates.len()];
    let mut total = vec![vec![[0.0f64; 2]; n]; candidates.len()];
    for _ in 0..cases {
        let theta_o = rng.uniform(THETA_BANDS[t]);
        let alpha = rng.uniform(ALPHA_BANDS[a]);
        // A light above the horizon, uniform in solid angle.
        let z = rng.uniform([5f64.to_radians().sin(), 1.0]);
        let phi = rng.uniform([0.0, std::f64::consts::TAU]);
        let r = (1.0 - z * z).sqrt();
        let l = DVec3::new(r * phi.cos(), r * phi.sin(), z);
        let aniso = Aniso {
            ratio: aniso_rng.uniform(ANISO_RATIO),
            phi_o: aniso_rng.uniform([0.0, std::f64::consts::TAU]),
        };
        let case = one_case(lut, candidates, (theta_o, alpha), l, &mut rng, aniso);
        for (s, (exact, got)) in case.iter().enumerate() {
            let f32_lobes = got[0];
            // Σ|x − y| per lobe (y zero: Σ|x|).
            let sum = |acc: &mut [f64; 2], x: Lobes<f64>, y: Lobes<f64>| {
                acc[0] += (x.specular - y.specular).abs();
                acc[1] += (x.diffuse - y.diffuse).abs();
            };
            sum(&mut exact_sum[s], *exact, Lobes::default());
            sum(&mut f32_sum[s], f32_lobes, Lobes::default());
            for (k, g) in got[1..].iter().enumerate() {
                sum(&mut added[k][s], *g, f32_lobes);
                sum(&mut total[k][s], *g, *exact);
            }
        }
    }
    let ratio = |e: [f64; 2], t: [f64; 2]| [0, 1].map(|k| e[k] / t[k].max(1e-300));
    let mut rows = Vec::new();
    for (k, candidate) in candidates.iter().enumerate() {
        for (s, &shape) in SHAPES.iter().enumerate() {
            let anisotropic = shape.starts_with("aniso");
            rows.push(EncodingError {
                name: candidate.name.clone(),
                bytes: match anisotropic {
                    true => candidate.aniso_bytes,
                    false => candidate.bytes,
                },
                shape,
                alpha: ALPHA_BANDS[a],
                theta: THETA_BANDS[t],
                cases,
                added: ratio(added[k][s], f32_sum[s]),
                total: ratio(total[k][s], exact_sum[s]),
            });
        }
    }
    rows
}

/// The anisotropic material of a case beside its isotropic one: α_y/α_x and the view's
/// azimuth from the tangent.
#[derive(Clone, Copy)]
struct Aniso {
    ratio: f64,
    phi_o: f64,
}

/// One view and light direction: each shape's exact lobes and its lobes by `lut` (first)
/// and then by each candidate's.
fn one_case(
    lut: &Lut,
    candidates: &[Candidate],
    (theta_o, alpha): (f64, f64),
    l: DVec3,
    rng: &mut SplitMix64,
    aniso: Aniso,
) -> Case {
    let all: Vec<&Lut> = std::iter::once(lut)
        .chain(candidates.iter().map(|c| &c.lut))
        .collect();
    let rules = LtcRules::default();
    let point_exact = lobes(lut, &rules, (theta_o, alpha), l).0;
    let point = all.iter().map(|t| lobes(t, &rules, (theta_o, alpha), l).1);
    let sphere_exact = one_sphere(lut, (theta_o, alpha), l, SPHERE_RADIUS_DEG, NODES).0;
    let v = DVec3::from(view_from_theta(theta_o.to_radians().min(THETA_MAX)));
    let a = Alpha::isotropic(alpha);
    let sphere = all.iter().map(|t| {
        let pair = t.ltc_pair(alpha, v);
        let s = SphereShading::unit(v, l, SPHERE_RADIUS_DEG, a, F0, &pair);
        sphere_light(SphereMethod::LtcDisk, &s)
    });
    let elevation = l.z.asin().to_degrees();
    let azimuth = l.y.atan2(l.x).to_degrees();
    let (rect, disk) = lights(rng, AREA_SOLID_ANGLE, elevation, azimuth);
    let rects = all.iter().map(|t| {
        let pair = t.ltc_pair(alpha, v);
        let s = RectShading {
            pixel: EmitterShading::corrected(v, a, F0, &pair),
            rect,
        };
        rect_light(RectMethod::LtcPolygon, &s)
    });
    let disks = all.iter().map(|t| {
        let pair = t.ltc_pair(alpha, v);
        let s = DiskShading {
            pixel: EmitterShading::corrected(v, a, F0, &pair),
            disk,
        };
        disk_light(DiskMethod::LtcDisk, &s)
    });
    let [aniso_point, aniso_rect] = anisotropic(&all, (theta_o, alpha), aniso, l, &rect);
    [
        (point_exact, point.collect()),
        (sphere_exact, sphere.collect()),
        (rect_exact(v, &rect, a, F0, NODES), rects.collect()),
        (disk_exact(v, &disk, a, F0, NODES), disks.collect()),
        aniso_point,
        aniso_rect,
    ]
}

/// The anisotropic material under the point light `l` and under `rect`: exact, and by each
/// table's 4D table (`Lut::aniso_pair`), as §4.11 measures them.
fn anisotropic(
    all: &[&Lut],
    (theta_o, alpha): (f64, f64),
    aniso: Aniso,
    l: DVec3,
    rect: &crate::light::rect::Rect,
) -> [(Lobes<f64>, Vec<Lobes<f64>>); 2] {
    let a = Alpha {
        x: alpha,
        y: (aniso.ratio * alpha).max(ALPHA_MIN),
    };
    let theta = theta_o.to_radians().min(THETA_MAX);
    let v = DVec3::new(
        theta.sin() * aniso.phi_o.cos(),
        theta.sin() * aniso.phi_o.sin(),
        theta.cos(),
    );
    let pairs: Vec<_> = all.iter().map(|t| t.aniso_pair(a, v)).collect();
    let point = |pair, method| sphere_light(method, &SphereShading::unit(v, l, 0.0, a, F0, pair));
    let rect_by = |pair| {
        let s = RectShading {
            pixel: EmitterShading::corrected(v, a, F0, pair),
            rect: *rect,
        };
        rect_light(RectMethod::LtcPolygon, &s)
    };
    [
        (
            point(&pairs[0], SphereMethod::Exact),
            pairs
                .iter()
                .map(|p| point(p, SphereMethod::LtcPoint))
                .collect(),
        ),
        (
            rect_exact(v, rect, a, F0, NODES),
            pairs.iter().map(rect_by).collect(),
        ),
    ]
}

/// The figures as CSV rows
/// (`encoding,bytes,shape,alpha,theta_o,cases,added_spec,added_diff,total_spec,total_diff`),
/// bands as `lo..hi`.
pub fn csv_rows(errors: &[EncodingError]) -> String {
    let mut out = String::new();
    for e in errors {
        out += &format!(
            "{},{},{},{}..{},{}..{},{},{:.3e},{:.3e},{:.3e},{:.3e}\n",
            e.name,
            e.bytes,
            e.shape,
            e.alpha[0],
            e.alpha[1],
            e.theta[0],
            e.theta[1],
            e.cases,
            e.added[0],
            e.added[1],
            e.total[0],
            e.total[1]
        );
    }
    out
}
