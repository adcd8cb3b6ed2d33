//! What the user set in the lab, persisted by eframe between runs, and the panels' names.

use serde::{Deserialize, Serialize};

use crate::ltc::lobe::Lobe;
use crate::ltc::lut::{Lut, THETA_MAX, Table};
use crate::ltc::{Clipping, LtcPair, Normalization};
use crate::render::{Method, View};
use crate::scene::{Scene, preset};

/// paper-100's light count (assets/scenes/paper-100.toml), whose intensities the light-count
/// slider's lights share.
const PAPER_LIGHT_COUNT: f64 = 100.0;

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

/// What the plane's side B is: the exact BRDF, or LTC with table B (two tables compared).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Compare {
    #[default]
    Brdf,
    TableB,
}

/// Everything the user set; persisted by eframe between runs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct LabState {
    pub scene: Scene,
    /// θo of the lobe and matrix panels, degrees.
    pub theta_o_deg: f64,
    /// The LTC and BRDF forms compared in the plane panel.
    pub method_ltc: Method,
    pub method_brdf: Method,
    /// Split (LTC | BRDF), difference map, or one method alone (A: the LTC form, B: the
    /// BRDF form).
    pub view: View,
    pub divider: f64,
    pub clipping: Clipping,
    pub normalization: Normalization,
    /// Multiplies every light's intensity when shading.
    pub intensity_scale: f64,
    /// Replaces every light's range when > 0.
    pub range_override: f64,
    /// Tiled culling of ranged lights in the plane's render (the same image, faster).
    pub cull: bool,
    /// The plane's live GPU times in its progress line (off for a slide or a screenshot
    /// that must not change run to run).
    pub show_gpu_times: bool,
    pub light_count: usize,
    pub seed: u64,
    pub selected_light: Option<usize>,
    /// The plane's pinned pixel, in image coordinates (0–1), opened into its lights.
    pub pinned: Option<[f64; 2]>,
    /// The pinned pixel's lights table: the column sorted by, and whether descending.
    pub light_sort: (LightColumn, bool),
    /// A light of the pinned pixel shown on the lobe panel: ω in the shading frame.
    pub lobe_light: Option<[f64; 3]>,
    pub lobe: Lobe,
    /// 0: the clamped cosine (M = I); 1: the fitted LTC.
    pub morph: f64,
    pub orbit_yaw: f32,
    pub orbit_pitch: f32,
    pub colour_difference: bool,
    /// The clipping panel's row whose case map legend and profile are shown.
    pub clip_scene: ClipScene,
    /// The clipping panel's α, lights and table (the rules are `clipping`, the lab's).
    pub clip_setup: ClipSetup,
    pub maximised: Option<PanelId>,
    /// The panel shown when the window is too small for the grid (tabs).
    pub tab: PanelId,
    /// The side panel folded away.
    pub controls_hidden: bool,
    pub scene_path: String,
    pub screenshot_path: String,
    /// A LUT file to shade with; empty: the embedded table.
    pub lut_path: String,
    /// Which shipped table shades (classic or the point-light fit), unless `table_file`.
    pub table: Table,
    /// The file table A was loaded from; read again at the next start.
    pub table_file: Option<String>,
    /// Overlay table B's LTC in the lobe panel.
    pub overlay_other_fit: bool,
    /// The plane's side B.
    pub compare: Compare,
    /// The chart's last measurement (or study), kept between runs.
    pub measurement: Option<crate::app::measure::Measurement>,
    /// The matrix panel's last refit, kept between runs.
    pub refit: Option<crate::app::refit::RefitResult>,
}

/// The columns of the pinned pixel's lights table (sortable).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum LightColumn {
    Index,
    Elevation,
    ElevationCos,
    Case,
    DSpec,
    Jacobian,
    Fresnel,
    Irradiance,
    Ltc,
    Exact,
    ErrorShare,
}

/// The Figure-2 scene whose case map and profile the clipping panel shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum ClipScene {
    Normal,
    Case1,
    Case2,
}

impl ClipScene {
    pub const ALL: [Self; 3] = [Self::Normal, Self::Case1, Self::Case2];

    pub fn index(self) -> usize {
        self as usize
    }

    pub fn preset(self) -> &'static str {
        match self {
            Self::Normal => "figure2-normal",
            Self::Case1 => "figure2-case1",
            Self::Case2 => "figure2-case2",
        }
    }
}

/// What the clipping panel shades its Figure-2 scenes with: per scene (normal, case 1,
/// case 2) its α and its light's position, and table A or B.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ClipSetup {
    pub alpha: [f64; 3],
    pub light: [[f64; 3]; 3],
    pub table_b: bool,
}

impl Default for ClipSetup {
    /// The presets' α and lights (assets/scenes/figure2-*.toml).
    fn default() -> Self {
        let scenes = ClipScene::ALL.map(|c| preset(c.preset()));
        Self {
            alpha: scenes.each_ref().map(|s| s.material.alpha),
            light: scenes.each_ref().map(|s| s.lights[0].position),
            table_b: false,
        }
    }
}

impl ClipSetup {
    /// The scene `which` with this setup's α and light; `light_of` picks whose light (the
    /// normal light of (a)/(b) is shaded with the case row's α).
    pub fn scene(&self, which: ClipScene, light_of: ClipScene) -> Scene {
        let mut s = preset(which.preset());
        s.material.alpha = self.alpha[light_of.index()];
        s.lights[0].position = self.light[which.index()];
        s
    }
}

impl Default for LabState {
    fn default() -> Self {
        let scene = preset("paper-100");
        Self {
            light_count: scene.lights.len(),
            scene,
            theta_o_deg: 45.0,
            method_ltc: Method::LtcFast,
            method_brdf: Method::Brdf,
            view: View::Split,
            divider: 0.5,
            clipping: Clipping::BOTH,
            normalization: Normalization::Corrected,
            intensity_scale: 1.0,
            range_override: 0.0,
            cull: true,
            show_gpu_times: true,
            seed: 27,
            selected_light: None,
            pinned: None,
            light_sort: (LightColumn::ErrorShare, true),
            lobe_light: None,
            lobe: Lobe::Specular,
            morph: 1.0,
            orbit_yaw: 0.6,
            orbit_pitch: 0.35,
            colour_difference: false,
            clip_scene: ClipScene::Case1,
            clip_setup: ClipSetup::default(),
            maximised: None,
            tab: PanelId::Plane,
            controls_hidden: false,
            scene_path: "scene.toml".into(),
            screenshot_path: "ltc-lab.png".into(),
            lut_path: String::new(),
            table: Table::Classic,
            table_file: None,
            overlay_other_fit: true,
            compare: Compare::Brdf,
            measurement: None,
            refit: None,
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

    /// Shows `scene` (a preset, a loaded file, the one the lab started with), its lights cut
    /// to the `max_lights` this adapter shades, which it then says; the light selection is
    /// cleared, as it may name a light the new scene lacks.
    pub fn use_scene(&mut self, scene: Scene, max_lights: usize) -> Option<String> {
        self.scene = scene;
        self.selected_light = None;
        self.keep_lights(max_lights)
    }

    /// Cuts the scene's lights to the `max_lights` this adapter shades, and says so.
    pub fn keep_lights(&mut self, max_lights: usize) -> Option<String> {
        let held = self.scene.lights.len();
        self.scene.lights.truncate(max_lights);
        self.light_count = self.scene.lights.len();
        self.selected_light = self.selected_light.filter(|&k| k < self.light_count);
        (held > max_lights).then(|| {
            format!(
                "the scene holds {held} lights, more than the {max_lights} this adapter shades at once: the first {max_lights} are kept"
            )
        })
    }

    /// `count` lights from the seeded generator, as the lights slider makes them (heights
    /// 0.05–0.6, paper-100's intensities and range); they replace the current ones.
    pub fn set_light_count(&mut self, count: usize) {
        self.light_count = count;
        // paper-100's intensities, scaled down past 100 lights so that the total power stays
        // paper-100's: 20 000 lights at those intensities only show a white plane.
        let dim = (PAPER_LIGHT_COUNT / count.max(1) as f64).min(1.0);
        self.scene.lights = crate::scene::generate_lights(
            &crate::scene::RandomLights {
                count,
                seed: self.seed,
                height: [0.05, 0.6],
                intensity: [0.02 * dim, 0.08 * dim],
                range: Some(crate::bench::DEFAULT_RANGE),
            },
            self.scene.plane.half_size,
        );
        self.selected_light = None;
    }

    /// The LTC pair of the lobe and matrix panels' (θo, α).
    pub fn ltc_pair(&self, lut: &Lut) -> LtcPair {
        let theta = self.theta_o_deg.to_radians().min(THETA_MAX);
        lut.sample(self.alpha(), theta.cos()).ltc_pair()
    }
}
