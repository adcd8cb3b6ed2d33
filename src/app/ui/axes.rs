//! Plot axes the lab's charts share: a symmetric log axis for signed values over decades, a
//! log axis for positive ones, both with ticks at round values and labelled with the values
//! themselves (egui_plot draws in the transformed coordinates).

use egui_plot::{GridInput, GridMark, Plot};

use crate::colormap::{round_sig, short_number, symlog, symlog_inverse};

/// Decades between labelled ticks, so that labels keep the spacing egui_plot draws them at
/// (`AxisHints`' label spacing, full strength: 30 points on y, 80 on x). `base` is
/// `GridInput::base_step_size`: the plot units of its grid's minimum spacing, 8 points.
fn decade_stride(base: f64, x: bool) -> i32 {
    let points = if x { 80.0 } else { 30.0 };
    (base * points / 8.0).ceil().max(1.0) as i32
}

/// A plot whose y coordinates are `symlog(value, c)`: ticks at 0 and ±10ᵏ, labelled in values.
pub fn symlog_y(plot: Plot<'_>, c: f64) -> Plot<'_> {
    plot.y_grid_spacer(move |input: GridInput| {
        let (lo, hi) = input.bounds;
        let top = symlog_inverse(lo.abs().max(hi.abs()), c);
        // A decade of values is about one unit of symlog (for values well above `c`).
        let stride = decade_stride(input.base_step_size, false);
        let step_size = f64::from(stride);
        let mut marks = vec![GridMark {
            value: 0.0,
            step_size,
        }];
        // Round decades only, from the first power of ten at or above the linear threshold
        // down from the top, every `stride`-th (so that the largest is always labelled).
        let first = c.log10().ceil() as i32;
        let mut k = top.log10().floor() as i32;
        while k >= first {
            for v in [10f64.powi(k), -(10f64.powi(k))] {
                let value = symlog(v, c);
                if (lo..=hi).contains(&value) {
                    marks.push(GridMark { value, step_size });
                }
            }
            k -= stride;
        }
        marks
    })
    .y_axis_formatter(move |mark, _| short_number(round_sig(symlog_inverse(mark.value, c))))
}

/// A plot whose `axis` coordinates are log10 of the values: ticks at 1, 2, 5 × 10ᵏ (decades
/// only when that would crowd), labelled in values.
pub fn log_axis(plot: Plot<'_>, x: bool) -> Plot<'_> {
    let spacer = move |input: GridInput| {
        let (lo, hi) = input.bounds;
        let decades = hi - lo;
        let stride = decade_stride(input.base_step_size, x);
        let multiples: &[f64] = if decades > 3.0 || stride > 1 {
            &[1.0]
        } else {
            &[1.0, 2.0, 5.0]
        };
        let mut marks = Vec::new();
        for k in (lo.floor() as i32)..=(hi.ceil() as i32) {
            if k.rem_euclid(stride) != 0 {
                continue;
            }
            for &m in multiples {
                let value = (m * 10f64.powi(k)).log10();
                if (lo..=hi).contains(&value) {
                    marks.push(GridMark {
                        value,
                        step_size: if m == 1.0 { f64::from(stride) } else { 0.3 },
                    });
                }
            }
        }
        marks
    };
    let format = |mark: GridMark, _: &std::ops::RangeInclusive<f64>| {
        short_number(round_sig(10f64.powf(mark.value)))
    };
    if x {
        plot.x_grid_spacer(spacer).x_axis_formatter(format)
    } else {
        plot.y_grid_spacer(spacer).y_axis_formatter(format)
    }
}
