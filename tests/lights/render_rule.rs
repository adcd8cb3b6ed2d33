//! Every shipped preset's exact image, as the CPU renders it (the renders' rule, docs/
//! design.md §1.14), within 1e-3 of a converged f64 integral: each shape's own rule at
//! `REFERENCE_NODES` a piece, an independent path, itself converged (tests/gpu/exact_rule.rs
//! holds the GPU's image to the same reference).

use ltc_lab::cpu;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::measure::exact_rule::{
    CHECK_NODES, REFERENCE_NODES, exact_settings, reference, worst_error,
};
use ltc_lab::scene::{preset, shipped_presets};

/// The size every preset is rendered at: 576 pixels, each light seen from as many places.
const SIZE: (usize, usize) = (32, 18);

/// Where a drawn reference must be (the bound `eval`'s rule meets): 1e-3 of the converged
/// integral, pixel by pixel.
const BOUND: f64 = 1e-3;

/// The reference's own step from `CHECK_NODES` to `REFERENCE_NODES`, which bounds the coarser
/// rule's error. The rules converge geometrically, the slowest (brushed-rect's, the plane rule
/// over a strip across an anisotropic lobe) by some 50× from 64 to 96 nodes (2.4e-5, then
/// 5e-7 against 128), so a step under 1e-4 leaves the reference within a few 1e-6 of the
/// integral: a hundredth of the bound it measures.
const CONVERGED: f64 = 1e-4;

#[test]
fn every_presets_exact_image_is_within_1e_3_of_a_converged_integral() {
    let (w, h) = SIZE;
    for (name, _) in shipped_presets() {
        let scene = preset(name);
        let want = reference(&scene, w, h, REFERENCE_NODES);
        let (step, _) = worst_error(&reference(&scene, w, h, CHECK_NODES), &want);
        assert!(
            step <= CONVERGED,
            "{name}: the reference moved {step:.1e} from {CHECK_NODES} to {REFERENCE_NODES} nodes"
        );
        let got = cpu::render(&scene, Lut::embedded(), &exact_settings(w, h));
        let (worst, at) = worst_error(&got, &want);
        eprintln!(
            "{name}: the CPU's exact image within {worst:.1e} (pixel {at}); the reference within {step:.1e}"
        );
        assert!(
            worst <= BOUND,
            "{name}: pixel {at} off by {worst:.2e} (over {BOUND:e})"
        );
    }
}
