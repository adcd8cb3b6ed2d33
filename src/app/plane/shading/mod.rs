//! The lab's renderer: the GPU plane shader on the window's own device, summed across frames
//! in chunks that fit a time budget, shown straight from the GPU (tone-mapped there, never
//! read back); or — where the window has no wgpu device — the CPU reference at a smaller size
//! on a worker thread. The UI thread never waits for a render.

mod cpu;
mod gpu;

use std::time::Duration;

use web_time::Instant;

use crate::app::lab::{Exposure, Lab, parts};
use crate::app::ui::display::ShownImage;
use crate::app::work::cache::{Cached, Own};
use crate::gpu::GpuContext;
use crate::gpu::method_file::MethodFile;
use crate::gpu::plane_render::PlaneRender;
use crate::gpu::target::PendingRead;
use crate::render::{Frame, FrameKind, RenderSettings, View};
use crate::scene::Scene;
use cpu::CpuShading;
use gpu::GpuShading;

/// GPU milliseconds a frame may spend on the plane (and on the chart's measurement): half a
/// 60 Hz frame, leaving the other half to egui's own drawing (and, on a CPU driver, to the UI
/// thread's share of the cores).
pub const FRAME_BUDGET_MS: f64 = 8.0;

/// The largest side the CPU fallback renders: the f64 reference shades ~1e8 light-pixels/s
/// on two cores, so 320 px keeps 100 lights interactive.
pub const CPU_FALLBACK_SIDE: usize = 320;

/// How far the current render is.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Progress {
    /// While the tile lists are being made (culling): how far, 0 to 1.
    pub binning: Option<f32>,
    /// Entries of each pixel's light list summed so far, of `total` (every light).
    pub done: usize,
    pub total: usize,
    /// GPU milliseconds spent on it so far (timestamp queries; 0 without them).
    pub gpu_ms: f64,
    /// UI frames it has taken so far.
    pub frames: usize,
    /// When it started (for the time left).
    pub started: Option<Instant>,
}

/// How long a render runs before the lab says how long it has left.
pub const TIME_LEFT_AFTER: Duration = Duration::from_secs(1);

impl Progress {
    /// While lights are being summed, the factor that scales the partial sum to every light
    /// (`total / done`): a preview of the image, not a dark fraction of it. The lights come in
    /// the scene's order, which the generator scatters over the plane. 1 otherwise.
    pub fn preview_scale(&self) -> f64 {
        let summing = self.binning.is_none() && self.done > 0 && self.done < self.total;
        if summing {
            self.total as f64 / self.done as f64
        } else {
            1.0
        }
    }

    /// The time left at the rate so far, once the render has run `TIME_LEFT_AFTER`.
    pub fn time_left(&self, elapsed: Duration) -> Option<Duration> {
        let known = self.done > 0 && !self.complete() && elapsed >= TIME_LEFT_AFTER;
        known.then(|| elapsed.mul_f64((self.total - self.done) as f64 / self.done as f64))
    }

    pub fn complete(&self) -> bool {
        self.done >= self.total
    }

    /// "3 200 / 20 000 lights, 16%" (or "binning lights into tiles: 40%").
    pub fn describe(&self) -> String {
        if let Some(b) = self.binning {
            return format!("binning lights into tiles: {:.0}%", 100.0 * b);
        }
        let percent = if self.total > 0 {
            100.0 * self.done as f64 / self.total as f64
        } else {
            100.0
        };
        format!(
            "{} / {} lights, {percent:.0}%",
            thousands(self.done),
            thousands(self.total)
        )
    }
}

/// A count with thin spaces between thousands.
pub fn thousands(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (k, c) in digits.chars().enumerate() {
        if k > 0 && (digits.len() - k).is_multiple_of(3) {
            out.push('\u{2009}');
        }
        out.push(c);
    }
    out
}

/// The plane's renderer: on the window's GPU, or the CPU reference where there is none.
pub struct Shading {
    path: Path,
    /// The scene the current render shades, made from the parts it reads with the panel's
    /// settings: made again, the render starts again.
    render: Cached<(Scene, RenderSettings)>,
    /// The tables the GPU's table buffer holds.
    tables: Cached<()>,
    progress: Progress,
    /// An error of the last render, shown over the image.
    error: Option<String>,
    /// The finished image's read-back, on its way (`read`).
    reading: Option<PendingRead>,
    /// Why a method file's render was stopped, for the lab to say (`tell`).
    stopped: Option<String>,
    /// Whether the finished render's image was checked for a method file's stop mark.
    file_checked: bool,
    /// What the device said went wrong, for the lab to say once (`tell`).
    device_note: Option<String>,
}

enum Path {
    Gpu(Box<GpuShading>),
    Cpu(CpuShading),
}

impl Shading {
    /// The renderer on the window's device (`gpu`: the lab's device and the window's
    /// render state), shading the lab's tables; or the CPU, and why not the GPU.
    pub fn new(gpu: Option<(&GpuContext, &egui_wgpu::RenderState)>) -> (Self, Option<String>) {
        let (path, why) = match gpu.map(|(ctx, rs)| GpuShading::new(ctx, rs)) {
            Some(Ok(g)) => (Path::Gpu(Box::new(g)), None),
            Some(Err(e)) => (Path::Cpu(CpuShading::default()), Some(e)),
            None => (Path::Cpu(CpuShading::default()), None),
        };
        let shading = Self {
            path,
            render: Cached::new("plane.render"),
            tables: Cached::new("plane.tables"),
            progress: Progress::default(),
            error: None,
            reading: None,
            stopped: None,
            file_checked: false,
            device_note: None,
        };
        (shading, why)
    }

    /// How far the current render is.
    pub fn progress(&self) -> &Progress {
        &self.progress
    }

    /// An error of the last render.
    pub fn error(&self) -> Option<&str> {
        self.error.as_deref()
    }

    /// Its caches, with their counts.
    pub fn caches(&self) -> [(&'static str, u64); 2] {
        [self.render.count(), self.tables.count()]
    }

    /// One frame's share of the render of the lab's scene as `settings` says: restarted when
    /// either changed, then one chunk within the budget if the last one is done. Never waits.
    pub fn update(
        &mut self,
        ui: &egui::Context,
        lab: &Lab,
        settings: &RenderSettings,
    ) -> ShownImage {
        let (_, before) = self.render.count();
        // The exposure is applied when the image is shown: the sums do not read it.
        let inputs = (
            lab.stage(),
            lab.material(),
            lab.lights(),
            lab.overrides(),
            lab.tables(),
            // A method file loaded again, with other text, renders again.
            Own((*settings, lab.method_file().map(MethodFile::id))),
        );
        self.render.get(
            inputs,
            |(stage, material, lights, overrides, _, Own((s, _)))| {
                let scene = parts::scene(stage, material, lights, &Exposure(1.0));
                (parts::shaded(scene, overrides), s)
            },
        );
        let restart = self.render.count().1 != before || self.watch_device();
        let kind = if settings.view == View::Diff {
            FrameKind::RelativeDifference
        } else {
            FrameKind::Radiance
        };
        let exposure = lab.exposure().0;
        if restart {
            self.restart(ui, lab, kind, exposure);
        }
        let (ready, stopped) = match &mut self.path {
            Path::Gpu(g) => (g.ready(&mut self.progress), g.stopped.take()),
            Path::Cpu(_) => (true, None),
        };
        // A method file's batch past its limit ends the render (`GpuShading::ready`).
        if let Some(why) = stopped {
            self.stop(why);
            self.progress.done = self.progress.total;
        }
        let texture = match &mut self.path {
            Path::Gpu(g) => {
                if self.error.is_none() && !self.progress.complete() && ready {
                    g.chunk(ui, &mut self.progress, kind, exposure);
                }
                if !self.progress.complete() || g.in_flight.is_some() {
                    ui.request_repaint();
                }
                g.show(kind, exposure * self.progress.preview_scale());
                g.texture
            }
            Path::Cpu(cpu) => {
                if cpu.collect(ui, exposure) {
                    self.progress.done = self.progress.total;
                } else {
                    ui.request_repaint();
                }
                cpu.texture.as_ref().map(egui::TextureHandle::id)
            }
        };
        if !self.file_checked
            && self.progress.complete()
            && settings.methods().contains(&crate::render::Method::File)
        {
            self.check_file_mark(ui);
        }
        ShownImage {
            texture,
            size: (settings.width, settings.height),
        }
    }

    /// What the device said went wrong since the last frame (`GpuContext::check`): an error it
    /// reported of the lab's work is shown over the image; a lost device (a watchdog's or a
    /// driver's reset) moves the plane to the CPU, every setting kept. True where the render
    /// must start again (on the CPU).
    fn watch_device(&mut self) -> bool {
        let Path::Gpu(g) = &self.path else {
            return false;
        };
        let Err(e) = g.ctx.check() else {
            return false;
        };
        let lost = g.ctx.failures.lost().is_some();
        if lost {
            self.path = Path::Cpu(CpuShading::default());
            self.device_note = Some(format!(
                "{e}. The plane is shaded on the CPU from now on, every setting kept; open the lab again to shade on the GPU"
            ));
        } else {
            self.error = Some(e.to_string());
            self.device_note = Some(e.to_string());
        }
        lost
    }

    /// Reads the finished image back over frames and says where a method file's loops were
    /// stopped in it (its alpha mark, docs/design.md §5.13).
    fn check_file_mark(&mut self, ui: &egui::Context) {
        let checked = self
            .texels()
            .map(|(render, texels)| render.check_texels(&texels));
        if checked.is_none() && self.reading.is_some() {
            // On its way.
            ui.request_repaint();
            return;
        }
        // Read (or nothing to read: the CPU path, no render).
        self.file_checked = true;
        if let Some(Err(e)) = checked {
            self.stop(e.to_string());
        }
    }

    /// A method file's render stopped: shown over the image, and said by the panel.
    fn stop(&mut self, why: String) {
        self.error = Some(why.clone());
        self.stopped = Some(why);
    }

    /// The GPU render's image as texels, read back over frames (`None` while on its way, and
    /// on the CPU path), with the render they belong to.
    fn texels(&mut self) -> Option<(&PlaneRender, Vec<u8>)> {
        let Path::Gpu(g) = &mut self.path else {
            return None;
        };
        let render = g.render.as_ref()?;
        let pending = self
            .reading
            .get_or_insert_with(|| render.start_read(&g.ctx));
        let texels = pending.try_take(&g.ctx)?;
        self.reading = None;
        Some((render, texels))
    }

    /// What the render has to tell the lab, once: a method file's stop (the lab puts its side
    /// back to the lab's form and says why) and what the device said went wrong
    /// (`watch_device`).
    pub fn tell(&mut self, lab: &mut Lab) {
        if let Some(why) = self.stopped.take() {
            lab.stop_method_file(&why);
        }
        if let Some(note) = self.device_note.take() {
            lab.say(crate::app::lab::Message::error(note));
        }
    }

    /// Starts the render afresh (the tables brought up to date first).
    fn restart(&mut self, ui: &egui::Context, lab: &Lab, kind: FrameKind, exposure: f64) {
        let Some((scene, settings)) = self.render.last() else {
            return;
        };
        let (scene, settings) = (scene.clone(), *settings);
        let settings = &settings;
        self.error = None;
        self.reading = None;
        self.file_checked = false;
        let tables = &lab.tables().named;
        match &mut self.path {
            Path::Gpu(g) => {
                let (_, before) = self.tables.count();
                self.tables.get(lab.tables(), |_| ());
                if self.tables.count().1 != before {
                    self.error = g.set_tables(tables).err();
                }
                if self.error.is_none() {
                    // The method file, where a side names it (the same file keeps the module).
                    self.error = g
                        .renderer
                        .set_method_file(&g.ctx, lab.method_file().cloned())
                        .err()
                        .map(|e| e.to_string());
                }
                if self.error.is_none() {
                    self.error = g.begin(&scene, settings).err();
                }
                self.progress = Progress {
                    total: g.render.as_ref().map_or(0, PlaneRender::light_count),
                    binning: g.render.as_ref().and_then(PlaneRender::binning_progress),
                    started: Some(Instant::now()),
                    ..Progress::default()
                };
                // No lights: nothing to sum, but the last image must go. One empty chunk
                // resolves the cleared sums: the plane black, as it is.
                if self.error.is_none() && self.progress.total == 0 {
                    g.chunk(ui, &mut self.progress, kind, exposure);
                }
            }
            Path::Cpu(_) if settings.methods().contains(&crate::render::Method::File) => {
                self.error = Some("a method file runs on the GPU only".into());
            }
            Path::Cpu(cpu) => {
                self.progress = Progress {
                    total: scene.lights.len(),
                    started: Some(Instant::now()),
                    ..Progress::default()
                };
                cpu.start(ui, scene, settings, tables);
            }
        }
    }

    /// The method file's value of each light at the image point `at` (0–1) of the current
    /// render, evaluated on the GPU (the pixel inspector, docs/design.md §5.13); `None` where
    /// no side shades with a file, on the CPU, and in the browser (which cannot wait).
    pub fn probe_file(&mut self, at: [f64; 2]) -> Option<Result<Option<Vec<glam::DVec3>>, String>> {
        if cfg!(target_arch = "wasm32") {
            return None;
        }
        let (scene, settings) = self.render.last()?;
        let Path::Gpu(g) = &mut self.path else {
            return None;
        };
        if !settings.methods().contains(&crate::render::Method::File) {
            return None;
        }
        // The renderer holds the render's file: a file loaded since has restarted the render.
        Some(
            g.renderer
                .probe_file(&g.ctx, scene, settings, at)
                .map_err(|e| e.to_string()),
        )
    }

    /// Whether the current render is still being summed.
    pub fn in_flight(&self) -> bool {
        !self.progress.complete()
    }

    /// Whether the finished image's read-back is on its way (`read` will have it).
    pub fn read_pending(&self) -> bool {
        self.reading.is_some()
    }

    /// The finished image, read back (for saving an EXR, finding the worst pixel); `None`
    /// while in flight, and while the GPU's copy is on its way back: nothing waits (the
    /// browser cannot), so the caller asks again in a later frame.
    pub fn read(&mut self) -> Option<Frame> {
        if self.in_flight() {
            return None;
        }
        if let Path::Cpu(cpu) = &self.path {
            return cpu.frame.clone();
        }
        let (render, texels) = self.texels()?;
        Some(render.frame_of(&texels))
    }
}
