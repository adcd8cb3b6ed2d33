//! The GPU for tests: skipped loudly where there is no adapter, unless LTC_LAB_REQUIRE_GPU
//! is set (as .ci/run sets it after installing lavapipe), where a missing adapter fails.
#![allow(dead_code)]

use std::sync::{Mutex, OnceLock};

use ltc_lab::gpu::GpuContext;
use ltc_lab::gpu::plane::{PlaneRenderer, ShaderChecks};
use ltc_lab::ltc::lut::Lut;

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
            eprintln!("\n*** SKIPPED: GPU test without a GPU adapter ({e}). Install mesa-vulkan-drivers or set LTC_LAB_REQUIRE_GPU=1 to make this a failure. ***\n");
            None
        }
    })
    .as_ref()
}
