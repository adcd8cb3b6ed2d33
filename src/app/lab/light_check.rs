//! A light entering the lab (stored state, a view, a typed value) within the scene file's
//! limits (docs/design.md §3), each value that is not said and kept or clamped.

use glam::DVec3;

use crate::app::lab::part::Notes;
use crate::light::Shape;
use crate::scene::{Light, MAX_COORDINATE, MAX_INTENSITY, MIN_NORMAL, MIN_RADIUS};

pub use crate::light::RADIUS_RANGE;

/// Light `k` within the limits; `false` where it has a non-finite value and no light before
/// it to take the value from.
pub fn check_light(n: &mut Notes, k: usize, l: &mut Light, before: Option<&Light>) -> bool {
    let values = l.position.into_iter().chain(l.color).chain([l.intensity]);
    let vectors = l
        .shape
        .vectors()
        .into_iter()
        .flat_map(|v| v.value.to_array());
    let finite = values
        .chain(l.range)
        .chain([l.shape.radius()])
        .chain(vectors)
        .all(f64::is_finite);
    let before = match (before, finite) {
        (Some(b), _) => *b,
        (None, true) => *l,
        (None, false) => {
            n.say(format!(
                "lights[{k}]: a non-finite value, the light refused"
            ));
            return false;
        }
    };
    let name = |f: &str| format!("lights[{k}].{f}");
    let coordinate = [-MAX_COORDINATE, MAX_COORDINATE];
    n.numbers(
        &name("position"),
        &mut l.position,
        &before.position,
        coordinate,
    );
    n.numbers(&name("color"), &mut l.color, &before.color, [0.0, 1.0]);
    n.number(
        &name("intensity"),
        &mut l.intensity,
        before.intensity,
        [0.0, MAX_INTENSITY],
    );
    if let Some(r) = &mut l.range {
        // A range is > 0 (docs/design.md §3); 1e-6 is `brdf::MIN_LIGHT_DISTANCE`, within which
        // a light lights nothing anyway.
        let previous = before.range.unwrap_or(*r);
        n.number(&name("range"), r, previous, [1e-6, 2.0 * MAX_COORDINATE]);
    }
    check_dimensions(n, &name, l, &before);
    if !has_area(l.shape) {
        let shape = if has_area(before.shape) {
            before.shape
        } else {
            Shape::Point
        };
        n.say(format!(
            "lights[{k}]: half_u × half_v has no area (under {:e}): not a rect, kept as a {}",
            MIN_RADIUS * MIN_RADIUS,
            if shape == Shape::Point {
                "point"
            } else {
                "shape it had"
            }
        ));
        l.shape = shape;
    }
    true
}

/// Each of a light's dimensions within its limits (docs/design.md §3), as its shape names
/// them (`Shape::vectors`): a radius, where the shape has one, of at least `MIN_RADIUS`; each
/// vector within the coordinates' limits, and a direction of some length.
fn check_dimensions(n: &mut Notes, name: &dyn Fn(&str) -> String, l: &mut Light, before: &Light) {
    let mut radius = l.shape.radius();
    if l.shape.kind().has_radius() {
        n.number(
            &name("radius"),
            &mut radius,
            before.shape.radius(),
            RADIUS_RANGE,
        );
    }
    let previous = |field: &str| before.shape.vectors().into_iter().find(|v| v.name == field);
    let checked: Vec<DVec3> = l
        .shape
        .vectors()
        .into_iter()
        .map(|v| {
            let was = previous(v.name).map_or(v.value, |b| b.value);
            let mut xs = v.value.to_array();
            let coordinate = [-MAX_COORDINATE, MAX_COORDINATE];
            n.numbers(&name(v.name), &mut xs, &was.to_array(), coordinate);
            match v.direction {
                true => some_direction(n, &name(v.name), DVec3::from(xs), was),
                false => DVec3::from(xs),
            }
        })
        .collect();
    l.shape = l.shape.map_dimensions(|k, _| checked[k], |_| radius);
}

/// A direction (a disk's normal) of some length (`scene::MIN_NORMAL`): one of none takes the
/// one it replaces (`was`), or faces down (−z, toward the plane).
fn some_direction(n: &mut Notes, name: &str, direction: DVec3, was: DVec3) -> DVec3 {
    if direction.length() >= MIN_NORMAL {
        return direction;
    }
    let kept = Some(was)
        .filter(|b| b.length() >= MIN_NORMAL)
        .unwrap_or(DVec3::NEG_Z);
    n.say(format!(
        "{name}: of length under {MIN_NORMAL:e}, no direction: kept as {:?}",
        kept.to_array()
    ));
    kept
}

/// Whether a rect spans `scene::check_rect`'s least area (other shapes do).
fn has_area(shape: Shape) -> bool {
    shape
        .half_edges()
        .is_none_or(|(u, v)| u.cross(v).length() >= MIN_RADIUS * MIN_RADIUS)
}
