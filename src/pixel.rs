//! One surface point opened into its lights: for each, where it is in the shading frame and
//! after `M⁻¹`, its clipping case, the factors of eq. 30 (D, the Jacobian, the magnitudes)
//! and of eq. 28 (Fresnel), its irradiance, and its LTC and exact radiance — the terms whose
//! sums are the pixel (`cpu::shade_ltc`, `cpu::shade_exact`).

use glam::DVec3;

use crate::brdf::{f_schlick, irradiance_scale};
use crate::cpu::{LtcPixel, exact_term, ltc_term};
use crate::ltc::lut::Lut;
use crate::ltc::{ClipCase, Clipping, Normalization};
use crate::metrics::luminance;
use crate::render::{LutFilter, SurfacePoint};
use crate::scene::Scene;

/// One light's share of a pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightTerm {
    /// The light's index in the scene.
    pub index: usize,
    /// ω: toward the light, unit, in the shading frame (view in the xz-plane).
    pub omega: DVec3,
    /// ω' = M⁻¹ω of the specular lobe, normalized: where the clamped cosine sees it.
    pub omega_cos: DVec3,
    pub case: ClipCase,
    /// The specular and diffuse `D(ω)` with the rules in force (1/sr).
    pub d_spec: f64,
    pub d_diff: f64,
    /// The change of variables `|M⁻¹| / |M⁻¹ω|³` of the specular lobe (eq. 18).
    pub jacobian: f64,
    /// The lobes' magnitudes: `F0 n_s + (1 − F0) f_s` (with the fitted scale) and `n_d`.
    pub spec_magnitude: f64,
    pub diff_magnitude: f64,
    /// Schlick's `F(v·h)` of the exact BRDF toward this light.
    pub fresnel: f64,
    /// `E = I·w(d)/d²` on luminance.
    pub irradiance: f64,
    pub distance: f64,
    /// Its radiance toward the camera by LTC and exactly.
    pub ltc: DVec3,
    pub exact: DVec3,
}

impl LightTerm {
    /// `L_LTC − L_exact` on luminance.
    pub fn error(&self) -> f64 {
        luminance(self.ltc) - luminance(self.exact)
    }
}

/// A pixel's lights and their sums.
#[derive(Clone, Debug, PartialEq)]
pub struct PixelTerms {
    /// θo at the point, radians.
    pub theta_o: f64,
    pub terms: Vec<LightTerm>,
    pub ltc: DVec3,
    pub exact: DVec3,
}

impl PixelTerms {
    /// `(L_LTC − L_exact) / L_exact` on luminance.
    pub fn relative_error(&self) -> f64 {
        let e = luminance(self.exact);
        (luminance(self.ltc) - e) / e.abs().max(1e-300)
    }

    /// A light's share of the pixel's error `L_LTC − L_exact` (the shares sum to one).
    pub fn error_share(&self, term: &LightTerm) -> f64 {
        let total = luminance(self.ltc) - luminance(self.exact);
        if total == 0.0 {
            0.0
        } else {
            term.error() / total
        }
    }
}

/// Elevation above the tangent plane and azimuth from the view's side, degrees.
pub fn elevation_azimuth(w: DVec3) -> (f64, f64) {
    let w = w.normalize_or_zero();
    (
        w.z.clamp(-1.0, 1.0).asin().to_degrees(),
        w.y.atan2(w.x).to_degrees(),
    )
}

/// Every light of `scene` at `p`, LTC with `lut` and the given rules against the exact BRDF;
/// `None` where the camera sees the plane from below.
pub fn pixel_terms(
    scene: &Scene,
    lut: &Lut,
    p: &SurfacePoint,
    clipping: Clipping,
    normalization: Normalization,
    filter: LutFilter,
) -> Option<PixelTerms> {
    if p.view.z <= 0.0 {
        return None;
    }
    let m = &scene.material;
    let px = LtcPixel::new(lut, m.alpha, p.view, filter);
    let v = px.frame.tangent_from_world(p.view);
    let terms: Vec<LightTerm> = scene
        .lights
        .iter()
        .enumerate()
        .map(|(index, light)| {
            let u = px
                .frame
                .tangent_from_world(DVec3::from(light.position) - p.position);
            let distance = u.length();
            let omega = u / distance;
            let spec = &px.pair.spec;
            let w = spec.cos_from_brdf * omega;
            let h = (v + omega).normalize_or_zero();
            LightTerm {
                index,
                omega,
                omega_cos: w.normalize_or_zero(),
                case: px.pair.clip_case(omega),
                d_spec: spec.ltc_eval(omega, clipping, normalization),
                d_diff: px.pair.diff.ltc_eval(omega, clipping, normalization),
                jacobian: spec.det_cos_from_brdf / w.length().powi(3),
                spec_magnitude: px.pair.spec_magnitude(m.f0),
                diff_magnitude: px.pair.diff.magnitude(),
                fresnel: f_schlick(m.f0, v.dot(h)),
                irradiance: luminance(light.radiant_intensity())
                    * irradiance_scale(1.0, distance, light.range_or_infinity()),
                distance,
                ltc: ltc_term(scene, &px, p, light, clipping, normalization),
                exact: exact_term(scene, &px.frame, p, light),
            }
        })
        .collect();
    // Summed in the lights' order, as `shade_ltc` and `shade_exact` sum them.
    let (ltc, exact) = terms.iter().fold((DVec3::ZERO, DVec3::ZERO), |(a, b), t| {
        (a + t.ltc, b + t.exact)
    });
    Some(PixelTerms {
        theta_o: v.z.clamp(-1.0, 1.0).acos(),
        terms,
        ltc,
        exact,
    })
}
