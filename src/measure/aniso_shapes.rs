//! Anisotropic LTC on every light shape, measured (docs/design.md §4.11): each shape's LTC
//! method against the exact integral of the anisotropic BRDF, by the material's anisotropy
//! α_y/α_x and the elevation of the light's centre, with several 4D tables side by side.
//! Σ|LTC − exact| / Σ exact of the specular lobe, the one the 4D table shapes (the diffuse
//! lobe is the 2D table's at Burley's α).

use glam::DVec3;
use rayon::prelude::*;

use crate::brdf::Alpha;
use crate::light::EmitterShading;
use crate::light::disk::{DiskMethod, DiskShading, disk_exact, disk_light};
use crate::light::rect::{RectMethod, RectShading, rect_exact, rect_light};
use crate::light::sphere::cap::Cap;
use crate::light::sphere::{SphereMethod, SphereShading, sphere_exact, sphere_light};
use crate::ltc::LtcPair;
use crate::ltc::lut::{ALPHA_MIN, Lut};
use crate::measure::shape_error::{BANDS, F0, lights};
use crate::named::named_enum;
use crate::scene::SplitMix64;

/// α_y / α_x of the rows: isotropic (the 4D table on its diagonal), then ever more brushed.
pub const RATIOS: [f64; 4] = [1.0, 0.5, 0.25, 0.1];

named_enum! {
    /// The light shapes, each with its LTC method: the point formula, the sphere's and the
    /// disk's cone algebra (`ltc-disk`), the rect's clipped polygon (`ltc-polygon`).
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub enum Measured {
        Point = "point",
        Sphere = "sphere",
        Rect = "rect",
        Disk = "disk",
    }
}

/// Solid angle of a sized light, sr: a sphere of 10° angular radius (0.095 sr), rects and
/// disks of 0.1 sr (`shape_error::lights`), the middle of §4.9's sizes.
pub const SOLID_ANGLE: f64 = 0.1;

/// The sphere's angular radius, degrees (about `SOLID_ANGLE`).
pub const SPHERE_RADIUS_DEG: f64 = 10.0;

/// Views θo drawn from (degrees): to 80°, as §4.9's tables; the azimuth from a full turn.
const THETA_O_DEG: [f64; 2] = [0.0, 80.0];

/// α_x drawn from, as §4.9's α.
const ALPHA_X: [f64; 2] = [0.1, 0.8];

/// One shape, anisotropy and band: each table's Σ|LTC − exact| / Σ exact (specular).
#[derive(Clone, Debug, PartialEq)]
pub struct AnisoShapeError {
    pub shape: Measured,
    pub ratio: f64,
    pub band: [f64; 2],
    pub cases: usize,
    pub errors: Vec<f64>,
}

/// Every (shape, ratio, band) cell over `cases` cases, seeded, each table's 4D table read as
/// the renderer reads it (`Lut::aniso_pair`); the exact rules with `nodes` nodes.
pub fn aniso_shape_errors(
    tables: &[&Lut],
    cases: usize,
    seed: u64,
    nodes: usize,
) -> Vec<AnisoShapeError> {
    let cells: Vec<(Measured, usize, usize)> = Measured::ALL
        .into_iter()
        .flat_map(|s| (0..RATIOS.len()).flat_map(move |r| (0..BANDS.len()).map(move |b| (s, r, b))))
        .collect();
    cells
        .par_iter()
        .map(|&(shape, r, b)| {
            // Every shape and ratio sees the same views and lights in a band.
            let mut rng = SplitMix64(seed.wrapping_add(b as u64));
            let (mut err, mut total) = (vec![0.0; tables.len()], 0.0);
            for _ in 0..cases {
                let case = Case::draw(&mut rng, RATIOS[r], BANDS[b]);
                let exact = case.exact(shape, nodes);
                total += exact;
                for (e, lut) in err.iter_mut().zip(tables) {
                    let pair = lut.aniso_pair(case.alpha, case.v);
                    *e += (case.ltc(shape, &pair) - exact).abs();
                }
            }
            AnisoShapeError {
                shape,
                ratio: RATIOS[r],
                band: BANDS[b],
                cases,
                errors: err.iter().map(|e| e / f64::max(total, 1e-300)).collect(),
            }
        })
        .collect()
}

/// One case: a material, a view in its tangent frame, and a light's centre direction with
/// the rect and disk drawn about it.
struct Case {
    alpha: Alpha<f64>,
    v: DVec3,
    l: DVec3,
    rect: crate::light::rect::Rect,
    disk: crate::light::disk::Disk,
}

impl Case {
    fn draw(rng: &mut SplitMix64, ratio: f64, band: [f64; 2]) -> Self {
        let theta = rng.uniform(THETA_O_DEG).to_radians();
        let phi = rng.uniform([0.0, std::f64::consts::TAU]);
        let x = rng.uniform(ALPHA_X);
        let alpha = Alpha {
            x,
            y: (ratio * x).max(ALPHA_MIN),
        };
        let v = DVec3::new(
            theta.sin() * phi.cos(),
            theta.sin() * phi.sin(),
            theta.cos(),
        );
        let (elevation, azimuth) = (rng.uniform(band), rng.uniform([0.0, 360.0]));
        let (rect, disk) = lights(rng, SOLID_ANGLE, elevation, azimuth);
        Self {
            alpha,
            v,
            l: rect.centre.normalize(),
            rect,
            disk,
        }
    }

    fn sphere<'a>(&self, radius_deg: f64, pair: &'a LtcPair) -> SphereShading<'a> {
        SphereShading::unit(self.v, self.l, radius_deg, self.alpha, F0, pair)
    }

    /// The exact specular radiance (unit intensity or radiance) of `shape`.
    fn exact(&self, shape: Measured, nodes: usize) -> f64 {
        // The exact methods read no LTC.
        let cosine = crate::ltc::Ltc::from_brdf_from_cos(glam::DMat3::IDENTITY, 1.0, 0.0);
        let unused = LtcPair {
            spec: cosine,
            diff: cosine,
        };
        match shape {
            Measured::Point => {
                sphere_light(SphereMethod::Exact, &self.sphere(0.0, &unused)).specular
            }
            Measured::Sphere => {
                let s = self.sphere(SPHERE_RADIUS_DEG, &unused);
                match Cap::of_sphere(s.u, s.radius) {
                    Some(cap) => sphere_exact(&s, &cap, nodes).specular,
                    None => sphere_light(SphereMethod::Exact, &s).specular,
                }
            }
            Measured::Rect => rect_exact(self.v, &self.rect, self.alpha, F0, nodes).specular,
            Measured::Disk => disk_exact(self.v, &self.disk, self.alpha, F0, nodes).specular,
        }
    }

    /// The LTC method's specular radiance of `shape` with `pair`, eq. 30's rules.
    fn ltc(&self, shape: Measured, pair: &LtcPair) -> f64 {
        let pixel = EmitterShading::corrected(self.v, self.alpha, F0, pair);
        match shape {
            Measured::Point => {
                sphere_light(SphereMethod::LtcPoint, &self.sphere(0.0, pair)).specular
            }
            Measured::Sphere => {
                let s = self.sphere(SPHERE_RADIUS_DEG, pair);
                sphere_light(SphereMethod::LtcDisk, &s).specular
            }
            Measured::Rect => {
                let s = RectShading {
                    pixel,
                    rect: self.rect,
                };
                rect_light(RectMethod::LtcPolygon, &s).specular
            }
            Measured::Disk => {
                let s = DiskShading {
                    pixel,
                    disk: self.disk,
                };
                disk_light(DiskMethod::LtcDisk, &s).specular
            }
        }
    }
}

/// The figures as CSV rows (`shape,alpha_ratio,band,cases,` then one column per table), the
/// band as `lo..hi` degrees.
pub fn csv_rows(errors: &[AnisoShapeError]) -> String {
    errors
        .iter()
        .map(|e| {
            let cols: Vec<String> = e.errors.iter().map(|x| format!("{x:.6}")).collect();
            format!(
                "{},{},{}..{},{},{}\n",
                e.shape.name(),
                e.ratio,
                e.band[0],
                e.band[1],
                e.cases,
                cols.join(",")
            )
        })
        .collect()
}
