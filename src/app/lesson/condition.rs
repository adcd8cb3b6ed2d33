//! A step's *try this* condition: `quantity op number`, joined by `and`, over what the lab
//! shows now (docs/design.md §5.11): `morph <= 0.05`, `case1 == 0 and case2 == 0`,
//! `pinned_case1 >= 1`. The quantities are named for the controls a student moves.

use std::fmt;
use std::str::FromStr;

use crate::app::chart::measure::Measurement;
use crate::app::lab::Lab;
use crate::app::lobe::LobeState;
use crate::app::plane::PlaneState;
use crate::light::rect::RectMethod;
use crate::ltc::{ClipCase, Normalization};
use crate::named::named_enum;
use crate::pixel::PixelTerms;
use crate::render::View;

/// What the lab shows now: its parts, and the panels' own settings and results a lesson reads.
#[derive(Clone, Copy)]
pub struct Now<'a> {
    pub lab: &'a Lab,
    pub lobe: &'a LobeState,
    pub plane: &'a PlaneState,
    /// The plane's pinned pixel opened into its lights, once computed.
    pub pinned: Option<&'a PixelTerms>,
    /// The chart's measurement (or the reference study it starts with).
    pub measurement: Option<&'a Measurement>,
    /// Measurements the chart finished: since the lab started, or, as a step's condition
    /// reads it, since the step was opened.
    pub measurements: u64,
}

named_enum! {
    /// What a condition reads, each a number (a switch is 1 on, 0 off).
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub enum Quantity {
        Alpha = "alpha",
        ThetaO = "theta_o",
        AlphaY = "alpha_y",
        PhiO = "phi_o",
        F0 = "f0",
        Morph = "morph",
        Case1 = "case1",
        Case2 = "case2",
        PaperLiteral = "paper_literal",
        Lights = "lights",
        LobeLight = "lobe_light",
        LightElevation = "light_elevation",
        Pinned = "pinned",
        PinnedCase1 = "pinned_case1",
        PinnedCase2 = "pinned_case2",
        Difference = "difference",
        Divider = "divider",
        Measured = "measured",
        RectProxy = "rect_proxy",
    }
}

impl Quantity {
    /// What it is, for the lesson's authors (the README lists these).
    pub fn describe(self) -> &'static str {
        match self {
            Self::Alpha => "the material's GGX α",
            Self::ThetaO => "θo, degrees",
            Self::AlphaY => "the material's α_y (its α while isotropic)",
            Self::PhiO => "φo, the view's azimuth from the tangent, degrees",
            Self::F0 => "Schlick's F0",
            Self::Morph => "the lobe panel's \"M: I -> fitted\" slider, 0 to 1",
            Self::Case1 => "clipping rule 1 (clip at the surface's horizon) on: 1, off: 0",
            Self::Case2 => "clipping rule 2 (clip after M^-1) on: 1, off: 0",
            Self::PaperLiteral => "the paper's eq. 25 as printed (1) or corrected (0)",
            Self::Lights => "the scene's light count",
            Self::LobeLight => "a light shown on the lobe panel: 1, none: 0",
            Self::LightElevation => "the lobe panel's light's elevation, degrees",
            Self::Pinned => "a pixel pinned on the plane: 1, none: 0",
            Self::PinnedCase1 => "the pinned pixel's lights in clipping case 1",
            Self::PinnedCase2 => "the pinned pixel's lights in clipping case 2",
            Self::Difference => "the plane shows the difference map: 1, else 0",
            Self::Divider => "the plane's divider, 0 (left) to 1 (right)",
            Self::Measured => "measurements the chart finished since the step opened",
            Self::RectProxy => {
                "the LTC side shades rects by a proxy (ltc-proxy or ltc-proxy-fast): 1, else 0"
            }
        }
    }

    /// Its value now; `None` where it has none yet (no light on the lobe, no pixel pinned).
    pub fn value(self, now: &Now<'_>) -> Option<f64> {
        let lab = now.lab;
        let switch = |on: bool| Some(if on { 1.0 } else { 0.0 });
        let light = lab.lobe_view().light;
        let count = |case: ClipCase| {
            now.pinned
                .map(|p| p.terms.iter().filter(|t| t.case == case).count() as f64)
        };
        match self {
            Self::Alpha => Some(lab.alpha()),
            Self::ThetaO => Some(lab.lobe_view().theta_o_deg),
            Self::AlphaY => Some(lab.material().roughness().y),
            Self::PhiO => Some(lab.lobe_view().phi_o_deg),
            Self::F0 => Some(lab.material().f0),
            Self::Morph => Some(now.lobe.morph),
            Self::Case1 => switch(lab.rules().clipping.case1),
            Self::Case2 => switch(lab.rules().clipping.case2),
            Self::PaperLiteral => switch(lab.rules().normalization == Normalization::PaperLiteral),
            Self::Lights => Some(lab.lights().list.len() as f64),
            Self::LobeLight => switch(light.is_some()),
            // Elevation above the surface, degrees.
            Self::LightElevation => light.map(|l| l[2].clamp(-1.0, 1.0).asin().to_degrees()),
            Self::Pinned => switch(now.plane.pinned.is_some()),
            Self::PinnedCase1 => count(ClipCase::Lifted),
            Self::PinnedCase2 => count(ClipCase::PushedBelow),
            Self::Difference => switch(now.plane.view == View::Diff),
            Self::Divider => Some(now.plane.divider),
            Self::Measured => switch(now.measurements > 0),
            Self::RectProxy => switch(matches!(
                lab.shape_forms().ltc.get(),
                RectMethod::LtcProxy | RectMethod::LtcProxyFast
            )),
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Op {
    Lt,
    Le,
    Gt,
    Ge,
    Eq,
    Ne,
}

impl Op {
    /// Longest first, so that `<=` is not read as `<`.
    const ALL: [(&'static str, Self); 6] = [
        ("<=", Self::Le),
        (">=", Self::Ge),
        ("==", Self::Eq),
        ("!=", Self::Ne),
        ("<", Self::Lt),
        (">", Self::Gt),
    ];

    fn holds(self, a: f64, b: f64) -> bool {
        match self {
            Self::Lt => a < b,
            Self::Le => a <= b,
            Self::Gt => a > b,
            Self::Ge => a >= b,
            // A switch's 0 and 1, a count: exact; a slider's value: within a rounding.
            Self::Eq => (a - b).abs() <= 1e-9 * b.abs().max(1.0),
            Self::Ne => (a - b).abs() > 1e-9 * b.abs().max(1.0),
        }
    }

    fn text(self) -> &'static str {
        Self::ALL
            .iter()
            .find(|(_, op)| *op == self)
            .map_or("?", |(t, _)| t)
    }
}

/// One comparison.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Test {
    quantity: Quantity,
    op: Op,
    value: f64,
}

/// Comparisons that must all hold.
#[derive(Clone, Debug, PartialEq)]
pub struct Condition(Vec<Test>);

impl Condition {
    /// Whether every comparison holds now (one without a value yet does not).
    pub fn holds(&self, now: &Now<'_>) -> bool {
        self.0.iter().all(|t| {
            t.quantity
                .value(now)
                .is_some_and(|v| t.op.holds(v, t.value))
        })
    }
}

impl FromStr for Condition {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        let tests = text
            .split(" and ")
            .map(|part| {
                let part = part.trim();
                let (at, (op_text, op)) = Op::ALL
                    .iter()
                    .filter_map(|&(t, op)| part.find(t).map(|at| (at, (t, op))))
                    .min_by_key(|&(at, (t, _))| (at, std::cmp::Reverse(t.len())))
                    .ok_or_else(|| format!("'{part}' has no comparison (<, <=, >, >=, ==, !=)"))?;
                let name = part[..at].trim();
                let quantity = Quantity::from_name(name).ok_or_else(|| {
                    let names: Vec<&str> = Quantity::ALL.iter().map(|q| q.name()).collect();
                    format!(
                        "'{name}' is not a quantity the lab checks ({})",
                        names.join(", ")
                    )
                })?;
                let number = part[at + op_text.len()..].trim();
                let value: f64 = number
                    .parse()
                    .ok()
                    .filter(|v: &f64| v.is_finite())
                    .ok_or_else(|| format!("'{number}' is not a finite number"))?;
                Ok(Test {
                    quantity,
                    op,
                    value,
                })
            })
            .collect::<Result<Vec<_>, String>>()?;
        Ok(Self(tests))
    }
}

impl fmt::Display for Condition {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (k, t) in self.0.iter().enumerate() {
            if k > 0 {
                f.write_str(" and ")?;
            }
            write!(f, "{} {} {}", t.quantity.name(), t.op.text(), t.value)?;
        }
        Ok(())
    }
}
