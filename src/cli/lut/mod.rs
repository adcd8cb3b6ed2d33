//! `ltc-lab lut`: a table's summary, every cell as CSV, or the error atlas; its encodings
//! (`encodings.rs`).

mod encodings;

use std::path::PathBuf;

use ltc_lab::error::{Error, Result};
use ltc_lab::files::check_distinct;
use ltc_lab::ltc::formats::dds::Precision;
use ltc_lab::ltc::formats::{Export, Header, export, export_encoded};
use ltc_lab::ltc::lut::{Channel, Encoding};
use ltc_lab::measure::atlas::atlas_files;

use super::{LutArgs, one_of, print};

#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    lut: LutArgs,
    /// Print every cell as CSV: i,j,alpha,theta_o (degrees), then the channels.
    #[arg(long)]
    dump: bool,
    /// Write the error atlas into this directory (made if missing): heat maps of spec.err and
    /// diff.err, the error of one light orbiting a point, and their CSVs.
    #[arg(long)]
    atlas: Option<PathBuf>,
    /// Write the table in another layout: ltc-code-js (ltc_code's ltc.js), ltc-code-dds
    /// (its ltc_1.dds and ltc_2.dds), c (a header) or wgsl (const arrays and a lookup). The
    /// point table's fitted scale is folded into the magnitudes. aniso-texture writes the 4D
    /// table (--aniso-lut's, else the shipped one) as three RGBA32F 3D textures
    /// (ltc_aniso.bin) with a WGSL lookup (ltc_aniso.wgsl).
    #[arg(long, value_parser = one_of(&Written::ALL, Written::name), requires = "out")]
    export: Option<Written>,
    /// Write the table as an engine storing it in the encoding NAME reads it back
    /// (docs/design.md §2.10: f32, f16, unorm8 or unorm10, optionally -64, -32, -16 or -8 to
    /// resample; or a formula, chebD or rationalD, optionally -STORAGE), as this project's
    /// .exr, which --lut reads: shading with that file is shading with --encoding NAME. A
    /// resampled table's spec.err and diff.err are filtered, not measured. With --export c or
    /// wgsl, the table's texels in that storage instead, with their decoding.
    #[arg(long, value_parser = |s: &str| Encoding::parse(s), requires = "out", conflicts_with_all = ["dump", "atlas"])]
    encode: Option<Encoding>,
    /// Measure every encoding (docs/design.md §2.10: each storage at 64², 32², 16² and 8²)
    /// on every light shape: CSV on stdout, a row per encoding, shape, α band and θo band,
    /// with the error each adds against the f32 table and its total against the exact
    /// integral, per lobe.
    #[arg(long, conflicts_with_all = ["export", "encode", "dump", "atlas"])]
    encodings: bool,
    /// Print what a lookup of every encoding (and --formulas) costs in each layout
    /// (docs/design.md §2.10): two-texture (ltc_code's, widened to the diffuse lobe), fewest
    /// (one texture array, one sampler) and per-lookup (a formula evaluated per pixel), as
    /// CSV: bytes shipped and in texture memory, textures, samplers, fetches, multiply-adds.
    #[arg(long, conflicts_with_all = ["export", "encode", "dump", "atlas", "encodings"])]
    layouts: bool,
    /// Cases a band for --encodings (1–100000).
    #[arg(long, default_value_t = 64, requires = "encodings")]
    cases: usize,
    /// With --encodings, also the classic table fitted at each of these sizes (32, 16, 8;
    /// comma-separated) by `fit --size`, as rows `fit-SIZE` beside the resampled `f32-SIZE`.
    #[arg(long, value_delimiter = ',', requires = "encodings")]
    fitted: Vec<usize>,
    /// With --encodings or --layouts, also these formulas (docs/design.md §2.10): chebD, a Chebyshev series
    /// of degree D on each axis as three.js PR #34611 ships (1–40), rationalD, one rational
    /// function of total degree D (1–8), each optionally -STORAGE (cheb16-f16 is #34611's
    /// half-float rebuild), fitted to the table and rebuilt at its cells.
    #[arg(long, value_delimiter = ',', value_parser = |s: &str| Encoding::parse(s))]
    formulas: Vec<Encoding>,
    /// Where --export or --encode writes: a file, or for ltc-code-dds and aniso-texture a
    /// directory (made if missing).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Texels of ltc-code-dds: f16 (RGBA16F, as ltc_code writes them) or f32 (RGBA32F).
    #[arg(long, value_parser = one_of(&Precision::ALL, Precision::name), default_value = "f16")]
    precision: Precision,
}

/// What `--export` writes: the 2D table in a layout of `Export`, or the 4D table's textures.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Written {
    Table(Export),
    AnisoTexture,
}

impl Written {
    const ALL: [Self; 5] = [
        Self::Table(Export::LtcCodeJs),
        Self::Table(Export::LtcCodeDds),
        Self::Table(Export::C),
        Self::Table(Export::Wgsl),
        Self::AnisoTexture,
    ];

    fn name(self) -> &'static str {
        match self {
            Self::Table(e) => e.name(),
            Self::AnisoTexture => "aniso-texture",
        }
    }
}

pub fn run(a: &Args) -> Result<()> {
    if a.out.is_some() && a.export.is_none() && a.encode.is_none() {
        return Err(Error::input(
            "--out",
            "names where --export or --encode writes",
        ));
    }
    if let (Some(encoding), Some(out), None) = (a.encode, &a.out, a.export) {
        return encodings::write_encoded(a, encoding, out);
    }
    if a.encodings {
        return encodings::measure_encodings(a);
    }
    if a.layouts {
        return encodings::layouts(a);
    }
    if !a.formulas.is_empty() {
        return Err(Error::input(
            "--formulas",
            "is measured by --encodings or costed by --layouts: pass one of them",
        ));
    }
    check_export_beside_atlas(a)?;
    if let (Some(Written::AnisoTexture), Some(dir)) = (a.export, &a.out) {
        return export_aniso(a, dir);
    }
    // The dump and the atlas show spec.err; the summary and an export do not need it.
    let lut = if a.dump || a.atlas.is_some() {
        a.lut.load_measured()?
    } else {
        a.lut.load()?
    };
    if let (Some(Written::Table(format)), Some(out)) = (a.export, &a.out) {
        let shipped = a.lut.lut.is_none().then_some(a.lut.table());
        let header = Header::new(&lut, &a.lut.describe(), shipped);
        let written = match a.encode {
            Some(encoding) => export_encoded(&lut, &header, format, encoding, out)?,
            None => export(&lut, &header, format, a.precision, out)?,
        };
        let names: Vec<String> = written.iter().map(|p| p.display().to_string()).collect();
        eprintln!("wrote {}", names.join(", "));
        if a.atlas.is_none() && !a.dump {
            return Ok(());
        }
    }
    if a.export.is_some() && a.out.is_none() {
        return Err(Error::input("--export", "needs --out"));
    }
    if let Some(dir) = &a.atlas {
        let summary = ltc_lab::measure::atlas::write_atlas(&lut, dir)?;
        print(
            &summary
                .lines
                .iter()
                .map(|l| format!("{l}\n"))
                .collect::<String>(),
        )?;
        eprintln!("wrote the atlas into {}", dir.display());
        if !a.dump {
            return Ok(());
        }
    }
    if !a.dump {
        return print(&format!(
            "{}: {}×{} cells, α_min = {}, channels: {}\npass --dump for every cell as CSV\n",
            a.lut.describe(),
            lut.size,
            lut.size,
            lut.alpha_min,
            channel_names().join(" ")
        ));
    }
    let mut out = format!("i,j,alpha,theta_o,{}\n", channel_names().join(","));
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
    print(&out)
}

/// A file export must be neither the atlas directory nor one of its files: one output would
/// replace the other, or fail after the first was written.
fn check_export_beside_atlas(a: &Args) -> Result<()> {
    let (Some(format), Some(out), Some(dir)) = (a.export, &a.out, &a.atlas) else {
        return Ok(());
    };
    // ltc-code-dds and aniso-texture write a directory of their own names, none of them an
    // atlas file.
    if matches!(
        format,
        Written::Table(Export::LtcCodeDds) | Written::AnisoTexture
    ) {
        return Ok(());
    }
    let files: Vec<PathBuf> = atlas_files().iter().map(|f| dir.join(f)).collect();
    let mut outputs = vec![("--atlas", dir.as_path())];
    outputs.extend(files.iter().map(|f| ("--atlas", f.as_path())));
    outputs.push(("--out", out.as_path()));
    check_distinct(&outputs)
}

/// `--export aniso-texture`: the 4D table's textures and lookup into `dir` (made if
/// missing), both files or neither; the bytes are said.
fn export_aniso(a: &Args, dir: &std::path::Path) -> Result<()> {
    use ltc_lab::gpu::ltc_aniso::export;
    let lut = a.lut.load()?;
    let table = lut.aniso();
    let header = format!(
        "{}\nfrom {}",
        export::describe(table),
        a.lut.describe_aniso()
    );
    let bytes = export::texture_bytes(table);
    let files = [
        (export::TEXTURE_FILE, bytes.clone()),
        (export::WGSL_FILE, export::wgsl(table, &header).into_bytes()),
    ];
    let names = files.each_ref().map(|(n, _)| *n);
    let mut outputs = ltc_lab::files::Outputs::new(dir, &names)?;
    for (name, data) in &files {
        outputs.stage(name, data)?;
    }
    outputs.commit()?;
    let [w, h, d] = export::texture_size(table);
    eprintln!(
        "wrote {} ({} bytes: three RGBA32F 3D textures of {w}×{h}×{d}) and {}",
        dir.join(export::TEXTURE_FILE).display(),
        bytes.len(),
        dir.join(export::WGSL_FILE).display()
    );
    Ok(())
}

/// The channels' names in a cell's order.
fn channel_names() -> Vec<&'static str> {
    Channel::ALL.map(Channel::name).to_vec()
}
