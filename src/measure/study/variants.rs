//! The study's shading variants (docs/design.md §4.6): each a method, its rules and the table
//! it reads, by name — the lab's forms, the horizon remedies, and each table encoding's
//! `ltc-table-NAME`.

use crate::ltc::lut::Encoding;
use crate::ltc::remedy::Horizon;
use crate::ltc::{Clipping, Normalization};
use crate::render::{LtcRules, LutFilter, Method, RenderSettings};

/// Which table a variant shades with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LutChoice {
    /// The shipped 64×64 table.
    Shipped,
    /// A table of this size fitted by `ltc::fit` at the study's start.
    Fitted(usize),
    /// The shipped point-light fit (`luts/ltc_point.exr`).
    Point,
    /// The horizon remedies' fits (`luts/ltc_arrival.exr`, `luts/ltc_constrained.exr`).
    Arrival,
    Constrained,
    /// The shipped table as an encoding gives it back (docs/design.md §2.10).
    Encoded(Encoding),
}

/// One shading variant of the study.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Variant {
    pub name: &'static str,
    pub method: Method,
    pub normalization: Normalization,
    pub filter: LutFilter,
    pub lut: LutChoice,
    /// The horizon remedy (eq30 but in the remedies' variants).
    pub horizon: Horizon,
}

/// The variants the study compares (docs/design.md §4.6), and `ltc-fast` with each horizon remedy
/// (docs/design.md §4.7); `brdf` is the reference (error 0).
pub fn variants() -> Vec<Variant> {
    let v = |name, method, normalization, filter, lut| Variant {
        name,
        method,
        normalization,
        filter,
        lut,
        horizon: Horizon::Eq30,
    };
    let remedy = |name, lut, horizon| Variant {
        horizon,
        ..v(
            name,
            Method::LtcFast,
            Normalization::Corrected,
            LutFilter::Bilinear,
            lut,
        )
    };
    use LutChoice::*;
    use LutFilter::*;
    use Method::*;
    use Normalization::*;
    vec![
        v("brdf", Brdf, Corrected, Bilinear, Shipped),
        v("brdf-fast", BrdfFast, Corrected, Bilinear, Shipped),
        LTC,
        v("ltc-fast", LtcFast, Corrected, Bilinear, Shipped),
        v("ltc-paper", Ltc, PaperLiteral, Bilinear, Shipped),
        v("ltc-nearest", Ltc, Corrected, Nearest, Shipped),
        v("ltc-lut16", Ltc, Corrected, Bilinear, Fitted(16)),
        v("ltc-lut32", Ltc, Corrected, Bilinear, Fitted(32)),
        v("ltc-point", Ltc, Corrected, Bilinear, Point),
        v("ltc-fast-point", LtcFast, Corrected, Bilinear, Point),
        // Where the adapter has SHADER_F16 (`run` drops them elsewhere).
        v("ltc-f16", LtcF16, Corrected, Bilinear, Shipped),
        v("ltc-f16-pairs", LtcF16Pairs, Corrected, Bilinear, Shipped),
        remedy("ltc-fast-arrival-fit", Arrival, Horizon::ArrivalFit),
        remedy(
            "ltc-fast-constrained-fit",
            Constrained,
            Horizon::ConstrainedFit,
        ),
        remedy("ltc-fast-nl-fit", Shipped, Horizon::NlFit),
        remedy("ltc-fast-exact-band", Shipped, Horizon::ExactBand),
    ]
}

/// The variant every other is measured against (error 0), the first of `variants`, which a
/// study always runs.
pub const REFERENCE: &str = "brdf";

/// `variant`'s name, or why there is none, naming the names there are (`study --variants`).
pub fn variant_named(name: &str) -> Result<&'static str, String> {
    variant(name).map(|v| v.name).ok_or_else(|| {
        let names: Vec<&str> = variants().iter().map(|v| v.name).collect();
        format!("no variant {name:?}; the variants: {}", names.join(", "))
    })
}

/// The `ltc` variant, which each encoding's variant shades as.
pub const LTC: Variant = Variant {
    name: "ltc",
    method: Method::Ltc,
    normalization: Normalization::Corrected,
    filter: LutFilter::Bilinear,
    lut: LutChoice::Shipped,
    horizon: Horizon::Eq30,
};

impl Variant {
    /// How the variant renders at `size`, culling or not.
    pub fn settings(&self, cull: bool, (width, height): (usize, usize)) -> RenderSettings {
        RenderSettings {
            rules: LtcRules {
                clipping: Clipping::BOTH,
                normalization: self.normalization,
                filter: self.filter,
                horizon: self.horizon.rule(),
            },
            cull,
            ..RenderSettings::single(width, height, self.method)
        }
    }
}

/// The variant named `name`.
pub fn variant(name: &str) -> Option<Variant> {
    variants().into_iter().find(|v| v.name == name)
}

/// The variant name of the shipped table in `encoding` (`ltc-table-unorm8`).
pub fn encoded_variant(encoding: Encoding) -> String {
    format!("ltc-table-{}", encoding.name())
}

/// The encoding a variant's name stands for, if it is one (`encoded_variant`'s inverse).
pub fn variant_encoding(name: &str) -> Option<Encoding> {
    Encoding::parse(name.strip_prefix("ltc-table-")?).ok()
}
