//! The scene of DESIGN §3 and no more: a plane `z = 0`, its material, a camera and point
//! lights, read from small TOML presets (`assets/scenes/`), with a seeded light generator.

use std::path::Path;

use glam::DVec3;
use serde::{Deserialize, Serialize};

use crate::error::{InputError, Result};

/// The square plane `|x|, |y| ≤ half_size`, `z = 0`, normal `+z`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Plane {
    pub half_size: f64,
}

/// GGX specular over Burley diffuse (DESIGN §1).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Material {
    /// Diffuse albedo `c`, linear RGB.
    pub base_color: [f64; 3],
    /// Specular reflectance at normal incidence (Schlick's `F0`).
    pub f0: f64,
    /// GGX α (= perceptual roughness²).
    pub alpha: f64,
}

/// A pinhole camera looking at `target`, `+z` up.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Camera {
    pub position: [f64; 3],
    pub target: [f64; 3],
    /// Vertical field of view in degrees.
    pub fov_y_degrees: f64,
}

/// A point light: RGB `color × intensity` (W/sr-like units: irradiance `I/d²` at distance d).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Light {
    pub position: [f64; 3],
    #[serde(default = "white")]
    pub color: [f64; 3],
    pub intensity: f64,
    /// Range `R` of the windowed falloff; absent means infinite.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub range: Option<f64>,
}

fn white() -> [f64; 3] {
    [1.0; 3]
}

impl Light {
    /// `color × intensity`.
    pub fn radiant_intensity(&self) -> DVec3 {
        DVec3::from(self.color) * self.intensity
    }

    pub fn range_or_infinity(&self) -> f64 {
        self.range.unwrap_or(f64::INFINITY)
    }
}

/// Lights made by `generate_lights`, added to the listed ones when the scene loads.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RandomLights {
    pub count: usize,
    pub seed: u64,
    /// Heights above the plane, `[min, max]`.
    pub height: [f64; 2],
    /// Intensities, `[min, max]`.
    pub intensity: [f64; 2],
    /// Range of every generated light; absent means infinite.
    #[serde(default)]
    pub range: Option<f64>,
}

/// The largest light count a scene may ask for; far above the lab's 20 000-light slider,
/// small enough that a typo cannot exhaust memory (32 bytes each on the GPU: 32 MiB).
pub const MAX_LIGHTS: usize = 1 << 20;

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    pub plane: Plane,
    pub material: Material,
    pub camera: Camera,
    #[serde(default)]
    pub lights: Vec<Light>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub random_lights: Option<RandomLights>,
    /// Multiplies radiance before the PNG tone map (not the EXR).
    #[serde(default = "one")]
    pub exposure: f64,
}

fn one() -> f64 {
    1.0
}

impl Scene {
    /// Reads, validates and expands a scene file; every error names the file.
    pub fn load(path: &Path) -> Result<Scene> {
        let name = path.display().to_string();
        let text = std::fs::read_to_string(path)
            .map_err(|e| InputError::new(&name, format!("cannot read: {e}")))?;
        Scene::from_toml(&text, &name)
    }

    /// Parses TOML text; `name` is used in errors.
    pub fn from_toml(text: &str, name: &str) -> Result<Scene> {
        let scene: Scene = toml::from_str(text).map_err(|e| {
            let line = e
                .span()
                .map(|s| format!(" (line {})", text[..s.start].lines().count().max(1)));
            InputError::new(
                name,
                format!("{}{}", e.message().trim(), line.unwrap_or_default()),
            )
        })?;
        scene.validate().map_err(|m| InputError::new(name, m))?;
        Ok(scene.expanded())
    }

    pub fn to_toml(&self) -> String {
        toml::to_string_pretty(self).expect("a scene always serializes")
    }

    /// The listed lights followed by the generated ones; `random_lights` becomes explicit.
    pub fn expanded(mut self) -> Scene {
        if let Some(r) = self.random_lights.take() {
            self.lights
                .extend(generate_lights(&r, self.plane.half_size));
        }
        self
    }

    /// Why the scene cannot be rendered, if it cannot.
    pub fn validate(&self) -> std::result::Result<(), String> {
        let finite = |what: &str, xs: &[f64]| match xs {
            _ if xs.iter().all(|x| x.is_finite()) => Ok(()),
            [x] => Err(format!("{what} must be a finite number, got {x}")),
            _ => Err(format!("{what} must be finite numbers, got {xs:?}")),
        };
        finite("plane.half_size", &[self.plane.half_size])?;
        if self.plane.half_size <= 0.0 {
            return Err(format!(
                "plane.half_size must be > 0, got {}",
                self.plane.half_size
            ));
        }
        let m = &self.material;
        finite("material.base_color", &m.base_color)?;
        finite("material.f0", &[m.f0])?;
        finite("material.alpha", &[m.alpha])?;
        if m.base_color.iter().any(|c| !(0.0..=1.0).contains(c)) {
            return Err(format!(
                "material.base_color must be in [0, 1], got {:?}",
                m.base_color
            ));
        }
        if !(0.0..=1.0).contains(&m.f0) {
            return Err(format!("material.f0 must be in [0, 1], got {}", m.f0));
        }
        if !(m.alpha > 0.0 && m.alpha <= 1.0) {
            return Err(format!("material.alpha must be in (0, 1], got {}", m.alpha));
        }
        let c = &self.camera;
        finite("camera.position", &c.position)?;
        finite("camera.target", &c.target)?;
        finite("camera.fov_y_degrees", &[c.fov_y_degrees])?;
        if !(c.fov_y_degrees > 0.0 && c.fov_y_degrees < 180.0) {
            return Err(format!(
                "camera.fov_y_degrees must be in (0, 180), got {}",
                c.fov_y_degrees
            ));
        }
        let forward = DVec3::from(c.target) - DVec3::from(c.position);
        if forward.length() <= 1e-9 || forward.normalize().cross(DVec3::Z).length() <= 1e-9 {
            return Err("camera must look somewhere other than straight up or down (target − position ∦ z) and target ≠ position".into());
        }
        finite("exposure", &[self.exposure])?;
        if self.exposure <= 0.0 {
            return Err(format!("exposure must be > 0, got {}", self.exposure));
        }
        for (k, l) in self.lights.iter().enumerate() {
            check_light(&format!("lights[{k}]"), l)?;
        }
        if let Some(r) = &self.random_lights {
            finite("random_lights.height", &r.height)?;
            finite("random_lights.intensity", &r.intensity)?;
            if r.height[0] > r.height[1] || r.intensity[0] > r.intensity[1] {
                return Err("random_lights: each [min, max] must have min ≤ max".into());
            }
            if r.intensity[0] < 0.0 {
                return Err("random_lights.intensity must be ≥ 0".into());
            }
            check_range("random_lights.range", r.range)?;
        }
        let total = self.lights.len() + self.random_lights.map_or(0, |r| r.count);
        if total > MAX_LIGHTS {
            return Err(format!(
                "{total} lights is more than the {MAX_LIGHTS} a scene may hold"
            ));
        }
        Ok(())
    }
}

fn check_range(what: &str, range: Option<f64>) -> std::result::Result<(), String> {
    match range {
        Some(r) if r.is_nan() || r <= 0.0 => Err(format!("{what} must be > 0, got {r}")),
        _ => Ok(()),
    }
}

fn check_light(what: &str, l: &Light) -> std::result::Result<(), String> {
    if !l.position.iter().chain(&l.color).all(|x| x.is_finite()) || !l.intensity.is_finite() {
        return Err(format!(
            "{what}: position, color and intensity must be finite"
        ));
    }
    if l.intensity < 0.0 || l.color.iter().any(|&c| c < 0.0) {
        return Err(format!("{what}: color and intensity must be ≥ 0"));
    }
    check_range(&format!("{what}.range"), l.range)
}

/// SplitMix64 (Steele et al. 2014): a tiny, well-mixed, seedable generator, so the same
/// seed gives the same lights on every machine.
#[derive(Clone, Debug)]
pub struct SplitMix64(pub u64);

impl SplitMix64 {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1) from the top 53 bits.
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    pub fn uniform(&mut self, [lo, hi]: [f64; 2]) -> f64 {
        lo + (hi - lo) * self.next_f64()
    }
}

/// `r.count` lights over the plane (x, y uniform on it), heights and intensities uniform in
/// their ranges, colours of random hue at full value and 60% saturation.
pub fn generate_lights(r: &RandomLights, half_size: f64) -> Vec<Light> {
    let mut rng = SplitMix64(r.seed);
    (0..r.count)
        .map(|_| {
            let x = rng.uniform([-half_size, half_size]);
            let y = rng.uniform([-half_size, half_size]);
            let z = rng.uniform(r.height);
            let hue = rng.next_f64();
            Light {
                position: [x, y, z],
                color: hue_color(hue, 0.6),
                intensity: rng.uniform(r.intensity),
                range: r.range,
            }
        })
        .collect()
}

/// A colour of the given hue (0..1) and saturation at full value (the HSV hexcone).
fn hue_color(hue: f64, saturation: f64) -> [f64; 3] {
    let channel = |offset: f64| {
        let k = (hue * 6.0 + offset) % 6.0;
        let ramp = (k.min(4.0 - k)).clamp(0.0, 1.0);
        1.0 - saturation * ramp
    };
    [channel(5.0), channel(3.0), channel(1.0)]
}
