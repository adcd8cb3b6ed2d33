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
use serde::Serialize;

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
        setup.adapter.get_downlevel_capabilities().flags,
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

/// What `#selfcheck` holds: `backend` "webgpu" or "webgl2"; on WebGPU the largest relative
/// difference from the CPU reference over the methods, against the parity tolerance.
#[derive(Serialize, Default)]
struct CheckReport {
    backend: &'static str,
    adapter: Option<String>,
    max_rel_diff: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    tolerance: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    passed: Option<bool>,
    first_frame_ms: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    total_ms: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    size: Option<[usize; 2]>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    methods: Vec<MethodReport>,
    #[serde(skip_serializing_if = "Option::is_none")]
    note: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<String>,
}

#[derive(Serialize)]
struct MethodReport {
    method: &'static str,
    max_rel_diff: f64,
    silhouette: usize,
}

impl CheckReport {
    fn json(&self) -> String {
        serde_json::to_string(self).unwrap_or_else(|e| {
            serde_json::json!({ "error": format!("the report does not serialize: {e}") })
                .to_string()
        })
    }
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
                let methods = report
                    .methods
                    .iter()
                    .map(|m| MethodReport {
                        method: m.method.name(),
                        max_rel_diff: m.parity.max_rel_diff,
                        silhouette: m.parity.silhouette,
                    })
                    .collect();
                return CheckReport {
                    backend: "webgpu",
                    adapter: Some(report.adapter.clone()),
                    max_rel_diff: Some(report.max_rel_diff()),
                    tolerance: Some(ltc_lab::measure::parity::RADIANCE_TOLERANCE),
                    passed: Some(report.check().is_ok()),
                    first_frame_ms: first_frame_ms.map(f64::round),
                    total_ms: Some(browser::now_ms().round()),
                    size: Some([SIZE.0, SIZE.1]),
                    methods,
                    ..CheckReport::default()
                }
                .json();
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
    CheckReport {
        backend: "webgl2",
        first_frame_ms: Some(browser::now_ms().round()),
        note: Some(format!(
            "{why}: the plane is shaded on the CPU, nothing to compare"
        )),
        ..CheckReport::default()
    }
    .json()
}

fn failed(backend: &'static str, adapter: &str, why: &str) -> String {
    CheckReport {
        backend,
        adapter: Some(adapter.to_owned()),
        passed: Some(false),
        error: Some(why.to_owned()),
        ..CheckReport::default()
    }
    .json()
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
