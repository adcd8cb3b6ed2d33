//! What the panels look at: the lobe and matrix panels' view (θo, α, the light), the selected
//! light, and the matrix panel's last refit; each checked where it enters the lab.

use serde::{Deserialize, Serialize};

use crate::app::lab::part::{Checked, notes};
use crate::app::lab::refit_result::RefitResult;
use crate::ltc::lobe::Lobe;

/// The lobe and matrix panels' view: θo, which lobe, and a light of the plane's pinned pixel
/// shown on the lobe.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct LobeView {
    /// Degrees.
    pub theta_o_deg: f64,
    /// The view's azimuth from the tangent, in degrees (an anisotropic material's fourth
    /// axis; an isotropic lobe is the same at every φo).
    pub phi_o_deg: f64,
    pub lobe: Lobe,
    /// ω in the shading frame, unit.
    pub light: Option<[f64; 3]>,
    /// Where that light is a rect: its corners' directions in the shading frame, unit (the
    /// spherical polygon P drawn over the lobe, and M^-1 P over the cosine's hemisphere).
    pub polygon: Option<[[f64; 3]; 4]>,
}

impl Default for LobeView {
    fn default() -> Self {
        Self {
            theta_o_deg: 45.0,
            phi_o_deg: 0.0,
            lobe: Lobe::Specular,
            light: None,
            polygon: None,
        }
    }
}

impl Checked for LobeView {
    /// θo within the tables' rows' degrees, φo within a turn; the light a unit vector, or none.
    fn check(&mut self, previous: &Self) -> Vec<String> {
        notes(|n| {
            n.number(
                "θo",
                &mut self.theta_o_deg,
                previous.theta_o_deg,
                [0.0, 90.0],
            );
            let phi = &mut self.phi_o_deg;
            n.number("φo", phi, previous.phi_o_deg, [0.0, 360.0]);
            // A polygon's corners are directions, each: one that is not refuses the polygon.
            if let Some(corners) = self.polygon {
                let units: Option<Vec<[f64; 3]>> = corners
                    .iter()
                    .map(|&c| glam::DVec3::from(c).try_normalize().map(|u| u.to_array()))
                    .collect();
                self.polygon = units.and_then(|u| u.try_into().ok());
                if self.polygon.is_none() {
                    n.say("the lobe panel's rect: a corner is not a direction, refused".into());
                }
            }
            let Some(w) = self.light else {
                return;
            };
            let v = glam::DVec3::from(w);
            // A unit vector (the pinned pixel's table hands over one) is kept to the bit.
            if (v.length() - 1.0).abs() < 1e-9 {
                return;
            }
            self.light = v.try_normalize().map(|u| u.to_array());
            if self.light.is_none() {
                n.say("the lobe panel's light: not a direction, refused".into());
            }
        })
    }
}

/// The selected light: its marker drawn larger, its fields in the side panel.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Selection {
    pub light: Option<usize>,
}

/// Its index is the lab's to check against its lights.
impl Checked for Selection {
    fn check(&mut self, _: &Self) -> Vec<String> {
        Vec::new()
    }
}

/// The matrix panel's last refit, which the lobe panel draws while its cell is chosen.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(transparent)]
pub struct LastRefit(pub Option<RefitResult>);

impl Checked for LastRefit {
    /// A refit whose numbers are not all finite, or whose matrix is singular, is refused.
    fn check(&mut self, _: &Self) -> Vec<String> {
        match &self.0 {
            Some(r) if !r.is_sound() => {
                self.0 = None;
                vec!["the last refit: not a finite, invertible fit, dropped".into()]
            }
            _ => Vec::new(),
        }
    }
}
