//! The LTC look-up table of docs/design.md §2: N×N cells over (roughness, view angle), each a
//! `Channel` per fitted value; the shipped tables embedded in the binary. Its axes, its file,
//! its validation, its sampler and its encodings are modules of their own.

mod axes;
mod channel;
pub mod encoding;
mod exr;
pub mod formula;
pub mod layout;
mod sample;
pub mod storage;
pub mod taps;
mod validate;

use std::sync::{Arc, OnceLock};

pub use axes::{ALPHA_MIN, THETA_MAX, axes, cell_alpha, cell_theta};
pub use channel::Channel;
pub use encoding::{Encoding, Storage};
pub use exr::{MAX_SIZE, check_size};
pub use formula::Formula;

/// The most bytes of a table file this program reads (`files::read_bytes`; a DDS pair's
/// each): the shipped 64² tables are ~100 kB, a 2048² table of 14 f32 channels uncompressed
/// 235 MB. A `MAX_SIZE` table beyond that must come compressed.
pub const MAX_FILE_BYTES: u64 = 256 << 20;
pub use sample::LutSample;
pub use taps::bilinear_taps;
pub use validate::ChannelLimits;

use glam::{DMat3, DVec3};

use crate::brdf::Alpha;
use crate::ltc::aniso::AnisoLut;
use crate::ltc::{Ltc, LtcPair, mat3_rows};
use crate::named::named_enum;

/// The stored form of docs/design.md §2: `M⁻¹` divided by its middle element, as
/// `[m00, m02, m20, m22]` of `[[m00, 0, m02], [0, 1, 0], [m20, 0, m22]]`.
pub fn normalized_cos_from_brdf(ltc: &Ltc) -> [f64; 4] {
    let r = mat3_rows(ltc.cos_from_brdf);
    let s = r[1][1];
    [r[0][0] / s, r[0][2] / s, r[2][0] / s, r[2][2] / s]
}

/// The shipped table (`luts/ltc.exr`, made by `ltc-lab fit`), so the lab runs from anywhere.
pub const EMBEDDED_EXR: &[u8] = include_bytes!("../../../luts/ltc.exr");

/// The shipped point-light fit (`luts/ltc_point.exr`, `ltc-lab fit --objective point`).
pub const EMBEDDED_POINT_EXR: &[u8] = include_bytes!("../../../luts/ltc_point.exr");

/// The arrival-weighted point fit (`luts/ltc_arrival.exr`, `ltc-lab fit --objective arrival`).
pub const EMBEDDED_ARRIVAL_EXR: &[u8] = include_bytes!("../../../luts/ltc_arrival.exr");

/// The horizon-constrained point fit (`luts/ltc_constrained.exr`,
/// `ltc-lab fit --objective constrained`).
pub const EMBEDDED_CONSTRAINED_EXR: &[u8] = include_bytes!("../../../luts/ltc_constrained.exr");

named_enum! {
    /// Which shipped table (and the objective that fitted it).
    #[derive(
        Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
    )]
    pub enum Table {
        /// ltc_code's objective (`luts/ltc.exr`).
        #[default]
        Classic = "classic",
        /// The point-light objective (`luts/ltc_point.exr`).
        Point = "point",
        /// The point-light objective weighted by where lights above a plane arrive from, the
        /// horizon included (`luts/ltc_arrival.exr`; docs/design.md §4.7).
        Arrival = "arrival",
        /// The point-light objective with `m20 = 0`, so that `M⁻¹` never carries a direction
        /// across the horizon (`luts/ltc_constrained.exr`; docs/design.md §4.7).
        Constrained = "constrained",
    }
}

impl Table {
    /// The shipped file's path in the repository.
    pub fn path(self) -> &'static str {
        match self {
            Self::Classic => "luts/ltc.exr",
            Self::Point => "luts/ltc_point.exr",
            Self::Arrival => "luts/ltc_arrival.exr",
            Self::Constrained => "luts/ltc_constrained.exr",
        }
    }

    fn bytes(self) -> &'static [u8] {
        match self {
            Self::Classic => EMBEDDED_EXR,
            Self::Point => EMBEDDED_POINT_EXR,
            Self::Arrival => EMBEDDED_ARRIVAL_EXR,
            Self::Constrained => EMBEDDED_CONSTRAINED_EXR,
        }
    }

    /// The table a lab compares with this one: the classic table, or the point table
    /// beside the classic one.
    pub fn default_b(self) -> Self {
        match self {
            Self::Classic => Self::Point,
            _ => Self::Classic,
        }
    }
}

/// One cell: the channels of `CHANNEL_NAMES`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LutCell(pub [f32; Channel::COUNT]);

impl LutCell {
    /// From fitted lobes: `M⁻¹` normalized by its middle element (docs/design.md §2).
    pub fn from_fits(spec: &Ltc, spec_err: f64, diff: &Ltc, diff_err: f64) -> Self {
        let s = normalized_cos_from_brdf(spec);
        let d = normalized_cos_from_brdf(diff);
        let values = [
            s[0],
            s[1],
            s[2],
            s[3],
            spec.norm,
            spec.fresnel,
            spec_err,
            d[0],
            d[1],
            d[2],
            d[3],
            diff.norm,
            diff_err,
            spec.scale,
        ];
        Self(values.map(|x| x as f32))
    }

    pub fn get(&self, c: Channel) -> f32 {
        self.0[c as usize]
    }

    /// Channel `c` as the table is shaded with it: the specular magnitudes with the fitted
    /// scale folded in per cell, as ltc_code's layout stores them (docs/design.md §2), so that
    /// a table and its export filter the same products and shade alike.
    pub fn shaded(&self, c: Channel) -> f64 {
        let x = f64::from(self.get(c));
        match c {
            Channel::SpecNorm | Channel::SpecFresnel => f64::from(self.get(Channel::SpecScale)) * x,
            _ => x,
        }
    }

    /// Sets channel `c` to its shaded value `x` (`shaded`'s inverse): a specular magnitude is
    /// stored divided by the cell's scale.
    pub fn set_shaded(&mut self, c: Channel, x: f64) {
        let stored = match c {
            Channel::SpecNorm | Channel::SpecFresnel => x / f64::from(self.get(Channel::SpecScale)),
            _ => x,
        };
        self.0[c as usize] = stored as f32;
    }
}

/// An N×N table; `cells[j * size + i]`.
#[derive(Clone, Debug, Default)]
pub struct Lut {
    pub size: usize,
    pub alpha_min: f64,
    pub cells: Vec<LutCell>,
    /// The `nl-fit` correction of each cell (`crate::ltc::nl_fit::nl_terms`), fitted on
    /// first use; the cells must not change after it.
    pub nl_terms: OnceLock<Vec<[f64; 4]>>,
    /// The 4D table that anisotropic materials' specular lobes read (docs/design.md §2.9):
    /// the shipped one (`AnisoLut::shipped`) unless another is set (`with_aniso`).
    pub aniso: Option<Arc<AnisoLut>>,
}

impl PartialEq for Lut {
    /// The same cells and 4D table: whether the correction was fitted yet does not matter.
    fn eq(&self, other: &Self) -> bool {
        (self.size, self.alpha_min) == (other.size, other.alpha_min)
            && self.cells == other.cells
            && self.aniso() == other.aniso()
    }
}

impl Lut {
    /// The 4D table anisotropic materials read.
    pub fn aniso(&self) -> &AnisoLut {
        self.aniso.as_deref().unwrap_or_else(|| AnisoLut::shipped())
    }

    /// The same table with `aniso` as its 4D table.
    pub fn with_aniso(self, aniso: Arc<AnisoLut>) -> Self {
        Self {
            aniso: Some(aniso),
            ..self
        }
    }

    /// Both lobes of an anisotropic material of roughness `alpha` seen from unit `v` in its
    /// tangent frame (docs/design.md §1.13): the specular lobe from the 4D table; the diffuse
    /// lobe, isotropic, from the 2D table at Burley's α, turned from the view's frame into the
    /// tangent's.
    pub fn aniso_pair(&self, alpha: Alpha<f64>, v: DVec3) -> LtcPair {
        let spec = self.aniso().ltc(alpha, v);
        let diff = self.sample(alpha.diffuse(), v.z).ltc_pair().diff;
        // A tangent-frame direction has view-frame coordinates turned by −φ (φ the view's
        // azimuth about the normal), and M⁻¹ acts on those.
        let view_from_tangent = DMat3::from_rotation_z(-v.y.atan2(v.x));
        let diff = Ltc::from_cos_from_brdf(diff.cos_from_brdf * view_from_tangent, diff.norm, 0.0);
        LtcPair { spec, diff }
    }

    /// The table embedded in the binary (parsed once).
    pub fn embedded() -> &'static Lut {
        Lut::shipped(Table::Classic)
    }

    /// The shipped point-light table (parsed once).
    pub fn embedded_point() -> &'static Lut {
        Lut::shipped(Table::Point)
    }

    /// One of the shipped tables (each parsed once).
    pub fn shipped(table: Table) -> &'static Lut {
        static PARSED: [OnceLock<Lut>; Table::ALL.len()] = [const { OnceLock::new() }; 4];
        PARSED[table as usize].get_or_init(|| {
            Lut::from_exr_bytes(table.bytes(), &format!("embedded {}", table.path()))
                .expect("the embedded tables are checked by the test suite")
        })
    }

    pub fn cell(&self, i: usize, j: usize) -> &LutCell {
        &self.cells[j * self.size + i]
    }
}
