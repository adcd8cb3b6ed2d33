//! What the user set in the lab, persisted by eframe between runs: what the panels share,
//! each panel's own settings, and the window's; and the panels' names.

use serde::{Deserialize, Serialize};

use crate::app::chart::ChartState;
use crate::app::clip_setup::ClippingState;
use crate::app::controls::ControlsState;
use crate::app::lab::Shared;
use crate::app::lobe::LobeState;
use crate::app::plane::PlaneState;

/// The panels, for maximising one and for headless screenshots.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
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

    /// The name on the command line (`lab --panel`).
    pub fn name(self) -> &'static str {
        match self {
            Self::Lobe => "lobe",
            Self::Matrix => "matrix",
            Self::Plane => "plane",
            Self::Clipping => "clipping",
            Self::Chart => "chart",
        }
    }

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

/// Everything the user set; persisted by eframe between runs.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct LabState {
    pub lab: Shared,
    pub lobe: LobeState,
    pub plane: PlaneState,
    pub clipping: ClippingState,
    pub chart: ChartState,
    pub controls: ControlsState,
    pub window: WindowState,
}

/// How the window lays the panels out.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct WindowState {
    pub maximised: Option<PanelId>,
    /// The panel shown when the window is too small for the grid (tabs).
    pub tab: PanelId,
    /// The side panel folded away.
    pub controls_hidden: bool,
}

impl Default for WindowState {
    fn default() -> Self {
        Self {
            maximised: None,
            tab: PanelId::Plane,
            controls_hidden: false,
        }
    }
}
