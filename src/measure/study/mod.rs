//! Speed against accuracy (docs/design.md §4): every shading variant timed on the GPU in one run and
//! compared with the exact BRDF image of the same scene, for the paper-100 set-up at several
//! light counts and roughnesses.

use crate::error::{Error, Result};
use crate::gpu::GpuContext;
use crate::gpu::method_file::MethodFile;
use crate::gpu::plane::ShaderChecks;
use crate::gpu::renderer::PlaneRenderer;
use crate::light::ShapeKind;
use crate::ltc::fit::{FitSettings, fit_table};
use crate::ltc::lut::{Encoding, Lut, Table};
use crate::ltc::remedy::Horizon;
use crate::measure::bench::sized_scene;
use crate::metrics::image_error;
use crate::render::{Frame, Method, RenderSettings, ShapeMethod, ShapeMethods};
use crate::scene::Scene;

mod variants;

pub use variants::{
    LTC, LutChoice, REFERENCE, Variant, encoded_variant, variant, variant_encoding, variant_named,
    variants,
};

/// One row of `study.csv`.
#[derive(Clone, Debug, PartialEq)]
pub struct StudyRow {
    pub variant: String,
    pub alpha: f64,
    pub lights: usize,
    pub width: usize,
    pub height: usize,
    pub cull: bool,
    /// Every light's range (`None`: infinite).
    pub range: Option<f64>,
    pub ms_median: f64,
    pub rel_rmse: f64,
    pub max_rel_err: f64,
    pub p99_rel_err: f64,
}

impl StudyRow {
    pub const CSV_HEADER: &'static str = "variant,alpha,lights,width,height,cull,range,ms_median,glightpx_per_s,rel_rmse,max_rel_err,p99_rel_err";

    /// Light-pixel evaluations per second, in billions (every pixel of the study scene sees
    /// the plane).
    pub fn glightpx_per_s(&self) -> f64 {
        (self.lights * self.width * self.height) as f64 / (self.ms_median * 1e-3) / 1e9
    }

    pub fn csv(&self) -> String {
        format!(
            "{},{},{},{},{},{},{},{:.6},{:.4},{:.6e},{:.6e},{:.6e}",
            self.variant,
            self.alpha,
            self.lights,
            self.width,
            self.height,
            if self.cull { "on" } else { "off" },
            crate::measure::bench::range_text(self.range),
            self.ms_median,
            self.glightpx_per_s(),
            self.rel_rmse,
            self.max_rel_err,
            self.p99_rel_err
        )
    }

    /// Parses a row written by `csv` (the lab reads study.csv back); errors name the line.
    pub fn parse(line: &str, at: &str) -> Result<Self> {
        let f: Vec<&str> = line.split(',').map(str::trim).collect();
        if f.len() != 12 {
            return Err(Error::input(
                at,
                format!("expected 12 values, found {}", f.len()),
            ));
        }
        let num = |k: usize| -> Result<f64> {
            f[k].parse::<f64>()
                .ok()
                .filter(|x| x.is_finite() && *x >= 0.0)
                .ok_or_else(|| Error::input(at, format!("'{}' is not a finite number ≥ 0", f[k])))
        };
        let int = |k: usize| -> Result<usize> {
            f[k].parse::<usize>()
                .ok()
                .filter(|&n| n > 0)
                .ok_or_else(|| Error::input(at, format!("'{}' is not a whole number ≥ 1", f[k])))
        };
        // A time of 0 makes fps = 1000/0: the chart froze on it.
        let time = |k: usize| -> Result<f64> {
            Some(num(k)?)
                .filter(|&t| t > 0.0)
                .ok_or_else(|| Error::input(at, format!("ms_median '{}' must be > 0", f[k])))
        };
        let cull = match f[5] {
            "on" => true,
            "off" => false,
            other => {
                return Err(Error::input(
                    at,
                    format!("cull '{other}' is neither on nor off"),
                ));
            }
        };
        let range = match f[6] {
            "inf" => None,
            _ => Some(num(6)?).filter(|&r| r > 0.0),
        };
        Ok(Self {
            variant: f[0].to_string(),
            alpha: num(1)?,
            lights: int(2)?,
            width: int(3)?,
            height: int(4)?,
            cull,
            range,
            ms_median: time(7)?,
            rel_rmse: num(9)?,
            max_rel_err: num(10)?,
            p99_rel_err: num(11)?,
        })
    }
}

/// The study scene: paper-100's plane, material and light distribution with `lights`
/// generated lights (100 gives paper-100's own) at `heights` and GGX α = `alpha`, seen from
/// above so that every pixel shades the plane.
pub fn study_scene(lights: usize, alpha: f64, range: Option<f64>, heights: [f64; 2]) -> Scene {
    let mut scene = crate::measure::bench::bench_scene_at(lights, range, heights);
    scene.material.alpha = alpha;
    scene
}

/// The most bytes of a `study.csv` this program reads (`files::read_text`): a study's row is
/// ~200 bytes, and a study of every method at a hundred light counts is some 20 kB.
pub const MAX_FILE_BYTES: u64 = 16 << 20;

/// Reads `study.csv`; errors name the file and line.
pub fn read_csv(path: &std::path::Path) -> Result<Vec<StudyRow>> {
    let text = crate::files::read_text(path, MAX_FILE_BYTES)?;
    parse_csv(&text, &path.display().to_string())
}

/// A `study.csv`'s text (`name` for errors); lines starting with `#` are comments (the
/// bundled reference study states its device and size in them).
pub fn parse_csv(text: &str, name: &str) -> Result<Vec<StudyRow>> {
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim_start().starts_with('#'));
    match lines.next() {
        Some((_, h)) if h.trim() == StudyRow::CSV_HEADER => {}
        other => {
            return Err(Error::input(
                format!("{name} line {}", other.map_or(1, |(k, _)| k + 1)),
                format!("the header must be '{}'", StudyRow::CSV_HEADER),
            ));
        }
    }
    lines
        .filter(|(_, l)| !l.trim().is_empty())
        .map(|(k, l)| StudyRow::parse(l, &format!("{name} line {}", k + 1)))
        .collect()
}

/// What the study measures.
#[derive(Clone, Debug, PartialEq)]
pub struct StudySettings {
    pub size: (usize, usize),
    pub lights: Vec<usize>,
    pub alphas: Vec<f64>,
    pub frames: usize,
    /// Culling off, on, or both (the same images: only the times differ).
    pub culls: Vec<bool>,
    pub range: Option<f64>,
    /// The remedies whose variants run (eq30's always do).
    pub horizons: Vec<Horizon>,
    /// Only these point variants (of the generated lights and of a scene's points), beside
    /// the reference (`REFERENCE`); every one where `None`.
    pub only: Option<Vec<&'static str>>,
    /// The lights' heights above the plane (paper-100's, or a scene whose lights sit low).
    pub heights: [f64; 2],
    /// Also every light a light of each of these shapes of that size (`ShapeKind::bench_shape`:
    /// a rect a square facing the plane, a disk facing it…), by each of the shape's methods
    /// against its exact integral (variants `<shape>-<method>`).
    pub sizes: Vec<(ShapeKind, f64)>,
    /// Also this method file, on the points (variant `file`) and on each sized shape of the
    /// study it shades (`rect-file`, `disk-file`…), timed with wgpu's runtime checks (its own
    /// renderer: a file is not trusted) and measured against the same exact images.
    pub method_file: Option<MethodFile>,
    /// Scenes studied as given, by name (`study --scene FILE`, and each sized shape's failure
    /// preset beside its generated lights): every method of each shape they hold against
    /// their exact image (`scene_study`).
    pub scenes: Vec<(String, Scene)>,
    /// Table encodings, each a variant `ltc-table-NAME` on the generated lights: `ltc` with
    /// the shipped table as the encoding gives it back, so that every encoding's time and
    /// error come from one run beside `ltc`'s.
    pub encodings: Vec<Encoding>,
}

/// The renderers of a study: one per table its variants shade with, and the method file's.
pub(crate) struct Renderers {
    pub by_lut: Vec<(LutChoice, PlaneRenderer)>,
    pub file: Option<(crate::gpu::method_file::Shades, PlaneRenderer)>,
}

impl Renderers {
    /// The renderer of the table `lut` (made for every variant's table).
    pub fn of(&mut self, lut: LutChoice) -> &mut PlaneRenderer {
        &mut self
            .by_lut
            .iter_mut()
            .find(|(c, _)| *c == lut)
            .expect("made for every variant's table")
            .1
    }
}

/// A sized variant set: the shape, its scene (the study's lights as that shape) and its
/// methods by name.
type SizedVariants = (ShapeKind, Scene, Vec<(String, ShapeMethods)>);

/// The sized variants of a study: each shape asked for, its scene and its methods by name,
/// the exact one first (each shape's reference, error 0), the points by ltc-fast.
fn sized_variants(s: &StudySettings, scene: &Scene) -> Vec<SizedVariants> {
    let a = RenderSettings::single(1, 1, Method::LtcFast).a;
    s.sizes
        .iter()
        .map(|&(kind, size)| {
            let methods = ShapeMethod::all(kind)
                .into_iter()
                .map(|m| (format!("{}-{}", kind.name(), m.name()), a.with(m)))
                .collect();
            (kind, sized_scene(kind, scene, size), methods)
        })
        .collect()
}

/// The heights of the study's scene whose lights sit low: most pixels see most of their
/// lights within 15° of the horizon (a light 0.15 up is 15° above a pixel 0.56 away).
pub const LOW_HEIGHTS: [f64; 2] = [0.02, 0.15];

/// A study begun: the variants this device runs and the renderers of their tables (fitted
/// once for the generated lights and the scenes as given, `scene_study`).
pub struct Study {
    pub(crate) variants: Vec<Variant>,
    pub(crate) renderers: Renderers,
}

impl Study {
    /// The variants of `s` this device runs, and their renderers.
    pub fn new(ctx: &GpuContext, shipped: &Lut, s: &StudySettings) -> Result<Self> {
        crate::measure::bench::check(ctx, &s.lights, s.size)?;
        // The variants shade points: with no generated lights and no point in a scene as
        // given, none runs, and their tables (two of them fitted, seconds each) are not made.
        let points = |scene: &Scene| {
            scene
                .lights
                .iter()
                .any(|l| l.shape.kind() == ShapeKind::Point)
        };
        let shaded = !s.lights.is_empty() || s.scenes.iter().any(|(_, scene)| points(scene));
        let variants: Vec<Variant> = if shaded { variants() } else { Vec::new() }
            .into_iter()
            .filter(|v| !v.method.needs_f16() || ctx.has_f16())
            .filter(|v| v.horizon == Horizon::Eq30 || s.horizons.contains(&v.horizon))
            .filter(|v| v.name == REFERENCE || s.only.as_ref().is_none_or(|o| o.contains(&v.name)))
            .collect();
        let mut renderers: Vec<(LutChoice, PlaneRenderer)> = Vec::new();
        // The scenes as given shade sized lights with the shipped table too.
        let encoded = s.encodings.iter().map(|&e| LutChoice::Encoded(e));
        let tables = variants.iter().map(|v| v.lut).chain([LutChoice::Shipped]);
        let tables = tables.chain(encoded);
        for lut in tables {
            if renderers.iter().any(|(c, _)| *c == lut) {
                continue;
            }
            let choice = lut;
            let lut = match choice {
                LutChoice::Shipped => shipped.clone(),
                LutChoice::Point => Lut::embedded_point().clone(),
                LutChoice::Arrival => Lut::shipped(Table::Arrival).clone(),
                LutChoice::Constrained => Lut::shipped(Table::Constrained).clone(),
                LutChoice::Encoded(e) => e.decoded(shipped),
                LutChoice::Fitted(size) => {
                    fit_table(
                        &FitSettings {
                            size,
                            ..FitSettings::default()
                        },
                        &|| {},
                    )
                    .lut
                }
            };
            renderers.push((
                choice,
                PlaneRenderer::new(ctx, &lut, ShaderChecks::Trusted)?,
            ));
        }
        let file_renderer = match &s.method_file {
            Some(f) => {
                let mut r = PlaneRenderer::new(ctx, shipped, ShaderChecks::Checked)?;
                r.set_method_file(ctx, Some(f.clone()))?;
                Some((ShapeKind::ALL.map(|k| f.shades(k)), r))
            }
            None => None,
        };
        Ok(Self {
            variants,
            renderers: Renderers {
                by_lut: renderers,
                file: file_renderer,
            },
        })
    }

    /// The rows of the generated lights: for each α, light count and culling, the exact image,
    /// then every variant, each timed and measured against it.
    pub fn generated(
        &mut self,
        ctx: &GpuContext,
        s: &StudySettings,
        progress: &mut impl FnMut(&StudyRow),
    ) -> Result<Vec<StudyRow>> {
        let (width, height) = s.size;
        let (variants, r) = (&self.variants, &mut self.renderers);
        let mut rows = Vec::new();
        for &alpha in &s.alphas {
            for &lights in &s.lights {
                let scene = study_scene(lights, alpha, s.range, s.heights);
                for &cull in &s.culls {
                    let mut exact = None;
                    for v in variants {
                        let renderer = r.of(v.lut);
                        let settings = v.settings(cull, s.size);
                        let (ms, image) = timed(ctx, renderer, &scene, &settings, s.frames)?;
                        let reference = exact.get_or_insert_with(|| image.clone());
                        let row = row(v.name, (alpha, lights, cull), s, ms, &image, reference);
                        progress(&row);
                        rows.push(row);
                    }
                    // Each encoding of the table, shaded as `ltc` is.
                    for &e in &s.encodings {
                        let settings = LTC.settings(cull, s.size);
                        let renderer = r.of(LutChoice::Encoded(e));
                        let (ms, image) = timed(ctx, renderer, &scene, &settings, s.frames)?;
                        let Some(reference) = &exact else { break };
                        let name = encoded_variant(e);
                        let row = row(&name, (alpha, lights, cull), s, ms, &image, reference);
                        progress(&row);
                        rows.push(row);
                    }
                    if let (Some((shades, fr)), Some(reference)) = (&mut r.file, &exact)
                        && shades[0]
                    {
                        let settings = RenderSettings {
                            cull,
                            ..RenderSettings::single(width, height, Method::File)
                        };
                        let (ms, image) = timed(ctx, fr, &scene, &settings, s.frames)?;
                        let row = row("file", (alpha, lights, cull), s, ms, &image, reference);
                        progress(&row);
                        rows.push(row);
                    }
                    // The lights with a size, each shape against its own exact image.
                    for (kind, shaped, methods) in sized_variants(s, &scene) {
                        let mut exact = None;
                        for (name, a) in methods {
                            let settings = RenderSettings {
                                cull,
                                a,
                                ..RenderSettings::single(width, height, Method::LtcFast)
                            };
                            let renderer = r.of(LutChoice::Shipped);
                            let (ms, image) = timed(ctx, renderer, &shaped, &settings, s.frames)?;
                            let reference = exact.get_or_insert_with(|| image.clone());
                            let row = row(&name, (alpha, lights, cull), s, ms, &image, reference);
                            progress(&row);
                            rows.push(row);
                        }
                        // The method file on this shape, where it shades it.
                        if let (Some((shades, fr)), Some(reference)) = (&mut r.file, &exact)
                            && shades[kind.index()]
                        {
                            let settings = RenderSettings {
                                cull,
                                ..RenderSettings::single(width, height, Method::File)
                            };
                            let (ms, image) = timed(ctx, fr, &shaped, &settings, s.frames)?;
                            let name = format!("{}-file", kind.name());
                            let row = row(&name, (alpha, lights, cull), s, ms, &image, reference);
                            progress(&row);
                            rows.push(row);
                        }
                    }
                }
            }
        }
        Ok(rows)
    }
}

/// One render of `scene` timed: the median GPU ms of `frames` after one warm-up, and its image.
pub(crate) fn timed(
    ctx: &GpuContext,
    renderer: &mut PlaneRenderer,
    scene: &Scene,
    settings: &RenderSettings,
    frames: usize,
) -> Result<(f64, Frame)> {
    let mut render = renderer.begin(ctx, scene, settings, None)?;
    render.run(ctx, &mut |_| {})?;
    let mut ms: Vec<f64> = (0..frames.max(1))
        .map(|_| render.run(ctx, &mut |_| {}).map(|t| t.total_ms()))
        .collect::<Result<_>>()?;
    ms.sort_by(f64::total_cmp);
    Ok((ms[ms.len() / 2], render.read(ctx)?))
}

/// The row of a variant's render: its time and its image's error against `reference`.
pub(crate) fn row(
    variant: &str,
    (alpha, lights, cull): (f64, usize, bool),
    s: &StudySettings,
    ms_median: f64,
    image: &Frame,
    reference: &Frame,
) -> StudyRow {
    let e = image_error(image, reference);
    StudyRow {
        variant: variant.into(),
        alpha,
        lights,
        width: s.size.0,
        height: s.size.1,
        cull,
        range: s.range,
        ms_median,
        rel_rmse: e.rel_rmse,
        max_rel_err: e.max_rel,
        p99_rel_err: e.p99_rel,
    }
}

/// The rows as CSV text.
pub fn csv(rows: &[StudyRow]) -> String {
    let mut out = format!("{}\n", StudyRow::CSV_HEADER);
    for r in rows {
        out.push_str(&r.csv());
        out.push('\n');
    }
    out
}

/// The Pareto chart as PNG bytes: every row as a faint marker, the case closest to
/// paper-100 (100 lights, α = 0.27) as one large labelled marker per variant; `scene` names the
/// light set in the title (paper-100, or the low-lights scene).
pub fn pareto_png(rows: &[StudyRow], device: &str, scene: &str) -> Result<Vec<u8>> {
    let key =
        |r: &StudyRow| ((r.lights as f64).ln() - 100f64.ln()).abs() + (r.alpha - 0.27).abs() * 10.0;
    let best = rows.iter().map(key).fold(f64::INFINITY, f64::min);
    let (lights, alpha) = rows
        .iter()
        .find(|r| key(r) == best)
        .map_or((0, 0.0), |r| (r.lights, r.alpha));
    let points: Vec<crate::plot::ParetoPoint> = rows
        .iter()
        .map(|r| crate::plot::ParetoPoint {
            label: r.variant.clone(),
            ms: r.ms_median,
            error: r.rel_rmse,
            highlight: r.lights == lights && r.alpha == alpha,
        })
        .collect();
    let size = rows.first().map_or((0, 0), |r| (r.width, r.height));
    crate::plot::pareto_png(
        "study.png",
        &format!(
            "{scene}: {lights} lights, α = {alpha} (large); all cases (small) — {}×{} on {device}",
            size.0, size.1
        ),
        &points,
    )
}
