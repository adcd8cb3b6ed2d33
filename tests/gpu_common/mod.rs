//! The GPU for tests: skipped loudly where there is no adapter, unless LTC_LAB_REQUIRE_GPU
//! is set (as .ci/run sets it after installing lavapipe), where a missing adapter fails.
#![allow(dead_code)]

use std::sync::{Mutex, OnceLock};

use ltc_lab::gpu::GpuContext;
use ltc_lab::gpu::plane::{PlaneRenderer, ShaderChecks};
use ltc_lab::ltc::lut::Lut;
use ltc_lab::metrics::{luminance, relative_floor};
use ltc_lab::render::Frame;

/// Says loudly that a check was skipped: straight to the process's stderr, which the test
/// harness does not capture (its `eprintln!` capture would hide the line of a passing test).
pub fn skipped(why: &str) {
    use std::io::Write;
    let _ = writeln!(std::io::stderr(), "\n*** SKIPPED: {why} ***\n");
}

pub struct Gpu {
    pub ctx: GpuContext,
    pub renderer: Mutex<PlaneRenderer>,
}

/// One device for the whole test binary (device creation on lavapipe takes ~100 ms).
pub fn gpu() -> Option<&'static Gpu> {
    static GPU: OnceLock<Option<Gpu>> = OnceLock::new();
    GPU.get_or_init(|| match GpuContext::new() {
        Ok(ctx) => {
            eprintln!("GPU tests on {}", ctx.describe());
            let renderer = Mutex::new(
                PlaneRenderer::new(&ctx, Lut::embedded(), ShaderChecks::Checked)
                    .expect("the shipped LUT fits every adapter"),
            );
            Some(Gpu { ctx, renderer })
        }
        Err(e) if GpuContext::required_by_environment() => {
            panic!("LTC_LAB_REQUIRE_GPU is set but {e}")
        }
        Err(e) => {
            skipped(&format!("GPU test without a GPU adapter ({e}). Install mesa-vulkan-drivers or set LTC_LAB_REQUIRE_GPU=1 to make this a failure."));
            None
        }
    })
    .as_ref()
}

/// A frame's pixels to the bit, for checks of exact equality.
pub fn bits(f: &Frame) -> Vec<[u64; 3]> {
    f.pixels
        .iter()
        .map(|p| [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()])
        .collect()
}

/// Per-pixel agreement of a GPU frame with the CPU reference.
///
/// Tolerance 2e-4 of `max(|reference luminance|, floor)`: the GPU shades in f32. Its hit
/// point is off by ~1e-7 relative (f32 ray arithmetic over a 5-unit scene), which the
/// inverse-square falloff's relative gradient 2/d (100 at d = 0.02, figure2-case2's light)
/// turns into ~5e-5; f32 rounding of 1000-term sums and of the LUT blend adds ~1e-5. The
/// largest difference measured on lavapipe over all cases was 6.9e-5 (figure2-case1, no
/// clipping, paper-literal). The floor (1% of the reference's mean,
/// `metrics::relative_floor`) covers pixels near zero, where the clipping decisions may fall
/// differently in f32 on terms that vanish there.
/// Pixels whose camera ray hits the plane in one precision only (its silhouette) are skipped:
/// at most 1% of the image.
pub const RADIANCE_TOLERANCE: f64 = 2e-4;

pub fn assert_close(what: &str, gpu: &Frame, cpu: &Frame) {
    let floor = relative_floor(cpu, cpu);
    let mut silhouette = 0;
    let mut worst: (f64, usize) = (0.0, 0);
    for k in 0..cpu.pixels.len() {
        if gpu.on_plane[k] != cpu.on_plane[k] {
            silhouette += 1;
            continue;
        }
        let (g, c) = (gpu.pixels[k], cpu.pixels[k]);
        assert!(g.is_finite(), "{what}: pixel {k} is {g}");
        let scale = luminance(c.abs()).max(floor);
        let err = (g - c).abs().max_element() / scale;
        if err > worst.0 {
            worst = (err, k);
        }
    }
    assert!(
        silhouette * 100 <= cpu.pixels.len(),
        "{what}: {silhouette} pixels differ in coverage"
    );
    let (err, k) = worst;
    assert!(
        err <= RADIANCE_TOLERANCE,
        "{what}: pixel {k} differs by {err:.2e} (gpu {:?}, cpu {:?})",
        gpu.pixels[k],
        cpu.pixels[k]
    );
}

/// The bound on a diff-view pixel `r = |a − b| / max(b, f)` given the radiance bound ε =
/// `RADIANCE_TOLERANCE` (relative to `max(reference, floor)`) on each of a and b. With
/// `D = max(b, f)`: `|δb| ≤ εD`, and `|δa| ≤ ε·max(a, f) ≤ εD(1 + r)` since `a ≤ b + rD`;
/// the numerator moves by at most `|δa| + |δb|`, the denominator by `|δb|`, so
/// `|δr| ≤ (ε(1 + r) + ε + rε) / (1 − ε) ≈ 2ε(1 + r)`. The floors of the radiance check and
/// of the diff are both 1% of a mean luminance, of A's and of B's image (equal to the
/// LTC's mean error, ~1%): a 10% margin covers their mismatch.
pub fn diff_tolerance(r: f64) -> f64 {
    2.0 * RADIANCE_TOLERANCE * (1.0 + r) * 1.1
}
