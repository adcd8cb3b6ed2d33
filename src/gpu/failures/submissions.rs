//! A render split into submissions that an operating system's GPU watchdog never sees
//! (docs/design.md §5.14): Windows resets a device whose submission runs for 2 s (TDR's default
//! `TdrDelay`), and other systems do likewise, losing the device with it. Each submission's
//! estimated work — pixels × lights × the work of one light (`gpu::work`'s count, a method
//! file's loops at their whole step budget) — stays under `MAX_SUBMISSION_WORK`: a chunk of
//! lights over the whole image, or, where one light over the whole image is already past it,
//! one light over a band of tile rows.

use crate::gpu::scene::TILE_SIDE;

/// The most estimated work (operations, `gpu::work::Work::operations`) one submission may hold.
/// The slowest GPU the lab expects, an integrated Intel UHD Graphics 630 (24 EUs × 16 f32
/// operations a clock × 1.15 GHz = 0.44 TFLOP/s, Intel's Gen9.5 data sheet), does 0.9·10¹²
/// operations in a 2 s watchdog; this is a ninth of that, for what the count leaves out
/// (memory's stalls, a loop of the lab's counted once).
pub const MAX_SUBMISSION_WORK: f64 = 1e11;

/// The longest one submission of a render with a method file may take before the render is
/// stopped (docs/design.md §5.13), in the lab and the CLI alike: a submission is sized to take
/// a small part of it on any GPU, so one this long is a file at its worst on a slow device.
pub const METHOD_FILE_SUBMISSION_MS: f64 = 2000.0;

/// How a render of `lights` on a `width × height` image is split: `lights_per` lights over
/// `rows_per` tile rows a submission.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Plan {
    pub lights: usize,
    pub rows: u32,
    pub lights_per: usize,
    pub rows_per: u32,
}

impl Plan {
    /// The split of `lights` lights of `work_per_light` operations a pixel each over an image of
    /// `width × height` pixels.
    pub fn new(width: usize, height: usize, lights: usize, work_per_light: f64) -> Self {
        let rows = height.div_ceil(TILE_SIDE).max(1) as u32;
        // A band's pixels are whole tiles: its workgroups run every invocation.
        let row_work =
            (width.div_ceil(TILE_SIDE) * TILE_SIDE * TILE_SIDE) as f64 * work_per_light.max(1.0);
        let image_work = row_work * f64::from(rows);
        let (lights_per, rows_per) = if image_work <= MAX_SUBMISSION_WORK {
            let per = (MAX_SUBMISSION_WORK / image_work).floor() as usize;
            (per.clamp(1, lights.max(1)), rows)
        } else {
            let per = (MAX_SUBMISSION_WORK / row_work).floor() as u32;
            (1, per.clamp(1, rows))
        };
        Self {
            lights,
            rows,
            lights_per,
            rows_per,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A submission of the plan — `lights_per` lights over `rows_per` tile rows — stays within
    /// the bound, unless it is already one light over one row; and it never asks for more
    /// lights or rows than the render has (`PlaneRender::run` walks the render in these).
    #[test]
    fn a_planned_submission_stays_within_the_bound() {
        for (w, h, lights, work) in [
            (512, 512, 100, 300.0),
            (1920, 1080, 65_536, 2.0e5),
            (1920, 1080, 1, 1e9),
            (16, 16, 0, 10.0),
            (17, 33, 7, 1e12),
        ] {
            let plan = Plan::new(w, h, lights, work);
            assert_eq!(plan.rows, h.div_ceil(16) as u32);
            assert!((1..=lights.max(1)).contains(&plan.lights_per), "{plan:?}");
            assert!((1..=plan.rows).contains(&plan.rows_per), "{plan:?}");
            let band = (w.div_ceil(16) * 256 * plan.rows_per as usize) as f64;
            let estimate = band * plan.lights_per as f64 * work;
            let smallest = plan.lights_per == 1 && plan.rows_per == 1;
            assert!(
                estimate <= MAX_SUBMISSION_WORK || smallest,
                "{w}x{h} {lights}: {plan:?}"
            );
            // Bands only where one light over the whole image is past the bound.
            assert_eq!(
                plan.rows_per < plan.rows,
                plan.lights_per == 1 && {
                    let image = (w.div_ceil(16) * 256) as f64 * f64::from(plan.rows) * work;
                    image > MAX_SUBMISSION_WORK
                }
            );
        }
        // 65,536 lights at a method file's worst: one light over bands of rows.
        let worst = Plan::new(1920, 1080, 65_536, 2.0e5);
        assert_eq!(worst.lights_per, 1);
        assert!(worst.rows_per < worst.rows);
    }
}
