//! How an encoded table is laid out in textures (docs/design.md §2.10), and what one lookup
//! costs in each layout: textures, samplers, filtered fetches and the arithmetic after them.
//! The lab itself reads the decoded table from one f32 storage buffer through its own
//! bilinear filter (`lut_sample_uv` in ltc.wgsl); these are the layouts an engine ships.

use crate::ltc::lut::encoding::{Encoding, SHADER_CHANNELS, Storage};
use crate::named::named_enum;

named_enum! {
    /// Where the shader's channels go.
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
    pub enum Layout {
        /// ltc_code's: a texture for `M⁻¹`'s four entries and one for the magnitudes (its
        /// `ltc_1` and `ltc_2`), with the lab's diffuse lobe the same again: specular `M⁻¹`,
        /// the three magnitudes together, diffuse `M⁻¹` — a sampler per texture, as ltc_code
        /// and three.js bind them.
        TwoTexture = "two-texture",
        /// The fewest samplers, as Filament packs its tables (its rect-light PR #8020 was
        /// closed for adding two samplers): every texel of a cell a layer of one texture
        /// array, read through one sampler.
        Fewest = "fewest",
        /// No texture: a formula evaluated per lookup (`chebD`, `rationalD`); a table has none.
        PerLookup = "per-lookup",
    }
}

/// The groups of channels `TwoTexture` keeps together: specular `M⁻¹`, the magnitudes
/// (specular norm and Fresnel, diffuse norm), diffuse `M⁻¹`.
const GROUPS: [usize; 3] = [4, 3, 4];

/// Shader arithmetic of any lookup before the fetches: `lut_uv`'s two square roots and two
/// multiply-adds (docs/design.md §2.3), counted as four.
const UV_OPS: usize = 4;

/// What one lookup of an encoded table costs in a layout, and the bytes it takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LookupCost {
    /// Bytes shipped (`Encoding::bytes`).
    pub shipped_bytes: usize,
    /// Bytes of texture memory at run time, texels padded to four values (or RGB10A2's three).
    pub texture_bytes: usize,
    pub textures: usize,
    pub samplers: usize,
    /// Filtered texture fetches a lookup.
    pub fetches: usize,
    /// Multiply-adds a lookup besides the fetches' filtering: the coordinates, a fixed-point
    /// value's scale and bias per channel, or the whole formula.
    pub multiply_adds: usize,
}

impl Layout {
    /// `encoding` of a table of `size` cells a side in this layout; `None` where they do not
    /// go together (a table per lookup, or a formula's rebuilt table per lookup is its formula).
    pub fn cost(self, encoding: &Encoding, size: usize) -> Option<LookupCost> {
        let shipped_bytes = encoding.bytes(size);
        if self == Self::PerLookup {
            // A formula evaluated per pixel is evaluated in f32; a storage is for its texture.
            if encoding.storage != Storage::F32 {
                return None;
            }
            let formula = encoding.formula?.for_size(size);
            return Some(LookupCost {
                shipped_bytes,
                texture_bytes: 0,
                textures: 0,
                samplers: 0,
                fetches: 0,
                multiply_adds: formula.multiply_adds(),
            });
        }
        let per_texel = encoding.storage.values_per_texel();
        let texels_per_cell: usize = match self {
            Self::TwoTexture => GROUPS.iter().map(|g| g.div_ceil(per_texel)).sum(),
            _ => SHADER_CHANNELS.len().div_ceil(per_texel),
        };
        let n = encoding.size.unwrap_or(size);
        let textures = match self {
            Self::TwoTexture => texels_per_cell,
            _ => 1,
        };
        let decode = match encoding.storage {
            Storage::Unorm8 | Storage::Unorm10 => SHADER_CHANNELS.len(),
            Storage::F32 | Storage::F16 => 0,
        };
        Some(LookupCost {
            shipped_bytes,
            texture_bytes: n * n * texels_per_cell * texel_bytes(encoding.storage),
            textures,
            samplers: textures,
            fetches: texels_per_cell,
            multiply_adds: UV_OPS + decode,
        })
    }
}

/// Bytes of one texel: RGBA32F 16, RGBA16F 8, RGBA8 4, RGB10A2 4.
fn texel_bytes(storage: Storage) -> usize {
    match storage {
        Storage::F32 => 16,
        Storage::F16 => 8,
        Storage::Unorm8 | Storage::Unorm10 => 4,
    }
}

/// Every encoding's cost in every layout it goes with, as CSV
/// (`encoding,layout,shipped_bytes,texture_bytes,textures,samplers,fetches,multiply_adds`),
/// for a table of `size` cells a side.
pub fn layout_csv(encodings: &[Encoding], size: usize) -> String {
    let mut out = String::from(
        "encoding,layout,shipped_bytes,texture_bytes,textures,samplers,fetches,multiply_adds\n",
    );
    for e in encodings {
        for layout in Layout::ALL {
            if let Some(c) = layout.cost(e, size) {
                out += &format!(
                    "{},{},{},{},{},{},{},{}\n",
                    e.name(),
                    layout.name(),
                    c.shipped_bytes,
                    c.texture_bytes,
                    c.textures,
                    c.samplers,
                    c.fetches,
                    c.multiply_adds
                );
            }
        }
    }
    out
}
