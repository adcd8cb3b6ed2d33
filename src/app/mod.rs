//! The lab: an eframe app with five panels — the lobe on the sphere, the fitted matrix and
//! the LUT, the plane in split or difference view, the paper's Figure 2 clipping cases, and
//! speed against accuracy — and the global controls beside them. State persists between runs.

pub mod axes;
pub mod chart;
pub mod clipping;
pub mod completion;
pub mod controls;
pub mod display;
pub mod lobe;
pub mod matrix;
pub mod measure;
pub mod other;
pub mod pacer;
pub mod pixel_table;
pub mod plane;
pub mod refit;
pub mod screenshot;
pub mod shading;
pub mod state;

pub use controls::Message;
pub use screenshot::{PendingScreenshot, ScreenshotApp, Settling};
pub use state::{ClipScene, Compare, LabState, PanelId};

use crate::ltc::lut::Lut;

/// What a snapshot of the lab's side effects needs that is not persisted.
pub struct LabApp {
    pub state: LabState,
    pub lut: Lut,
    /// What table A is, for labels: a shipped table's name or the file's path.
    pub lut_name: String,
    /// Table B, the other fit.
    pub other: other::OtherTable,
    pub shading: shading::Shading,
    pub lobe: lobe::LobePanel,
    pub matrix: matrix::MatrixPanel,
    pub plane: plane::PlanePanel,
    pub clipping: clipping::ClippingPanel,
    pub chart: chart::ChartPanel,
    /// The last error or notice for the side panel.
    pub message: Option<Message>,
    /// A screenshot on its way to a file.
    pub screenshot: Option<PendingScreenshot>,
    /// The window's size in points when the zoom was last looked at, and its size at zoom 1
    /// when it was last fitted.
    zoomed_for: Option<([u32; 2], [u32; 2])>,
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
        let refused = state.measurement.as_ref().and_then(|m| m.validate().err());
        if refused.is_some() {
            state.measurement = None;
        }
        let refused =
            refused.map(|why| format!("the saved chart was dropped ({why}): measure again"));
        // Table A: the file it was loaded from, read again; one that vanished or broke since
        // cannot stop the lab from starting: the shipped table shades, and the window says so.
        let (lut, lut_name, lost) = table_a(&mut state);
        let other = other::OtherTable::shipped_other(state.table);
        let mut shading = shading::Shading::new(&lut, render_state);
        shading.set_lut_b(Some(&other.lut));
        // No more lights than this adapter shades: the slider and the scene agree.
        let cut = state.keep_lights(shading.max_lights());
        let notice: Vec<String> = [refused, lost, cut].into_iter().flatten().collect();
        Self {
            lut_name,
            other,
            state,
            lobe: lobe::LobePanel,
            matrix: matrix::MatrixPanel::new(&lut),
            plane: plane::PlanePanel::default(),
            clipping: clipping::ClippingPanel::default(),
            chart: chart::ChartPanel::default(),
            lut,
            shading,
            message: (!notice.is_empty()).then(|| Message::error(notice.join("; "))),
            screenshot: None,
            zoomed_for: None,
        }
    }

    /// For eframe: the persisted state if there is one.
    pub fn from_creation_context(cc: &eframe::CreationContext<'_>) -> Self {
        let state = cc
            .storage
            .and_then(|s| eframe::get_value::<LabState>(s, STORAGE_KEY))
            .filter(|s| s.scene.validate().is_ok())
            .unwrap_or_default();
        Self::new(state, cc.wgpu_render_state.as_ref())
    }

    /// Whether anything is still being computed for the window: the plane's render, a
    /// measurement, a refit (a screenshot waits for none of them to be in flight).
    pub fn busy(&self) -> bool {
        self.shading.in_flight() || self.chart.busy() || self.matrix.busy()
    }

    /// The whole window: the side panel (unless folded), then the panels — one maximised,
    /// all in a grid, or, below `GRID_MIN`, one at a time under tabs.
    pub fn show(&mut self, ui: &mut egui::Ui) {
        self.fit_zoom(ui.ctx());
        if let Some(m) = &self.message {
            let dismissed = egui::Panel::bottom("notices")
                .show(ui, |ui| controls::message_bar(ui, m))
                .inner;
            if dismissed {
                self.message = None;
            }
        }
        if !self.state.controls_hidden {
            egui::Panel::left("controls")
                .resizable(true)
                .default_size(250.0)
                .show(ui, |ui| {
                    egui::ScrollArea::vertical().show(ui, |ui| {
                        let action = controls::show(
                            ui,
                            &mut self.state,
                            &self.shading,
                            &self.other,
                            &mut self.message,
                        );
                        if let Some(action) = action {
                            self.act(action);
                        }
                    });
                });
        }
        egui::CentralPanel::default().show(ui, |ui| {
            let size = ui.available_size();
            let tabs = size.x < GRID_MIN.x || size.y < GRID_MIN.y;
            ui.horizontal(|ui| {
                let label = if self.state.controls_hidden {
                    ">> controls"
                } else {
                    "<< controls"
                };
                if ui
                    .small_button(label)
                    .on_hover_text("Fold the side panel away, or back")
                    .clicked()
                {
                    self.state.controls_hidden = !self.state.controls_hidden;
                }
                if tabs && self.state.maximised.is_none() {
                    for id in PanelId::ALL {
                        ui.selectable_value(&mut self.state.tab, id, id.title());
                    }
                }
            });
            match (self.state.maximised, tabs) {
                (Some(id), _) => self.panel_frame(ui, id),
                (None, true) => {
                    let id = self.state.tab;
                    self.panel_frame(ui, id);
                }
                (None, false) => self.grid(ui),
            }
        });
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
                ui.strong(match id {
                    PanelId::Plane => plane::title(&self.state, &self.lut_name, &self.other),
                    _ => id.title().to_string(),
                });
                ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                    let maximised = self.state.maximised == Some(id);
                    let label = if maximised { "restore" } else { "maximise" };
                    if ui
                        .small_button(label)
                        .on_hover_text("Show this panel alone, or all five again")
                        .clicked()
                    {
                        self.state.maximised = if maximised { None } else { Some(id) };
                    }
                });
            });
            ui.separator();
            match id {
                PanelId::Lobe => {
                    let refit = self.matrix.refit_ltc(&self.state);
                    let table = (&self.lut, self.lut_name.as_str());
                    self.lobe
                        .show(ui, &mut self.state, table, refit, &self.other);
                }
                PanelId::Matrix => {
                    let tables = (&self.lut, self.lut_name.as_str(), &self.other);
                    self.matrix.show(ui, &mut self.state, tables);
                }
                PanelId::Plane => {
                    let tables = (&self.lut, &self.other);
                    self.plane
                        .show(ui, &mut self.state, &mut self.shading, tables);
                }
                PanelId::Clipping => {
                    self.clipping
                        .show(ui, &mut self.state, &self.lut, &self.other);
                }
                PanelId::Chart => self
                    .chart
                    .show(ui, &mut self.state, &self.lut, &self.shading),
            }
        });
    }

    /// Carries out what the side panel asked for.
    fn act(&mut self, action: controls::Action) {
        match action {
            controls::Action::UseLut(lut, name) => self.use_lut(lut, name),
            controls::Action::UseOther(other) => self.use_other(other),
            controls::Action::SaveExr(path) => {
                let exposure = self.state.scene.exposure;
                self.message = Some(
                    match plane::PlanePanel::save_exr(&self.shading, &path, exposure) {
                        Ok(()) => Message::note(format!("saved {}", path.display())),
                        Err(e) => Message::error(e),
                    },
                );
            }
            controls::Action::Screenshot(path) => {
                self.screenshot = Some(PendingScreenshot::new(path));
            }
        }
    }

    /// Shades with `lut` from now on: every panel that holds the table starts again. Table B
    /// follows to the other shipped table unless the user chose it.
    fn use_lut(&mut self, lut: Lut, name: String) {
        self.shading.set_lut(&lut);
        self.matrix = matrix::MatrixPanel::new(&lut);
        self.clipping = clipping::ClippingPanel::default();
        self.lut = lut;
        self.lut_name = name;
        if !self.other.chosen {
            self.use_other(other::OtherTable::shipped_other(self.state.table));
        }
    }

    /// Compares with `other` as table B from now on.
    fn use_other(&mut self, other: other::OtherTable) {
        self.shading.set_lut_b(Some(&other.lut));
        self.other = other;
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
        self.message = Some(match outcome {
            Ok(path) => Message::note(format!("saved {}", path.display())),
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

/// Table A as `state` says (its file read again, or the shipped table), its name, and why a
/// file could not be read again (the file is then forgotten).
fn table_a(state: &mut LabState) -> (Lut, String, Option<String>) {
    let shipped = |state: &LabState| {
        let t = state.table;
        (Lut::shipped(t).clone(), t.name().to_string())
    };
    let Some(file) = state.table_file.clone() else {
        let (lut, name) = shipped(state);
        return (lut, name, None);
    };
    match controls::load(&file) {
        Ok((lut, name, _)) => (lut, name, None),
        Err(e) => {
            state.table_file = None;
            let (lut, name) = shipped(state);
            let why = format!(
                "table A was {file}, which cannot be read again ({e}): shading with the {name} table"
            );
            (lut, name, Some(why))
        }
    }
}

impl Settling for LabApp {
    fn busy(&self) -> bool {
        LabApp::busy(self)
    }

    fn progress(&self) -> (usize, usize) {
        (self.shading.progress.done, self.shading.progress.total)
    }
}

impl eframe::App for LabApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.show(ui);
        let ctx = ui.ctx().clone();
        self.save_screenshot(&ctx);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, STORAGE_KEY, &self.state);
    }
}
