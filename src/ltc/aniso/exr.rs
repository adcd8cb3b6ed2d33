//! A 4D table as a file (docs/design.md §2.9): one OpenEXR layer of f32 pixels holding the
//! nodes in a 2D layout, `x = a + N_a · b`, `y = t + N_t · p` (so that the image's row-major
//! order is `AnisoLut::index`'s), a channel per stored entry and magnitude, and the axes, the
//! node counts and which matrix is stored in header attributes.

use std::io::Cursor;
use std::path::Path;

use exr::prelude::*;

use crate::error::{Error, Result};
use crate::files::write_atomically;
use crate::ltc::aniso::{AnisoAxes, AnisoCell, AnisoLut, Stored};

/// The channels, in this order: `M⁻¹`'s entries by rows, the magnitudes, the node's error.
pub const CHANNELS: [&str; 12] = [
    "m00", "m01", "m02", "m10", "m11", "m12", "m20", "m21", "m22", "norm", "fresnel", "err",
];

/// The most nodes per axis a file may claim, checked before anything is allocated: 64⁴
/// nodes of 12 f32 channels are 800 MB.
pub const MAX_NODES_PER_AXIS: usize = 64;

/// The most bytes of a 4D table file this program reads (a 64⁴ table uncompressed is 805 MB;
/// one that size must come compressed).
pub const MAX_FILE_BYTES: u64 = 256 << 20;

/// The one header attribute that says what the table is: `axes=<AnisoAxes::name>
/// stored=<Stored::name> dims=<Na>x<Nb>x<Nt>x<Np>`. One attribute, because the EXR writer keeps
/// its attributes in a hash map, whose order (and so the file's bytes) changes run to run.
const ATTRIBUTE: &str = "ltc.aniso";

impl AnisoAxes {
    /// Its name in a file's header.
    pub fn name(self) -> &'static str {
        match self {
            Self::Lab => "lab",
            Self::I3dAlphaXY => "i3d-alphax-alphay",
            Self::I3dAlphaLambda => "i3d-alpha-lambda",
        }
    }
}

impl Stored {
    /// Its name in a file's header.
    pub fn name(self) -> &'static str {
        match self {
            Self::CosFromBrdf => "cos_from_brdf",
            Self::BrdfFromCos => "brdf_from_cos",
            Self::MirrorFromCos => "mirror_from_cos",
            Self::MirrorPole => "mirror_pole",
        }
    }
}

/// A text attribute of the layer, or why it is missing.
fn text(layer: &LayerAttributes, key: &str) -> std::result::Result<String, String> {
    match layer.other.get(&Text::from(key)) {
        Some(AttributeValue::Text(t)) => Ok(t.to_string()),
        Some(other) => Err(format!("attribute {key} is not text ({other:?})")),
        None => Err(format!("attribute {key} is missing")),
    }
}

/// What the attribute says: the axes, the stored matrix, the node counts.
fn parse_attribute(s: &str) -> std::result::Result<(AnisoAxes, Stored, [usize; 4]), String> {
    let field = |key: &str| {
        s.split_whitespace()
            .find_map(|f| f.strip_prefix(&format!("{key}=")))
            .ok_or(format!("{ATTRIBUTE} '{s}' has no {key}="))
    };
    let axes = field("axes")?;
    let axes = AnisoAxes::ALL
        .into_iter()
        .find(|a| a.name() == axes)
        .ok_or(format!("{ATTRIBUTE}: '{axes}' is not a known kind of axes"))?;
    let stored = field("stored")?;
    let stored = Stored::ALL
        .into_iter()
        .find(|k| k.name() == stored)
        .ok_or(format!("{ATTRIBUTE}: '{stored}' is not a stored matrix"))?;
    let dims_text = field("dims")?;
    let parts: Vec<usize> = dims_text
        .split('x')
        .map(|p| {
            p.parse::<usize>()
                .map_err(|_| format!("{ATTRIBUTE}: dims '{dims_text}'"))
        })
        .collect::<std::result::Result<_, _>>()?;
    let dims: [usize; 4] = parts
        .try_into()
        .map_err(|_| format!("{ATTRIBUTE}: dims '{dims_text}': four node counts expected"))?;
    if dims.iter().any(|&n| !(2..=MAX_NODES_PER_AXIS).contains(&n)) {
        return Err(format!(
            "{ATTRIBUTE}: dims '{dims_text}': each axis holds 2 to {MAX_NODES_PER_AXIS} nodes"
        ));
    }
    Ok((axes, stored, dims))
}

impl AnisoLut {
    /// Reads and validates a 4D table file; errors name the file.
    pub fn read(path: &Path) -> Result<AnisoLut> {
        let name = path.display().to_string();
        let bytes = crate::files::read_bytes(path, MAX_FILE_BYTES)?;
        AnisoLut::from_exr_bytes(&bytes, &name)
    }

    pub fn from_exr_bytes(bytes: &[u8], name: &str) -> Result<AnisoLut> {
        let bad = |m: String| Error::input(name, m);
        // The header first: the node counts bound what the pixels may allocate.
        let meta = exr::meta::MetaData::read_from_buffered(Cursor::new(bytes), false)
            .map_err(|e| bad(format!("not a readable OpenEXR 4D table ({e})")))?;
        let header = meta.headers.first().ok_or_else(|| bad("no layer".into()))?;
        let (axes, stored, dims) =
            parse_attribute(&text(&header.own_attributes, ATTRIBUTE).map_err(bad)?).map_err(bad)?;
        let (w, h) = (dims[0] * dims[1], dims[2] * dims[3]);
        if (header.layer_size.width(), header.layer_size.height()) != (w, h) {
            return Err(bad(format!(
                "the image is {}×{}, but {dims:?} nodes make {w}×{h}",
                header.layer_size.width(),
                header.layer_size.height()
            )));
        }
        let image = read()
            .no_deep_data()
            .largest_resolution_level()
            .all_channels()
            .first_valid_layer()
            .all_attributes()
            .from_buffered(Cursor::new(bytes))
            .map_err(|e| bad(format!("not a readable OpenEXR 4D table ({e})")))?;
        let layer = &image.layer_data;
        let mut values = vec![[0.0f32; 12]; w * h];
        for (c, channel_name) in CHANNELS.iter().enumerate() {
            let Some(channel) = layer
                .channel_data
                .list
                .iter()
                .find(|ch| ch.name == **channel_name)
            else {
                return Err(bad(format!("channel {channel_name} is missing")));
            };
            let FlatSamples::F32(samples) = &channel.sample_data else {
                return Err(bad(format!("channel {channel_name} is not 32-bit float")));
            };
            for (k, &x) in samples.iter().enumerate() {
                values[k][c] = x;
            }
        }
        let lut = AnisoLut {
            axes,
            dims,
            stored,
            cells: values
                .iter()
                .map(|v| AnisoCell {
                    m: std::array::from_fn(|e| v[e]),
                    norm: v[9],
                    fresnel: v[10],
                    err: v[11],
                })
                .collect(),
        };
        lut.validate().map_err(bad)?;
        Ok(lut)
    }

    /// Why the table cannot shade, naming the first node at fault: every value finite, the
    /// magnitudes those of a lobe (`norm` in (0, 1.05], `fresnel` in [0, norm]), the error in
    /// [0, 4], and every stored matrix proper (a positive determinant, the canonical form).
    pub fn validate(&self) -> std::result::Result<(), String> {
        for k in self.nodes() {
            let c = self.cell(k);
            let at = |what: &str| format!("node {k:?}: {what}");
            if c.m
                .iter()
                .chain([&c.norm, &c.fresnel])
                .any(|x| !x.is_finite())
            {
                return Err(at("a value is not finite"));
            }
            // 1.05: the 2D table's bound on an albedo estimated by sampling (§2.5).
            if !(c.norm > 0.0 && c.norm <= 1.05 && c.fresnel >= 0.0 && c.fresnel <= c.norm) {
                return Err(at(&format!(
                    "magnitudes norm {} and fresnel {} are not a lobe's",
                    c.norm, c.fresnel
                )));
            }
            if !(c.err.is_nan() || (0.0..=4.0).contains(&c.err)) {
                return Err(at(&format!("err {} is outside [0, 4]", c.err)));
            }
            self.stored.check(c.matrix()).map_err(at)?;
        }
        for c in super::all_nodes(self.dims.map(|n| n - 1)) {
            let corners: Vec<glam::DMat3> = (0..16usize)
                .map(|corner| {
                    let k: [usize; 4] = std::array::from_fn(|axis| c[axis] + (corner >> axis & 1));
                    self.cell(k).matrix()
                })
                .collect();
            if !super::poles_agree(self.stored, &corners) {
                return Err(format!(
                    "the cell at {c:?}: its nodes' poles are in no one hemisphere, so a blend of them can vanish"
                ));
            }
        }
        Ok(())
    }

    pub fn to_exr_bytes(&self) -> Vec<u8> {
        let (w, h) = (self.dims[0] * self.dims[1], self.dims[2] * self.dims[3]);
        let channels = CHANNELS
            .iter()
            .enumerate()
            .map(|(e, name)| {
                let value = |c: &AnisoCell| match e {
                    0..=8 => c.m[e],
                    9 => c.norm,
                    10 => c.fresnel,
                    _ => c.err,
                };
                AnyChannel::new(
                    *name,
                    FlatSamples::F32(self.cells.iter().map(value).collect()),
                )
            })
            .collect();
        let mut attributes = LayerAttributes::named("ltc-aniso");
        let value = format!(
            "axes={} stored={} dims={}",
            self.axes.name(),
            self.stored.name(),
            self.dims.map(|n| n.to_string()).join("x")
        );
        attributes.other.insert(
            Text::from(ATTRIBUTE),
            AttributeValue::Text(Text::from(value.as_str())),
        );
        crate::ltc::exr_bytes::layer_bytes((w, h), attributes, channels)
    }

    /// Writes the table to `path` (atomically: no partial file on failure).
    pub fn write(&self, path: &Path) -> Result<()> {
        write_atomically(path, &self.to_exr_bytes())
    }
}
