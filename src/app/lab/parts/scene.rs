//! The scene as four parts: its lights, its material, the stage — plane
//! and camera — and the exposure it is shown with; each checked where it enters the lab.

use serde::{Deserialize, Serialize};

use crate::app::lab::light_check::check_light;
use crate::app::lab::part::{Checked, notes};
use crate::app::lab::parts::shading::Overrides;
use crate::ltc::lut::ALPHA_MIN;
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
