//! `shaders/ltc.wgsl`: LTC evaluation and the in-shader bilinear LUT sampler, mirroring
//! `crate::ltc` and `crate::ltc::lut`; here, the LUT's packing into a storage buffer.

use crate::ltc::lut::{Channel, Lut};

/// The shader text (composed after `brdf::SOURCE`).
pub const SOURCE: &str = include_str!("../../shaders/ltc.wgsl");

/// Three vec4s per cell, as `lut_texel` in ltc.wgsl reads them:
/// `[spec m00 m02 m20 m22] [diff m00 m02 m20 m22] [spec.norm spec.fresnel diff.norm spec.scale]`.
/// The `err` channels are not needed for shading and stay on the CPU.
pub fn pack_lut(lut: &Lut) -> Vec<[f32; 4]> {
    use Channel::*;
    lut.cells
        .iter()
        .flat_map(|c| {
            [
                [
                    c.get(SpecM00),
                    c.get(SpecM02),
                    c.get(SpecM20),
                    c.get(SpecM22),
                ],
                [
                    c.get(DiffM00),
                    c.get(DiffM02),
                    c.get(DiffM20),
                    c.get(DiffM22),
                ],
                [
                    c.get(SpecNorm),
                    c.get(SpecFresnel),
                    c.get(DiffNorm),
                    c.get(SpecScale),
                ],
            ]
        })
        .collect()
}
