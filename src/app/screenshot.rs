//! Saving the window: a screenshot the user asked for (the side panel's button), and the
//! screenshot mode of `ltc-lab lab --screenshot`, which shows a few frames, saves and exits.

use std::path::PathBuf;
use std::sync::{Arc, Mutex};

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
    /// then the outcome (the file written, or why not).
    pub fn poll(&mut self, ctx: &egui::Context) -> Option<Result<PathBuf, String>> {
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

    fn save(&self, image: &egui::ColorImage) -> Result<PathBuf, String> {
        let rgba = image::RgbaImage::from_raw(
            image.width() as u32,
            image.height() as u32,
            image.as_raw().to_vec(),
        )
        .ok_or("the screenshot had an unexpected size")?;
        let mut png = std::io::Cursor::new(Vec::new());
        rgba.write_to(&mut png, image::ImageFormat::Png)
            .map_err(|e| format!("{}: {e}", self.path.display()))?;
        crate::files::write_atomically(&self.path, &png.into_inner()).map_err(|e| e.to_string())?;
        Ok(self.path.clone())
    }
}

/// Frames drawn before the screenshot: textures uploaded, layout settled (egui lays out
/// sizes on the first frame and draws on the second).
pub const SCREENSHOT_AFTER_FRAMES: u32 = 4;

/// `ltc-lab lab --screenshot`: shows `app` for a few frames, saves the window to `path` and
/// closes it; the outcome is left in `result` for the command line.
pub struct ScreenshotApp<A> {
    pub app: A,
    pending: PendingScreenshot,
    frames: u32,
    pub result: Arc<Mutex<Option<Result<(), String>>>>,
}

impl<A> ScreenshotApp<A> {
    pub fn new(app: A, path: PathBuf) -> Self {
        Self {
            app,
            pending: PendingScreenshot::new(path),
            frames: 0,
            result: Arc::default(),
        }
    }
}

impl<A: eframe::App> eframe::App for ScreenshotApp<A> {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        self.app.ui(ui, frame);
        let ctx = ui.ctx().clone();
        self.frames += 1;
        if self.frames >= SCREENSHOT_AFTER_FRAMES
            && let Some(outcome) = self.pending.poll(&ctx)
        {
            *self.result.lock().expect("not poisoned") = Some(outcome.map(|_| ()));
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
        ctx.request_repaint();
    }
}
