//! The scene of docs/design.md §3 and no more: a plane `z = 0`, its material, a camera (and its
//! rays) and lights (`light`: points, spheres and rects, and a seeded generator), read from
//! small TOML presets (`assets/scenes/`) and checked (`check`).

mod check;
mod light;
mod lists;
mod table_presets;

use std::path::Path;

use crate::light::ShapeKind;
pub use crate::light::disk::PRESETS as DISK_PRESETS;
pub use crate::light::rect::PRESETS as RECT_PRESETS;
pub use crate::light::sphere::PRESETS as SPHERE_PRESETS;
use glam::DVec3;
use serde::{Deserialize, Serialize};

use crate::brdf::Alpha;
use crate::error::{Error, Result, number};
use crate::render::{Gloss, SurfacePoint};
pub use check::MIN_NORMAL;
use check::{check_light, check_radius, check_range, finite, within};
pub use light::{Light, MIN_RADIUS, RandomLights, SplitMix64, generate_lights};
use lists::exactly as exact_list;
pub use table_presets::{ENCODING_FAILURES, EncodingFailure, TABLE_PRESETS};

/// The shipped presets, embedded so that the lab and the benchmarks run from anywhere.
pub const PRESETS: [(&str, &str); 4] = [
    (
        "paper-100",
        include_str!("../../assets/scenes/paper-100.toml"),
    ),
    (
        "figure2-normal",
        include_str!("../../assets/scenes/figure2-normal.toml"),
    ),
    (
        "figure2-case1",
        include_str!("../../assets/scenes/figure2-case1.toml"),
    ),
    (
        "figure2-case2",
        include_str!("../../assets/scenes/figure2-case2.toml"),
    ),
];

/// The anisotropic presets (docs/design.md §1.13): brushed metal under a rect and under
/// spheres.
pub const ANISO_PRESETS: [(&str, &str); 2] = [
    (
        "brushed-rect",
        include_str!("../../assets/scenes/brushed-rect.toml"),
    ),
    (
        "brushed-spheres",
        include_str!("../../assets/scenes/brushed-spheres.toml"),
    ),
];

/// The failure presets of lights of `kind`, its module's (`ShapeKind::presets`; none for
/// points: theirs are `PRESETS`).
pub fn shape_presets(kind: ShapeKind) -> &'static [(&'static str, &'static str)] {
    kind.presets()
}

/// Every shipped preset, its name and its text (`PRESETS`, each shape's, `ANISO_PRESETS`,
/// `TABLE_PRESETS`).
pub fn shipped_presets() -> impl Iterator<Item = &'static (&'static str, &'static str)> {
    PRESETS
        .iter()
        .chain(ShapeKind::sized().flat_map(ShapeKind::presets))
        .chain(&ANISO_PRESETS)
        .chain(&TABLE_PRESETS)
}

/// A shipped preset by name (`shipped_presets`).
pub fn preset(name: &str) -> Scene {
    let (_, text) = shipped_presets()
        .find(|(n, _)| *n == name)
        .expect("a shipped preset");
    Scene::from_toml(text, name).expect("shipped presets are valid (tests/math/presets.rs)")
}

/// The square plane `|x|, |y| ≤ half_size`, `z = 0`, normal `+z`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Plane {
    pub half_size: f64,
}

/// GGX specular over Burley diffuse (docs/design.md §1).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Material {
    /// Diffuse albedo `c`, linear RGB.
    #[serde(with = "exact_list")]
    pub base_color: [f64; 3],
    /// Specular reflectance at normal incidence (Schlick's `F0`).
    pub f0: f64,
    /// GGX α (= perceptual roughness²); α along the tangent where `alpha_y` is given.
    pub alpha: f64,
    /// GGX α along the bitangent, for an anisotropic material (docs/design.md §1.13; brushed
    /// metal); absent, the material is isotropic and shades as it always did.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alpha_y: Option<f64>,
    /// The tangent's angle in the plane, in degrees from the world's +x axis toward +y: the
    /// direction along which `alpha` acts (the brushing's direction). Unused while isotropic.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub tangent_degrees: f64,
}

/// Whether a value is 0: such a field is left out of a saved scene.
fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

impl Material {
    /// The material's roughness along its tangent and bitangent.
    pub fn roughness(&self) -> Alpha<f64> {
        Alpha {
            x: self.alpha,
            y: self.alpha_y.unwrap_or(self.alpha),
        }
    }

    /// Whether the material is anisotropic: shaded in its tangent frame, its specular lobe
    /// from the 4D table.
    pub fn is_anisotropic(&self) -> bool {
        !self.roughness().is_isotropic()
    }

    /// The unit tangent (world, in the plane).
    pub fn tangent(&self) -> DVec3 {
        let (s, c) = self.tangent_degrees.to_radians().sin_cos();
        DVec3::new(c, s, 0.0)
    }

    /// What a shading point needs of the material's roughness.
    pub fn gloss(&self) -> Gloss {
        Gloss {
            alpha: self.roughness(),
            tangent: self.tangent(),
        }
    }
}

impl Default for Material {
    /// paper-100's (assets/scenes/paper-100.toml).
    fn default() -> Self {
        preset("paper-100").material
    }
}

/// A pinhole camera looking at `target`, `+z` up.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Camera {
    #[serde(with = "exact_list")]
    pub position: [f64; 3],
    #[serde(with = "exact_list")]
    pub target: [f64; 3],
    /// Vertical field of view in degrees.
    pub fov_y_degrees: f64,
}

/// The range of paper-100's lights (assets/scenes/paper-100.toml), which the benchmark's and
/// the lab's generated lights share.
pub const PAPER_RANGE: f64 = 2.0;

/// The largest light count a scene may ask for; far above the lab's 20 000-light slider,
/// small enough that a typo cannot exhaust memory (32 bytes each on the GPU: 32 MiB).
pub const MAX_LIGHTS: usize = 1 << 20;

/// The most bytes of a scene file this program reads (`files::read_text`): `MAX_LIGHTS`
/// lights written out one by one take some 150 bytes each as TOML, 150 MiB in all.
pub const MAX_FILE_BYTES: u64 = 256 << 20;

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
        let text = crate::files::read_text(path, MAX_FILE_BYTES)?;
        Scene::from_toml(&text, &name)
    }

    /// Parses TOML text; `name` is used in errors.
    pub fn from_toml(text: &str, name: &str) -> Result<Scene> {
        let scene: Scene = toml::from_str(text).map_err(|e| {
            let line = e
                .span()
                .map(|s| format!(" (line {})", text[..s.start].lines().count().max(1)));
            Error::input(
                name,
                format!("{}{}", e.message().trim(), line.unwrap_or_default()),
            )
        })?;
        scene.validate().map_err(|m| Error::input(name, m))?;
        Ok(scene.expanded())
    }

    /// The scene as a person would write it: light positions to 1e-4 scene units (a tenth of
    /// a millimetre in metres), colours to 1e-3 (finer than 8-bit steps), intensities, ranges
    /// and radii to 4 significant digits. Dragged lights and generated ones otherwise save
    /// with 16 decimals; every rounded value stays within the limits `validate` checks.
    pub fn rounded_for_saving(&self) -> Scene {
        let decimals = |x: f64, d: i32| (x * 10f64.powi(d)).round() / 10f64.powi(d);
        let significant = |x: f64| {
            if x == 0.0 || !x.is_finite() {
                return x;
            }
            let d = 3 - x.abs().log10().floor() as i32;
            decimals(x, d)
        };
        let mut out = self.clone();
        for l in &mut out.lights {
            l.position = l.position.map(|x| decimals(x, 4));
            l.color = l.color.map(|x| decimals(x, 3));
            l.intensity = significant(l.intensity);
            l.range = l.range.map(significant);
            l.shape = l
                .shape
                .map_dimensions(|_, v| v.to_array().map(significant).into(), significant);
        }
        out
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
        finite("plane.half_size", &[self.plane.half_size])?;
        if !(self.plane.half_size > 0.0 && self.plane.half_size <= MAX_COORDINATE) {
            return Err(format!(
                "plane.half_size must be in (0, {}], got {}",
                number(MAX_COORDINATE),
                number(self.plane.half_size)
            ));
        }
        let m = &self.material;
        within("material.base_color", &m.base_color, 0.0, 1.0)?;
        within("material.f0", &[m.f0], 0.0, 1.0)?;
        within(
            "material.alpha",
            &[m.alpha],
            crate::ltc::lut::ALPHA_MIN,
            1.0,
        )?;
        if let Some(alpha_y) = m.alpha_y {
            within(
                "material.alpha_y",
                &[alpha_y],
                crate::ltc::lut::ALPHA_MIN,
                1.0,
            )?;
        }
        within(
            "material.tangent_degrees",
            &[m.tangent_degrees],
            -360.0,
            360.0,
        )?;
        let c = &self.camera;
        within(
            "camera.position",
            &c.position,
            -MAX_COORDINATE,
            MAX_COORDINATE,
        )?;
        within("camera.target", &c.target, -MAX_COORDINATE, MAX_COORDINATE)?;
        if c.position[2] <= 0.0 {
            return Err(format!(
                "camera.position must be above the plane (z > 0), got z = {}: the plane is lit from above and one-sided",
                c.position[2]
            ));
        }
        finite("camera.fov_y_degrees", &[c.fov_y_degrees])?;
        if !(c.fov_y_degrees > 0.0 && c.fov_y_degrees < 180.0) {
            return Err(format!(
                "camera.fov_y_degrees must be in (0, 180), got {}",
                number(c.fov_y_degrees)
            ));
        }
        let forward = DVec3::from(c.target) - DVec3::from(c.position);
        if forward.length() <= 1e-9 || forward.normalize().cross(DVec3::Z).length() <= 1e-9 {
            return Err("camera must look somewhere other than straight up or down (target − position ∦ z) and target ≠ position".into());
        }
        finite("exposure", &[self.exposure])?;
        if self.exposure <= 0.0 {
            return Err(format!(
                "exposure must be > 0, got {}",
                number(self.exposure)
            ));
        }
        for (k, l) in self.lights.iter().enumerate() {
            check_light(&format!("lights[{k}]"), l)?;
        }
        if let Some(r) = &self.random_lights {
            within(
                "random_lights.height",
                &r.height,
                -MAX_COORDINATE,
                MAX_COORDINATE,
            )?;
            within("random_lights.intensity", &r.intensity, 0.0, MAX_INTENSITY)?;
            if r.height[0] > r.height[1] || r.intensity[0] > r.intensity[1] {
                return Err("random_lights: each [min, max] must have min ≤ max".into());
            }
            check_range("random_lights.range", r.range)?;
            check_radius("random_lights.radius", r.radius)?;
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

/// The camera's rays: the geometry every renderer shares.
impl Scene {
    /// The camera's position and orthonormal basis: eye, forward, right, up (`+z` is up).
    pub fn camera_basis(&self) -> (DVec3, DVec3, DVec3, DVec3) {
        let eye = DVec3::from(self.camera.position);
        let forward = (DVec3::from(self.camera.target) - eye).normalize();
        let right = forward.cross(DVec3::Z).normalize();
        (eye, forward, right, right.cross(forward))
    }

    /// The camera ray through image position (x, y) in pixels (pixel centres at k + ½) of a
    /// `width × height` image: origin and unit direction.
    pub fn camera_ray(&self, x: f64, y: f64, width: usize, height: usize) -> (DVec3, DVec3) {
        let (eye, forward, right, up) = self.camera_basis();
        let tan_half = (self.camera.fov_y_degrees.to_radians() * 0.5).tan();
        let aspect = width as f64 / height as f64;
        let sx = (2.0 * x / width as f64 - 1.0) * tan_half * aspect;
        let sy = (1.0 - 2.0 * y / height as f64) * tan_half;
        (eye, (forward + sx * right + sy * up).normalize())
    }

    /// Where world point `p` appears in a `width × height` image, in pixels; `None` behind
    /// the camera.
    pub fn project(&self, p: DVec3, width: usize, height: usize) -> Option<(f64, f64)> {
        let (eye, forward, right, up) = self.camera_basis();
        let d = p - eye;
        let z = d.dot(forward);
        if z <= 1e-9 {
            return None;
        }
        let tan_half = (self.camera.fov_y_degrees.to_radians() * 0.5).tan();
        let aspect = width as f64 / height as f64;
        let sx = d.dot(right) / (z * tan_half * aspect);
        let sy = d.dot(up) / (z * tan_half);
        Some((
            (sx + 1.0) * 0.5 * width as f64,
            (1.0 - sy) * 0.5 * height as f64,
        ))
    }

    /// The point of the plane seen through pixel (x, y) of a `width × height` image.
    pub fn surface_point(
        &self,
        x: usize,
        y: usize,
        width: usize,
        height: usize,
    ) -> Option<SurfacePoint> {
        self.surface_point_at(x as f64 + 0.5, y as f64 + 0.5, width, height)
    }

    /// `surface_point` at a continuous image position.
    pub fn surface_point_at(
        &self,
        x: f64,
        y: f64,
        width: usize,
        height: usize,
    ) -> Option<SurfacePoint> {
        let (eye, dir) = self.camera_ray(x, y, width, height);
        if dir.z == 0.0 {
            return None;
        }
        let t = -eye.z / dir.z;
        if t <= 0.0 {
            return None;
        }
        let position = eye + t * dir;
        let h = self.plane.half_size;
        if position.x.abs() > h || position.y.abs() > h {
            return None;
        }
        Some(SurfacePoint {
            position,
            view: (eye - position).normalize(),
        })
    }
}

/// The largest coordinate (and plane half-size) a scene may use. The GPU shades in f32, whose
/// spacing at 1e6 is 0.06 (positions beyond it cannot be told apart at the plane's metre
/// scale), and whose range still holds the fourth power of any distance within it
/// (`(2√3·1e6)⁴ ≈ 1.4e26 < 3.4e38`, ltc-fast's `|M⁻¹u|⁴` scaled by the matrix).
pub const MAX_COORDINATE: f64 = 1e6;

/// The largest `color × intensity` per channel of a light. With a light no nearer than
/// `brdf::MIN_LIGHT_DISTANCE` (E ≤ 1e6 / 1e-12), a lobe no sharper than α_min's (f·cos ≲ 2e11
/// at any view: D ≤ 1/(π α_min²), G/(4 n·v) ≤ 1/(2α)) and `MAX_LIGHTS` lights, a pixel's
/// radiance stays below 2e35, inside f32's range with a margin of 1000: the CPU and the GPU
/// render the same finite image.
pub const MAX_INTENSITY: f64 = 1e6;
