//! The lab: an eframe app with five panels — the lobe on the sphere, the fitted matrix and
//! the LUT, the plane in split or difference view, the paper's Figure 2 clipping cases, and
//! speed against accuracy — and the global controls beside them. State persists between runs.

pub mod chart;
pub mod clipping;
pub mod lobe;
pub mod matrix;
pub mod plane;
pub mod shading;

use serde::{Deserialize, Serialize};

use crate::gpu::plane::GpuMethod;
use crate::ltc::lobe::Lobe;
use crate::ltc::lut::Lut;
use crate::ltc::{Clipping, LtcPair, Normalization};
use crate::scene::Scene;

/// The panels, for maximising one and for headless screenshots.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize, clap::ValueEnum)]
pub enum PanelId {
    Lobe,
    Matrix,
    Plane,
    Clipping,
    Chart,
}

impl PanelId {
    pub const ALL: [Self; 5] = [
        Self::Lobe,
        Self::Matrix,
        Self::Plane,
        Self::Clipping,
        Self::Chart,
    ];

    pub fn title(self) -> &'static str {
        match self {
            Self::Lobe => "Lobe on the sphere",
            Self::Matrix => "Matrix and LUT",
            Self::Plane => "Plane: LTC | BRDF",
            Self::Clipping => "Clipping (Figure 2)",
            Self::Chart => "Speed vs accuracy",
        }
    }
}

/// The shipped presets, embedded so the lab runs from anywhere.
pub const PRESETS: [(&str, &str); 4] = [
    (
        "paper-100",
        include_str!("../../assets/scenes/paper-100.toml"),
    ),
    (
        "figure2-normal",
        include_str!("../../assets/scenes/figure2-normal.toml"),
    ),
    (
        "figure2-case1",
        include_str!("../../assets/scenes/figure2-case1.toml"),
    ),
    (
        "figure2-case2",
        include_str!("../../assets/scenes/figure2-case2.toml"),
    ),
];

pub fn preset(name: &str) -> Scene {
    let (_, text) = PRESETS
        .iter()
        .find(|(n, _)| *n == name)
        .expect("a shipped preset");
    Scene::from_toml(text, name).expect("shipped presets are valid (tests/presets.rs)")
}

/// Everything the user set; persisted by eframe between runs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct LabState {
    pub scene: Scene,
    /// θo of the lobe and matrix panels, degrees.
    pub theta_o_deg: f64,
    /// The LTC and BRDF forms compared in the plane panel.
    pub method_ltc: GpuMethod,
    pub method_brdf: GpuMethod,
    /// Split (LTC | BRDF), difference map, or one method alone.
    pub view: PlaneView,
    pub divider: f64,
    pub clipping: Clipping,
    pub normalization: Normalization,
    /// Multiplies every light's intensity when shading.
    pub intensity_scale: f64,
    /// Replaces every light's range when > 0.
    pub range_override: f64,
    pub light_count: usize,
    pub seed: u64,
    pub selected_light: Option<usize>,
    pub lobe: Lobe,
    /// 0: the clamped cosine (M = I); 1: the fitted LTC.
    pub morph: f64,
    pub orbit_yaw: f32,
    pub orbit_pitch: f32,
    pub colour_difference: bool,
    pub clip_panel: Clipping,
    pub clip_scene: ClipScene,
    pub maximised: Option<PanelId>,
    pub scene_path: String,
    pub screenshot_path: String,
    /// A LUT file to shade with; empty: the embedded table.
    pub lut_path: String,
    /// Which shipped table shades (classic or the point-light fit).
    pub table: crate::ltc::lut::Table,
    /// Overlay the other shipped table's LTC in the lobe panel.
    pub overlay_other_fit: bool,
}

/// What the plane panel shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum PlaneView {
    Split,
    Difference,
    LtcOnly,
    BrdfOnly,
}

/// The Figure-2 scene whose case map and profile the clipping panel shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum ClipScene {
    Normal,
    Case1,
    Case2,
}

impl ClipScene {
    pub fn preset(self) -> &'static str {
        match self {
            Self::Normal => "figure2-normal",
            Self::Case1 => "figure2-case1",
            Self::Case2 => "figure2-case2",
        }
    }
}

impl Default for LabState {
    fn default() -> Self {
        let scene = preset("paper-100");
        Self {
            light_count: scene.lights.len(),
            scene,
            theta_o_deg: 45.0,
            method_ltc: GpuMethod::LtcFast,
            method_brdf: GpuMethod::Brdf,
            view: PlaneView::Split,
            divider: 0.5,
            clipping: Clipping::BOTH,
            normalization: Normalization::Corrected,
            intensity_scale: 1.0,
            range_override: 0.0,
            seed: 27,
            selected_light: None,
            lobe: Lobe::Specular,
            morph: 1.0,
            orbit_yaw: 0.6,
            orbit_pitch: 0.35,
            colour_difference: false,
            clip_panel: Clipping::BOTH,
            clip_scene: ClipScene::Case1,
            maximised: None,
            scene_path: "scene.toml".into(),
            screenshot_path: "ltc-lab.png".into(),
            lut_path: String::new(),
            table: crate::ltc::lut::Table::Classic,
            overlay_other_fit: true,
        }
    }
}

impl LabState {
    pub fn alpha(&self) -> f64 {
        self.scene.material.alpha
    }

    /// The scene as shaded: global intensity and range applied.
    pub fn shaded_scene(&self) -> Scene {
        let mut s = self.scene.clone();
        for l in &mut s.lights {
            l.intensity *= self.intensity_scale;
            if self.range_override > 0.0 {
                l.range = Some(self.range_override);
            }
        }
        s
    }

    /// The LTC pair of the lobe and matrix panels' (θo, α).
    pub fn ltc_pair(&self, lut: &Lut) -> LtcPair {
        let theta = self
            .theta_o_deg
            .to_radians()
            .min(crate::ltc::fit::THETA_MAX);
        lut.sample(self.alpha(), theta.cos()).ltc_pair()
    }
}

/// What a snapshot of the lab's side effects needs that is not persisted.
pub struct LabApp {
    pub state: LabState,
    pub lut: Lut,
    pub shading: shading::Shading,
    pub lobe: lobe::LobePanel,
    pub matrix: matrix::MatrixPanel,
    pub plane: plane::PlanePanel,
    pub clipping: clipping::ClippingPanel,
    pub chart: chart::ChartPanel,
    /// The last error or notice for the side panel.
    pub message: Option<(bool, String)>,
    /// A screenshot on its way to a file.
    pub screenshot: Option<PendingScreenshot>,
}

/// A requested screenshot: the file the user named, and the slot eframe's callback fills.
pub struct PendingScreenshot {
    pub path: std::path::PathBuf,
    requested: bool,
    slot: std::sync::Arc<std::sync::Mutex<Option<std::sync::Arc<egui::ColorImage>>>>,
}

impl PendingScreenshot {
    pub fn new(path: std::path::PathBuf) -> Self {
        Self {
            path,
            requested: false,
            slot: Default::default(),
        }
    }
}

/// eframe's storage key.
const STORAGE_KEY: &str = "ltc-lab-state";

impl LabApp {
    pub fn new(state: LabState) -> Self {
        // The chosen shipped table; a persisted `lut_path` is loaded again only on request,
        // so a file that vanished since cannot stop the lab from starting.
        let lut = Lut::shipped(state.table).clone();
        let shading = shading::Shading::new(&lut);
        Self {
            state,
            lobe: lobe::LobePanel,
            matrix: matrix::MatrixPanel::new(&lut),
            plane: plane::PlanePanel::default(),
            clipping: clipping::ClippingPanel::default(),
            chart: chart::ChartPanel::default(),
            lut,
            shading,
            message: None,
            screenshot: None,
        }
    }

    /// For eframe: the persisted state if there is one.
    pub fn from_creation_context(cc: &eframe::CreationContext<'_>) -> Self {
        let state = cc
            .storage
            .and_then(|s| eframe::get_value::<LabState>(s, STORAGE_KEY))
            .filter(|s| s.scene.validate().is_ok())
            .unwrap_or_default();
        Self::new(state)
    }

    /// The whole window: the side panel, then the panels (one maximised, or all in a grid).
    pub fn show(&mut self, ui: &mut egui::Ui) {
        egui::Panel::left("controls")
            .resizable(true)
            .default_size(250.0)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| self.controls(ui));
            });
        egui::CentralPanel::default().show(ui, |ui| match self.state.maximised {
            Some(id) => self.panel_frame(ui, id),
            None => self.grid(ui),
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
                ui.strong(id.title());
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
                    let other = Lut::shipped(match self.state.table {
                        crate::ltc::lut::Table::Classic => crate::ltc::lut::Table::Point,
                        crate::ltc::lut::Table::Point => crate::ltc::lut::Table::Classic,
                    });
                    self.lobe.show(
                        ui,
                        &mut self.state,
                        &self.lut,
                        self.matrix.refit_ltc(),
                        other,
                    );
                }
                PanelId::Matrix => self.matrix.show(ui, &mut self.state, &self.lut),
                PanelId::Plane => {
                    self.plane
                        .show(ui, &mut self.state, &mut self.shading, &self.lut);
                }
                PanelId::Clipping => self.clipping.show(ui, &mut self.state, &self.lut),
                PanelId::Chart => self.chart.show(ui, &self.state, &self.lut),
            }
        });
    }

    /// The side panel: every global control, each with what it changes in the equations.
    fn controls(&mut self, ui: &mut egui::Ui) {
        let mut new_lut = None;
        self.controls_inner(ui, &mut new_lut);
        if let Some(lut) = new_lut {
            self.use_lut(lut);
        }
    }

    /// Shades with `lut` from now on: every panel that holds the table starts again.
    fn use_lut(&mut self, lut: Lut) {
        self.shading.set_lut(&lut);
        self.matrix = matrix::MatrixPanel::new(&lut);
        self.plane.invalidate();
        self.clipping = clipping::ClippingPanel::default();
        self.lut = lut;
    }

    fn controls_inner(&mut self, ui: &mut egui::Ui, new_lut: &mut Option<Lut>) {
        let s = &mut self.state;
        ui.heading("LTC Lab");
        ui.label(egui::RichText::new(self.shading.describe()).small())
            .on_hover_text("The adapter the plane and chart panels shade on");
        if let Some(e) = &self.shading.gpu_error {
            ui.colored_label(
                egui::Color32::from_rgb(230, 120, 60),
                format!(
                    "GPU unavailable — the plane is drawn by the CPU reference at reduced size. {e}"
                ),
            );
        }
        ui.separator();
        ui.strong("Material");
        let mut alpha = s.scene.material.alpha;
        ui.add(egui::Slider::new(&mut alpha, 1e-3..=1.0).logarithmic(true).text("α"))
            .on_hover_text("GGX α: D = α² / (π ((n·h)²(α²−1)+1)²), Λ = (−1+sqrt(1+α² tan²θ))/2; also the LUT column (r = sqrt α) the LTC comes from");
        let mut r = alpha.sqrt();
        if ui
            .add(egui::Slider::new(&mut r, 0.0316..=1.0).text("roughness r = √α"))
            .on_hover_text("Perceptual roughness; α = r². Burley's FD = 0.5 + 2α(l·h)² uses the paper's α (ltc_code and Unity use √α)")
            .changed()
        {
            alpha = r * r;
        }
        s.scene.material.alpha = alpha.clamp(1e-4, 1.0);
        ui.add(egui::Slider::new(&mut s.theta_o_deg, 0.0..=90.0).text("θo (°)"))
            .on_hover_text("View angle of the lobe and matrix panels: v = (sin θo, 0, cos θo); the LUT row is sqrt(1 − cos θo)");
        ui.add(egui::Slider::new(&mut s.scene.material.f0, 0.0..=1.0).text("F0"))
            .on_hover_text("Schlick: F = F0 + (1 − F0)(1 − v·h)⁵; in the LTC, the specular magnitude F0·n_s + (1 − F0)·f_s");
        ui.horizontal(|ui| {
            let mut c = s.scene.material.base_color.map(|x| x as f32);
            ui.color_edit_button_rgb(&mut c)
                .on_hover_text("Base colour c: fd = c/π (…)(…); in the LTC, c · n_d · D_d");
            s.scene.material.base_color = c.map(f64::from);
            ui.label("base colour");
        });
        ui.separator();
        ui.strong("Lights");
        ui.add(
            egui::Slider::new(&mut s.intensity_scale, 0.01..=100.0)
                .logarithmic(true)
                .text("intensity ×"),
        )
        .on_hover_text("Multiplies every light's I in E = I/d² · w(d)");
        ui.add(egui::Slider::new(&mut s.range_override, 0.0..=10.0).text("range R"))
            .on_hover_text("The window w(d) = clamp(1 − (d/R)⁴, 0, 1)²; 0 keeps each light's own range (absent = ∞)");
        if let Some(k) = s.selected_light.filter(|&k| k < s.scene.lights.len()) {
            ui.add(egui::Slider::new(&mut s.scene.lights[k].position[2], -1.0..=3.0).text(format!("height of light {k}")))
                .on_hover_text("z of the selected light; below 0 it is under the plane (clipping case 1). Shift-drag its marker for the same");
        }
        let mut count = s.light_count;
        let max = self.shading.max_lights().min(20_000);
        if ui
            .add(egui::Slider::new(&mut count, 0..=max).logarithmic(true).text("lights"))
            .on_hover_text("Regenerates the lights with the seeded generator (replaces the current ones): N point lights over the plane, heights 0.05–0.6")
            .changed()
        {
            s.light_count = count;
            s.scene.lights = crate::scene::generate_lights(
                &crate::scene::RandomLights {
                    count,
                    seed: s.seed,
                    height: [0.05, 0.6],
                    intensity: [0.02, 0.08],
                    range: Some(2.0),
                },
                s.scene.plane.half_size,
            );
            s.selected_light = None;
        }
        ui.separator();
        ui.strong("Shading");
        egui::ComboBox::from_label("LTC form")
            .selected_text(s.method_ltc.name())
            .show_ui(ui, |ui| {
                for m in [GpuMethod::Ltc, GpuMethod::LtcFast] {
                    ui.selectable_value(&mut s.method_ltc, m, m.name());
                }
            })
            .response
            .on_hover_text("ltc: the paper's eq. 30 per light; ltc-fast: M^-1 folded with the frame, unnormalized u, eq. 27's factoring");
        egui::ComboBox::from_label("BRDF form")
            .selected_text(s.method_brdf.name())
            .show_ui(ui, |ui| {
                for m in [GpuMethod::Brdf, GpuMethod::BrdfFast] {
                    ui.selectable_value(&mut s.method_brdf, m, m.name());
                }
            })
            .response
            .on_hover_text(
                "brdf: eq. 28 as DESIGN §1 writes it; brdf-fast: Filament's V_SmithGGXCorrelated",
            );
        ui.checkbox(&mut s.clipping.horizon, "clip case 1 (n·l ≤ 0)")
            .on_hover_text("Eq. 30's first rule: a light below the surface contributes nothing. Off: M^-1 can lift it above the horizon (the glow of Figure 2c)");
        ui.checkbox(&mut s.clipping.transformed, "clip case 2 ((M^-1l).z ≤ 0)")
            .on_hover_text("max(ω'.z, 0) in D: a light pushed below the horizon by M^-1 contributes nothing. Off: it contributes negative light");
        let mut paper = s.normalization == Normalization::PaperLiteral;
        ui.checkbox(&mut paper, "paper-literal normalization")
            .on_hover_text("The paper's eq. 25 as printed: no 1/π in D and no magnitudes n_s, f_s, n_d (DESIGN §1 corrects both)");
        s.normalization = if paper {
            Normalization::PaperLiteral
        } else {
            Normalization::Corrected
        };
        ui.separator();
        ui.strong("Scene");
        ui.horizontal_wrapped(|ui| {
            for (name, _) in PRESETS {
                if ui
                    .small_button(name)
                    .on_hover_text("Load this shipped preset")
                    .clicked()
                {
                    s.scene = preset(name);
                    s.light_count = s.scene.lights.len();
                    s.selected_light = None;
                }
            }
        });
        ui.horizontal(|ui| {
            ui.add(egui::TextEdit::singleline(&mut s.scene_path).desired_width(120.0))
                .on_hover_text("A scene TOML file to load, or to save to (only the file named here is written)");
            if ui.small_button("load").on_hover_text("Read the scene file named on the left").clicked() {
                self.message = Some(match Scene::load(std::path::Path::new(&s.scene_path)) {
                    Ok(scene) => {
                        s.light_count = scene.lights.len();
                        s.scene = scene;
                        (false, format!("loaded {}", s.scene_path))
                    }
                    Err(e) => (true, e.to_string()),
                });
            }
            if ui.small_button("save").on_hover_text("Write the scene to the file named on the left (and no other)").clicked() {
                let text = s.scene.to_toml();
                self.message = Some(
                    match crate::error::write_atomically(std::path::Path::new(&s.scene_path), text.as_bytes()) {
                        Ok(()) => (false, format!("saved {}", s.scene_path)),
                        Err(e) => (true, e.to_string()),
                    },
                );
            }
        });
        ui.horizontal(|ui| {
            ui.label("LTC table:");
            let before = s.table;
            for (t, name, hover) in [
                (crate::ltc::lut::Table::Classic, "classic", "ltc_code's fit (luts/ltc.exr): made for area lights' integrals"),
                (crate::ltc::lut::Table::Point, "point", "The point-light fit (luts/ltc_point.exr): minimizes ∫|n·D − f·cos| / ∫ f·cos, what one point light sees"),
            ] {
                ui.selectable_value(&mut s.table, t, name).on_hover_text(hover);
            }
            if s.table != before {
                *new_lut = Some(Lut::shipped(s.table).clone());
                s.lut_path.clear();
            }
        });
        ui.horizontal(|ui| {
            ui.add(egui::TextEdit::singleline(&mut s.lut_path).desired_width(120.0).hint_text("embedded LUT"))
                .on_hover_text("An LTC table (.exr, as `ltc-lab fit` writes it) to shade with; empty for the embedded one");
            if ui.small_button("use LUT").on_hover_text("Load the table named on the left; a missing or broken file is reported here and the current table stays").clicked() {
                let loaded = if s.lut_path.trim().is_empty() {
                    Ok(Lut::embedded().clone())
                } else {
                    Lut::read(std::path::Path::new(s.lut_path.trim()))
                };
                self.message = Some(match loaded {
                    Ok(lut) => {
                        *new_lut = Some(lut);
                        (false, format!("shading with {}", if s.lut_path.trim().is_empty() { "the embedded LUT" } else { s.lut_path.trim() }))
                    }
                    Err(e) => (true, format!("{e} — still using the previous table")),
                });
            }
        });
        ui.horizontal(|ui| {
            ui.add(egui::TextEdit::singleline(&mut s.screenshot_path).desired_width(120.0))
                .on_hover_text(
                    "Screenshot file: .png saves the window, .exr the plane's linear radiance",
                );
            if ui.small_button("screenshot").clicked() {
                let path = std::path::PathBuf::from(&s.screenshot_path);
                if path
                    .extension()
                    .is_some_and(|e| e.eq_ignore_ascii_case("exr"))
                {
                    self.message = Some(match self.plane.save_exr(&path, s.scene.exposure) {
                        Ok(()) => (false, format!("saved {}", path.display())),
                        Err(e) => (true, e),
                    });
                } else {
                    self.screenshot = Some(PendingScreenshot::new(path));
                }
            }
        });
        if let Some((is_error, text)) = &self.message {
            let colour = if *is_error {
                egui::Color32::from_rgb(230, 90, 80)
            } else {
                ui.visuals().text_color()
            };
            ui.colored_label(colour, text);
        }
    }

    /// Requests and saves a pending screenshot; true once it is written (or failed).
    fn handle_screenshot(&mut self, ctx: &egui::Context) -> bool {
        let Some(p) = &mut self.screenshot else {
            return false;
        };
        if !p.requested {
            let slot = p.slot.clone();
            ctx.request_screenshot(move |image| *slot.lock().expect("not poisoned") = Some(image));
            p.requested = true;
            ctx.request_repaint();
            return false;
        }
        let Some(image) = p.slot.lock().expect("not poisoned").take() else {
            ctx.request_repaint();
            return false;
        };
        let rgba = image::RgbaImage::from_raw(
            image.width() as u32,
            image.height() as u32,
            image.as_raw().to_vec(),
        );
        let path = p.path.clone();
        self.message = Some(match rgba.map(|img| img.save(&path)) {
            Some(Ok(())) => (false, format!("saved {}", path.display())),
            Some(Err(e)) => (true, format!("{}: {e}", path.display())),
            None => (true, "the screenshot had an unexpected size".into()),
        });
        self.screenshot = None;
        true
    }
}

impl eframe::App for LabApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.show(ui);
        let ctx = ui.ctx().clone();
        self.handle_screenshot(&ctx);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, STORAGE_KEY, &self.state);
    }
}

/// `ltc-lab lab --screenshot`: the app that shows a few frames, saves the window and exits.
pub struct ScreenshotApp {
    pub app: LabApp,
    pub path: std::path::PathBuf,
    pub frames: u32,
    pub result: std::sync::Arc<std::sync::Mutex<Option<Result<(), String>>>>,
}

/// Frames drawn before the screenshot: textures uploaded, layout settled (egui lays out
/// sizes on the first frame and draws on the second).
pub const SCREENSHOT_AFTER_FRAMES: u32 = 4;

impl eframe::App for ScreenshotApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.app.show(ui);
        let ctx = ui.ctx().clone();
        self.frames += 1;
        if self.frames == SCREENSHOT_AFTER_FRAMES {
            self.app.screenshot = Some(PendingScreenshot::new(self.path.clone()));
        }
        if self.app.handle_screenshot(&ctx) {
            let outcome = match &self.app.message {
                Some((false, _)) => Ok(()),
                Some((true, e)) => Err(e.clone()),
                None => Err("no screenshot".into()),
            };
            *self.result.lock().expect("not poisoned") = Some(outcome);
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
        ctx.request_repaint();
    }
}
