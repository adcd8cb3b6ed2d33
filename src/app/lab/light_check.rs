//! A light entering the lab (stored state, a view, a typed value) within the scene file's
//! limits (docs/design.md §3), each value that is not said and kept or clamped.

use glam::DVec3;

use crate::app::lab::part::Notes;
use crate::light::Shape;
use crate::scene::{Light, MAX_COORDINATE, MAX_INTENSITY, MIN_NORMAL, MIN_RADIUS};

/// A light's radius in the lab, where it has one: the scene's smallest (a tenth of a
/// millimetre) to 1 (half the default plane's half-size; larger spheres swallow the view).
pub const RADIUS_RANGE: [f64; 2] = [MIN_RADIUS, 1.0];

/// Light `k` within the limits; `false` where it has a non-finite value and no light before
/// it to take the value from.
pub fn check_light(n: &mut Notes, k: usize, l: &mut Light, before: Option<&Light>) -> bool {
    let values = l.position.into_iter().chain(l.color).chain([l.intensity]);
    let edges = l
        .shape
        .half_edges()
        .map_or([0.0; 6], |(u, v)| [u.x, u.y, u.z, v.x, v.y, v.z]);
    let normal = l.shape.normal().map_or([0.0; 3], |n| n.to_array());
    let finite = values
        .chain(l.range)
        .chain([l.shape.radius()])
        .chain(edges)
        .chain(normal)
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
    // A sphere's, a disk's or a tube's radius is at least `MIN_RADIUS` (docs/design.md §3).
    match &mut l.shape {
        Shape::Point => {}
        Shape::Sphere { radius } => {
            n.number(&name("radius"), radius, before.shape.radius(), RADIUS_RANGE);
        }
        Shape::Rect { half_u, half_v } => check_rect(n, &name, (half_u, half_v), &before),
        Shape::Disk { normal, radius } => {
            n.number(&name("radius"), radius, before.shape.radius(), RADIUS_RANGE);
            check_normal(n, &name("normal"), normal, &before);
        }
        Shape::Tube { half_axis, radius } => {
            n.number(&name("radius"), radius, before.shape.radius(), RADIUS_RANGE);
            let previous = before.shape.half_axis().unwrap_or(*half_axis).to_array();
            let mut xs = half_axis.to_array();
            n.numbers(
                &name("half_axis"),
                &mut xs,
                &previous,
                [-MAX_COORDINATE, MAX_COORDINATE],
            );
            *half_axis = DVec3::from(xs);
        }
    }
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

/// A disk's normal within the coordinates' limits and of some length (`scene::MIN_NORMAL`):
/// one of none takes the normal of the disk it replaces, or faces down (−z, toward the plane).
fn check_normal(n: &mut Notes, name: &str, normal: &mut DVec3, before: &Light) {
    let coordinate = [-MAX_COORDINATE, MAX_COORDINATE];
    let previous = before.shape.normal().unwrap_or(*normal);
    let mut xs = normal.to_array();
    n.numbers(name, &mut xs, &previous.to_array(), coordinate);
    *normal = DVec3::from(xs);
    if normal.length() < MIN_NORMAL {
        let kept = before
            .shape
            .normal()
            .filter(|b| b.length() >= MIN_NORMAL)
            .unwrap_or(DVec3::NEG_Z);
        n.say(format!(
            "{name}: of length under {MIN_NORMAL:e}, no direction: kept as {:?}",
            kept.to_array()
        ));
        *normal = kept;
    }
}

/// Whether a rect spans `scene::check_rect`'s least area (other shapes do).
fn has_area(shape: Shape) -> bool {
    shape
        .half_edges()
        .is_none_or(|(u, v)| u.cross(v).length() >= MIN_RADIUS * MIN_RADIUS)
}

/// A rect's half-edges within the coordinates' limits and of some area (`scene::check_rect`'s
/// `MIN_RADIUS²`): a flat one takes the shape of the light it replaces, or becomes a point.
fn check_rect(
    n: &mut Notes,
    name: &dyn Fn(&str) -> String,
    (half_u, half_v): (&mut DVec3, &mut DVec3),
    before: &Light,
) {
    let coordinate = [-MAX_COORDINATE, MAX_COORDINATE];
    let (before_u, before_v) = before.shape.half_edges().unwrap_or((*half_u, *half_v));
    for (field, edge, previous) in [("half_u", half_u, before_u), ("half_v", half_v, before_v)] {
        let mut xs = edge.to_array();
        n.numbers(&name(field), &mut xs, &previous.to_array(), coordinate);
        *edge = DVec3::from(xs);
    }
}
