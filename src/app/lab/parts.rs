//! The parts the panels share, each a value of its own type with the checks it passes where
//! it enters the lab: the scene as four parts (its lights, its material, the stage — plane and
//! camera — and the exposure it is shown with), the view of the lobe and matrix panels, the
//! shading forms, how each side shades lights with a size, side B, the lights' overrides, the LTC rules, the tables, the selection and
//! the last refit. The lab holds each in a `Part` (`app::lab`).

use serde::{Deserialize, Serialize};

use crate::app::lab::light_check::check_light;
use crate::app::lab::part::{Checked, notes};
use crate::app::lab::refit_result::RefitResult;
use crate::light::Shape;
use crate::light::disk::DiskMethod;
use crate::light::rect::RectMethod;
use crate::light::sphere::SphereMethod;
use crate::ltc::lobe::Lobe;
use crate::ltc::lut::ALPHA_MIN;
use crate::render::{LtcRules, Method};
use crate::scene::{Camera, Light, MAX_COORDINATE, MAX_LIGHTS, Material, Plane, Scene};

/// The scene the parts make.
pub fn scene(stage: &Stage, material: &Material, lights: &Lights, exposure: &Exposure) -> Scene {
    Scene {
        plane: stage.plane,
        material: *material,
        camera: stage.camera,
        lights: lights.list.clone(),
        random_lights: None,
        exposure: exposure.0,
    }
}

/// `scene` as shaded: every light's intensity multiplied, its range and radius replaced
/// where the overrides say.
pub fn shaded(mut scene: Scene, o: &Overrides) -> Scene {
    for l in &mut scene.lights {
        l.intensity *= o.intensity_scale;
        if o.range > 0.0 {
            l.range = Some(o.range);
        }
        l.shape = o.shaded_shape(l);
    }
    scene
}

/// The scene every part of which a lab starts with.
fn paper_100() -> crate::scene::Scene {
    crate::scene::preset("paper-100")
}

/// The scene's point lights, and the generator's seed the lights slider draws them with.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Lights {
    pub list: Vec<Light>,
    pub seed: u64,
}

impl Default for Lights {
    fn default() -> Self {
        Self {
            list: paper_100().lights,
            // paper-100's own (assets/scenes/paper-100.toml).
            seed: 27,
        }
    }
}

impl Checked for Lights {
    /// Every light within the scene file's limits (docs/design.md §3), its non-finite fields
    /// taken from the light it replaces, or, where there is none, the light refused; at most
    /// `MAX_LIGHTS`.
    fn check(&mut self, previous: &Self) -> Vec<String> {
        notes(|n| {
            if self.list.len() > MAX_LIGHTS {
                n.say(format!(
                    "lights: {} is more than the {MAX_LIGHTS} a scene may hold: the first {MAX_LIGHTS} are kept",
                    self.list.len()
                ));
                self.list.truncate(MAX_LIGHTS);
            }
            let mut k = 0;
            self.list.retain_mut(|light| {
                let kept = check_light(n, k, light, previous.list.get(k));
                k += 1;
                kept
            });
        })
    }
}

/// The plane's material: the scene file's ranges (docs/design.md §3).
impl Checked for Material {
    fn check(&mut self, previous: &Self) -> Vec<String> {
        notes(|n| {
            let p = previous;
            n.numbers(
                "material.base_color",
                &mut self.base_color,
                &p.base_color,
                [0.0, 1.0],
            );
            n.number("material.f0", &mut self.f0, p.f0, [0.0, 1.0]);
            n.number("material.alpha", &mut self.alpha, p.alpha, [ALPHA_MIN, 1.0]);
            if let Some(y) = self.alpha_y.as_mut() {
                let before = p.alpha_y.unwrap_or(p.alpha);
                n.number("material.alpha_y", y, before, [ALPHA_MIN, 1.0]);
            }
            let turn = [-360.0, 360.0];
            let t = &mut self.tangent_degrees;
            n.number("material.tangent_degrees", t, p.tangent_degrees, turn);
        })
    }
}

/// What the lights shine on and where it is seen from: the plane and the camera.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Stage {
    pub plane: Plane,
    pub camera: Camera,
}

impl Default for Stage {
    fn default() -> Self {
        let s = paper_100();
        Self {
            plane: s.plane,
            camera: s.camera,
        }
    }
}

impl Checked for Stage {
    /// The scene file's limits; a camera below the plane or looking straight down, which no
    /// clamp can mend, is refused whole.
    fn check(&mut self, previous: &Self) -> Vec<String> {
        notes(|n| {
            let (c, p) = (&mut self.camera, &previous.camera);
            let size = [1e-6, MAX_COORDINATE];
            n.number(
                "plane.half_size",
                &mut self.plane.half_size,
                previous.plane.half_size,
                size,
            );
            let coordinate = [-MAX_COORDINATE, MAX_COORDINATE];
            n.numbers("camera.position", &mut c.position, &p.position, coordinate);
            n.numbers("camera.target", &mut c.target, &p.target, coordinate);
            // 1°–179°: beyond them the view is a point or a half-space.
            n.number(
                "camera.fov_y_degrees",
                &mut c.fov_y_degrees,
                p.fov_y_degrees,
                [1.0, 179.0],
            );
            let scene = crate::scene::Scene {
                plane: self.plane,
                camera: *c,
                ..paper_100()
            };
            if let Err(why) = scene.validate() {
                n.say(format!("camera: {why}; the camera is kept as it was"));
                *c = *p;
            }
        })
    }
}

/// The exposure the plane is shown with: shown radiance and saved PNGs are `L · exposure`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(transparent)]
pub struct Exposure(pub f64);

/// Six stops each way of 1 (the exposure slider's range): paper-100 (peaks near 1) down to
/// the clipping scenes' faint light.
pub const EXPOSURE_RANGE: [f64; 2] = [1.0 / 64.0, 64.0];

impl Default for Exposure {
    fn default() -> Self {
        Self(paper_100().exposure)
    }
}

impl Checked for Exposure {
    fn check(&mut self, previous: &Self) -> Vec<String> {
        notes(|n| n.number("exposure", &mut self.0, previous.0, EXPOSURE_RANGE))
    }
}

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

pub use crate::app::lab::light_check::RADIUS_RANGE;

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
