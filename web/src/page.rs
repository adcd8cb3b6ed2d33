//! The lab on the page: opened on the view of the address's fragment (a broken one gives the
//! defaults and says why), and reporting itself in the page's `#lab-state` element as JSON —
//! the lab's own `Report` (busy, the plane's progress, how it shades, the panels it shows,
//! the message), when its first frame was drawn and when it settled, and its view — for the
//! browser test and any other tool that reads the page.

use eframe::wasm_bindgen::JsCast;
use ltc_lab::app::link::{self, FRAGMENT_KEY};
use ltc_lab::app::{LabApp, Report, browser};
use serde::Serialize;

/// How often the page's report is brought up to date (the view's encoding regenerates a
/// scene's lights to see whether they are generated ones: not every frame).
const REPORT_EVERY_MS: f64 = 250.0;

pub struct PageLab {
    app: LabApp,
    /// When the first frame was drawn (ms since the page's navigation started).
    first_frame_ms: Option<f64>,
    /// When the lab first had nothing left to compute (the plane drawn, the clipping
    /// pictures made).
    settled_ms: Option<f64>,
    reported_at: f64,
    /// Whether the lab was busy at the last report, its message, and its lesson's step.
    reported_busy: Option<(bool, Option<String>, Option<(usize, bool)>)>,
}

/// What `#lab-state` holds.
#[derive(Serialize)]
struct PageReport {
    first_frame_ms: Option<f64>,
    settled_ms: Option<f64>,
    reported_ms: f64,
    #[serde(flatten)]
    lab: Report,
    view: String,
}

impl PageLab {
    pub fn new(cc: &eframe::CreationContext<'_>) -> Self {
        let fragment = browser::fragment();
        if crate::texts::requested() {
            cc.egui_ctx.add_plugin(crate::texts::TextMap::default());
        }
        let mut app = LabApp::from_creation_context(cc, fragment.strip_prefix(FRAGMENT_KEY));
        app.open_lesson_link(&fragment);
        Self {
            app,
            first_frame_ms: None,
            settled_ms: None,
            reported_at: f64::NEG_INFINITY,
            reported_busy: None,
        }
    }

    /// The page's report of the lab, as JSON.
    fn report(&self) -> String {
        let report = PageReport {
            first_frame_ms: self.first_frame_ms.map(f64::round),
            settled_ms: self.settled_ms.map(f64::round),
            reported_ms: browser::now_ms().round(),
            lab: self.app.report(),
            view: link::encode(&self.app.state()),
        };
        serde_json::to_string(&report).unwrap_or_else(|e| {
            serde_json::json!({ "error": format!("the report does not serialize: {e}") })
                .to_string()
        })
    }
}

impl eframe::App for PageLab {
    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        eframe::App::ui(&mut self.app, ui, frame);
        let now = browser::now_ms();
        self.first_frame_ms.get_or_insert(now);
        if self.settled_ms.is_none() && !self.app.busy() {
            self.settled_ms = Some(now);
        }
        // Also at once when the lab's work starts or ends, its message changes or a lesson
        // moves to another step: a finished lab draws no more frames, and a report left from
        // before would say it is still busy, or at the step before.
        let busy = (
            self.app.busy(),
            self.app.lab().message().map(|m| m.text.clone()),
            self.app
                .lesson()
                .map(|bar| (bar.step(), bar.done(bar.step()))),
        );
        if now - self.reported_at >= REPORT_EVERY_MS || self.reported_busy.as_ref() != Some(&busy) {
            self.reported_at = now;
            self.reported_busy = Some(busy);
            browser::write_element("lab-state", &self.report());
        }
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::App::save(&mut self.app, storage);
    }

    fn persist_egui_memory(&self) -> bool {
        eframe::App::persist_egui_memory(&self.app)
    }
}

/// The page's canvas `#lab`.
pub fn canvas() -> Result<web_sys::HtmlCanvasElement, String> {
    web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document")?
        .get_element_by_id("lab")
        .ok_or("the page has no canvas #lab")?
        .dyn_into::<web_sys::HtmlCanvasElement>()
        .map_err(|_| "#lab is not a canvas".to_string())
}

/// Shows `text` in the page's `#status` element (hidden when empty).
pub fn say(text: &str) {
    let status = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.get_element_by_id("status"));
    if let Some(el) = status {
        el.set_text_content(Some(text));
        let _ = el.set_attribute("style", if text.is_empty() { "display:none" } else { "" });
    }
}
