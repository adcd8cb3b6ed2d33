//! The lab's two false-colour maps, the same in every panel, PNG and shader: viridis for
//! magnitudes, a dark-centred diverging map for signed values; the scales that put a value
//! on them (linear, logarithmic) with round tick values for colour bars; and the symmetric
//! log the plots' signed axes use.

/// Viridis at nine even stops, sRGB: R's `viridisLite::viridis(9)` (#440154 … #FDE725),
/// itself matplotlib's map. Perceptually uniform and readable in grey.
const VIRIDIS: [[u8; 3]; 9] = [
    [0x44, 0x01, 0x54],
    [0x47, 0x2d, 0x7b],
    [0x3b, 0x52, 0x8b],
    [0x2c, 0x72, 0x8e],
    [0x21, 0x90, 0x8c],
    [0x27, 0xad, 0x81],
    [0x5d, 0xc8, 0x63],
    [0xaa, 0xdc, 0x32],
    [0xfd, 0xe7, 0x25],
];

/// Our own diverging stops, sRGB, −1 … 1: dark at zero (the panels are dark, and zero is
/// "no light" in the clipping thumbnails), lightness rising with |value| on both sides, blue
/// for negative and orange for positive (after Crameri's dark-centred `berlin`).
const DIVERGING: [[u8; 3]; 5] = [
    [0x9e, 0xd8, 0xff],
    [0x33, 0x73, 0xd9],
    [0x1a, 0x1a, 0x1f],
    [0xd9, 0x4d, 0x26],
    [0xff, 0xe0, 0x8c],
];

/// Piecewise linear between evenly spaced sRGB stops, `t` in [0, 1].
fn ramp(stops: &[[u8; 3]], t: f64) -> [u8; 3] {
    let t = if t.is_nan() { 1.0 } else { t.clamp(0.0, 1.0) };
    let x = t * (stops.len() - 1) as f64;
    let k = (x.floor() as usize).min(stops.len() - 2);
    let f = x - k as f64;
    std::array::from_fn(|c| {
        (f64::from(stops[k][c]) * (1.0 - f) + f64::from(stops[k + 1][c]) * f).round() as u8
    })
}

/// Viridis at `t` ∈ [0, 1] (NaN shows as the top colour, like an out-of-range value).
pub fn viridis(t: f64) -> [u8; 3] {
    ramp(&VIRIDIS, t)
}

/// The diverging map at `s` ∈ [−1, 1].
pub fn diverging(s: f64) -> [u8; 3] {
    ramp(&DIVERGING, 0.5 + 0.5 * s)
}

/// Which map a scale paints with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColourMap {
    Viridis,
    Diverging,
}

/// How values reach the colour map.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Scale {
    /// `lo` … `hi` linearly.
    Linear { lo: f64, hi: f64 },
    /// `lo` … `hi` (both > 0) by decades.
    Log { lo: f64, hi: f64 },
}

/// A value's colour: a map and a scale, with a name and unit for the colour bar.
#[derive(Clone, Debug, PartialEq)]
pub struct ColourScale {
    pub map: ColourMap,
    pub scale: Scale,
    /// What the colour means, with its unit ("luminance ×240", "relative error").
    pub label: String,
    /// Tick values read as percentages (relative differences and errors).
    pub percent: bool,
}

/// `sign(x) · log10(1 + |x|/c)`: linear near zero, logarithmic beyond `c`.
pub fn symlog(x: f64, c: f64) -> f64 {
    x.signum() * (x.abs() / c).ln_1p() / std::f64::consts::LN_10
}

/// The inverse of `symlog`.
pub fn symlog_inverse(y: f64, c: f64) -> f64 {
    y.signum() * c * (10f64.powf(y.abs()) - 1.0)
}

impl ColourScale {
    /// Magnitudes from `lo` to `hi`, viridis.
    pub fn linear(lo: f64, hi: f64, label: impl Into<String>) -> Self {
        let hi = if hi > lo { hi } else { lo + 1e-12 };
        Self {
            map: ColourMap::Viridis,
            scale: Scale::Linear { lo, hi },
            label: label.into(),
            percent: false,
        }
    }

    /// Magnitudes over decades, viridis.
    pub fn log(lo: f64, hi: f64, label: impl Into<String>) -> Self {
        let lo = lo.max(1e-300);
        Self {
            map: ColourMap::Viridis,
            scale: Scale::Log {
                lo,
                hi: hi.max(lo * 10.0),
            },
            label: label.into(),
            percent: false,
        }
    }

    /// Signed values in ±`max`, diverging and linear.
    pub fn signed(max: f64, label: impl Into<String>) -> Self {
        let max = max.abs().max(1e-300);
        Self {
            map: ColourMap::Diverging,
            scale: Scale::Linear { lo: -max, hi: max },
            label: label.into(),
            percent: false,
        }
    }

    /// The same scale with its values read as percentages.
    pub fn in_percent(self) -> Self {
        Self {
            percent: true,
            ..self
        }
    }

    /// A value as the bar's ticks print it.
    pub fn format(&self, x: f64) -> String {
        if self.percent {
            format!("{}%", short_number(100.0 * x))
        } else {
            short_number(x)
        }
    }

    /// Where `x` falls on the bar, in [0, 1] (NaN: 1).
    pub fn position(&self, x: f64) -> f64 {
        if x.is_nan() {
            return 1.0;
        }
        let t = match self.scale {
            Scale::Linear { lo, hi } => (x - lo) / (hi - lo),
            Scale::Log { lo, hi } => (x.max(lo).ln() - lo.ln()) / (hi.ln() - lo.ln()),
        };
        t.clamp(0.0, 1.0)
    }

    /// The value at bar position `t` (the inverse of `position`).
    pub fn value_at(&self, t: f64) -> f64 {
        match self.scale {
            Scale::Linear { lo, hi } => lo + t * (hi - lo),
            Scale::Log { lo, hi } => (lo.ln() + t * (hi.ln() - lo.ln())).exp(),
        }
    }

    /// The colour of bar position `t`.
    pub fn colour_at(&self, t: f64) -> [u8; 3] {
        match self.map {
            ColourMap::Viridis => viridis(t),
            ColourMap::Diverging => diverging(2.0 * t - 1.0),
        }
    }

    /// The colour of value `x`.
    pub fn colour(&self, x: f64) -> [u8; 3] {
        self.colour_at(self.position(x))
    }

    /// Round values to label the bar with, and where they fall on it.
    pub fn ticks(&self) -> Vec<(f64, f64)> {
        let values = match self.scale {
            Scale::Linear { lo, hi } => nice_ticks(lo, hi, 5),
            Scale::Log { lo, hi } => decades(lo, hi),
        };
        values.into_iter().map(|v| (self.position(v), v)).collect()
    }
}

/// Multiples of 1, 2 or 5 × 10ᵏ in [lo, hi], about `n` of them.
pub fn nice_ticks(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    let span = hi - lo;
    if span.is_nan() || span <= 0.0 || !span.is_finite() {
        return vec![lo];
    }
    let raw = span / n.max(1) as f64;
    let power = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * power)
        .find(|&s| s >= raw)
        .unwrap_or(10.0 * power);
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last).map(|k| k as f64 * step).collect()
}

/// The powers of ten in [lo, hi] (at most six, every other decade beyond that).
fn decades(lo: f64, hi: f64) -> Vec<f64> {
    let (a, b) = (lo.log10().ceil() as i32, hi.log10().floor() as i32);
    let stride = ((b - a) / 6 + 1).max(1) as usize;
    // Counted down from the top decade, so that the largest value always has its tick.
    let mut v: Vec<f64> = (a..=b)
        .rev()
        .step_by(stride)
        .map(|k| 10f64.powi(k))
        .collect();
    v.reverse();
    v
}

/// A tick or readout value, short: "0", "0.25", "1e-3", "−5e+4".
pub fn short_number(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let a = x.abs();
    if !(1e-3..1e4).contains(&a) {
        let s = format!("{x:.0e}");
        // A 1×10ᵏ tick reads "1e-3"; a value that is not one keeps a digit more.
        if (x / s.parse::<f64>().unwrap_or(x) - 1.0).abs() < 1e-9 {
            return s;
        }
        return format!("{x:.1e}");
    }
    let s = format!("{x:.4}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// `x` rounded to three significant digits (exposure factors; ticks computed through exp
/// and log, which come out a hair off).
pub fn round_sig(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let p = 10f64.powi(2 - x.abs().log10().floor() as i32);
    (x * p).round() / p
}
