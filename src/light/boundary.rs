//! A light's boundary and its brightest point (docs/design.md §1.14): where a glossy lobe
//! peaks outside the light, the polar rule's pole is the boundary's point where the lobe is
//! largest. `shaders/boundary.wgsl` is the same search by name.

use glam::{DVec2, DVec3};

/// A smooth piece of a region's boundary, `s ∈ [0, 1]`: a great circle's arc between two
/// directions or a cap's circle between two angles about its axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Arc {
    /// `normalize(a + (b − a) s)`.
    Line { a: DVec3, b: DVec3 },
    /// `cos σ axis + sin σ (t₁ cos ψ + t₂ sin ψ)`, `ψ = from + sweep s`.
    Circle {
        axis: DVec3,
        cos_sin: DVec2,
        t1: DVec3,
        t2: DVec3,
        from: f64,
        sweep: f64,
    },
}

impl Arc {
    /// The arc's direction at `s`.
    pub fn at(&self, s: f64) -> DVec3 {
        match *self {
            Self::Line { a, b } => (a + (b - a) * s).normalize(),
            Self::Circle {
                axis,
                cos_sin,
                t1,
                t2,
                from,
                sweep,
            } => {
                let (sin, cos) = (from + sweep * s).sin_cos();
                axis * cos_sin.x + (t1 * cos + t2 * sin) * cos_sin.y
            }
        }
    }

    /// The unit tangent along the arc at `x` (a point of it).
    pub fn tangent(&self, x: DVec3) -> DVec3 {
        match *self {
            Self::Line { a, b } => a.cross(b).cross(x).normalize(),
            Self::Circle { axis, .. } => axis.cross(x).normalize(),
        }
    }
}

/// Samples along each arc the brightest point is looked for among.
pub const BRIGHTEST_SAMPLES: usize = 16;

/// Golden-section steps that narrow the brightest sample's neighbourhood.
pub const BRIGHTEST_STEPS: usize = 24;

/// How near an arc's end (in its parameter) the brightest point is taken to be its corner. A
/// pole a twentieth of an edge from its corner leaves the next edge that far from it, a
/// sliver the rule still integrates to its bound.
pub const CORNER_SNAP: f64 = 0.05;

/// The point of the boundary `arcs` where `g` is largest (a glossy lobe's peak restricted to
/// a light it misses): the best of `BRIGHTEST_SAMPLES + 1` samples an arc, then narrowed by
/// golden sections between its neighbours; the arc and its parameter.
pub fn brightest(arcs: &[Arc], g: impl Fn(DVec3) -> f64) -> (usize, f64) {
    let step = 1.0 / BRIGHTEST_SAMPLES as f64;
    let mut best = (f64::NEG_INFINITY, 0, 0.0);
    for (k, arc) in arcs.iter().enumerate() {
        for i in 0..=BRIGHTEST_SAMPLES {
            let s = i as f64 * step;
            let value = g(arc.at(s));
            if value > best.0 {
                best = (value, k, s);
            }
        }
    }
    let (_, k, s) = best;
    let arc = &arcs[k];
    let (mut lo, mut hi) = ((s - step).max(0.0), (s + step).min(1.0));
    // The golden ratio's conjugate, (√5 − 1)/2.
    let ratio = 0.618_033_988_749_894_9;
    for _ in 0..BRIGHTEST_STEPS {
        let m1 = hi - ratio * (hi - lo);
        let m2 = lo + ratio * (hi - lo);
        if g(arc.at(m1)) >= g(arc.at(m2)) {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    // A point within `CORNER_SNAP` of the arc's end is its corner: a pole just off a corner
    // leaves a sliver of the next edge beside it, which the rule integrates badly, and f32's
    // search ends there where f64's reaches the corner (a lobe's plateau at the corner is
    // rounding noise to f32).
    let s = 0.5 * (lo + hi);
    let s = if s < CORNER_SNAP {
        0.0
    } else if s > 1.0 - CORNER_SNAP {
        1.0
    } else {
        s
    };
    (k, s)
}
