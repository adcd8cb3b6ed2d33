//! The half-precision forms' error against the f64 reference, per pixel: for paper-100 and
//! the lab's 20 000-light scene, each f16 form on the GPU against the CPU's f64 `ltc` (the
//! same math), as max and mean of `|L_gpu − L_f64| / max(L_f64, 1% of the mean)` on
//! luminance over the plane (docs/design.md §4's difference map), with f32 `ltc-fast` beside them.
//!
//! `cargo run --release --example f16_error` (needs a GPU adapter with SHADER_F16).

use ltc_lab::app::Lab;
use ltc_lab::gpu::GpuContext;
use ltc_lab::gpu::plane::ShaderChecks;
use ltc_lab::gpu::renderer::PlaneRenderer;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::metrics::relative_difference;
use ltc_lab::render::{Method, RenderSettings};
use ltc_lab::scene::{Scene, preset};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let ctx = GpuContext::new()?;
    println!("{}", ctx.describe());
    let lut = Lut::embedded();
    let mut gpu = PlaneRenderer::new(&ctx, lut, ShaderChecks::Checked)?;
    // The lab's light generator, as its slider makes 20 000 lights.
    let mut lab = Lab::new(
        Default::default(),
        Err("not needed".into()),
        ltc_lab::scene::MAX_LIGHTS,
    );
    lab.set_light_count(20_000);
    let scenes: [(&str, Scene, usize); 2] = [
        ("paper-100", preset("paper-100"), 512),
        ("lab 20 000 lights", lab.shaded_scene(), 256),
    ];
    println!("| scene | size | method | max rel | mean rel |");
    println!("|---|---|---|---:|---:|");
    for (name, scene, side) in scenes {
        let reference = ltc_lab::cpu::render(
            &scene,
            lut,
            &RenderSettings::single(side, side, Method::Ltc),
        );
        for method in [Method::LtcFast, Method::LtcF16, Method::LtcF16Pairs] {
            if !gpu.supports(method) {
                println!(
                    "| {name} | {side}² | {} | (no SHADER_F16) | |",
                    method.name()
                );
                continue;
            }
            let (image, _) =
                gpu.render(&ctx, &scene, &RenderSettings::single(side, side, method))?;
            let diff = relative_difference(&image, &reference);
            let rel: Vec<f64> = (0..diff.pixels.len())
                .filter(|&k| reference.on_plane[k])
                .map(|k| diff.pixels[k].x)
                .collect();
            let max = rel.iter().copied().fold(0.0, f64::max);
            let mean = rel.iter().sum::<f64>() / rel.len().max(1) as f64;
            println!(
                "| {name} | {side}² | {} | {max:.2e} | {mean:.2e} |",
                method.name()
            );
        }
    }
    Ok(())
}
