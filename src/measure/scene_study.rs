//! A study of a scene as given (docs/design.md §4.6): a scene file (`study --scene FILE`), or a
//! sized shape's failure preset studied beside its generated lights (`rect-horizon` with
//! `--rect-half-edge`, `disk-limits` with `--disk-radius`). The generated lights face the plane
//! from above and never cross the horizon, where a clamp matters: measured there alone, a
//! method file without its horizon clamp came out better than three.js's. Here every method
//! of each shape the scene holds is measured against the scene's exact image — every shape
//! exact, the points by the BRDF — with the other shapes exact, in rows named
//! `<variant>@<scene>`.

use crate::error::Result;
use crate::gpu::GpuContext;
use crate::light::ShapeKind;
use crate::ltc::Clipping;
use crate::measure::study::{
    LutChoice, Renderers, Study, StudyRow, StudySettings, Variant, row, timed,
};
use crate::render::{LtcRules, Method, RenderSettings, ShapeMethod, ShapeMethods};
use crate::scene::Scene;

/// The rows of every scene of `s` studied as given (`StudySettings::scenes`), at each α and
/// culling, on the renderers of `study`.
pub fn run(
    ctx: &GpuContext,
    study: &mut Study,
    s: &StudySettings,
    progress: &mut impl FnMut(&StudyRow),
) -> Result<Vec<StudyRow>> {
    let mut rows = Vec::new();
    for &alpha in &s.alphas {
        for &cull in &s.culls {
            for (name, scene) in &s.scenes {
                let one = SceneStudy {
                    scene,
                    name,
                    alpha,
                    cull,
                };
                rows.extend(one.rows(ctx, &mut study.renderers, &study.variants, s, progress)?);
            }
        }
    }
    Ok(rows)
}

/// One scene at one α and culling.
pub struct SceneStudy<'a> {
    pub scene: &'a Scene,
    /// Its name in the rows (`<variant>@<name>`).
    pub name: &'a str,
    pub alpha: f64,
    pub cull: bool,
}

impl SceneStudy<'_> {
    /// Its rows: the exact image (error 0), then each point variant where it holds points,
    /// each method of each sized shape it holds, and the method file where it shades one of
    /// them (its points without a function of its own by `ltc`).
    pub(crate) fn rows(
        &self,
        ctx: &GpuContext,
        r: &mut Renderers,
        variants: &[Variant],
        s: &StudySettings,
        progress: &mut impl FnMut(&StudyRow),
    ) -> Result<Vec<StudyRow>> {
        let mut scene = self.scene.clone();
        scene.material.alpha = self.alpha;
        let case = (self.alpha, scene.lights.len().max(1), self.cull);
        let base = RenderSettings {
            a: ShapeMethods::references(),
            cull: self.cull,
            ..RenderSettings::single(s.size.0, s.size.1, Method::Brdf)
        };
        let (ms, reference) = timed(ctx, r.of(LutChoice::Shipped), &scene, &base, s.frames)?;
        let exact = row(&self.named("exact"), case, s, ms, &reference, &reference);
        progress(&exact);
        let mut rows = vec![exact];
        let mut measure = |name: String, r: &mut _, settings: &RenderSettings| -> Result<()> {
            let (ms, image) = timed(ctx, r, &scene, settings, s.frames)?;
            let row = row(&self.named(&name), case, s, ms, &image, &reference);
            progress(&row);
            rows.push(row);
            Ok(())
        };
        let kinds: Vec<ShapeKind> = self.scene.lights.iter().map(|l| l.shape.kind()).collect();
        if kinds.contains(&ShapeKind::Point) {
            for v in variants.iter().filter(|v| v.method != Method::Brdf) {
                let settings = RenderSettings {
                    a: ShapeMethods::references().with(v.method),
                    rules: LtcRules {
                        clipping: Clipping::BOTH,
                        normalization: v.normalization,
                        filter: v.filter,
                        horizon: v.horizon.rule(),
                    },
                    ..base
                };
                measure(v.name.to_string(), r.of(v.lut), &settings)?;
            }
        }
        for a in sized_methods(&kinds) {
            let name = format!("{}-{}", a.0, a.1);
            let settings = RenderSettings { a: a.2, ..base };
            measure(name, r.of(LutChoice::Shipped), &settings)?;
        }
        if let Some((shades, fr)) = &mut r.file
            && kinds.iter().any(|k| shades[k.index()])
        {
            let settings = RenderSettings {
                a: ShapeMethods::references().with(Method::File),
                ..base
            };
            measure("file".to_string(), fr, &settings)?;
        }
        Ok(rows)
    }

    fn named(&self, variant: &str) -> String {
        format!("{variant}@{}", self.name)
    }
}

/// Each inexact method of each sized shape among `kinds`: the shape's name, the method's,
/// and the methods of a render by it (every other shape exact).
fn sized_methods(kinds: &[ShapeKind]) -> Vec<(&'static str, &'static str, ShapeMethods)> {
    let inexact = |kind| {
        ShapeMethod::all(kind)
            .into_iter()
            .filter(move |&m| m != ShapeMethod::reference(kind))
            .map(move |m| (kind.name(), m.name(), ShapeMethods::references().with(m)))
    };
    ShapeKind::sized()
        .filter(|k| kinds.contains(k))
        .flat_map(inexact)
        .collect()
}
