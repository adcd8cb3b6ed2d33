//! The plane's renderer: what is kept between renders on one device — the plane shader's
//! pipelines, the binning passes and the tables' buffer — and the checks a render must pass
//! before it begins. A render begun (`begin`) is a `PlaneRender` of its own, which holds all
//! it needs; one that is over leaves its buffers to the next (`PlaneRender::into_kept`).

use crate::error::{Error, Result};
use crate::gpu::GpuContext;
use crate::gpu::bin::Binning;
use crate::gpu::limits;
use crate::gpu::ltc::LutBuffer;
use crate::gpu::method_file::MethodFile;
use crate::gpu::plane::{PlanePipelines, ShaderChecks, pipeline_key};
use crate::gpu::plane_render::{Begun, Kept, PlaneRender, RunProgress};
use crate::gpu::scene::GpuLight;
use crate::gpu::target;
use crate::ltc::lut::Lut;
use crate::ltc::remedy::HorizonRule;
use crate::render::{Frame, Method, RenderSettings};
use crate::scene::Scene;

pub struct PlaneRenderer {
    pipelines: PlanePipelines,
    /// Whether its module (without a method file) is built with runtime checks.
    checks: ShaderChecks,
    binning: Binning,
    tables: LutBuffer,
    /// Whether the module has the f16 methods (the device has `SHADER_F16`).
    f16: bool,
    /// The buffers of the last render made whole by `render`, for the next.
    spare: Option<Kept>,
}

impl PlaneRenderer {
    /// The module, layouts and table buffer; refused where the LUT exceeds the device's
    /// storage.
    pub fn new(ctx: &GpuContext, lut: &Lut, checks: ShaderChecks) -> Result<Self> {
        Ok(Self {
            pipelines: PlanePipelines::new(ctx, checks)?,
            checks,
            binning: Binning::new(ctx),
            tables: LutBuffer::new(ctx, lut, None)?,
            f16: ctx.has_f16(),
            spare: None,
        })
    }

    /// Renders begun from now on shade with `a` as table A, and `b` as table B where
    /// `RenderSettings::b_reads_table_b` (a render begun before keeps its tables). Both at
    /// once: a new table A must not lose table B.
    pub fn set_tables(&mut self, ctx: &GpuContext, a: &Lut, b: Option<&Lut>) -> Result<()> {
        self.tables = LutBuffer::new(ctx, a, b)?;
        Ok(())
    }

    /// Renders begun from now on shade the method `file` by `file`: the module is built again
    /// with it composed in (with runtime checks), or without one. The same file keeps the
    /// module. Refused where the device cannot run the file (`PlanePipelines::with_file`): the
    /// module it had stays.
    pub fn set_method_file(&mut self, ctx: &GpuContext, file: Option<MethodFile>) -> Result<()> {
        if self.pipelines.file != file {
            self.pipelines = PlanePipelines::with_file(ctx, self.checks, file)?;
        }
        Ok(())
    }

    /// The pixel inspector's values of the method file (docs/design.md §5.13): each light of
    /// `scene` alone at the point `[u, v]` (0–1) of the image `settings` renders, by the side
    /// that shades with the file, evaluated on the GPU; `None` where the point is off the
    /// plane. Made on a small image of the same camera whose sums hold one entry per light.
    /// Blocks (the desktop's inspector).
    pub fn probe_file(
        &mut self,
        ctx: &GpuContext,
        scene: &Scene,
        settings: &RenderSettings,
        [u, v]: [f64; 2],
    ) -> Result<Option<Vec<glam::DVec3>>> {
        if self.pipelines.file.is_none() || !settings.methods().contains(&Method::File) {
            return Err(Error::input(
                "the pixel inspector",
                "no side shades with a method file",
            ));
        }
        let n = scene.lights.len().max(1);
        let aspect = settings.width as f64 / settings.height.max(1) as f64;
        let w = ((n as f64 * aspect).sqrt().ceil() as usize).max(16);
        let h = n
            .div_ceil(w)
            .max((w as f64 / aspect).round() as usize)
            .max(1);
        let small = RenderSettings {
            width: w,
            height: h,
            ..*settings
        };
        let pipeline = self.pipelines.probe(ctx, pipeline_key(&small, scene))?;
        let mut render = self.begin(ctx, scene, &small, None)?;
        let at = [(u * w as f64) as f32, (v * h as f64) as f32];
        render.probe(ctx, &pipeline, at, aspect as f32)
    }

    /// The method file its module holds.
    pub fn method_file(&self) -> Option<&MethodFile> {
        self.pipelines.file.as_ref()
    }

    /// Whether this device can run `method` (`LtcF16` and `LtcF16Pairs` need `SHADER_F16`).
    pub fn supports(&self, method: Method) -> bool {
        !method.needs_f16() || self.f16
    }

    /// The most lights this device shades (`limits::max_lights`).
    pub fn max_lights(ctx: &GpuContext) -> usize {
        limits::max_lights(ctx, std::mem::size_of::<GpuLight>())
    }

    /// Refuses more lights than this device shades.
    pub fn check_light_count(ctx: &GpuContext, count: usize) -> limits::Result<()> {
        limits::check_light_count(ctx, count, std::mem::size_of::<GpuLight>())
    }

    /// Refuses what this device cannot render, before any work: the lights, a method it has
    /// no shaders for, a second table it was not given, the image.
    pub fn check(&self, ctx: &GpuContext, scene: &Scene, settings: &RenderSettings) -> Result<()> {
        // A rect takes two elements of the buffer (`light_elements`): counted as two lights.
        let elements = crate::gpu::scene::element_count(&scene.lights);
        Self::check_light_count(ctx, elements).map_err(|e| e.named("scene"))?;
        if let Some(m) = settings.methods().into_iter().find(|&m| !self.supports(m)) {
            return Err(Error::input(
                m.name(),
                format!("{} has no f16 shaders (SHADER_F16)", ctx.info.name),
            ));
        }
        if settings.methods().contains(&Method::File) && self.pipelines.file.is_none() {
            return Err(Error::input(
                "the method file",
                "the method `file` needs a method file (--method-file)",
            ));
        }
        if settings.b_reads_table_b && self.tables.b.is_none() {
            return Err(Error::input("table B", "no second table was given"));
        }
        let f16 = settings.methods().into_iter().find(|m| m.needs_f16());
        if let Some(m) = f16.filter(|_| settings.rules.horizon != HorizonRule::Eq30) {
            return Err(Error::input(
                "the horizon remedy",
                format!(
                    "{} shades with eq30's rules only (docs/design.md §4.8)",
                    m.name()
                ),
            ));
        }
        Ok(target::check_size(ctx, settings.width, settings.height)?)
    }

    /// Begins a render of `scene`: checked, its pipelines compiled where they are new, in the
    /// buffers `kept` (a render over) leaves where they hold it. Nothing is summed yet.
    pub fn begin(
        &mut self,
        ctx: &GpuContext,
        scene: &Scene,
        settings: &RenderSettings,
        kept: Option<Kept>,
    ) -> Result<PlaneRender> {
        self.check(ctx, scene, settings)?;
        if settings.rules.horizon == HorizonRule::NlFit {
            self.tables.ensure_nl(ctx)?;
        }
        let begun = Begun {
            pipelines: self.pipelines.get(ctx, pipeline_key(settings, scene))?,
            layout: &self.pipelines.layout,
            binning: &self.binning,
            tables: &self.tables,
            file: self.pipelines.file.as_ref().map(|f| f.name.clone()),
            light_work: self.pipelines.light_work,
        };
        Ok(PlaneRender::new(ctx, begun, (scene, settings), kept))
    }

    /// One render whole, its image poisoned first (a pixel no pass writes shows), read back:
    /// the frame and its GPU ms.
    pub fn render(
        &mut self,
        ctx: &GpuContext,
        scene: &Scene,
        settings: &RenderSettings,
    ) -> Result<(Frame, f64)> {
        self.render_with(ctx, scene, settings, &mut |_| {})
    }

    /// `render`, with `progress` hearing each of its submissions done.
    pub fn render_with(
        &mut self,
        ctx: &GpuContext,
        scene: &Scene,
        settings: &RenderSettings,
        progress: &mut dyn FnMut(RunProgress),
    ) -> Result<(Frame, f64)> {
        let spare = self.spare.take();
        let mut render = self.begin(ctx, scene, settings, spare)?;
        render.poison(ctx);
        let times = render.run(ctx, progress)?;
        let frame = render.read(ctx)?;
        self.spare = Some(render.into_kept());
        Ok((frame, times.total_ms()))
    }
}
