//! The LTC look-up table of docs/design.md §2: an N×N f32 EXR (x = column i ↔ roughness, y = row j ↔
//! view angle) with 14 named channels, its bilinear sampler (exactly the GPU's addressing),
//! and the shipped 64×64 table embedded in the binary.

use std::io::Cursor;
use std::path::Path;
use std::sync::OnceLock;

use exr::prelude::*;
use glam::DVec3;

use crate::error::{Error, Result};
use crate::files::write_atomically;
use crate::ltc::lobe::Lobe;
use crate::ltc::{Ltc, LtcPair, cos_from_brdf_from_entries, mat3_rows};

/// α_min = 1e-4, the `MIN_ALPHA` of ltc_code's published fit. Smaller (ltc_code's later 1e-5)
/// makes the r = 0 lobe a near-delta whose `M⁻¹` entries grow like 1/α (1e5) — an f32
/// bilinear blend with the next column is then meaningless; larger (a fork's 5e-4, Unity's
/// 1e-3) clamps the r = 1/63 column (α = r² = 2.5e-4) onto the r = 0 one, so the table loses
/// a column of its resolution. Any value below 2.5e-4 keeps every column distinct.
pub const ALPHA_MIN: f64 = 1e-4;

/// The largest table this program reads, in cells per side, checked before anything is
/// allocated: 4096² cells hold 940 MB as f32 (14 channels), 64 times the shipped 64² per axis
/// and 4 times the largest `ltc-lab fit` makes (1024); a file that claims more is refused.
pub const MAX_SIZE: usize = 4096;

/// Refuses a table side outside `2..=MAX_SIZE`, naming what claimed it.
pub fn check_size(width: usize, height: usize) -> std::result::Result<usize, String> {
    if width != height || width < 2 {
        return Err(format!(
            "the table is {width}×{height}: a table is square, at least 2×2"
        ));
    }
    if width > MAX_SIZE {
        return Err(format!(
            "the table claims {width}×{width} cells: this program reads tables of at most {MAX_SIZE}×{MAX_SIZE}"
        ));
    }
    Ok(width)
}

/// The fewest bytes an OpenEXR chunk takes: its 8-byte entry in the offset table, and its
/// y coordinate and data size (4 bytes each) before any data.
const EXR_MIN_CHUNK_BYTES: usize = 16;

/// ltc_code clamps θo just below 90° (1.57 rad) so that the grazing row has `n·v > 0`.
pub const THETA_MAX: f64 = 1.57;

/// The LUT axes of docs/design.md §2: column `i` ↔ `r = i/(N−1)`, `α = max(r², α_min)`.
pub fn cell_alpha(i: usize, size: usize, alpha_min: f64) -> f64 {
    let r = i as f64 / (size - 1) as f64;
    (r * r).max(alpha_min)
}

/// Row `j` ↔ `sqrt(1 − cos θo) = j/(N−1)`, θo clamped to `THETA_MAX`.
pub fn cell_theta(j: usize, size: usize) -> f64 {
    let x = j as f64 / (size - 1) as f64;
    (1.0 - x * x).clamp(-1.0, 1.0).acos().min(THETA_MAX)
}

/// The stored form of docs/design.md §2: `M⁻¹` divided by its middle element, as
/// `[m00, m02, m20, m22]` of `[[m00, 0, m02], [0, 1, 0], [m20, 0, m22]]`.
pub fn normalized_cos_from_brdf(ltc: &Ltc) -> [f64; 4] {
    let r = mat3_rows(ltc.cos_from_brdf);
    let s = r[1][1];
    [r[0][0] / s, r[0][2] / s, r[2][0] / s, r[2][2] / s]
}

/// The channels in docs/design.md §2's order; `Channel as usize` indexes a cell.
pub const CHANNEL_NAMES: [&str; CHANNEL_COUNT] = [
    "spec.m00",
    "spec.m02",
    "spec.m20",
    "spec.m22",
    "spec.norm",
    "spec.fresnel",
    "spec.err",
    "diff.m00",
    "diff.m02",
    "diff.m20",
    "diff.m22",
    "diff.norm",
    "diff.err",
    "spec.scale",
];
pub const CHANNEL_COUNT: usize = 14;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Channel {
    SpecM00,
    SpecM02,
    SpecM20,
    SpecM22,
    SpecNorm,
    SpecFresnel,
    SpecErr,
    DiffM00,
    DiffM02,
    DiffM20,
    DiffM22,
    DiffNorm,
    DiffErr,
    /// The fitted factor on the specular magnitude (`Ltc::scale`): 1 in the classic table.
    SpecScale,
}

impl Channel {
    /// A lobe's four stored entries of `M⁻¹`: `m00, m02, m20, m22`.
    pub fn entries(lobe: Lobe) -> [Self; 4] {
        use Channel::*;
        match lobe {
            Lobe::Specular => [SpecM00, SpecM02, SpecM20, SpecM22],
            Lobe::Diffuse => [DiffM00, DiffM02, DiffM20, DiffM22],
        }
    }

    /// A lobe's pointwise error.
    pub fn err(lobe: Lobe) -> Self {
        match lobe {
            Lobe::Specular => Self::SpecErr,
            Lobe::Diffuse => Self::DiffErr,
        }
    }
}

/// The values a channel may hold in a table that any fit could have made, and why.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChannelLimits {
    pub min: f64,
    /// Whether `min` itself is refused (albedos and scales divide and multiply).
    pub min_excluded: bool,
    pub max: f64,
    pub why: &'static str,
}

impl ChannelLimits {
    pub fn contains(&self, x: f64) -> bool {
        (if self.min_excluded {
            x > self.min
        } else {
            x >= self.min
        }) && x <= self.max
    }

    /// `[a, b]` or `(a, b]`.
    pub fn interval(&self) -> String {
        let open = if self.min_excluded { '(' } else { '[' };
        format!("{open}{}, {}]", self.min, self.max)
    }
}

/// The limits of channel `c` (an index into `CHANNEL_NAMES`).
pub fn channel_limits(c: usize) -> ChannelLimits {
    use Channel::*;
    let limits = |min, min_excluded, max, why| ChannelLimits {
        min,
        min_excluded,
        max,
        why,
    };
    match c {
        c if c == SpecNorm as usize || c == SpecFresnel as usize => limits(
            0.0,
            c == SpecNorm as usize,
            // 1.05 for the albedo, times the fits' largest scale (1.1), which tables in
            // ltc_code's layout carry folded into these channels.
            1.05 * 1.1 * (1.0 + f64::from(f32::EPSILON)),
            "GGX's directional albedo is at most 1 (single scattering only loses energy), 5% for estimation noise, times the fitted scale (at most 1.1) that ltc_code's layout folds in",
        ),
        c if c == DiffNorm as usize => limits(
            0.0,
            true,
            6.25,
            "Burley's fd·cos integrates to at most FD² = (0.5 + 2α)² ≤ 6.25; the shipped fits reach 1.56 at α = 1",
        ),
        c if c == SpecScale as usize => limits(
            0.0,
            true,
            // The fits' cap (`point_params::SCALE_MAX`), as f32 rounds it up.
            1.1 * (1.0 + f64::from(f32::EPSILON)),
            "a fitted factor on the albedo: 1 in the classic fit, 0.5–1.004 in the point fit, up to 1.1 (the fits' cap) in the arrival fit",
        ),
        c if c == SpecErr as usize || c == DiffErr as usize => limits(
            0.0,
            false,
            4.0,
            "a relative L1 distance of two lobes of near-equal mass, at most 2.05; twice that for estimation noise",
        ),
        _ => limits(
            -100.0,
            false,
            100.0,
            "M⁻¹ divided by its middle element: ltc_code's and this project's fits stay below 2 in magnitude",
        ),
    }
}

/// The header attribute that records α_min (the `alpha` of column 0).
const ALPHA_MIN_ATTRIBUTE: &str = "ltc.alpha_min";

/// The shipped table (`luts/ltc.exr`, made by `ltc-lab fit`), so the lab runs from anywhere.
pub const EMBEDDED_EXR: &[u8] = include_bytes!("../../luts/ltc.exr");

/// The shipped point-light fit (`luts/ltc_point.exr`, `ltc-lab fit --objective point`).
pub const EMBEDDED_POINT_EXR: &[u8] = include_bytes!("../../luts/ltc_point.exr");

/// The arrival-weighted point fit (`luts/ltc_arrival.exr`, `ltc-lab fit --objective arrival`).
pub const EMBEDDED_ARRIVAL_EXR: &[u8] = include_bytes!("../../luts/ltc_arrival.exr");

/// The horizon-constrained point fit (`luts/ltc_constrained.exr`,
/// `ltc-lab fit --objective constrained`).
pub const EMBEDDED_CONSTRAINED_EXR: &[u8] = include_bytes!("../../luts/ltc_constrained.exr");

/// Which shipped table (and the objective that fitted it).
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
pub enum Table {
    /// ltc_code's objective (`luts/ltc.exr`).
    #[default]
    Classic,
    /// The point-light objective (`luts/ltc_point.exr`).
    Point,
    /// The point-light objective weighted by where lights above a plane arrive from, the
    /// horizon included (`luts/ltc_arrival.exr`; docs/design.md §4.7).
    Arrival,
    /// The point-light objective with `m20 = 0`, so that `M⁻¹` never carries a direction
    /// across the horizon (`luts/ltc_constrained.exr`; docs/design.md §4.7).
    Constrained,
}

impl Table {
    pub const ALL: [Self; 4] = [Self::Classic, Self::Point, Self::Arrival, Self::Constrained];

    pub fn name(self) -> &'static str {
        match self {
            Self::Classic => "classic",
            Self::Point => "point",
            Self::Arrival => "arrival",
            Self::Constrained => "constrained",
        }
    }

    /// The shipped file's path in the repository.
    pub fn path(self) -> &'static str {
        match self {
            Self::Classic => "luts/ltc.exr",
            Self::Point => "luts/ltc_point.exr",
            Self::Arrival => "luts/ltc_arrival.exr",
            Self::Constrained => "luts/ltc_constrained.exr",
        }
    }

    fn bytes(self) -> &'static [u8] {
        match self {
            Self::Classic => EMBEDDED_EXR,
            Self::Point => EMBEDDED_POINT_EXR,
            Self::Arrival => EMBEDDED_ARRIVAL_EXR,
            Self::Constrained => EMBEDDED_CONSTRAINED_EXR,
        }
    }

    /// The table a lab compares with this one: the classic table, or the point table
    /// beside the classic one.
    pub fn other(self) -> Self {
        match self {
            Self::Classic => Self::Point,
            _ => Self::Classic,
        }
    }
}

/// One cell: the channels of `CHANNEL_NAMES`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LutCell(pub [f32; CHANNEL_COUNT]);

impl LutCell {
    /// From fitted lobes: `M⁻¹` normalized by its middle element (docs/design.md §2).
    pub fn from_fits(spec: &Ltc, spec_err: f64, diff: &Ltc, diff_err: f64) -> Self {
        let s = normalized_cos_from_brdf(spec);
        let d = normalized_cos_from_brdf(diff);
        let values = [
            s[0],
            s[1],
            s[2],
            s[3],
            spec.norm,
            spec.fresnel,
            spec_err,
            d[0],
            d[1],
            d[2],
            d[3],
            diff.norm,
            diff_err,
            spec.scale,
        ];
        Self(values.map(|x| x as f32))
    }

    pub fn get(&self, c: Channel) -> f32 {
        self.0[c as usize]
    }

    /// Channel `c` as the table is shaded with it: the specular magnitudes with the fitted
    /// scale folded in per cell, as ltc_code's layout stores them (docs/design.md §2), so that
    /// a table and its export filter the same products and shade alike.
    pub fn shaded(&self, c: usize) -> f64 {
        let x = f64::from(self.0[c]);
        if c == Channel::SpecNorm as usize || c == Channel::SpecFresnel as usize {
            f64::from(self.0[Channel::SpecScale as usize]) * x
        } else {
            x
        }
    }
}

/// What an EXR's header claims, checked before its pixels are allocated: every layer within
/// `MAX_SIZE`, and the file long enough for the chunks it declares (a header claiming 100000²
/// over a 4×4 body would otherwise allocate 40 GB first).
fn check_exr_header(bytes: &[u8]) -> std::result::Result<(), String> {
    // Unreadable headers are left to the full reader, which says what is wrong.
    let Ok(meta) = exr::meta::MetaData::read_from_buffered(Cursor::new(bytes), false) else {
        return Ok(());
    };
    let mut chunks = 0usize;
    for header in &meta.headers {
        let size = header.layer_size;
        check_size(size.width(), size.height())?;
        chunks = chunks.saturating_add(header.chunk_count);
    }
    let least = chunks.saturating_mul(EXR_MIN_CHUNK_BYTES);
    if bytes.len() < least {
        return Err(format!(
            "its header declares {chunks} chunks (at least {least} bytes) but the file holds {} bytes: it is cut short or its header is wrong",
            bytes.len()
        ));
    }
    Ok(())
}

/// A sampled cell in f64: what the renderer and `eval` use. `spec.norm` and `spec.fresnel`
/// hold the filtered products `spec.scale × magnitude` (`LutCell::shaded`), `spec.scale` the
/// filtered scale.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LutSample(pub [f64; CHANNEL_COUNT]);

impl LutSample {
    /// One cell, unfiltered.
    pub fn of_cell(cell: &LutCell) -> Self {
        Self(std::array::from_fn(|c| cell.shaded(c)))
    }

    pub fn get(&self, c: Channel) -> f64 {
        self.0[c as usize]
    }

    /// Both lobes as `Ltc`s: `M⁻¹ = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]]`. The specular
    /// magnitudes are divided by the filtered scale, so that `norm` stays the albedo while
    /// `scale × norm` is the filtered product the table shades with.
    pub fn ltc_pair(&self) -> LtcPair {
        use Channel::*;
        let lobe = |lobe: Lobe, norm: f64, fresnel: f64| {
            let m = cos_from_brdf_from_entries(Channel::entries(lobe).map(|c| self.get(c)));
            Ltc::from_cos_from_brdf(m, norm, fresnel)
        };
        let scale = self.get(SpecScale);
        LtcPair {
            spec: lobe(
                Lobe::Specular,
                self.get(SpecNorm) / scale,
                self.get(SpecFresnel) / scale,
            )
            .with_scale(scale),
            diff: lobe(Lobe::Diffuse, self.get(DiffNorm), 0.0),
        }
    }
}

/// One axis of bilinear filtering with clamp-to-edge addressing at coordinate `t` of a table
/// of `n` cells: the two texels (clamped into the table) and the weight of the second.
pub fn bilinear_taps(n: usize, t: f64) -> (usize, usize, f64) {
    let x = if t.is_finite() {
        t * n as f64 - 0.5
    } else {
        0.0
    };
    let x0 = x.floor();
    let clamp = |k: f64| k.clamp(0.0, (n - 1) as f64) as usize;
    (clamp(x0), clamp(x0 + 1.0), x - x0)
}

/// An N×N table; `cells[j * size + i]`.
#[derive(Clone, Debug, Default)]
pub struct Lut {
    pub size: usize,
    pub alpha_min: f64,
    pub cells: Vec<LutCell>,
    /// The `nl-fit` correction of each cell (`crate::ltc::nl_fit::nl_terms`), fitted on
    /// first use; the cells must not change after it.
    pub nl_terms: OnceLock<Vec<[f64; 4]>>,
}

impl PartialEq for Lut {
    /// The same cells: whether the correction was fitted yet does not matter.
    fn eq(&self, other: &Self) -> bool {
        (self.size, self.alpha_min) == (other.size, other.alpha_min) && self.cells == other.cells
    }
}

impl Lut {
    /// The table embedded in the binary (parsed once).
    pub fn embedded() -> &'static Lut {
        Lut::shipped(Table::Classic)
    }

    /// Reads and validates a LUT file; errors name the file.
    pub fn read(path: &Path) -> Result<Lut> {
        let name = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|e| Error::io(&name, "read", &e))?;
        Lut::from_exr_bytes(&bytes, &name)
    }

    /// The shipped point-light table (parsed once).
    pub fn embedded_point() -> &'static Lut {
        Lut::shipped(Table::Point)
    }

    /// One of the shipped tables (each parsed once).
    pub fn shipped(table: Table) -> &'static Lut {
        static PARSED: [OnceLock<Lut>; Table::ALL.len()] = [const { OnceLock::new() }; 4];
        PARSED[table as usize].get_or_init(|| {
            Lut::from_exr_bytes(table.bytes(), &format!("embedded {}", table.path()))
                .expect("the embedded tables are checked by the test suite")
        })
    }

    pub fn from_exr_bytes(bytes: &[u8], name: &str) -> Result<Lut> {
        let bad = |m: String| Error::input(name, m);
        check_exr_header(bytes).map_err(bad)?;
        let image = read()
            .no_deep_data()
            .largest_resolution_level()
            .all_channels()
            .first_valid_layer()
            .all_attributes()
            .from_buffered(Cursor::new(bytes))
            .map_err(|e| bad(format!("not a readable OpenEXR LTC table ({e})")))?;
        let layer = &image.layer_data;
        let (w, h) = (layer.size.width(), layer.size.height());
        check_size(w, h).map_err(bad)?;
        // Written as f64 by this project; another writer may use f32.
        let alpha_min = match layer.attributes.other.get(&Text::from(ALPHA_MIN_ATTRIBUTE)) {
            Some(AttributeValue::F64(a)) => *a,
            Some(AttributeValue::F32(a)) => f64::from(*a),
            Some(other) => {
                return Err(bad(format!(
                    "attribute {ALPHA_MIN_ATTRIBUTE} is not a number ({other:?})"
                )));
            }
            None => return Err(bad(format!("attribute {ALPHA_MIN_ATTRIBUTE} is missing"))),
        };
        if !(alpha_min > 0.0 && alpha_min < 1.0) {
            return Err(bad(format!(
                "attribute {ALPHA_MIN_ATTRIBUTE} must be in (0, 1), got {}",
                crate::error::number(alpha_min)
            )));
        }
        let mut cells = vec![LutCell([0.0; CHANNEL_COUNT]); w * h];
        for (c, channel_name) in CHANNEL_NAMES.iter().enumerate() {
            let Some(channel) = layer
                .channel_data
                .list
                .iter()
                .find(|ch| ch.name == **channel_name)
            else {
                // docs/design.md §2's 13 channels make a complete table: without the point fit's
                // scale, the magnitudes are used as they are.
                if c == Channel::SpecScale as usize {
                    cells.iter_mut().for_each(|cell| cell.0[c] = 1.0);
                    continue;
                }
                return Err(bad(format!("channel {channel_name} is missing")));
            };
            let FlatSamples::F32(samples) = &channel.sample_data else {
                return Err(bad(format!("channel {channel_name} is not 32-bit float")));
            };
            for (k, &x) in samples.iter().enumerate() {
                if !x.is_finite() {
                    return Err(bad(format!(
                        "channel {channel_name} at cell (i={}, j={}) is {x}",
                        k % w,
                        k / w
                    )));
                }
                cells[k].0[c] = x;
            }
        }
        let lut = Lut {
            nl_terms: Default::default(),
            size: w,
            alpha_min,
            cells,
        };
        lut.validate().map_err(bad)?;
        Ok(lut)
    }

    /// Values no fit produces: a channel outside `channel_limits`, or a singular or
    /// reflecting `M⁻¹`.
    pub fn validate(&self) -> std::result::Result<(), String> {
        for (k, cell) in self.cells.iter().enumerate() {
            let at = format!("cell (i={}, j={})", k % self.size, k / self.size);
            for (c, name) in CHANNEL_NAMES.iter().enumerate() {
                let x = f64::from(cell.0[c]);
                let limits = channel_limits(c);
                if !limits.contains(x) {
                    return Err(format!(
                        "{name} at {at} is {}, outside {} ({})",
                        crate::error::number(x),
                        limits.interval(),
                        limits.why
                    ));
                }
            }
            for lobe in Lobe::BOTH {
                let [m00, m02, m20, m22] = Channel::entries(lobe).map(|c| f64::from(cell.get(c)));
                let det = m00 * m22 - m02 * m20;
                if det <= 0.0 {
                    return Err(format!(
                        "the {} matrix at {at} has determinant {} (must be > 0)",
                        &CHANNEL_NAMES[Channel::entries(lobe)[0] as usize][..4],
                        crate::error::number(det)
                    ));
                }
            }
        }
        Ok(())
    }

    pub fn to_exr_bytes(&self) -> Vec<u8> {
        let n = self.size;
        let channels = CHANNEL_NAMES
            .iter()
            .enumerate()
            .map(|(c, name)| {
                AnyChannel::new(
                    *name,
                    FlatSamples::F32(self.cells.iter().map(|cell| cell.0[c]).collect()),
                )
            })
            .collect();
        let mut attributes = LayerAttributes::named("ltc");
        attributes.other.insert(
            Text::from(ALPHA_MIN_ATTRIBUTE),
            AttributeValue::F64(self.alpha_min),
        );
        // ZIP is lossless: the round trip is bit-exact.
        let encoding = Encoding {
            compression: Compression::ZIP16,
            ..Encoding::default()
        };
        let layer = Layer::new((n, n), attributes, encoding, AnyChannels::sort(channels));
        let mut out = Cursor::new(Vec::new());
        Image::from_layer(layer)
            .write()
            // Parallel compression writes chunks in the order they finish: the same table
            // would give different bytes run to run.
            .non_parallel()
            .to_buffered(&mut out)
            .expect("writing an EXR to memory cannot fail");
        out.into_inner()
    }

    /// Writes the table to `path` (atomically: no partial file on failure).
    pub fn write(&self, path: &Path) -> Result<()> {
        write_atomically(path, &self.to_exr_bytes())
    }

    pub fn cell(&self, i: usize, j: usize) -> &LutCell {
        &self.cells[j * self.size + i]
    }

    /// The GPU texture coordinate of docs/design.md §2:
    /// `uv = (r, sqrt(1 − cos θo)) · (N−1)/N + 0.5/N`, `r = sqrt(α)`.
    pub fn uv(&self, alpha: f64, cos_theta_o: f64) -> (f64, f64) {
        let r = alpha.max(0.0).sqrt();
        let s = (1.0 - cos_theta_o.clamp(0.0, 1.0)).sqrt();
        self.uv_of_axes(r, s)
    }

    /// The texture coordinate of the table's axes `(r, s)`, each in [0, 1]: cell `(i, j)` of
    /// any N sits at `(i/(N−1), j/(N−1))` — also the grazing row, whose θo is clamped.
    pub fn uv_of_axes(&self, r: f64, s: f64) -> (f64, f64) {
        let n = self.size as f64;
        let scale = (n - 1.0) / n;
        let bias = 0.5 / n;
        (r * scale + bias, s * scale + bias)
    }

    /// Bilinear filtering at `uv` with clamp-to-edge addressing, as a GPU sampler does it:
    /// texel centres at `(k + ½)/N`, the four nearest texels clamped into the table.
    pub fn sample_uv(&self, u: f64, v: f64) -> LutSample {
        let (i0, i1, fx) = bilinear_taps(self.size, u);
        let (j0, j1, fy) = bilinear_taps(self.size, v);
        let (c00, c10, c01, c11) = (
            self.cell(i0, j0),
            self.cell(i1, j0),
            self.cell(i0, j1),
            self.cell(i1, j1),
        );
        LutSample(std::array::from_fn(|c| {
            let top = c00.shaded(c) * (1.0 - fx) + c10.shaded(c) * fx;
            let bottom = c01.shaded(c) * (1.0 - fx) + c11.shaded(c) * fx;
            top * (1.0 - fy) + bottom * fy
        }))
    }

    /// The table at `(α, cos θo)`, bilinearly filtered.
    pub fn sample(&self, alpha: f64, cos_theta_o: f64) -> LutSample {
        let (u, v) = self.uv(alpha, cos_theta_o);
        self.sample_uv(u, v)
    }

    /// The nearest cell at `(α, cos θo)` (what a nearest-filtering sampler returns).
    pub fn sample_nearest(&self, alpha: f64, cos_theta_o: f64) -> LutSample {
        let (u, v) = self.uv(alpha, cos_theta_o);
        let n = self.size;
        let index = |t: f64| ((t * n as f64).floor().max(0.0) as usize).min(n - 1);
        LutSample::of_cell(self.cell(index(u), index(v)))
    }

    /// The LTCs for a view `v` (unit, shading frame) and roughness.
    pub fn ltc_pair(&self, alpha: f64, v: DVec3) -> LtcPair {
        self.sample(alpha, v.z).ltc_pair()
    }

    /// α of column `i` (docs/design.md §2).
    pub fn alpha(&self, i: usize) -> f64 {
        cell_alpha(i, self.size, self.alpha_min)
    }

    /// θo (radians) of row `j` (docs/design.md §2).
    pub fn theta_o(&self, j: usize) -> f64 {
        cell_theta(j, self.size)
    }
}
