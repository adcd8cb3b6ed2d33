//! Integrals over a disk light's directions in f64 (docs/design.md §1.12): the ground truth of
//! disk lights. The part of the disk above the surface is a circular segment; it is integrated
//! over its area in polar coordinates about an apex inside it, `dω = cos θ_x dA / |x|²`, in
//! four pieces of azimuth whose ends are the segment's corners (where the distance to its rim
//! has a kink). For a glossy lobe the apex is where the lobe peaks, so the nodes crowd there.

use std::f64::consts::PI;

use glam::{DVec2, DVec3};

use crate::light::disk::Disk;
use crate::light::sphere::quadrature::gauss_legendre;

/// The part of a disk above the surface, in its plane's coordinates in radii along `f1`
/// (where the height above the surface grows) and `f2 = n × f1`: `x² + y² ≤ 1`, `x ≥ x0`
/// (`x0 = −1`: all of it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    pub f1: DVec3,
    pub f2: DVec3,
    pub x0: f64,
}

/// Which side of a segment a piece of azimuth reaches: the circle or the chord.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rim {
    Arc,
    Chord,
}

/// The four pieces of azimuth about an apex: each its first angle, its width and the rim it
/// reaches.
pub type Pieces = [(f64, f64, Rim); 4];

impl Segment {
    /// The part of `disk` above the surface `z = 0`, `None` where none is. The height of
    /// `c + r (x f1 + y f2)` is `c_z + r k x` with `k = √(1 − n_z²)`, `f1` the surface's normal
    /// projected into the disk's plane (any direction in it where the disk lies flat).
    pub fn above(disk: &Disk) -> Option<Self> {
        let n = disk.normal;
        let up = DVec3::Z - n * n.z;
        let k = up.length();
        let f1 = if k > 0.0 {
            up / k
        } else {
            n.any_orthonormal_pair().0
        };
        let x0 = if k > 0.0 {
            (-disk.centre.z / (disk.radius * k)).max(-1.0)
        } else if disk.centre.z > 0.0 {
            -1.0
        } else {
            1.0
        };
        (x0 < 1.0).then(|| Self {
            f1,
            f2: n.cross(f1),
            x0,
        })
    }

    /// The segment's point at plane coordinates `q`.
    pub fn point(&self, disk: &Disk, q: DVec2) -> DVec3 {
        disk.centre + (self.f1 * q.x + self.f2 * q.y) * disk.radius
    }

    /// Where the ray from the origin along `direction` meets the disk's plane, in plane
    /// coordinates, if that point lies inside the segment.
    pub fn hit_inside(&self, disk: &Disk, direction: DVec3) -> Option<DVec2> {
        let along = direction.dot(disk.normal);
        if along == 0.0 {
            return None;
        }
        let t = disk.centre.dot(disk.normal) / along;
        if t <= 0.0 {
            return None;
        }
        let offset = direction * t - disk.centre;
        let q = DVec2::new(offset.dot(self.f1), offset.dot(self.f2)) / disk.radius;
        (q.length_squared() < 1.0 && q.x > self.x0).then_some(q)
    }

    /// A point inside: the middle of the segment's axis (the disk's centre for a whole disk).
    pub fn middle(&self) -> DVec2 {
        DVec2::new(0.5 * (self.x0 + 1.0), 0.0)
    }

    /// The pieces of azimuth about `apex`: a whole disk's four quarters, or a segment's arc in
    /// three and its chord, split at the corners `(x0, ±√(1 − x0²))`.
    pub fn pieces(&self, apex: DVec2) -> Pieces {
        if self.x0 <= -1.0 {
            return [0.0, 1.0, 2.0, 3.0].map(|k| (k * 0.5 * PI, 0.5 * PI, Rim::Arc));
        }
        let y1 = (1.0 - self.x0 * self.x0).max(0.0).sqrt();
        let upper = (y1 - apex.y).atan2(self.x0 - apex.x);
        let lower = (-y1 - apex.y).atan2(self.x0 - apex.x);
        // Counter-clockwise about the apex the rim runs from the lower corner along the arc
        // to the upper one, then back along the chord.
        let arc = (upper - lower).rem_euclid(2.0 * PI);
        let third = arc / 3.0;
        [
            (lower, third, Rim::Arc),
            (lower + third, third, Rim::Arc),
            (lower + 2.0 * third, third, Rim::Arc),
            (upper, 2.0 * PI - arc, Rim::Chord),
        ]
    }

    /// The distance from `apex` along unit `d` to the rim `rim`.
    pub fn reach(&self, apex: DVec2, d: DVec2, rim: Rim) -> f64 {
        match rim {
            Rim::Arc => {
                let b = apex.dot(d);
                -b + (b * b + 1.0 - apex.length_squared()).max(0.0).sqrt()
            }
            Rim::Chord => ((self.x0 - apex.x) / d.x).max(0.0),
        }
    }
}

/// `∫ g(ω) dω` over the directions of the part of `disk` above the surface, `n × n`
/// Gauss–Legendre nodes in each of `Segment::pieces` (azimuth × distance from the apex), the
/// apex where `focus` meets the segment, else its middle.
pub fn disk_integral_about<const K: usize>(
    disk: &Disk,
    n: usize,
    focus: Option<DVec3>,
    g: impl Fn(DVec3) -> [f64; K],
) -> [f64; K] {
    let mut total = [0.0; K];
    let Some(segment) = Segment::above(disk) else {
        return total;
    };
    let rule = gauss_legendre(n);
    let apex = focus
        .and_then(|f| segment.hit_inside(disk, f))
        .unwrap_or_else(|| segment.middle());
    let r2 = disk.radius * disk.radius;
    for (start, width, rim) in segment.pieces(apex) {
        for &(xs, ws) in &rule {
            let phi = start + 0.5 * width * (xs + 1.0);
            let d = DVec2::new(phi.cos(), phi.sin());
            let reach = segment.reach(apex, d, rim);
            for &(xt, wt) in &rule {
                let rho = 0.5 * reach * (xt + 1.0);
                let x = segment.point(disk, apex + d * rho);
                let len2 = x.length_squared();
                if len2 == 0.0 {
                    continue;
                }
                let len = len2.sqrt();
                // dA = r² ρ dρ dφ; dω = |cos θ_x| dA / |x|².
                let cos_x = (x.dot(disk.normal) / len).abs();
                let weight = 0.25 * ws * wt * width * reach * rho * r2 * cos_x / len2;
                for (acc, value) in total.iter_mut().zip(g(x / len)) {
                    *acc += weight * value;
                }
            }
        }
    }
    total
}
