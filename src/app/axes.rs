//! Plot axes the lab's charts share: a symmetric log axis for signed values over decades, a
//! log axis for positive ones, both with ticks at round values and labelled with the values
//! themselves (egui_plot draws in the transformed coordinates).

use egui_plot::{GridInput, GridMark, Plot};

use crate::colormap::{round_sig, short_number, symlog, symlog_inverse};

/// A plot whose y coordinates are `symlog(value, c)`: ticks at 0 and ±10ᵏ, labelled in values.
pub fn symlog_y(plot: Plot<'_>, c: f64) -> Plot<'_> {
    plot.y_grid_spacer(move |input: GridInput| {
        let (lo, hi) = input.bounds;
        let top = symlog_inverse(lo.abs().max(hi.abs()), c);
        let mut marks = vec![GridMark {
            value: 0.0,
            step_size: 1.0,
        }];
        // Round decades only: the first power of ten at or above the linear threshold.
        let mut p = 10f64.powf(c.log10().ceil());
        while p <= top * 1.0001 {
            for v in [p, -p] {
                let value = symlog(v, c);
                if (lo..=hi).contains(&value) {
                    marks.push(GridMark {
                        value,
                        step_size: 1.0,
                    });
                }
            }
            p *= 10.0;
        }
        marks
    })
    .y_axis_formatter(move |mark, _| short_number(round_sig(symlog_inverse(mark.value, c))))
}

/// A plot whose `axis` coordinates are log10 of the values: ticks at 1, 2, 5 × 10ᵏ (decades
/// only when that would crowd), labelled in values.
pub fn log_axis(plot: Plot<'_>, x: bool) -> Plot<'_> {
    let spacer = |input: GridInput| {
        let (lo, hi) = input.bounds;
        let decades = hi - lo;
        let multiples: &[f64] = if decades > 3.0 {
            &[1.0]
        } else {
            &[1.0, 2.0, 5.0]
        };
        let mut marks = Vec::new();
        for k in (lo.floor() as i32)..=(hi.ceil() as i32) {
            for &m in multiples {
                let value = (m * 10f64.powi(k)).log10();
                if (lo..=hi).contains(&value) {
                    marks.push(GridMark {
                        value,
                        step_size: if m == 1.0 { 1.0 } else { 0.3 },
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
