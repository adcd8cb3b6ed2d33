//! One surface point opened into its lights: for each, where it is in the shading frame and
//! after `M⁻¹`, its clipping case, the factors of eq. 30 (D, the Jacobian, the magnitudes)
//! and of eq. 28 (Fresnel), its irradiance, and its LTC and exact radiance — the terms whose
//! sums are the pixel (`cpu::shade`). Where two tables are compared, also its LTC radiance
//! with table B, whose sum is the pixel of side B. A light with a size is shaded by each side's
//! sphere or rect method, and has every such method's radiance beside (docs/design.md §1.10,
//! §1.11).

use glam::DVec3;

use crate::brdf::{f_schlick, irradiance_scale};
use crate::cpu::{LtcPixel, exact_term, ltc_term, shape_term};
use crate::light::{ExactRule, Shape, ShapeKind};
use crate::ltc::ClipCase;
use crate::ltc::lut::Lut;
use crate::metrics::luminance;
use crate::render::{LtcRules, ShapeMethod, ShapeMethods, SurfacePoint};
use crate::scene::{Light, Scene};

/// One light's share of a pixel.
#[derive(Clone, Debug, PartialEq)]
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
    /// Its radiance toward the camera by LTC (table A) and exactly.
    pub ltc: DVec3,
    pub exact: DVec3,
    /// Its LTC radiance with table B, where two tables are compared.
    pub ltc_b: Option<DVec3>,
    /// A light with a size: its radiance by each method of its shape (table A), in its
    /// module's order (`ShapeMethod::all`); empty for a point.
    pub by_method: Vec<(ShapeMethod, DVec3)>,
    /// A rect: its corners' directions in the shading frame, unit.
    pub corners: Option<[DVec3; 4]>,
}

impl LightTerm {
    /// Its radiance by `method`, where it is a light of that method's shape.
    pub fn by(&self, method: impl Into<ShapeMethod>) -> Option<DVec3> {
        let method = method.into();
        self.by_method
            .iter()
            .find(|(m, _)| *m == method)
            .map(|(_, v)| *v)
    }

    /// `L_LTC − L_exact` on luminance.
    pub fn error(&self) -> f64 {
        luminance(self.ltc) - luminance(self.exact)
    }

    /// Side B of the comparison: LTC with table B where two tables are compared, else the
    /// exact BRDF.
    pub fn side_b(&self) -> DVec3 {
        self.ltc_b.unwrap_or(self.exact)
    }

    /// `L_A − L_B` on luminance (side A: LTC with table A).
    pub fn difference(&self) -> f64 {
        luminance(self.ltc) - luminance(self.side_b())
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
    /// The pixel by LTC with table B, where two tables are compared.
    pub ltc_b: Option<DVec3>,
    /// `Σ |L_A − L_B|` over the lights, once: every share divides by it, and a table sorted
    /// by share asks for it `n log n` times.
    abs_difference_sum: f64,
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

    /// Side B of the comparison (`LightTerm::side_b`), summed.
    pub fn side_b(&self) -> DVec3 {
        self.ltc_b.unwrap_or(self.exact)
    }

    /// `(L_A − L_B) / L_B` on luminance.
    pub fn relative_difference(&self) -> f64 {
        let b = luminance(self.side_b());
        (luminance(self.ltc) - b) / b.abs().max(1e-300)
    }

    /// A light's share of how far the two sides are apart: its `|L_A − L_B|` over the sum of
    /// every light's (the shares are ≥ 0 and sum to one). Absolute, not signed as
    /// `error_share` is: two tables' differences cancel between lights, and a light whose
    /// difference another one cancels still makes the tables differ.
    pub fn difference_share(&self, term: &LightTerm) -> f64 {
        if self.abs_difference_sum == 0.0 {
            0.0
        } else {
            term.difference().abs() / self.abs_difference_sum
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

/// Every light of `scene` at `p`, LTC with table A and the given rules against the exact
/// BRDF, and with table B too where there is one (`tables.1`); lights with a size by side
/// `a`'s method for their shape (the LTC side) against side `b`'s (the exact side); `None`
/// where the camera sees the plane from below.
pub fn pixel_terms(
    scene: &Scene,
    (lut, lut_b): (&Lut, Option<&Lut>),
    p: &SurfacePoint,
    rules: &LtcRules,
    (a, b): (&ShapeMethods, &ShapeMethods),
) -> Option<PixelTerms> {
    if p.view.z <= 0.0 {
        return None;
    }
    let gloss = scene.material.gloss();
    let px = LtcPixel::new(lut, &gloss, p.view, rules);
    let px_b = lut_b.map(|b| LtcPixel::new(b, &gloss, p.view, rules));
    let terms: Vec<LightTerm> = scene
        .lights
        .iter()
        .enumerate()
        .map(|(index, light)| {
            let mut term = light_term(scene, &px, p, (index, light), rules);
            let kind = light.shape.kind();
            let render =
                |px: &LtcPixel, m| shape_term(scene, px, p, light, rules, (m, ExactRule::Render));
            // A point's side B with table B is the paper's LTC, as its side A is here.
            term.ltc_b = match kind {
                ShapeKind::Point => px_b.as_ref().map(|b| ltc_term(scene, b, p, light, rules)),
                _ => px_b.as_ref().map(|b| render(b, a.of(kind))),
            };
            if kind != ShapeKind::Point {
                // Every method of the shape, made once; each side's value its method's.
                term.by_method = ShapeMethod::all(kind)
                    .into_iter()
                    .map(|m| (m, render(&px, m)))
                    .collect();
                term.ltc = term.by(a.of(kind)).unwrap_or_default();
                term.exact = term.by(b.of(kind)).unwrap_or_default();
            }
            if let Shape::Rect { half_u, half_v } = light.shape {
                term.corners = Some(rect_corners(&px, p, (light, half_u, half_v)));
            }
            term
        })
        .collect();
    // Summed in the lights' order, as `shade_ltc` and `shade_exact` sum them.
    let sum = |f: &dyn Fn(&LightTerm) -> DVec3| terms.iter().fold(DVec3::ZERO, |a, t| a + f(t));
    let v = px.frame.tangent_from_world(p.view);
    Some(PixelTerms {
        theta_o: v.z.clamp(-1.0, 1.0).acos(),
        ltc: sum(&|t| t.ltc),
        exact: sum(&|t| t.exact),
        ltc_b: px_b.map(|_| sum(&|t| t.ltc_b.unwrap_or_default())),
        abs_difference_sum: terms.iter().map(|t| t.difference().abs()).sum(),
        terms,
    })
}

/// One light's terms at `p`, LTC with table A (`px`) against the exact BRDF.
fn light_term(
    scene: &Scene,
    px: &LtcPixel,
    p: &SurfacePoint,
    (index, light): (usize, &Light),
    rules: &LtcRules,
) -> LightTerm {
    let (clipping, normalization) = (rules.clipping, rules.normalization);
    let m = &scene.material;
    let v = px.frame.tangent_from_world(p.view);
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
        ltc: ltc_term(scene, px, p, light, rules),
        exact: exact_term(scene, &px.frame, p, light),
        ltc_b: None,
        by_method: Vec::new(),
        corners: None,
    }
}

/// A rect's corners seen from `p`: their directions in the pixel's shading frame.
fn rect_corners(
    px: &LtcPixel,
    p: &SurfacePoint,
    (light, half_u, half_v): (&Light, DVec3, DVec3),
) -> [DVec3; 4] {
    let rect = crate::light::rect::Rect {
        centre: DVec3::from(light.position) - p.position,
        u: half_u,
        v: half_v,
    };
    rect.corners()
        .map(|c| px.frame.tangent_from_world(c).normalize_or_zero())
}
