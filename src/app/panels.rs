//! The panels, in one registry (as egui's demo app iterates its apps): the side panel and
//! the five panels of the grid. The window lays them out, the frame log times them, the
//! page and the screenshot ask whether they are busy: all from `PanelId::ALL` and
//! `Panels::get`.

use crate::app::chart::ChartPanel;
use crate::app::clipping::ClippingPanel;
use crate::app::controls::ControlsPanel;
use crate::app::lab::Lab;
use crate::app::lab::Message;
use crate::app::lesson::Now;
use crate::app::lobe::LobePanel;
use crate::app::matrix::MatrixPanel;
use crate::app::panel::{Panel, PanelId};
use crate::app::plane::PlanePanel;
use crate::app::plane::shading::Progress;
use crate::app::state::LabState;
use crate::error::Result;
use crate::gpu::GpuContext;
use crate::measure::study::StudyRow;

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

    /// Writes the plane's finished image as EXR to the path the user named, once it is read
    /// back: `None` until then (`PlanePanel::save_exr`).
    pub fn save_plane_exr(
        &mut self,
        path: &std::path::Path,
        exposure: f64,
    ) -> Option<Result<String, String>> {
        self.plane.save_exr(path, exposure)
    }

    /// Whether the plane's image is still being read back for `save_plane_exr`.
    pub fn plane_read_pending(&self) -> bool {
        self.plane.read_pending()
    }

    /// How far the plane's render is, and its size once it has shown one (for the report).
    pub fn plane_progress(&self) -> (&Progress, Option<(usize, usize)>) {
        (self.plane.progress(), self.plane.size())
    }

    /// Hands the chart a study read from a file, and says what became of it.
    pub fn use_study(&mut self, rows: Result<Vec<StudyRow>>, name: &str) -> Message {
        self.chart.use_study(rows, name)
    }

    /// Starts the chart's measurement (`lab --measure`).
    pub fn start_measurement(&mut self, lab: &Lab) {
        self.chart.start(lab);
    }
}
