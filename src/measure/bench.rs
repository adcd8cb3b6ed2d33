//! The paper's Table 1 on this machine's GPU: GPU time per frame of every method at several
//! light counts, culled and not, measured in one run, with the ratios between the LTC and
//! BRDF forms and the fraction of lights in range of a pixel (the best culling can do).

use glam::DVec3;

use crate::error::Result;
use crate::gpu::GpuContext;
use crate::gpu::method_file::MethodFile;
use crate::gpu::plane::ShaderChecks;
use crate::gpu::renderer::PlaneRenderer;
use crate::gpu::timing::FrameTimes;
use crate::light::ShapeKind;
use crate::ltc::lut::Lut;
use crate::ltc::remedy::Horizon;
use crate::render::{LtcRules, Method, RenderSettings, ShapeMethod, ShapeMethods};
use crate::scene::{RandomLights, Scene, generate_lights, preset};

/// The paper's Table 1 (GTX 1060, its resolution unstated): fps at 100, 500, 1000, 5000
/// lights.
pub const PAPER_LIGHTS: [usize; 4] = [100, 500, 1000, 5000];
pub const PAPER_BRDF_FPS: [f64; 4] = [118.0, 23.0, 12.0, 2.0];
pub const PAPER_LTC_FPS: [f64; 4] = [285.0, 56.0, 28.0, 5.0];

/// The range of the benchmark's lights unless `--range` says otherwise: paper-100's.
pub const DEFAULT_RANGE: f64 = crate::scene::PAPER_RANGE;

/// What shape every light of a run had, and how it was shaded: points by the run's point
/// method, or every light of one shape with a size by one of its methods.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Sizing {
    Point,
    /// Every light of the method's shape, by it.
    Shape(ShapeMethod),
    /// Every light of this shape (with a size), shaded by the method file.
    File(ShapeKind),
}

impl Sizing {
    /// The shape, as the CSV's `shape` column writes it.
    pub fn shape_name(self) -> &'static str {
        self.kind().name()
    }

    /// The lights' shape.
    pub fn kind(self) -> ShapeKind {
        match self {
            Self::Point => ShapeKind::Point,
            Self::Shape(m) => m.kind(),
            Self::File(kind) => kind,
        }
    }

    /// The shape's method, as the CSV's `shape_method` column writes it (empty for points:
    /// the row's `method`).
    pub fn method_name(self) -> &'static str {
        match self {
            Self::Point => "",
            Self::Shape(m) => m.name(),
            Self::File(_) => "file",
        }
    }
}

/// The lights of `points` as lights of `kind` of this size (`--size-for`:
/// `ShapeKind::bench_shape`; a point's are `points`).
pub fn sized_scene(kind: ShapeKind, points: &Scene, size: f64) -> Scene {
    let mut sized = points.clone();
    if kind != ShapeKind::Point {
        for l in &mut sized.lights {
            l.shape = kind.bench_shape(size);
        }
    }
    sized
}

/// The symbol of a size of `kind` in a row's label: a radius, or a rect's half-edge.
pub fn size_symbol(kind: ShapeKind) -> &'static str {
    kind.size_symbol()
}

/// The lights of `kind` the benchmark times, in words (its sized table's title).
pub fn sized_title(kind: ShapeKind, size: f64) -> String {
    kind.bench_title(size)
}

/// One measured cell of the table.
#[derive(Clone, Debug, PartialEq)]
pub struct BenchRow {
    pub method: Method,
    /// How every light was shaped and shaded (`Sizing::Point`: as points, by `method`).
    pub sizing: Sizing,
    /// The lights' size: a sphere's radius, a square rect's half-edge (0: points).
    pub size: f64,
    /// The horizon remedy the LTC methods shaded with (eq30 for the BRDF forms).
    pub horizon: Horizon,
    pub lights: usize,
    pub width: usize,
    pub height: usize,
    pub frames: usize,
    pub cull: bool,
    /// Every light's range (`None`: infinite).
    pub range: Option<f64>,
    /// The mean fraction of lights within range of a pixel: the least any culling must sum.
    pub in_range_fraction: f64,
    /// Per frame: binning (culled) plus shading.
    pub ms_median: f64,
    pub ms_min: f64,
    pub ms_max: f64,
    /// The binning's share of the median frame (culled frames with timestamps).
    pub bin_ms_median: Option<f64>,
    /// The material's α_y where it was anisotropic (α_x the bench scene's α), shaded from
    /// the 4D table; `None`: isotropic, the 2D table.
    pub alpha_y: Option<f64>,
}

impl BenchRow {
    pub fn fps(&self) -> f64 {
        1e3 / self.ms_median
    }

    /// Light-pixel evaluations per second, in billions, counting every light at every pixel
    /// (as unculled shading does them), so that culled and unculled rates compare.
    pub fn glightpx_per_s(&self) -> f64 {
        (self.lights * self.width * self.height) as f64 / (self.ms_median * 1e-3) / 1e9
    }

    pub const CSV_HEADER: &'static str = "method,horizon,lights,width,height,frames,cull,range,in_range_fraction,ms_median,ms_min,ms_max,bin_ms,fps,glightpx_per_s,shape,shape_method,size,alpha_y";

    pub fn csv(&self) -> String {
        format!(
            "{},{},{},{},{},{},{},{},{:.6},{:.6},{:.6},{:.6},{},{:.3},{:.3},{},{},{},{}",
            self.method.name(),
            self.horizon.name(),
            self.lights,
            self.width,
            self.height,
            self.frames,
            if self.cull { "on" } else { "off" },
            range_text(self.range),
            self.in_range_fraction,
            self.ms_median,
            self.ms_min,
            self.ms_max,
            self.bin_ms_median
                .map_or(String::new(), |b| format!("{b:.6}")),
            self.fps(),
            self.glightpx_per_s(),
            self.sizing.shape_name(),
            self.sizing.method_name(),
            self.size,
            self.alpha_y.map_or(String::new(), |a| a.to_string())
        )
    }

    /// The method as the table names it: the sphere method and radius, the rect method and
    /// half-edge, or the point method with its remedy.
    pub fn label(&self) -> String {
        let label = self.material_free_label();
        match self.alpha_y {
            Some(a) => format!("{label}, α_y = {a}"),
            None => label,
        }
    }

    fn material_free_label(&self) -> String {
        match (self.sizing, self.horizon) {
            // A sphere's rows came first, when every light with a size was one: unprefixed.
            (Sizing::Shape(m), _) if m.kind() == ShapeKind::Sphere => {
                format!("{} (r = {})", m.name(), self.size)
            }
            (Sizing::Shape(m), _) => {
                let kind = m.kind();
                let symbol = size_symbol(kind);
                format!("{} {} ({symbol} = {})", kind.name(), m.name(), self.size)
            }
            (Sizing::File(kind), _) => format!("{} file (size {})", kind.name(), self.size),
            (Sizing::Point, Horizon::Eq30) => self.method.name().to_string(),
            (Sizing::Point, h) => format!("{} ({})", self.method.name(), h.name()),
        }
    }
}

/// A range as the CSV and the table write it.
pub fn range_text(range: Option<f64>) -> String {
    range.map_or("inf".into(), |r| r.to_string())
}

/// The benchmark scene: paper-100's material (α = 0.27) and light distribution, seen from
/// above a plane large enough that every pixel shades it, so that light-pixels = lights ×
/// width × height; every light of range `range`.
pub fn bench_scene(lights: usize, range: Option<f64>) -> Scene {
    bench_scene_at(lights, range, PAPER_HEIGHTS)
}

/// paper-100's light heights above the plane.
pub const PAPER_HEIGHTS: [f64; 2] = [0.05, 0.6];

/// `bench_scene` with the lights' heights drawn from `height` instead of paper-100's.
pub fn bench_scene_at(lights: usize, range: Option<f64>, height: [f64; 2]) -> Scene {
    let mut scene = preset("paper-100");
    let spread = scene.plane.half_size;
    scene.plane.half_size = 1e3;
    scene.camera.position = [0.0, -2.0, 2.5];
    scene.camera.target = [0.0, 0.0, 0.0];
    scene.lights = generate_lights(
        &RandomLights {
            count: lights,
            seed: 27,
            height,
            intensity: [0.02, 0.08],
            range,
            radius: 0.0,
        },
        spread,
    );
    scene
}

/// Pixels between the samples of `in_range_fraction`, each way: 1/64 of a 1920×1080 frame
/// (32 400 pixels) already pins the mean to ~0.5% of itself.
const FRACTION_STRIDE: usize = 8;

/// The mean over the plane's pixels of the fraction of lights whose range reaches them (an
/// infinite range reaches every pixel), on every `FRACTION_STRIDE`-th pixel each way.
pub fn in_range_fraction(scene: &Scene, width: usize, height: usize) -> f64 {
    if scene.lights.is_empty() {
        return 0.0;
    }
    let (mut sum, mut count) = (0.0, 0usize);
    for y in (FRACTION_STRIDE / 2..height).step_by(FRACTION_STRIDE) {
        for x in (FRACTION_STRIDE / 2..width).step_by(FRACTION_STRIDE) {
            let Some(p) = scene.surface_point(x, y, width, height) else {
                continue;
            };
            let reached = scene
                .lights
                .iter()
                .filter(|l| {
                    l.range
                        .is_none_or(|r| DVec3::from(l.position).distance(p.position) < r)
                })
                .count();
            sum += reached as f64 / scene.lights.len() as f64;
            count += 1;
        }
    }
    if count > 0 { sum / count as f64 } else { 0.0 }
}

/// Median of a non-empty sample.
fn median(xs: &mut [f64]) -> f64 {
    xs.sort_by(f64::total_cmp);
    let n = xs.len();
    if n % 2 == 1 {
        xs[n / 2]
    } else {
        0.5 * (xs[n / 2 - 1] + xs[n / 2])
    }
}

/// Frames shaded before timing starts (pipeline compilation, caches, clocks).
pub const WARM_UP_FRAMES: usize = 5;

/// Every light count and the size against the adapter's limits: nothing is measured for a
/// run that cannot finish (`study` checks the same).
pub fn check(
    ctx: &GpuContext,
    light_counts: &[usize],
    (width, height): (usize, usize),
) -> crate::gpu::limits::Result<()> {
    for &n in light_counts {
        PlaneRenderer::check_light_count(ctx, n)?;
    }
    crate::gpu::target::check_size(ctx, width, height)
}

/// What `run` measures.
#[derive(Clone, Debug, PartialEq)]
pub struct BenchSettings {
    pub lights: Vec<usize>,
    pub size: (usize, usize),
    pub frames: usize,
    pub checks: ShaderChecks,
    /// Culling off, on, or both.
    pub culls: Vec<bool>,
    pub range: Option<f64>,
    /// The horizon remedies each LTC method is measured with (the f16 forms: eq30 only).
    pub horizons: Vec<Horizon>,
    /// Also every light as a light of each of these shapes (at most one size each, a shape
    /// with a size), of that size (`ShapeKind::bench_shape`), by each of its methods.
    pub sizes: Vec<(ShapeKind, f64)>,
    /// Leave out the sized lights' exact methods (the reference, not a real-time method).
    pub skip_exact: bool,
    /// Also time this method file, on every shape of the run it shades; every method of
    /// the run is then timed with wgpu's runtime checks (a file is not trusted).
    pub method_file: Option<MethodFile>,
    /// Also time every run with the material anisotropic, of this α_y (α_x the scene's α),
    /// right after the same run isotropic.
    pub alpha_y: Option<f64>,
    /// A scene as given (`bench --scene FILE`) in place of the generated lights: its lights,
    /// their shapes (each point method's rows shade its sized lights by the lab's default
    /// method of their shape), its camera and material.
    pub scene: Option<Scene>,
}

impl BenchSettings {
    /// The size every light of `kind` is timed at, where it is (0 for points).
    pub fn size_of(&self, kind: ShapeKind) -> Option<f64> {
        match kind {
            ShapeKind::Point => Some(0.0),
            _ => self.sizes.iter().find(|(k, _)| *k == kind).map(|&(_, s)| s),
        }
    }
}

/// The methods this device runs: the f32 four, and the f16 ones where it has f16 shaders.
pub fn methods(ctx: &GpuContext) -> Vec<Method> {
    let f16 = if ctx.has_f16() { &Method::F16[..] } else { &[] };
    Method::F32.iter().chain(f16).copied().collect()
}

/// The methods and remedies of one light count and culling: each BRDF form once with eq30,
/// each f32 LTC form with eq30 (the reference every remedy is divided by) and then each
/// other remedy, the f16 forms with eq30 alone.
pub fn runs(ctx: &GpuContext, horizons: &[Horizon]) -> Vec<(Method, Horizon)> {
    let mut runs = Vec::new();
    for m in methods(ctx) {
        runs.push((m, Horizon::Eq30));
        if m.is_ltc() && !m.needs_f16() {
            for &h in horizons {
                if !runs.contains(&(m, h)) {
                    runs.push((m, h));
                }
            }
        }
    }
    runs
}

/// What one timed run shades: a point method with its remedy, and the lights' shape and
/// its method.
type Run = (Method, Horizon, Sizing);

/// `runs`, then each sphere method where the lights are spheres and each rect method where
/// they are rects (on ltc-fast's sums, the form an engine ships; a sized light's cost does
/// not depend on the point method).
fn all_runs(ctx: &GpuContext, s: &BenchSettings) -> Vec<Run> {
    let points = runs(ctx, &s.horizons)
        .into_iter()
        .map(|(m, h)| (m, h, Sizing::Point));
    let sized = ShapeKind::sized()
        .filter(|&k| s.size_of(k).is_some())
        .flat_map(ShapeMethod::all)
        .map(|m| (Method::LtcFast, Horizon::Eq30, Sizing::Shape(m)));
    let exact = |r: &Run| matches!(r.2, Sizing::Shape(m) if m == ShapeMethod::reference(m.kind()));
    let file = s.method_file.iter().flat_map(|f| {
        ShapeKind::ALL
            .into_iter()
            .filter(move |&k| f.shades(k) && s.size_of(k).is_some())
            .map(|k| {
                let sizing = match k {
                    ShapeKind::Point => Sizing::Point,
                    _ => Sizing::File(k),
                };
                (Method::File, Horizon::Eq30, sizing)
            })
    });
    points
        .chain(sized)
        .chain(file)
        .filter(|r| !(s.skip_exact && exact(r)))
        .collect()
}

/// `base` with a run's sized method, where it times one.
fn shaded_as(sizing: Sizing, base: ShapeMethods) -> ShapeMethods {
    match sizing {
        Sizing::Shape(m) => base.with(m),
        Sizing::Point | Sizing::File(_) => base,
    }
}

/// `scene` with every light a square rect of half-edge `h` facing down onto the plane.
pub fn as_rects(scene: &Scene, h: f64) -> Scene {
    sized_scene(ShapeKind::Rect, scene, h)
}

/// `scene` with every light a disk of radius `r` facing down onto the plane.
pub fn as_disks(scene: &Scene, r: f64) -> Scene {
    sized_scene(ShapeKind::Disk, scene, r)
}

/// Measures every method (and remedy) at every light count and culling: `frames` timed
/// frames after warm-up each.
pub fn run(
    ctx: &GpuContext,
    lut: &Lut,
    s: &BenchSettings,
    mut progress: impl FnMut(&BenchRow),
) -> Result<Vec<BenchRow>> {
    let counts = match &s.scene {
        Some(scene) => vec![scene.lights.len()],
        None => s.lights.clone(),
    };
    check(ctx, &counts, s.size)?;
    let (width, height) = s.size;
    let mut renderer = PlaneRenderer::new(ctx, lut, s.checks)?;
    renderer.set_method_file(ctx, s.method_file.clone())?;
    let mut rows = Vec::new();
    let mut kept = None;
    // Sized lights of a scene as given keep their shape in the point methods' rows.
    let defaults = RenderSettings::single(1, 1, Method::Ltc).a;
    // Generated lights: the shapes not timed in a row shade as their centres (none is there).
    let as_points = ShapeKind::sized().fold(ShapeMethods::approximations(), |a, k| {
        a.with(ShapeMethod::at_centre(k))
    });
    let given = s.scene.is_some();
    for &lights in &counts {
        let points = s
            .scene
            .clone()
            .unwrap_or_else(|| bench_scene(lights, s.range));
        let fraction = in_range_fraction(&points, width, height);
        let shaped: Vec<(ShapeKind, f64, Scene)> = ShapeKind::sized()
            .filter_map(|k| {
                s.size_of(k)
                    .map(|size| (k, size, sized_scene(k, &points, size)))
            })
            .collect();
        for &cull in &s.culls {
            let materials = std::iter::once(None).chain(s.alpha_y.map(Some));
            let runs = all_runs(ctx, s).into_iter();
            let runs: Vec<_> = runs
                .flat_map(|r| materials.clone().map(move |m| (r, m)))
                .collect();
            for ((method, horizon, sizing), alpha_y) in runs {
                let (scene, size) = match shaped.iter().find(|(k, ..)| *k == sizing.kind()) {
                    Some((_, size, scene)) => (scene, *size),
                    None => (&points, 0.0),
                };
                let table = horizon.table().map_or(lut, |t| Lut::shipped(t));
                renderer.set_tables(ctx, table, None)?;
                let settings = RenderSettings {
                    cull,
                    rules: LtcRules {
                        horizon: horizon.rule(),
                        ..LtcRules::default()
                    },
                    a: shaded_as(sizing, if given { defaults } else { as_points }).with(method),
                    ..RenderSettings::single(width, height, method)
                };
                let mut brushed;
                let scene = match alpha_y {
                    Some(_) => {
                        brushed = scene.clone();
                        brushed.material.alpha_y = alpha_y;
                        &brushed
                    }
                    None => scene,
                };
                let mut render = renderer.begin(ctx, scene, &settings, kept.take())?;
                for _ in 0..WARM_UP_FRAMES {
                    render.run(ctx, &mut |_| {})?;
                }
                let times: Vec<FrameTimes> = (0..s.frames)
                    .map(|_| render.run(ctx, &mut |_| {}))
                    .collect::<Result<_>>()?;
                kept = Some(render.into_kept());
                let mut ms: Vec<f64> = times.iter().map(FrameTimes::total_ms).collect();
                let mut bins: Vec<f64> = times.iter().filter_map(|t| t.bin_ms).collect();
                let row = BenchRow {
                    method,
                    sizing,
                    size,
                    horizon,
                    lights,
                    width,
                    height,
                    frames: s.frames,
                    cull,
                    range: s.range,
                    in_range_fraction: fraction,
                    ms_min: ms.iter().copied().fold(f64::INFINITY, f64::min),
                    ms_max: ms.iter().copied().fold(0.0, f64::max),
                    ms_median: median(&mut ms),
                    bin_ms_median: (!bins.is_empty()).then(|| median(&mut bins)),
                    alpha_y,
                };
                progress(&row);
                rows.push(row);
            }
        }
    }
    Ok(rows)
}
