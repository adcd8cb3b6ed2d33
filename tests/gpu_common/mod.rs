//! The GPU for tests: skipped loudly where there is no adapter, unless LTC_LAB_REQUIRE_GPU
//! is set (as .ci/run sets it after installing lavapipe), where a missing adapter fails.
#![allow(dead_code)]

use std::sync::{Mutex, OnceLock};

use ltc_lab::gpu::GpuContext;
use ltc_lab::gpu::plane::ShaderChecks;
use ltc_lab::gpu::renderer::PlaneRenderer;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::parity::{Parity, RADIANCE_TOLERANCE};
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
        Err(e) if required_by_environment() => {
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

/// Per-pixel agreement of a GPU frame with the CPU reference, at the library's parity
/// tolerance (`ltc_lab::parity`, which says where it comes from).
pub fn assert_close(what: &str, gpu: &Frame, cpu: &Frame) {
    let parity = Parity::of(gpu, cpu);
    if let Err(why) = parity.check() {
        let k = parity.worst;
        panic!(
            "{what}: {why} (gpu {:?}, cpu {:?})",
            gpu.pixels[k], cpu.pixels[k]
        );
    }
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

/// Whether the tests must fail rather than skip when there is no adapter.
fn required_by_environment() -> bool {
    std::env::var_os("LTC_LAB_REQUIRE_GPU").is_some_and(|v| !v.is_empty() && v != "0")
}
