//! The renders' exact rule against a converged f64 integral (docs/design.md §1.14). A scene's
//! exact image — every shape by its exact method, points by the BRDF, as a split's reference
//! side draws it — beside one made by an independent path: each shape's own rule (the plane
//! and cap rules of §1.10–§1.12) at `REFERENCE_NODES` a dimension and piece, itself checked
//! converged against `CHECK_NODES`. tests/lights/render_rule.rs holds the CPU's image to it,
//! tests/gpu/exact_rule.rs the GPU's.

use crate::cpu::{Side, render_side};
use crate::light::ExactRule;
use crate::ltc::lut::Lut;
use crate::metrics::{luminance, relative_error};
use crate::render::{Frame, Method, RenderSettings, View};
use crate::scene::Scene;

/// Nodes a dimension and piece of the reference. The plane and cap rules converge
/// geometrically: from `CHECK_NODES` to 96 they move the slowest preset's pixels
/// (`brushed-rect`) by 2.4e-5 and from 96 to 128 by 5e-7 (measured, docs/design.md §1.14), so
/// 96 is converged far past the 1e-3 a rule is held to.
pub const REFERENCE_NODES: usize = 96;

/// The reference's check: its images at this many nodes and at `REFERENCE_NODES` differ by
/// the error of the coarser one at most, which a test bounds.
pub const CHECK_NODES: usize = 64;

/// What a pixel's error is relative to, below the pixel itself: this much of the image's
/// brightest pixel (a near-black pixel is judged on the scale of the light it is part of).
/// 1e-4 is 40 times under the step of an 8-bit display (1/255), so an error the floor
/// forgives is one no image shows.
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
    render_side(scene, &s, side)
}

/// The largest of each plane pixel's `|a − b| / max(b, FLOOR · b's brightest)` in
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
        .map(|(i, (&x, &y))| (relative_error(luminance(x), luminance(y), floor), i))
        .fold((0.0, 0), |w, e| if e.0 > w.0 { e } else { w })
}
