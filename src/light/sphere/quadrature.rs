//! Integrals over a spherical cap in f64: the ground truth of lights with a size
//! (docs/design.md §1.10). Gauss–Legendre in `μ = cos θ` about the cap's axis and in the
//! azimuth, with the horizon's cut placed exactly: for each ring of the cap the azimuths
//! above the surface are found in closed form, so the integrand the rule sees is smooth.

use glam::DVec3;

/// The `n` Gauss–Legendre nodes and weights on `[-1, 1]` (Abramowitz & Stegun 25.4.29),
/// each node by Newton's method on the three-term recurrence from Tricomi's first guess.
pub fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            // Newton converges quadratically from this guess: 100 steps is a bound, not a cost.
            for _ in 0..100 {
                let (p, d) = legendre(n, x);
                dp = d;
                let step = p / d;
                x -= step;
                if step.abs() < 1e-16 {
                    break;
                }
            }
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .collect()
}

/// `P_n(x)` and `P_n'(x)` by Bonnet's recursion.
fn legendre(n: usize, x: f64) -> (f64, f64) {
    if n == 0 {
        return (1.0, 0.0);
    }
    let (mut p0, mut p1) = (1.0, x);
    for k in 2..=n {
        let k = k as f64;
        let p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
    }
    let n = n as f64;
    (p1, n * (x * p1 - p0) / (x * x - 1.0))
}

/// `∫ g(ω) dω` over the directions within the cap of unit `axis` and depth `1 − cos σ =
/// depth` (`2`: the whole sphere; passed as the depth, not `cos σ`, because `1 − cos σ`
/// computed from a rounded `cos σ` loses every digit for a small cap) that lie above the surface (`ω.z > 0`), for `K` integrands at
/// once, with `n` nodes per dimension and per piece. The rings' `μ` range is split where
/// the horizon starts to cut them, so each piece's integrand is smooth and the rule's error
/// falls as fast as the integrand allows (tests/lights/sphere_light.rs measures it, n against 2n).
pub fn cap_integral<const K: usize>(
    axis: DVec3,
    depth: f64,
    n: usize,
    g: impl Fn(DVec3) -> [f64; K],
) -> [f64; K] {
    cap_integral_about(axis, depth, n, None, g)
}

/// `cap_integral` for an integrand peaked about the unit direction `focus` (a glossy lobe's
/// mirror direction): the pieces are also split at the focus's `μ` and, on each ring, at its
/// azimuth, so that the peak sits where four pieces meet and their nodes crowd to it.
pub fn cap_integral_about<const K: usize>(
    axis: DVec3,
    depth: f64,
    n: usize,
    focus: Option<DVec3>,
    g: impl Fn(DVec3) -> [f64; K],
) -> [f64; K] {
    let rule = gauss_legendre(n);
    let rule = rule.as_slice();
    // A frame whose `t` lies in the plane of the axis and the normal, so that a ring's height
    // is `μ a_z + sin θ cos φ t_z` with `t_z ≥ 0`: its part above the horizon is one interval
    // of φ about 0.
    let (t, b) = ring_frame(axis);
    let focus_phi = focus.map(|f| f.dot(b).atan2(f.dot(t)));
    // Rings are placed by `ν = 1 − μ`, not `μ`: near the pole `μ` would keep a small cap's
    // rings to f32's resolution of 1 (6e-8 against a cap of 1 − cos σ = 3e-5 at σ = 0.44°);
    // the shaders share this rule.
    let ring = |nu: f64| -> [f64; K] {
        let mu = 1.0 - nu;
        let s = (nu * (2.0 - nu)).max(0.0).sqrt();
        let mut sum = [0.0; K];
        let Some(half) = visible_half_azimuth(mu * axis.z, s * t.z) else {
            return sum;
        };
        let mut add = |phi: f64, w: f64| {
            let l = axis * mu + (t * phi.cos() + b * phi.sin()) * s;
            for (acc, v) in sum.iter_mut().zip(g(l)) {
                *acc += w * v;
            }
        };
        // The integrand is smooth across a ring's visible arc (the cut lies where the ring
        // leaves the surface), so the plain rule serves unless the arc holds the peak.
        match focus_phi.filter(|p| p.abs() < half) {
            Some(peak) => {
                for (phi, w) in crowded(rule, -half, peak).chain(crowded(rule, peak, half)) {
                    add(phi, w);
                }
            }
            None => {
                for &(x, w) in rule {
                    add(half * x, half * w);
                }
            }
        }
        sum
    };
    // A ring turns from wholly visible (or wholly hidden) to cut where |μ a_z| = s t_z, that
    // is at μ = ±t_z, ν = 1 ∓ t_z (a_z² + t_z² = 1): the φ-integral has a square-root kink
    // there.
    let widest = depth.clamp(0.0, 2.0);
    let mut cuts = vec![0.0, widest];
    let focus_nu = focus.map(|f| 1.0 - f.dot(axis));
    cuts.extend(
        [Some(1.0 + t.z), Some(1.0 - t.z), focus_nu]
            .into_iter()
            .flatten()
            .filter(|&k| k > 0.0 && k < widest),
    );
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let mut total = [0.0; K];
    for piece in cuts.windows(2) {
        for (nu, w) in crowded(rule, piece[0], piece[1]) {
            for (acc, v) in total.iter_mut().zip(ring(nu)) {
                *acc += w * v;
            }
        }
    }
    total
}

/// The rule's nodes and weights on `[lo, hi]`, crowded to both ends by the cubic
/// `x ↦ x (3 − x²)/2`. A piece ends at a kink, at the cap's pole or rim or at a peak, where
/// the integrand goes as a square root (a cut ring's width in φ, `sin θ` at the pole) or
/// changes fast: the cubic puts nodes quadratically close to the ends, which turns those
/// square roots into smooth functions and keeps the rule's convergence fast.
fn crowded(rule: &[(f64, f64)], lo: f64, hi: f64) -> impl Iterator<Item = (f64, f64)> + '_ {
    let (mid, half) = (0.5 * (lo + hi), 0.5 * (hi - lo));
    rule.iter().map(move |&(x, w)| {
        (
            mid + half * 0.5 * x * (3.0 - x * x),
            w * half * 1.5 * (1.0 - x * x),
        )
    })
}

/// Two unit vectors completing `axis` to a right-handed frame, `t` in the plane of `axis`
/// and `+z` with `t.z ≥ 0` (`+x`, where `axis` is `±z`).
fn ring_frame(axis: DVec3) -> (DVec3, DVec3) {
    let t = (DVec3::Z - axis * axis.z)
        .try_normalize()
        .unwrap_or(DVec3::X);
    (t, axis.cross(t))
}

/// The half-width `φmax ∈ (0, π]` of the azimuths where `c + k cos φ > 0` (`k ≥ 0`: a
/// ring's height above the surface), `None` where there are none.
pub fn visible_half_azimuth(c: f64, k: f64) -> Option<f64> {
    if c >= k {
        return Some(std::f64::consts::PI);
    }
    if c <= -k {
        return None;
    }
    Some((-c / k).clamp(-1.0, 1.0).acos())
}
