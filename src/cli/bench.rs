//! `ltc-lab bench`: the paper's Table 1 on this machine's GPU, both methods in one run.

use std::path::PathBuf;

use ltc_lab::error::Result;
use ltc_lab::files::{check_writable, write_atomically};
use ltc_lab::gpu::GpuContext;
use ltc_lab::gpu::plane::ShaderChecks;
use ltc_lab::measure::bench::{BenchRow, BenchSettings};

use ltc_lab::ltc::remedy::Horizon;

use super::sizes::SizeArgs;
use super::{
    CullArgs, EncodingArgs, LutArgs, Range, check_frames_and_lights, horizon_parser, parse_size,
    print,
};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Light counts, comma-separated (default 100,500,1000,5000); not with --scene, which
    /// brings its own.
    #[arg(long, value_delimiter = ',')]
    lights: Option<Vec<usize>>,
    /// A scene file (TOML, as `render` takes) timed as given in place of the generated
    /// lights: its lights and their shapes (each point method's rows shade its sized lights by
    /// the lab's default method of their shape), camera and material.
    #[arg(long)]
    scene: Option<PathBuf>,
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
    #[command(flatten)]
    culling: CullArgs,
    #[command(flatten)]
    lut: LutArgs,
    #[command(flatten)]
    encoding: EncodingArgs,
    /// Horizon remedies, comma-separated: each LTC form is timed with eq30 and with each of
    /// these, in the same run (arrival-fit and constrained-fit with their own tables). See
    /// docs/design.md §4.7.
    #[arg(long, value_delimiter = ',', value_parser = horizon_parser(), default_value = "eq30")]
    horizon: Vec<Horizon>,
    #[command(flatten)]
    sizes: SizeArgs,
    /// Leave out the exact method of every shape with a size: the reference, whose 64 to 320
    /// BRDF evaluations per light take seconds a frame on a CPU adapter.
    #[arg(long)]
    skip_exact: bool,
    /// Also time the method in this WGSL file (docs/design.md §5.13) on every shape of the
    /// run it shades, in the same run; every method is then timed with runtime checks.
    #[arg(long)]
    method_file: Option<PathBuf>,
    /// Also time every run with the scene's material anisotropic, of this α_y (α_x the
    /// scene's α = 0.27, the tangent along x), right after the same run isotropic: the 4D
    /// table's cost against the 2D table's.
    #[arg(long)]
    alpha_y: Option<f64>,
}

pub fn run(a: &Args) -> Result<()> {
    let scene = a
        .scene
        .as_deref()
        .map(ltc_lab::scene::Scene::load)
        .transpose()?;
    let lights = match (&a.lights, &scene) {
        (Some(_), Some(_)) => {
            return Err(ltc_lab::error::Error::input(
                "--lights",
                "--scene brings its own lights",
            ));
        }
        (Some(l), None) => l.clone(),
        (None, Some(s)) => vec![s.lights.len()],
        (None, None) => vec![100, 500, 1000, 5000],
    };
    check_frames_and_lights(a.frames, &lights)?;
    let sizes = a.sizes.sizes()?;
    if let Some(y) = a.alpha_y
        && !(ltc_lab::ltc::lut::ALPHA_MIN..=1.0).contains(&y)
    {
        return Err(ltc_lab::error::Error::input(
            "--alpha-y",
            format!(
                "must be in [{}, 1], got {}",
                ltc_lab::ltc::lut::ALPHA_MIN,
                ltc_lab::error::number(y)
            ),
        ));
    }
    if let Some(p) = &a.csv {
        // Refuse a bad path before minutes of measuring.
        check_writable(p)?;
    }
    let method_file = a
        .method_file
        .as_deref()
        .map(ltc_lab::gpu::method_file::MethodFile::read)
        .transpose()?;
    if let Some(f) = &method_file {
        eprintln!(
            "{}: work per light from its IR: {}",
            f.name,
            ltc_lab::gpu::work::file_work_line(f)
        );
    }
    let lut = a.encoding.apply(a.lut.load()?);
    let ctx = GpuContext::new()?;
    ltc_lab::measure::bench::check(&ctx, &lights, a.size).map_err(super::flag_of)?;
    let device = ctx.describe();
    eprintln!("benchmarking on {device}");
    if !ctx.has_timestamps() {
        eprintln!(
            "warning: the adapter has no timestamp queries; times are wall clock (submit to done) and include driver overhead"
        );
    }
    if method_file.is_some() && !a.checked {
        eprintln!(
            "note: with a method file every method is timed with wgpu's runtime checks (as --checked)"
        );
    }
    let checks = if a.checked || method_file.is_some() {
        ShaderChecks::Checked
    } else {
        ShaderChecks::Trusted
    };
    let settings = BenchSettings {
        lights,
        size: a.size,
        frames: a.frames,
        checks,
        culls: a.culling.cull.clone(),
        range: Range::or_default(a.culling.range),
        horizons: a.horizon.clone(),
        sizes,
        skip_exact: a.skip_exact,
        method_file,
        alpha_y: a.alpha_y,
        scene,
    };
    let rows = ltc_lab::measure::bench::run(&ctx, &lut, &settings, |r| {
        eprintln!(
            "  {:>28} {:>6} lights, cull {:>3}: {:.3} ms",
            r.label(),
            r.lights,
            if r.cull { "on" } else { "off" },
            r.ms_median
        );
    })?;
    if let Some(p) = &a.csv {
        let mut text = format!("{}\n", BenchRow::CSV_HEADER);
        for r in &rows {
            text.push_str(&r.csv());
            text.push('\n');
        }
        write_atomically(p, text.as_bytes())?;
    }
    print(&ltc_lab::measure::bench_table::markdown(&rows, &device))
}
