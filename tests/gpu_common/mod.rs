//! The GPU for tests: skipped loudly where there is no adapter, unless LTC_LAB_REQUIRE_GPU
//! is set (as .ci/run sets it after installing lavapipe), where a missing adapter fails.
#![allow(dead_code)]

use std::sync::{Mutex, OnceLock};

use ltc_lab::gpu::GpuContext;
use ltc_lab::gpu::plane::ShaderChecks;
use ltc_lab::gpu::renderer::PlaneRenderer;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::measure::parity::{Parity, RADIANCE_TOLERANCE};
use ltc_lab::render::Frame;
use wgpu::util::DeviceExt;

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

/// One device for the whole test binary (device creation on lavapipe takes ~100 ms). On
/// OpenGL the calling test first waits for its turn (`take_gl_turn`).
pub fn gpu() -> Option<&'static Gpu> {
    let gpu = shared_gpu();
    if gpu.is_some_and(|g| g.ctx.info.backend == wgpu::Backend::Gl) {
        take_gl_turn();
    }
    gpu
}

/// On OpenGL the tests take turns with the device, each for the rest of its thread (libtest
/// runs every test on a thread of its own), its drops included. wgpu's GL backend has one
/// context for every thread, which a pipeline holds while Mesa compiles it (a few seconds for
/// the renders' exact rule on llvmpipe), and a thread that waits for it more than 6 s panics
/// (wgpu-hal's `CONTEXT_LOCK_TIMEOUT_SECS`); a panic in a drop aborts the whole test binary.
/// Vulkan has no such lock, and its tests run side by side.
fn take_gl_turn() {
    static TURN: Mutex<()> = Mutex::new(());
    thread_local! {
        static HELD: std::cell::RefCell<Option<std::sync::MutexGuard<'static, ()>>> =
            const { std::cell::RefCell::new(None) };
    }
    HELD.with_borrow_mut(|held| {
        if held.is_none() {
            // A test that failed in its turn leaves the lock poisoned; the device is whole.
            *held = Some(
                TURN.lock()
                    .unwrap_or_else(std::sync::PoisonError::into_inner),
            );
        }
    });
}

fn shared_gpu() -> Option<&'static Gpu> {
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
/// tolerance (`ltc_lab::measure::parity`, which says where it comes from).
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

/// Runs the compute entry point `probe` of `source` on the tests' device: `input` at binding
/// 0, `outputs` vec4s out at binding 1, `more` at bindings 2…, with the override `constants`;
/// the vec4s come back. How the tests measure a WGSL function directly.
pub fn run_probe(
    source: &str,
    constants: &[(&str, f64)],
    input: &[u8],
    more: &[&[u8]],
    outputs: usize,
) -> Vec<[f32; 4]> {
    let g = gpu().expect("a probe runs where there is an adapter");
    let (device, queue) = (&g.ctx.device, &g.ctx.queue);
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("probe"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: None,
        layout: None,
        module: &module,
        entry_point: Some("probe"),
        compilation_options: wgpu::PipelineCompilationOptions {
            constants,
            ..Default::default()
        },
        cache: None,
    });
    let storage = |contents: &[u8]| {
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: None,
            contents,
            usage: wgpu::BufferUsages::STORAGE,
        })
    };
    let out_size = (outputs * 16) as u64;
    let buffer = |usage| {
        device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: out_size,
            usage,
            mapped_at_creation: false,
        })
    };
    let out = buffer(wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC);
    let read = buffer(wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST);
    let inputs: Vec<wgpu::Buffer> = std::iter::once(input)
        .chain(more.iter().copied())
        .map(storage)
        .collect();
    let mut entries = vec![
        wgpu::BindGroupEntry {
            binding: 0,
            resource: inputs[0].as_entire_binding(),
        },
        wgpu::BindGroupEntry {
            binding: 1,
            resource: out.as_entire_binding(),
        },
    ];
    for (k, b) in inputs.iter().enumerate().skip(1) {
        entries.push(wgpu::BindGroupEntry {
            binding: k as u32 + 1,
            resource: b.as_entire_binding(),
        });
    }
    let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &entries,
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind, &[]);
        pass.dispatch_workgroups((outputs as u32).div_ceil(64), 1, 1);
    }
    encoder.copy_buffer_to_buffer(&out, 0, &read, 0, out_size);
    queue.submit([encoder.finish()]);
    read.slice(..).map_async(wgpu::MapMode::Read, |_| {});
    let _ = device.poll(wgpu::PollType::wait_indefinitely());
    let data = read.slice(..).get_mapped_range().unwrap();
    bytemuck::cast_slice(&data).to_vec()
}

/// `s` rendered on the tests' device.
pub fn gpu_frame(
    scene: &ltc_lab::scene::Scene,
    s: &ltc_lab::render::RenderSettings,
) -> ltc_lab::render::Frame {
    let g = gpu().expect("an adapter");
    g.renderer
        .lock()
        .unwrap()
        .render(&g.ctx, scene, s)
        .unwrap()
        .0
}

/// A unit vector of the given elevation and azimuth (the probes' light directions).
pub fn direction(elevation: f64, azimuth: f64) -> glam::DVec3 {
    glam::DVec3::new(
        elevation.cos() * azimuth.cos(),
        elevation.cos() * azimuth.sin(),
        elevation.sin(),
    )
}

/// An upper bound on the condition number of `M⁻¹`: `‖M⁻¹‖·‖M‖` in Frobenius norms.
pub fn condition(lobe: &ltc_lab::ltc::Ltc) -> f64 {
    let norm = |m: glam::DMat3| m.to_cols_array().iter().map(|x| x * x).sum::<f64>().sqrt();
    norm(lobe.cos_from_brdf) * norm(lobe.brdf_from_cos)
}

/// Each failure preset of `kind` rendered with each of the shape's methods as side A's
/// method for it, beside each point form, then the lab's opening split: the GPU against the
/// CPU, finite, never negative, within the renders' parity tolerance. The shapes' preset
/// tests (rects, disks) are this loop.
pub fn assert_shape_presets_match(kind: ltc_lab::light::ShapeKind) {
    use ltc_lab::render::{Method, RenderSettings, ShapeMethod, View};
    for (preset, _) in ltc_lab::scene::shape_presets(kind) {
        let scene = ltc_lab::scene::preset(preset);
        for method in [Method::Brdf, Method::LtcFast] {
            for m in ShapeMethod::all(kind) {
                let single = RenderSettings::single(48, 40, method);
                let s = RenderSettings {
                    a: single.a.with(m),
                    ..single
                };
                let what = format!("{preset} {} {}", method.name(), m.name());
                let gpu = gpu_frame(&scene, &s);
                assert_eq!(gpu.first_invalid(s.rules.clipping), None, "{what}");
                let cpu = ltc_lab::cpu::render(&scene, Lut::embedded(), &s);
                assert_close(&what, &gpu, &cpu);
            }
        }
        let s = RenderSettings::compare(48, 40, View::Split);
        let cpu = ltc_lab::cpu::render(&scene, Lut::embedded(), &s);
        let gpu = gpu_frame(&scene, &s);
        assert_close(&format!("{preset} split"), &gpu, &cpu);
    }
}

/// The lights' shaders a probe composes its `tail` after: the BRDF's and the LTC's, each
/// shape's file and the exact rule they share (`gpu::light::sources`).
pub fn lights_probe_source(tail: &str) -> String {
    use ltc_lab::gpu::{brdf, brdf_aniso, light, ltc};
    [
        brdf::SOURCE,
        brdf_aniso::SOURCE,
        ltc::SOURCE,
        &light::sources(),
        tail,
    ]
    .join("\n")
}

/// A probe's reader of an LTC lobe packed by `pack_pair` (four vec4s from `probe_in[k]`):
/// composed into the probe shaders after their `probe_in` binding.
pub const PROBE_LTC: &str = "
fn probe_ltc(k: u32) -> Ltc {
    let m = mat3x3<f32>(probe_in[k].xyz, probe_in[k + 1u].xyz, probe_in[k + 2u].xyz);
    let c = probe_in[k + 3u];
    return Ltc(m, c.x, c.y, c.z, c.w);
}
";

/// Both lobes of `pair` as `PROBE_LTC` reads them: per lobe M⁻¹'s columns, then
/// (det M⁻¹, norm, fresnel, scale); the specular lobe first.
pub fn pack_pair(pair: &ltc_lab::ltc::LtcPair) -> Vec<[f32; 4]> {
    let f = |x: f64| x as f32;
    [&pair.spec, &pair.diff]
        .into_iter()
        .flat_map(|l| {
            let m = l.cos_from_brdf;
            let col = |v: glam::DVec3| [f(v.x), f(v.y), f(v.z), 0.0];
            [
                col(m.x_axis),
                col(m.y_axis),
                col(m.z_axis),
                [f(l.det_cos_from_brdf), f(l.norm), f(l.fresnel), f(l.scale)],
            ]
        })
        .collect()
}
