//! A scene's lights: each as the lab holds it (`Light`, its shape a `light::Shape`) and as a
//! file writes it (its table, its shape by the fields its module names), and the seeded
//! generator of many (docs/design.md §3).

use std::sync::OnceLock;

use glam::DVec3;
use serde::ser::SerializeStruct;
use serde::{Deserialize, Deserializer, Serialize, Serializer, de};

use crate::light::{Shape, ShapeKind, VectorField};
use crate::scene::lists::{exactly, exactly_option};

/// A light: RGB `color × intensity` (W/sr-like units: irradiance `I/d²` at distance d) from
/// `position`, of a shape (a point; a sphere whose radiance `I/(π r²)` lights a distant point
/// as the point light does, docs/design.md §1.10; a shape whose radiance `I/A` lights it as
/// the oriented point light of intensity `I cos θe`, §1.11 and §1.12, or, emitting all
/// around, as the point light, §1.15).
///
/// A scene file (and a link, and the lab's stored state) writes it as a table: `position`,
/// `color`, `intensity`, `range`, `radius` (0 or absent for a point, and for a shape without
/// one), then the shape's vectors by their names (`ShapeKind::vector_fields`: `half_u` and
/// `half_v` for a rect centred on `position`, `normal` for a disk…), which say what it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    pub position: [f64; 3],
    pub color: [f64; 3],
    pub intensity: f64,
    /// Range `R` of the windowed falloff; absent means infinite.
    pub range: Option<f64>,
    pub shape: Shape,
}

/// The fields a light's table has beside its shape's vectors.
const FIXED_FIELDS: [&str; 5] = ["position", "color", "intensity", "range", "radius"];

/// Every field a light's table may have: `FIXED_FIELDS`, then each shape's vectors.
fn fields() -> &'static [&'static str] {
    static FIELDS: OnceLock<Vec<&'static str>> = OnceLock::new();
    FIELDS.get_or_init(|| {
        let mut all = FIXED_FIELDS.to_vec();
        for kind in ShapeKind::ALL {
            all.extend(kind.vector_fields().iter().map(|f| f.name));
        }
        all
    })
}

impl Serialize for Light {
    /// The fields in `fields()`' order, each optional one only where it is: a range where
    /// the light has one, a radius where it is not 0, and the shape's vectors.
    fn serialize<S: Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        let radius = self.shape.radius();
        let vectors = self.shape.vectors();
        let count = 3 + usize::from(self.range.is_some()) + usize::from(radius != 0.0);
        // The struct's name of before, which RON's messages give.
        let mut t = s.serialize_struct("LightFile", count + vectors.len())?;
        t.serialize_field("position", &self.position[..])?;
        t.serialize_field("color", &self.color[..])?;
        t.serialize_field("intensity", &self.intensity)?;
        match self.range {
            Some(_) => t.serialize_field("range", &self.range)?,
            None => t.skip_field("range")?,
        }
        match radius != 0.0 {
            true => t.serialize_field("radius", &radius)?,
            false => t.skip_field("radius")?,
        }
        for v in vectors {
            // An option, as an optional field was: RON (the lab's stored state) writes
            // `Some(…)` for it, and reads it back only so.
            t.serialize_field(v.name, &Some(&v.value.to_array()[..]))?;
        }
        t.end()
    }
}

impl<'de> Deserialize<'de> for Light {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        d.deserialize_struct("LightFile", fields(), LightVisitor)
    }
}

/// A field's name, read as an identifier (RON's struct fields are; TOML's and JSON's keys
/// are strings, which an identifier takes too).
struct FieldName(String);

impl<'de> Deserialize<'de> for FieldName {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        struct Name;
        impl de::Visitor<'_> for Name {
            type Value = FieldName;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("a field name")
            }
            fn visit_str<E: de::Error>(self, v: &str) -> std::result::Result<FieldName, E> {
                Ok(FieldName(v.to_string()))
            }
        }
        d.deserialize_identifier(Name)
    }
}

/// `Some(…)` or a bare list, of exactly three numbers (`lists::exactly_option`'s reading).
#[derive(Deserialize)]
#[serde(transparent)]
struct Vector(#[serde(with = "exactly_option")] Option<[f64; 3]>);

/// Exactly three numbers (`lists::exactly`'s reading).
#[derive(Deserialize)]
#[serde(transparent)]
struct Triple(#[serde(with = "exactly")] [f64; 3]);

/// Reads a light's table: every field once, none unknown (as `deny_unknown_fields`), and
/// then its shape from the vectors it has (`shape_of`).
struct LightVisitor;

impl<'de> de::Visitor<'de> for LightVisitor {
    type Value = Light;

    fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("a light's table")
    }

    fn visit_map<A: de::MapAccess<'de>>(self, mut map: A) -> std::result::Result<Light, A::Error> {
        let (mut position, mut color, mut intensity, mut range, mut radius) =
            (None, None, None, None, None);
        let mut vectors: Vec<(&'static str, DVec3)> = Vec::new();
        while let Some(FieldName(key)) = map.next_key()? {
            let Some(&name) = fields().iter().find(|&&f| f == key) else {
                return Err(de::Error::unknown_field(&key, fields()));
            };
            let repeated = match name {
                "position" => position.replace(map.next_value::<Triple>()?.0).is_some(),
                "color" => color.replace(map.next_value::<Triple>()?.0).is_some(),
                "intensity" => intensity.replace(map.next_value::<f64>()?).is_some(),
                "range" => range.replace(map.next_value::<Option<f64>>()?).is_some(),
                "radius" => radius.replace(map.next_value::<f64>()?).is_some(),
                _ => {
                    let repeated = vectors.iter().any(|(n, _)| *n == name);
                    if let Some(v) = map.next_value::<Vector>()?.0 {
                        vectors.push((name, DVec3::from(v)));
                    }
                    repeated
                }
            };
            if repeated {
                return Err(de::Error::duplicate_field(name));
            }
        }
        let radius = radius.unwrap_or(0.0);
        let shape = shape_of(radius, &vectors).map_err(de::Error::custom)?;
        Ok(Light {
            position: position.ok_or_else(|| de::Error::missing_field("position"))?,
            color: color.unwrap_or_else(white),
            intensity: intensity.ok_or_else(|| de::Error::missing_field("intensity"))?,
            range: range.flatten(),
            shape,
        })
    }
}

/// The shape a light's fields name: the one shape whose vectors it has, all of them, with a
/// radius where that shape has one and none where it has not; a point or a sphere by its
/// radius where it has no vectors.
fn shape_of(radius: f64, given: &[(&'static str, DVec3)]) -> std::result::Result<Shape, String> {
    let has = |f: &VectorField| given.iter().any(|(n, _)| *n == f.name);
    let named: Vec<ShapeKind> = ShapeKind::ALL
        .into_iter()
        .filter(|k| k.vector_fields().iter().any(has))
        .collect();
    let what = |k: ShapeKind| {
        let names: Vec<_> = k.vector_fields().iter().map(|f| f.name).collect();
        format!("{} ({})", names.join(" and "), k.light_noun())
    };
    let kind = match named[..] {
        [] => return Ok(Shape::of_radius(radius)),
        [kind] => kind,
        [a, b] => return Err(format!("a light has {} or {}, not both", what(a), what(b))),
        _ => {
            let all: Vec<_> = named.iter().map(|&k| what(k)).collect();
            return Err(format!(
                "a light has {}: one shape's, not several",
                all.join(", ")
            ));
        }
    };
    let fields = kind.vector_fields();
    let names: Vec<_> = fields.iter().map(|f| f.name).collect();
    if !fields.iter().all(has) {
        let both = if names.len() == 2 { "both " } else { "all of " };
        return Err(format!(
            "{} needs {both}{}",
            kind.light_noun(),
            names.join(" and ")
        ));
    }
    match (kind.has_radius(), radius == 0.0) {
        (true, true) => Err(format!(
            "{} ({}) needs a radius",
            kind.light_noun(),
            names.join(" and ")
        )),
        (false, false) => Err(format!(
            "a light has a radius (a sphere) or {}, not both",
            what(kind)
        )),
        _ => {
            let value = |f: &VectorField| given.iter().find(|(n, _)| *n == f.name).map(|v| v.1);
            let vectors: Vec<DVec3> = fields.iter().filter_map(value).collect();
            Ok(Shape::of_dimensions(kind, radius, &vectors))
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

pub use crate::light::MIN_RADIUS;

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
