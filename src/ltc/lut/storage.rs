//! How one value of a table is stored (docs/design.md §2.10): f32, f16, or fixed point over
//! each channel's own range, and a column of values stored and read back as an engine reads
//! it. The 2D table's encodings and the 4D table's storage (`aniso::encoded`) both use it.

use crate::ltc::lut::channel::SHADER_CHANNELS;
use crate::named::named_enum;

named_enum! {
    /// How one value of the table is stored.
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
    pub enum Storage {
        /// 32-bit floats, as the lab shades (the reference every other encoding is held to).
        #[default]
        F32 = "f32",
        /// IEEE half floats (three.js's and PlayCanvas's fallback where float textures fail).
        F16 = "f16",
        /// 8 bits a value over each channel's own range, with a scale and a bias per channel
        /// (PlayCanvas's last fallback).
        Unorm8 = "unorm8",
        /// The packed 10-bit form (RGB10A2: three 10-bit values in 4 bytes), over each
        /// channel's own range as `unorm8`. (R11G11B10's 11- and 10-bit floats have no sign
        /// bit, and `M⁻¹`'s off-diagonal entries are negative: they do not fit the table.)
        Unorm10 = "unorm10",
    }
}

impl Storage {
    /// Bytes of one texel holding every shader channel: f32 and f16 a value each at their
    /// width, 8-bit values a byte each, 10-bit ones three to a 4-byte texel.
    pub fn cell_bytes(self) -> usize {
        self.bytes_of(SHADER_CHANNELS.len())
    }

    /// Bytes of `n` values in texels of this storage (RGB10A2 texels whole).
    pub fn bytes_of(self, n: usize) -> usize {
        match self {
            Self::F32 => 4 * n,
            Self::F16 => 2 * n,
            Self::Unorm8 => n,
            Self::Unorm10 => 4 * n.div_ceil(self.values_per_texel()),
        }
    }

    /// Values one texel holds: RGBA's four, RGB10A2's three (its 2-bit alpha holds none).
    pub fn values_per_texel(self) -> usize {
        match self {
            Self::Unorm10 => 3,
            Self::F32 | Self::F16 | Self::Unorm8 => 4,
        }
    }

    /// One channel's `values` in a fixed-point storage (`None`: a float): its bias (the least
    /// value), its step (`(max − min)` over the storage's steps) and each value's whole steps
    /// above the bias, what a texel holds.
    pub fn quantized(self, values: &[f64]) -> Option<Quantized> {
        let steps = self.steps()?;
        let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let step = (hi - lo) / steps;
        let whole = |v: f64| match step > 0.0 {
            true => ((v - lo) / step).round() as u32,
            false => 0,
        };
        Some(Quantized {
            bias: lo,
            step,
            steps: values.iter().map(|&v| whole(v)).collect(),
        })
    }

    /// Steps of a fixed-point storage over a channel's range (`None`: a float).
    pub fn steps(self) -> Option<f64> {
        match self {
            Self::Unorm8 => Some(255.0),
            Self::Unorm10 => Some(1023.0),
            Self::F32 | Self::F16 => None,
        }
    }
}

/// One channel in a fixed-point storage (`Storage::quantized`): value `k` is
/// `bias + steps[k] · step`.
#[derive(Clone, Debug, PartialEq)]
pub struct Quantized {
    pub bias: f64,
    pub step: f64,
    pub steps: Vec<u32>,
}

/// `v` as an f16 from the f32 an engine holds (as `lut --export ltc-code-dds` rounds), clamped
/// to f16's finite range (`Encoding::clamped` counts what was).
pub fn half_of(v: f64) -> half::f16 {
    let limit = f32::from(half::f16::MAX);
    half::f16::from_f32((v as f32).clamp(-limit, limit))
}

/// `values` stored in `storage` and read back.
pub fn store(storage: Storage, values: &[f64]) -> Vec<f64> {
    match storage {
        Storage::F32 => values.iter().map(|&v| f64::from(v as f32)).collect(),
        Storage::F16 => values.iter().map(|&v| f64::from(half_of(v))).collect(),
        Storage::Unorm8 | Storage::Unorm10 => match storage.quantized(values) {
            Some(q) => q
                .steps
                .iter()
                .map(|&k| q.bias + f64::from(k) * q.step)
                .collect(),
            None => values.to_vec(),
        },
    }
}
