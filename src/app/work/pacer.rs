//! How much work fits a frame: the size of the next chunk of a render spread over frames, from
//! the GPU time the last chunks took.

/// A proportional controller of chunk size on measured GPU time.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pacer {
    /// Units (lights, tile rows) in the last chunk.
    last: usize,
    /// The least time a chunk has taken: the fixed cost of a chunk (the per-pixel set-up,
    /// the resolve), which no smaller chunk can undercut.
    fixed_ms: Option<f64>,
    /// The time of the last chunk, once measured.
    last_ms: Option<f64>,
}

impl Default for Pacer {
    fn default() -> Self {
        Self {
            last: 1,
            fixed_ms: None,
            last_ms: None,
        }
    }
}

/// How far one chunk may grow or shrink the next: a render's cost is not linear in its units
/// (culled tiles run out of lights at different entries), so a measurement is followed, but
/// by at most this factor per frame.
const STEP_FACTOR: usize = 2;

impl Pacer {
    /// The time a chunk aims at: the budget, or — where a chunk's fixed cost alone exceeds it
    /// (a CPU driver at a large size) — half again that cost, so that the render still
    /// advances.
    pub fn target_ms(&self, budget_ms: f64) -> f64 {
        self.fixed_ms.map_or(budget_ms, |f| budget_ms.max(1.5 * f))
    }

    /// Units of the next chunk, at least 1.
    pub fn next(&self, budget_ms: f64) -> usize {
        let Some(ms) = self.last_ms.filter(|&ms| ms > 0.0) else {
            return self.last.max(1);
        };
        let wanted = (self.last as f64 * self.target_ms(budget_ms) / ms).ceil() as usize;
        wanted.clamp(
            (self.last / STEP_FACTOR).max(1),
            self.last.saturating_mul(STEP_FACTOR),
        )
    }

    /// A chunk of `units` took `ms` of GPU time.
    pub fn record(&mut self, units: usize, ms: f64) {
        self.last = units.max(1);
        self.last_ms = Some(ms);
        self.fixed_ms = Some(self.fixed_ms.map_or(ms, |f| f.min(ms)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chunks_grow_to_the_budget_and_shrink_past_it() {
        let mut p = Pacer::default();
        assert_eq!(p.next(8.0), 1);
        // 1 ms per unit plus nothing fixed: doubling up to 8 units.
        let mut units = p.next(8.0);
        for _ in 0..6 {
            p.record(units, units as f64);
            units = p.next(8.0);
        }
        assert_eq!(units, 8);
        // Twice as slow now: halves.
        p.record(8, 16.0);
        assert_eq!(p.next(8.0), 4);
    }

    #[test]
    fn a_fixed_cost_above_the_budget_still_lets_the_render_advance() {
        let mut p = Pacer::default();
        // 30 ms fixed, 0.1 ms per unit: the target becomes 45 ms, 150 units.
        let mut units = 1;
        for _ in 0..20 {
            p.record(units, 30.0 + 0.1 * units as f64);
            units = p.next(8.0);
        }
        assert!((140..=160).contains(&units), "{units}");
    }
}
