//! A table cell's channels (docs/design.md §2.4): each knows its name in the file and the
//! lobe it belongs to, and its place in a cell is its discriminant.

use crate::ltc::lobe::Lobe;

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Channel {
    SpecM00,
    SpecM02,
    SpecM20,
    SpecM22,
    SpecNorm,
    SpecFresnel,
    SpecErr,
    DiffM00,
    DiffM02,
    DiffM20,
    DiffM22,
    DiffNorm,
    DiffErr,
    /// The fitted factor on the specular magnitude (`Ltc::scale`): 1 in the classic table.
    SpecScale,
}

impl Channel {
    pub const COUNT: usize = 14;

    /// Every channel in a cell's order (`Channel as usize`; `tests/lut.rs` checks it).
    pub const ALL: [Self; Self::COUNT] = [
        Self::SpecM00,
        Self::SpecM02,
        Self::SpecM20,
        Self::SpecM22,
        Self::SpecNorm,
        Self::SpecFresnel,
        Self::SpecErr,
        Self::DiffM00,
        Self::DiffM02,
        Self::DiffM20,
        Self::DiffM22,
        Self::DiffNorm,
        Self::DiffErr,
        Self::SpecScale,
    ];

    /// The channel's name in a table file, `lut --dump`'s header and the lab.
    pub fn name(self) -> &'static str {
        match self {
            Self::SpecM00 => "spec.m00",
            Self::SpecM02 => "spec.m02",
            Self::SpecM20 => "spec.m20",
            Self::SpecM22 => "spec.m22",
            Self::SpecNorm => "spec.norm",
            Self::SpecFresnel => "spec.fresnel",
            Self::SpecErr => "spec.err",
            Self::DiffM00 => "diff.m00",
            Self::DiffM02 => "diff.m02",
            Self::DiffM20 => "diff.m20",
            Self::DiffM22 => "diff.m22",
            Self::DiffNorm => "diff.norm",
            Self::DiffErr => "diff.err",
            Self::SpecScale => "spec.scale",
        }
    }

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
