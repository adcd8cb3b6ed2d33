//! The CPU reference renderer: the plane seen by the camera, shaded in f64 with the exact
//! BRDF (eq. 28) or the LTC approximation (eq. 30 with DESIGN §1's corrections), rows in
//! parallel with rayon. It is the ground truth every GPU test compares against.

use glam::DVec3;
use rayon::prelude::*;

use crate::brdf::{Lobes, irradiance_scale, point_light_exact};
use crate::ltc::lut::Lut;
use crate::ltc::{Clipping, LtcPair, Normalization};
use crate::metrics::relative_difference;
use crate::render::{
    Frame, FrameKind, LutFilter, Method, RenderSettings, ShadingFrame, SurfacePoint, Tables, View,
};
use crate::scene::{Light, Scene};

/// The per-pixel state of LTC shading: the frame and the two looked-up lobes.
#[derive(Clone, Copy, Debug)]
pub struct LtcPixel {
    pub frame: ShadingFrame,
    pub pair: LtcPair,
}

impl LtcPixel {
    pub fn new(lut: &Lut, alpha: f64, view: DVec3, filter: LutFilter) -> Self {
        let frame = ShadingFrame::new(view);
        let cos_theta_o = frame.tangent_from_world(view).z;
        let sample = match filter {
            LutFilter::Bilinear => lut.sample(alpha, cos_theta_o),
            LutFilter::Nearest => lut.sample_nearest(alpha, cos_theta_o),
        };
        Self {
            frame,
            pair: sample.ltc_pair(),
        }
    }
}

/// The exact radiance toward the camera at `p` (eq. 28), summed over `lights`.
pub fn shade_exact(scene: &Scene, p: &SurfacePoint, lights: &[Light]) -> DVec3 {
    if p.view.z <= 0.0 {
        return DVec3::ZERO;
    }
    let frame = ShadingFrame::new(p.view);
    let v = frame.tangent_from_world(p.view).to_array();
    let m = &scene.material;
    lights.iter().fold(DVec3::ZERO, |sum, light| {
        let u = frame.tangent_from_world(DVec3::from(light.position) - p.position);
        let lobes = point_light_exact(
            v,
            u.to_array(),
            1.0,
            light.range_or_infinity(),
            m.alpha,
            m.f0,
        );
        sum + light.radiant_intensity() * combine(lobes, m.base_color)
    })
}

/// The LTC radiance toward the camera at `p` (eq. 30, corrected or paper-literal).
pub fn shade_ltc(
    scene: &Scene,
    lut: &Lut,
    p: &SurfacePoint,
    lights: &[Light],
    clipping: Clipping,
    normalization: Normalization,
    filter: LutFilter,
) -> DVec3 {
    if p.view.z <= 0.0 {
        return DVec3::ZERO;
    }
    let m = &scene.material;
    let px = LtcPixel::new(lut, m.alpha, p.view, filter);
    lights.iter().fold(DVec3::ZERO, |sum, light| {
        let u = px
            .frame
            .tangent_from_world(DVec3::from(light.position) - p.position);
        let d = u.length();
        let e = irradiance_scale(1.0, d, light.range_or_infinity());
        if e <= 0.0 {
            return sum;
        }
        let lobes = px.pair.ltc_lobes(u / d, m.f0, clipping, normalization);
        sum + light.radiant_intensity() * (e * combine(lobes, m.base_color))
    })
}

/// `specular + c · diffuse`, per channel.
fn combine(lobes: Lobes<f64>, base_color: [f64; 3]) -> DVec3 {
    DVec3::splat(lobes.specular) + lobes.diffuse * DVec3::from(base_color)
}

/// Renders the scene as `s.view` shows it: one method's radiance, both split at the divider,
/// or their relative difference. `tables`: one table, or A's and B's (`s.table_b`).
pub fn render<'a>(scene: &Scene, tables: impl Into<Tables<'a>>, s: &RenderSettings) -> Frame {
    let tables = tables.into();
    let (a, b) = ((s.method_a, tables.a), (s.method_b, tables.for_b(s)));
    let divider = s.divider_column();
    let shade = |pick: &Pick<'_>| render_radiance(scene, s, pick);
    match s.view {
        View::A => shade(&|_| a),
        View::B => shade(&|_| b),
        View::Split => {
            let mut frame = shade(&|x| if x < divider { a } else { b });
            frame.divider = Some(divider);
            frame
        }
        View::Diff => relative_difference(&shade(&|_| a), &shade(&|_| b)),
    }
}

/// The method, and its table, that shades a pixel column.
type Pick<'a> = dyn Fn(usize) -> (Method, &'a Lut) + Sync + 'a;

/// The radiance at one surface point by `method` (its literal form: the CPU has one of each).
pub fn shade(
    scene: &Scene,
    lut: &Lut,
    p: &SurfacePoint,
    s: &RenderSettings,
    method: Method,
) -> DVec3 {
    if method.is_ltc() {
        shade_ltc(
            scene,
            lut,
            p,
            &scene.lights,
            s.clipping,
            s.normalization,
            s.lut_filter,
        )
    } else {
        shade_exact(scene, p, &scene.lights)
    }
}

/// Radiance with the method (and table) `pick` gives for each pixel column.
fn render_radiance(scene: &Scene, s: &RenderSettings, pick: &Pick<'_>) -> Frame {
    let rows: Vec<(Vec<DVec3>, Vec<bool>)> = (0..s.height)
        .into_par_iter()
        .map(|y| {
            (0..s.width)
                .map(|x| match scene.surface_point(x, y, s.width, s.height) {
                    None => (DVec3::ZERO, false),
                    Some(p) => {
                        let (method, lut) = pick(x);
                        (shade(scene, lut, &p, s, method), true)
                    }
                })
                .unzip()
        })
        .collect();
    let (pixels, on_plane) = rows
        .into_iter()
        .fold((Vec::new(), Vec::new()), |mut acc, (p, m)| {
            acc.0.extend(p);
            acc.1.extend(m);
            acc
        });
    Frame {
        width: s.width,
        height: s.height,
        kind: FrameKind::Radiance,
        pixels,
        on_plane,
        divider: None,
    }
}

/// How many lights fall in each clipping case at a surface point (the paper's §2.5).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ClipCounts {
    /// Case 1: below the horizon (`n·l ≤ 0`).
    pub below_horizon: usize,
    /// Case 2: above the horizon, but pushed below it by `M⁻¹` of either lobe.
    pub pushed_below: usize,
}

impl std::ops::Add for ClipCounts {
    type Output = Self;
    fn add(self, b: Self) -> Self {
        Self {
            below_horizon: self.below_horizon + b.below_horizon,
            pushed_below: self.pushed_below + b.pushed_below,
        }
    }
}

/// Counts the lights that reach `p` (non-zero irradiance) in clipping cases 1 and 2.
pub fn clip_counts(scene: &Scene, lut: &Lut, p: &SurfacePoint, lights: &[Light]) -> ClipCounts {
    use crate::ltc::ClipCase;
    let px = LtcPixel::new(lut, scene.material.alpha, p.view, LutFilter::Bilinear);
    let mut counts = ClipCounts::default();
    for light in lights {
        let u = px
            .frame
            .tangent_from_world(DVec3::from(light.position) - p.position);
        let d = u.length();
        if irradiance_scale(1.0, d, light.range_or_infinity()) <= 0.0 {
            continue;
        }
        let l = u / d;
        match (px.pair.spec.clip_case(l), px.pair.diff.clip_case(l)) {
            (ClipCase::BelowHorizon, _) => counts.below_horizon += 1,
            (ClipCase::PushedBelow, _) | (_, ClipCase::PushedBelow) => counts.pushed_below += 1,
            _ => {}
        }
    }
    counts
}

/// Clipping counts summed over every pixel of a `width × height` view.
pub fn clip_counts_image(scene: &Scene, lut: &Lut, width: usize, height: usize) -> ClipCounts {
    (0..height)
        .into_par_iter()
        .map(|y| {
            (0..width)
                .filter_map(|x| scene.surface_point(x, y, width, height))
                .map(|p| clip_counts(scene, lut, &p, &scene.lights))
                .fold(ClipCounts::default(), std::ops::Add::add)
        })
        .reduce(ClipCounts::default, std::ops::Add::add)
}
