//! Formulas in place of the table (docs/design.md §2.10): each shader channel as a function of
//! the table's axes `(r, s)`, shipped as coefficients instead of cells. A Chebyshev series
//! (`chebD`, three.js PR #34611's form) or one rational function (`rationalD`), fitted to a
//! table's cells, and the table rebuilt from it at the table's own cells, as #34611 rebuilds
//! its textures at run time.

mod chebyshev;
mod least_squares;
mod rational;

pub use chebyshev::{chebyshev_fit, chebyshev_terms, chebyshev_value};
pub use least_squares::least_squares;
pub use rational::{rational_coefficients, rational_fit, rational_value};

use crate::ltc::lut::Lut;
use crate::ltc::lut::channel::SHADER_CHANNELS;

/// The largest degrees accepted: a Chebyshev series of degree 40 has 1 681 coefficients a
/// channel (more than the 64² table's 4 096 cells hold as data, with a 41-column fit at 64
/// cells a side); a rational fit of degree 8 has 89, past which its passes no longer
/// stay free of poles on the shipped tables.
pub const MAX_CHEBYSHEV_DEGREE: usize = 40;
pub const MAX_RATIONAL_DEGREE: usize = 8;

/// Which formula, and its degree.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Formula {
    /// `Σ c_ab T_a T_b`, `a, b ≤ D`: `(D + 1)²` coefficients a channel.
    Chebyshev(usize),
    /// `P / Q`, each of total degree `D` in Chebyshev products, `Q`'s constant 1.
    Rational(usize),
}

impl Formula {
    /// `chebD` or `rationalD`; `None` where `text` names neither (it may be a storage),
    /// an error where the degree is wrong.
    pub fn parse(text: &str) -> Option<Result<Self, String>> {
        let (kind, digits, max): (fn(usize) -> Self, &str, usize) =
            if let Some(d) = text.strip_prefix("cheb") {
                (Self::Chebyshev, d, MAX_CHEBYSHEV_DEGREE)
            } else if let Some(d) = text.strip_prefix("rational") {
                (Self::Rational, d, MAX_RATIONAL_DEGREE)
            } else {
                return None;
            };
        Some(match digits.parse::<usize>() {
            Ok(d) if (1..=max).contains(&d) => Ok(kind(d)),
            _ => Err(format!(
                "`{text}`: the degree is a whole number from 1 to {max}, not `{digits}`"
            )),
        })
    }

    pub fn name(self) -> String {
        match self {
            Self::Chebyshev(d) => format!("cheb{d}"),
            Self::Rational(d) => format!("rational{d}"),
        }
    }

    /// Coefficients a channel.
    pub fn coefficients_per_channel(self) -> usize {
        match self {
            Self::Chebyshev(d) => (d + 1) * (d + 1),
            Self::Rational(d) => rational_coefficients(d),
        }
    }

    /// Coefficients in all: every shader channel's.
    pub fn coefficients(self) -> usize {
        SHADER_CHANNELS.len() * self.coefficients_per_channel()
    }

    /// Multiply-adds a lookup costs where the formula is evaluated per pixel instead of
    /// rebuilt into a texture: per channel, a Chebyshev series `(D+1)²` products of the two
    /// axes' terms (each axis's `D − 1` recurrences shared by every channel), a rational
    /// function its coefficients and a division.
    pub fn multiply_adds(self) -> usize {
        match self {
            Self::Chebyshev(d) => 2 * d.saturating_sub(1) + self.coefficients(),
            Self::Rational(d) => {
                2 * d.saturating_sub(1) + self.coefficients() + SHADER_CHANNELS.len()
            }
        }
    }

    /// The degree a table of `size` cells a side can be fitted with: a Chebyshev series has at
    /// most `size` terms an axis.
    pub fn for_size(self, size: usize) -> Self {
        match self {
            Self::Chebyshev(d) => Self::Chebyshev(d.min(size - 1)),
            Self::Rational(d) => Self::Rational(d),
        }
    }

    /// The formula fitted to `lut`'s shader channels (at `for_size`'s degree).
    pub fn fitted(self, lut: &Lut) -> FittedFormula {
        let formula = self.for_size(lut.size);
        let n = lut.size;
        let channels = SHADER_CHANNELS.map(|c| {
            let values: Vec<f64> = lut.cells.iter().map(|cell| cell.shaded(c)).collect();
            let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let coefficients = match formula {
                Formula::Chebyshev(d) => {
                    chebyshev_fit(&values, n, d).unwrap_or_else(|| vec![0.0; (d + 1) * (d + 1)])
                }
                Formula::Rational(d) => rational_fit(&values, n, d),
            };
            ChannelFit {
                coefficients,
                range: [lo, hi],
            }
        });
        FittedFormula { formula, channels }
    }
}

/// One channel's coefficients, and the range of its values over the table: an engine clamps
/// the formula into it, as a series that rings near the table's edges would otherwise give
/// `M⁻¹` a negative diagonal (a lobe turned inside out).
#[derive(Clone, Debug, PartialEq)]
pub struct ChannelFit {
    pub coefficients: Vec<f64>,
    pub range: [f64; 2],
}

/// A formula fitted to a table, channel by channel in `SHADER_CHANNELS`' order.
#[derive(Clone, Debug, PartialEq)]
pub struct FittedFormula {
    pub formula: Formula,
    pub channels: [ChannelFit; SHADER_CHANNELS.len()],
}

impl FittedFormula {
    /// Channel `k` (of `SHADER_CHANNELS`) at the table's axes `(r, s)`, clamped into its range.
    pub fn value(&self, k: usize, r: f64, s: f64) -> f64 {
        let fit = &self.channels[k];
        let v = match self.formula {
            Formula::Chebyshev(d) => chebyshev_value(&fit.coefficients, d, r, s),
            Formula::Rational(d) => rational_value(&fit.coefficients, d, r, s),
        };
        v.clamp(fit.range[0], fit.range[1])
    }

    /// `lut` with every shader channel of every cell the formula's value there (the errors
    /// and `spec.scale` kept): the table an engine rebuilds from the coefficients.
    pub fn rebuilt(&self, lut: &Lut) -> Lut {
        let n = lut.size;
        let mut out = Lut {
            nl_terms: Default::default(),
            ..lut.clone()
        };
        for (index, cell) in out.cells.iter_mut().enumerate() {
            let (i, j) = (index % n, index / n);
            // The cell's axes (docs/design.md §2.3): (i, j)/(N − 1).
            let (r, s) = (i as f64 / (n - 1) as f64, j as f64 / (n - 1) as f64);
            for (k, &c) in SHADER_CHANNELS.iter().enumerate() {
                cell.set_shaded(c, self.value(k, r, s));
            }
        }
        out
    }
}
