//! The horizon remedies of docs/design.md §4.7: what is done for point lights near the
//! horizon, where eq. 30's LTC is wrong by half. Two remedies are tables fitted otherwise
//! (`Table::Arrival`, `Table::Constrained`); two change the shading per light
//! (`HorizonRule`).

use crate::brdf::Lobes;
use crate::ltc::lut::Table;
use crate::ltc::nl_fit::{NlTerms, nl_weight};
use crate::named::named_enum;

/// `n·l` below which `exact-band` shades with the exact BRDF: sin 15°, the top of the two
/// bands where the LTC is wrong by half (docs/design.md §4.7).
pub const EXACT_BAND_Z: f64 = 0.258_819_045_102_520_74;

/// What the shading does per light near the horizon.
#[derive(
    Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
)]
pub enum HorizonRule {
    /// The paper's rules alone (eq. 30's clipping).
    #[default]
    Eq30,
    /// Each lobe scaled by its cell's `w(n·l)` (`crate::ltc::nl_fit`).
    NlFit,
    /// The exact BRDF for lights with `0 < n·l < EXACT_BAND_Z`, LTC elsewhere.
    ExactBand,
}

impl HorizonRule {
    /// One light's lobes under the rule: `ltc` as eq. 30 gives them, `nl` the pixel's
    /// correction (read only by `NlFit`), `exact` the BRDF's (called only inside the band).
    pub fn apply(
        self,
        z: f64,
        ltc: Lobes<f64>,
        nl: &NlTerms,
        exact: impl FnOnce() -> Lobes<f64>,
    ) -> Lobes<f64> {
        match self {
            Self::NlFit => Lobes {
                specular: ltc.specular * nl_weight([nl[0], nl[1]], z),
                diffuse: ltc.diffuse * nl_weight([nl[2], nl[3]], z),
            },
            Self::ExactBand if in_exact_band(z) => exact(),
            Self::Eq30 | Self::ExactBand => ltc,
        }
    }
}

/// Whether a light at `n·l = z` is shaded exactly by `ExactBand`.
pub fn in_exact_band(z: f64) -> bool {
    z > 0.0 && z < EXACT_BAND_Z
}

named_enum! {
    /// A horizon remedy as `--horizon` and the lab name it: eq. 30 (the reference), a table
    /// fitted otherwise, or a rule per light.
    #[derive(
        Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize,
    )]
    pub enum Horizon {
        #[default]
        Eq30 = "eq30",
        /// `Table::Arrival` with eq. 30's rules.
        ArrivalFit = "arrival-fit",
        /// `Table::Constrained` with eq. 30's rules.
        ConstrainedFit = "constrained-fit",
        /// `HorizonRule::NlFit` on the table in use.
        NlFit = "nl-fit",
        /// `HorizonRule::ExactBand` on the table in use.
        ExactBand = "exact-band",
    }
}

impl Horizon {
    /// The table the remedy shades with, where it is a table.
    pub fn table(self) -> Option<Table> {
        match self {
            Self::ArrivalFit => Some(Table::Arrival),
            Self::ConstrainedFit => Some(Table::Constrained),
            _ => None,
        }
    }

    /// The rule the remedy shades with.
    pub fn rule(self) -> HorizonRule {
        match self {
            Self::NlFit => HorizonRule::NlFit,
            Self::ExactBand => HorizonRule::ExactBand,
            _ => HorizonRule::Eq30,
        }
    }

    /// One line for a tooltip or `--help`.
    pub fn describe(self) -> &'static str {
        match self {
            Self::Eq30 => "the paper's clipping rules alone (the reference)",
            Self::ArrivalFit => {
                "a table fitted with directions weighted by where lights above a plane arrive from"
            }
            Self::ConstrainedFit => {
                "a table fitted with m20 = 0: M⁻¹ never carries a light across the horizon"
            }
            Self::NlFit => "each lobe scaled by a quadratic in n·l below 30°, fitted per cell",
            Self::ExactBand => "the exact BRDF for lights below 15°, LTC above",
        }
    }
}
