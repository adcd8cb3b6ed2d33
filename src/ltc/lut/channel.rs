//! A table cell's channels (docs/design.md §2.4): each knows its name in the file and the
//! lobe it belongs to, and its place in a cell is its discriminant.

use crate::ltc::lobe::Lobe;
use crate::named::named_enum;

named_enum! {
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
    pub enum Channel {
        SpecM00 = "spec.m00",
        SpecM02 = "spec.m02",
        SpecM20 = "spec.m20",
        SpecM22 = "spec.m22",
        SpecNorm = "spec.norm",
        SpecFresnel = "spec.fresnel",
        SpecErr = "spec.err",
        DiffM00 = "diff.m00",
        DiffM02 = "diff.m02",
        DiffM20 = "diff.m20",
        DiffM22 = "diff.m22",
        DiffNorm = "diff.norm",
        DiffErr = "diff.err",
        /// The fitted factor on the specular magnitude (`Ltc::scale`): 1 in the classic table.
        SpecScale = "spec.scale",
    }
}

impl Channel {
    pub const COUNT: usize = Self::ALL.len();

    /// The lobe whose fit the channel holds.
    pub fn lobe(self) -> Lobe {
        use Channel::*;
        match self {
            SpecM00 | SpecM02 | SpecM20 | SpecM22 | SpecNorm | SpecFresnel | SpecErr
            | SpecScale => Lobe::Specular,
            DiffM00 | DiffM02 | DiffM20 | DiffM22 | DiffNorm | DiffErr => Lobe::Diffuse,
        }
    }

    /// A lobe's four stored entries of `M⁻¹`: `m00, m02, m20, m22`.
    pub fn entries(lobe: Lobe) -> [Self; 4] {
        use Channel::*;
        match lobe {
            Lobe::Specular => [SpecM00, SpecM02, SpecM20, SpecM22],
            Lobe::Diffuse => [DiffM00, DiffM02, DiffM20, DiffM22],
        }
    }

    /// A lobe's pointwise error.
    pub fn err(lobe: Lobe) -> Self {
        match lobe {
            Lobe::Specular => Self::SpecErr,
            Lobe::Diffuse => Self::DiffErr,
        }
    }

    /// Whether this channel is a lobe's pointwise error (drawn on a log scale).
    pub fn is_err(self) -> bool {
        self == Self::err(self.lobe())
    }
}

/// The channels a shader reads: both lobes' four entries of `M⁻¹` and magnitudes, with
/// `spec.scale` folded into the specular magnitudes (`LutCell::shaded`) as ltc_code's layout
/// stores them. The pointwise errors are measurements, not read by a shader.
pub const SHADER_CHANNELS: [Channel; 11] = [
    Channel::SpecM00,
    Channel::SpecM02,
    Channel::SpecM20,
    Channel::SpecM22,
    Channel::SpecNorm,
    Channel::SpecFresnel,
    Channel::DiffM00,
    Channel::DiffM02,
    Channel::DiffM20,
    Channel::DiffM22,
    Channel::DiffNorm,
];
