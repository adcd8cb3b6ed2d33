//! LTC Lab in a browser (issue 21): the desktop lab's `LabApp`, started on the page's canvas
//! by eframe's `WebRunner`. On WebGPU the plane is shaded by the same compute shaders; where
//! the browser has only WebGL2 the lab falls back to the CPU reference, as it does on a
//! desktop without an adapter. `web/index.html` is the page.

#![cfg(target_arch = "wasm32")]

use wasm_bindgen::prelude::*;

/// Starts the lab on the canvas `#lab`; a failure is shown in the page's `#status` element
/// instead of a blank page.
#[wasm_bindgen(start)]
pub fn start() {
    eframe::WebLogger::init(log::LevelFilter::Warn).ok();
    wasm_bindgen_futures::spawn_local(async {
        if let Err(why) = run().await {
            say(&format!("The lab could not start: {why}"));
        }
    });
}

async fn run() -> Result<(), String> {
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document")?;
    let canvas = document
        .get_element_by_id("lab")
        .ok_or("the page has no canvas #lab")?
        .dyn_into::<web_sys::HtmlCanvasElement>()
        .map_err(|_| "#lab is not a canvas")?;
    let options = eframe::WebOptions {
        wgpu_options: eframe::egui_wgpu::WgpuConfiguration {
            wgpu_setup: ltc_lab::app::shading::wgpu_setup(),
            ..Default::default()
        },
        ..Default::default()
    };
    eframe::WebRunner::new()
        .start(
            canvas,
            options,
            Box::new(|cc| Ok(Box::new(ltc_lab::app::LabApp::from_creation_context(cc)))),
        )
        .await
        .map_err(|e| format!("{e:?}"))?;
    say("");
    Ok(())
}

/// Shows `text` in the page's `#status` element (hidden when empty).
fn say(text: &str) {
    let status = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.get_element_by_id("status"));
    if let Some(el) = status {
        el.set_text_content(Some(text));
        let _ = el.set_attribute("style", if text.is_empty() { "display:none" } else { "" });
    }
}
