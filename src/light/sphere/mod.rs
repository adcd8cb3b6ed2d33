//! Lights with a size: a sphere of radius `r` and uniform radiance, and the ways engines
//! shade it (docs/design.md §1.10). Everything is in the shading frame (`n = +z`), in f64:
//! the exact integral over the visible cap is the reference; the paper's point formula at the
//! centre, Karis's representative point and Heitz & Hill's LTC disk are the approximations
//! measured against it. A radius of zero is the paper's point light, unchanged.

pub mod cap;
pub mod disk;
pub mod quadrature;
pub mod region;

use glam::DVec3;

use crate::brdf::{self, Alpha, Lobes, MIN_LIGHT_DISTANCE};
use crate::light::ExactRule;
pub use crate::light::polar::mirror;
use crate::light::sphere::cap::Cap;
use crate::light::sphere::quadrature::cap_integral_about;
use crate::ltc::{Clipping, LtcPair, Normalization};
use crate::named::named_enum;

/// The failure cases of lights with a size (docs/design.md §1.10), shipped beside the
/// clipping panel's: a sphere cut by the horizon, one touching the plane, discs seen edge-on,
/// and ltc_code's black spots.
pub const PRESETS: [(&str, &str); 4] = [
    (
        "sphere-horizon",
        include_str!("../../../assets/scenes/sphere-horizon.toml"),
    ),
    (
        "sphere-touching",
        include_str!("../../../assets/scenes/sphere-touching.toml"),
    ),
    (
        "sphere-edge-on",
        include_str!("../../../assets/scenes/sphere-edge-on.toml"),
    ),
    (
        "sphere-black-spots",
        include_str!("../../../assets/scenes/sphere-black-spots.toml"),
    ),
];

/// The radiance of a sphere of radius `r` whose intensity toward a distant point is `I`:
/// `L = I / (π r²)` (its silhouette is a disc of area `π r²`), so that far away it lights as
/// the point light of intensity `I` does.
pub fn sphere_radiance(intensity: f64, r: f64) -> f64 {
    intensity / (std::f64::consts::PI * r * r)
}

named_enum! {
    /// The ways a sphere light is shaded (docs/design.md §1.10).
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
    pub enum SphereMethod {
        /// The BRDF integrated over the visible cap, by `quadrature::cap_integral`.
        Exact = "exact",
        /// The paper's point formula at the centre (the lab's point lights).
        LtcPoint = "ltc-point",
        /// The cap as a disc of the same solid angle, shaded by LTC (Heitz & Hill 2017).
        LtcDisk = "ltc-disk",
        /// Karis 2013's representative point, with its energy normalization.
        RepresentativePoint = "representative-point",
    }
}

impl SphereMethod {
    /// One line for a reader of the lab or the command line.
    pub fn describe(self) -> &'static str {
        match self {
            Self::Exact => {
                "The BRDF integrated over the visible cap (8 Gauss–Legendre nodes per dimension and piece in renders): the reference"
            }
            Self::LtcPoint => "The paper's point formula at the sphere's centre: good to σ ≈ 2°",
            Self::LtcDisk => {
                "The cap as an LTC disk of the same solid angle (Heitz & Hill 2017; EEVEE, Bevy's pull request)"
            }
            Self::RepresentativePoint => {
                "Karis 2013's closest point to the mirror ray with its energy normalization (Unreal)"
            }
        }
    }
}

/// One sphere light at one shading point: everything the methods read.
#[derive(Clone, Copy, Debug)]
pub struct SphereShading<'a> {
    /// Unit view direction, shading frame.
    pub v: DVec3,
    /// The sphere's centre minus the shading point, shading frame.
    pub u: DVec3,
    pub intensity: f64,
    /// The window's range (infinite: no window), applied at the centre's distance.
    pub range: f64,
    pub radius: f64,
    /// The material's roughness along the shading frame's x and y.
    pub alpha: Alpha<f64>,
    pub f0: f64,
    /// The LTC lobes at this pixel's (θo, α), for the LTC methods.
    pub ltc: &'a LtcPair,
    pub clip: Clipping,
    pub normalization: Normalization,
}

/// Gauss–Legendre nodes per dimension of the exact method: 64 × 64 per piece of the cap keeps
/// the rule's error under 1e-6 of the result for α ≥ 0.05 and caps up to 30°
/// (tests/lights/sphere_light.rs compares it with 128 nodes).
pub const EXACT_NODES: usize = 64;

/// Below this `sin σ = r/d` every method shades a sphere as its point light: the cap's mean
/// differs from its centre's value by O((σ/α)²) ≤ 1e-6 even at the table's smallest α
/// (1e-4), far inside each method's own error, while the closed forms cancel or overflow as
/// σ goes on to 0 (the radiance `I/(π r²)` overflows once r² underflows).
pub const POINT_LIMIT_SIN_SIGMA: f64 = 1e-7;

impl<'a> SphereShading<'a> {
    /// A sphere of unit intensity at unit distance toward unit `l`, with angular radius
    /// `sigma_deg`, no window and eq. 30's corrected rules: the case `eval` and
    /// `sphere_error` measure, whose σ = 0 is a unit-irradiance point light.
    pub fn unit(
        v: DVec3,
        l: DVec3,
        sigma_deg: f64,
        alpha: Alpha<f64>,
        f0: f64,
        ltc: &'a LtcPair,
    ) -> Self {
        Self {
            v,
            u: l,
            intensity: 1.0,
            range: f64::INFINITY,
            radius: sigma_deg.to_radians().sin(),
            alpha,
            f0,
            ltc,
            clip: Clipping::BOTH,
            normalization: Normalization::Corrected,
        }
    }
}

/// The radiance toward `v`, per lobe (base colour 1): `specular + c · diffuse`.
pub fn sphere_light(method: SphereMethod, s: &SphereShading<'_>) -> Lobes<f64> {
    sphere_light_with(method, s, ExactRule::Nodes(EXACT_NODES))
}

/// `sphere_light` with the exact method by `rule`: the renders take `ExactRule::Render` on
/// the CPU, as the GPU does.
pub fn sphere_light_with(
    method: SphereMethod,
    s: &SphereShading<'_>,
    rule: ExactRule,
) -> Lobes<f64> {
    let cap = Cap::of_sphere(s.u, s.radius).filter(|c| c.sin_sigma >= POINT_LIMIT_SIN_SIGMA);
    let Some(cap) = cap else {
        return sphere_point(method, s);
    };
    match method {
        SphereMethod::Exact => match rule {
            ExactRule::Nodes(nodes) => sphere_exact(s, &cap, nodes),
            ExactRule::Render => sphere_rule(s, &cap),
        },
        SphereMethod::LtcPoint => sphere_ltc_point(s),
        SphereMethod::LtcDisk => sphere_ltc_disk(s, &cap),
        SphereMethod::RepresentativePoint => sphere_representative_point(s, &cap),
    }
}

/// A radius of zero (or a sphere below `POINT_LIMIT_SIN_SIGMA`): the exact methods are the
/// exact point light, the LTC ones the paper's.
pub fn sphere_point(method: SphereMethod, s: &SphereShading<'_>) -> Lobes<f64> {
    match method {
        SphereMethod::Exact | SphereMethod::RepresentativePoint => brdf::point_light_exact_aniso(
            s.v.to_array(),
            s.u.to_array(),
            s.intensity,
            s.range,
            s.alpha,
            s.f0,
        ),
        SphereMethod::LtcPoint | SphereMethod::LtcDisk => sphere_ltc_point(s),
    }
}

/// The window `w(d)` at the centre's distance, as engines apply it to sphere lights.
fn window(s: &SphereShading<'_>) -> f64 {
    brdf::window_falloff(s.u.length(), s.range)
}

/// The exact radiance: `w(d) · L · ∫ f cos dω` over the cap's directions above the surface,
/// with `nodes` Gauss–Legendre nodes per dimension.
pub fn sphere_exact(s: &SphereShading<'_>, cap: &Cap, nodes: usize) -> Lobes<f64> {
    let scale = window(s) * sphere_radiance(s.intensity, s.radius);
    // The specular lobe peaks about the mirror direction: the rule crowds its nodes there.
    let focus = Some(mirror(s.v));
    let [specular, diffuse] = cap_integral_about(cap.axis, cap.depth(), nodes, focus, |l| {
        let lobes = brdf::brdf_cos_aniso(s.v.to_array(), l.to_array(), s.alpha, s.f0);
        [lobes.specular, lobes.diffuse]
    });
    Lobes {
        specular: scale * specular,
        diffuse: scale * diffuse,
    }
}

/// The exact radiance by the renders' rule (`region::cap_rule`): `w(d) · L` times the
/// integral over the visible cap.
pub fn sphere_rule(s: &SphereShading<'_>, cap: &Cap) -> Lobes<f64> {
    let scale = window(s) * sphere_radiance(s.intensity, s.radius);
    let lobes = region::cap_rule(s.v, cap, s.alpha, s.f0);
    Lobes {
        specular: scale * lobes.specular,
        diffuse: scale * lobes.diffuse,
    }
}

/// The paper's point formula with the sphere's centre as the light (eq. 30 corrected).
pub fn sphere_ltc_point(s: &SphereShading<'_>) -> Lobes<f64> {
    let d = s.u.length();
    let e = brdf::irradiance_scale(s.intensity, d, s.range);
    if e <= 0.0 {
        return Lobes::default();
    }
    let lobes = s.ltc.ltc_lobes(s.u / d, s.f0, s.clip, s.normalization);
    Lobes {
        specular: e * lobes.specular,
        diffuse: e * lobes.diffuse,
    }
}

/// Heitz & Hill 2017: each lobe's LTC integrated over the cap, seen as the disc facing the
/// point with the same solid angle (`ltc::disk`), times the sphere's radiance and the lobe's
/// magnitude.
pub fn sphere_ltc_disk(s: &SphereShading<'_>, cap: &Cap) -> Lobes<f64> {
    if s.clip.case1 && cap.below_horizon() {
        return Lobes::default();
    }
    let scale = window(s) * sphere_radiance(s.intensity, s.radius);
    let (spec_weight, diff_weight) = s.ltc.lobe_weights(s.f0, s.normalization);
    let lobe = |ltc| crate::light::sphere::disk::ltc_disk(ltc, cap, s.clip.case2, s.normalization);
    Lobes {
        specular: scale * spec_weight * lobe(&s.ltc.spec),
        diffuse: scale * diff_weight * lobe(&s.ltc.diff),
    }
}

/// Karis 2013 ("Real Shading in Unreal Engine 4", eqs. 10–14): the specular lobe at the
/// point of the sphere closest to the reflected ray, its peak lowered by the energy
/// normalization `(α/α')²` with `α' = saturate(α + ½ saturate(r/d))` (Unreal's form of eq. 10),
/// and the diffuse lobe at the centre with the sphere's exact irradiance (Lagarde & de
/// Rousiers 2014 §4.7.2). `1/d²` takes `d ≥ r`: at the surface `I/r² = πL`, the irradiance of
/// the half-space of radiance `L` a point touching the sphere sees.
pub fn sphere_representative_point(s: &SphereShading<'_>, cap: &Cap) -> Lobes<f64> {
    let d = s.u.length();
    let w = window(s);
    let reflected = mirror(s.v);
    let centre_to_ray = reflected * s.u.dot(reflected) - s.u;
    let reach = centre_to_ray.length();
    let closest = if reach > s.radius {
        s.u + centre_to_ray * (s.radius / reach)
    } else {
        s.u + centre_to_ray
    };
    let l = closest.try_normalize().unwrap_or(reflected);
    let energy = widening_energy(s.alpha, (s.radius / d.max(MIN_LIGHT_DISTANCE)).min(1.0));
    let d2 = d.max(s.radius).powi(2);
    let specular = brdf::brdf_cos_aniso(s.v.to_array(), l.to_array(), s.alpha, s.f0).specular;
    let diffuse = fd_toward(s.v, cap.axis, s.alpha.diffuse())
        * sphere_radiance(s.intensity, s.radius)
        * cap.illuminance();
    Lobes {
        specular: w * s.intensity / d2 * energy * specular,
        diffuse: w * diffuse,
    }
}

/// Karis's energy normalization for a lobe widened by a light's angular size `spread`
/// (`saturate(r/d)`): `(α/α')²`, `α' = saturate(α + spread/2)`. D's peak goes as `1/(α_x α_y)`,
/// so an anisotropic lobe widened along both axes keeps `(α_x/α_x')(α_y/α_y')`.
pub fn widening_energy(alpha: Alpha<f64>, spread: f64) -> f64 {
    let wide = |a: f64| (a + 0.5 * spread).min(1.0);
    if alpha.is_isotropic() {
        return (alpha.x / wide(alpha.x)).powi(2);
    }
    (alpha.x / wide(alpha.x)) * (alpha.y / wide(alpha.y))
}

/// Burley's diffuse BRDF (base colour 1) toward a light direction that may lie below the
/// horizon, as a sphere's centre can while part of it is above: `n·l` is taken at 0 there.
pub fn fd_toward(v: DVec3, l: DVec3, alpha: f64) -> f64 {
    let Some(h) = (v + l).try_normalize() else {
        return 0.0;
    };
    brdf::fd_burley(v.z, l.z.max(0.0), l.dot(h), alpha)
}
