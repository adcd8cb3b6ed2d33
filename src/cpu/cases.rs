//! Each pixel's cases (the paper's §2.5 clipping cases, docs/design.md §1.10's sphere cases)
//! for the lab's case maps: which lights reach a surface point, in which case, over a whole view.

use glam::DVec3;
use rayon::prelude::*;

use super::LtcPixel;
use crate::brdf::irradiance_scale;
use crate::light::Shape;
use crate::light::sphere::cap::{Cap, SphereCase};
use crate::ltc::ClipCase;
use crate::ltc::lut::Lut;
use crate::render::{LtcRules, ShadingFrame, SurfacePoint};
use crate::scene::{Light, Scene};

/// The most telling sphere case (`SphereCase::ALL`'s order) of the lights with a size that
/// reach `p`; `None` where none does.
pub fn sphere_case(scene: &Scene, p: &SurfacePoint) -> Option<SphereCase> {
    let frame = ShadingFrame::of(&scene.material.gloss(), p.view);
    scene
        .lights
        .iter()
        .filter_map(|l| {
            let Shape::Sphere { radius } = l.shape else {
                return None;
            };
            let u = frame.tangent_from_world(DVec3::from(l.position) - p.position);
            let lit = irradiance_scale(1.0, u.length(), l.range_or_infinity()) > 0.0;
            let cap = Cap::of_sphere(u, radius)?;
            // Inside the sphere the window's distance is 0 or less: it reaches the point.
            (lit || cap.encloses()).then(|| cap.case())
        })
        .max()
}

/// Each pixel's `sphere_case` for a `width × height` view (`None` off the plane or where no
/// light with a size reaches), rows in parallel.
pub fn sphere_case_map(scene: &Scene, width: usize, height: usize) -> Vec<Option<SphereCase>> {
    per_pixel(scene, (width, height), |p| sphere_case(scene, p))
}

/// `at` of each pixel's surface point of a `width × height` view (`None` off the plane), rows
/// in parallel.
fn per_pixel<T: Send>(
    scene: &Scene,
    (width, height): (usize, usize),
    at: impl Fn(&SurfacePoint) -> Option<T> + Sync,
) -> Vec<Option<T>> {
    (0..height)
        .into_par_iter()
        .flat_map_iter(|y| {
            let at = &at;
            (0..width).map(move |x| {
                scene
                    .surface_point(x, y, width, height)
                    .and_then(|p| at(&p))
            })
        })
        .collect()
}

/// How many lights fall in each clipping case at a surface point (the paper's §2.5, in the
/// four classes of `ClipCase`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ClipCounts {
    pub visible: usize,
    /// Case 1: below the horizon, lifted above it by `M⁻¹` (the glow).
    pub lifted: usize,
    /// Case 2: above the horizon, pushed below it by `M⁻¹` (the negative light).
    pub pushed_below: usize,
    /// Below the horizon and still below after `M⁻¹` (harmless once clipped).
    pub stays_below: usize,
}

impl ClipCounts {
    pub fn get(&self, case: ClipCase) -> usize {
        match case {
            ClipCase::Visible => self.visible,
            ClipCase::Lifted => self.lifted,
            ClipCase::PushedBelow => self.pushed_below,
            ClipCase::StaysBelow => self.stays_below,
        }
    }

    fn add_one(&mut self, case: ClipCase) {
        match case {
            ClipCase::Visible => self.visible += 1,
            ClipCase::Lifted => self.lifted += 1,
            ClipCase::PushedBelow => self.pushed_below += 1,
            ClipCase::StaysBelow => self.stays_below += 1,
        }
    }

    /// The class a case map paints a pixel: an artifact (case 1, then case 2) before the
    /// harmless classes; `None` where no light reaches the point.
    pub fn class(&self) -> Option<ClipCase> {
        [
            ClipCase::Lifted,
            ClipCase::PushedBelow,
            ClipCase::Visible,
            ClipCase::StaysBelow,
        ]
        .into_iter()
        .find(|&c| self.get(c) > 0)
    }
}

impl std::ops::Add for ClipCounts {
    type Output = Self;
    fn add(self, b: Self) -> Self {
        Self {
            visible: self.visible + b.visible,
            lifted: self.lifted + b.lifted,
            pushed_below: self.pushed_below + b.pushed_below,
            stays_below: self.stays_below + b.stays_below,
        }
    }
}

/// Counts the lights that reach `p` (non-zero irradiance) in each clipping case.
pub fn clip_counts(scene: &Scene, lut: &Lut, p: &SurfacePoint, lights: &[Light]) -> ClipCounts {
    let px = LtcPixel::new(lut, &scene.material.gloss(), p.view, &LtcRules::default());
    let mut counts = ClipCounts::default();
    for light in lights {
        let u = px
            .frame
            .tangent_from_world(DVec3::from(light.position) - p.position);
        let d = u.length();
        if irradiance_scale(1.0, d, light.range_or_infinity()) <= 0.0 {
            continue;
        }
        counts.add_one(px.pair.clip_case(u / d));
    }
    counts
}

/// Each pixel's clipping counts for a `width × height` view (`None` off the plane), rows in
/// parallel.
pub fn clip_counts_map(
    scene: &Scene,
    lut: &Lut,
    width: usize,
    height: usize,
) -> Vec<Option<ClipCounts>> {
    per_pixel(scene, (width, height), |p| {
        Some(clip_counts(scene, lut, p, &scene.lights))
    })
}
