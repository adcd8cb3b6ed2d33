//! Every shipped preset's exact image, as the GPU renders it (the renders' rule in
//! shaders/polar.wgsl and the shapes' files, docs/design.md §1.14), within 1e-3 of the
//! converged f64 integral tests/lights/render_rule.rs checks the CPU's against: each shape's
//! own rule at `REFERENCE_NODES` a piece.

use crate::gpu_common::{gpu, gpu_frame};
use ltc_lab::measure::exact_rule::{REFERENCE_NODES, exact_settings, reference, worst_error};
use ltc_lab::scene::{preset, shipped_presets};

/// The CPU test's size and bound (tests/lights/render_rule.rs): 1e-3 of the converged
/// integral, pixel by pixel. The GPU's f32 rule is the CPU's within the renders' parity
/// tolerance (2e-4), so it meets the bound where the CPU's does with that to spare.
const SIZE: (usize, usize) = (32, 18);
const BOUND: f64 = 1e-3;

#[test]
fn every_presets_exact_image_on_the_gpu_is_within_1e_3_of_a_converged_integral() {
    if gpu().is_none() {
        return;
    }
    let (w, h) = SIZE;
    for (name, _) in shipped_presets() {
        let scene = preset(name);
        let want = reference(&scene, w, h, REFERENCE_NODES);
        let got = gpu_frame(&scene, &exact_settings(w, h));
        let (worst, at) = worst_error(&got, &want);
        eprintln!("{name}: the GPU's exact image within {worst:.1e} (pixel {at})");
        assert!(
            worst <= BOUND,
            "{name}: pixel {at} off by {worst:.2e} (over {BOUND:e})"
        );
    }
}
