//! What the chart measures (docs/design.md §4.6): the tasks of one measurement — the methods on
//! the scene, each light shape's methods, and the paper's Table 1 curves.

use crate::gpu::method_file::MethodFile;
use crate::light::Shape;
use crate::light::disk::DiskMethod;
use crate::light::rect::RectMethod;
use crate::light::sphere::SphereMethod;
use crate::ltc::Normalization;
use crate::measure::bench::{DEFAULT_RANGE, PAPER_LIGHTS, bench_scene};
use crate::render::{LtcRules, Method, RenderSettings, ShapeMethods};
use crate::scene::Scene;

use super::{MEASURE_SIZE, Task};

/// The methods timed on the scene itself: the exact BRDF, the LTC forms, the paper's printed
/// normalization, and a method file where one is loaded.
pub(super) fn method_tasks(scene: &Scene, file: Option<&MethodFile>) -> Vec<Task> {
    let (w, h) = MEASURE_SIZE;
    let mut tasks = Vec::new();
    // The reference shades every light exactly, whatever its shape; the LTC forms shade
    // lights with a size by the lab's defaults (ltc-disk, ltc-polygon, ltc-disk).
    let exact = ShapeMethods {
        point: Method::Brdf,
        sphere: SphereMethod::Exact,
        rect: RectMethod::Exact,
        disk: DiskMethod::Exact,
    };
    for (label, method, normalization) in [
        ("brdf", Method::Brdf, Normalization::Corrected),
        ("brdf-fast", Method::BrdfFast, Normalization::Corrected),
        ("ltc", Method::Ltc, Normalization::Corrected),
        ("ltc-fast", Method::LtcFast, Normalization::Corrected),
        ("ltc-paper", Method::Ltc, Normalization::PaperLiteral),
    ] {
        let single = RenderSettings::single(w, h, method);
        let a = if method.is_ltc() {
            single.a
        } else {
            ShapeMethods {
                point: method,
                ..exact
            }
        };
        tasks.push(Task {
            label: label.into(),
            method: Some(method),
            scene: scene.clone(),
            settings: RenderSettings {
                rules: LtcRules {
                    normalization,
                    ..LtcRules::default()
                },
                a,
                ..single
            },
            curve: None,
        });
    }
    // The method file: each shape by its function where it has one, the rest as the lab.
    if let Some(f) = file {
        tasks.push(Task {
            label: format!("file: {}", f.name),
            method: Some(Method::File),
            scene: scene.clone(),
            settings: RenderSettings::single(w, h, Method::File),
            curve: None,
        });
    }
    tasks
}

/// Each method of each light shape the scene holds, timed and measured alone.
pub(super) fn shape_tasks(scene: &Scene) -> Vec<Task> {
    let (w, h) = MEASURE_SIZE;
    let mut tasks = Vec::new();
    // Each method of each shape the scene holds, its points by ltc-fast and its other
    // sized lights by the defaults: what that shape's method costs and misses.
    let fast = RenderSettings::single(w, h, Method::LtcFast);
    let has = |shape: fn(&Shape) -> bool| scene.lights.iter().any(|l| shape(&l.shape));
    let mut sized = |label: String, a: ShapeMethods| {
        tasks.push(Task {
            label,
            method: None,
            scene: scene.clone(),
            settings: RenderSettings { a, ..fast },
            curve: None,
        });
    };
    if has(|s| matches!(s, Shape::Sphere { .. })) {
        for sphere in SphereMethod::ALL.into_iter().skip(1) {
            sized(
                format!("sphere {}", sphere.name()),
                ShapeMethods { sphere, ..fast.a },
            );
        }
    }
    if has(|s| matches!(s, Shape::Rect { .. })) {
        for rect in RectMethod::ALL.into_iter().skip(1) {
            sized(
                format!("rect {}", rect.name()),
                ShapeMethods { rect, ..fast.a },
            );
        }
    }
    if has(|s| matches!(s, Shape::Disk { .. })) {
        for disk in DiskMethod::ALL.into_iter().skip(1) {
            sized(
                format!("disk {}", disk.name()),
                ShapeMethods { disk, ..fast.a },
            );
        }
    }
    tasks
}

/// The paper's Table 1 curves: each f32 method at each of its light counts.
pub(super) fn curve_tasks() -> Vec<Task> {
    let (w, h) = MEASURE_SIZE;
    let mut tasks = Vec::new();
    for method in Method::F32 {
        for &n in &PAPER_LIGHTS {
            tasks.push(Task {
                label: format!("{} at {n} lights", method.name()),
                method: Some(method),
                scene: bench_scene(n, Some(DEFAULT_RANGE)),
                settings: RenderSettings::single(w, h, method),
                curve: Some((method, n)),
            });
        }
    }
    tasks
}
