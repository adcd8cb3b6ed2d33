//! LTC tables in and out of engines: this project's EXR, and selfshadow/ltc_code's layout —
//! its JavaScript arrays and DDS textures (read and written), a C header and WGSL (written).
//! A file is recognised by its content, its extension serving as a hint only where the
//! content is unreadable.

pub mod dds;
pub mod encoded;
pub mod formula;
pub mod js;
pub mod packing;
pub mod source;

use std::borrow::Cow;
use std::path::{Path, PathBuf};

use crate::error::{Error, Result};
use crate::files::Outputs;
use crate::ltc::lut::{Channel, Lut, Table};
use crate::named::named_enum;
use packing::Packed;

/// A table read from a file, with what the file could not hold.
#[derive(Clone, Debug)]
pub struct Loaded {
    pub lut: Cow<'static, Lut>,
    /// For ltc_code's layout: where the diffuse lobe and α_min came from. Every command that
    /// shades with the table says it.
    pub note: Option<String>,
    /// Whether `spec.err` holds a measurement. ltc_code's layout has no such channel, and
    /// measuring it costs about a millisecond a cell on one core (34 s for a 256² table on
    /// two), so a table read from it is measured only by what shows the error
    /// (`measure_spec_err`), never to shade.
    pub spec_err_measured: bool,
}

impl Loaded {
    /// Measures `spec.err` if the file did not hold it, calling `on_cell` after each cell.
    pub fn measure_spec_err(&mut self, on_cell: &(dyn Fn() + Sync)) {
        if !self.spec_err_measured {
            packing::measure_spec_err(self.lut.to_mut(), on_cell);
            self.spec_err_measured = true;
        }
    }
}

/// The shipped `table`, or the file at `path` in any format this module reads.
pub fn load(path: Option<&Path>, table: Table) -> Result<Loaded> {
    match path {
        Some(p) => read(p),
        None => Ok(Loaded {
            lut: Cow::Borrowed(Lut::shipped(table)),
            note: None,
            spec_err_measured: true,
        }),
    }
}

/// The EXR magic number (OpenEXR file layout, "magic number" 20000630).
const EXR_MAGIC: [u8; 4] = [0x76, 0x2f, 0x31, 0x01];

/// The sidecar that carries the header of a DDS pair (DDS has no room for comments).
pub const DDS_HEADER_FILE: &str = "ltc_dds.txt";

/// Reads a table: this project's EXR, ltc_code's `ltc.js`, or its `ltc_1.dds`/`ltc_2.dds`
/// (either file, or their directory).
pub fn read(path: &Path) -> Result<Loaded> {
    read_from(&Disk, path)
}

/// Reads a table from files given by name and bytes (picked in a browser, or dropped on the
/// window): one table file, or a DDS pair with its header sidecar.
pub fn read_given(files: &[(String, Vec<u8>)]) -> Result<Loaded> {
    let first = files
        .iter()
        .find(|(name, _)| !name.ends_with(DDS_HEADER_FILE))
        .ok_or_else(|| Error::input("the given files", "no table among them"))?;
    read_from(&Given(files), Path::new(&first.0))
}

/// Where a table's files are read from.
trait Source {
    fn bytes(&self, path: &Path) -> Result<Vec<u8>>;
    fn is_dir(&self, path: &Path) -> bool;
}

struct Disk;

impl Source for Disk {
    fn bytes(&self, path: &Path) -> Result<Vec<u8>> {
        crate::files::read_bytes(path, crate::ltc::lut::MAX_FILE_BYTES)
    }

    fn is_dir(&self, path: &Path) -> bool {
        path.is_dir()
    }
}

/// Files given by name: a path is found by its file name.
struct Given<'a>(&'a [(String, Vec<u8>)]);

impl Source for Given<'_> {
    fn bytes(&self, path: &Path) -> Result<Vec<u8>> {
        let file = path.file_name();
        self.0
            .iter()
            .find(|(name, _)| Path::new(name).file_name() == file)
            .map(|(_, bytes)| bytes.clone())
            .ok_or_else(|| {
                Error::input(
                    path.display().to_string(),
                    "was not given: pick (or drop) both files of a DDS pair at once",
                )
            })
    }

    fn is_dir(&self, _: &Path) -> bool {
        false
    }
}

fn read_from(source: &dyn Source, path: &Path) -> Result<Loaded> {
    let name = path.display().to_string();
    if source.is_dir(path) {
        return read_dds_pair(source, &path.join("ltc_1.dds"), &path.join("ltc_2.dds"));
    }
    let bytes = source.bytes(path)?;
    let ext = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    if bytes.starts_with(&EXR_MAGIC) {
        return native(Lut::from_exr_bytes(&bytes, &name)?);
    }
    if dds::looks_like(&bytes) || ext.as_deref() == Some("dds") {
        let (first, second) = dds_pair(path)?;
        return read_dds_pair(source, &first, &second);
    }
    let text = String::from_utf8_lossy(&bytes);
    if js::looks_like(&text) || ext.as_deref() == Some("js") {
        let packed = js::read(&text, &name)?;
        return foreign(
            &packed,
            header_alpha_min(&text),
            "ltc_code's JavaScript arrays",
            &name,
        );
    }
    if ext.as_deref() == Some("exr") {
        // Unreadable as anything: the EXR reader says what is wrong with it.
        return native(Lut::from_exr_bytes(&bytes, &name)?);
    }
    Err(Error::input(
        name,
        "not an LTC table this lab reads: OpenEXR (ltc-lab fit), ltc_code's ltc.js, or its ltc_1.dds and ltc_2.dds",
    ))
}

fn native(lut: Lut) -> Result<Loaded> {
    Ok(Loaded {
        lut: Cow::Owned(lut),
        note: None,
        spec_err_measured: true,
    })
}

/// The two files of a pair, from either: `…_1.dds` ↔ `…_2.dds`.
fn dds_pair(path: &Path) -> Result<(PathBuf, PathBuf)> {
    let file = path
        .file_name()
        .map(|f| f.to_string_lossy().into_owned())
        .unwrap_or_default();
    let sibling = |from: &str, to: &str| {
        file.rfind(from)
            .map(|k| path.with_file_name(format!("{}{to}{}", &file[..k], &file[k + from.len()..])))
    };
    if let Some(second) = sibling("_1.", "_2.") {
        Ok((path.to_path_buf(), second))
    } else if let Some(first) = sibling("_2.", "_1.") {
        Ok((first, path.to_path_buf()))
    } else {
        Err(Error::input(
            path.display().to_string(),
            "a DDS table is a pair named like ltc_1.dds and ltc_2.dds: give either, or their directory",
        ))
    }
}

fn read_dds_pair(source: &dyn Source, first: &Path, second: &Path) -> Result<Loaded> {
    let texture = |p: &Path| dds::read(&source.bytes(p)?, &p.display().to_string());
    let (n1, tex1, _) = texture(first)?;
    let (n2, tex2, _) = texture(second)?;
    let name = first.display().to_string();
    if n1 != n2 {
        return Err(Error::input(
            name,
            format!(
                "is {n1}×{n1} but {} is {n2}×{n2}: both textures have one texel per cell",
                second.display()
            ),
        ));
    }
    let sidecar = first.with_file_name(DDS_HEADER_FILE);
    let alpha_min = source
        .bytes(&sidecar)
        .ok()
        .and_then(|t| header_alpha_min(&String::from_utf8_lossy(&t)));
    let packed = Packed {
        size: n1,
        tex1,
        tex2,
    };
    foreign(&packed, alpha_min, "ltc_code's DDS textures", &name)
}

/// A table in ltc_code's layout: the specular lobe from it, the diffuse lobe from the
/// embedded table, `spec.err` not yet measured; validated as any table.
fn foreign(packed: &Packed, alpha_min: Option<f64>, what: &str, name: &str) -> Result<Loaded> {
    let (alpha_min, how) = match alpha_min {
        Some(a) if a > 0.0 && a < 1.0 => (a, "from its header"),
        _ => (
            packing::estimated_alpha_min(packed),
            "estimated from its normal-view cell (m22 ≈ 2α)",
        ),
    };
    let lut = packing::unpack(packed, alpha_min, Lut::embedded());
    lut.validate().map_err(|m| Error::input(name, m))?;
    Ok(Loaded {
        lut: Cow::Owned(lut),
        note: Some(format!(
            "{name}: {what} ({n}×{n}) hold the specular lobe only; the diffuse lobe is the embedded classic table's; spec.err is measured here where it is shown; α_min = {alpha_min:e} {how}",
            n = packed.size
        )),
        spec_err_measured: false,
    })
}

/// `alpha_min: X` from a header this module wrote.
fn header_alpha_min(text: &str) -> Option<f64> {
    let k = text.find("alpha_min:")?;
    text[k + "alpha_min:".len()..]
        .split_whitespace()
        .next()?
        .trim_end_matches(',')
        .parse()
        .ok()
}

/// What an export says about itself in its comment header.
#[derive(Clone, Debug, PartialEq)]
pub struct Header {
    /// Where the table came from (a file, or a shipped table).
    pub source: String,
    /// How it was fitted.
    pub objective: String,
    pub size: usize,
    pub alpha_min: f64,
}

impl Header {
    /// The header of `lut`, described as `source` (the objective read off `spec.scale`
    /// where the source does not say).
    pub fn new(lut: &Lut, source: &str, table: Option<Table>) -> Self {
        let fitted_scale = lut.cells.iter().any(|c| c.get(Channel::SpecScale) != 1.0);
        let objective = match table {
            Some(Table::Classic) => "ltc_code's (Σ|f·cos − n·D|³ / (pdf_ltc + pdf_brdf))",
            Some(Table::Point) => {
                "the point-light fit (∫|s·n·D − f·cos| / ∫ f·cos, a fitted scale s)"
            }
            Some(Table::Arrival) => {
                "the arrival-weighted point fit (∫|s·n·D − f·cos|·a / ∫ f·cos·a, a = 1/max(n·l, sin 5°))"
            }
            Some(Table::Constrained) => {
                "the constrained point fit (∫|s·n·D − f·cos| / ∫ f·cos with m20 = 0)"
            }
            None if fitted_scale => "a fitted magnitude scale: the point-light fit's form",
            None => "not recorded in the source (its magnitude scale is 1)",
        };
        Self {
            source: source.to_string(),
            objective: objective.to_string(),
            size: lut.size,
            alpha_min: lut.alpha_min,
        }
    }

    /// The header as comment lines, each starting with `prefix`: where the table comes from,
    /// then ltc_code's packing.
    pub fn comment(&self, prefix: &str) -> String {
        let packing = [
            "packing: selfshadow/ltc_code (fit/fitLTC.cpp packTab). Texel (a, t), index a + t*N:",
            "  ltc_1 = M^-1 / M^-1[1][1] as (m00, m20, m02, m22): M^-1 = mat3(vec3(x, 0, y), vec3(0, 1, 0), vec3(z, 0, w)) (columns)",
            "  ltc_2 = (magnitude, fresnel, 0, horizon-clipped sphere form factor); any fitted scale is folded into the first two",
            "  specular = F0 * ltc_2.x + (1 - F0) * ltc_2.y times D(l) = max((M^-1 l).z, 0) |det M^-1| / (pi |M^-1 l|^4), l unit",
            "lookup: uv = (sqrt(alpha), sqrt(1 - cos theta_o)) * (N - 1)/N + 0.5/N, bilinear, clamp to edge",
        ];
        let packing: String = packing.iter().map(|l| format!("{prefix}{l}\n")).collect();
        self.origin(prefix) + &packing + "\n"
    }

    /// Where the table comes from, as comment lines: what an encoding's export says before
    /// its own layout.
    pub fn origin(&self, prefix: &str) -> String {
        let n = self.size;
        [
            "LTC table for point lights (GGX specular), written by ltc-lab.".to_string(),
            format!("source: {}", self.source),
            format!("fit objective: {}", self.objective),
            format!("size: {n} x {n}, alpha_min: {:e}", self.alpha_min),
        ]
        .iter()
        .map(|l| format!("{prefix}{l}\n"))
        .collect::<String>()
    }
}

named_enum! {
    /// The formats `lut --export` writes.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub enum Export {
        LtcCodeJs = "ltc-code-js",
        LtcCodeDds = "ltc-code-dds",
        C = "c",
        Wgsl = "wgsl",
    }
}

impl Export {}

/// Writes `lut` as `encoding` gives it to the file `out` as a C header or WGSL: a table's
/// texels (`encoded::EncodedTable`), or a formula's coefficients (`formula::FormulaSource`);
/// ltc_code's layouts hold floats alone and are refused.
pub fn export_encoded(
    lut: &Lut,
    header: &Header,
    format: Export,
    encoding: crate::ltc::lut::Encoding,
    out: &Path,
) -> Result<Vec<PathBuf>> {
    let text = match (format, formula::FormulaSource::new(lut, encoding)) {
        (Export::C, Some(f)) => formula::c_header(&f, header),
        (Export::Wgsl, Some(f)) => formula::wgsl(&f, header),
        (Export::C | Export::Wgsl, None) => {
            let table = encoded::EncodedTable::new(lut, encoding)
                .map_err(|e| Error::input("--encode", e))?;
            match format {
                Export::C => encoded::c_header(&table, header),
                _ => encoded::wgsl(&table, header),
            }
        }
        (Export::LtcCodeJs | Export::LtcCodeDds, _) => {
            return Err(Error::input(
                "--encode",
                format!(
                    "{} holds ltc_code's float textures; an encoding is exported as c or wgsl",
                    format.name()
                ),
            ));
        }
    };
    write_one(out, text.into_bytes())
}

/// Writes `lut` as `format` to `out` (for DDS: a directory, made if missing, receiving
/// `ltc_1.dds`, `ltc_2.dds` and the header as `ltc_dds.txt`); all files or none. Returns the
/// files written.
pub fn export(
    lut: &Lut,
    header: &Header,
    format: Export,
    precision: dds::Precision,
    out: &Path,
) -> Result<Vec<PathBuf>> {
    let packed = packing::pack(lut);
    let text = match format {
        Export::LtcCodeDds => {
            let files = [
                (
                    "ltc_1.dds",
                    dds::write(&packed.tex1, packed.size, precision),
                ),
                (
                    "ltc_2.dds",
                    dds::write(&packed.tex2, packed.size, precision),
                ),
                (DDS_HEADER_FILE, header.comment("").into_bytes()),
            ];
            return write_files(out, &files);
        }
        Export::LtcCodeJs => js::write(&packed, header),
        Export::C => source::c_header(&packed, header),
        Export::Wgsl => source::wgsl(&packed, header),
    };
    write_one(out, text.into_bytes())
}

/// Writes `bytes` to the file `out` alone (staged, then moved into place).
fn write_one(out: &Path, bytes: Vec<u8>) -> Result<Vec<PathBuf>> {
    let name = out
        .file_name()
        .ok_or_else(|| Error::input(out.display().to_string(), "not a file path"))?
        .to_string_lossy()
        .into_owned();
    let dir = match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    write_files(&dir, &[(name.as_str(), bytes)])
}

/// Writes each `(name, bytes)` into `dir`: all of them or none.
fn write_files(dir: &Path, files: &[(&str, Vec<u8>)]) -> Result<Vec<PathBuf>> {
    let names: Vec<&str> = files.iter().map(|(n, _)| *n).collect();
    let mut outputs = Outputs::new(dir, &names)?;
    for (name, bytes) in files {
        outputs.stage(name, bytes)?;
    }
    outputs.commit()?;
    Ok(names.iter().map(|n| dir.join(n)).collect())
}
