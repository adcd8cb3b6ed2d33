//! `shaders/plane.wgsl`: the compute shader that shades the plane. Here its constants and
//! bindings as Rust names them (`tests/shaders/main.rs` checks both against the WGSL), and its
//! pipelines: one per combination of methods, view, table filter, table B, horizon rule and
//! the methods of each shape some light has (override constants), compiled on first use and
//! kept. What a render keeps between its chunks is `gpu::plane_render`; what is kept between
//! renders, `gpu::renderer`.

use std::collections::HashMap;

use crate::error::{Error, Result};
use crate::gpu::GpuContext;
use crate::gpu::binding::{self, Binding, Kind, binding};
use crate::gpu::failures::scoped;
use crate::gpu::light;
use crate::gpu::ltc::horizon_constant;
use crate::gpu::method_file::MethodFile;
use crate::gpu::method_file::device_check::DeviceShaders;
use crate::gpu::target::OUTPUT_FORMAT;
use crate::light::ShapeKind;
use crate::ltc::remedy::HorizonRule;
use crate::render::{LutFilter, Method, RenderSettings, ShapeMethod, ShapeMethods, View};
use crate::scene::Scene;

/// The shader text (composed after `scene::SOURCE`).
pub const SOURCE: &str = include_str!("../../shaders/plane.wgsl");

/// `METHOD_*` of plane.wgsl: its value and its name there.
pub fn method_constant(m: Method) -> (u32, &'static str) {
    match m {
        Method::Brdf => (0, "METHOD_BRDF"),
        Method::BrdfFast => (1, "METHOD_BRDF_FAST"),
        Method::Ltc => (2, "METHOD_LTC"),
        Method::LtcFast => (3, "METHOD_LTC_FAST"),
        Method::LtcF16 => (4, "METHOD_LTC_F16"),
        Method::LtcF16Pairs => (5, "METHOD_LTC_F16_PAIRS"),
        Method::File => (6, "METHOD_FILE"),
    }
}

/// A method's code, whatever its shape: `METHOD_*` of plane.wgsl for a point's, the shape's
/// shader's for a sized shape's (`gpu::light::method_constant`).
pub fn shape_method_constant(m: ShapeMethod) -> (u32, &'static str) {
    light::method_constant(m).unwrap_or_else(method_constant)
}

/// `VIEW_*` of plane.wgsl: method A alone, A | B split, or their difference.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ViewConstant {
    Single,
    Split,
    Diff,
}

impl ViewConstant {
    pub const ALL: [Self; 3] = [Self::Single, Self::Split, Self::Diff];

    /// Its value and its name in plane.wgsl.
    pub fn constant(self) -> (u32, &'static str) {
        match self {
            Self::Single => (0, "VIEW_SINGLE"),
            Self::Split => (1, "VIEW_SPLIT"),
            Self::Diff => (2, "VIEW_DIFF"),
        }
    }
}

/// The bindings of the plane shader (and of scene.wgsl and ltc.wgsl, composed with it).
pub const PARAMS: Binding = binding(0, "params", Kind::Uniform);
pub const LIGHTS: Binding = binding(1, "lights", Kind::Read);
pub const LUT: Binding = binding(2, "lut", Kind::Read);
pub const OUTPUT: Binding = binding(3, "output", Kind::WrittenTexture(OUTPUT_FORMAT));
pub const ACCUM_0: Binding = binding(4, "accum_0", Kind::ReadWrite);
pub const TILE_OFFSETS: Binding = binding(5, "tile_offsets", Kind::Read);
pub const TILE_LIGHTS: Binding = binding(6, "tile_lights", Kind::Read);
pub const PARTIALS: Binding = binding(7, "partials", Kind::ReadWrite);
pub const ACCUM_1: Binding = binding(8, "accum_1", Kind::ReadWrite);
pub const ACCUM_2: Binding = binding(9, "accum_2", Kind::ReadWrite);
pub const BINDINGS: [Binding; 10] = [
    PARAMS,
    LIGHTS,
    LUT,
    OUTPUT,
    ACCUM_0,
    TILE_OFFSETS,
    TILE_LIGHTS,
    PARTIALS,
    ACCUM_1,
    ACCUM_2,
];

/// What a pipeline is specialized for (its override constants): methods A and B, the view,
/// the LUT filter, whether B reads table B, the horizon rule, each sized shape's methods on
/// both sides where some light has that shape (`ShapeSides`), and whether the material is
/// anisotropic.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct PipelineKey {
    pub a: Method,
    pub b: Method,
    pub view: ViewConstant,
    pub filter: LutFilter,
    pub table_b: bool,
    pub horizon: HorizonRule,
    pub shapes: ShapeSides,
    /// The material is anisotropic (docs/design.md §1.13): its tangent frame and 4D table.
    pub aniso: bool,
}

/// Each shape with a size that some light has, with A's and B's methods for it, keyed by
/// `ShapeKind`: a shape no light has is `None`, and the pipeline has none of its code (the
/// point's slot is always `None`: its methods are the key's `a` and `b`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct ShapeSides([Option<(ShapeMethod, ShapeMethod)>; ShapeKind::ALL.len()]);

impl ShapeSides {
    /// The sized shapes among `kinds`, with `(a, b)`'s methods for them.
    pub fn of(
        (a, b): (&ShapeMethods, &ShapeMethods),
        kinds: impl Iterator<Item = ShapeKind>,
    ) -> Self {
        let mut sides = Self::default();
        for kind in kinds.filter(|&k| k != ShapeKind::Point) {
            sides.0[kind.index()] = Some((a.of(kind), b.of(kind)));
        }
        sides
    }

    /// A's and B's methods for `kind`, where some light has it.
    pub fn get(&self, kind: ShapeKind) -> Option<(ShapeMethod, ShapeMethod)> {
        self.0[kind.index()]
    }

    /// Some light has a size.
    pub fn any(&self) -> bool {
        self.0.iter().any(Option::is_some)
    }
}

/// The pipeline's methods and view: `View::B` is B shaded as the single A (with B's table,
/// which the render puts in A's place).
pub fn pipeline_key(s: &RenderSettings, scene: &Scene) -> PipelineKey {
    let (a, b, view, table_b) = match s.view {
        View::A => (s.a.point(), s.b.point(), ViewConstant::Single, false),
        View::B => (s.b.point(), s.b.point(), ViewConstant::Single, false),
        View::Split => (
            s.a.point(),
            s.b.point(),
            ViewConstant::Split,
            s.b_reads_table_b,
        ),
        View::Diff => (
            s.a.point(),
            s.b.point(),
            ViewConstant::Diff,
            s.b_reads_table_b,
        ),
    };
    let sides = match s.view {
        View::B => (&s.b, &s.b),
        _ => (&s.a, &s.b),
    };
    PipelineKey {
        a,
        b,
        view,
        filter: s.rules.filter,
        table_b,
        horizon: s.rules.horizon,
        shapes: ShapeSides::of(sides, scene.lights.iter().map(|l| l.shape.kind())),
        aniso: scene.material.is_anisotropic(),
    }
}

/// Whether wgpu wraps the shader in its runtime bounds checks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShaderChecks {
    /// wgpu's defaults (every render but the benchmark).
    Checked,
    /// Without bounds checks: the benchmark path, as a fast engine would ship (5–17% faster
    /// on the reference GPU, docs/design.md §4.5).
    Trusted,
}

/// The entry points of one specialization.
#[derive(Clone)]
pub struct Pipelines {
    pub shade: wgpu::ComputePipeline,
    pub reduce: wgpu::ComputePipeline,
    pub floor: wgpu::ComputePipeline,
    pub resolve: wgpu::ComputePipeline,
}

/// The plane shader's module and layouts, and every specialization compiled so far.
pub struct PlanePipelines {
    /// The method file composed into the module, if any.
    pub file: Option<MethodFile>,
    /// The estimated operations of one light at one pixel (`work::light_operations`).
    pub light_work: f64,
    module: wgpu::ShaderModule,
    pub layout: wgpu::BindGroupLayout,
    pipeline_layout: wgpu::PipelineLayout,
    compiled: HashMap<PipelineKey, Pipelines>,
    /// The pixel inspector's probe of the method file, per specialization, made on first use.
    probes: HashMap<PipelineKey, wgpu::ComputePipeline>,
}

impl PlanePipelines {
    pub fn new(ctx: &GpuContext, checks: ShaderChecks) -> Result<Self> {
        Self::with_file(ctx, checks, None)
    }

    /// The module with `file` composed into it: always with wgpu's runtime checks, whatever
    /// `checks` says (the text is the user's, not ours), and checked against the device's
    /// capabilities first (`MethodFile::check_for`). What the device refuses of it is the
    /// file's fault (bad input); of the lab's own module, the machine's.
    pub fn with_file(
        ctx: &GpuContext,
        checks: ShaderChecks,
        file: Option<MethodFile>,
    ) -> Result<Self> {
        if let Some(f) = &file {
            f.check_for(&DeviceShaders::of(ctx))?;
        }
        let device = &ctx.device;
        let source = super::plane_module_source_with(ctx.has_f16(), file.as_ref());
        let desc = wgpu::ShaderModuleDescriptor {
            label: Some("plane.wgsl"),
            source: wgpu::ShaderSource::Wgsl(source.into()),
        };
        let checks = if file.is_some() {
            ShaderChecks::Checked
        } else {
            checks
        };
        let (module, error) = scoped(device, || match checks {
            ShaderChecks::Checked => device.create_shader_module(desc),
            // SAFETY: the module is our own embedded WGSL (never a method file's), validated by naga in
            // tests/shaders/main.rs; every buffer index in it is bounded by construction (lights
            // by light_count ≤ the buffer's length, tile lists by their total ≤ the capacity,
            // LUT cells clamped into the table, sums and texture writes guarded by the image
            // size), which is what the runtime checks guard.
            #[allow(unsafe_code)]
            ShaderChecks::Trusted => unsafe {
                device.create_shader_module_trusted(desc, wgpu::ShaderRuntimeChecks::unchecked())
            },
        });
        refused(ctx, file.as_ref(), error)?;
        let layout = binding::layout(device, "plane", &BINDINGS);
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("plane"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let light_work = light_work(file.as_ref())?;
        Ok(Self {
            file,
            light_work,
            module,
            layout,
            pipeline_layout,
            compiled: HashMap::new(),
            probes: HashMap::new(),
        })
    }

    /// The method file's probe (`probe_file` of method_file.wgsl) of a specialization,
    /// compiled on first use.
    pub fn probe(&mut self, ctx: &GpuContext, key: PipelineKey) -> Result<wgpu::ComputePipeline> {
        if let Some(p) = self.probes.get(&key) {
            return Ok(p.clone());
        }
        let (module, layout) = (&self.module, &self.pipeline_layout);
        let (probe, error) = scoped(&ctx.device, || {
            entry_point(ctx, (module, layout), &constants(key), "probe_file")
        });
        refused(ctx, self.file.as_ref(), error)?;
        Ok(self.probes.entry(key).or_insert(probe).clone())
    }

    /// The pipelines of a specialization, compiled on first use (refused as `with_file`'s
    /// module is, where the device refuses them).
    pub fn get(&mut self, ctx: &GpuContext, key: PipelineKey) -> Result<Pipelines> {
        if let Some(p) = self.compiled.get(&key) {
            return Ok(p.clone());
        }
        let (module, layout) = (&self.module, &self.pipeline_layout);
        let (pipelines, error) = scoped(&ctx.device, || compile(ctx, module, layout, key));
        refused(ctx, self.file.as_ref(), error)?;
        Ok(self.compiled.entry(key).or_insert(pipelines).clone())
    }
}

/// The estimated operations of one light at one pixel with `file` (`work::light_operations`;
/// the lab's own module's counted once a process). A count refused is the lab's fault, a
/// file's refused here was checked already: both a failure of the machine.
fn light_work(file: Option<&MethodFile>) -> Result<f64> {
    static LAB: std::sync::OnceLock<std::result::Result<f64, String>> = std::sync::OnceLock::new();
    let counted = match file {
        None => LAB
            .get_or_init(|| crate::gpu::work::light_operations(None))
            .clone(),
        Some(f) => crate::gpu::work::light_operations(Some(f)),
    };
    counted.map_err(|e| {
        Error::machine(
            "the plane shader",
            format!("its work could not be counted: {e}"),
        )
    })
}

/// The device's error of a module or pipeline as an error: the method `file`'s (bad input)
/// where one is composed in, else the machine's.
fn refused(ctx: &GpuContext, file: Option<&MethodFile>, error: Option<wgpu::Error>) -> Result<()> {
    let Some(e) = error else {
        return Ok(());
    };
    let message = format!("{} refused its shader: {e}", ctx.name());
    Err(match file {
        Some(f) => Error::input(&f.name, message),
        None => Error::machine(ctx.name(), message),
    })
}

/// The four entry points of `module` with the override constants of `key`.
fn compile(
    ctx: &GpuContext,
    module: &wgpu::ShaderModule,
    layout: &wgpu::PipelineLayout,
    key: PipelineKey,
) -> Pipelines {
    let constants = constants(key);
    let pipeline = |entry| entry_point(ctx, (module, layout), &constants, entry);
    Pipelines {
        shade: pipeline("shade"),
        reduce: pipeline("reduce"),
        floor: pipeline("floor_of_means"),
        resolve: pipeline("resolve"),
    }
}

/// One entry point of `module` with `constants`.
fn entry_point(
    ctx: &GpuContext,
    (module, layout): (&wgpu::ShaderModule, &wgpu::PipelineLayout),
    constants: &[(&str, f64)],
    entry: &str,
) -> wgpu::ComputePipeline {
    ctx.device
        .create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(entry),
            layout: Some(layout),
            module,
            entry_point: Some(entry),
            compilation_options: wgpu::PipelineCompilationOptions {
                constants,
                zero_initialize_workgroup_memory: false,
            },
            cache: None,
        })
}

/// The override constants of a specialization.
fn constants(key: PipelineKey) -> Vec<(&'static str, f64)> {
    let PipelineKey {
        a,
        b,
        view,
        filter,
        table_b,
        horizon,
        shapes,
        aniso,
    } = key;
    let mut constants = vec![
        ("METHOD_A", f64::from(method_constant(a).0)),
        ("METHOD_B", f64::from(method_constant(b).0)),
        ("VIEW", f64::from(view.constant().0)),
        (
            "LUT_NEAREST",
            f64::from(u8::from(filter == LutFilter::Nearest)),
        ),
        ("TABLE_B", f64::from(u8::from(table_b))),
        ("HORIZON", f64::from(horizon_constant(horizon).0)),
        ("SIZED", f64::from(u8::from(shapes.any()))),
    ];
    for kind in ShapeKind::sized() {
        let names = light::overrides(kind);
        let present = shapes.get(kind);
        // A shape no light has keeps the shader's defaults, the sides' defaults.
        let (ma, mb) = present.unwrap_or((
            ShapeMethod::approximation(kind),
            ShapeMethod::reference(kind),
        ));
        if let Some(flag) = names.present {
            constants.push((flag, f64::from(u8::from(present.is_some()))));
        }
        constants.push((names.a, f64::from(shape_method_constant(ma).0)));
        constants.push((names.b, f64::from(shape_method_constant(mb).0)));
    }
    // Set only where anisotropic: an isotropic pipeline is specialized exactly as before.
    if aniso {
        constants.push(("ANISO", 1.0));
    }
    constants
}
