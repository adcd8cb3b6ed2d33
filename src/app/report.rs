//! The lab in numbers, for tools: what the browser's page writes into `#lab-state`, and what
//! the frame log (`lab --frame-log`) records each frame — whether it is busy and with what,
//! the plane's progress, the panels shown and their milliseconds, the caches made again.

use serde::Serialize;

use crate::app::LabApp;
use crate::app::panel::PanelId;

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Report {
    pub busy: bool,
    /// The panels shown that are still computing.
    pub working: Vec<&'static str>,
    /// The plane's render: list entries summed, of the total.
    pub plane: [usize; 2],
    /// The plane's render's size in pixels, once it has one.
    pub plane_size: Option<[usize; 2]>,
    /// Where the plane is shaded: "gpu" or "cpu".
    pub shading: &'static str,
    pub device: String,
    /// The panels the last frame drew.
    pub panels: Vec<&'static str>,
    /// The notices bar's line.
    pub message: Option<String>,
    /// Milliseconds the last frame spent in each panel, in `PanelId::ALL`'s order (0 for one
    /// not shown).
    pub part_ms: Vec<f64>,
    /// The caches the last frame made again (`app::work::cache`), by name.
    pub remade: Vec<&'static str>,
    /// The lesson being walked, if any.
    pub lesson: Option<LessonReport>,
}

/// Where a lesson is.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LessonReport {
    /// A shipped lesson's name, or its file's.
    pub source: String,
    /// The step shown, from 1, of `steps`.
    pub step: usize,
    pub steps: usize,
    pub title: String,
    /// Its *try this* done.
    pub done: bool,
}

impl LabApp {
    /// The lab as the last frame left it.
    pub fn report(&self) -> Report {
        let (progress, plane_size) = self.panels.plane_progress();
        Report {
            busy: self.busy(),
            working: self
                .panels
                .working(&self.shown)
                .into_iter()
                .map(PanelId::name)
                .collect(),
            plane: [progress.done, progress.total],
            plane_size: plane_size.map(|(w, h)| [w, h]),
            shading: if self.lab.device().is_some() {
                "gpu"
            } else {
                "cpu"
            },
            device: self.lab.describe_device(),
            panels: self.shown.iter().map(|p| p.name()).collect(),
            message: self.lab.message().map(|m| m.text.clone()),
            part_ms: self.part_ms.to_vec(),
            remade: self.remade.clone(),
            lesson: self.lesson().map(|bar| LessonReport {
                source: bar.source().to_string(),
                step: bar.step() + 1,
                steps: bar.lesson().steps.len(),
                title: bar.current().title.clone(),
                done: bar.done(bar.step()),
            }),
        }
    }
}
