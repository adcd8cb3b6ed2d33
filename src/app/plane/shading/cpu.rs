//! The plane on the CPU reference, on a worker thread, where the window has no wgpu device:
//! at most `CPU_FALLBACK_SIDE` pixels a side, encoded for the window with the same tone map.

use std::sync::Arc;
use std::sync::mpsc;

use web_time::Instant;

use crate::app::work::pacer::Pacer;
use crate::render::{Frame, RenderSettings, Tables};
use crate::scene::Scene;
use crate::tables::NamedTables;

use super::{CPU_FALLBACK_SIDE, FRAME_BUDGET_MS};

/// The CPU reference on a worker thread, where there is no GPU.
#[derive(Default)]
pub(super) struct CpuShading {
    pub(super) rx: Option<mpsc::Receiver<Frame>>,
    pub(super) texture: Option<egui::TextureHandle>,
    /// The last finished frame.
    pub(super) frame: Option<Frame>,
    /// The exposure the texture was encoded with (`None`: not encoded yet), so that an
    /// exposure change re-encodes the frame instead of rendering it again.
    pub(super) encoded: Option<f64>,
    /// Held while the current render's steps run; dropped, they stop.
    pub(super) token: Option<Arc<()>>,
}

impl CpuShading {
    /// Starts the CPU render at a reduced size on a worker thread, or over the browser's
    /// frames (a stale one stops, and its result is dropped: only the newest receiver is
    /// read).
    pub(super) fn start(
        &mut self,
        ui: &egui::Context,
        scene: Scene,
        settings: &RenderSettings,
        tables: &NamedTables,
    ) {
        let scale =
            (CPU_FALLBACK_SIDE as f64 / settings.width.max(settings.height) as f64).min(1.0);
        let s = RenderSettings {
            width: ((settings.width as f64 * scale).round() as usize).max(1),
            height: ((settings.height as f64 * scale).round() as usize).max(1),
            ..*settings
        };
        let (tx, rx) = mpsc::channel();
        let repaint = ui.clone();
        let (a, b) = (tables.a.lut.clone(), tables.b.lut.clone());
        // A restarted render stops the one before: its steps see their token gone.
        let token = Arc::new(());
        let current = Arc::downgrade(&token);
        self.token = Some(token);
        let mut bands = crate::cpu::Bands::new(&s);
        let mut pacer = Pacer::default();
        crate::app::work::background::spawn_steps(
            "cpu render",
            Box::new(move || {
                if current.strong_count() == 0 {
                    return true;
                }
                // A thread renders the image whole (its rows in parallel); the browser in
                // bands of rows sized to the frame's budget.
                let rows = if cfg!(target_arch = "wasm32") {
                    pacer.next(FRAME_BUDGET_MS)
                } else {
                    s.height
                };
                let started = Instant::now();
                let frame = bands.step(&scene, Tables { a: &a, b: &b }, rows);
                pacer.record(rows, started.elapsed().as_secs_f64() * 1e3);
                let Some(frame) = frame else {
                    return false;
                };
                let _ = tx.send(frame);
                repaint.request_repaint();
                true
            }),
        );
        self.rx = Some(rx);
    }

    /// Encodes the last frame into the texture where it was encoded with another exposure.
    pub(super) fn encode(&mut self, ui: &egui::Context, exposure: f64) {
        let Some(frame) = &self.frame else {
            return;
        };
        if self.encoded == Some(exposure) {
            return;
        }
        self.encoded = Some(exposure);
        let image = crate::app::ui::display::frame_image(frame, exposure);
        match &mut self.texture {
            Some(t) => t.set(image, egui::TextureOptions::LINEAR),
            None => {
                self.texture = Some(ui.load_texture("plane", image, egui::TextureOptions::LINEAR));
            }
        }
    }

    /// Takes a finished render into the texture; whether the current one is done.
    pub(super) fn collect(&mut self, ui: &egui::Context, exposure: f64) -> bool {
        let Some(rx) = &self.rx else {
            self.encode(ui, exposure);
            return true;
        };
        match rx.try_recv() {
            Ok(frame) => {
                self.frame = Some(frame);
                self.encoded = None;
                self.rx = None;
                self.encode(ui, exposure);
                true
            }
            Err(mpsc::TryRecvError::Empty) => false,
            Err(mpsc::TryRecvError::Disconnected) => {
                self.rx = None;
                true
            }
        }
    }
}
