//! What the chart measures (docs/design.md §4.6): the tasks of one measurement — the methods on
//! the scene, each light shape's methods, and the paper's Table 1 curves.

use crate::gpu::method_file::MethodFile;
use crate::light::ShapeKind;
use crate::ltc::Normalization;
use crate::measure::bench::{DEFAULT_RANGE, PAPER_LIGHTS, bench_scene};
use crate::render::{LtcRules, Method, RenderSettings, ShapeMethod, ShapeMethods};
use crate::scene::Scene;

use super::{MEASURE_SIZE, Task};

/// The methods timed on the scene itself: the exact BRDF, the LTC forms, the paper's printed
/// normalization, and a method file where one is loaded.
pub(super) fn method_tasks(scene: &Scene, file: Option<&MethodFile>) -> Vec<Task> {
    let (w, h) = MEASURE_SIZE;
    let mut tasks = Vec::new();
    // The reference shades every light exactly, whatever its shape; the LTC forms shade
    // lights with a size by the lab's defaults (ltc-disk, ltc-polygon, ltc-disk).
    let exact = ShapeMethods::references();
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
            exact.with(method)
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
    let kinds: Vec<ShapeKind> = scene.lights.iter().map(|l| l.shape.kind()).collect();
    for kind in ShapeKind::sized().filter(|k| kinds.contains(k)) {
        let inexact = ShapeMethod::all(kind)
            .into_iter()
            .filter(|&m| m != ShapeMethod::reference(kind));
        for m in inexact {
            tasks.push(Task {
                label: format!("{} {}", kind.name(), m.name()),
                method: None,
                scene: scene.clone(),
                settings: RenderSettings {
                    a: fast.a.with(m),
                    ..fast
                },
                curve: None,
            });
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
