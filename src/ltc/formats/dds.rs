//! ltc_code's DDS textures (`fit/export.h` `writeDDS`, `fit/dds.cpp` `SaveDDS`): one
//! uncompressed RGBA16F or RGBA32F texture per file, `ltc_1.dds` and `ltc_2.dds`, behind the
//! legacy 128-byte header with a Direct3D format code as its FourCC (113 = A16B16G16R16F,
//! 116 = A32B32G32R32F). Reading also takes the DX10 extension header (DXGI formats 10 and 2),
//! which older ltc_code versions and other tools write.

use half::f16;

use crate::error::{Error, Result};
use crate::ltc::lut::check_size;
use crate::named::named_enum;

named_enum! {
    /// Texel precision of a DDS texture.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub enum Precision {
        /// RGBA16F: what ltc_code writes.
        F16 = "f16",
        F32 = "f32",
    }
}

impl Precision {
    fn texel_bytes(self) -> usize {
        match self {
            Self::F16 => 8,
            Self::F32 => 16,
        }
    }

    /// The FourCC of the legacy header: D3DFMT_A16B16G16R16F or D3DFMT_A32B32G32R32F.
    fn fourcc(self) -> u32 {
        match self {
            Self::F16 => 113,
            Self::F32 => 116,
        }
    }
}

const MAGIC: &[u8; 4] = b"DDS ";
const HEADER_BYTES: usize = 4 + 124;
/// DDSD_CAPS | DDSD_HEIGHT | DDSD_WIDTH | DDSD_PIXELFORMAT | DDSD_PITCH, as `SaveDDS` sets.
const FLAGS: u32 = 0x100F;
/// DDPF_FOURCC.
const PF_FOURCC: u32 = 0x4;
/// DDSCAPS_TEXTURE.
const CAPS_TEXTURE: u32 = 0x1000;
/// "DX10": an extension header follows.
const FOURCC_DX10: u32 = u32::from_le_bytes(*b"DX10");
/// DXGI_FORMAT_R16G16B16A16_FLOAT and DXGI_FORMAT_R32G32B32A32_FLOAT.
const DXGI_RGBA16F: u32 = 10;
const DXGI_RGBA32F: u32 = 2;

/// Whether `bytes` begin like a DDS file.
pub fn looks_like(bytes: &[u8]) -> bool {
    bytes.starts_with(MAGIC)
}

/// An `n × n` texture as ltc_code writes it.
pub fn write(texels: &[[f32; 4]], n: usize, precision: Precision) -> Vec<u8> {
    let mut out = Vec::with_capacity(HEADER_BYTES + texels.len() * precision.texel_bytes());
    out.extend_from_slice(MAGIC);
    let mut header = [0u32; 31];
    header[0] = 124; // dwSize
    header[1] = FLAGS;
    header[2] = n as u32; // dwHeight
    header[3] = n as u32; // dwWidth
    header[4] = (n * precision.texel_bytes()) as u32; // dwPitchOrLinearSize
    header[5] = 1; // dwDepth
    header[6] = 1; // dwMipMapCount
    // dwReserved1[11] at 7..18; the pixel format at 18..26.
    header[18] = 32; // ddspf.dwSize
    header[19] = PF_FOURCC;
    header[20] = precision.fourcc();
    header[26] = CAPS_TEXTURE; // dwCaps
    for word in header {
        out.extend_from_slice(&word.to_le_bytes());
    }
    for t in texels {
        for &x in t {
            match precision {
                Precision::F16 => out.extend_from_slice(&f16::from_f32(x).to_le_bytes()),
                Precision::F32 => out.extend_from_slice(&x.to_le_bytes()),
            }
        }
    }
    out
}

/// A square RGBA16F or RGBA32F texture: its side, texels and precision.
pub fn read(bytes: &[u8], name: &str) -> Result<(usize, Vec<[f32; 4]>, Precision)> {
    let bad = |m: String| Error::input(name, m);
    if !looks_like(bytes) || bytes.len() < HEADER_BYTES {
        return Err(bad("not a DDS file (no 'DDS ' header)".into()));
    }
    let word = |k: usize| {
        let at = 4 + 4 * k;
        u32::from_le_bytes([bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]])
    };
    let (height, width) = (word(2) as usize, word(3) as usize);
    let (pf_flags, fourcc) = (word(19), word(20));
    let (precision, data_start) = if pf_flags & PF_FOURCC == 0 {
        return Err(bad(
            "its pixel format has no FourCC: ltc_code's tables are RGBA16F or RGBA32F".into(),
        ));
    } else if fourcc == FOURCC_DX10 {
        if bytes.len() < HEADER_BYTES + 20 {
            return Err(bad("its DX10 header is cut short".into()));
        }
        let dxgi = u32::from_le_bytes(bytes[HEADER_BYTES..HEADER_BYTES + 4].try_into().unwrap());
        let precision = match dxgi {
            DXGI_RGBA16F => Precision::F16,
            DXGI_RGBA32F => Precision::F32,
            other => {
                return Err(bad(format!(
                    "DXGI format {other}: ltc_code's tables are RGBA16F (10) or RGBA32F (2)"
                )));
            }
        };
        (precision, HEADER_BYTES + 20)
    } else {
        let precision = Precision::ALL
            .into_iter()
            .find(|p| p.fourcc() == fourcc)
            .ok_or_else(|| {
                bad(format!(
                    "pixel format {} (FourCC {fourcc}): ltc_code's tables are RGBA16F (113) or RGBA32F (116)",
                    fourcc_text(fourcc)
                ))
            })?;
        (precision, HEADER_BYTES)
    };
    let width = check_size(width, height).map_err(bad)?;
    // Within MAX_SIZE the byte count cannot overflow; checked all the same, since a header
    // that claims 2^30×2^30 once wrapped it to 0.
    let need = width
        .checked_mul(width)
        .and_then(|cells| cells.checked_mul(precision.texel_bytes()))
        .ok_or_else(|| {
            bad(format!(
                "a {width}×{width} texture has more bytes than fit in memory"
            ))
        })?;
    let data = &bytes[data_start..];
    if data.len() < need {
        return Err(bad(format!(
            "{width}×{width} {} texels need {need} bytes; the file holds {}",
            precision.name(),
            data.len()
        )));
    }
    let texels = data[..need]
        .chunks_exact(precision.texel_bytes())
        .map(|t| {
            std::array::from_fn(|c| match precision {
                Precision::F16 => f16::from_le_bytes([t[2 * c], t[2 * c + 1]]).to_f32(),
                Precision::F32 => f32::from_le_bytes(t[4 * c..4 * c + 4].try_into().unwrap()),
            })
        })
        .collect::<Vec<[f32; 4]>>();
    if let Some(k) = texels.iter().position(|t| t.iter().any(|x| !x.is_finite())) {
        return Err(bad(format!(
            "texel ({}, {}) is not finite: {:?}",
            k % width,
            k / width,
            texels[k]
        )));
    }
    Ok((width, texels, precision))
}

/// A FourCC as text where it is four printable characters ("DXT1"), else its number.
fn fourcc_text(fourcc: u32) -> String {
    let b = fourcc.to_le_bytes();
    if b.iter().all(u8::is_ascii_graphic) {
        String::from_utf8_lossy(&b).into_owned()
    } else {
        fourcc.to_string()
    }
}
