//! Disk lights (docs/design.md §1.12): a one-sided disk of uniform radiance, in the shading
//! frame (`n = +z`, the shading point at the origin). The exact integral's rule is in
//! `quadrature`; the LTC disk is the sphere's (`light::sphere::disk`), fed the disk's own
//! ellipse where a sphere feeds its cap's circle.

pub mod form;
pub mod quadrature;

use std::f64::consts::PI;

use glam::{DMat3, DVec3};

use crate::brdf::{self, Alpha, Lobes};
use crate::light::sphere::disk::{cone_image, cone_integral, hemisphere};
use crate::light::{EmitterLobes, EmitterShading, ExactRule};
use crate::ltc::{Ltc, Normalization};
use crate::named::named_enum;

pub use form::{
    EVAL_COLUMNS, MIN_NORMAL, PRESETS, SIZES, VECTORS, bench_shape, bench_title, eval_row, outline,
};

pub use quadrature::disk_integral_about;

/// A disk: its centre, unit normal (the side it emits toward) and radius.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Disk {
    pub centre: DVec3,
    pub normal: DVec3,
    pub radius: f64,
}

impl Disk {
    /// Two perpendicular radii in its plane, `(e₁, e₂)` with `e₁ × e₂` along the normal (any
    /// pair serves, the disk being round).
    pub fn half_axes(&self) -> (DVec3, DVec3) {
        let (t1, t2) = self.normal.any_orthonormal_pair();
        (t1 * self.radius, t2 * self.radius)
    }

    /// Its area, `π r²`.
    pub fn area(&self) -> f64 {
        PI * self.radius * self.radius
    }

    /// Whether the shading point (the origin) is on the side it emits toward.
    pub fn faces_origin(&self) -> bool {
        self.centre.dot(self.normal) < 0.0
    }

    /// `r / |c|`: a bound on the angle its radius subtends (`DISK_POINT_LIMIT`).
    pub fn angular_size(&self) -> f64 {
        self.radius / self.centre.length()
    }

    /// Whether no point of it is above the surface: its highest point, `c_z + r √(1 − n_z²)`,
    /// is at or below it.
    pub fn below_horizon(&self) -> bool {
        self.centre.z + self.radius * (1.0 - self.normal.z * self.normal.z).max(0.0).sqrt() <= 0.0
    }

    /// The irradiance of its oriented point light at unit radiance: `A cos θe / d²`.
    pub fn point_irradiance(&self) -> f64 {
        let d2 = self.centre.length_squared();
        let cos_e = -self.normal.dot(self.centre) / d2.sqrt();
        self.area() * cos_e.max(0.0) / d2
    }
}

named_enum! {
    /// The ways a disk light is shaded (docs/design.md §1.12).
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
    pub enum DiskMethod {
        /// The BRDF integrated over the disk's directions above the surface (`disk_exact`).
        Exact = "exact",
        /// Heitz & Hill 2017: `M⁻¹` takes the disk's cone to an elliptical one, integrated
        /// in closed form and clipped as the sphere of the same vector form factor.
        LtcDisk = "ltc-disk",
        /// The centre as an oriented point light of intensity `L·A·cos θe` (the limit).
        LtcPoint = "ltc-point",
    }
}

impl DiskMethod {
    /// One line for a reader of the lab or the command line.
    pub fn describe(self) -> &'static str {
        match self {
            Self::Exact => {
                "The BRDF integrated over the disk above the surface (8 × 8 nodes in 4 polar pieces in renders): the reference"
            }
            Self::LtcDisk => {
                "Heitz & Hill 2017: the disk's cone mapped by M⁻¹, an elliptical cone's form factor, clipped as a sphere (Unity HDRP, EEVEE)"
            }
            Self::LtcPoint => {
                "The disk's centre as an oriented point light of intensity L·A·cos θe"
            }
        }
    }
}

/// Nodes per dimension and piece of `DiskMethod::Exact` in `disk_light`: tests/lights/disk_light.rs
/// holds the rule to its bound against Lambert's edge formula over a fine polygon.
pub const EXACT_NODES: usize = 64;

/// Nodes per dimension and piece of the renders' exact method (`ExactRule::Render`), on the
/// CPU and in shaders/disk_light.wgsl alike: 4 pieces of 144 BRDF evaluations per light. The
/// disk keeps its plane rule (docs/design.md §1.14): in the disk's own polar coordinates a disk
/// seen edge-on stays round, where the directions' polar rule sees a needle.
pub const RENDER_NODES: usize = 12;

/// Below this `angular_size` every method shades a disk as its oriented point light, as a
/// sphere is below `sphere::POINT_LIMIT_SIN_SIGMA` (the same bound, for the same reason: the
/// mean over the disk differs from its centre's value by `O((r/d)²/α²)`, far inside each
/// method's own error, while the cone's algebra runs out of f32 digits).
pub const DISK_POINT_LIMIT: f64 = 1e-7;

/// One disk light of unit radiance at one shading point: everything the methods read.
#[derive(Clone, Copy, Debug)]
pub struct DiskShading<'a> {
    /// The view, the material, the LTC lobes and the rules (every emitter's).
    pub pixel: EmitterShading<'a>,
    pub disk: Disk,
}

/// A disk's unit-radiance lobes by `method` and its area (`EmitterLobes`), centred at
/// `centre` from the shading point with `normal` (world, mapped to the shading frame by
/// `to_frame`; its length not read) and `radius`, the exact method by `rule`.
pub fn emitter_lobes(
    method: DiskMethod,
    (centre, normal, radius): (DVec3, DVec3, f64),
    to_frame: &dyn Fn(DVec3) -> DVec3,
    s: &EmitterShading<'_>,
    rule: ExactRule,
) -> EmitterLobes {
    let disk = Disk {
        centre: to_frame(centre),
        normal: to_frame(normal.normalize()),
        radius,
    };
    let shading = DiskShading { pixel: *s, disk };
    (disk_light_with(method, &shading, rule), disk.area())
}

/// The radiance toward `v` of a disk of unit radiance, per lobe (base colour 1), the exact
/// method by `EXACT_NODES`. A disk facing away gives 0.
pub fn disk_light(method: DiskMethod, s: &DiskShading<'_>) -> Lobes<f64> {
    disk_light_with(method, s, ExactRule::Nodes(EXACT_NODES))
}

/// `disk_light` with the exact method by `rule` (the renders take `ExactRule::Render`).
pub fn disk_light_with(method: DiskMethod, s: &DiskShading<'_>, rule: ExactRule) -> Lobes<f64> {
    if !s.disk.faces_origin() {
        return Lobes::default();
    }
    if s.disk.angular_size() < DISK_POINT_LIMIT {
        return disk_point(method, s);
    }
    match method {
        DiskMethod::Exact => {
            let nodes = match rule {
                ExactRule::Nodes(nodes) => nodes,
                ExactRule::Render => RENDER_NODES,
            };
            disk_exact(s.pixel.v, &s.disk, s.pixel.alpha, s.pixel.f0, nodes)
        }
        DiskMethod::LtcDisk => disk_ltc(s),
        DiskMethod::LtcPoint => disk_point(method, s),
    }
}

/// The disk as its oriented point light at the centre (`point_irradiance`): the exact point
/// light for the exact method, the paper's point formula for the LTC ones.
pub fn disk_point(method: DiskMethod, s: &DiskShading<'_>) -> Lobes<f64> {
    let e = s.disk.point_irradiance();
    let l = s.disk.centre.normalize();
    let exact = method == DiskMethod::Exact;
    s.pixel.point_light(exact, l, e)
}

/// The exact radiance of a disk of unit radiance toward `v`, per lobe (base colour 1):
/// `∫ f(v, ω) cos ω dω` over its directions above the surface, `n × n` nodes a piece.
pub fn disk_exact(v: DVec3, disk: &Disk, alpha: Alpha<f64>, f0: f64, n: usize) -> Lobes<f64> {
    if !disk.faces_origin() {
        return Lobes::default();
    }
    // The specular lobe peaks about the mirror direction: the rule centres its pieces there.
    let mirror = DVec3::new(-v.x, -v.y, v.z);
    let [specular, diffuse] = disk_integral_about(disk, n, Some(mirror), |l| {
        let lobes = brdf::brdf_cos_aniso(v.to_array(), l.to_array(), alpha, f0);
        [lobes.specular, lobes.diffuse]
    });
    Lobes { specular, diffuse }
}

/// Heitz & Hill 2017 for a disk light: each lobe's LTC over the disk's cone, times the lobe's
/// magnitude. With case 1 a disk wholly below the surface gives 0; one across it is left to
/// case 2, as the sphere's LTC disk is (the cone's algebra has no cut).
pub fn disk_ltc(s: &DiskShading<'_>) -> Lobes<f64> {
    if s.pixel.clip.case1 && s.disk.below_horizon() {
        return Lobes::default();
    }
    let (spec_weight, diff_weight) = s.pixel.ltc.lobe_weights(s.pixel.f0, s.pixel.normalization);
    let lobe = |ltc| ltc_disk_light(ltc, &s.disk, s.pixel.clip.case2, s.pixel.normalization);
    Lobes {
        specular: spec_weight * lobe(&s.pixel.ltc.spec),
        diffuse: diff_weight * lobe(&s.pixel.ltc.diff),
    }
}

/// `∫ D(ω) dω` over a disk light's directions (the sphere's `ltc_disk` for the ellipse
/// `[e₁ e₂ c]`): the hemisphere behind its normal where the cone is too wide for its algebra
/// (the point all but on the disk).
pub fn ltc_disk_light(ltc: &Ltc, disk: &Disk, case2: bool, normalization: Normalization) -> f64 {
    let (e1, e2) = disk.half_axes();
    let (axis, form_factor) = Some(cone_image(
        ltc,
        DMat3::from_cols(e1, e2, disk.centre),
        disk.centre,
    ))
    .filter(|(axis, ff)| axis.is_finite() && ff.is_finite())
    .unwrap_or_else(|| hemisphere(ltc, -disk.normal));
    cone_integral(axis, form_factor, case2, normalization)
}
