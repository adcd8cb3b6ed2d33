//! The renders' exact rule: integrals over a convex region of directions in polar coordinates
//! about a pole, stretched to the lobe (docs/design.md §1.14). `shaders/polar.wgsl` is the
//! same rule by name.
//!
//! A light's directions above the surface are a convex region of the sphere, cut out by a few
//! bounds (`Bounds`: great circles, a cap). About a pole `c` in it, each meridian
//! `ω(u) = cos u c + sin u d` leaves the region where its first bound stops it, in closed form
//! (`meridian`); so the region is a fan of pieces of azimuth, split where its boundary turns
//! (`cuts`), and `∫ g dω = ∫∫ g sin u du dφ` is smooth on each. A glossy lobe is integrated
//! about its peak in coordinates stretched to its ellipse (`Lobe`): azimuth by the ellipse's
//! own angle, radius by `tan(u/2) = (r/2) tan t`, which turns GGX's `1/(α² + θ²)²` into
//! `sin t cos t`. Nothing here depends on the integrand: a poor guess of the ellipse or the
//! pole costs convergence, never correctness.

use std::f64::consts::PI;
use std::sync::OnceLock;

use glam::{DVec2, DVec3};

use crate::light::sphere::quadrature::gauss_legendre;

/// The most planes a region has: a rect clipped by the horizon has five edges.
pub const MAX_PLANES: usize = 5;

/// The Gauss–Legendre rule of `n` nodes (up to `MAX_RULE_NODES`), computed once.
pub fn rule(n: usize) -> &'static [(f64, f64)] {
    static RULES: [OnceLock<Vec<(f64, f64)>>; MAX_RULE_NODES + 1] =
        [const { OnceLock::new() }; MAX_RULE_NODES + 1];
    RULES[n.min(MAX_RULE_NODES)].get_or_init(|| gauss_legendre(n.min(MAX_RULE_NODES)))
}

/// The most nodes `rule` keeps a rule of.
pub const MAX_RULE_NODES: usize = 128;

/// Nodes per dimension and piece of the renders' exact rule (docs/design.md §1.14: every
/// shipped preset within 2e-4 of a converged integral at 64 × 36 pixels).
pub const RULE_NODES: usize = 12;

/// Nodes a dimension and piece of the diffuse lobe, smooth everywhere: every shipped preset
/// within 1e-5 of the converged integral at 8 (9e-8 at 12, at twice the cost).
pub const DIFFUSE_NODES: usize = 8;

/// The same for an anisotropic material's specular lobe, whose ellipse the stretch follows
/// less well (the brushed presets within 1.1e-4 at 24, 5.4e-3 at 12).
pub const RULE_NODES_ANISO: usize = 24;

/// The nodes a dimension of the specular lobe's rule takes for a material of roughness
/// `alpha`.
pub fn rule_nodes(alpha: crate::brdf::Alpha<f64>) -> usize {
    if alpha.is_isotropic() {
        RULE_NODES
    } else {
        RULE_NODES_ANISO
    }
}

/// What cuts out a convex region of directions: great circles `n·ω ≥ 0` (`n` toward the
/// region) and at most one cap `|ω − axis|² ≤ 2 depth` (`depth = 1 − cos σ`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Bounds {
    pub planes: [DVec3; MAX_PLANES],
    pub count: usize,
    pub cap: Option<(DVec3, f64)>,
}

/// A convex region of directions as the polar rule reads it: where each meridian from a pole
/// inside it runs inside it. `Bounds` is one; a union of convex pieces whose union is convex
/// (a shape's own region, as its module defines it) is another.
pub trait Region {
    /// The part `[lo, hi]` of the meridian from `c` along the unit tangent `d` inside the
    /// region, in `T = tan(u/2) ∈ [0, ∞]`; `None` where none is.
    fn meridian(&self, c: DVec3, d: DVec3) -> Option<(f64, f64)>;
}

impl Region for Bounds {
    fn meridian(&self, c: DVec3, d: DVec3) -> Option<(f64, f64)> {
        Bounds::meridian(self, c, d)
    }
}

impl Bounds {
    /// The region above the surface of one cap (the whole upper hemisphere for `None`).
    pub fn above(cap: Option<(DVec3, f64)>) -> Self {
        let mut b = Self {
            cap,
            ..Self::default()
        };
        b.push(DVec3::Z);
        b
    }

    /// Adds the great circle of inward normal `n`.
    pub fn push(&mut self, n: DVec3) {
        self.planes[self.count] = n;
        self.count += 1;
    }

    /// Whether `x` is in the closed region.
    pub fn contains(&self, x: DVec3) -> bool {
        self.planes[..self.count].iter().all(|n| n.dot(x) >= 0.0)
            && self
                .cap
                .is_none_or(|(axis, depth)| 0.5 * (x - axis).length_squared() <= depth)
    }

    /// The part `[lo, hi]` of the meridian from `c` along the unit tangent `d` inside every
    /// bound, in `T = tan(u/2) ∈ [0, ∞]`; `None` where none is.
    pub fn meridian(&self, c: DVec3, d: DVec3) -> Option<(f64, f64)> {
        let mut lo: f64 = 0.0;
        let mut hi = f64::INFINITY;
        for n in &self.planes[..self.count] {
            let (l, h) = plane_meridian(n.dot(c), n.dot(d))?;
            lo = lo.max(l);
            hi = hi.min(h);
        }
        if let Some((axis, depth)) = self.cap {
            let (l, h) = cap_meridian(c, d, axis, depth)?;
            lo = lo.max(l);
            hi = hi.min(h);
        }
        (hi > lo).then_some((lo, hi))
    }
}

/// `A cos u + B sin u ≥ 0` on `u ∈ [0, π]`, in `T = tan(u/2)`: the part before its root where
/// `A ≥ 0` (the pole inside), after it where `A < 0`. The root's `T` is `sin/(1 + cos)` of
/// `(−B, A)/R` (or `(B, −A)/R`), in whichever form does not cancel.
pub fn plane_meridian(a: f64, b: f64) -> Option<(f64, f64)> {
    let r = a.hypot(b);
    if r == 0.0 {
        return Some((0.0, f64::INFINITY));
    }
    if a >= 0.0 {
        let root = if b < 0.0 { a / (r - b) } else { (r + b) / a };
        (root > 0.0).then_some((0.0, root))
    } else {
        let root = if b > 0.0 { -a / (r + b) } else { (r - b) / -a };
        Some((root, f64::INFINITY))
    }
}

/// `|ω(u) − a|² ≤ 2D` in `T`: with `q = |c − a|²/2` and `B = (a − c)·d` it is
/// `(2 − D − q) T² − 2B T + (q − D) ≤ 0`, each coefficient without cancellation for a small
/// cap (`q` and `D` are small differences computed as such).
pub fn cap_meridian(c: DVec3, d: DVec3, axis: DVec3, depth: f64) -> Option<(f64, f64)> {
    let q = 0.5 * (c - axis).length_squared();
    let b = (axis - c).dot(d);
    // 2 − D − q = cos σ + c·a > 0 for a pole in a cap smaller than a hemisphere.
    let lead = (2.0 - depth - q).max(f64::MIN_POSITIVE);
    let (lo, hi) = quadratic_roots(lead, -2.0 * b, q - depth)?;
    (hi > lo.max(0.0)).then_some((lo.max(0.0), hi))
}

/// The roots `x₁ ≤ x₂` of `a x² + b x + c` (`a > 0`), by the form that does not cancel.
fn quadratic_roots(a: f64, b: f64, c: f64) -> Option<(f64, f64)> {
    let disc = b * b - 4.0 * a * c;
    if disc < 0.0 {
        return None;
    }
    let s = -0.5 * (b + disc.sqrt().copysign(b));
    if s == 0.0 {
        return Some((0.0, 0.0));
    }
    let (x1, x2) = (c / s, s / a);
    Some((x1.min(x2), x1.max(x2)))
}

/// A lobe's ellipse on the tangent plane at the pole: an orthonormal basis `b1, b2` and the
/// symmetric positive-definite `s` (its columns in that basis) that takes the unit circle to
/// the lobe's widths, in radians of direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lobe {
    pub b1: DVec3,
    pub b2: DVec3,
    pub s: [DVec2; 2],
}

impl Lobe {
    /// Width 2 every way, where `tan(u/2) = tan t` is `u = 2t`: the plain polar rule, for a
    /// smooth integrand (the diffuse lobe).
    pub fn round(c: DVec3) -> Self {
        let (b1, b2) = tangent_basis(c);
        Self {
            b1,
            b2,
            s: [DVec2::new(2.0, 0.0), DVec2::new(0.0, 2.0)],
        }
    }

    /// GGX's specular lobe about the pole `c`, for the view `v` and roughness `(αx, αy)` along
    /// the frame's x and y: near the mirror direction a tilt `δh` of the half vector moves `l`
    /// by `2 (n·v) δh + 2 (v·δh) n`, which takes the NDF's ellipse of slopes `diag(αx, αy)` to
    /// the lobe's `A`; `s = √(A Aᵀ + dist² I)`, `dist` from the pole to the mirror direction
    /// (where the pole is off the peak, the tail about it falls off over that distance).
    pub fn specular(c: DVec3, v: DVec3, (ax, ay): (f64, f64)) -> Self {
        let (b1, b2) = tangent_basis(c);
        let moved = |dh: DVec3| dh * (2.0 * v.z) + DVec3::Z * (2.0 * v.dot(dh));
        let (lx, ly) = (moved(DVec3::X * ax), moved(DVec3::Y * ay));
        let a = [
            DVec2::new(b1.dot(lx), b2.dot(lx)),
            DVec2::new(b1.dot(ly), b2.dot(ly)),
        ];
        let dist2 = (c - mirror(v)).length_squared();
        // A floor keeps `s` invertible for a mirror lobe seen at grazing angles.
        let floor = 1e-8;
        let m00 = a[0].x * a[0].x + a[1].x * a[1].x + dist2 + floor;
        let m11 = a[0].y * a[0].y + a[1].y * a[1].y + dist2 + floor;
        let m01 = a[0].x * a[0].y + a[1].x * a[1].y;
        Self {
            b1,
            b2,
            s: sqrt_spd(m00, m01, m11),
        }
    }

    /// The lobe as the region limits it: along each principal axis of `s` the width `w` and
    /// the region's chord `d` along it through its `middle` (a point well inside) combine as
    /// `1/√(1/w² + 1/d²)`, the width of the product of the lobe and the light (a narrow strip
    /// across a wide lobe leaves a round product, not the lobe's 10:1 ellipse). Measured
    /// through the middle rather than the pole, the chord is the light's own width wherever
    /// the pole is, on its boundary too.
    pub fn within<R: Region>(self, bounds: &R, middle: DVec3) -> Self {
        let [a, b] = self.s;
        let (m00, m01, m11) = (a.x, a.y, b.y);
        let half_trace = 0.5 * (m00 + m11);
        let root = (0.25 * (m00 - m11) * (m00 - m11) + m01 * m01).sqrt();
        let (w1, w2) = (half_trace + root, (half_trace - root).max(1e-12));
        let angle = 0.5 * (2.0 * m01).atan2(m00 - m11);
        let e1 = DVec2::new(angle.cos(), angle.sin());
        let e2 = DVec2::new(-e1.y, e1.x);
        let chord = |e: DVec2| -> f64 {
            let t = self.b1 * e.x + self.b2 * e.y;
            [t, -t]
                .iter()
                .map(|&t| {
                    toward(middle, middle + t).map_or(0.0, |d| {
                        bounds
                            .meridian(middle, d)
                            .map_or(0.0, |(_, hi)| 2.0 * hi.atan())
                    })
                })
                .sum::<f64>()
                .max(1e-9)
        };
        let limit = |w: f64, d: f64| 1.0 / (1.0 / (w * w) + 1.0 / (d * d)).sqrt();
        let (w1, w2) = (limit(w1, chord(e1)), limit(w2, chord(e2)));
        let column = |k: usize| e1 * (w1 * e1[k]) + e2 * (w2 * e2[k]);
        Self {
            s: [column(0), column(1)],
            ..self
        }
    }

    /// `s w`.
    fn apply(&self, w: DVec2) -> DVec2 {
        self.s[0] * w.x + self.s[1] * w.y
    }

    /// The ellipse's angle `τ` of the tangent `t` at the pole: the polar angle of `s⁻¹ t`
    /// (by its adjugate: a positive factor does not change an angle).
    fn angle_of(&self, t: DVec3) -> f64 {
        let p = DVec2::new(t.dot(self.b1), t.dot(self.b2));
        let [a, b] = self.s;
        let w = DVec2::new(b.y * p.x - b.x * p.y, -a.y * p.x + a.x * p.y);
        w.y.atan2(w.x)
    }

    fn det(&self) -> f64 {
        self.s[0].x * self.s[1].y - self.s[1].x * self.s[0].y
    }
}

/// The mirror direction of `v` about the normal `+z`: where a glossy lobe peaks.
pub fn mirror(v: DVec3) -> DVec3 {
    DVec3::new(-v.x, -v.y, v.z)
}

/// An orthonormal basis of the tangent plane at unit `c`, the first vector horizontal (any
/// pair where `c` is vertical).
fn tangent_basis(c: DVec3) -> (DVec3, DVec3) {
    match DVec3::Z.cross(c).try_normalize() {
        Some(b1) => (b1, c.cross(b1)),
        None => (DVec3::X, c.cross(DVec3::X)),
    }
}

/// The square root of the symmetric positive-definite `[[m00, m01], [m01, m11]]`,
/// `(M + √det I) / √(tr M + 2 √det)`, as columns.
fn sqrt_spd(m00: f64, m01: f64, m11: f64) -> [DVec2; 2] {
    let root_det = (m00 * m11 - m01 * m01).max(0.0).sqrt();
    let scale = 1.0 / (m00 + m11 + 2.0 * root_det).sqrt();
    [
        DVec2::new(m00 + root_det, m01) * scale,
        DVec2::new(m01, m11 + root_det) * scale,
    ]
}

/// The unit tangent at `c` toward the direction `p` along their great circle; `None` where
/// `p` is within `SAME_DIRECTION` of `c` (or of its opposite), where the tangent is rounding.
pub fn toward(c: DVec3, p: DVec3) -> Option<DVec3> {
    let t = p - c * p.dot(c);
    (t.length_squared() > SAME_DIRECTION * SAME_DIRECTION).then(|| t.normalize())
}

/// Directions closer than this (radians) are one: a corner this near the pole is the pole.
/// It lies above f32's rounding of a unit vector (6e-8) and far below any light's size.
pub const SAME_DIRECTION: f64 = 1e-6;

/// The most cuts a region takes: a clipped rect's five corners and five feet, and the four
/// quarter turns.
pub const MAX_CUTS: usize = 16;

/// A region ready to integrate: its bounds, its pole and the unit tangents at the pole
/// toward where its boundary turns (corners, the feet of the perpendiculars to its edges, its
/// boundary's own tangents where the pole is on it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Polar<R = Bounds> {
    pub bounds: R,
    pub pole: DVec3,
    pub cuts: [DVec3; MAX_CUTS],
    pub count: usize,
}

impl<R: Region> Polar<R> {
    /// The region of `bounds` about `pole`, cut at the `turns` (2 or 4) equal turns of the
    /// pole's tangent basis: no piece is wider than that, whatever the other cuts, and the
    /// pieces move with the cuts continuously (an f32 and an f64 rule differ where their
    /// pieces do). A polygon's corners cut it enough to take 2, a cap's circle 4.
    pub fn new(bounds: R, pole: DVec3, turns: usize) -> Self {
        let mut polar = Self {
            bounds,
            pole,
            cuts: [DVec3::ZERO; MAX_CUTS],
            count: 0,
        };
        let (b1, b2) = tangent_basis(pole);
        polar.cut_both(b1);
        if turns > 2 {
            polar.cut_both(b2);
        }
        polar
    }

    /// Cuts at the direction toward where the great circle of unit normal `n` passes nearest
    /// the pole (the foot of the perpendicular): there an edge close to the pole is nearest,
    /// and the exits on either side grow like `1/cos` toward its ends.
    pub fn cut_foot(&mut self, n: DVec3) {
        if let Some(t) = (self.pole * self.pole.dot(n) - n).try_normalize() {
            self.cut(t);
        }
    }

    /// Cuts at the tangent toward `p` (none where `p` is the pole itself).
    pub fn cut_toward(&mut self, p: DVec3) {
        if let Some(t) = toward(self.pole, p) {
            self.cut(t);
        }
    }

    /// Cuts at the tangent `t` (unit, or along the pole's tangent plane) and its opposite:
    /// a boundary through the pole.
    pub fn cut_both(&mut self, t: DVec3) {
        if let Some(t) = (t - self.pole * t.dot(self.pole)).try_normalize() {
            self.cut(t);
            self.cut(-t);
        }
    }

    fn cut(&mut self, t: DVec3) {
        if self.count < MAX_CUTS {
            self.cuts[self.count] = t;
            self.count += 1;
        }
    }

    /// `∫ g(ω) dω` over the region, stretched to `lobe` (about this pole), `n × n`
    /// Gauss–Legendre nodes a piece.
    pub fn integral(&self, lobe: &Lobe, n: usize, g: impl Fn(DVec3) -> f64) -> f64 {
        let rule = rule(n);
        let det = lobe.det();
        let c = self.pole;
        let mut total = 0.0;
        for (a, b) in self.pieces(lobe) {
            let tau0 = lobe.angle_of(lobe.b1 * a.cos() + lobe.b2 * a.sin());
            let tau1 = lobe.angle_of(lobe.b1 * b.cos() + lobe.b2 * b.sin());
            let span = (tau1 - tau0).rem_euclid(2.0 * PI);
            for &(xs, ws) in rule {
                let tau = tau0 + 0.5 * span * (xs + 1.0);
                let p = lobe.apply(DVec2::new(tau.cos(), tau.sin()));
                let r = p.length();
                let d = (lobe.b1 * p.x + lobe.b2 * p.y) / r;
                let Some((lo, hi)) = self.bounds.meridian(c, d) else {
                    continue;
                };
                // tan(u/2) = (r/2) tan t; dφ/dτ = det s / r².
                let (t0, t1) = ((2.0 * lo / r).atan(), (2.0 * hi / r).atan());
                let w_phi = 0.5 * span * ws * det / (r * r) * 0.5 * (t1 - t0);
                for &(xt, wt) in rule {
                    let t = t0 + 0.5 * (t1 - t0) * (xt + 1.0);
                    let tan_t = t.tan();
                    let half = 0.5 * r * tan_t;
                    let h2 = half * half;
                    let (cos_u, sin_u) = ((1.0 - h2) / (1.0 + h2), 2.0 * half / (1.0 + h2));
                    // du/dt = r (1 + tan² t) / (1 + T²).
                    let du_dt = r * (1.0 + tan_t * tan_t) / (1.0 + h2);
                    total += w_phi * wt * sin_u * du_dt * g(c * cos_u + d * sin_u);
                }
            }
        }
        total
    }

    /// The pieces of azimuth about the pole: between the cuts' angles in the lobe's basis,
    /// sorted, only those whose middle meridian meets the region.
    fn pieces(&self, lobe: &Lobe) -> Vec<(f64, f64)> {
        let mut angles: Vec<f64> = self.cuts[..self.count]
            .iter()
            .map(|t| t.dot(lobe.b2).atan2(t.dot(lobe.b1)))
            .collect();
        if angles.is_empty() {
            angles.push(0.0);
        }
        angles.sort_by(f64::total_cmp);
        let mut out = Vec::new();
        for k in 0..angles.len() {
            let start = angles[k];
            let end = angles.get(k + 1).copied().unwrap_or(angles[0] + 2.0 * PI);
            if end - start <= PIECE_MIN_WIDTH {
                continue;
            }
            let mid = 0.5 * (start + end);
            let d = lobe.b1 * mid.cos() + lobe.b2 * mid.sin();
            if self.bounds.meridian(self.pole, d).is_some() {
                out.push((start, end));
            }
        }
        out
    }
}

/// Pieces narrower than this are dropped: two cuts at one direction (a corner that is also
/// a foot), which f32 sets 1e-7 apart where f64 sets them 1e-16 apart; either piece holds
/// under 1e-6 of the region.
pub const PIECE_MIN_WIDTH: f64 = 1e-6;
