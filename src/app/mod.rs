//! The lab: an eframe app with five panels — the lobe on the sphere, the fitted matrix and
//! the LUT, the plane in split or difference view, the paper's Figure 2 clipping cases, and
//! speed against accuracy — and the global controls beside them. State persists between runs.

pub mod axes;
pub mod background;
#[cfg(target_arch = "wasm32")]
pub mod browser;
pub mod chart;
pub mod clip_rows;
pub mod clip_setup;
pub mod clipping;
pub mod completion;
pub mod controls;
pub mod display;
pub mod elevation;
pub mod file_io;
pub mod lab;
pub mod link;
pub mod lobe;
pub mod lobe_sphere;
pub mod matrix;
pub mod measure;
pub mod pacer;
pub mod pixel_table;
pub mod plane;
pub mod plane_paint;
pub mod refit;
pub mod screenshot;
pub mod shading;
pub mod state;

pub use lab::{Aspect, Compare, Lab, Message, Panel};
pub use screenshot::{PendingScreenshot, ScreenshotApp, Settling};
pub use state::{LabState, PanelId};

use crate::app::file_io::{Given, Purpose, group};
use crate::app::lab::Request;
use crate::scene::Scene;
use crate::tables::{NamedTable, NamedTables};

/// The window: the lab the panels share, the side panel, the five panels and the layout.
pub struct LabApp {
    pub lab: Lab,
    pub controls: controls::ControlsPanel,
    pub lobe: lobe::LobePanel,
    pub matrix: matrix::MatrixPanel,
    pub plane: plane::PlanePanel,
    pub clipping: clipping::ClippingPanel,
    pub chart: chart::ChartPanel,
    pub window: state::WindowState,
    /// A screenshot on its way to a file.
    pub screenshot: Option<PendingScreenshot>,
    /// The plane's EXR the user asked for, saved once its image is read back.
    saving_exr: Option<std::path::PathBuf>,
    /// Milliseconds the last frame spent in the side panel and in each panel, for the frame
    /// log (`screenshot::PART_NAMES`).
    part_ms: [f64; screenshot::PART_COUNT],
    /// The window's size in points when the zoom was last looked at, and its size at zoom 1
    /// when it was last fitted.
    zoomed_for: Option<([u32; 2], [u32; 2])>,
    /// The panels the last frame drew (the browser's page reports them).
    pub shown: Vec<PanelId>,
    /// Files the browser is reading: picked for a purpose, or dropped (`None`: each for what
    /// its name says).
    #[cfg(target_arch = "wasm32")]
    picking: Option<(Option<file_io::Purpose>, browser::Picked)>,
}

/// The smallest central area that shows all five panels at once: below it each panel is
/// too small to read (the clipping pictures and the matrix numbers first), so they go
/// under tabs.
const GRID_MIN: egui::Vec2 = egui::vec2(1100.0, 640.0);

/// eframe's storage key.
const STORAGE_KEY: &str = "ltc-lab-state";

impl LabApp {
    /// The lab drawing with the window's wgpu device (`render_state`: eframe's, or a test
    /// harness's); without one, the plane is drawn by the CPU reference.
    pub fn new(mut state: LabState, render_state: Option<&egui_wgpu::RenderState>) -> Self {
        // A saved chart that cannot be plotted is dropped, and the window says why.
        let refused = state
            .chart
            .measurement
            .as_ref()
            .and_then(|m| m.validate().err());
        if refused.is_some() {
            state.chart.measurement = None;
        }
        let refused =
            refused.map(|why| format!("the saved chart was dropped ({why}): measure again"));
        // Table A: the file it was loaded from, read again; one that vanished or broke since
        // cannot stop the lab from starting: the shipped table shades, and the window says so.
        let (tables, lost) = tables(&mut state.lab);
        let (shading, why) = shading::Shading::new(&tables.a.lut, render_state);
        let gpu = shading.context().cloned().ok_or(why.unwrap_or_default());
        let mut lab = Lab::new(state.lab, tables, gpu);
        // No more lights than this adapter shades: the slider and the scene agree.
        let cut = lab.keep_lights();
        let notice: Vec<String> = [refused, lost, cut].into_iter().flatten().collect();
        if !notice.is_empty() {
            lab.say(Message::error(notice.join("; ")));
        }
        Self {
            lab,
            controls: controls::ControlsPanel::new(state.controls),
            lobe: lobe::LobePanel::new(state.lobe),
            matrix: matrix::MatrixPanel::default(),
            plane: plane::PlanePanel::new(shading, state.plane),
            clipping: clipping::ClippingPanel::new(state.clipping),
            chart: chart::ChartPanel::new(state.chart),
            window: state.window,
            screenshot: None,
            saving_exr: None,
            part_ms: [0.0; screenshot::PART_COUNT],
            zoomed_for: None,
            shown: Vec::new(),
            #[cfg(target_arch = "wasm32")]
            picking: None,
        }
    }

    /// For eframe: the persisted state if there is one.
    pub fn from_creation_context(cc: &eframe::CreationContext<'_>) -> Self {
        Self::new(Self::stored_state(cc), cc.wgpu_render_state.as_ref())
    }

    /// The state eframe persisted, if there is one that can be shaded; else the defaults.
    pub fn stored_state(cc: &eframe::CreationContext<'_>) -> LabState {
        cc.storage
            .and_then(|s| eframe::get_value::<LabState>(s, STORAGE_KEY))
            .filter(|s| s.lab.scene.validate().is_ok())
            .unwrap_or_default()
    }

    /// What the user set, as eframe persists it.
    pub fn state(&self) -> LabState {
        LabState {
            lab: self.lab.shared().clone(),
            lobe: self.lobe.state.clone(),
            plane: self.plane.state.clone(),
            clipping: self.clipping.state.clone(),
            chart: self.chart.state.clone(),
            controls: self.controls.state.clone(),
            window: self.window.clone(),
        }
    }

    /// Whether anything is still being computed for the window: the plane's render, the
    /// clipping pictures, a measurement, a refit (a screenshot waits for none of them).
    pub fn busy(&self) -> bool {
        self.plane.busy() || self.clipping.busy() || self.chart.busy() || self.matrix.busy()
    }

    /// The whole window: the side panel (unless folded), then the panels — one maximised,
    /// all in a grid, or, below `GRID_MIN`, one at a time under tabs.
    pub fn show(&mut self, ui: &mut egui::Ui) {
        self.fit_zoom(ui.ctx());
        if let Some(m) = &self.lab.message {
            let dismissed = egui::Panel::bottom("notices")
                .show(ui, |ui| controls::message_bar(ui, m))
                .inner;
            if dismissed {
                self.lab.message = None;
            }
        }
        self.part_ms = [0.0; screenshot::PART_COUNT];
        self.shown.clear();
        self.take_dropped(ui.ctx());
        // The browser's share of the work that runs on threads on the desktop.
        if background::run_for(shading::FRAME_BUDGET_MS) {
            ui.ctx().request_repaint();
        }
        if !self.window.controls_hidden {
            let started = web_time::Instant::now();
            egui::Panel::left("controls")
                .resizable(true)
                .default_size(250.0)
                .show(ui, |ui| {
                    egui::ScrollArea::vertical()
                        .show(ui, |ui| self.controls.show(ui, &mut self.lab));
                });
            self.part_ms[0] = started.elapsed().as_secs_f64() * 1e3;
        }
        egui::CentralPanel::default().show(ui, |ui| {
            let size = ui.available_size();
            let tabs = size.x < GRID_MIN.x || size.y < GRID_MIN.y;
            ui.horizontal(|ui| self.top_bar(ui, tabs));
            match (self.window.maximised, tabs) {
                (Some(id), _) => self.panel_frame(ui, id),
                (None, true) => {
                    let id = self.window.tab;
                    self.panel_frame(ui, id);
                }
                (None, false) => self.grid(ui),
            }
        });
        self.carry_out(ui.ctx());
    }

    /// The side panel's fold, and the tabs where the panels do not fit side by side.
    fn top_bar(&mut self, ui: &mut egui::Ui, tabs: bool) {
        let label = if self.window.controls_hidden {
            ">> controls"
        } else {
            "<< controls"
        };
        if ui
            .small_button(label)
            .on_hover_text("Fold the side panel away, or back")
            .clicked()
        {
            self.window.controls_hidden = !self.window.controls_hidden;
        }
        if tabs && self.window.maximised.is_none() {
            for id in PanelId::ALL {
                let title = self.title(id);
                ui.selectable_value(&mut self.window.tab, id, title);
            }
        }
    }

    /// A panel's title: the plane's says what its two sides are.
    fn title(&self, id: PanelId) -> String {
        match id {
            PanelId::Plane => plane::title(self.lab.shared().compare, self.lab.tables()),
            _ => id.title().to_string(),
        }
    }

    /// Three panels on top (lobe, matrix, plane) and two below (clipping, chart).
    fn grid(&mut self, ui: &mut egui::Ui) {
        let full = ui.available_rect_before_wrap();
        let gap = 6.0;
        let top_h = (full.height() * 0.55).floor();
        let rows = [
            (
                egui::Rect::from_min_size(full.min, egui::vec2(full.width(), top_h - gap)),
                vec![
                    (PanelId::Lobe, 0.28),
                    (PanelId::Matrix, 0.30),
                    (PanelId::Plane, 0.42),
                ],
            ),
            (
                egui::Rect::from_min_max(egui::pos2(full.min.x, full.min.y + top_h), full.max),
                vec![(PanelId::Clipping, 0.55), (PanelId::Chart, 0.45)],
            ),
        ];
        for (row, panels) in rows {
            let mut x = row.min.x;
            for (id, fraction) in panels {
                let w = row.width() * fraction;
                let rect = egui::Rect::from_min_size(
                    egui::pos2(x, row.min.y),
                    egui::vec2(w - gap, row.height()),
                );
                x += w;
                let mut child = ui.new_child(egui::UiBuilder::new().max_rect(rect).id_salt(id));
                child.set_clip_rect(rect);
                self.panel_frame(&mut child, id);
            }
        }
        ui.allocate_rect(full, egui::Sense::hover());
    }

    /// One panel in a frame with its title and a maximise/restore button.
    fn panel_frame(&mut self, ui: &mut egui::Ui, id: PanelId) {
        egui::Frame::group(ui.style()).show(ui, |ui| {
            ui.set_min_size(ui.available_size());
            ui.horizontal(|ui| {
                ui.strong(self.title(id));
                ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                    let maximised = self.window.maximised == Some(id);
                    let label = if maximised { "restore" } else { "maximise" };
                    if ui
                        .small_button(label)
                        .on_hover_text("Show this panel alone, or all five again")
                        .clicked()
                    {
                        self.window.maximised = if maximised { None } else { Some(id) };
                    }
                });
            });
            ui.separator();
            let panel: &mut dyn Panel = match id {
                PanelId::Lobe => &mut self.lobe,
                PanelId::Matrix => &mut self.matrix,
                PanelId::Plane => &mut self.plane,
                PanelId::Clipping => &mut self.clipping,
                PanelId::Chart => &mut self.chart,
            };
            let started = web_time::Instant::now();
            self.shown.push(id);
            panel.show(ui, &mut self.lab);
            self.part_ms[1 + id as usize] = started.elapsed().as_secs_f64() * 1e3;
        });
    }

    /// Writes a file a panel asked for, shares the view, or opens the browser's picker.
    fn carry_out(&mut self, ctx: &egui::Context) {
        #[cfg(target_arch = "wasm32")]
        self.take_picked();
        if let Some(path) = &self.saving_exr {
            let exposure = self.lab.shared().scene.exposure;
            match self.plane.save_exr(path, exposure) {
                Some(Ok(done)) => self.lab.say(Message::note(done)),
                Some(Err(e)) => self.lab.say(Message::error(e)),
                None => ctx.request_repaint(),
            }
            if !self.plane.shading.read_pending() {
                self.saving_exr = None;
            }
        }
        match self.lab.request.take() {
            Some(Request::SaveExr(path)) => self.saving_exr = Some(path),
            Some(Request::Screenshot(path)) => {
                self.screenshot = Some(PendingScreenshot::new(path));
            }
            Some(Request::Share) => self.share(ctx),
            #[cfg(target_arch = "wasm32")]
            Some(Request::Pick(purpose)) => {
                let picked = browser::pick(purpose.accept(), purpose.multiple(), ctx.clone());
                match picked {
                    Ok(p) => self.picking = Some((Some(purpose), p)),
                    Err(e) => self.lab.say(Message::error(e)),
                }
            }
            #[cfg(not(target_arch = "wasm32"))]
            Some(Request::Pick(_)) => {}
            None => {}
        }
    }

    /// The view as a link: in a browser the page's address becomes it (and is copied); on the
    /// desktop the string for `ltc-lab lab --view` is copied and shown.
    fn share(&mut self, ctx: &egui::Context) {
        let view = link::encode(&self.state());
        #[cfg(target_arch = "wasm32")]
        let message = match browser::set_fragment(&format!("{}{view}", link::FRAGMENT_KEY)) {
            Some(url) => {
                ctx.copy_text(url);
                Message::note("this view's link is in the address bar, and copied")
            }
            None => Message::error("the browser would not change the page's address"),
        };
        #[cfg(not(target_arch = "wasm32"))]
        let message = {
            ctx.copy_text(view.clone());
            Message::note(format!(
                "copied this view ({} characters): ltc-lab lab --view {view}",
                view.len()
            ))
        };
        self.lab.say(message);
    }

    /// Fits egui's zoom to the window when the window's size changes (`auto_zoom`). A change
    /// of the size in points that keeps the size at zoom 1 is a zoom (the user's Ctrl + / −,
    /// or the one set here, which the window's size follows a frame late): it stands.
    fn fit_zoom(&mut self, ctx: &egui::Context) {
        let points = ctx.input(|i| i.viewport_rect().size());
        let logical = points * ctx.zoom_factor();
        let key = |v: egui::Vec2| [v.x.round() as u32, v.y.round() as u32];
        let (points_key, logical_key) = (key(points), key(logical));
        match self.zoomed_for {
            Some((p, _)) if p == points_key => {}
            Some((_, l)) if l == logical_key => self.zoomed_for = Some((points_key, l)),
            _ => {
                self.zoomed_for = Some((points_key, logical_key));
                ctx.set_zoom_factor(auto_zoom(logical));
            }
        }
    }

    /// Saves a screenshot the user asked for, once its pixels arrive.
    fn save_screenshot(&mut self, ctx: &egui::Context) {
        let Some(outcome) = self.screenshot.as_mut().and_then(|p| p.poll(ctx)) else {
            return;
        };
        self.lab.say(match outcome {
            Ok(done) => Message::note(done),
            Err(e) => Message::error(e.to_string()),
        });
        self.screenshot = None;
    }
}

/// The zoom for a window `size` points large at zoom 1: 1 up to 1920×1080, the size the
/// panels are laid out for, and growing with the window beyond it (2 at 3840×2160), so that
/// pictures and text grow with a large screen instead of floating small in empty space.
pub fn auto_zoom(size: egui::Vec2) -> f32 {
    // At most 3: beyond it a wall-sized window is better served by Ctrl + / −.
    (size.x / 1920.0).min(size.y / 1080.0).clamp(1.0, 3.0)
}

/// The tables as `shared` says (their files read again, or the shipped tables), and why a
/// file could not be read again (the file is then forgotten).
fn tables(shared: &mut lab::Shared) -> (NamedTables, Option<String>) {
    let mut lost = Vec::new();
    let mut read_again = |file: &mut Option<String>, which: &str| {
        let path = file.clone()?;
        match controls::load(&path) {
            Ok((table, _)) => Some(table),
            Err(e) => {
                *file = None;
                lost.push(format!(
                    "table {which} was {path}, which cannot be read again ({e})"
                ));
                None
            }
        }
    };
    let a = read_again(&mut shared.table_file, "A");
    let b = read_again(&mut shared.table_b_file, "B");
    let mut tables = match a {
        Some(a) => NamedTables::with_a(a, shared.table),
        None => NamedTables::shipped(shared.table),
    };
    if let Some(b) = b {
        tables.b = b;
        tables.b_chosen = true;
    }
    let why = (!lost.is_empty()).then(|| {
        format!(
            "{}: shading with the {} table, comparing with {}",
            lost.join("; "),
            tables.a.name,
            tables.b.name
        )
    });
    (tables, why)
}

impl Settling for LabApp {
    fn busy(&self) -> bool {
        LabApp::busy(self)
    }

    fn progress(&self) -> (usize, usize) {
        let p = &self.plane.shading.progress;
        (p.done, p.total)
    }

    fn part_ms(&self) -> [f64; screenshot::PART_COUNT] {
        self.part_ms
    }
}

impl eframe::App for LabApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.show(ui);
        let ctx = ui.ctx().clone();
        self.save_screenshot(&ctx);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, STORAGE_KEY, &self.state());
    }

    /// egui's memory holds the zoom, which the lab fits to the window at every start
    /// (`auto_zoom`): restored, eframe sized the next window by it (`--size 1920x1080` after
    /// a 4K session opened a 3840×2160 window at zoom 2). The lab's store has its own
    /// application id (`cli::lab`), away from the one that holds an earlier version's memory.
    fn persist_egui_memory(&self) -> bool {
        false
    }
}

// Files given to the window: dropped (both targets) or picked (the browser).
impl LabApp {
    /// Takes the files dropped on the window this frame: read at once on the desktop; in a
    /// browser, which reads them asynchronously, once they have arrived (`take_picked`).
    pub(crate) fn take_dropped(&mut self, ctx: &egui::Context) {
        let files = ctx.input(|i| i.raw.dropped_files.clone());
        if files.is_empty() {
            return;
        }
        #[cfg(not(target_arch = "wasm32"))]
        {
            let mut given = Vec::new();
            let mut refused = Vec::new();
            for file in files {
                let name = file.path().display().to_string();
                match file.bytes() {
                    Ok(bytes) => given.push((name, bytes)),
                    Err(e) => refused.push(format!("{name}: cannot read it ({e})")),
                }
            }
            self.take_given(None, given, refused);
        }
        #[cfg(target_arch = "wasm32")]
        {
            let arrived = crate::app::browser::Picked::default();
            let into = arrived.clone();
            let repaint = ctx.clone();
            wasm_bindgen_futures::spawn_local(async move {
                let mut given = Vec::new();
                for file in files {
                    if let Ok(bytes) = file.bytes_async().await {
                        given.push((file.path().display().to_string(), bytes));
                    }
                }
                *into.borrow_mut() = Some(given);
                repaint.request_repaint();
            });
            self.picking = Some((None, arrived));
        }
    }

    /// Takes what the browser read (picked or dropped files), once it has.
    #[cfg(target_arch = "wasm32")]
    pub(crate) fn take_picked(&mut self) {
        let Some((purpose, picked)) = &self.picking else {
            return;
        };
        let Some(files) = picked.borrow_mut().take() else {
            return;
        };
        let purpose = *purpose;
        self.picking = None;
        self.take_given(purpose, files, Vec::new());
    }

    /// Uses given files: all for `purpose`, or (`None`, dropped) each for what its name says;
    /// says what was `refused` before (files that could not be read) with what is refused here.
    fn take_given(
        &mut self,
        purpose: Option<Purpose>,
        files: Vec<Given>,
        mut refused: Vec<String>,
    ) {
        match purpose {
            Some(p) => self.take_in(p, &files),
            None => {
                let (groups, unread) = group(files);
                refused.extend(unread);
                for (p, files) in groups {
                    self.take_in(p, &files);
                }
            }
        }
        if !refused.is_empty() {
            self.lab.say(Message::error(refused.join("; ")));
        }
    }

    /// Uses given files as `purpose` says: the scene, table A or B, the chart's study. A file
    /// that cannot be used changes nothing and says why (its name first).
    pub fn take_in(&mut self, purpose: Purpose, files: &[Given]) {
        let Some((name, bytes)) = files.first() else {
            return;
        };
        let text = || String::from_utf8_lossy(bytes).into_owned();
        let message = match purpose {
            Purpose::Scene => {
                controls::use_loaded_scene(&mut self.lab, Scene::from_toml(&text(), name), name)
            }
            Purpose::Table | Purpose::TableB => match given_table(files) {
                Ok(loaded) => controls::use_loaded_table(
                    &mut self.lab,
                    loaded,
                    None,
                    purpose == Purpose::TableB,
                ),
                Err(e) => Message::error(format!("{e} — the tables stay")),
            },
            Purpose::Study => {
                self.chart
                    .use_study(crate::study::parse_csv(&text(), name), name);
                match &self.chart.error {
                    Some(e) => Message::error(e.clone()),
                    None => Message::note(format!("plotting {name}")),
                }
            }
        };
        self.lab.say(message);
    }
}

/// The table in given files, named for labels, with what its format could not hold.
fn given_table(files: &[Given]) -> Result<(NamedTable, String), String> {
    let loaded = crate::ltc::formats::read_given(files).map_err(|e| e.to_string())?;
    let name = files
        .iter()
        .map(|(n, _)| n.as_str())
        .find(|n| !n.ends_with(crate::ltc::formats::DDS_HEADER_FILE))
        .unwrap_or_default();
    Ok(controls::named_table(loaded, name))
}
