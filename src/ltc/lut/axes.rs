//! The table's axes (docs/design.md §2.3): column `i` ↔ roughness `r = √α`, row `j` ↔
//! `sqrt(1 − cos θo)`, and the texture coordinate a GPU sampler reads them at.

use crate::ltc::lut::Lut;

/// α_min = 1e-4, the `MIN_ALPHA` of ltc_code's published fit. Smaller (ltc_code's later 1e-5)
/// makes the r = 0 lobe a near-delta whose `M⁻¹` entries grow like 1/α (1e5) — an f32
/// bilinear blend with the next column is then meaningless; larger (a fork's 5e-4, Unity's
/// 1e-3) clamps the r = 1/63 column (α = r² = 2.5e-4) onto the r = 0 one, so the table loses
/// a column of its resolution. Any value below 2.5e-4 keeps every column distinct.
pub const ALPHA_MIN: f64 = 1e-4;

/// ltc_code clamps θo just below 90° (1.57 rad) so that the grazing row has `n·v > 0`.
pub const THETA_MAX: f64 = 1.57;

/// Column `i` ↔ `r = i/(N−1)`, `α = max(r², α_min)`.
pub fn cell_alpha(i: usize, size: usize, alpha_min: f64) -> f64 {
    let r = i as f64 / (size - 1) as f64;
    (r * r).max(alpha_min)
}

/// Row `j` ↔ `sqrt(1 − cos θo) = j/(N−1)`, θo clamped to `THETA_MAX`.
pub fn cell_theta(j: usize, size: usize) -> f64 {
    let x = j as f64 / (size - 1) as f64;
    (1.0 - x * x).clamp(-1.0, 1.0).acos().min(THETA_MAX)
}

/// The table's axes at `(α, cos θo)`: `(r, s) = (sqrt α, sqrt(1 − cos θo))`, each in [0, 1]
/// where the table has cells.
pub fn axes(alpha: f64, cos_theta_o: f64) -> (f64, f64) {
    (
        alpha.max(0.0).sqrt(),
        (1.0 - cos_theta_o.clamp(0.0, 1.0)).sqrt(),
    )
}

impl Lut {
    /// The GPU texture coordinate of docs/design.md §2.3:
    /// `uv = (r, sqrt(1 − cos θo)) · (N−1)/N + 0.5/N`, `r = sqrt(α)`.
    pub fn uv(&self, alpha: f64, cos_theta_o: f64) -> (f64, f64) {
        let (r, s) = axes(alpha, cos_theta_o);
        self.uv_of_axes(r, s)
    }

    /// The texture coordinate of the table's axes `(r, s)`, each in [0, 1]: cell `(i, j)` of
    /// any N sits at `(i/(N−1), j/(N−1))` — also the grazing row, whose θo is clamped.
    pub fn uv_of_axes(&self, r: f64, s: f64) -> (f64, f64) {
        let n = self.size as f64;
        let scale = (n - 1.0) / n;
        let bias = 0.5 / n;
        (r * scale + bias, s * scale + bias)
    }

    /// The cell nearest `(α, cos θo)` on the table's axes: (column of α, row of θo).
    pub fn nearest_cell(&self, alpha: f64, cos_theta_o: f64) -> (usize, usize) {
        let n = self.size;
        let (r, s) = axes(alpha, cos_theta_o);
        let at = |x: f64| ((x * (n - 1) as f64).round() as usize).min(n - 1);
        (at(r), at(s))
    }

    /// α of column `i`.
    pub fn alpha(&self, i: usize) -> f64 {
        cell_alpha(i, self.size, self.alpha_min)
    }

    /// θo (radians) of row `j`.
    pub fn theta_o(&self, j: usize) -> f64 {
        cell_theta(j, self.size)
    }
}
