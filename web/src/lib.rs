//! LTC Lab in a browser (docs/design.md §5.8): the desktop lab's `LabApp`, started
//! on the page's canvas by eframe's `WebRunner`. On WebGPU the plane is shaded by the same
//! compute shaders; where the browser has only WebGL2 the lab falls back to the CPU
//! reference, as it does on a desktop without an adapter. `index.html#view=…` opens a shared
//! view; `index.html#selfcheck` runs the self-check instead of the lab; `index.html?texts`
//! also maps the texts drawn, for tools (`texts.rs`). `web/index.html` is the page.

#![cfg(target_arch = "wasm32")]

mod page;
mod selfcheck;
mod texts;

use ltc_lab::app::browser;
use wasm_bindgen::prelude::*;

thread_local! {
    /// The lab's runner, kept for the page's lifetime.
    static RUNNER: std::cell::RefCell<Option<eframe::WebRunner>> = const { std::cell::RefCell::new(None) };
}

/// Starts the lab on the canvas `#lab` (or the self-check); a failure is shown in the page's
/// `#status` element instead of a blank page.
#[wasm_bindgen(start)]
pub fn start() {
    eframe::WebLogger::init(log::LevelFilter::Warn).ok();
    wasm_bindgen_futures::spawn_local(async {
        let run = if browser::fragment() == "selfcheck" {
            selfcheck::run().await
        } else {
            run().await
        };
        if let Err(why) = run {
            page::say(&format!("The lab could not start: {why}"));
        }
    });
}

async fn run() -> Result<(), String> {
    let canvas = page::canvas()?;
    let options = eframe::WebOptions {
        wgpu_options: eframe::egui_wgpu::WgpuConfiguration {
            wgpu_setup: ltc_lab::app::device::wgpu_setup(),
            ..Default::default()
        },
        ..Default::default()
    };
    let runner = eframe::WebRunner::new();
    runner
        .start(
            canvas,
            options,
            Box::new(|cc| Ok(Box::new(page::PageLab::new(cc)))),
        )
        .await
        .map_err(|e| format!("{e:?}"))?;
    RUNNER.with(|r| *r.borrow_mut() = Some(runner));
    page::say("");
    Ok(())
}
