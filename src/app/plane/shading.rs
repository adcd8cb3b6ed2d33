//! The lab's renderer: the GPU plane shader on the window's own device, summed across frames
//! in chunks that fit a time budget, shown straight from the GPU (tone-mapped there, never
//! read back); or — where the window has no wgpu device — the CPU reference at a smaller size
//! on a worker thread. The UI thread never waits for a render.

use std::sync::Arc;
use std::sync::mpsc;
use std::time::Duration;

use web_time::Instant;

use crate::app::lab::{Exposure, Lab, parts};
use crate::app::ui::display::ShownImage;
use crate::app::work::cache::{Cached, Own};
use crate::app::work::completion::{Chunk, Completion};
use crate::app::work::pacer::Pacer;
use crate::gpu::GpuContext;
use crate::gpu::display::DisplayPass;
use crate::gpu::plane::ShaderChecks;
use crate::gpu::plane_render::PlaneRender;
use crate::gpu::renderer::PlaneRenderer;
use crate::gpu::target::PendingRead;
use crate::gpu::timing::FrameTimes;
use crate::render::{Frame, FrameKind, RenderSettings, Tables, View};
use crate::scene::Scene;
use crate::tables::NamedTables;

/// GPU milliseconds a frame may spend on the plane (and on the chart's measurement): half a
/// 60 Hz frame, leaving the other half to egui's own drawing (and, on a CPU driver, to the UI
/// thread's share of the cores).
pub const FRAME_BUDGET_MS: f64 = 8.0;

/// The largest side the CPU fallback renders: the f64 reference shades ~1e8 light-pixels/s
/// on two cores, so 320 px keeps 100 lights interactive.
pub const CPU_FALLBACK_SIDE: usize = 320;

/// What a chunk does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Work {
    Bin,
    Shade,
}

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
}

enum Path {
    Gpu(Box<GpuShading>),
    Cpu(CpuShading),
}

/// The plane on the window's device.
struct GpuShading {
    ctx: GpuContext,
    renderer: PlaneRenderer,
    /// The current render, once one has begun.
    render: Option<PlaneRender>,
    display: DisplayPass,
    egui: egui_wgpu::RenderState,
    texture: Option<egui::TextureId>,
    /// When the last chunk's work was done, by the wall clock (made with the first chunk,
    /// which brings the window to wake).
    completion: Option<Completion>,
    /// Whether chunks are paced on timestamp queries (a discrete or integrated GPU that has
    /// them) or on the wall clock (a CPU driver, or no queries).
    paced_on_timestamps: bool,
    /// Sizes the chunks of lights and of binning from their times.
    shade_pacer: Pacer,
    bin_pacer: Pacer,
    /// The chunk in flight, if any.
    in_flight: Option<InFlight>,
    /// How the shown image was last made from the sums (a change re-encodes it).
    shown: Option<(FrameKind, f64)>,
}

/// A chunk submitted and not yet timed.
struct InFlight {
    work: Work,
    /// Its size, for its pacer: tile rows or list entries.
    units: usize,
    /// Submission to completion, once the waiter has seen it done.
    wall_ms: Option<f64>,
    /// Whether it belongs to a render since restarted (its time says nothing of the new one).
    stale: bool,
}

/// The CPU reference on a worker thread, where there is no GPU.
#[derive(Default)]
struct CpuShading {
    rx: Option<mpsc::Receiver<Frame>>,
    texture: Option<egui::TextureHandle>,
    /// The last finished frame.
    frame: Option<Frame>,
    /// The exposure the texture was encoded with (`None`: not encoded yet), so that an
    /// exposure change re-encodes the frame instead of rendering it again.
    encoded: Option<f64>,
    /// Held while the current render's steps run; dropped, they stop.
    token: Option<Arc<()>>,
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
            Own(*settings),
        );
        self.render
            .get(inputs, |(stage, material, lights, overrides, _, Own(s))| {
                let scene = parts::scene(stage, material, lights, &Exposure(1.0));
                (parts::shaded(scene, overrides), s)
            });
        let restart = self.render.count().1 != before;
        let kind = if settings.view == View::Diff {
            FrameKind::RelativeDifference
        } else {
            FrameKind::Radiance
        };
        let exposure = lab.exposure().0;
        if restart {
            self.restart(ui, lab, kind, exposure);
        }
        let texture = match &mut self.path {
            Path::Gpu(g) => {
                let ready = g.ready(&mut self.progress);
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
        ShownImage {
            texture,
            size: (settings.width, settings.height),
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
        let tables = &lab.tables().named;
        match &mut self.path {
            Path::Gpu(g) => {
                let (_, before) = self.tables.count();
                self.tables.get(lab.tables(), |_| ());
                if self.tables.count().1 != before {
                    self.error = g.set_tables(tables).err();
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
        match &mut self.path {
            Path::Gpu(g) => {
                let render = g.render.as_ref()?;
                let pending = self
                    .reading
                    .get_or_insert_with(|| render.start_read(&g.ctx));
                let texels = pending.try_take(&g.ctx)?;
                self.reading = None;
                Some(render.frame_of(&texels))
            }
            Path::Cpu(cpu) => cpu.frame.clone(),
        }
    }
}

impl GpuShading {
    fn new(ctx: &GpuContext, rs: &egui_wgpu::RenderState) -> Result<Self, String> {
        let ctx = ctx.clone();
        // The shipped table until the first render's tables are set.
        let lut = crate::ltc::lut::Lut::embedded();
        let renderer =
            PlaneRenderer::new(&ctx, lut, ShaderChecks::Checked).map_err(|e| e.to_string())?;
        Ok(Self {
            display: DisplayPass::new(&ctx),
            completion: None,
            paced_on_timestamps: ctx.has_timestamps()
                && ctx.info.device_type != wgpu::DeviceType::Cpu,
            ctx,
            renderer,
            render: None,
            egui: rs.clone(),
            texture: None,
            shade_pacer: Pacer::default(),
            bin_pacer: Pacer::default(),
            in_flight: None,
            shown: None,
        })
    }

    /// Tables A and B into the table buffer.
    fn set_tables(&mut self, tables: &NamedTables) -> Result<(), String> {
        self.renderer
            .set_tables(&self.ctx, &tables.a.lut, Some(&tables.b.lut))
            .map_err(|e| e.to_string())
    }

    fn begin(&mut self, scene: &Scene, settings: &RenderSettings) -> Result<(), String> {
        // A new render's cost per light may be anything: its chunks start small again.
        self.shade_pacer = Pacer::default();
        self.bin_pacer = Pacer::default();
        if let Some(chunk) = &mut self.in_flight {
            chunk.stale = true;
        }
        let kept = self.render.take().map(PlaneRender::into_kept);
        self.render = Some(
            self.renderer
                .begin(&self.ctx, scene, settings, kept)
                .map_err(|e| e.to_string())?,
        );
        Ok(())
    }

    /// Whether the last chunk's work is done and its time taken (into the progress and its
    /// pacer); polls the device, never waits.
    fn ready(&mut self, progress: &mut Progress) -> bool {
        let Some(chunk) = &mut self.in_flight else {
            return true;
        };
        // Runs the timestamp read-back's callback, if one is pending. Only while a chunk is
        // in flight: on a CPU driver (lavapipe) a poll can wait behind the window's own
        // drawing, up to tens of milliseconds of an idle frame.
        let _ = self.ctx.device.poll(wgpu::PollType::Poll);
        if chunk.wall_ms.is_none() {
            match self
                .completion
                .as_ref()
                .map_or(Chunk::Idle, Completion::take)
            {
                Chunk::InFlight => return false,
                Chunk::Done { ms } => chunk.wall_ms = Some(ms),
                Chunk::Idle => chunk.wall_ms = Some(0.0),
            }
        }
        let wall_ms = chunk.wall_ms.unwrap_or(0.0);
        let by_wall_clock = match chunk.work {
            Work::Bin => FrameTimes {
                bin_ms: Some(wall_ms),
                shade_ms: 0.0,
            },
            Work::Shade => FrameTimes {
                bin_ms: None,
                shade_ms: wall_ms,
            },
        };
        let times = match self.render.as_mut().and_then(PlaneRender::try_times) {
            Some(t) if self.paced_on_timestamps => t,
            // The timestamps follow the work: a frame or so later.
            None if self.paced_on_timestamps
                && self.render.as_ref().is_some_and(PlaneRender::times_pending) =>
            {
                return false;
            }
            // None coming (a chunk submitted while the last read-back was still out, or a
            // read-back that failed: seen in a browser), or not paced on them (any read is
            // dropped, so that they do not pile up): the wall clock.
            _ => by_wall_clock,
        };
        if chunk.stale {
            self.in_flight = None;
            return true;
        }
        progress.gpu_ms += times.total_ms();
        match chunk.work {
            Work::Bin => self
                .bin_pacer
                .record(chunk.units, times.bin_ms.unwrap_or(times.shade_ms)),
            Work::Shade => self.shade_pacer.record(chunk.units, times.shade_ms),
        }
        self.in_flight = None;
        true
    }

    /// Dispatches the next chunk within the budget: a band of tile rows while the lists are
    /// being made, else entries of every pixel's list (and the image shown from them).
    fn chunk(
        &mut self,
        window: &egui::Context,
        progress: &mut Progress,
        kind: FrameKind,
        exposure: f64,
    ) {
        let budget_ms = FRAME_BUDGET_MS;
        let submitted = Instant::now();
        let Some(render) = &mut self.render else {
            return;
        };
        let (work, units) = if render.binning_progress().is_some() {
            let rows = self.bin_pacer.next(budget_ms);
            render.bin_step(&self.ctx, rows);
            (Work::Bin, rows)
        } else {
            let end = (progress.done + self.shade_pacer.next(budget_ms)).min(progress.total);
            render.step(&self.ctx, progress.done..end);
            let units = end - progress.done;
            progress.done = end;
            self.encode_display(kind, exposure * progress.preview_scale());
            (Work::Shade, units)
        };
        // An empty submission's index stands for all the work before it.
        let index = self.ctx.queue.submit([]);
        let (device, queue) = (&self.ctx.device, &self.ctx.queue);
        self.completion
            .get_or_insert_with(|| Completion::new(device.clone(), queue.clone(), window.clone()))
            .submitted(index, submitted);
        self.in_flight = Some(InFlight {
            work,
            units,
            wall_ms: None,
            stale: false,
        });
        progress.binning = self.render.as_ref().and_then(PlaneRender::binning_progress);
        progress.frames += 1;
    }

    /// Re-encodes the shown image where it was made otherwise (the exposure changed).
    fn show(&mut self, kind: FrameKind, exposure: f64) {
        if self.shown != Some((kind, exposure)) {
            self.encode_display(kind, exposure);
        }
    }

    fn encode_display(&mut self, kind: FrameKind, exposure: f64) {
        let Some(image) = self.render.as_ref().map(PlaneRender::output) else {
            return;
        };
        let size = image.texture().size();
        let (view, fresh) = self.display.target(&self.ctx, (size.width, size.height));
        if fresh || self.texture.is_none() {
            let mut egui = self.egui.renderer.write();
            self.texture = Some(match self.texture {
                Some(id) => {
                    egui.update_egui_texture_from_wgpu_texture(
                        &self.ctx.device,
                        view,
                        wgpu::FilterMode::Linear,
                        id,
                    );
                    id
                }
                None => {
                    egui.register_native_texture(&self.ctx.device, view, wgpu::FilterMode::Linear)
                }
            });
        }
        let mut encoder = self
            .ctx
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("display"),
            });
        self.display
            .encode(&self.ctx, &mut encoder, image, kind, exposure);
        self.ctx.queue.submit([encoder.finish()]);
        self.shown = Some((kind, exposure));
    }
}

impl CpuShading {
    /// Starts the CPU render at a reduced size on a worker thread, or over the browser's
    /// frames (a stale one stops, and its result is dropped: only the newest receiver is
    /// read).
    fn start(
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
    fn encode(&mut self, ui: &egui::Context, exposure: f64) {
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
    fn collect(&mut self, ui: &egui::Context, exposure: f64) -> bool {
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
