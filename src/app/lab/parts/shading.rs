//! How the lab shades: the point-light forms of each side, how each side shades lights with a
//! size (by shape), what side B is, the lights' overrides and the LTC rules; each checked
//! where it enters the lab.

use serde::{Deserialize, Serialize};

use crate::app::lab::light_check::RADIUS_RANGE;
use crate::app::lab::part::{Checked, notes};
use crate::light::Shape;
use crate::light::disk::DiskMethod;
use crate::light::rect::RectMethod;
use crate::light::sphere::SphereMethod;
use crate::render::{LtcRules, Method};
use crate::scene::Light;

/// The LTC and BRDF forms the plane compares (and the chart names), and whether its sum is
/// culled by range.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Forms {
    pub ltc: Method,
    pub brdf: Method,
    /// Tiled culling of ranged lights in the plane's render (the same image, faster).
    pub cull: bool,
}

/// The forms the lab offers: each family's literal form and its fast one (the f16 forms are
/// the benchmark's).
pub const LTC_FORMS: [Method; 2] = [Method::Ltc, Method::LtcFast];

pub const BRDF_FORMS: [Method; 2] = [Method::Brdf, Method::BrdfFast];

impl Default for Forms {
    fn default() -> Self {
        Self {
            ltc: Method::LtcFast,
            brdf: Method::Brdf,
            cull: true,
        }
    }
}

impl Checked for Forms {
    fn check(&mut self, previous: &Self) -> Vec<String> {
        notes(|n| {
            for (field, form, offered, kept) in [
                ("LTC form", &mut self.ltc, LTC_FORMS, previous.ltc),
                ("BRDF form", &mut self.brdf, BRDF_FORMS, previous.brdf),
            ] {
                // The method file: offered where one is loaded (`Lab::keep_method_file`).
                if !offered.contains(form) && *form != Method::File {
                    n.say(format!(
                        "{field}: {} refused, kept {}",
                        form.name(),
                        kept.name()
                    ));
                    *form = kept;
                }
            }
        })
    }
}

/// How each side of the plane shades the lights with a size (docs/design.md §1.10).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct SphereForms {
    /// The LTC side's (and table B's, where two tables are compared).
    pub ltc: SphereMethod,
    /// The reference side's.
    pub brdf: SphereMethod,
}

impl Default for SphereForms {
    /// What engines ship (EEVEE, Bevy's pull request) against the reference.
    fn default() -> Self {
        Self {
            ltc: SphereMethod::LtcDisk,
            brdf: SphereMethod::Exact,
        }
    }
}

/// A choice among the sphere methods holds no number.
impl Checked for SphereForms {
    fn check(&mut self, _: &Self) -> Vec<String> {
        Vec::new()
    }
}

/// How each side of the plane shades rect lights (docs/design.md §1.11).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct RectForms {
    /// The LTC side's (and table B's, where two tables are compared).
    pub ltc: RectMethod,
    /// The reference side's.
    pub brdf: RectMethod,
}

impl Default for RectForms {
    /// The paper's own method against the reference.
    fn default() -> Self {
        Self {
            ltc: RectMethod::LtcPolygon,
            brdf: RectMethod::Exact,
        }
    }
}

/// A choice among the rect methods holds no number.
impl Checked for RectForms {
    fn check(&mut self, _: &Self) -> Vec<String> {
        Vec::new()
    }
}

/// How each side of the plane shades disk lights (docs/design.md §1.12).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct DiskForms {
    /// The LTC side's (and table B's, where two tables are compared).
    pub ltc: DiskMethod,
    /// The reference side's.
    pub brdf: DiskMethod,
}

impl Default for DiskForms {
    /// What engines ship (Unity HDRP, EEVEE) against the reference.
    fn default() -> Self {
        Self {
            ltc: DiskMethod::LtcDisk,
            brdf: DiskMethod::Exact,
        }
    }
}

/// A choice among the disk methods holds no number.
impl Checked for DiskForms {
    fn check(&mut self, _: &Self) -> Vec<String> {
        Vec::new()
    }
}

/// What the plane's side B is: the exact BRDF, or LTC with table B (two tables compared).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum SideB {
    #[default]
    Brdf,
    TableB,
}

impl Checked for SideB {
    fn check(&mut self, _: &Self) -> Vec<String> {
        Vec::new()
    }
}

/// What the lab does to every light as it shades: its intensity multiplied, its range and
/// radius replaced.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Overrides {
    pub intensity_scale: f64,
    /// Every light's range where > 0; 0 keeps each light's own.
    pub range: f64,
    /// Every light a sphere of this radius where > 0; 0 keeps each light's own shape.
    pub radius: f64,
}

/// The intensity slider's range: four decades about the scene's own.
pub const INTENSITY_RANGE: [f64; 2] = [0.01, 100.0];

/// The range slider's: 0 (each light's own), or 0.01 (its smallest step, the first value it
/// shows as other than 0) to 10 (five times the plane's side).
pub const RANGE_RANGE: [f64; 2] = [0.01, 10.0];

impl Overrides {
    /// The shape `l` is shaded with: every light's sphere where set, else its own.
    pub fn shaded_shape(&self, l: &Light) -> Shape {
        if self.radius > 0.0 {
            Shape::Sphere {
                radius: self.radius,
            }
        } else {
            l.shape
        }
    }
}

impl Default for Overrides {
    fn default() -> Self {
        Self {
            intensity_scale: 1.0,
            range: 0.0,
            radius: 0.0,
        }
    }
}

impl Checked for Overrides {
    fn check(&mut self, previous: &Self) -> Vec<String> {
        notes(|n| {
            let p = previous;
            n.number(
                "intensity ×",
                &mut self.intensity_scale,
                p.intensity_scale,
                INTENSITY_RANGE,
            );
            if self.range != 0.0 {
                n.number("range R", &mut self.range, p.range, RANGE_RANGE);
            }
            if self.radius != 0.0 {
                n.number("radius r", &mut self.radius, p.radius, RADIUS_RANGE);
            }
        })
    }
}

/// Eq. 30's rules, the normalization, the filter and the horizon rule hold no number.
impl Checked for LtcRules {
    fn check(&mut self, _: &Self) -> Vec<String> {
        Vec::new()
    }
}
