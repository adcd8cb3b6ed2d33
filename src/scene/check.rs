//! Why a scene's values cannot be rendered: each finite and within the limits of
//! docs/design.md §3, named by its field.

use glam::DVec3;

use crate::error::number;
use crate::scene::{Light, MAX_COORDINATE, MAX_INTENSITY, MIN_RADIUS};

pub(super) fn finite(what: &str, xs: &[f64]) -> std::result::Result<(), String> {
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
pub(super) fn within(what: &str, xs: &[f64], lo: f64, hi: f64) -> std::result::Result<(), String> {
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
pub(super) fn check_range(what: &str, range: Option<f64>) -> std::result::Result<(), String> {
    match range {
        Some(r) if r.is_nan() || r <= 0.0 => Err(format!("{what} must be > 0, got {}", number(r))),
        _ => Ok(()),
    }
}

pub(super) fn check_light(what: &str, l: &Light) -> std::result::Result<(), String> {
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
    // Each dimension of the shape, as it names it: its radius (0 for a shape without one),
    // each vector, and a rect's area.
    check_radius(&format!("{what}.radius"), l.shape.radius())?;
    for v in l.shape.vectors() {
        let name = format!("{what}.{}", v.name);
        match v.direction {
            true => check_normal(&name, v.value)?,
            // Of any length, 0 included: its shape's methods take it (docs/design.md §3).
            false => within(&name, &v.value.to_array(), -MAX_COORDINATE, MAX_COORDINATE)?,
        }
    }
    match l.shape.half_edges() {
        Some((half_u, half_v)) => check_rect_area(what, half_u, half_v),
        None => Ok(()),
    }
}

pub use crate::light::disk::MIN_NORMAL;

/// A disk's normal is finite, within `MAX_COORDINATE` and of length at least `MIN_NORMAL`.
fn check_normal(what: &str, normal: DVec3) -> std::result::Result<(), String> {
    within(what, &normal.to_array(), -MAX_COORDINATE, MAX_COORDINATE)?;
    let length = normal.length();
    if length < MIN_NORMAL {
        return Err(format!(
            "{what} must have length ≥ {} (the direction the disk emits toward), got {}",
            number(MIN_NORMAL),
            number(length)
        ));
    }
    Ok(())
}

/// A rect's half-edges span a quarter-area `|half_u × half_v|` of at least `MIN_RADIUS²`: its
/// radiance `I/A` then stays within f32 (≤ 1e6/(4·1e-8) = 2.5e13), as a sphere's does.
fn check_rect_area(what: &str, half_u: DVec3, half_v: DVec3) -> std::result::Result<(), String> {
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
pub(super) fn check_radius(what: &str, radius: f64) -> std::result::Result<(), String> {
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
