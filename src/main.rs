//! `ltc-lab`: the headless command line of DESIGN §6. Every bad input ends in one line on
//! stderr naming it and exit code 2 (clap's own usage errors exit 2 as well).

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use clap::{Parser, Subcommand, ValueEnum};
use glam::DVec3;

use ltc_lab::bench::BenchRow;
use ltc_lab::brdf::{brdf_cos, view_from_theta};
use ltc_lab::cpu::{Method, RenderSettings, render};
use ltc_lab::error::{InputError, Result};
use ltc_lab::gpu::GpuContext;
use ltc_lab::gpu::plane::{GpuMethod, GpuView, PlaneRenderer, PlaneSettings, ShaderChecks};
use ltc_lab::ltc::fit::{FitSettings, fit_table};
use ltc_lab::ltc::lut::{CHANNEL_NAMES, Channel, Lut, Table};
use ltc_lab::ltc::{Clipping, Normalization};
use ltc_lab::metrics::relative_floor;
use ltc_lab::output::write_frame;
use ltc_lab::scene::Scene;

#[derive(Parser, Debug)]
#[command(
    name = "ltc-lab",
    version,
    about = "Point lights shaded with Linearly Transformed Cosines: fit, evaluate, render, measure."
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Open the lab (the default with no subcommand).
    Lab {
        /// Render a few frames, save the window's pixels to this PNG and exit.
        #[arg(long)]
        screenshot: Option<PathBuf>,
        /// Show one panel maximised (default: all five).
        #[arg(long, value_enum, default_value_t = PanelArg::All)]
        panel: PanelArg,
        /// Window size, WxH.
        #[arg(long, default_value = "1600x900", value_parser = parse_size)]
        size: (usize, usize),
        /// Start with this scene instead of the saved state.
        #[arg(long)]
        scene: Option<PathBuf>,
        /// Fill the speed-vs-accuracy chart before showing (as its "measure" button does).
        #[arg(long)]
        measure: bool,
    },
    /// Fit both lobes (GGX specular, Burley diffuse) over an N×N (θo, α) table and write the LUT.
    Fit {
        /// Cells per side.
        #[arg(long, default_value_t = 64)]
        size: usize,
        /// classic: ltc_code's objective (luts/ltc.exr); point: the pointwise relative L1
        /// error a point light sees, from the classic fit (luts/ltc_point.exr).
        #[arg(long, value_enum, default_value_t = Objective::Classic)]
        objective: Objective,
        /// Where to write the table (OpenEXR); default luts/ltc.exr or luts/ltc_point.exr.
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Evaluate the exact lobes and their LTC approximation for the cases of a CSV file.
    ///
    /// Input header: theta_o,alpha,lx,ly,lz,f0 — theta_o in degrees (0–90), alpha the GGX α in
    /// (0, 1], l the unit light direction in the shading frame (n = +z, v in the xz-plane),
    /// f0 in [0, 1]. Output on stdout: those columns plus brdf_spec,brdf_diffuse,ltc_spec,
    /// ltc_diffuse — each f·cos for a unit-irradiance light and base colour 1, the LTC through
    /// the LUT's bilinear sampler with both clipping rules (eq. 30).
    Eval {
        #[arg(long)]
        cases: PathBuf,
        /// A LUT file instead of the embedded one.
        #[arg(long)]
        lut: Option<PathBuf>,
        /// Which shipped table: classic (ltc_code's fit) or point (the point-light fit).
        #[arg(long, value_enum, default_value_t = Table::Classic)]
        table: Table,
    },
    /// Inspect a LUT.
    Lut {
        /// A LUT file instead of the embedded one.
        #[arg(long)]
        lut: Option<PathBuf>,
        /// Which shipped table: classic (ltc_code's fit) or point (the point-light fit).
        #[arg(long, value_enum, default_value_t = Table::Classic)]
        table: Table,
        /// Print every cell as CSV: i,j,alpha,theta_o (degrees), then the channels.
        #[arg(long)]
        dump: bool,
        /// Write the error atlas into this directory: heat maps of spec.err and diff.err, the
        /// error of one light orbiting a point, and their CSVs.
        #[arg(long)]
        atlas: Option<PathBuf>,
    },
    /// Speed against accuracy: every variant timed on the GPU and compared with the exact
    /// image, per light count and roughness; writes study.csv and study.png (Pareto chart).
    Study {
        #[arg(long, default_value = "study")]
        out: PathBuf,
        #[arg(long, default_value = "320x180", value_parser = parse_size)]
        size: (usize, usize),
        #[arg(long, value_delimiter = ',', default_value = "100,1000")]
        lights: Vec<usize>,
        #[arg(long, value_delimiter = ',', default_value = "0.1,0.27,0.6")]
        alpha: Vec<f64>,
        /// Timed frames per variant (median, after one warm-up).
        #[arg(long, default_value_t = 5)]
        frames: usize,
    },
    /// Render a scene preset to PNG (tone-mapped) or EXR (linear radiance), on the GPU
    /// (default) or the CPU reference.
    Render {
        #[arg(long)]
        scene: PathBuf,
        /// brdf, brdf-fast, ltc, ltc-fast, ltc-f16, split (LTC | BRDF) or diff (|LTC − BRDF| / BRDF).
        /// On the CPU the fast forms are the same math as their literal twins.
        #[arg(long, value_enum)]
        method: RenderMethod,
        /// Image size, WxH.
        #[arg(long, default_value = "512x512", value_parser = parse_size)]
        size: (usize, usize),
        /// Output file (.png or .exr); default `<scene>-<method>.png`, never overwritten.
        #[arg(long)]
        out: Option<PathBuf>,
        /// Render on the CPU (the f64 reference) instead of the GPU.
        #[arg(long)]
        cpu: bool,
        /// Light clipping rules (eq. 30): both, horizon (case 1 only), transformed (case 2
        /// only) or none.
        #[arg(long, value_enum, default_value_t = ClipArg::Both)]
        clip: ClipArg,
        /// corrected (DESIGN §1) or paper (eq. 25 as printed: no 1/π, no magnitudes).
        #[arg(long, value_enum, default_value_t = NormalizationArg::Corrected)]
        normalization: NormalizationArg,
        /// Where the split view changes from LTC (left) to BRDF (right), 0–1 of the width.
        #[arg(long, default_value_t = 0.5)]
        divider: f64,
        /// A LUT file instead of the embedded one.
        #[arg(long)]
        lut: Option<PathBuf>,
        /// Which shipped table: classic (ltc_code's fit) or point (the point-light fit).
        #[arg(long, value_enum, default_value_t = Table::Classic)]
        table: Table,
    },
    /// The paper's Table 1 on this machine's GPU: every method at each light count.
    Bench {
        /// Light counts, comma-separated.
        #[arg(long, value_delimiter = ',', default_value = "100,500,1000,5000")]
        lights: Vec<usize>,
        #[arg(long, default_value = "1920x1080", value_parser = parse_size)]
        size: (usize, usize),
        /// Timed frames per method and light count (after 5 warm-up frames).
        #[arg(long, default_value_t = 30)]
        frames: usize,
        /// Also write the rows as CSV.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Keep wgpu's runtime bounds checks (the default benchmarks trusted shader modules).
        #[arg(long)]
        checked: bool,
        /// A LUT file instead of the embedded one.
        #[arg(long)]
        lut: Option<PathBuf>,
        /// Which shipped table: classic (ltc_code's fit) or point (the point-light fit).
        #[arg(long, value_enum, default_value_t = Table::Classic)]
        table: Table,
    },
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum PanelArg {
    Lobe,
    Matrix,
    Plane,
    Clipping,
    Chart,
    All,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum Objective {
    Classic,
    Point,
}

/// What `render` draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum RenderMethod {
    Brdf,
    BrdfFast,
    Ltc,
    LtcFast,
    /// ltc-fast with M⁻¹l and D in f16 (GPUs with SHADER_F16).
    LtcF16,
    Split,
    Diff,
}

impl RenderMethod {
    /// The CPU reference's method (it has one form of each).
    fn cpu(self) -> Method {
        match self {
            Self::Brdf | Self::BrdfFast => Method::Brdf,
            Self::Ltc | Self::LtcFast | Self::LtcF16 => Method::Ltc,
            Self::Split => Method::Split,
            Self::Diff => Method::Diff,
        }
    }

    /// The GPU's methods and view: split and diff compare the literal forms, as the CPU does.
    fn gpu(self) -> (GpuMethod, GpuView) {
        match self {
            Self::Brdf => (GpuMethod::Brdf, GpuView::Single),
            Self::BrdfFast => (GpuMethod::BrdfFast, GpuView::Single),
            Self::Ltc => (GpuMethod::Ltc, GpuView::Single),
            Self::LtcFast => (GpuMethod::LtcFast, GpuView::Single),
            Self::LtcF16 => (GpuMethod::LtcF16, GpuView::Single),
            Self::Split => (GpuMethod::Ltc, GpuView::Split),
            Self::Diff => (GpuMethod::Ltc, GpuView::Diff),
        }
    }
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum ClipArg {
    Both,
    Horizon,
    Transformed,
    None,
}

impl From<ClipArg> for Clipping {
    fn from(c: ClipArg) -> Self {
        match c {
            ClipArg::Both => Clipping::BOTH,
            ClipArg::Horizon => Clipping::HORIZON,
            ClipArg::Transformed => Clipping::TRANSFORMED,
            ClipArg::None => Clipping::NONE,
        }
    }
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum NormalizationArg {
    Corrected,
    Paper,
}

impl From<NormalizationArg> for Normalization {
    fn from(n: NormalizationArg) -> Self {
        match n {
            NormalizationArg::Corrected => Normalization::Corrected,
            NormalizationArg::Paper => Normalization::PaperLiteral,
        }
    }
}

/// The largest image side `--size` accepts: 16K, beyond any display, small enough that a
/// typo cannot ask for terabytes.
const MAX_IMAGE_SIDE: usize = 16384;

fn parse_size(s: &str) -> std::result::Result<(usize, usize), String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("'{s}' is not WxH (e.g. 512x512)"))?;
    let side = |t: &str| {
        t.trim()
            .parse::<usize>()
            .ok()
            .filter(|&n| (1..=MAX_IMAGE_SIDE).contains(&n))
            .ok_or_else(|| {
                format!("'{s}': each side must be a whole number in 1..={MAX_IMAGE_SIDE}")
            })
    };
    Ok((side(w)?, side(h)?))
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        None => run_lab(None, PanelArg::All, (1600, 900), None, false),
        Some(Command::Lab {
            screenshot,
            panel,
            size,
            scene,
            measure,
        }) => run_lab(screenshot, panel, size, scene.as_deref(), measure),
        Some(Command::Fit {
            size,
            objective,
            out,
        }) => {
            let out = out.unwrap_or_else(|| {
                PathBuf::from(match objective {
                    Objective::Classic => "luts/ltc.exr",
                    Objective::Point => "luts/ltc_point.exr",
                })
            });
            run_fit(size, objective, &out)
        }
        Some(Command::Eval { cases, lut, table }) => run_eval(&cases, lut.as_deref(), table),
        Some(Command::Lut {
            lut,
            table,
            dump,
            atlas,
        }) => run_lut(lut.as_deref(), table, dump, atlas.as_deref()),
        Some(Command::Study {
            out,
            size,
            lights,
            alpha,
            frames,
        }) => run_study(&out, size, &lights, &alpha, frames),
        Some(Command::Render {
            scene,
            method,
            size,
            out,
            cpu,
            clip,
            normalization,
            divider,
            lut,
            table,
        }) => {
            let mut settings = RenderSettings::new(size.0, size.1, method.cpu());
            settings.clipping = clip.into();
            settings.normalization = normalization.into();
            settings.divider = divider;
            run_render(&scene, method, settings, out, cpu, lut.as_deref(), table)
        }
        Some(Command::Bench {
            lights,
            size,
            frames,
            csv,
            checked,
            lut,
            table,
        }) => run_bench(
            &lights,
            size,
            frames,
            csv.as_deref(),
            checked,
            lut.as_deref(),
            table,
        ),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("ltc-lab: {e}");
            ExitCode::from(2)
        }
    }
}

fn run_fit(size: usize, objective: Objective, out: &Path) -> Result<()> {
    if !(2..=1024).contains(&size) {
        return Err(InputError::new(
            "--size",
            format!("must be in 2..=1024, got {size}"),
        ));
    }
    let settings = FitSettings {
        size,
        ..FitSettings::default()
    };
    let bar = indicatif::ProgressBar::new((2 * size * size) as u64);
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "fitting {bar:40} {pos}/{len} cells  {elapsed_precise}",
        )
        .expect("a valid template"),
    );
    let start = Instant::now();
    let (lut, at_limit) = match objective {
        Objective::Classic => {
            let fitted = fit_table(&settings, &|| bar.inc(1));
            (fitted.lut, Some(fitted.at_iteration_limit))
        }
        Objective::Point => {
            // Each point-fit sweep visits every cell (both lobes) once.
            let sweeps = 1 + ltc_lab::ltc::fit_point::REFINEMENTS;
            bar.set_length((2 * sweeps * size * size) as u64);
            // Warm start: the classic fit of the same cells (the shipped one at its size).
            let classic = if size == Lut::embedded().size {
                Lut::embedded().clone()
            } else {
                bar.inc_length((2 * size * size) as u64);
                fit_table(&settings, &|| bar.inc(1)).lut
            };
            let lut = ltc_lab::ltc::fit_point::fit_point_table(&classic, &settings, &|| {
                bar.inc(2);
            });
            (lut, None)
        }
    };
    let seconds = start.elapsed().as_secs_f64();
    bar.finish_and_clear();
    lut.write(out)?;
    let stats = |c: Channel| {
        let xs: Vec<f32> = lut.cells.iter().map(|cell| cell.get(c)).collect();
        let mean = xs.iter().map(|&x| f64::from(x)).sum::<f64>() / xs.len() as f64;
        let (k, max) =
            xs.iter().enumerate().fold(
                (0, f32::MIN),
                |acc, (k, &x)| if x > acc.1 { (k, x) } else { acc },
            );
        (mean, max, k % size, k / size)
    };
    eprintln!(
        "fitted {size}×{size} cells × 2 lobes in {seconds:.1} s on {} threads (α_min = {}); wrote {}",
        rayon::current_num_threads(),
        settings.alpha_min,
        out.display()
    );
    if let Some([spec, diff]) = at_limit {
        eprintln!(
            "  cells stopped at the {}-iteration limit: spec {spec}, diff {diff}",
            settings.max_iterations
        );
    }
    for c in [Channel::SpecErr, Channel::DiffErr] {
        let (mean, max, i, j) = stats(c);
        eprintln!(
            "  {:<9} mean {mean:.4}  max {max:.4} at i={i} (α={:.4}), j={j} (θo={:.1}°)",
            CHANNEL_NAMES[c as usize],
            lut.alpha(i),
            lut.theta_o(j).to_degrees()
        );
    }
    Ok(())
}

/// One validated row of an `eval` CSV.
struct Case {
    theta_o_degrees: f64,
    alpha: f64,
    l: DVec3,
    f0: f64,
}

const EVAL_HEADER: &str = "theta_o,alpha,lx,ly,lz,f0";

/// How far from unit length `l` may be: CSV values typed with 4 decimals are off by ~1e-4.
const UNIT_TOLERANCE: f64 = 1e-3;

fn parse_cases(text: &str, name: &str) -> Result<Vec<Case>> {
    let mut lines = text.lines().enumerate();
    let header = lines.next().map(|(_, h)| h.trim().replace(' ', ""));
    if header.as_deref() != Some(EVAL_HEADER) {
        return Err(InputError::new(
            format!("{name} line 1"),
            format!("the header must be '{EVAL_HEADER}'"),
        ));
    }
    let mut cases = Vec::new();
    for (k, line) in lines {
        if line.trim().is_empty() {
            continue;
        }
        let at = format!("{name} line {}", k + 1);
        let fields: Vec<&str> = line.split(',').map(str::trim).collect();
        if fields.len() != 6 {
            return Err(InputError::new(
                at,
                format!("expected 6 values, found {}", fields.len()),
            ));
        }
        let mut v = [0.0; 6];
        for (x, f) in v.iter_mut().zip(&fields) {
            *x = f
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| InputError::new(&at, format!("'{f}' is not a finite number")))?;
        }
        let [theta_o, alpha, lx, ly, lz, f0] = v;
        if !(0.0..=90.0).contains(&theta_o) {
            return Err(InputError::new(
                at,
                format!("theta_o must be in [0, 90] degrees, got {theta_o}"),
            ));
        }
        if !(alpha > 0.0 && alpha <= 1.0) {
            return Err(InputError::new(
                at,
                format!("alpha must be in (0, 1], got {alpha}"),
            ));
        }
        if !(0.0..=1.0).contains(&f0) {
            return Err(InputError::new(
                at,
                format!("f0 must be in [0, 1], got {f0}"),
            ));
        }
        let l = DVec3::new(lx, ly, lz);
        if (l.length() - 1.0).abs() > UNIT_TOLERANCE {
            return Err(InputError::new(
                at,
                format!("l must be unit length, |l| = {}", l.length()),
            ));
        }
        cases.push(Case {
            theta_o_degrees: theta_o,
            alpha,
            l: l.normalize(),
            f0,
        });
    }
    Ok(cases)
}

fn run_eval(cases_path: &Path, lut_path: Option<&Path>, table: Table) -> Result<()> {
    let name = cases_path.display().to_string();
    let text = std::fs::read_to_string(cases_path)
        .map_err(|e| InputError::new(&name, format!("cannot read: {e}")))?;
    let cases = parse_cases(&text, &name)?;
    let lut = Lut::load(lut_path, table)?;
    let mut out = String::from(EVAL_HEADER);
    out.push_str(",brdf_spec,brdf_diffuse,ltc_spec,ltc_diffuse\n");
    for c in &cases {
        let theta = c
            .theta_o_degrees
            .to_radians()
            .min(ltc_lab::ltc::fit::THETA_MAX);
        let v = DVec3::from(view_from_theta(theta));
        let exact = brdf_cos(v.to_array(), c.l.to_array(), c.alpha, c.f0);
        let approx =
            lut.ltc_pair(c.alpha, v)
                .ltc_lobes(c.l, c.f0, Clipping::BOTH, Normalization::Corrected);
        out.push_str(&format!(
            "{},{},{},{},{},{},{:e},{:e},{:e},{:e}\n",
            c.theta_o_degrees,
            c.alpha,
            c.l.x,
            c.l.y,
            c.l.z,
            c.f0,
            exact.specular,
            exact.diffuse,
            approx.specular,
            approx.diffuse
        ));
    }
    print!("{out}");
    Ok(())
}

fn run_lut(lut_path: Option<&Path>, table: Table, dump: bool, atlas: Option<&Path>) -> Result<()> {
    let lut = Lut::load(lut_path, table)?;
    if let Some(dir) = atlas {
        let summary = ltc_lab::atlas::write_atlas(&lut, dir)?;
        for line in summary.lines {
            println!("{line}");
        }
        eprintln!("wrote the atlas into {}", dir.display());
        if !dump {
            return Ok(());
        }
    }
    if !dump {
        println!(
            "{}: {}×{} cells, α_min = {}, channels: {}",
            lut_path.map_or(format!("embedded {table:?} table"), |p| p
                .display()
                .to_string()),
            lut.size,
            lut.size,
            lut.alpha_min,
            CHANNEL_NAMES.join(" ")
        );
        println!("pass --dump for every cell as CSV");
        return Ok(());
    }
    let mut out = format!("i,j,alpha,theta_o,{}\n", CHANNEL_NAMES.join(","));
    for j in 0..lut.size {
        for i in 0..lut.size {
            let values: Vec<String> = lut.cell(i, j).0.iter().map(f32::to_string).collect();
            out.push_str(&format!(
                "{i},{j},{},{},{}\n",
                lut.alpha(i),
                lut.theta_o(j).to_degrees(),
                values.join(",")
            ));
        }
    }
    print!("{out}");
    Ok(())
}

fn run_render(
    scene_path: &Path,
    method: RenderMethod,
    settings: RenderSettings,
    out: Option<PathBuf>,
    cpu: bool,
    lut_path: Option<&Path>,
    table: Table,
) -> Result<()> {
    if !settings.divider.is_finite() || !(0.0..=1.0).contains(&settings.divider) {
        return Err(InputError::new(
            "--divider",
            format!("must be in [0, 1], got {}", settings.divider),
        ));
    }
    let scene = Scene::load(scene_path)?;
    let lut = Lut::load(lut_path, table)?;
    let out = match out {
        Some(p) => p,
        None => {
            let stem = scene_path
                .file_stem()
                .map_or("render".into(), |s| s.to_string_lossy());
            let name = method.to_possible_value().expect("no skipped variants");
            let p = PathBuf::from(format!("{stem}-{}.png", name.get_name()));
            if p.exists() {
                return Err(InputError::new(
                    p.display().to_string(),
                    "exists; name it with --out to overwrite it",
                ));
            }
            p
        }
    };
    if !matches!(
        out.extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
            .as_deref(),
        Some("png" | "exr")
    ) {
        return Err(InputError::new(
            out.display().to_string(),
            "the output must end in .png or .exr",
        ));
    }
    let start = Instant::now();
    let (frame, device) = if cpu {
        let frame = render(&scene, &lut, &settings);
        (
            frame,
            format!("the CPU ({} threads)", rayon::current_num_threads()),
        )
    } else {
        render_gpu(&scene, &lut, method, &settings)?
    };
    let seconds = start.elapsed().as_secs_f64();
    write_frame(&frame, &out, scene.exposure)?;
    eprintln!(
        "rendered {} lights at {}×{} on {device} in {seconds:.3} s; wrote {}",
        scene.lights.len(),
        settings.width,
        settings.height,
        out.display()
    );
    Ok(())
}

/// The GPU render of `render`: the diff view first renders the exact image for its floor.
fn render_gpu(
    scene: &Scene,
    lut: &Lut,
    method: RenderMethod,
    s: &RenderSettings,
) -> Result<(ltc_lab::cpu::Frame, String)> {
    let ctx = GpuContext::new()?;
    let mut renderer = PlaneRenderer::new(&ctx, lut, ShaderChecks::Checked);
    let (method_a, view) = method.gpu();
    let mut settings = PlaneSettings::single(s.width, s.height, method_a);
    settings.view = view;
    settings.clipping = s.clipping;
    settings.normalization = s.normalization;
    settings.divider = s.divider;
    if view == GpuView::Diff {
        let exact = renderer.render(
            &ctx,
            scene,
            &PlaneSettings::single(s.width, s.height, GpuMethod::Brdf),
        )?;
        settings.rel_floor = relative_floor(&exact.0);
    }
    let (frame, ms) = renderer.render(&ctx, scene, &settings)?;
    Ok((frame, format!("{} ({ms:.2} ms GPU)", ctx.describe())))
}

fn run_bench(
    lights: &[usize],
    size: (usize, usize),
    frames: usize,
    csv: Option<&Path>,
    checked: bool,
    lut_path: Option<&Path>,
    table: Table,
) -> Result<()> {
    check_frames_and_lights(frames, lights)?;
    if let Some(p) = csv {
        // Refuse a bad path before minutes of measuring.
        let dir = p
            .parent()
            .filter(|d| !d.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        if !dir.is_dir() {
            return Err(InputError::new(
                p.display().to_string(),
                "its directory does not exist",
            ));
        }
    }
    let lut = Lut::load(lut_path, table)?;
    let ctx = GpuContext::new()?;
    let device = ctx.describe();
    eprintln!("benchmarking on {device}");
    if !ctx.has_timestamps() {
        eprintln!(
            "warning: the adapter has no timestamp queries; times are wall clock (submit to done) and include driver overhead"
        );
    }
    let checks = if checked {
        ShaderChecks::Checked
    } else {
        ShaderChecks::Trusted
    };
    let rows = ltc_lab::bench::run(&ctx, &lut, lights, size, frames, checks, |r| {
        eprintln!(
            "  {:>9} {:>6} lights: {:.3} ms",
            r.method.name(),
            r.lights,
            r.ms_median
        );
    })?;
    print!("{}", ltc_lab::bench::markdown(&rows, &device));
    if let Some(p) = csv {
        let mut text = format!("{}\n", BenchRow::CSV_HEADER);
        for r in &rows {
            text.push_str(&r.csv());
            text.push('\n');
        }
        ltc_lab::error::write_atomically(p, text.as_bytes())?;
    }
    Ok(())
}

/// Opens the lab; with `screenshot`, saves the window after a few frames and exits.
fn run_lab(
    screenshot: Option<PathBuf>,
    panel: PanelArg,
    (w, h): (usize, usize),
    scene: Option<&Path>,
    measure: bool,
) -> Result<()> {
    use ltc_lab::app::{LabApp, LabState, PanelId, ScreenshotApp};
    let scene = scene.map(Scene::load).transpose()?;
    if let Some(p) = &screenshot
        && !p.extension().is_some_and(|e| e.eq_ignore_ascii_case("png"))
    {
        return Err(InputError::new(
            p.display().to_string(),
            "the screenshot must be a .png",
        ));
    }
    let maximised = match panel {
        PanelArg::Lobe => Some(PanelId::Lobe),
        PanelArg::Matrix => Some(PanelId::Matrix),
        PanelArg::Plane => Some(PanelId::Plane),
        PanelArg::Clipping => Some(PanelId::Clipping),
        PanelArg::Chart => Some(PanelId::Chart),
        PanelArg::All => None,
    };
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("LTC Lab")
            .with_inner_size([w as f32, h as f32]),
        renderer: eframe::Renderer::Wgpu,
        // A screenshot shows the defaults, not whatever the last session left.
        persist_window: screenshot.is_none(),
        ..Default::default()
    };
    let configure = move |mut state: LabState| {
        if let Some(sc) = &scene {
            state.light_count = sc.lights.len();
            state.scene = sc.clone();
        }
        if panel != PanelArg::All {
            state.maximised = maximised;
        }
        state
    };
    let outcome = match screenshot {
        Some(path) => {
            let result = std::sync::Arc::new(std::sync::Mutex::new(None));
            let slot = result.clone();
            let run = eframe::run_native(
                "LTC Lab (screenshot)",
                options,
                Box::new(move |_cc| {
                    let mut app = LabApp::new(configure(LabState::default()));
                    if measure {
                        app.chart.measure_now(&app.state.shaded_scene(), &app.lut);
                    }
                    Ok(Box::new(ScreenshotApp {
                        app,
                        path,
                        frames: 0,
                        result: slot,
                    }))
                }),
            );
            let taken = result.lock().expect("not poisoned").take();
            match (run, taken) {
                (Ok(()), Some(Ok(()))) => Ok(()),
                (Ok(()), Some(Err(e))) => Err(e),
                (Ok(()), None) => Err("the window closed before the screenshot".into()),
                (Err(e), _) => Err(e.to_string()),
            }
        }
        None => eframe::run_native(
            "LTC Lab",
            options,
            Box::new(move |cc| {
                let mut app = LabApp::from_creation_context(cc);
                app.state = configure(app.state);
                if measure {
                    app.chart.measure_now(&app.state.shaded_scene(), &app.lut);
                }
                Ok(Box::new(app))
            }),
        )
        .map_err(|e| e.to_string()),
    };
    outcome.map_err(|e| InputError::new("lab", format!("cannot open the window: {e}")))
}

/// `--frames` and `--lights` of `bench` and `study`.
fn check_frames_and_lights(frames: usize, lights: &[usize]) -> Result<()> {
    if frames == 0 {
        return Err(InputError::new("--frames", "must be at least 1"));
    }
    match lights
        .iter()
        .find(|&&n| n == 0 || n > ltc_lab::scene::MAX_LIGHTS)
    {
        Some(&n) => Err(InputError::new(
            "--lights",
            format!(
                "each count must be in 1..={}, got {n}",
                ltc_lab::scene::MAX_LIGHTS
            ),
        )),
        None => Ok(()),
    }
}

fn run_study(
    out: &Path,
    size: (usize, usize),
    lights: &[usize],
    alphas: &[f64],
    frames: usize,
) -> Result<()> {
    use ltc_lab::study;
    check_frames_and_lights(frames, lights)?;
    if let Some(&a) = alphas.iter().find(|&&a| !(a > 0.0 && a <= 1.0)) {
        return Err(InputError::new(
            "--alpha",
            format!("each α must be in (0, 1], got {a}"),
        ));
    }
    std::fs::create_dir_all(out)
        .map_err(|e| InputError::new(out.display().to_string(), format!("cannot create: {e}")))?;
    let ctx = GpuContext::new()?;
    let device = ctx.describe();
    eprintln!("study on {device}");
    let start = Instant::now();
    let rows = study::run(&ctx, Lut::embedded(), size, lights, alphas, frames, |r| {
        eprintln!(
            "  α {:<5} {:>6} lights {:>12}: {:9.3} ms, rel RMSE {:.2e}, p99 {:.2e}",
            r.alpha, r.lights, r.variant, r.ms_median, r.rel_rmse, r.p99_rel_err
        );
    })?;
    ltc_lab::error::write_atomically(&out.join("study.csv"), study::csv(&rows).as_bytes())?;
    study::pareto_png(&out.join("study.png"), &rows, &ctx.info.name)?;
    print!("{}", study::csv(&rows));
    eprintln!(
        "study done in {:.0} s; wrote {}/study.csv and study.png",
        start.elapsed().as_secs_f64(),
        out.display()
    );
    Ok(())
}
