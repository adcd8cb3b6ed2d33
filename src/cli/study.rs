//! `ltc-lab study`: every shading variant timed and measured against the exact image, and
//! the error by light elevation of its tables; `study.csv`, the Pareto chart `study.png` and
//! `horizon.csv` land together or not at all.

use std::path::{Path, PathBuf};
use std::time::Instant;

use ltc_lab::error::{Error, Result, number};
use ltc_lab::files::Outputs;
use ltc_lab::gpu::GpuContext;
use ltc_lab::light::ShapeKind;
use ltc_lab::ltc::lut::{ALPHA_MIN, Lut};
use ltc_lab::ltc::remedy::Horizon;
use ltc_lab::measure::horizon;
use ltc_lab::measure::study;

use super::sizes::SizeArgs;
use super::{
    CullArgs, EncodingArgs, LutArgs, Range, check_frames_and_lights, horizon_parser, parse_size,
    print,
};

/// The directory `study` writes into unless told otherwise.
const DEFAULT_DIR: &str = "study";
const FILES: [&str; 3] = ["study.csv", "study.png", "horizon.csv"];
/// `--horizon-cases`' ceiling: 10⁸ cases a band take about two minutes a remedy in a release
/// build on two cores (`horizon::CASES`' second, a hundred times).
const MAX_HORIZON_CASES: usize = 100_000_000;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Directory for study.csv, study.png and horizon.csv (made if missing; files in it are
    /// replaced). Default: ./study, or the first of study-2, study-3… that holds none, taken
    /// when the study starts so that two studies at once never share one.
    #[arg(long)]
    out: Option<PathBuf>,
    #[arg(long, default_value = "320x180", value_parser = parse_size)]
    size: (usize, usize),
    /// Light counts of the generated lights, comma-separated (default 100,1000); not with a
    /// scene file, which brings its own.
    #[arg(long, value_delimiter = ',')]
    lights: Option<Vec<usize>>,
    #[arg(long, value_delimiter = ',', default_value = "0.1,0.27,0.6")]
    alpha: Vec<f64>,
    /// Timed frames per variant (median, after one warm-up).
    #[arg(long, default_value_t = 5)]
    frames: usize,
    #[command(flatten)]
    culling: CullArgs,
    /// The table of the variants that shade with the shipped one (ltc, ltc-fast, ltc-paper,
    /// ltc-nearest, ltc-f16, ltc-fast-nl-fit, ltc-fast-exact-band).
    #[command(flatten)]
    lut: LutArgs,
    #[command(flatten)]
    encoding: EncodingArgs,
    /// Table encodings, comma-separated (docs/design.md §2.10), each a variant
    /// ltc-table-NAME on the generated lights: ltc with the table as the encoding gives it back,
    /// timed and measured in the same run as ltc (the lab's GPU reads every decoded table as
    /// f32 values, so the times differ only by the table's size).
    #[arg(long, value_delimiter = ',', value_parser = |s: &str| ltc_lab::ltc::lut::Encoding::parse(s))]
    encodings: Vec<ltc_lab::ltc::lut::Encoding>,
    /// Horizon remedies, comma-separated, each run as an ltc-fast variant
    /// (ltc-fast-<remedy>) beside the others; eq30 alone runs none. See docs/design.md §4.7.
    #[arg(
        long,
        value_delimiter = ',',
        value_parser = horizon_parser(),
        default_value = "arrival-fit,constrained-fit,nl-fit,exact-band"
    )]
    horizon: Vec<Horizon>,
    /// Only these point variants, comma-separated (study.csv's names: ltc, ltc-fast,
    /// ltc-fast-nl-fit…), beside brdf, the reference, which always runs; on the generated
    /// lights and a scene's points alike. A remedy's variant needs its remedy in --horizon too,
    /// an f16 one an adapter with f16. Default: every one. The sized lights' methods all run.
    #[arg(long, value_delimiter = ',')]
    variants: Option<Vec<String>>,
    /// Cases per elevation band of horizon.csv, from 1 to 10⁸: the default puts each band's
    /// error within about 1% of itself, 10⁵ within about 3% in a tenth of the time.
    #[arg(long, default_value_t = horizon::CASES)]
    horizon_cases: usize,
    /// paper-100: paper-100's lights (0.05–0.6 above the plane); low-lights: lights
    /// 0.02–0.15 above it, most of them within 15° of the horizon where they shade; or a scene
    /// file (TOML, as `render` takes; the presets are in assets/scenes/), studied as given:
    /// every method of each shape it holds against its exact image, in variants
    /// `<variant>@<scene>` (docs/design.md §4.6).
    #[arg(long, default_value = "paper-100")]
    scene: String,
    #[command(flatten)]
    sizes: SizeArgs,
    /// Also the method in this WGSL file (docs/design.md §5.13): variants `file`, and
    /// `<shape>-file` where it shades the study's sized lights; timed with runtime checks.
    #[arg(long)]
    method_file: Option<PathBuf>,
}

/// The light sets `--scene` names: generated lights at these heights, or none (a scene file).
fn generated(a: &Args) -> Result<(Option<[f64; 2]>, Vec<usize>)> {
    let heights = match a.scene.as_str() {
        "paper-100" => Some(ltc_lab::measure::bench::PAPER_HEIGHTS),
        "low-lights" => Some(study::LOW_HEIGHTS),
        _ => None,
    };
    let lights = match (&a.lights, heights) {
        (Some(_), None) => {
            return Err(Error::input(
                "--lights",
                format!("the scene file {} brings its own lights", a.scene),
            ));
        }
        (Some(l), Some(_)) => l.clone(),
        (None, Some(_)) => vec![100, 1000],
        (None, None) => Vec::new(),
    };
    Ok((heights, lights))
}

/// The scenes studied as given: the scene file, and each sized shape's first failure preset
/// (`ShapeKind::presets`: rect-horizon, disk-limits…).
fn scenes(
    a: &Args,
    file: bool,
    sizes: &[(ShapeKind, f64)],
) -> Result<Vec<(String, ltc_lab::scene::Scene)>> {
    let mut scenes = Vec::new();
    if file {
        let path = Path::new(&a.scene);
        let name = path
            .file_stem()
            .map_or(a.scene.clone(), |s| s.to_string_lossy().into_owned());
        scenes.push((name, ltc_lab::scene::Scene::load(path)?));
    }
    for (kind, _) in sizes {
        if let Some((name, _)) = kind.presets().first() {
            scenes.push((name.to_string(), ltc_lab::scene::preset(name)));
        }
    }
    Ok(scenes)
}

pub fn run(a: &Args) -> Result<()> {
    let (heights, lights) = generated(a)?;
    let counts: Vec<usize> = match heights {
        Some(_) => lights.clone(),
        None => vec![1],
    };
    check_frames_and_lights(a.frames, &counts)?;
    let sizes = a.sizes.sizes()?;
    let scenes = scenes(a, heights.is_none(), &sizes)?;
    if !(1..=MAX_HORIZON_CASES).contains(&a.horizon_cases) {
        return Err(Error::input(
            "--horizon-cases",
            format!(
                "from 1 to {MAX_HORIZON_CASES} cases per band, got {}",
                a.horizon_cases
            ),
        ));
    }
    let only = a
        .variants
        .as_ref()
        .map(|names| names.iter().map(|n| study::variant_named(n)).collect())
        .transpose()
        .map_err(|why| Error::input("--variants", why))?;
    // The scene's range: a material below α_min is refused everywhere else.
    let alphas = ALPHA_MIN..=1.0;
    if let Some(&alpha) = a.alpha.iter().find(|x| !alphas.contains(*x)) {
        return Err(Error::input(
            "--alpha",
            format!(
                "each α must be in [{}, 1], got {}",
                number(ALPHA_MIN),
                number(alpha)
            ),
        ));
    }
    let lut = a.encoding.apply(a.lut.load()?);
    let mut out = match &a.out {
        Some(d) => Outputs::new(d, &FILES)?,
        None => Outputs::claim_free_directory(Path::new(DEFAULT_DIR), &FILES)?,
    };
    let dir = out.dir().to_path_buf();
    let ctx = GpuContext::new()?;
    ltc_lab::measure::bench::check(&ctx, &lights, a.size).map_err(super::flag_of)?;
    let device = ctx.describe();
    eprintln!("study on {device}");
    let start = Instant::now();
    let settings = study::StudySettings {
        size: a.size,
        lights,
        alphas: a.alpha.clone(),
        frames: a.frames,
        culls: a.culling.cull.clone(),
        range: Range::or_default(a.culling.range),
        horizons: a.horizon.clone(),
        only,
        heights: heights.unwrap_or(ltc_lab::measure::bench::PAPER_HEIGHTS),
        sizes,
        method_file: a
            .method_file
            .as_deref()
            .map(ltc_lab::gpu::method_file::MethodFile::read)
            .transpose()?,
        scenes,
        encodings: a.encodings.clone(),
    };
    let mut report = |r: &study::StudyRow| {
        eprintln!(
            "  α {:<5} {:>6} lights cull {:>3} {:>13}: {:9.3} ms, rel RMSE {:.2e}, p99 {:.2e}",
            r.alpha,
            r.lights,
            if r.cull { "on" } else { "off" },
            r.variant,
            r.ms_median,
            r.rel_rmse,
            r.p99_rel_err
        );
    };
    let mut begun = study::Study::new(&ctx, &lut, &settings)?;
    let mut rows = begun.generated(&ctx, &settings, &mut report)?;
    rows.extend(ltc_lab::measure::scene_study::run(
        &ctx,
        &mut begun,
        &settings,
        &mut report,
    )?);
    let csv = study::csv(&rows);
    out.stage("study.csv", csv.as_bytes())?;
    let png = study::pareto_png(&rows, &ctx.info.name, &a.scene)?;
    out.stage("study.png", &png)?;
    out.stage(
        "horizon.csv",
        horizon_csv(
            &lut,
            &(a.lut.name() + &a.encoding.suffix()),
            a.horizon_cases,
        )
        .as_bytes(),
    )?;
    out.commit()?;
    eprintln!(
        "study done in {:.0} s; wrote {}/study.csv, study.png and horizon.csv",
        start.elapsed().as_secs_f64(),
        dir.display()
    );
    print(&csv)
}

/// The error by light elevation (docs/design.md §4.7) of the study's table `lut` (named
/// `name`) under every horizon remedy (the fitted ones with their own tables), and of the
/// point fit of `ltc-point` and `ltc-fast-point` with eq. 30's rules, `cases` per band.
fn horizon_csv(lut: &Lut, name: &str, cases: usize) -> String {
    let mut text = String::from("table,rules,band,cases,specular,diffuse,specular_energy\n");
    // A path may hold a comma: the CSV's own separator.
    let name = name.replace(',', ";");
    let point = Lut::embedded_point();
    let runs = Horizon::ALL
        .map(|r| (r, lut))
        .into_iter()
        .chain([(Horizon::Eq30, point)]);
    for (remedy, lut) in runs {
        let (used, bands) = horizon::remedy_errors(lut, remedy, cases, horizon::SEED);
        let table = match remedy.table() {
            Some(t) => t.name(),
            None if std::ptr::eq(used, point) => "point",
            None => &name,
        };
        text.push_str(&horizon::csv_rows(
            &format!("{table},{},", remedy.name()),
            &bands,
        ));
    }
    text
}
