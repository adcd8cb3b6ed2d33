//! How the lab shades: the point-light forms of each side, how each side shades each shape
//! with a size (`ShapeForms`), what side B is, the lights' overrides and the LTC rules; each checked
//! where it enters the lab.

use serde::{Deserialize, Serialize};

use crate::app::lab::light_check::RADIUS_RANGE;
use crate::app::lab::part::{Checked, notes};
use crate::light::{Shape, ShapeKind};
use crate::render::{LtcRules, Method, ShapeMethod, ShapeMethods};
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

/// How each side of the plane shades each shape with a size (docs/design.md §1.10–§1.12):
/// a method of each shape per side, keyed by shape (`ShapeMethods`; their points' methods
/// are `Forms`'). Stored and linked by names, `rect = { ltc = "ltc-proxy", brdf = "exact" }`;
/// a name that is no shape's or no method of its shape is refused where it enters (`check`).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(from = "FormNames", into = "FormNames")]
pub struct ShapeForms {
    /// The LTC side's (and table B's, where two tables are compared): what engines ship
    /// (EEVEE, Bevy's pull request for spheres, HDRP for disks) and the paper's own polygon.
    pub ltc: ShapeMethods,
    /// The reference side's: each shape's exact integral.
    pub brdf: ShapeMethods,
    /// The names read that are no shape's or method's, said once by `check`.
    refused: Vec<String>,
}

impl Default for ShapeForms {
    fn default() -> Self {
        Self {
            ltc: ShapeMethods::approximations(),
            brdf: ShapeMethods::references(),
            refused: Vec::new(),
        }
    }
}

/// A side's method names for one shape, as a file holds them.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(default)]
struct SideNames {
    ltc: Option<String>,
    brdf: Option<String>,
}

/// `ShapeForms` by names, shape by shape.
type FormNames = std::collections::BTreeMap<String, SideNames>;

impl From<FormNames> for ShapeForms {
    fn from(names: FormNames) -> Self {
        let mut forms = Self::default();
        for (shape, sides) in names {
            let Some(kind) = ShapeKind::sized().find(|k| k.name() == shape) else {
                forms.refused.push(format!("shape `{shape}`"));
                continue;
            };
            for (name, side) in [(sides.ltc, &mut forms.ltc), (sides.brdf, &mut forms.brdf)] {
                let Some(name) = name else { continue };
                match ShapeMethod::parse(kind, &name) {
                    Some(m) => side.set(m),
                    None => forms.refused.push(format!("{shape} method `{name}`")),
                }
            }
        }
        forms
    }
}

impl From<ShapeForms> for FormNames {
    fn from(forms: ShapeForms) -> Self {
        let names = |kind| SideNames {
            ltc: Some(forms.ltc.of(kind).name().to_string()),
            brdf: Some(forms.brdf.of(kind).name().to_string()),
        };
        ShapeKind::sized()
            .map(|kind| (kind.name().to_string(), names(kind)))
            .collect()
    }
}

/// A choice among a shape's methods holds no number: only names, refused where unknown.
impl Checked for ShapeForms {
    fn check(&mut self, _: &Self) -> Vec<String> {
        let refused = std::mem::take(&mut self.refused);
        refused
            .into_iter()
            .map(|r| format!("{r} refused: no such shape or method, the default kept"))
            .collect()
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::light::rect::RectMethod;

    /// Stored and linked by names: read back as written, and a name that is no shape's or
    /// no method of its shape is said and leaves the default.
    #[test]
    fn shape_forms_are_stored_by_names_and_unknown_names_are_refused() {
        let mut forms = ShapeForms::default();
        forms.ltc.set(RectMethod::LtcProxy);
        let text = toml::to_string(&forms).unwrap();
        assert!(text.contains("ltc-proxy"), "{text}");
        let back: ShapeForms = toml::from_str(&text).unwrap();
        assert_eq!(back, forms);
        let odd =
            "[rect]\nltc = \"ltc-disk\"\n[cone]\nltc = \"exact\"\n[disk]\nbrdf = \"ltc-point\"\n";
        let mut read: ShapeForms = toml::from_str(odd).unwrap();
        let notes = read.check(&ShapeForms::default());
        assert_eq!(notes.len(), 2, "{notes:?}");
        assert!(notes.iter().any(|n| n.contains("rect method `ltc-disk`")));
        assert!(notes.iter().any(|n| n.contains("shape `cone`")));
        assert_eq!(read.ltc.get::<RectMethod>(), RectMethod::LtcPolygon);
        assert_eq!(read.brdf.of(ShapeKind::Disk).name(), "ltc-point");
        // Said once.
        assert!(read.check(&ShapeForms::default()).is_empty());
    }
}
