//! What the clipping panel shades its Figure-2 scenes with, kept between runs: per case its
//! α and its light, the table, and the case whose legend and profile are shown.

use serde::{Deserialize, Serialize};

use crate::app::lab::part::Notes;
use crate::app::lab::{Checked, TableId};
use crate::ltc::lut::ALPHA_MIN;
use crate::scene::{Scene, preset};

/// The clipping panel's own settings (its rules are the lab's).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ClippingState {
    /// The row whose case map legend and profile are shown.
    pub clip_scene: ClipScene,
    pub setup: ClipSetup,
    /// The elevation view (one light's error over its height) above Figure 2's rows, where a
    /// lesson's step is about it.
    pub elevation_first: bool,
}

impl Default for ClippingState {
    fn default() -> Self {
        Self {
            clip_scene: ClipScene::Case1,
            setup: ClipSetup::default(),
            elevation_first: false,
        }
    }
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
    pub table: TableId,
}

/// How far the case lights' fields reach, scene units: the plane spans ±2, and a light
/// farther than a plane's width off it lights the pictures as a distant one does.
pub const LIGHT_REACH: f64 = 3.0;

impl Checked for ClippingState {
    fn check(&mut self, previous: &Self) -> Vec<String> {
        let mut n = Notes(Vec::new());
        let (s, p) = (&mut self.setup, &previous.setup);
        n.numbers(
            "the clipping panel's α",
            &mut s.alpha,
            &p.alpha,
            [ALPHA_MIN, 1.0],
        );
        for (k, (light, before)) in s.light.iter_mut().zip(&p.light).enumerate() {
            let field = format!("the clipping panel's light {k}");
            n.numbers(&field, light, before, [-LIGHT_REACH, LIGHT_REACH]);
        }
        n.0
    }
}

impl Default for ClipSetup {
    /// The presets' α and lights (assets/scenes/figure2-*.toml).
    fn default() -> Self {
        let scenes = ClipScene::ALL.map(|c| preset(c.preset()));
        Self {
            alpha: scenes.each_ref().map(|s| s.material.alpha),
            light: scenes.each_ref().map(|s| s.lights[0].position),
            table: TableId::A,
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
