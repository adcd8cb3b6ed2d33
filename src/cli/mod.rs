//! The command line of docs/design.md §6, one module per subcommand; here what they share: the
//! argument parsers built from the library's own names (the library knows no clap), the LUT
//! choice, and standard output that ends quietly on a closed pipe.

pub mod bench;
pub mod eval;
pub mod fit;
pub mod lab;
pub mod lut;
pub mod method_for;
pub mod render;
pub mod sizes;
pub mod study;

use std::borrow::Cow;
use std::io::Write;
use std::path::PathBuf;

use clap::builder::{PossibleValuesParser, TypedValueParser};
use clap::{Parser, Subcommand};

use ltc_lab::error::{Error, Result};
use ltc_lab::gpu::limits::{LimitError, Limited};
use ltc_lab::ltc::aniso::source::AnisoSource;
use ltc_lab::ltc::formats;
use ltc_lab::ltc::lut::{Encoding, Lut, Table};
use ltc_lab::ltc::remedy::Horizon;

#[derive(Parser, Debug)]
#[command(
    name = "ltc-lab",
    version,
    about = "Point lights shaded with Linearly Transformed Cosines: fit, evaluate, render, measure.",
    after_help = "Exit codes: 0 done; 1 the machine failed (no GPU adapter, a GPU or I/O error); 2 bad input (a file, an argument or a value, named on stderr); 130 interrupted (SIGINT, SIGTERM or SIGHUP), with every unfinished output removed."
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Open the lab (the default with no subcommand).
    Lab(lab::Args),
    /// Fit both lobes (GGX specular, Burley diffuse) over an N×N (θo, α) table and write the LUT.
    Fit(fit::Args),
    /// Evaluate the exact lobes and their LTC approximation for the cases of a CSV file.
    Eval(eval::Args),
    /// Inspect a LUT: a summary, every cell as CSV, or the error atlas.
    Lut(lut::Args),
    /// Render a scene to PNG (tone-mapped) or EXR (linear radiance), on the GPU (default) or
    /// the CPU reference.
    Render(render::Args),
    /// The paper's Table 1 on this machine's GPU: every method at each light count.
    Bench(bench::Args),
    /// Speed against accuracy: every variant timed on the GPU and compared with the exact
    /// image, per light count and roughness; writes study.csv and study.png (Pareto chart).
    Study(study::Args),
}

/// A clap parser for one of a library enum's values, by the name the library gives it.
pub fn one_of<T: Copy + Send + Sync + 'static>(
    all: &'static [T],
    name: fn(T) -> &'static str,
) -> impl TypedValueParser<Value = T> {
    PossibleValuesParser::new(all.iter().map(|&t| name(t))).map(move |s| {
        *all.iter()
            .find(|&&t| name(t) == s)
            .expect("clap accepted one of the names")
    })
}

/// The largest image side `--size` accepts: 16K, beyond any display, small enough that a
/// typo cannot ask for terabytes.
pub const MAX_IMAGE_SIDE: usize = 16384;

/// `--size WxH`.
pub fn parse_size(s: &str) -> std::result::Result<(usize, usize), String> {
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

/// The LTC table a command shades with: a file, or one of the shipped ones.
#[derive(clap::Args, Debug, Clone)]
pub struct LutArgs {
    /// A LUT file instead of the embedded one: this project's .exr, ltc_code's ltc.js (or
    /// three.js's copy of it), or its ltc_1.dds / ltc_2.dds (either file, or their directory).
    #[arg(long)]
    pub lut: Option<PathBuf>,
    /// Which shipped table: classic (ltc_code's fit, the default), point (the point-light
    /// fit), arrival or constrained (the horizon remedies' fits).
    #[arg(long, value_parser = one_of(&Table::ALL, Table::name))]
    pub table: Option<Table>,
    /// The 4D table anisotropic materials read (docs/design.md §2.9): lab (the shipped fit,
    /// luts/ltc_aniso.exr), i3d-alphax-alphay or i3d-alpha-lambda (I3D 2022's tables, read as
    /// an engine reads them, with the lab's magnitudes), or a file `fit --aniso` wrote.
    #[arg(long, value_parser = aniso_parser())]
    pub aniso_lut: Option<AnisoSource>,
}

/// `--aniso-lut` and `--aniso-b`: a 4D table by name or file.
pub fn aniso_parser() -> impl TypedValueParser<Value = AnisoSource> {
    clap::builder::StringValueParser::new().map(|s| AnisoSource::parse(&s))
}

/// `lut` with its 4D table replaced by `aniso`'s where one is asked for.
pub fn with_aniso(
    lut: Cow<'static, Lut>,
    aniso: Option<&AnisoSource>,
) -> Result<Cow<'static, Lut>> {
    match aniso {
        Some(source) => Ok(Cow::Owned(lut.into_owned().with_aniso(source.load()?))),
        None => Ok(lut),
    }
}

/// `lut` as `encoding` gives it back, what it clamped said on stderr as a note.
pub fn decoded_saying(encoding: Encoding, lut: &Lut) -> Lut {
    let (decoded, note) = encoding.decoded_saying(lut);
    if let Some(note) = note {
        eprintln!("ltc-lab: note: {note}");
    }
    decoded
}

/// `--encoding`: the table as an engine storing it so reads it back (docs/design.md §2.10).
#[derive(clap::Args, Debug, Clone)]
pub struct EncodingArgs {
    /// Shade with the table as an engine storing it so reads it back (docs/design.md §2.10):
    /// STORAGE (f32, f16, unorm8, unorm10) or STORAGE-SIZE (SIZE 64, 32, 16 or 8: resampled
    /// first), or a formula rebuilt into the table's cells, chebD or rationalD (-STORAGE);
    /// f32 is the table itself.
    #[arg(long, value_parser = |s: &str| Encoding::parse(s))]
    pub encoding: Option<Encoding>,
}

impl EncodingArgs {
    /// `lut` as the encoding asked for decodes it (`lut` itself without one).
    pub fn apply(&self, lut: Cow<'static, Lut>) -> Cow<'static, Lut> {
        match self.encoding {
            Some(encoding) => Cow::Owned(decoded_saying(encoding, &lut)),
            None => lut,
        }
    }

    /// What a table's name gains: ` as f16-32`, or nothing.
    pub fn suffix(&self) -> String {
        self.encoding
            .map_or(String::new(), |e| format!(" as {}", e.name()))
    }
}

/// `--horizon`'s help: what LTC does for lights near the horizon (docs/design.md §4.7).
pub const HORIZON_HELP: &str = "What LTC does for lights near the horizon (docs/design.md §4.7): eq30 (the paper's clipping alone), arrival-fit and constrained-fit (shaded with the shipped arrival and constrained tables), nl-fit (each lobe scaled by a fitted quadratic in n·l below 30°), exact-band (the exact BRDF below 15°)";

/// `--horizon NAME`.
pub fn horizon_parser() -> impl TypedValueParser<Value = Horizon> {
    one_of(&Horizon::ALL, Horizon::name)
}

impl LutArgs {
    /// The shipped table asked for: `--table`, or the classic one.
    pub fn table(&self) -> Table {
        self.table.unwrap_or_default()
    }

    /// `--lut` and `--table` for a command shading with one horizon remedy: a remedy that
    /// is a table cannot shade with another one.
    pub fn check_horizon(&self, horizon: Horizon) -> Result<()> {
        match horizon.table() {
            Some(own) if self.lut.is_some() || self.table.is_some_and(|t| t != own) => {
                Err(Error::input(
                    "--horizon",
                    format!(
                        "{} is the {} table ({}): it takes no --lut or other --table",
                        horizon.name(),
                        own.name(),
                        own.path()
                    ),
                ))
            }
            _ => Ok(()),
        }
    }

    /// The table a remedy shades with: its own where it is a table, else this one.
    pub fn load_for(&self, horizon: Horizon) -> Result<Cow<'static, Lut>> {
        match horizon.table() {
            Some(own) => with_aniso(Cow::Borrowed(Lut::shipped(own)), self.aniso_lut.as_ref()),
            None => self.load(),
        }
    }

    /// The table to shade with; what a foreign layout could not hold is said on stderr.
    pub fn load(&self) -> Result<Cow<'static, Lut>> {
        Ok(self.loaded()?.lut)
    }

    /// The table with its `spec.err` measured, for what shows it: a table in ltc_code's
    /// layout does not hold it, and is measured here behind a progress bar.
    pub fn load_measured(&self) -> Result<Cow<'static, Lut>> {
        let mut loaded = self.loaded()?;
        if !loaded.spec_err_measured {
            let bar = progress_bar("measuring spec.err", loaded.lut.cells.len());
            loaded.measure_spec_err(&|| bar.inc(1));
            bar.finish_and_clear();
        }
        Ok(loaded.lut)
    }

    fn loaded(&self) -> Result<formats::Loaded> {
        let mut loaded = formats::load(self.lut.as_deref(), self.table())?;
        if let Some(note) = &loaded.note {
            eprintln!("ltc-lab: note: {note}");
        }
        loaded.lut = with_aniso(loaded.lut, self.aniso_lut.as_ref())?;
        Ok(loaded)
    }

    /// The table's name, for a column: the shipped table's name or the file's path.
    pub fn name(&self) -> String {
        let table = self.table();
        self.lut
            .as_ref()
            .map_or(table.name().to_string(), |p| p.display().to_string())
    }

    /// What the table is, for messages.
    /// Where the table shaded with under `horizon` comes from.
    pub fn source(&self, horizon: Horizon) -> ltc_lab::tables::Source {
        use ltc_lab::tables::Source;
        match (horizon.table(), &self.lut) {
            (Some(own), _) => Source::Shipped(own),
            (None, Some(p)) => Source::File(p.display().to_string()),
            (None, None) => Source::Shipped(self.table()),
        }
    }

    /// The 4D table's name, as `describe` names the 2D one.
    pub fn describe_aniso(&self) -> String {
        self.aniso_lut.clone().unwrap_or(AnisoSource::Lab).name()
    }

    pub fn describe(&self) -> String {
        let table = self.table();
        match &self.lut {
            Some(p) => p.display().to_string(),
            None => format!("the embedded {} table ({})", table.name(), table.path()),
        }
    }
}

/// `bench`'s and `study`'s culling: which passes, and every light's range.
#[derive(clap::Args, Debug, Clone)]
pub struct CullArgs {
    /// Tiled culling of ranged lights: off, on, or both (off,on) in one run; the images are
    /// the same.
    #[arg(long, value_delimiter = ',', default_value = "on", value_parser = parse_cull)]
    pub cull: Vec<bool>,
    /// Every light's range (scene units, or inf); default paper-100's 2.
    #[arg(long, value_parser = parse_range)]
    pub range: Option<Range>,
}

/// `--cull on|off` (each of a list, for `bench` and `study`).
pub fn parse_cull(s: &str) -> std::result::Result<bool, String> {
    match s {
        "on" => Ok(true),
        "off" => Ok(false),
        _ => Err(format!("'{s}' is neither on nor off")),
    }
}

/// `--range R`: every light's range in scene units (`None`: infinite).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Range(pub Option<f64>);

/// `--range R`: a range > 0, or `inf`.
pub fn parse_range(s: &str) -> std::result::Result<Range, String> {
    if s == "inf" {
        return Ok(Range(None));
    }
    s.parse::<f64>()
        .ok()
        .filter(|r| r.is_finite() && *r > 0.0)
        .map(|r| Range(Some(r)))
        .ok_or_else(|| format!("'{s}' is not a range > 0 (or inf)"))
}

impl Range {
    /// The range asked for, or paper-100's.
    pub fn or_default(range: Option<Range>) -> Option<f64> {
        range.map_or(Some(ltc_lab::measure::bench::DEFAULT_RANGE), |r| r.0)
    }
}

/// A progress bar on stderr (drawn only on a terminal) counting `len` cells.
pub fn progress_bar(what: &str, len: usize) -> indicatif::ProgressBar {
    progress_bar_of(what, len, "cells")
}

/// A progress bar on stderr (drawn only on a terminal) counting `len` of `unit`.
pub fn progress_bar_of(what: &str, len: usize, unit: &str) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(len as u64);
    bar.set_style(
        indicatif::ProgressStyle::with_template(&format!(
            "{what} {{bar:40}} {{pos}}/{{len}} {unit}  {{elapsed_precise}}"
        ))
        .expect("a valid template"),
    );
    bar
}

/// The most timed frames `bench` and `study` take per measurement: a median of 10 000 frames
/// is stable far below the spread between runs, and a run stays within hours even at a
/// second a frame; more is a typo that would run for ever.
pub const MAX_FRAMES: usize = 10_000;

/// `--frames` and `--lights` of `bench` and `study`.
pub fn check_frames_and_lights(frames: usize, lights: &[usize]) -> Result<()> {
    if !(1..=MAX_FRAMES).contains(&frames) {
        return Err(Error::input(
            "--frames",
            format!("must be in 1..={MAX_FRAMES}, got {frames}"),
        ));
    }
    let max = ltc_lab::scene::MAX_LIGHTS;
    match lights.iter().find(|&&n| n == 0 || n > max) {
        Some(&n) => Err(Error::input(
            "--lights",
            format!("each count must be in 1..={max}, got {n}"),
        )),
        None => Ok(()),
    }
}

/// A value beyond the adapter's limits, named by the flag it came from.
pub fn flag_of(e: LimitError) -> Error {
    let flag = match e.value {
        Limited::ImageSize => "--size",
        Limited::LightCount => "--lights",
        Limited::TableSize => "--lut",
    };
    e.named(flag)
}

/// Writes `text` to standard output. A closed pipe (`| head -1`) ends the output quietly: the
/// reader has what it wanted. Any other failure (`> /dev/full`) is the machine's.
pub fn print(text: &str) -> Result<()> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(Error::io("standard output", "write", &e)),
        Ok(()) => Ok(()),
    }
}

/// `--sphere-radius`, `--rect-half-edge` and `--disk-radius` (bench, study): a size a scene's
/// light may have, and not 0 (that is the point rows): a radius of at least `MIN_RADIUS`, a
/// square of half-edge at least `MIN_RADIUS` (so `|half_u × half_v| ≥ MIN_RADIUS²`, as a
/// scene requires).
pub(crate) fn check_size(flag: &str, r: f64) -> Result<()> {
    let (lo, hi) = (ltc_lab::scene::MIN_RADIUS, ltc_lab::scene::MAX_COORDINATE);
    if (lo..=hi).contains(&r) {
        return Ok(());
    }
    Err(ltc_lab::error::Error::input(
        flag,
        format!("must be in [{lo}, {hi}] scene units, got {r}"),
    ))
}
