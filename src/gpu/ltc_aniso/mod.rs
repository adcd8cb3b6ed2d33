//! `shaders/ltc_aniso.wgsl`: the anisotropic table's lookup on the GPU, mirroring
//! `crate::ltc::aniso` (docs/design.md §2.9); here its constants and the packing of a 4D
//! table into the LUT buffer.

pub mod export;

use crate::ltc::aniso::{AnisoAxes, AnisoLut, Stored};

/// The shader text (composed after `ltc::SOURCE`).
pub const SOURCE: &str = include_str!("../../../shaders/ltc_aniso.wgsl");

/// `ANISO_VEC4S_PER_NODE` of ltc_aniso.wgsl.
pub const ANISO_VEC4S_PER_NODE: usize = 3;

/// `AXES_*` of ltc_aniso.wgsl: its value and its name there.
pub fn axes_constant(axes: AnisoAxes) -> (u32, &'static str) {
    match axes {
        AnisoAxes::Lab => (0, "AXES_LAB"),
        AnisoAxes::I3dAlphaXY => (1, "AXES_I3D_ALPHA_XY"),
        AnisoAxes::I3dAlphaLambda => (2, "AXES_I3D_ALPHA_LAMBDA"),
    }
}

/// `STORED_*` of ltc_aniso.wgsl: its value and its name there.
pub fn stored_constant(stored: Stored) -> (u32, &'static str) {
    match stored {
        Stored::CosFromBrdf => (0, "STORED_COS_FROM_BRDF"),
        Stored::BrdfFromCos => (1, "STORED_BRDF_FROM_COS"),
        Stored::MirrorFromCos => (2, "STORED_MIRROR_FROM_COS"),
        Stored::MirrorPole => (3, "STORED_MIRROR_POLE"),
    }
}

/// Three vec4s a node, as `aniso_sample` reads them: `[m00 m01 m02 m10] [m11 m12 m20 m21]
/// [m22 norm fresnel 0]`, the stored matrix by rows (the `err` channel stays on the CPU).
pub fn pack_aniso(lut: &AnisoLut) -> Vec<[f32; 4]> {
    lut.cells
        .iter()
        .flat_map(|c| {
            let m = c.m;
            [
                [m[0], m[1], m[2], m[3]],
                [m[4], m[5], m[6], m[7]],
                [m[8], c.norm, c.fresnel, 0.0],
            ]
        })
        .collect()
}

/// Where a 4D table sits in the LUT buffer and how it reads, as `Params::aniso_a` and
/// `aniso_dims_a` (or `_b`) hold it: `[first vec4, axes, stored, 0]`, the node counts.
pub fn aniso_params(lut: &AnisoLut, base: u32) -> ([u32; 4], [u32; 4]) {
    (
        [
            base,
            axes_constant(lut.axes).0,
            stored_constant(lut.stored).0,
            0,
        ],
        lut.dims.map(|n| n as u32),
    )
}
