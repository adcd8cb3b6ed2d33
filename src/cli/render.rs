//! `ltc-lab render`: a scene to PNG (tone-mapped) or EXR (linear radiance), on the GPU or
//! the CPU reference. A default output name never replaces a file.

use std::path::{Path, PathBuf};
use std::time::Instant;

use ltc_lab::cpu;
use ltc_lab::error::{Error, Result, number};
use ltc_lab::files::{Claim, check_writable, write_atomically};
use ltc_lab::gpu::GpuContext;
use ltc_lab::gpu::method_file::MethodFile;
use ltc_lab::gpu::plane::ShaderChecks;
use ltc_lab::gpu::renderer::PlaneRenderer;
use ltc_lab::light::ShapeKind;
use ltc_lab::light::disk::DiskMethod;
use ltc_lab::light::rect::RectMethod;
use ltc_lab::light::sphere::SphereMethod;
use ltc_lab::ltc::aniso::source::AnisoSource;
use ltc_lab::ltc::formats;
use ltc_lab::ltc::lut::{Encoding, Table};
use ltc_lab::ltc::{Clipping, Normalization};
use ltc_lab::output::{ImageFormat, frame_bytes};
use ltc_lab::render::{Frame, Method, RenderSettings, ShapeMethod, View};
use ltc_lab::scene::Scene;
use ltc_lab::tables::{NamedTable, NamedTables, Source};

use super::method_for::{self, MethodFor, Side};
use super::{EncodingArgs, HORIZON_HELP, LutArgs, horizon_parser, one_of, parse_cull, parse_size};
use ltc_lab::ltc::remedy::Horizon;

/// What `--method` names: one method alone, or LTC against the BRDF.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shown {
    Alone(Method),
    Compared(View),
}

impl Shown {
    const ALL: [Self; 9] = [
        Self::Alone(Method::Brdf),
        Self::Alone(Method::BrdfFast),
        Self::Alone(Method::Ltc),
        Self::Alone(Method::LtcFast),
        Self::Alone(Method::LtcF16),
        Self::Alone(Method::LtcF16Pairs),
        Self::Alone(Method::File),
        Self::Compared(View::Split),
        Self::Compared(View::Diff),
    ];

    fn name(self) -> &'static str {
        match self {
            Self::Alone(m) => m.name(),
            Self::Compared(View::Diff) => "diff",
            Self::Compared(_) => "split",
        }
    }

    /// The settings: split and diff compare the literal forms (`ltc` | `brdf`), as the CPU.
    fn settings(self, (w, h): (usize, usize)) -> RenderSettings {
        match self {
            Self::Alone(m) => RenderSettings::single(w, h, m),
            Self::Compared(view) => RenderSettings::compare(w, h, view),
        }
    }
}

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The scene, a TOML file (the presets are in assets/scenes/).
    #[arg(long)]
    scene: PathBuf,
    /// brdf, brdf-fast, ltc, ltc-fast, ltc-f16, ltc-f16-pairs, file (--method-file), split
    /// (LTC | BRDF) or diff (|LTC − BRDF| / BRDF); with --table-b or --lut-b, split and diff
    /// compare two tables; --point-a and --point-b pick other sides. On the CPU the fast
    /// forms are the same math as their literal twins.
    #[arg(long, value_parser = one_of(&Shown::ALL, Shown::name))]
    method: Shown,
    /// Image size, WxH.
    #[arg(long, default_value = "512x512", value_parser = parse_size)]
    size: (usize, usize),
    /// Output file (.png or .exr); default `<scene>-<method>.png`, or the next free
    /// `<scene>-<method>-2.png`…, taken when the render starts: a default name never
    /// replaces a file, and two renders at once never share one.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Render on the CPU (the f64 reference) instead of the GPU.
    #[arg(long)]
    cpu: bool,
    /// Light clipping rules (eq. 30): both, horizon (case 1 only), transformed (case 2
    /// only) or none.
    #[arg(long, value_parser = one_of(&Clipping::ALL, Clipping::name), default_value = "both")]
    clip: Clipping,
    /// corrected (docs/design.md §1) or paper (eq. 25 as printed: no 1/π, no magnitudes).
    #[arg(long, value_parser = one_of(&Normalization::ALL, Normalization::name), default_value = "corrected")]
    normalization: Normalization,
    /// Where the split view changes from LTC (left) to BRDF (right), 0–1 of the width.
    #[arg(long, default_value_t = 0.5)]
    divider: f64,
    /// Tiled culling of ranged lights (the same image, faster where ranges are short).
    #[arg(long, default_value = "on", value_parser = parse_cull, action = clap::ArgAction::Set)]
    cull: bool,
    #[command(flatten)]
    lut: LutArgs,
    #[command(flatten)]
    encoding: EncodingArgs,
    #[arg(long, value_parser = horizon_parser(), default_value = "eq30", help = HORIZON_HELP)]
    horizon: Horizon,
    /// Compare with this table instead of the BRDF: split and diff show LTC with the table
    /// of --lut/--table (left) against LTC with this one (right). A file in any format --lut
    /// reads.
    #[arg(long)]
    lut_b: Option<PathBuf>,
    /// The same, with a shipped table: classic or point.
    #[arg(long, value_parser = one_of(&Table::ALL, Table::name), conflicts_with = "lut_b")]
    table_b: Option<Table>,
    /// The 4D table of the right side's LTC on an anisotropic material (as --aniso-lut):
    /// split and diff then compare two 4D tables (without --table-b or --lut-b, both sides
    /// keep table A's 2D table).
    #[arg(long, value_parser = super::aniso_parser())]
    aniso_b: Option<AnisoSource>,
    /// The right side's table as this encoding decodes it (as --encoding): split and diff
    /// then compare two encodings, e.g. f32 | unorm8 (alone, table B is table A's table,
    /// before A's own --encoding).
    #[arg(long, value_parser = |s: &str| Encoding::parse(s))]
    encoding_b: Option<Encoding>,
    /// How a side shades one shape (`method_for::help`).
    #[arg(long, value_parser = method_for::parse, value_name = "[SIDE:]SHAPE=METHOD", help = method_for::help())]
    method_for: Vec<MethodFor>,
    /// Alias of --method-for a:sphere=METHOD.
    #[arg(long, value_parser = one_of(&SphereMethod::ALL, SphereMethod::name))]
    sphere_a: Option<SphereMethod>,
    /// Alias of --method-for b:sphere=METHOD.
    #[arg(long, value_parser = one_of(&SphereMethod::ALL, SphereMethod::name))]
    sphere_b: Option<SphereMethod>,
    /// Alias of --method-for a:rect=METHOD.
    #[arg(long, value_parser = one_of(&RectMethod::ALL, RectMethod::name))]
    rect_a: Option<RectMethod>,
    /// Alias of --method-for b:rect=METHOD.
    #[arg(long, value_parser = one_of(&RectMethod::ALL, RectMethod::name))]
    rect_b: Option<RectMethod>,
    /// Alias of --method-for a:disk=METHOD.
    #[arg(long, value_parser = one_of(&DiskMethod::ALL, DiskMethod::name))]
    disk_a: Option<DiskMethod>,
    /// Alias of --method-for b:disk=METHOD.
    #[arg(long, value_parser = one_of(&DiskMethod::ALL, DiskMethod::name))]
    disk_b: Option<DiskMethod>,
    /// A method of your own: a WGSL file of functions under the interface of
    /// docs/design.md §5.13, the method `file` (GPU only). With split or diff it is the left
    /// side unless --point-a or --point-b says otherwise.
    #[arg(long)]
    method_file: Option<PathBuf>,
    /// The point method left of a split (the numerator of a diff): ltc unless --method-file
    /// makes it file (as --method-for a:point=METHOD).
    #[arg(long, value_parser = one_of(&Method::ALL, Method::name))]
    point_a: Option<Method>,
    /// The point method right of a split (the reference of a diff): brdf by default (as
    /// --method-for b:point=METHOD).
    #[arg(long, value_parser = one_of(&Method::ALL, Method::name))]
    point_b: Option<Method>,
}

impl Args {
    /// Every per-shape choice, the aliases' first and then --method-for's, one per side and
    /// shape (`method_for::merged`).
    fn shape_methods(&self) -> Result<Vec<MethodFor>> {
        let alias = |flag, side, method: Option<ShapeMethod>| {
            method.map(|method| (flag, MethodFor { side, method }))
        };
        let aliases = [
            alias("--point-a", Side::A, self.point_a.map(ShapeMethod::from)),
            alias("--point-b", Side::B, self.point_b.map(ShapeMethod::from)),
            alias("--sphere-a", Side::A, self.sphere_a.map(ShapeMethod::from)),
            alias("--sphere-b", Side::B, self.sphere_b.map(ShapeMethod::from)),
            alias("--rect-a", Side::A, self.rect_a.map(ShapeMethod::from)),
            alias("--rect-b", Side::B, self.rect_b.map(ShapeMethod::from)),
            alias("--disk-a", Side::A, self.disk_a.map(ShapeMethod::from)),
            alias("--disk-b", Side::B, self.disk_b.map(ShapeMethod::from)),
        ];
        let given: Vec<_> = aliases
            .into_iter()
            .flatten()
            .chain(self.method_for.iter().map(|&c| ("--method-for", c)))
            .collect();
        method_for::merged(&given)
    }
}

pub fn run(a: &Args) -> Result<()> {
    if !a.divider.is_finite() || !(0.0..=1.0).contains(&a.divider) {
        return Err(Error::input(
            "--divider",
            format!("must be in [0, 1], got {}", number(a.divider)),
        ));
    }
    let mut settings = a.method.settings(a.size);
    settings.rules.clipping = a.clip;
    settings.rules.normalization = a.normalization;
    settings.divider = a.divider;
    settings.cull = a.cull;
    settings.rules.horizon = a.horizon.rule();
    let chosen = a.shape_methods()?;
    for c in chosen
        .iter()
        .filter(|c| c.method.kind() != ShapeKind::Point)
    {
        match c.side {
            Side::A => settings.a.set(c.method),
            Side::B => settings.b.set(c.method),
        }
    }
    let method_file = sides(a, &chosen, &mut settings)?;
    a.lut.check_horizon(a.horizon)?;
    let out = a
        .out
        .clone()
        .unwrap_or_else(|| default_name(&a.scene, a.method, a.horizon, method_file.as_ref()));
    let format = ImageFormat::of(&out)?;
    check_writable(&out)?;
    // Taken before any work: a file that appears meanwhile, or another run, gets another
    // name. Dropped on an error, the empty file goes again.
    let claim = a
        .out
        .is_none()
        .then(|| Claim::first_free(&out))
        .transpose()?;
    let scene = Scene::load(&a.scene)?;
    let table_a = a.horizon.table().unwrap_or(a.lut.table());
    let named_a = NamedTable {
        lut: a.encoding.apply(a.lut.load_for(a.horizon)?).into_owned(),
        name: match a.horizon.table() {
            Some(t) => format!("the embedded {} table ({})", t.name(), t.path()),
            None => a.lut.describe(),
        } + &a.encoding.suffix(),
        source: a.lut.source(a.horizon),
    };
    let tables = match table_b(a)? {
        Some(b) => {
            if !matches!(a.method, Shown::Compared(_)) {
                return Err(Error::input(
                    "--method",
                    "--table-b, --lut-b, --aniso-b and --encoding-b compare two tables: use split or diff",
                ));
            }
            settings.b.set(settings.a.point());
            settings.b_reads_table_b = true;
            NamedTables { a: named_a, b }
        }
        None => NamedTables::with_a(named_a, table_a),
    };
    let start = Instant::now();
    // A difference is measured too: each side alone, A against B (`sides_measured`).
    let mut all = vec![settings];
    if settings.view == View::Diff {
        all.extend([View::A, View::B].map(|view| RenderSettings { view, ..settings }));
    }
    let (frames, device) = if a.cpu {
        let frames = all
            .iter()
            .map(|s| cpu::render(&scene, tables.pair(), s))
            .collect();
        let threads = rayon::current_num_threads();
        (frames, format!("the CPU ({threads} threads)"))
    } else {
        render_gpu(&scene, &tables, &all, method_file.as_ref())?
    };
    let (frame, caption) =
        sides_measured(frames, &settings, (&scene, method_file.as_ref()), &tables);
    let seconds = start.elapsed().as_secs_f64();
    if let Some(file) = &method_file {
        // A file's light may be negative (a port's artifact, shown as it is), never NaN.
        if let Some((k, p)) = frame.first_invalid(Clipping::NONE) {
            return Err(Error::input(
                &file.name,
                format!(
                    "pixel ({}, {}) came out {p}; nothing was written",
                    k % frame.width,
                    k / frame.width
                ),
            ));
        }
    } else if let Some((k, p)) = frame.first_invalid(settings.rules.clipping) {
        return Err(Error::machine(
            "render",
            format!(
                "pixel ({}, {}) came out {p} on {device}; nothing was written",
                k % frame.width,
                k / frame.width
            ),
        ));
    }
    let bytes = match (format, &caption) {
        (ImageFormat::Png, Some(caption)) => {
            ltc_lab::output::png_with_caption(&frame, scene.exposure, caption)
        }
        _ => frame_bytes(&frame, format, scene.exposure),
    };
    let written = match claim {
        Some(claim) => claim.fill(&bytes)?,
        None => {
            write_atomically(&out, &bytes)?;
            out
        }
    };
    eprintln!(
        "rendered {} lights at {}×{} on {device} in {seconds:.3} s; wrote {}",
        scene.lights.len(),
        settings.width,
        settings.height,
        written.display()
    );
    Ok(())
}

/// `<scene stem>-<method>.png` in the current directory, `<scene stem>-<method>-<remedy>.png`
/// with a horizon remedy.
fn default_name(
    scene: &Path,
    shown: Shown,
    horizon: Horizon,
    file: Option<&MethodFile>,
) -> PathBuf {
    let stem = scene
        .file_stem()
        .map_or("render".into(), |s| s.to_string_lossy());
    let remedy = match horizon {
        Horizon::Eq30 => String::new(),
        h => format!("-{}", h.name()),
    };
    // A file's render names the file: `paper-100-split-no-case2.png`.
    let file = file.map_or(String::new(), |f| {
        let name = Path::new(&f.name)
            .file_stem()
            .map_or(String::new(), |s| s.to_string_lossy().into_owned());
        format!("-{name}")
    });
    PathBuf::from(format!("{stem}-{}{remedy}{file}.png", shown.name()))
}

/// The point methods of the sides (`--point-a`, `--point-b`; with a method file and neither,
/// the file on the left), and the method file, read and checked. Refused: the method `file`
/// without a file, a file no side shades, a file on the CPU.
fn sides(
    a: &Args,
    chosen: &[MethodFor],
    settings: &mut RenderSettings,
) -> Result<Option<MethodFile>> {
    let file = a.method_file.as_deref().map(MethodFile::read).transpose()?;
    let point = |side| {
        chosen.iter().find_map(|c| match c.method {
            ShapeMethod::Point(m) if c.side == side => Some(m),
            _ => None,
        })
    };
    let (point_a, point_b) = (point(Side::A), point(Side::B));
    if let Shown::Compared(_) = a.method {
        let default_a = if file.is_some() && point_b != Some(Method::File) {
            Method::File
        } else {
            Method::Ltc
        };
        settings.a.set(point_a.unwrap_or(default_a));
        settings.b.set(point_b.unwrap_or(Method::Brdf));
    } else if point_a.is_some() || point_b.is_some() {
        let flag = match (a.point_a, a.point_b) {
            (Some(_), _) => "--point-a",
            (_, Some(_)) => "--point-b",
            _ => "--method-for",
        };
        return Err(Error::input(
            flag,
            "the point methods (--point-a, --point-b, --method-for point=…) pick the sides of split and diff",
        ));
    }
    let uses_file = settings.methods().contains(&Method::File);
    match (&file, uses_file) {
        (None, true) => Err(Error::input(
            "--method-file",
            "the method `file` needs --method-file (a WGSL file, docs/design.md §5.13)",
        )),
        (Some(f), false) => Err(Error::input(
            "--method-file",
            format!(
                "no side shades with {}: pick --method file, split or diff",
                f.name
            ),
        )),
        (Some(f), true) if a.cpu => Err(Error::input(
            "--cpu",
            format!("{} is WGSL: a method file runs on the GPU only", f.name),
        )),
        (Some(f), true) => {
            eprintln!(
                "{}: work per light from its IR: {}",
                f.name,
                ltc_lab::gpu::work::file_work_line(f)
            );
            Ok(file)
        }
        _ => Ok(file),
    }
}

/// The second table of a comparison, if one is asked for.
fn table_b(a: &Args) -> Result<Option<NamedTable>> {
    if a.lut_b.is_none() && a.table_b.is_none() && a.aniso_b.is_none() && a.encoding_b.is_none() {
        return Ok(None);
    }
    // Only a 4D table or an encoding asked for: table A's 2D table beside it.
    let (table, file) = match (a.table_b, &a.lut_b) {
        (None, None) => (a.lut.table(), a.lut.lut.as_deref()),
        (t, f) => (t.unwrap_or(Table::Classic), f.as_deref()),
    };
    let loaded = formats::load(file, table)?;
    if let Some(note) = &loaded.note {
        eprintln!("ltc-lab: note: {note}");
    }
    let (mut name, source) = match file {
        Some(p) => {
            let path = p.display().to_string();
            (path.clone(), Source::File(path))
        }
        None => (table.name().to_string(), Source::Shipped(table)),
    };
    if let Some(aniso) = &a.aniso_b {
        name = format!("{name} with {}", aniso.name());
    }
    let encoding = EncodingArgs {
        encoding: a.encoding_b,
    };
    Ok(Some(NamedTable {
        lut: encoding
            .apply(super::with_aniso(loaded.lut, a.aniso_b.as_ref())?)
            .into_owned(),
        name: name + &encoding.suffix(),
        source,
    }))
}

/// The first of `frames` (the image asked for) and, for a difference (each side alone after
/// it), A measured against B, said on stderr and returned as the PNG's caption.
fn sides_measured(
    mut frames: Vec<Frame>,
    s: &RenderSettings,
    (scene, file): (&Scene, Option<&MethodFile>),
    tables: &NamedTables,
) -> (Frame, Option<String>) {
    let sides = frames.split_off(1);
    let frame = frames.remove(0);
    let [a, b] = &sides[..] else {
        return (frame, None);
    };
    let e = ltc_lab::metrics::image_error(a, b);
    // Where the sides read two tables (or two encodings of one), each side's is named too.
    let table = |t: &NamedTable| match s.b_reads_table_b {
        true => format!(", table {}", t.name),
        false => String::new(),
    };
    eprintln!(
        "diff: A ({}{}) against B ({}{}): relative RMSE {:.2}%, p99 of the pixels' relative error {:.2}%",
        side_name(&s.a, scene, file),
        table(&tables.a),
        side_name(&s.b, scene, file),
        table(&tables.b),
        100.0 * e.rel_rmse,
        100.0 * e.p99_rel
    );
    let caption = format!(
        "RMSE {:.2}% P99 {:.2}%",
        100.0 * e.rel_rmse,
        100.0 * e.p99_rel
    );
    (frame, Some(caption))
}

/// A side's methods for the shapes `scene` holds (`ltc-polygon`, or `point ltc, rect
/// ltc-polygon` where it holds several), a method file by its name.
fn side_name(
    m: &ltc_lab::render::ShapeMethods,
    scene: &Scene,
    file: Option<&MethodFile>,
) -> String {
    // The file shades every shape it has a function for.
    let name = |kind: ShapeKind| match (m.point(), file) {
        (Method::File, Some(f)) if f.shades(kind) => f.name.clone(),
        _ => m.of(kind).name().to_string(),
    };
    let point = name(ShapeKind::Point);
    let mut parts: Vec<(&str, String)> = Vec::new();
    for light in &scene.lights {
        let kind = light.shape.kind();
        let part = (kind.name(), name(kind));
        if !parts.contains(&part) {
            parts.push(part);
        }
    }
    match &parts[..] {
        [] => point,
        [(_, one)] => one.clone(),
        many => many
            .iter()
            .map(|(shape, method)| format!("{shape} {method}"))
            .collect::<Vec<_>>()
            .join(", "),
    }
}

/// The GPU renders of `all`, checked against the adapter's limits before any work.
fn render_gpu(
    scene: &Scene,
    tables: &NamedTables,
    all: &[RenderSettings],
    file: Option<&MethodFile>,
) -> Result<(Vec<Frame>, String)> {
    let s = &all[0];
    let ctx = GpuContext::new().map_err(|e| Error {
        message: format!("{} (--cpu)", e.message),
        ..e
    })?;
    ltc_lab::gpu::target::check_size(&ctx, s.width, s.height).map_err(super::flag_of)?;
    let mut renderer = PlaneRenderer::new(&ctx, &tables.a.lut, ShaderChecks::Checked)?;
    if s.b_reads_table_b {
        renderer.set_tables(&ctx, &tables.a.lut, Some(&tables.b.lut))?;
    }
    renderer.set_method_file(&ctx, file.cloned())?;
    // A render split into submissions a watchdog never sees (gpu/failures/submissions.rs) shows how far
    // it is, and says how many it took.
    let mut bar = None;
    let mut submissions = 0;
    let (frame, ms) = renderer.render_with(&ctx, scene, s, &mut |at| {
        submissions = at.submissions;
        if at.submissions > 1 {
            bar.get_or_insert_with(|| super::progress_bar_of("render", at.lights, "lights"))
                .set_position(at.lights_done as u64);
        }
    })?;
    let mut frames = vec![frame];
    for s in &all[1..] {
        frames.push(renderer.render(&ctx, scene, s)?.0);
    }
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    if submissions > 1 {
        eprintln!(
            "render: {submissions} submissions, each under {:.0e} estimated operations (docs/design.md §5.14)",
            ltc_lab::gpu::failures::submissions::MAX_SUBMISSION_WORK
        );
    }
    Ok((frames, format!("{} ({ms:.2} ms GPU)", ctx.describe())))
}
