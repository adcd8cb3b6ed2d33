//! The lab: an eframe app with five panels — the lobe on the sphere, the fitted matrix and
//! the LUT, the plane in split or difference view, the paper's Figure 2 clipping cases, and
//! speed against accuracy — and the global controls beside them. State persists between runs.

#[cfg(target_arch = "wasm32")]
pub mod browser;
pub mod chart;
pub mod clicks;
pub mod clipping;
pub mod controls;
pub mod device;
pub mod file_io;
pub mod files;
pub mod lab;
pub mod layout;
pub mod lesson;
pub mod link;
pub mod lobe;
pub mod matrix;
pub mod panel;
pub mod panels;
pub mod plane;
pub mod report;
pub mod screenshot;
pub mod state;
pub mod ui;
pub mod work;

pub use lab::{Lab, Message};
pub use panel::{Panel, PanelId};
pub use report::Report;
pub use screenshot::{PendingScreenshot, ScreenshotApp, Settling};
pub use state::LabState;

use crate::app::lab::Request;
use crate::app::panels::Panels;
use crate::app::plane::shading;
use crate::app::state::WindowState;
use crate::app::ui::widgets;
use crate::app::work::background;
use crate::scene::Scene;

/// The window: the lab the panels share, the panels, and the layout.
pub struct LabApp {
    lab: Lab,
    panels: Panels,
    window: WindowState,
    /// A screenshot on its way to a file.
    screenshot: Option<PendingScreenshot>,
    /// The plane's EXR the user asked for, saved once its image is read back.
    saving_exr: Option<std::path::PathBuf>,
    /// Milliseconds the last frame spent in each panel, in `PanelId::ALL`'s order.
    part_ms: [f64; PanelId::ALL.len()],
    /// The window's size in points when the zoom was last looked at, and its size at zoom 1
    /// when it was last fitted.
    zoomed_for: Option<([u32; 2], [u32; 2])>,
    /// The panels the last frame drew.
    shown: Vec<PanelId>,
    /// The panels' caches' counts after the last frame, and the caches it made again.
    counts: Vec<(&'static str, u64)>,
    remade: Vec<&'static str>,
    /// The lesson being walked, with its bar.
    lesson: Option<lesson::bar::LessonBar>,
    /// Files the browser is reading: picked for a purpose, or dropped (`None`: each for what
    /// its name says).
    #[cfg(target_arch = "wasm32")]
    picking: Option<(Option<files::Purpose>, browser::Picked)>,
}

/// What a start asks of the lab beyond its state (the command line's `lab` options).
#[derive(Clone, Debug, Default)]
pub struct Startup {
    pub scene: Option<Scene>,
    pub lights: Option<usize>,
    /// One panel maximised.
    pub panel: Option<PanelId>,
    /// Fill the chart, as its *measure* button does.
    pub measure: bool,
    /// A lesson to walk, where it came from, and the step (from 0) to open it at.
    pub lesson: Option<(lesson::Lesson, String, usize)>,
    /// A method file to shade with (`lab --method-file`), read and checked.
    pub method_file: Option<crate::gpu::method_file::MethodFile>,
}

/// The key eframe keeps the lab's state under.
pub const STORAGE_KEY: &str = "ltc-lab-state";

impl LabApp {
    /// The lab of `state` (every value checked where it enters; what was refused or clamped
    /// is said), drawing with the window's wgpu device (`render_state`: eframe's, or a test
    /// harness's); without one, the plane is drawn by the CPU reference.
    pub fn new(mut state: LabState, render_state: Option<&egui_wgpu::RenderState>) -> Self {
        let notes = state.check();
        let device = device::of_window(render_state);
        let gpu = device.as_ref().ok().zip(render_state);
        let (panels, why) = Panels::new(&state, gpu);
        let device = match why {
            Some(why) => Err(why),
            None => device,
        };
        let max_lights = device.as_ref().map_or(crate::scene::MAX_LIGHTS, |g| {
            crate::gpu::renderer::PlaneRenderer::max_lights(g)
        });
        let mut lab = Lab::new(state.lab, device, max_lights);
        let notes: Vec<String> = notes
            .into_iter()
            .chain(lab.message().map(|m| m.text.clone()))
            .collect();
        if !notes.is_empty() {
            lab.say(Message::error(notes.join("; ")));
        }
        Self {
            lab,
            panels,
            window: state.window,
            screenshot: None,
            saving_exr: None,
            part_ms: [0.0; PanelId::ALL.len()],
            zoomed_for: None,
            shown: Vec::new(),
            counts: Vec::new(),
            remade: Vec::new(),
            lesson: None,
            #[cfg(target_arch = "wasm32")]
            picking: None,
        }
    }

    /// The lab as eframe starts it: the state it kept (or the defaults), with the view of
    /// `view` over it where given (a link; `None` where it is not a view, which is refused
    /// with why), on eframe's device.
    pub fn from_creation_context(cc: &eframe::CreationContext<'_>, view: Option<&str>) -> Self {
        let (stored, unread) = match cc.storage.and_then(|s| s.get_string(STORAGE_KEY)) {
            None => (LabState::default(), None),
            Some(text) => match ron::from_str::<LabState>(&text) {
                Ok(state) => (state, None),
                Err(e) => (LabState::default(), Some(e)),
            },
        };
        let (state, refused) = match view.map(|v| link::decode(v, &stored)) {
            None => (stored, None),
            Some(Ok(state)) => (state, None),
            Some(Err(why)) => (LabState::default(), Some(why)),
        };
        clicks::keep_slow_clicks(&cc.egui_ctx);
        let mut app = Self::new(state, cc.wgpu_render_state.as_ref());
        if let Some(e) = unread {
            app.lab.say(Message::error(format!(
                "the settings kept from the last run could not be read ({e}): showing the defaults"
            )));
        }
        if let Some(why) = refused {
            app.lab.say(Message::error(format!(
                "the link's view could not be opened ({why}): showing the defaults"
            )));
        }
        app
    }

    /// What a start asks for, over the state.
    pub fn start_with(&mut self, s: Startup) {
        if let Some(scene) = s.scene {
            self.lab.use_scene(scene);
        }
        if let Some(n) = s.lights {
            self.lab.set_light_count(n);
        }
        if s.panel.is_some() {
            self.window.maximised = s.panel;
        }
        // The method file before the measurement, which measures it too (it was loaded after,
        // and `lab --measure --method-file` left the file's point out).
        if let Some(file) = s.method_file {
            let said = self.lab.use_method_file(file);
            self.lab.say(said);
        }
        if s.measure {
            self.panels.start_measurement(&self.lab);
        }
        if let Some((lesson, source, step)) = s.lesson {
            self.open_lesson(lesson, &source, step);
        }
    }

    /// The lab, read-only.
    pub fn lab(&self) -> &Lab {
        &self.lab
    }

    /// What the user set, as eframe keeps it.
    pub fn state(&self) -> LabState {
        let mut state = LabState {
            lab: self.lab.shared().clone(),
            window: self.window.clone(),
            ..LabState::default()
        };
        self.panels.save_into(&mut state);
        state
    }

    /// Whether anything is still being computed for the window: by a panel it shows, the
    /// plane's render, the clipping pictures, a measurement, a refit.
    pub fn busy(&self) -> bool {
        !self.panels.working(&self.shown).is_empty()
    }

    /// The whole window: the notices bar, the side panel (unless folded), then the panels —
    /// one maximised, all in a grid, or, below the grid's size, one at a time under tabs.
    fn show(&mut self, ui: &mut egui::Ui) {
        self.fit_zoom(ui.ctx());
        if let Some(m) = self.lab.message().cloned() {
            let dismissed = egui::Panel::bottom("notices")
                .show(ui, |ui| widgets::message_bar(ui, &m))
                .inner;
            if dismissed {
                self.lab.dismiss();
            }
        }
        self.part_ms = [0.0; PanelId::ALL.len()];
        self.shown.clear();
        self.take_dropped(ui.ctx());
        self.lesson_keys(ui.ctx());
        // The browser's share of the work that runs on threads on the desktop.
        if background::run_for(shading::FRAME_BUDGET_MS) {
            ui.ctx().request_repaint();
        }
        self.layout(ui);
        self.carry_out(ui.ctx());
        self.count_caches(ui.ctx().current_pass_index() == 0);
    }

    /// The caches made again this frame, from their counts: over all of its passes (egui runs
    /// a frame again where a widget's size changed, and the pass that made a cache is then not
    /// the last).
    fn count_caches(&mut self, first_pass: bool) {
        let counts = self.panels.caches();
        if first_pass {
            self.remade.clear();
        }
        for c in counts.iter().filter(|c| !self.counts.contains(c)) {
            if !self.remade.contains(&c.0) {
                self.remade.push(c.0);
            }
        }
        self.counts = counts;
    }

    /// Carries out what the panels asked for: a file read or written, the view shared.
    fn carry_out(&mut self, ctx: &egui::Context) {
        #[cfg(target_arch = "wasm32")]
        self.take_picked();
        if let Some(path) = &self.saving_exr {
            let exposure = self.lab.exposure().0;
            match self.panels.save_plane_exr(path, exposure) {
                Some(Ok(done)) => self.lab.say(Message::note(done)),
                Some(Err(e)) => self.lab.say(Message::error(e)),
                None => ctx.request_repaint(),
            }
            if !self.panels.plane_read_pending() {
                self.saving_exr = None;
            }
        }
        for request in self.lab.take_requests() {
            match request {
                Request::SaveExr(path) => self.saving_exr = Some(path),
                Request::Screenshot(path) => self.screenshot = Some(PendingScreenshot::new(path)),
                Request::SaveScene(path) => self.save_scene(&path),
                Request::Share => self.share(ctx),
                Request::Open(purpose, path) => self.open(purpose, &path, ctx),
            }
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

impl Settling for LabApp {
    fn busy(&self) -> bool {
        LabApp::busy(self)
    }

    fn report(&self) -> Report {
        LabApp::report(self)
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
    /// (`layout::auto_zoom`): restored, eframe would size the next window by it (`--size
    /// 1920x1080` after a 4K session would open a 3840×2160 window at zoom 2).
    fn persist_egui_memory(&self) -> bool {
        false
    }
}
