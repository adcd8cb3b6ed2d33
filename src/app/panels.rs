//! The panels, in one registry (as egui's demo app iterates its apps): the side panel and
//! the five panels of the grid. The window lays them out, the frame log times them, the
//! page and the screenshot ask whether they are busy: all from `PanelId::ALL` and
//! `Panels::get`.

use crate::app::chart::ChartPanel;
use crate::app::clipping::ClippingPanel;
use crate::app::controls::ControlsPanel;
use crate::app::lab::Lab;
use crate::app::lesson::Now;
use crate::app::lobe::LobePanel;
use crate::app::matrix::MatrixPanel;
use crate::app::panel::{Panel, PanelId};
use crate::app::plane::PlanePanel;
use crate::app::state::LabState;
use crate::gpu::GpuContext;

/// The panels themselves.
pub struct Panels {
    controls: ControlsPanel,
    lobe: LobePanel,
    matrix: MatrixPanel,
    plane: PlanePanel,
    clipping: ClippingPanel,
    chart: ChartPanel,
}

impl Panels {
    /// The panels with their kept settings, the plane shaded on `gpu` (the lab's device and
    /// the window's render state) where there is one; and why the plane cannot shade there,
    /// where it cannot.
    pub fn new(
        state: &LabState,
        gpu: Option<(&GpuContext, &egui_wgpu::RenderState)>,
    ) -> (Self, Option<String>) {
        let (plane, why) = PlanePanel::new(state.plane.clone(), gpu);
        let panels = Self {
            controls: ControlsPanel::new(state.controls.clone()),
            lobe: LobePanel::new(state.lobe.clone()),
            matrix: MatrixPanel::default(),
            plane,
            clipping: ClippingPanel::new(state.clipping.clone()),
            chart: ChartPanel::new(state.chart.clone()),
        };
        (panels, why)
    }

    pub fn get(&self, id: PanelId) -> &dyn Panel {
        match id {
            PanelId::Controls => &self.controls,
            PanelId::Lobe => &self.lobe,
            PanelId::Matrix => &self.matrix,
            PanelId::Plane => &self.plane,
            PanelId::Clipping => &self.clipping,
            PanelId::Chart => &self.chart,
        }
    }

    pub fn get_mut(&mut self, id: PanelId) -> &mut dyn Panel {
        match id {
            PanelId::Controls => &mut self.controls,
            PanelId::Lobe => &mut self.lobe,
            PanelId::Matrix => &mut self.matrix,
            PanelId::Plane => &mut self.plane,
            PanelId::Clipping => &mut self.clipping,
            PanelId::Chart => &mut self.chart,
        }
    }

    /// The panels of `shown` still computing something (a panel's work advances as it is
    /// drawn: a hidden one's waits until it is shown again).
    pub fn working(&self, shown: &[PanelId]) -> Vec<PanelId> {
        shown
            .iter()
            .copied()
            .filter(|&id| self.get(id).busy())
            .collect()
    }

    /// Every cache of every panel, with its count.
    pub fn caches(&self) -> Vec<(&'static str, u64)> {
        PanelId::ALL
            .into_iter()
            .flat_map(|id| self.get(id).caches())
            .collect()
    }

    /// What the panels keep between runs, into `state`.
    pub fn save_into(&self, state: &mut LabState) {
        state.controls = self.controls.state().clone();
        state.lobe = self.lobe.state().clone();
        state.plane = self.plane.state().clone();
        state.clipping = self.clipping.state().clone();
        state.chart = self.chart.state().clone();
    }

    /// The panels' settings of a view (a lesson's step): the lobe's, the plane's and the
    /// clipping panel's, which a view carries.
    pub fn use_view(&mut self, state: &LabState) {
        self.lobe.set_state(state.lobe.clone());
        self.plane.set_state(state.plane.clone());
        self.clipping.set_state(state.clipping.clone());
    }

    /// What the lab shows now, as a lesson reads it.
    pub fn now<'a>(&'a self, lab: &'a Lab) -> Now<'a> {
        Now {
            lab,
            lobe: self.lobe.state(),
            plane: self.plane.state(),
            pinned: self.plane.pinned_terms(),
            measurement: self.chart.state().measurement.as_ref(),
            measurements: self.chart.finished(),
        }
    }

    /// The plane panel (the app saves its image and reports its progress).
    pub fn plane(&mut self) -> &mut PlanePanel {
        &mut self.plane
    }

    pub fn plane_ref(&self) -> &PlanePanel {
        &self.plane
    }

    /// The chart panel (the app hands it a study and starts a measurement).
    pub fn chart(&mut self) -> &mut ChartPanel {
        &mut self.chart
    }
}
