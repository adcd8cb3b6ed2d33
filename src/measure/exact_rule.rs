//! The renders' exact rule against a converged f64 integral (docs/design.md §1.14). A scene's
//! exact image — every shape by its exact method, points by the BRDF, as a split's reference
//! side draws it — beside one made by an independent path: each shape's own rule (the plane
//! and cap rules of §1.10–§1.12) at `REFERENCE_NODES` a dimension and piece, itself checked
//! converged against `CHECK_NODES`. tests/lights/render_rule.rs holds the CPU's image to it,
//! tests/gpu/exact_rule.rs the GPU's.

use rayon::prelude::*;

use crate::cpu::{Side, shade};
use crate::light::ExactRule;
use crate::ltc::lut::Lut;
use crate::metrics::luminance;
use crate::render::{Frame, FrameKind, Method, RenderSettings, View};
use crate::scene::Scene;

/// Nodes a dimension and piece of the reference. The plane and cap rules converge
/// geometrically; from `CHECK_NODES` to 96 they move every shipped preset's pixels by under
/// 3e-7 of a pixel (measured), so 96 is converged far past the 1e-3 a rule is held to.
pub const REFERENCE_NODES: usize = 96;

/// The reference's check: its images at this many nodes and at `REFERENCE_NODES` differ by
/// the error of the coarser one at most, which a test bounds.
pub const CHECK_NODES: usize = 64;

/// What a pixel's error is relative to, below the pixel itself: this much of the image's
/// brightest pixel (a near-black pixel is judged on the scale of the light it is part of).
pub const FLOOR: f64 = 1e-4;

/// The settings of the exact image: the reference side of `RenderSettings::single`, every
/// shape exact and points by the BRDF.
pub fn exact_settings(width: usize, height: usize) -> RenderSettings {
    RenderSettings {
        view: View::B,
        ..RenderSettings::single(width, height, Method::Ltc)
    }
}

/// The exact image of `scene` at `width × height`, each shape by its own rule at `nodes`.
pub fn reference(scene: &Scene, width: usize, height: usize, nodes: usize) -> Frame {
    let s = exact_settings(width, height);
    let side = Side {
        methods: s.b,
        lut: Lut::embedded(),
        rule: ExactRule::Nodes(nodes),
    };
    let (pixels, on_plane) = (0..width * height)
        .into_par_iter()
        .map(
            |i| match scene.surface_point(i % width, i / width, width, height) {
                Some(p) => (shade(scene, &p, &s.rules, &side), true),
                None => (glam::DVec3::ZERO, false),
            },
        )
        .unzip();
    Frame {
        width,
        height,
        kind: FrameKind::Radiance,
        pixels,
        on_plane,
        divider: None,
    }
}

/// The largest of each plane pixel's `|a − b| / max(|b|, FLOOR · b's brightest)` in
/// luminance, and the pixel it is at.
pub fn worst_error(a: &Frame, b: &Frame) -> (f64, usize) {
    let brightest = b
        .pixels
        .iter()
        .map(|&p| luminance(p).abs())
        .fold(0.0, f64::max);
    let floor = FLOOR * brightest;
    a.pixels
        .iter()
        .zip(&b.pixels)
        .enumerate()
        .filter(|&(i, _)| b.on_plane[i])
        .map(|(i, (&x, &y))| {
            let (x, y) = (luminance(x), luminance(y));
            ((x - y).abs() / y.abs().max(floor), i)
        })
        .fold((0.0, 0), |w, e| if e.0 > w.0 { e } else { w })
}
