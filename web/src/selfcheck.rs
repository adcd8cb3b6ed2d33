//! `index.html#selfcheck` (docs/design.md §5.8): the library's self-check
//! (`ltc_lab::gpu::selfcheck`) on the browser's WebGPU device, stepped once per turn of the
//! event loop, its result written as JSON into the page's `<pre id="selfcheck">`:
//! `{"backend", "adapter", "max_rel_diff", "first_frame_ms", …}`. Where the browser has no
//! WebGPU the lab shades on the CPU (WebGL2 has no compute shaders): the page then reports
//! `"backend": "webgl2"`, no GPU difference, and the CPU's time to the same image.

use eframe::egui_wgpu::wgpu;
use ltc_lab::app::browser;
use ltc_lab::gpu::GpuContext;
use ltc_lab::gpu::selfcheck::{METHODS, SIZE, SelfCheck};
use ltc_lab::render::RenderSettings;

use crate::page::json_string;

pub async fn run() -> Result<(), String> {
    crate::page::say("Running the self-check…");
    let json = match webgpu().await {
        Ok(ctx) => gpu_check(ctx).await,
        Err(why) => cpu_check(&why),
    };
    browser::write_element("selfcheck", &json);
    crate::page::say("");
    Ok(())
}

/// The browser's WebGPU device, with what the lab asks of a device; why not where there is
/// none.
async fn webgpu() -> Result<GpuContext, String> {
    let setup = webgpu_setup().await?;
    Ok(GpuContext::from_parts(
        setup.device,
        setup.queue,
        setup.adapter.get_info(),
    ))
}

/// The browser's WebGPU instance, adapter and device.
async fn webgpu_setup() -> Result<eframe::egui_wgpu::WgpuSetupExisting, String> {
    let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
    desc.backends = wgpu::Backends::BROWSER_WEBGPU;
    let instance = wgpu::Instance::new(desc);
    let adapter = instance
        .request_adapter(&wgpu::RequestAdapterOptions::default())
        .await
        .map_err(|e| format!("no WebGPU adapter ({e})"))?;
    let (device, queue) = adapter
        .request_device(&ltc_lab::gpu::device_descriptor(&adapter))
        .await
        .map_err(|e| format!("the WebGPU device would not open ({e})"))?;
    Ok(eframe::egui_wgpu::WgpuSetupExisting {
        instance,
        adapter,
        device,
        queue,
    })
}

async fn gpu_check(ctx: GpuContext) -> String {
    let adapter = ctx.describe();
    let mut check = match SelfCheck::new(ctx) {
        Ok(c) => c,
        Err(why) => return failed("webgpu", &adapter, &why),
    };
    let mut first_frame_ms = None;
    loop {
        match check.step() {
            Ok(Some(report)) => {
                let methods: Vec<String> = report
                    .methods
                    .iter()
                    .map(|m| {
                        format!(
                            "{{\"method\": \"{}\", \"max_rel_diff\": {:e}, \"silhouette\": {}}}",
                            m.method.name(),
                            m.parity.max_rel_diff,
                            m.parity.silhouette
                        )
                    })
                    .collect();
                return format!(
                    "{{\"backend\": \"webgpu\", \"adapter\": {}, \"max_rel_diff\": {:e}, \"tolerance\": {:e}, \"passed\": {}, \"first_frame_ms\": {:.0}, \"total_ms\": {:.0}, \"size\": [{}, {}], \"methods\": [{}]}}",
                    json_string(&report.adapter),
                    report.max_rel_diff(),
                    ltc_lab::parity::RADIANCE_TOLERANCE,
                    report.check().is_ok(),
                    first_frame_ms.unwrap_or(f64::NAN),
                    browser::now_ms(),
                    SIZE.0,
                    SIZE.1,
                    methods.join(", ")
                );
            }
            Ok(None) => {}
            Err(why) => return failed("webgpu", &adapter, &why),
        }
        if first_frame_ms.is_none() && check.frames_read() > 0 {
            first_frame_ms = Some(browser::now_ms());
        }
        next_turn().await;
    }
}

/// Without WebGPU: the CPU reference's time to the self-check's first image, as the lab
/// draws its plane on WebGL2.
fn cpu_check(why: &str) -> String {
    let scene = ltc_lab::scene::preset("paper-100");
    let lut = ltc_lab::ltc::lut::Lut::embedded();
    let _ = ltc_lab::cpu::render(
        &scene,
        lut,
        &RenderSettings::single(SIZE.0, SIZE.1, METHODS[0]),
    );
    format!(
        "{{\"backend\": \"webgl2\", \"adapter\": null, \"max_rel_diff\": null, \"first_frame_ms\": {:.0}, \"note\": {}}}",
        browser::now_ms(),
        json_string(&format!(
            "{why}: the plane is shaded on the CPU, nothing to compare"
        ))
    )
}

fn failed(backend: &str, adapter: &str, why: &str) -> String {
    format!(
        "{{\"backend\": \"{backend}\", \"adapter\": {}, \"max_rel_diff\": null, \"first_frame_ms\": null, \"passed\": false, \"error\": {}}}",
        json_string(adapter),
        json_string(why)
    )
}

/// Yields to the browser's event loop (where the device's work completes and a read-back's
/// mapping lands) until its next turn.
async fn next_turn() {
    let promise = js_sys::Promise::new(&mut |resolve, _| {
        if let Some(w) = web_sys::window() {
            let _ = w.set_timeout_with_callback_and_timeout_and_arguments_0(&resolve, 0);
        }
    });
    let _ = wasm_bindgen_futures::JsFuture::from(promise).await;
}
