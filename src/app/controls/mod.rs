//! The side panel: every global control, each with a tooltip naming what it changes in the
//! equations. It edits the lab's parts; a file to read or write is a request the app carries
//! out.

use serde::{Deserialize, Serialize};

use crate::app::lab::Lab;
use crate::app::panel::Panel;

mod files;
mod lights;
mod material;
mod rules;

use files::{method_file, save_buttons, scene_files, table};
use lights::lights;
use material::material;
use rules::shading_rules;

/// The light counts the slider offers, at most (and at most what the adapter shades).
pub const MAX_LIGHT_SLIDER: usize = 100_000;

/// The side panel's files, kept between runs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ControlsState {
    pub scene_path: String,
    pub screenshot_path: String,
    /// A LUT file to shade with; empty: the embedded table.
    pub lut_path: String,
    /// A method file's path (the path alone is kept, never its code).
    pub method_path: String,
}

impl Default for ControlsState {
    fn default() -> Self {
        Self {
            scene_path: "scene.toml".into(),
            screenshot_path: "ltc-lab.png".into(),
            lut_path: String::new(),
            method_path: String::new(),
        }
    }
}

/// Whether the load buttons open the browser's file picker (the web build) instead of
/// reading the path in their field (the desktop).
const PICKS: bool = cfg!(target_arch = "wasm32");

/// The side panel.
#[derive(Default)]
pub struct ControlsPanel {
    state: ControlsState,
}

impl ControlsPanel {
    pub fn new(state: ControlsState) -> Self {
        Self { state }
    }

    pub fn state(&self) -> &ControlsState {
        &self.state
    }
}

impl Panel for ControlsPanel {
    fn show(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        ui.heading("LTC Lab");
        ui.label(egui::RichText::new(lab.describe_device()).small())
            .on_hover_text("The adapter the plane and chart panels shade on");
        if let Some(e) = lab.device_error() {
            ui.colored_label(
                egui::Color32::from_rgb(230, 120, 60),
                format!(
                    "GPU unavailable — the plane is drawn by the CPU reference at reduced size. {e}"
                ),
            );
        }
        ui.separator();
        material(ui, lab);
        ui.separator();
        lights(ui, lab);
        ui.separator();
        shading_rules(ui, lab);
        ui.separator();
        ui.strong("Scene");
        scene_files(ui, lab, &mut self.state);
        table(ui, lab, &mut self.state);
        method_file(ui, lab, &mut self.state);
        save_buttons(ui, lab, &mut self.state);
    }
}
