//! Where on the plane: the pixel where a difference is largest (*worst pixel*), and a free
//! spot for a new light (*+ light*).

use glam::DVec3;

use crate::render::{Frame, FrameKind};
use crate::scene::Scene;

/// The plane pixel where a difference frame is largest (the first of equals); `None` for a
/// radiance frame or one without plane pixels.
pub fn worst_pixel(frame: &Frame) -> Option<(usize, usize)> {
    if frame.kind != FrameKind::RelativeDifference {
        return None;
    }
    let k = (0..frame.pixels.len())
        .filter(|&k| frame.on_plane[k] && !frame.pixels[k].x.is_nan())
        .reduce(|best, k| {
            if frame.pixels[k].x > frame.pixels[best].x {
                k
            } else {
                best
            }
        })?;
    Some((k % frame.width, k / frame.width))
}

/// Where *+ light* puts a light, a quarter of the plane's half size above it: of a 9 × 9 grid
/// over the plane, the point whose light and its foot are seen well inside a `size` image
/// and whose light lies farthest (in the image) from the divider column and from every other
/// light's image; above the centre where no point is seen.
pub fn free_spot(scene: &Scene, divider: f64, (width, height): (usize, usize)) -> [f64; 3] {
    const STEPS: usize = 9;
    let half = scene.plane.half_size;
    let z = 0.25 * half;
    let (w, h) = (width as f64, height as f64);
    // 5% of the width from the image's edges: a marker there is seen whole, not cut.
    let margin = 0.05 * w;
    let inside = |p: [f64; 3]| {
        scene
            .project(DVec3::from(p), width, height)
            .filter(|&(x, y)| x >= margin && x <= w - margin && y >= margin && y <= h - margin)
    };
    let others: Vec<(f64, f64)> = scene
        .lights
        .iter()
        .filter_map(|l| scene.project(DVec3::from(l.position), width, height))
        .collect();
    let divider_x = divider * w;
    let mut best: Option<(f64, [f64; 3])> = None;
    for j in 0..STEPS {
        for i in 0..STEPS {
            let at = |k: usize| half * (-0.9 + 1.8 * k as f64 / (STEPS - 1) as f64);
            let (x, y) = (at(i), at(j));
            let (Some(q), Some(_)) = (inside([x, y, z]), inside([x, y, 0.0])) else {
                continue;
            };
            let clearance = others
                .iter()
                .map(|o| (o.0 - q.0).hypot(o.1 - q.1))
                .fold((q.0 - divider_x).abs(), f64::min);
            if best.is_none_or(|(c, _)| clearance > c) {
                best = Some((clearance, [x, y, z]));
            }
        }
    }
    best.map_or([0.0, 0.0, z], |(_, p)| p)
}
