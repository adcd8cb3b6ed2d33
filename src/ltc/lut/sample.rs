//! Reading the table between its cells (docs/design.md §2.3): bilinear filtering with
//! clamp-to-edge addressing, exactly the GPU's (`lut_sample_uv` in ltc.wgsl), or the nearest
//! cell; and the LTCs of a sample.

use glam::DVec3;

use crate::ltc::lobe::Lobe;
use crate::ltc::lut::taps::bilinear_taps;
use crate::ltc::lut::{Channel, Lut, LutCell};
use crate::ltc::{Ltc, LtcPair, cos_from_brdf_from_entries};

/// A sampled cell in f64: what the renderer and `eval` use. `spec.norm` and `spec.fresnel`
/// hold the filtered products `spec.scale × magnitude` (`LutCell::shaded`), `spec.scale` the
/// filtered scale.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LutSample(pub [f64; Channel::COUNT]);

impl LutSample {
    /// One cell, unfiltered.
    pub fn of_cell(cell: &LutCell) -> Self {
        Self(Channel::ALL.map(|c| cell.shaded(c)))
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

impl Lut {
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
        LutSample(Channel::ALL.map(|c| {
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
}
