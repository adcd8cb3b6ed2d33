//! The scene of docs/design.md §3 and no more: a plane `z = 0`, its material, a camera (and its
//! rays) and point lights, read from small TOML presets (`assets/scenes/`), with a seeded
//! light generator.

use std::path::Path;

use crate::light::Shape;
use glam::DVec3;
use serde::{Deserialize, Serialize};

use crate::error::{Error, Result, number};
use crate::render::SurfacePoint;

/// The shipped presets, embedded so that the lab and the benchmarks run from anywhere.
pub const PRESETS: [(&str, &str); 4] = [
    ("paper-100", include_str!("../assets/scenes/paper-100.toml")),
    (
        "figure2-normal",
        include_str!("../assets/scenes/figure2-normal.toml"),
    ),
    (
        "figure2-case1",
        include_str!("../assets/scenes/figure2-case1.toml"),
    ),
    (
        "figure2-case2",
        include_str!("../assets/scenes/figure2-case2.toml"),
    ),
];

/// The failure cases of lights with a size (docs/design.md §1.10), shipped beside the
/// clipping panel's: a sphere cut by the horizon, one touching the plane, discs seen edge-on,
/// and ltc_code's black spots.
pub const SPHERE_PRESETS: [(&str, &str); 4] = [
    (
        "sphere-horizon",
        include_str!("../assets/scenes/sphere-horizon.toml"),
    ),
    (
        "sphere-touching",
        include_str!("../assets/scenes/sphere-touching.toml"),
    ),
    (
        "sphere-edge-on",
        include_str!("../assets/scenes/sphere-edge-on.toml"),
    ),
    (
        "sphere-black-spots",
        include_str!("../assets/scenes/sphere-black-spots.toml"),
    ),
];

/// The failure cases of rect lights (docs/design.md §1.11): rects across the horizon, edge-on
/// and facing away; touching the surface, behind it and tiny; and one filling the sky.
pub const RECT_PRESETS: [(&str, &str); 3] = [
    (
        "rect-horizon",
        include_str!("../assets/scenes/rect-horizon.toml"),
    ),
    (
        "rect-limits",
        include_str!("../assets/scenes/rect-limits.toml"),
    ),
    (
        "rect-ceiling",
        include_str!("../assets/scenes/rect-ceiling.toml"),
    ),
];

/// A shipped preset by name (`PRESETS`, `SPHERE_PRESETS`, `RECT_PRESETS`).
pub fn preset(name: &str) -> Scene {
    let (_, text) = PRESETS
        .iter()
        .chain(&SPHERE_PRESETS)
        .chain(&RECT_PRESETS)
        .find(|(n, _)| *n == name)
        .expect("a shipped preset");
    Scene::from_toml(text, name).expect("shipped presets are valid (tests/presets.rs)")
}

/// Exactly `N` numbers, as a list. serde's fixed-size arrays take the first `N` elements of a
/// longer TOML list and drop the rest without a word (a 4-element colour, a 5-element
/// position); and they are written as tuples, which RON (eframe's storage of the lab's state)
/// does not read back as a list.
mod exactly {
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    pub fn serialize<S: Serializer, const N: usize>(v: &[f64; N], s: S) -> Result<S::Ok, S::Error> {
        v.as_slice().serialize(s)
    }

    pub fn deserialize<'de, D: Deserializer<'de>, const N: usize>(
        d: D,
    ) -> Result<[f64; N], D::Error> {
        let v = Vec::<f64>::deserialize(d)?;
        let len = v.len();
        v.try_into().map_err(|_| {
            serde::de::Error::invalid_length(
                len,
                &format!("a list of exactly {N} numbers").as_str(),
            )
        })
    }
}

/// `exactly` for an optional list.
mod exactly_option {
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    pub fn serialize<S: Serializer, const N: usize>(
        v: &Option<[f64; N]>,
        s: S,
    ) -> Result<S::Ok, S::Error> {
        v.as_ref().map(<[f64; N]>::as_slice).serialize(s)
    }

    pub fn deserialize<'de, D: Deserializer<'de>, const N: usize>(
        d: D,
    ) -> Result<Option<[f64; N]>, D::Error> {
        // A list read as itself (not through a newtype, which RON writes differently).
        let Some(v) = Option::<Vec<f64>>::deserialize(d)? else {
            return Ok(None);
        };
        let len = v.len();
        v.try_into().map(Some).map_err(|_| {
            serde::de::Error::invalid_length(
                len,
                &format!("a list of exactly {N} numbers").as_str(),
            )
        })
    }
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
    #[serde(with = "exactly")]
    pub base_color: [f64; 3],
    /// Specular reflectance at normal incidence (Schlick's `F0`).
    pub f0: f64,
    /// GGX α (= perceptual roughness²).
    pub alpha: f64,
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
    #[serde(with = "exactly")]
    pub position: [f64; 3],
    #[serde(with = "exactly")]
    pub target: [f64; 3],
    /// Vertical field of view in degrees.
    pub fov_y_degrees: f64,
}

/// A light: RGB `color × intensity` (W/sr-like units: irradiance `I/d²` at distance d) from
/// `position`, of a shape (a point; a sphere whose radiance `I/(π r²)` lights a distant point
/// as the point light does, docs/design.md §1.10; a rect whose radiance `I/A` lights it as
/// the oriented point light of intensity `I cos θe`, §1.11).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "LightFile", into = "LightFile")]
pub struct Light {
    pub position: [f64; 3],
    pub color: [f64; 3],
    pub intensity: f64,
    /// Range `R` of the windowed falloff; absent means infinite.
    pub range: Option<f64>,
    pub shape: Shape,
}

/// A light as a scene file (and a link) writes it: the shape by its fields, `radius` for a
/// sphere (0 or absent: a point), `half_u` and `half_v` for a rect centred on `position`.
#[derive(Clone, Copy, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct LightFile {
    #[serde(with = "exactly")]
    position: [f64; 3],
    #[serde(default = "white", with = "exactly")]
    color: [f64; 3],
    intensity: f64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    range: Option<f64>,
    /// The sphere's radius in scene units (metres).
    #[serde(default, skip_serializing_if = "is_zero")]
    radius: f64,
    /// A rect's half-edge vectors (world); it emits toward `half_u × half_v`.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        with = "exactly_option"
    )]
    half_u: Option<[f64; 3]>,
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        with = "exactly_option"
    )]
    half_v: Option<[f64; 3]>,
}

impl TryFrom<LightFile> for Light {
    type Error = String;

    /// The shape its fields name: a rect needs both half-edges and no radius.
    fn try_from(f: LightFile) -> std::result::Result<Self, String> {
        let shape = match (f.half_u, f.half_v) {
            (None, None) => Shape::of_radius(f.radius),
            (Some(u), Some(v)) if f.radius == 0.0 => Shape::Rect {
                half_u: DVec3::from(u),
                half_v: DVec3::from(v),
            },
            (Some(_), Some(_)) => {
                return Err(
                    "a light has a radius (a sphere) or half_u and half_v (a rect), not both"
                        .into(),
                );
            }
            _ => return Err("a rect light needs both half_u and half_v".into()),
        };
        Ok(Self {
            position: f.position,
            color: f.color,
            intensity: f.intensity,
            range: f.range,
            shape,
        })
    }
}

impl From<Light> for LightFile {
    fn from(l: Light) -> Self {
        Self {
            position: l.position,
            color: l.color,
            intensity: l.intensity,
            range: l.range,
            radius: l.shape.radius(),
            half_u: l.shape.half_edges().map(|(u, _)| u.to_array()),
            half_v: l.shape.half_edges().map(|(_, v)| v.to_array()),
        }
    }
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
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

/// The smallest radius of a light with a size: a tenth of a millimetre in metres, the
/// precision a scene is saved to (`Scene::rounded_for_saving`). Its radiance `I/(π r²)` stays
/// within f32 (≤ 1e6/(π·1e-8) ≈ 3e13) for every intensity `validate` allows.
pub const MIN_RADIUS: f64 = 1e-4;

/// Lights made by `generate_lights`, added to the listed ones when the scene loads.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RandomLights {
    pub count: usize,
    pub seed: u64,
    /// Heights above the plane, `[min, max]`.
    #[serde(with = "exactly")]
    pub height: [f64; 2],
    /// Intensities, `[min, max]`.
    #[serde(with = "exactly")]
    pub intensity: [f64; 2],
    /// Range of every generated light; absent means infinite.
    #[serde(default)]
    pub range: Option<f64>,
    /// Radius of every generated light; absent or 0: point lights.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub radius: f64,
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
            l.shape = match l.shape {
                Shape::Rect { half_u, half_v } => Shape::Rect {
                    half_u: half_u.to_array().map(significant).into(),
                    half_v: half_v.to_array().map(significant).into(),
                },
                shape => Shape::of_radius(significant(shape.radius())),
            };
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

fn finite(what: &str, xs: &[f64]) -> std::result::Result<(), String> {
    match xs {
        _ if xs.iter().all(|x| x.is_finite()) => Ok(()),
        [x] => Err(format!(
            "{what} must be a finite number, got {}",
            number(*x)
        )),
        _ => Err(format!(
            "{what} must be finite numbers, got {}",
            numbers(xs)
        )),
    }
}

/// One value as written, or a list `[a, b, c]`.
fn numbers(xs: &[f64]) -> String {
    match xs {
        [x] => number(*x),
        _ => format!(
            "[{}]",
            xs.iter().map(|&x| number(x)).collect::<Vec<_>>().join(", ")
        ),
    }
}

/// Every value of `xs` finite and in `[lo, hi]`.
fn within(what: &str, xs: &[f64], lo: f64, hi: f64) -> std::result::Result<(), String> {
    finite(what, xs)?;
    match xs.iter().find(|x| !(lo..=hi).contains(*x)) {
        None => Ok(()),
        Some(_) => Err(format!(
            "{what} must be in [{}, {}], got {}",
            number(lo),
            number(hi),
            numbers(xs)
        )),
    }
}

/// A range is `> 0`; any positive value works the same on the CPU and the GPU (`GpuLight`
/// keeps a range too small for f32 positive rather than let it round to 0, "infinite").
fn check_range(what: &str, range: Option<f64>) -> std::result::Result<(), String> {
    match range {
        Some(r) if r.is_nan() || r <= 0.0 => Err(format!("{what} must be > 0, got {}", number(r))),
        _ => Ok(()),
    }
}

fn check_light(what: &str, l: &Light) -> std::result::Result<(), String> {
    within(
        &format!("{what}.position"),
        &l.position,
        -MAX_COORDINATE,
        MAX_COORDINATE,
    )?;
    finite(&format!("{what}.color"), &l.color)?;
    finite(&format!("{what}.intensity"), &[l.intensity])?;
    if l.intensity < 0.0 || l.color.iter().any(|&c| c < 0.0) {
        return Err(format!("{what}: color and intensity must be ≥ 0"));
    }
    let peak = l.color.iter().fold(0.0f64, |m, &c| m.max(c)) * l.intensity;
    if peak > MAX_INTENSITY {
        return Err(format!(
            "{what}: color × intensity must be ≤ {MAX_INTENSITY:e} per channel, got {peak:e} (beyond it f32 radiance overflows on the GPU)"
        ));
    }
    check_range(&format!("{what}.range"), l.range)?;
    match l.shape {
        Shape::Point => Ok(()),
        Shape::Sphere { radius } => check_radius(&format!("{what}.radius"), radius),
        Shape::Rect { half_u, half_v } => check_rect(what, half_u, half_v),
    }
}

/// A rect's half-edges are finite, each within `MAX_COORDINATE`, and span a quarter-area
/// `|half_u × half_v|` of at least `MIN_RADIUS²`: its radiance `I/A` then stays within f32
/// (≤ 1e6/(4·1e-8) = 2.5e13), as a sphere's does.
fn check_rect(what: &str, half_u: DVec3, half_v: DVec3) -> std::result::Result<(), String> {
    let (u, v) = (half_u.to_array(), half_v.to_array());
    within(
        &format!("{what}.half_u"),
        &u,
        -MAX_COORDINATE,
        MAX_COORDINATE,
    )?;
    within(
        &format!("{what}.half_v"),
        &v,
        -MAX_COORDINATE,
        MAX_COORDINATE,
    )?;
    let quarter_area = half_u.cross(half_v).length();
    if quarter_area < MIN_RADIUS * MIN_RADIUS {
        return Err(format!(
            "{what}: half_u × half_v must have length ≥ {} (a rect of some area; parallel or zero half-edges are not a rect), got {}",
            number(MIN_RADIUS * MIN_RADIUS),
            number(quarter_area)
        ));
    }
    Ok(())
}

/// A radius is 0 (a point) or in `[MIN_RADIUS, MAX_COORDINATE]`.
fn check_radius(what: &str, radius: f64) -> std::result::Result<(), String> {
    finite(what, &[radius])?;
    if radius == 0.0 || (MIN_RADIUS..=MAX_COORDINATE).contains(&radius) {
        return Ok(());
    }
    Err(format!(
        "{what} must be 0 (a point light) or in [{}, {}], got {}",
        number(MIN_RADIUS),
        number(MAX_COORDINATE),
        number(radius)
    ))
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
                shape: Shape::of_radius(r.radius),
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
