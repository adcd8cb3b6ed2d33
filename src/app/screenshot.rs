//! Saving the window: a screenshot the user asked for (the side panel's button), and the
//! screenshot mode of `ltc-lab lab --screenshot`, which shows a few frames, saves and exits.

use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use crate::app::panel::PanelId;
use crate::app::report::Report;
use crate::error::Error;

type Slot = Arc<Mutex<Option<Arc<egui::ColorImage>>>>;

/// A requested screenshot: the file the user named, and the slot eframe's callback fills.
pub struct PendingScreenshot {
    pub path: PathBuf,
    requested: bool,
    slot: Slot,
}

impl PendingScreenshot {
    pub fn new(path: PathBuf) -> Self {
        Self {
            path,
            requested: false,
            slot: Slot::default(),
        }
    }

    /// Asks for the window's pixels, then saves them once they arrive: `None` while waiting,
    /// then the outcome (what was saved, or why not).
    pub fn poll(&mut self, ctx: &egui::Context) -> Option<Result<String, Error>> {
        if !self.requested {
            let slot = self.slot.clone();
            ctx.request_screenshot(move |image| *slot.lock().expect("not poisoned") = Some(image));
            self.requested = true;
            ctx.request_repaint();
            return None;
        }
        let Some(image) = self.slot.lock().expect("not poisoned").take() else {
            ctx.request_repaint();
            return None;
        };
        Some(self.save(&image))
    }

    /// A file that cannot be written is the path's fault (`Error::io` says which), as in
    /// every command; an image that cannot be encoded is the machine's. In a browser, a
    /// download.
    fn save(&self, image: &egui::ColorImage) -> Result<String, Error> {
        let name = self.path.display().to_string();
        let rgba = image::RgbaImage::from_raw(
            image.width() as u32,
            image.height() as u32,
            image.as_raw().to_vec(),
        )
        .ok_or_else(|| Error::machine(&name, "the screenshot had an unexpected size"))?;
        let mut png = std::io::Cursor::new(Vec::new());
        rgba.write_to(&mut png, image::ImageFormat::Png)
            .map_err(|e| Error::machine(&name, format!("cannot encode the PNG: {e}")))?;
        crate::app::files::save(&self.path, &png.into_inner(), "image/png")
            .map_err(|why| Error::input(&name, why))
    }
}

/// Frames drawn before the screenshot: textures uploaded, layout settled (egui lays out
/// sizes on the first frame and draws on the second).
pub const SCREENSHOT_AFTER_FRAMES: u32 = 4;

/// How long the screenshot waits for the window's work to finish before it gives up: a
/// 20 000-light plane fills in under a minute on a CPU driver; ten leave room for a slow one.
pub const SETTLE_TIMEOUT: std::time::Duration = std::time::Duration::from_secs(600);

/// What the screenshot mode asks of the app it shows.
pub trait Settling {
    /// Whether anything is still being computed for the window.
    fn busy(&self) -> bool;
    /// The app as the last frame left it (for the frame log).
    fn report(&self) -> Report;
}

/// One row of the frame log.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameRecord {
    pub frame: usize,
    /// Wall-clock milliseconds since the previous UI frame began (the first: since start).
    pub ms: f64,
    pub render_in_flight: bool,
    pub lights_done: usize,
    pub lights_total: usize,
    /// Milliseconds in the app's own `ui` (our panels and egui's layout of their widgets;
    /// not egui's tessellation, the GPU's painting or the window's present, which follow it).
    pub ui_ms: f64,
    /// Of those, each panel's, in `PanelId::ALL`'s order.
    pub part_ms: Vec<f64>,
    /// The caches made again in the frame.
    pub remade: Vec<&'static str>,
}

/// The frame log as CSV: `frame,ms,render_in_flight,lights_done,lights_total,ui_ms`, then a
/// column per panel (`controls_ms`, `lobe_ms`, …), then `remade`: the caches made again,
/// separated by spaces.
pub fn frame_log_csv(records: &[FrameRecord]) -> String {
    let parts: Vec<String> = PanelId::ALL
        .iter()
        .map(|p| format!(",{}_ms", p.name()))
        .collect();
    let mut out = format!(
        "frame,ms,render_in_flight,lights_done,lights_total,ui_ms{},remade\n",
        parts.concat()
    );
    for r in records {
        let parts: Vec<String> = r.part_ms.iter().map(|ms| format!(",{ms:.3}")).collect();
        out.push_str(&format!(
            "{},{:.3},{},{},{},{:.3}{},{}\n",
            r.frame,
            r.ms,
            u8::from(r.render_in_flight),
            r.lights_done,
            r.lights_total,
            r.ui_ms,
            parts.concat(),
            r.remade.join(" ")
        ));
    }
    out
}

/// `ltc-lab lab --screenshot`: shows `app` until its work is done (at least a few frames),
/// saves the window to `path` and closes it; the outcome is left in `result`, and every UI
/// frame in `frames` for the frame log.
pub struct ScreenshotApp<A> {
    pub app: A,
    pending: PendingScreenshot,
    started: web_time::Instant,
    last_frame: Option<web_time::Instant>,
    pub frames: Arc<Mutex<Vec<FrameRecord>>>,
    pub result: Arc<Mutex<Option<Result<(), Error>>>>,
}

impl<A> ScreenshotApp<A> {
    pub fn new(app: A, path: PathBuf) -> Self {
        Self {
            app,
            pending: PendingScreenshot::new(path),
            started: web_time::Instant::now(),
            last_frame: None,
            frames: Arc::default(),
            result: Arc::default(),
        }
    }
}

impl<A: eframe::App + Settling> eframe::App for ScreenshotApp<A> {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        let now = web_time::Instant::now();
        let ms = now
            .duration_since(self.last_frame.unwrap_or(self.started))
            .as_secs_f64()
            * 1e3;
        self.last_frame = Some(now);
        self.app.ui(ui, frame);
        let ui_ms = now.elapsed().as_secs_f64() * 1e3;
        let ctx = ui.ctx().clone();
        let report = self.app.report();
        let [lights_done, lights_total] = report.plane;
        let busy = self.app.busy();
        let count = {
            let mut frames = self.frames.lock().expect("not poisoned");
            let record = FrameRecord {
                frame: frames.len(),
                ms,
                render_in_flight: busy,
                lights_done,
                lights_total,
                ui_ms,
                part_ms: report.part_ms,
                remade: report.remade,
            };
            frames.push(record);
            frames.len()
        };
        let timed_out = self.started.elapsed() > SETTLE_TIMEOUT;
        if timed_out && busy {
            *self.result.lock().expect("not poisoned") = Some(Err(Error::machine(
                "lab",
                format!(
                    "the window was still busy after {} s",
                    SETTLE_TIMEOUT.as_secs()
                ),
            )));
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        } else if count >= SCREENSHOT_AFTER_FRAMES as usize
            && !busy
            && let Some(outcome) = self.pending.poll(&ctx)
        {
            *self.result.lock().expect("not poisoned") = Some(outcome.map(|_| ()));
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
        ctx.request_repaint();
    }
}
