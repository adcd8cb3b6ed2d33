//! When the device fails (docs/design.md §5.14), by injection: a lost device (`destroy`) and
//! an invalid pipeline end in an error naming the device, never a panic; a method file that
//! shadows WGSL builtins leaves the lab's side as it was; a render split into many submissions
//! is the whole render to the bit.

use crate::gpu_common::gpu;
use ltc_lab::error::ErrorKind;
use ltc_lab::gpu::GpuContext;
use ltc_lab::gpu::failures::scoped;
use ltc_lab::gpu::method_file::MethodFile;
use ltc_lab::gpu::plane::ShaderChecks;
use ltc_lab::gpu::renderer::PlaneRenderer;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::render::{Method, RenderSettings};
use ltc_lab::scene::preset;

/// A device of the test's own: a lost one must not take the shared one with it.
fn own_device() -> Option<GpuContext> {
    gpu()?;
    Some(GpuContext::new().expect("a second device on the same adapter"))
}

#[test]
fn a_lost_device_is_an_error_naming_it_not_a_panic() {
    let Some(ctx) = own_device() else {
        return;
    };
    let mut r = PlaneRenderer::new(&ctx, Lut::embedded(), ShaderChecks::Checked).unwrap();
    let scene = preset("paper-100");
    let s = RenderSettings::single(64, 48, Method::Ltc);
    r.render(&ctx, &scene, &s).unwrap();
    ctx.device.destroy();
    let Err(e) = r.render(&ctx, &scene, &s) else {
        panic!("a render on a destroyed device succeeded");
    };
    assert_eq!(e.kind, ErrorKind::Machine, "{e}");
    assert_eq!(e.exit_code(), 1);
    assert!(e.input.contains(&ctx.info.name), "{e}");
    assert!(e.message.contains("lost"), "{e}");
    assert!(ctx.failures.lost().is_some());
}

/// A compute pipeline whose entry point its module lacks: a validation error.
fn invalid_pipeline(ctx: &GpuContext) -> wgpu::ComputePipeline {
    let module = ctx
        .device
        .create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("no entry point"),
            source: wgpu::ShaderSource::Wgsl("fn f() {}".into()),
        });
    ctx.device
        .create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("invalid"),
            layout: None,
            module: &module,
            entry_point: Some("missing"),
            compilation_options: Default::default(),
            cache: None,
        })
}

#[test]
fn a_validation_error_is_kept_and_named_not_a_panic() {
    let Some(ctx) = own_device() else {
        return;
    };
    // Inside a scope: the scope's error.
    let (_, error) = scoped(&ctx.device, || invalid_pipeline(&ctx));
    assert!(error.is_some(), "an invalid pipeline passed its scope");
    ctx.check().unwrap();
    // Outside any: wgpu's default handler would panic; the kept error is the machine's.
    invalid_pipeline(&ctx);
    let e = ctx.check().unwrap_err();
    assert_eq!(e.exit_code(), 1, "{e}");
    assert!(e.message.contains("refused"), "{e}");
    // Said once: the device goes on, and a render on it succeeds.
    ctx.check().unwrap();
    let mut r = PlaneRenderer::new(&ctx, Lut::embedded(), ShaderChecks::Checked).unwrap();
    let s = RenderSettings::single(32, 32, Method::Ltc);
    r.render(&ctx, &preset("paper-100"), &s).unwrap();
}

/// A file declaring functions and an alias named as WGSL builtins (which a module-scope
/// declaration shadows in the whole module) leaves the lab's own side's image to the bit.
#[test]
fn a_file_redefining_builtins_leaves_the_labs_side_as_it_was() {
    let Some(g) = gpu() else {
        return;
    };
    let src = "fn normalize(v: vec3<f32>) -> vec3<f32> { return vec3<f32>(0.0); }\n\
               fn max(a: f32, b: f32) -> f32 { return 0.0; }\n\
               fn dot(a: vec3<f32>, b: vec3<f32>) -> f32 { return 0.0; }\n\
               alias vec3f = vec4<f32>;\n\
               fn method_point(pixel: MethodPixel, light: MethodPoint) -> MethodRadiance {\n    \
               return MethodRadiance(normalize(pixel.n) * max(1.0, 2.0), vec3<f32>(dot(pixel.n, pixel.v)));\n}\n";
    let file = MethodFile::from_source("builtins.wgsl", src).unwrap();
    let mut with = PlaneRenderer::new(&g.ctx, Lut::embedded(), ShaderChecks::Checked).unwrap();
    with.set_method_file(&g.ctx, Some(file)).unwrap();
    let mut without = PlaneRenderer::new(&g.ctx, Lut::embedded(), ShaderChecks::Checked).unwrap();
    let scene = preset("paper-100");
    for method in [Method::Ltc, Method::Brdf] {
        let s = RenderSettings::single(64, 48, method);
        let a = with.render(&g.ctx, &scene, &s).unwrap().0;
        let b = without.render(&g.ctx, &scene, &s).unwrap().0;
        assert!(
            a.pixels == b.pixels,
            "{method:?}: the file changed the lab's side"
        );
        assert!(a.pixels.iter().any(|p| p.x > 0.0));
    }
    // The file's own calls reach its own functions: its side is all zero.
    let s = RenderSettings::single(64, 48, Method::File);
    let f = with.render(&g.ctx, &scene, &s).unwrap().0;
    assert!(f.pixels.iter().all(|p| *p == glam::DVec3::ZERO));
}

/// A render split into one light over bands of tile rows (the plan of a file at its worst)
/// is the render whole, to the bit: each pixel sums its lights in the same order.
#[test]
fn a_split_render_is_the_whole_render_to_the_bit() {
    let Some(g) = gpu() else {
        return;
    };
    let mut r = PlaneRenderer::new(&g.ctx, Lut::embedded(), ShaderChecks::Checked).unwrap();
    let scene = preset("paper-100");
    let s = RenderSettings::single(80, 72, Method::Ltc);
    let whole = r.render(&g.ctx, &scene, &s).unwrap().0;
    let mut render = r.begin(&g.ctx, &scene, &s, None).unwrap();
    render.poison(&g.ctx);
    let lights = render.light_count();
    let rows = 72u32.div_ceil(16);
    for light in 0..lights {
        for band in 0..rows.div_ceil(2) {
            let first = band * 2;
            render.step_band(&g.ctx, light..light + 1, first..(first + 2).min(rows));
        }
    }
    let split = render.read(&g.ctx).unwrap();
    assert!(split.pixels == whole.pixels, "the split render differs");
}
