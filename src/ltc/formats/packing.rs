//! ltc_code's packing of the specular LTC into two RGBA textures (selfshadow/ltc_code
//! `fit/fitLTC.cpp`, `packTab`), both ways. The mapping, with this project's channels
//! (docs/design.md §2: `M⁻¹ = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]]` in rows, divided by its middle
//! element, exactly as ltc_code divides `invM` by `invM[1][1]`):
//!
//! | texel | ltc_code (glm, column-major `invM[col][row]`) | this project |
//! |---|---|---|
//! | tex1.x | `invM[0][0]` | `spec.m00` |
//! | tex1.y | `invM[0][2]`: column 0, row 2 | `spec.m20` |
//! | tex1.z | `invM[2][0]`: column 2, row 0 | `spec.m02` |
//! | tex1.w | `invM[2][2]` | `spec.m22` |
//! | tex2.x | magnitude `∫ f cos` (F = 1) | `spec.scale × spec.norm` |
//! | tex2.y | Fresnel term `∫ (1 − v·h)⁵ f cos` | `spec.scale × spec.fresnel` |
//! | tex2.z | 0 (unused) | — |
//! | tex2.w | horizon-clipped sphere form factor, its own axes | `sphere::sphere_table_value` |
//!
//! A shader rebuilds `M⁻¹` as `mat3(vec3(t1.x, 0, t1.y), vec3(0, 1, 0), vec3(t1.z, 0, t1.w))`
//! (GLSL and WGSL take columns). Cells are in ltc_code's order `a + t·N`: roughness `a`
//! fastest, the view row `t` slowest, the axes of docs/design.md §2.

use glam::DVec3;
use rayon::prelude::*;

use crate::brdf::view_from_theta;
use crate::ltc::fit::pointwise_error;
use crate::ltc::lobe::Lobe;
use crate::ltc::lut::{Channel, Lut, LutCell, LutSample};
use crate::ltc::sphere::sphere_table_value;

/// ltc_code's two textures, `size × size` texels each, row-major from `(a, t) = (0, 0)`.
#[derive(Clone, Debug, PartialEq)]
pub struct Packed {
    pub size: usize,
    pub tex1: Vec<[f32; 4]>,
    pub tex2: Vec<[f32; 4]>,
}

/// tex1's entries, as this project's channels.
pub const TEX1: [Channel; 4] = [
    Channel::SpecM00,
    Channel::SpecM20,
    Channel::SpecM02,
    Channel::SpecM22,
];

/// Packs the specular lobe of `lut`; the point fit's scale is folded into the magnitudes, so
/// that a consumer of ltc_code's layout shades the fitted lobe exactly.
pub fn pack(lut: &Lut) -> Packed {
    let n = lut.size;
    let texel = |k: usize| {
        let cell = &lut.cells[k];
        let scale = f64::from(cell.get(Channel::SpecScale));
        let magnitude = |c: Channel| (scale * f64::from(cell.get(c))) as f32;
        (
            TEX1.map(|c| cell.get(c)),
            [
                magnitude(Channel::SpecNorm),
                magnitude(Channel::SpecFresnel),
                0.0,
                sphere_table_value(k % n, k / n, n) as f32,
            ],
        )
    };
    let (tex1, tex2) = (0..n * n).map(texel).unzip();
    Packed {
        size: n,
        tex1,
        tex2,
    }
}

/// Strata per side of the pointwise error measured for an imported table: the classic fit's
/// `FitSettings::error_samples`, so that both tables' `spec.err` are measured alike.
pub const ERROR_SAMPLES: usize = 64;

/// A table from ltc_code's textures: the specular lobe from them (scale 1, its magnitudes as
/// packed) and the diffuse lobe — which ltc_code's layout does not have — sampled from
/// `diffuse` on the same axes (its cells exactly where the sizes match). `spec.err`, which the
/// layout lacks too, is left at 0 for `measure_spec_err`: it costs about a millisecond a cell.
pub fn unpack(p: &Packed, alpha_min: f64, diffuse: &Lut) -> Lut {
    let n = p.size;
    let mut lut = Lut {
        nl_terms: Default::default(),
        aniso: None,
        size: n,
        alpha_min,
        cells: vec![LutCell([0.0; crate::ltc::lut::Channel::COUNT]); n * n],
    };
    let cells: Vec<LutCell> = (0..n * n)
        .into_par_iter()
        .map(|k| {
            let (i, j) = (k % n, k / n);
            let last = (n - 1) as f64;
            let (u, v) = diffuse.uv_of_axes(i as f64 / last, j as f64 / last);
            let mut cell = LutCell(diffuse.sample_uv(u, v).0.map(|x| x as f32));
            for (c, x) in TEX1.iter().zip(p.tex1[k]) {
                cell.0[*c as usize] = x;
            }
            cell.0[Channel::SpecNorm as usize] = p.tex2[k][0];
            cell.0[Channel::SpecFresnel as usize] = p.tex2[k][1];
            cell.0[Channel::SpecScale as usize] = 1.0;
            cell.0[Channel::SpecErr as usize] = 0.0;
            cell
        })
        .collect();
    lut.cells = cells;
    lut
}

/// Measures every cell's `spec.err` (in parallel), calling `on_cell` after each.
pub fn measure_spec_err(lut: &mut Lut, on_cell: &(dyn Fn() + Sync)) {
    let (n, alpha_min) = (lut.size, lut.alpha_min);
    lut.cells.par_iter_mut().enumerate().for_each(|(k, cell)| {
        let alpha = crate::ltc::lut::cell_alpha(k % n, n, alpha_min);
        let v = DVec3::from(view_from_theta(crate::ltc::lut::cell_theta(k / n, n)));
        let spec = LutSample::of_cell(cell).ltc_pair().spec;
        let err = pointwise_error(Lobe::Specular, v, alpha, &spec, ERROR_SAMPLES);
        cell.0[Channel::SpecErr as usize] = err as f32;
        on_cell();
    });
}

/// α_min of a table that does not record it: ltc_code fits the normal-view cell of its
/// smoothest column as `M = diag(m11, m11, 1)` with `m11 ≈ 2α` (its published table: 2e-5
/// at α_min = 1e-5, 5.04e-4 at α = 2.5e-4), so tex1.w of cell 0 over 2; kept above 1e-7 and
/// below column 1's α = 1/(N−1)², so that column 0 stays the smoothest.
pub fn estimated_alpha_min(p: &Packed) -> f64 {
    let column_1 = 1.0 / ((p.size - 1) as f64).powi(2);
    (f64::from(p.tex1[0][3]) / 2.0).clamp(1e-7, 0.5 * column_1)
}
