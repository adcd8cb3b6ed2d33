//! The lab on the page: opened on the view of the address's fragment (a broken one gives the
//! defaults and says why), and reporting itself in the page's `#lab-state` element as JSON —
//! when its first frame was drawn, how it shades, the panels it shows, its view — for the
//! browser test and any other tool that reads the page.

use eframe::wasm_bindgen::JsCast;
use ltc_lab::app::link::{self, FRAGMENT_KEY};
use ltc_lab::app::{LabApp, LabState, Message, browser};

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
    /// Whether the lab was busy at the last report, and its message's length.
    reported_busy: Option<(bool, Option<usize>)>,
}

impl PageLab {
    pub fn new(cc: &eframe::CreationContext<'_>) -> Self {
        let stored = LabApp::stored_state(cc);
        let fragment = browser::fragment();
        let (state, refused) = match fragment.strip_prefix(FRAGMENT_KEY) {
            None => (stored, None),
            Some(view) => match link::decode(view, &stored) {
                Ok(state) => (state, None),
                Err(why) => (LabState::default(), Some(why)),
            },
        };
        if crate::texts::requested() {
            cc.egui_ctx.add_plugin(crate::texts::TextMap::default());
        }
        let mut app = LabApp::new(state, cc.wgpu_render_state.as_ref());
        if let Some(why) = refused {
            app.lab.say(Message::error(format!(
                "the link's view could not be opened ({why}): showing the defaults"
            )));
        }
        Self {
            app,
            first_frame_ms: None,
            settled_ms: None,
            reported_at: f64::NEG_INFINITY,
            reported_busy: None,
        }
    }

    /// The panels still computing, quoted.
    fn working(&self) -> Vec<&'static str> {
        let a = &self.app;
        [
            ("\"plane\"", a.plane.busy()),
            ("\"clipping\"", a.clipping.busy()),
            ("\"chart\"", a.chart.busy()),
            ("\"matrix\"", a.matrix.busy()),
        ]
        .into_iter()
        .filter_map(|(name, busy)| busy.then_some(name))
        .collect()
    }

    /// The page's report of the lab, as JSON.
    fn report(&self) -> String {
        let panels: Vec<String> = self
            .app
            .shown
            .iter()
            .map(|p| format!("\"{}\"", p.name()))
            .collect();
        let shading = if self.app.lab.gpu.is_some() {
            "gpu"
        } else {
            "cpu"
        };
        format!(
            "{{\"first_frame_ms\": {}, \"settled_ms\": {}, \"reported_ms\": {:.0}, \"busy\": {}, \"working\": [{}], \"plane\": [{}, {}], \"shading\": \"{shading}\", \"device\": {}, \"panels\": [{}], \"message\": {}, \"view\": \"{}\"}}",
            ms(self.first_frame_ms),
            ms(self.settled_ms),
            browser::now_ms(),
            self.app.busy(),
            self.working().join(", "),
            self.app.plane.shading.progress.done,
            self.app.plane.shading.progress.total,
            json_string(&self.app.lab.describe_device()),
            panels.join(", "),
            self.app
                .lab
                .message
                .as_ref()
                .map_or("null".into(), |m| json_string(&m.text)),
            link::encode(&self.app.state()),
        )
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
        // Also at once when the lab's work starts or ends, or its message changes: a finished
        // lab draws no more frames, and a report left from before would say it is still busy.
        let busy = (
            self.app.busy(),
            self.app.lab.message.as_ref().map(|m| m.text.len()),
        );
        if now - self.reported_at >= REPORT_EVERY_MS || self.reported_busy != Some(busy) {
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

/// Milliseconds for JSON (`null`: not yet).
fn ms(t: Option<f64>) -> String {
    t.map_or("null".into(), |ms| format!("{ms:.0}"))
}

/// `text` as a JSON string.
pub fn json_string(text: &str) -> String {
    let mut out = String::from("\"");
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if u32::from(c) < 0x20 => out.push_str(&format!("\\u{:04x}", u32::from(c))),
            c => out.push(c),
        }
    }
    out.push('"');
    out
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
