//! What the user set in the lab, as eframe keeps it between runs and a link carries it: the
//! lab's parts, each panel's own settings, and the window's. Whoever hands it over (stored
//! state, a link, a lesson), every value is checked where it enters (`LabState::check`).

use serde::{Deserialize, Serialize};

use crate::app::chart::ChartState;
use crate::app::clipping::setup::ClippingState;
use crate::app::controls::ControlsState;
use crate::app::lab::{Checked, Shared};
use crate::app::lobe::LobeState;
use crate::app::panel::PanelId;
use crate::app::plane::PlaneState;

/// Everything the user set.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct LabState {
    pub lab: Shared,
    pub lobe: LobeState,
    pub plane: PlaneState,
    pub clipping: ClippingState,
    pub chart: ChartState,
    pub controls: ControlsState,
    pub window: WindowState,
}

impl LabState {
    /// Every value within its range (against the defaults: what came in had no value before
    /// it); what was refused or clamped, named.
    pub fn check(&mut self) -> Vec<String> {
        let mut notes = self.lab.check();
        notes.extend(self.lobe.check(&LobeState::default()));
        notes.extend(self.plane.check(&PlaneState::default()));
        notes.extend(self.clipping.check(&ClippingState::default()));
        notes.extend(self.chart.check(&ChartState::default()));
        notes.extend(self.window.check(&WindowState::default()));
        notes
    }
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

impl Checked for WindowState {
    /// Only the grid's panels are shown alone.
    fn check(&mut self, previous: &Self) -> Vec<String> {
        let mut notes = Vec::new();
        if self.maximised.is_some_and(|p| !PanelId::GRID.contains(&p)) {
            notes.push("the maximised panel: not one of the grid's, refused".into());
            self.maximised = previous.maximised;
        }
        if !PanelId::GRID.contains(&self.tab) {
            notes.push("the tab: not one of the grid's panels, refused".into());
            self.tab = previous.tab;
        }
        notes
    }
}
