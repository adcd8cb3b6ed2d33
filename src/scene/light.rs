//! A scene's lights: each as the lab holds it (`Light`, its shape a `light::Shape`) and as a
//! file writes it (`LightFile`), and the seeded generator of many (docs/design.md §3).

use glam::DVec3;
use serde::{Deserialize, Serialize};

use crate::light::Shape;
use crate::scene::lists::{exactly, exactly_option};

/// A light: RGB `color × intensity` (W/sr-like units: irradiance `I/d²` at distance d) from
/// `position`, of a shape (a point; a sphere whose radiance `I/(π r²)` lights a distant point
/// as the point light does, docs/design.md §1.10; a rect or a disk whose radiance `I/A` lights
/// it as the oriented point light of intensity `I cos θe`, §1.11 and §1.12).
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
/// sphere (0 or absent: a point), `half_u` and `half_v` for a rect centred on `position`,
/// `radius` and `normal` for a disk, `radius` and `half_axis` for a tube.
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
    /// A disk's normal (world): it emits toward it. Its length is not read.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        with = "exactly_option"
    )]
    normal: Option<[f64; 3]>,
    /// A tube's half axis (world): the capsule's segment runs from `position − half_axis` to
    /// `position + half_axis`, swept by `radius`.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        with = "exactly_option"
    )]
    half_axis: Option<[f64; 3]>,
}

impl TryFrom<LightFile> for Light {
    type Error = String;

    /// The shape its fields name: a rect needs both half-edges and no radius, a disk a
    /// radius and a normal, a tube a radius and a half axis.
    fn try_from(f: LightFile) -> std::result::Result<Self, String> {
        let shape = match (f.half_u, f.half_v) {
            _ if f.half_axis.is_some() => tube_of(&f)?,
            (None, None) => match f.normal {
                None => Shape::of_radius(f.radius),
                Some(_) if f.radius == 0.0 => {
                    return Err("a disk light (a normal) needs a radius".into());
                }
                Some(n) => Shape::Disk {
                    normal: DVec3::from(n),
                    radius: f.radius,
                },
            },
            (Some(_), Some(_)) if f.normal.is_some() => {
                return Err(
                    "a light has half_u and half_v (a rect) or a normal (a disk), not both".into(),
                );
            }
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

/// A file's tube: a half axis and a radius, and neither a rect's half-edges nor a normal.
fn tube_of(f: &LightFile) -> std::result::Result<Shape, String> {
    if f.half_u.is_some() || f.half_v.is_some() || f.normal.is_some() {
        return Err("a light has a half_axis (a tube), half_u and half_v (a rect) or a normal (a disk), not two of them".into());
    }
    match f.half_axis {
        Some(_) if f.radius == 0.0 => Err("a tube light (a half_axis) needs a radius".into()),
        Some(h) => Ok(Shape::Tube {
            half_axis: DVec3::from(h),
            radius: f.radius,
        }),
        None => Ok(Shape::of_radius(f.radius)),
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
            normal: l.shape.normal().map(|n| n.to_array()),
            half_axis: l.shape.half_axis().map(|h| h.to_array()),
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
