//! `shaders/ltc.wgsl`: LTC evaluation and the in-shader bilinear LUT sampler, mirroring
//! `crate::ltc` and `crate::ltc::lut`; here, the LUT's packing into a storage buffer, and the
//! buffer holding tables A and B.

use crate::error::Result;
use crate::gpu::ltc_aniso::{ANISO_VEC4S_PER_NODE, aniso_params, pack_aniso};
use crate::gpu::{GpuContext, limits};
use crate::ltc::aniso::AnisoLut;
use crate::ltc::lut::{Channel, Lut};
use crate::ltc::nl_fit::nl_terms;
use crate::ltc::remedy::HorizonRule;
use crate::ltc::{Clipping, Normalization};

/// The shader text (composed after `brdf::SOURCE`).
pub const SOURCE: &str = include_str!("../../shaders/ltc.wgsl");

/// `HORIZON_*` of ltc.wgsl (the plane pipeline's `HORIZON` constant): its value and its
/// name there.
pub fn horizon_constant(h: HorizonRule) -> (u32, &'static str) {
    match h {
        HorizonRule::Eq30 => (0, "HORIZON_EQ30"),
        HorizonRule::NlFit => (1, "HORIZON_NL_FIT"),
        HorizonRule::ExactBand => (2, "HORIZON_EXACT_BAND"),
    }
}

/// `LUT_VEC4S_PER_CELL` of ltc.wgsl.
pub const LUT_VEC4S_PER_CELL: usize = 4;

/// `CLIP_HORIZON` of ltc.wgsl: `Params::clip`'s bit for case 1 (clip at the surface's horizon).
pub const CLIP_HORIZON: u32 = 1;

/// `CLIP_TRANSFORMED` of ltc.wgsl: `Params::clip`'s bit for case 2 (clip after `M⁻¹`).
pub const CLIP_TRANSFORMED: u32 = 2;

/// `Params::clip`: the clipping rules as ltc.wgsl reads them.
pub fn clip_bits(c: Clipping) -> u32 {
    (if c.case1 { CLIP_HORIZON } else { 0 }) | (if c.case2 { CLIP_TRANSFORMED } else { 0 })
}

/// `NORMALIZATION_*` of ltc.wgsl (`Params::normalization`): its value and its name there.
pub fn normalization_constant(n: Normalization) -> (u32, &'static str) {
    match n {
        Normalization::Corrected => (0, "NORMALIZATION_CORRECTED"),
        Normalization::PaperLiteral => (1, "NORMALIZATION_PAPER_LITERAL"),
    }
}

/// Four vec4s per cell, as `lut_texel` and `nl_sample_uv` in ltc.wgsl read them:
/// `[spec m00 m02 m20 m22] [diff m00 m02 m20 m22] [scale·spec.norm scale·spec.fresnel diff.norm
/// spec.scale]`: the specular magnitudes with the scale folded in per cell, as
/// `LutCell::shaded` (and ltc_code's layout) has them, rounded to f32 once as an export does;
/// then the cell's `nl-fit` correction (`crate::ltc::nl_fit`, fitted on the table's first use)
/// where `with_nl`, else zeros (the shader reads it only under that rule). The `err`
/// channels are not needed for shading and stay on the CPU.
pub fn pack_lut(lut: &Lut, with_nl: bool) -> Vec<[f32; 4]> {
    use Channel::*;
    let nl = if with_nl {
        nl_terms(lut).to_vec()
    } else {
        vec![[0.0; 4]; lut.cells.len()]
    };
    lut.cells
        .iter()
        .zip(nl)
        .flat_map(|(c, nl)| {
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
                    c.shaded(SpecNorm) as f32,
                    c.shaded(SpecFresnel) as f32,
                    c.get(DiffNorm),
                    c.get(SpecScale),
                ],
                nl.map(|x| x as f32),
            ]
        })
        .collect()
}

/// The storage buffer the shaders read their tables from: A first, B (if any) after it, then
/// A's 4D table and B's where it is another (docs/design.md §2.9); and the tables, to pack
/// them again with the `nl-fit` correction when a render first needs it (fitting it takes
/// about a second on two cores: not for every table's set-up).
pub struct LutBuffer {
    pub buffer: wgpu::Buffer,
    pub size_a: usize,
    /// Cells per side and first vec4 of table B.
    pub b: Option<(usize, u32)>,
    /// Each side's 4D table as `Params::aniso_a` (and `_b`) hold it (`aniso_params`).
    pub aniso_a: ([u32; 4], [u32; 4]),
    pub aniso_b: ([u32; 4], [u32; 4]),
    /// Whether it holds the `nl-fit` correction (else zeros in its place).
    with_nl: bool,
    luts: (Lut, Option<Lut>),
}

impl LutBuffer {
    /// Table A packed, and B packed after it, without the `nl-fit` correction; refused where
    /// they exceed one storage binding.
    pub fn new(ctx: &GpuContext, a: &Lut, b: Option<&Lut>) -> Result<Self> {
        Self::packed(ctx, (a.clone(), b.cloned()), false)
    }

    /// Packs the same tables again with the `nl-fit` correction, where it does not hold it
    /// yet (left as it was where they no longer fit).
    pub fn ensure_nl(&mut self, ctx: &GpuContext) -> Result<()> {
        if !self.with_nl {
            *self = Self::packed(ctx, self.luts.clone(), true)?;
        }
        Ok(())
    }

    fn packed(ctx: &GpuContext, luts: (Lut, Option<Lut>), with_nl: bool) -> Result<Self> {
        let (a, b) = (&luts.0, luts.1.as_ref());
        let size_a = a.size;
        // Checked before packing: packing may fit the correction of every cell.
        let bytes = |lut: &Lut| (lut.size * lut.size * LUT_VEC4S_PER_CELL * 16) as u64;
        let largest = b.map_or(size_a, |lut| lut.size.max(size_a));
        let (aniso_a, aniso_b) = (a.aniso(), b.unwrap_or(a).aniso());
        let aniso_bytes = |t: &AnisoLut| (t.cells.len() * ANISO_VEC4S_PER_NODE * 16) as u64;
        let two_4d = aniso_a != aniso_b;
        let total = bytes(a)
            + b.map_or(0, bytes)
            + aniso_bytes(aniso_a)
            + if two_4d { aniso_bytes(aniso_b) } else { 0 };
        limits::check_lut_size(ctx, largest, total)?;
        let mut all = pack_lut(a, with_nl);
        let b_at = b.map(|lut| {
            let base = all.len() as u32;
            all.extend(pack_lut(lut, with_nl));
            (lut.size, base)
        });
        let aniso_a_at = aniso_params(aniso_a, all.len() as u32);
        all.extend(pack_aniso(aniso_a));
        let aniso_b_at = if two_4d {
            let at = aniso_params(aniso_b, all.len() as u32);
            all.extend(pack_aniso(aniso_b));
            at
        } else {
            aniso_a_at
        };
        let buffer = wgpu::util::DeviceExt::create_buffer_init(
            &ctx.device,
            &wgpu::util::BufferInitDescriptor {
                label: Some("ltc lut"),
                contents: bytemuck::cast_slice(&all),
                usage: wgpu::BufferUsages::STORAGE,
            },
        );
        Ok(Self {
            buffer,
            size_a,
            b: b_at,
            aniso_a: aniso_a_at,
            aniso_b: aniso_b_at,
            with_nl,
            luts,
        })
    }
}
