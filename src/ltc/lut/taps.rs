//! A texture sampler's arithmetic on one axis, shared by the 2D table and the 4D one
//! (docs/design.md §2.3, §2.9).

/// One axis of bilinear filtering with clamp-to-edge addressing at coordinate `t` of a table
/// of `n` cells: the two texels (clamped into the table) and the weight of the second.
pub fn bilinear_taps(n: usize, t: f64) -> (usize, usize, f64) {
    let x = if t.is_finite() {
        t * n as f64 - 0.5
    } else {
        0.0
    };
    let x0 = x.floor();
    let clamp = |k: f64| k.clamp(0.0, (n - 1) as f64) as usize;
    (clamp(x0), clamp(x0 + 1.0), x - x0)
}
