//! The anisotropic GGX table (docs/design.md §2.9): one LTC of the specular lobe per node of a
//! 4D grid over (α_x, α_y, θo, φo), each node's matrix in one canonical form among the
//! equivalent ones (`canonical`), read between the nodes by quadrilinear interpolation. The
//! lab's own table and the I3D 2022 tables (`anchor`) are both an `AnisoLut`; they differ in
//! their axes and in which matrix they store.

pub mod anchor;
pub mod axes;
pub mod canonical;
pub mod encoded;
pub mod exr;
pub mod fit;
pub mod lobe;
pub mod source;
pub mod stored;

use glam::{DMat3, DVec3};

use crate::brdf::Alpha;
use crate::ltc::lut::taps::bilinear_taps;
use crate::ltc::{Ltc, mat3_from_rows};

pub use axes::{AnisoAxes, AnisoPoint, Folded};
pub use stored::{Stored, mirror_frame, poles_agree};

/// One node: its matrix (row-major) and the lobe's magnitudes there.
#[derive(Clone, Copy, Debug)]
pub struct AnisoCell {
    /// The stored matrix, rows first: `m[3 r + c]` is row `r`, column `c`.
    pub m: [f32; 9],
    /// `n = ∫ f cos dω` with F = 1.
    pub norm: f32,
    /// `∫ (1 − v·h)⁵ f cos dω`, the Schlick split (docs/design.md §1.5).
    pub fresnel: f32,
    /// The node's pointwise lobe error (docs/design.md §4.1), NaN where unmeasured.
    pub err: f32,
}

/// The same node to the bit: an unmeasured error (NaN, as a table read from I3D 2022's files
/// holds) equals itself, so a table equals itself.
impl PartialEq for AnisoCell {
    fn eq(&self, other: &Self) -> bool {
        let bits = |c: &Self| {
            (
                c.m.map(f32::to_bits),
                [c.norm, c.fresnel, c.err].map(f32::to_bits),
            )
        };
        bits(self) == bits(other)
    }
}

impl AnisoCell {
    pub fn matrix(&self) -> DMat3 {
        let m = self.m.map(f64::from);
        mat3_from_rows([[m[0], m[1], m[2]], [m[3], m[4], m[5]], [m[6], m[7], m[8]]])
    }
}

/// A 4D table: `dims` nodes per axis, in the order `(a, b, t, p)` of `AnisoAxes`; node
/// `(a, b, t, p)` at `cells[((p · N_t + t) · N_b + b) · N_a + a]`.
#[derive(Clone, Debug, PartialEq)]
pub struct AnisoLut {
    pub axes: AnisoAxes,
    pub dims: [usize; 4],
    pub stored: Stored,
    pub cells: Vec<AnisoCell>,
}

/// The table read at one point of its domain, in the table's frame: the interpolated matrix
/// (as stored) and magnitudes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AnisoSample {
    pub matrix: DMat3,
    pub norm: f64,
    pub fresnel: f64,
}

/// The shipped 4D table (`luts/ltc_aniso.exr`, made by `ltc-lab fit --aniso`), embedded so
/// that the lab runs from anywhere.
pub const EMBEDDED_EXR: &[u8] = include_bytes!("../../../luts/ltc_aniso.exr");

impl AnisoLut {
    /// The shipped 4D table (parsed once).
    pub fn shipped() -> &'static AnisoLut {
        static PARSED: std::sync::OnceLock<AnisoLut> = std::sync::OnceLock::new();
        PARSED.get_or_init(|| {
            AnisoLut::from_exr_bytes(EMBEDDED_EXR, "embedded luts/ltc_aniso.exr")
                .expect("the embedded 4D table is checked by the test suite")
        })
    }

    /// The index of node `k` in `cells`.
    pub fn index(&self, [a, b, t, p]: [usize; 4]) -> usize {
        let [na, nb, nt, _] = self.dims;
        ((p * nt + t) * nb + b) * na + a
    }

    pub fn cell(&self, k: [usize; 4]) -> &AnisoCell {
        &self.cells[self.index(k)]
    }

    /// The material and view of node `k`.
    pub fn node(&self, k: [usize; 4]) -> AnisoPoint {
        self.axes.node(k, self.dims)
    }

    /// Every node's indices, in `cells`' order.
    pub fn nodes(&self) -> impl Iterator<Item = [usize; 4]> + use<> {
        all_nodes(self.dims)
    }

    /// Quadrilinear interpolation at a point of the domain, with clamp-to-edge addressing as
    /// a sampler does it (`lut::bilinear_taps` on each axis, at the texel coordinate of the
    /// point's axis coordinate), every channel in f64.
    pub fn sample(&self, q: &AnisoPoint) -> AnisoSample {
        let c = self.axes.coordinates(q);
        let taps: [(usize, usize, f64); 4] = std::array::from_fn(|axis| {
            let n = self.dims[axis] as f64;
            bilinear_taps(self.dims[axis], c[axis] * (n - 1.0) / n + 0.5 / n)
        });
        let mut m = [0.0f64; 9];
        let (mut norm, mut fresnel) = (0.0, 0.0);
        for corner in 0..16usize {
            let (mut k, mut w) = ([0usize; 4], 1.0);
            for (axis, &(k0, k1, f)) in taps.iter().enumerate() {
                let far = corner >> axis & 1 == 1;
                k[axis] = if far { k1 } else { k0 };
                w *= if far { f } else { 1.0 - f };
            }
            if w == 0.0 {
                continue;
            }
            let cell = self.cell(k);
            for (x, y) in m.iter_mut().zip(cell.m) {
                *x += w * f64::from(y);
            }
            norm += w * f64::from(cell.norm);
            fresnel += w * f64::from(cell.fresnel);
        }
        AnisoSample {
            matrix: mat3_from_rows([[m[0], m[1], m[2]], [m[3], m[4], m[5]], [m[6], m[7], m[8]]]),
            norm,
            fresnel,
        }
    }

    /// The specular lobe's LTC at a point of the domain whose unit view is `w`, in the
    /// table's frame: the interpolated matrix (inverted per pixel where the table stores `M`)
    /// with the interpolated magnitudes.
    pub fn ltc_in_table_frame(&self, q: &AnisoPoint, w: DVec3) -> Ltc {
        let s = self.sample(q);
        Ltc::from_cos_from_brdf(self.stored.cos_from_brdf(s.matrix, w), s.norm, s.fresnel)
    }

    /// The specular lobe's LTC for a material and a unit view `v` in the tangent frame (x
    /// the tangent, along which `alpha.x` acts; `v.z > 0`), acting on the tangent frame's
    /// directions: the table's `M⁻¹` at the folded point, conjugated by the fold
    /// (`Sᵀ M⁻¹ S`, an equivalent lobe whose determinant keeps its sign).
    pub fn ltc(&self, alpha: Alpha<f64>, v: DVec3) -> Ltc {
        let folded = self.axes.fold(alpha, v);
        let ltc = self.ltc_in_table_frame(&folded.point, folded.w);
        let s = folded.table_from_tangent;
        let cos_from_brdf = canonical::proper(s.transpose() * ltc.cos_from_brdf * s);
        Ltc::from_cos_from_brdf(cos_from_brdf, ltc.norm, ltc.fresnel)
    }
}

/// Every node of a table of `dims` nodes per axis, `a` fastest.
pub fn all_nodes(dims: [usize; 4]) -> impl Iterator<Item = [usize; 4]> {
    let [na, nb, nt, np] = dims;
    (0..np).flat_map(move |p| {
        (0..nt).flat_map(move |t| (0..nb).flat_map(move |b| (0..na).map(move |a| [a, b, t, p])))
    })
}

/// The worst blend a table's lookup reads (docs/design.md §2.9): over `n⁴` points of every
/// cell (its corners included), the smallest `det M` read there relative to the corners'
/// `det M` averaged geometrically with the point's own blend weights — negative where a
/// blend is mirrored, near zero where it collapses (a lobe squeezed onto a line), and at
/// least 1 for `Stored::MirrorPole`, whose blends' determinants are log-concave in the
/// weights — and the point where it is.
pub fn worst_blend(lut: &AnisoLut, n: usize) -> (f64, AnisoPoint) {
    let cells = lut.dims.map(|d| d - 1);
    let fine = lut.dims.map(|d| (d - 1) * (n - 1) + 1);
    let det_at = |q: &AnisoPoint| {
        lut.ltc_in_table_frame(q, q.view())
            .brdf_from_cos
            .determinant()
    };
    let mut worst = (f64::INFINITY, lut.node([0; 4]));
    for c in all_nodes(cells) {
        let log_dets: Vec<f64> = (0..16usize)
            .map(|corner| {
                let k: [usize; 4] = std::array::from_fn(|axis| c[axis] + (corner >> axis & 1));
                det_at(&lut.node(k)).abs().ln()
            })
            .collect();
        for s in all_nodes([n; 4]) {
            let w: [f64; 4] = std::array::from_fn(|axis| s[axis] as f64 / (n - 1) as f64);
            let mean: f64 = (0..16usize)
                .map(|corner| {
                    let weight: f64 = (0..4)
                        .map(|axis| {
                            if corner >> axis & 1 == 1 {
                                w[axis]
                            } else {
                                1.0 - w[axis]
                            }
                        })
                        .product();
                    weight * log_dets[corner]
                })
                .sum();
            let k: [usize; 4] = std::array::from_fn(|axis| c[axis] * (n - 1) + s[axis]);
            let q = lut.axes.node(k, fine);
            let ratio = det_at(&q) / mean.exp();
            if ratio < worst.0 {
                worst = (ratio, q);
            }
        }
    }
    worst
}
