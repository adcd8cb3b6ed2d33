//! The CPU reference renderer: the plane seen by the camera, shaded in f64 with the exact
//! BRDF (eq. 28) or the LTC approximation (eq. 30 with DESIGN §1's corrections), rows in
//! parallel with rayon. It is the ground truth every GPU test compares against.

use glam::DVec3;
use rayon::prelude::*;

use crate::brdf::{Lobes, irradiance_scale, point_light_exact};
use crate::ltc::lut::Lut;
use crate::ltc::{Clipping, LtcPair, Normalization};
use crate::metrics::relative_difference;
use crate::scene::{Light, Scene};

/// What a render shows.
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum, serde::Serialize, serde::Deserialize,
)]
pub enum Method {
    /// The exact BRDF (eq. 28).
    Brdf,
    /// The LTC approximation (eq. 30).
    Ltc,
    /// LTC left of the divider, exact BRDF right of it.
    Split,
    /// The per-pixel relative difference |LTC − BRDF| / BRDF as a false-colour map.
    Diff,
}

/// Everything about a render that is not the scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderSettings {
    pub width: usize,
    pub height: usize,
    pub method: Method,
    pub clipping: Clipping,
    pub normalization: Normalization,
    /// Where `Split` changes method, as a fraction of the width.
    pub divider: f64,
    /// How the LTC table is read.
    pub lut_filter: LutFilter,
}

/// How the LTC table is read per pixel (the `ltc-nearest` study variant uses `Nearest`).
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
pub enum LutFilter {
    /// Bilinear, as a GPU sampler (DESIGN §2).
    #[default]
    Bilinear,
    /// The nearest cell.
    Nearest,
}

impl RenderSettings {
    pub fn new(width: usize, height: usize, method: Method) -> Self {
        Self {
            width,
            height,
            method,
            clipping: Clipping::BOTH,
            normalization: Normalization::Corrected,
            divider: 0.5,
            lut_filter: LutFilter::Bilinear,
        }
    }

    /// The first pixel column of the exact side of a split image.
    pub fn divider_column(&self) -> usize {
        ((self.divider.clamp(0.0, 1.0) * self.width as f64).round() as usize).min(self.width)
    }
}

/// What the pixels of a `Frame` hold.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameKind {
    /// Linear RGB radiance.
    Radiance,
    /// The relative difference of `metrics::relative_difference`, in all three channels.
    RelativeDifference,
}

/// A rendered image, row-major from the top-left, in f64.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    pub width: usize,
    pub height: usize,
    pub kind: FrameKind,
    pub pixels: Vec<DVec3>,
    /// Whether the pixel's ray hit the plane (the rest is background).
    pub on_plane: Vec<bool>,
    /// The split column, for split renders.
    pub divider: Option<usize>,
}

/// A camera ray's hit on the plane, with what shading needs there.
#[derive(Clone, Copy, Debug)]
pub struct SurfacePoint {
    pub position: DVec3,
    /// Unit vector toward the camera, world space.
    pub view: DVec3,
}

/// The shading frame of DESIGN §1 at a point with normal `+z`: `t1` along the view's
/// tangential part, `t2 = n × t1`. Maps world vectors to frame coordinates.
#[derive(Clone, Copy, Debug)]
pub struct ShadingFrame {
    pub t1: DVec3,
    pub t2: DVec3,
}

impl ShadingFrame {
    pub fn new(view: DVec3) -> Self {
        let tangential = DVec3::new(view.x, view.y, 0.0);
        // At normal view any tangent will do: the lobes are rotationally symmetric there.
        let t1 = tangential.try_normalize().unwrap_or(DVec3::X);
        Self {
            t1,
            t2: DVec3::Z.cross(t1),
        }
    }

    /// `tangent_from_world` applied to `w`.
    pub fn tangent_from_world(&self, w: DVec3) -> DVec3 {
        DVec3::new(w.dot(self.t1), w.dot(self.t2), w.z)
    }
}

impl Scene {
    /// The camera's position and orthonormal basis: eye, forward, right, up (`+z` is up).
    pub fn camera_basis(&self) -> (DVec3, DVec3, DVec3, DVec3) {
        let eye = DVec3::from(self.camera.position);
        let forward = (DVec3::from(self.camera.target) - eye).normalize();
        let right = forward.cross(DVec3::Z).normalize();
        (eye, forward, right, right.cross(forward))
    }

    /// The camera ray through image position (x, y) in pixels (pixel centres at k + ½) of a
    /// `width × height` image: origin and unit direction.
    pub fn camera_ray(&self, x: f64, y: f64, width: usize, height: usize) -> (DVec3, DVec3) {
        let (eye, forward, right, up) = self.camera_basis();
        let tan_half = (self.camera.fov_y_degrees.to_radians() * 0.5).tan();
        let aspect = width as f64 / height as f64;
        let sx = (2.0 * x / width as f64 - 1.0) * tan_half * aspect;
        let sy = (1.0 - 2.0 * y / height as f64) * tan_half;
        (eye, (forward + sx * right + sy * up).normalize())
    }

    /// Where world point `p` appears in a `width × height` image, in pixels; `None` behind
    /// the camera.
    pub fn project(&self, p: DVec3, width: usize, height: usize) -> Option<(f64, f64)> {
        let (eye, forward, right, up) = self.camera_basis();
        let d = p - eye;
        let z = d.dot(forward);
        if z <= 1e-9 {
            return None;
        }
        let tan_half = (self.camera.fov_y_degrees.to_radians() * 0.5).tan();
        let aspect = width as f64 / height as f64;
        let sx = d.dot(right) / (z * tan_half * aspect);
        let sy = d.dot(up) / (z * tan_half);
        Some((
            (sx + 1.0) * 0.5 * width as f64,
            (1.0 - sy) * 0.5 * height as f64,
        ))
    }

    /// The point of the plane seen through pixel (x, y) of a `width × height` image.
    pub fn surface_point(
        &self,
        x: usize,
        y: usize,
        width: usize,
        height: usize,
    ) -> Option<SurfacePoint> {
        self.surface_point_at(x as f64 + 0.5, y as f64 + 0.5, width, height)
    }

    /// `surface_point` at a continuous image position.
    pub fn surface_point_at(
        &self,
        x: f64,
        y: f64,
        width: usize,
        height: usize,
    ) -> Option<SurfacePoint> {
        let (eye, dir) = self.camera_ray(x, y, width, height);
        if dir.z == 0.0 {
            return None;
        }
        let t = -eye.z / dir.z;
        if t <= 0.0 {
            return None;
        }
        let position = eye + t * dir;
        let h = self.plane.half_size;
        if position.x.abs() > h || position.y.abs() > h {
            return None;
        }
        Some(SurfacePoint {
            position,
            view: (eye - position).normalize(),
        })
    }
}

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

/// Renders the scene. `Diff` holds the relative difference, the others radiance.
pub fn render(scene: &Scene, lut: &Lut, s: &RenderSettings) -> Frame {
    let shade = |method: Method| render_radiance(scene, lut, s, method);
    match s.method {
        Method::Brdf | Method::Ltc => shade(s.method),
        Method::Split => {
            let mut frame = shade(Method::Split);
            frame.divider = Some(s.divider_column());
            frame
        }
        Method::Diff => {
            let ltc = shade(Method::Ltc);
            let exact = shade(Method::Brdf);
            relative_difference(&ltc, &exact)
        }
    }
}

/// Radiance of one method (`Split`: LTC left of the divider, exact right of it).
fn render_radiance(scene: &Scene, lut: &Lut, s: &RenderSettings, method: Method) -> Frame {
    let divider = s.divider_column();
    let rows: Vec<(Vec<DVec3>, Vec<bool>)> = (0..s.height)
        .into_par_iter()
        .map(|y| {
            (0..s.width)
                .map(|x| match scene.surface_point(x, y, s.width, s.height) {
                    None => (DVec3::ZERO, false),
                    Some(p) => {
                        let use_ltc = match method {
                            Method::Ltc => true,
                            Method::Split => x < divider,
                            Method::Brdf | Method::Diff => false,
                        };
                        let radiance = if use_ltc {
                            shade_ltc(
                                scene,
                                lut,
                                &p,
                                &scene.lights,
                                s.clipping,
                                s.normalization,
                                s.lut_filter,
                            )
                        } else {
                            shade_exact(scene, &p, &scene.lights)
                        };
                        (radiance, true)
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
