//! The horizon-clipped sphere form factor: the projected (cosine-weighted) solid angle of a
//! spherical cap cut by the horizon, the fourth channel of ltc_code's second texture. Area
//! lights use it to clip a polygon's vector form factor without clipping the polygon: they
//! look it up by the vector's elevation and length. Here too the cap a sphere light covers
//! (`Cap`), whose clipped form factor is the sphere's irradiance (docs/design.md §1.10).

use std::f64::consts::{FRAC_PI_2, PI};

use crate::named::named_enum;
use glam::DVec3;

/// The projected solid angle `∫_cap max(cos θ, 0) dω` of a spherical cap of angular radius
/// `sigma` whose centre is `omega` from the zenith, in closed form (Snyder 1996, "Area Light
/// Sources for Real-Time Graphics", Microsoft Research: the cap's form factor clipped to the
/// horizon, three cases by where the horizon cuts the cap).
pub fn clipped_cap_projected_solid_angle(omega: f64, sigma: f64) -> f64 {
    let sin2_s = sigma.sin().powi(2);
    if omega <= FRAC_PI_2 - sigma {
        // Wholly above the horizon: the unclipped form factor π sin²σ cos ω.
        return PI * omega.cos() * sin2_s;
    }
    if omega >= FRAC_PI_2 + sigma {
        return 0.0;
    }
    let g = (sigma.cos() / omega.sin()).clamp(-1.0, 1.0).asin();
    let big_g = -2.0 * omega.sin() * sigma.cos() * g.cos() + FRAC_PI_2 - g + g.sin() * g.cos();
    let cos2_g = g.cos().powi(2);
    let big_h = omega.cos()
        * (g.cos() * (sin2_s - cos2_g).max(0.0).sqrt()
            + sin2_s * (g.cos() / sigma.sin()).clamp(-1.0, 1.0).asin());
    if omega < FRAC_PI_2 {
        PI * omega.cos() * sin2_s + big_g - big_h
    } else {
        big_g + big_h
    }
}

/// The table's value at texel `(i, j)` of an `n × n` table, on ltc_code's axes: `u = i/(n−1)`
/// gives `cos ω = 2u − 1`, `v = j/(n−1)` gives the vector form factor's length `sin²σ`; the
/// value is the clipped form factor over the unclipped one's magnitude, `π sin²σ`, and
/// `max(cos ω, 0)` for a vanishing cap.
pub fn sphere_table_value(i: usize, j: usize, n: usize) -> f64 {
    let z = 2.0 * i as f64 / (n - 1) as f64 - 1.0;
    let len = j as f64 / (n - 1) as f64;
    if len <= 0.0 {
        return z.max(0.0);
    }
    let sigma = len.sqrt().asin();
    let omega = z.clamp(-1.0, 1.0).acos();
    clipped_cap_projected_solid_angle(omega, sigma) / (PI * len)
}

/// The directions a sphere light covers, seen from the shading point: a cap about `axis`
/// of half-angle σ, or every direction where the point is inside the sphere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cap {
    /// Unit direction to the sphere's centre (`+z` for a point at the centre).
    pub axis: DVec3,
    /// `sin σ = r/d`, 1 where the sphere touches or encloses the point.
    pub sin_sigma: f64,
    /// `cos σ = √(d² − r²)/d`; −1 where the point is inside (the cap is the whole sphere).
    pub cos_sigma: f64,
}

impl Cap {
    /// The cap of a sphere of radius `r > 0` at offset `u` (centre − shading point), or
    /// `None` for a point light (`r = 0`) or a sphere centred on the point with no radius.
    pub fn of_sphere(u: DVec3, r: f64) -> Option<Self> {
        if r <= 0.0 {
            return None;
        }
        let d = u.length();
        let axis = u.try_normalize().unwrap_or(DVec3::Z);
        if d <= r {
            return Some(Self {
                axis,
                sin_sigma: 1.0,
                cos_sigma: -1.0,
            });
        }
        let sin_sigma = r / d;
        // √((d − r)(d + r)) keeps the cosine accurate for a light far smaller than its distance.
        let cos_sigma = ((d - r) * (d + r)).sqrt() / d;
        Some(Self {
            axis,
            sin_sigma,
            cos_sigma,
        })
    }

    /// `1 − cos σ` without cancellation (`sin²σ / (1 + cos σ)`): a small cap's depth along
    /// its axis, 2 for the whole sphere.
    pub fn depth(&self) -> f64 {
        if self.encloses() {
            return 2.0;
        }
        self.sin_sigma * self.sin_sigma / (1.0 + self.cos_sigma)
    }

    /// True where the shading point is inside (or on) the sphere.
    pub fn encloses(&self) -> bool {
        self.cos_sigma <= -1.0
    }

    /// True where no direction of the cap is above the surface.
    pub fn below_horizon(&self) -> bool {
        !self.encloses() && self.axis.z <= -self.sin_sigma
    }

    /// Where the cap is against the surface (`SphereCase`).
    pub fn case(&self) -> SphereCase {
        if self.encloses() {
            SphereCase::Inside
        } else if self.below_horizon() {
            SphereCase::Below
        } else if self.axis.z < self.sin_sigma {
            SphereCase::Cut
        } else {
            SphereCase::Above
        }
    }

    /// `∫ max(ω.z, 0) dω` over the cap: the irradiance of unit radiance.
    pub fn illuminance(&self) -> f64 {
        if self.encloses() {
            return std::f64::consts::PI;
        }
        illuminance_sphere(self.axis.z, self.sin_sigma * self.sin_sigma)
    }
}

/// `∫ max(ω.z, 0) dω` over a cap of `sin²σ = sin2_sigma` whose axis has `cos θ = cos_theta`
/// with the normal, cut by the horizon: Snyder's integral in the form Lagarde & de Rousiers
/// (2014, §4.7.2, "illuminanceSphereOrDisk") write it. The same value as
/// `clipped_cap_projected_solid_angle`, but where a small cap straddles the horizon its terms
/// cancel from O(σ) (that form's from O(1)), which keeps f32 within about ε/σ of the value:
/// the shaders use this one.
pub fn illuminance_sphere(cos_theta: f64, sin2_sigma: f64) -> f64 {
    if cos_theta * cos_theta >= sin2_sigma {
        return PI * sin2_sigma * cos_theta.max(0.0);
    }
    let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
    // cot σ; the branch above takes every sinθ = 0, so the division below is safe.
    let x = (1.0 / sin2_sigma - 1.0).max(0.0).sqrt();
    let y = (-x * cos_theta / sin_theta).clamp(-1.0, 1.0);
    let z = sin_theta * (1.0 - y * y).sqrt();
    ((cos_theta * y.acos() - x * z) * sin2_sigma + z.atan2(x)).max(0.0)
}

named_enum! {
    /// Where a sphere light is against the surface, seen from a shading point: the failure cases
    /// of docs/design.md §1.10 (the plane panel's map of sphere cases), from the least to the most
    /// telling — the order a map takes the largest of a pixel's cases in.
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
    pub enum SphereCase {
        /// The whole cap above the horizon: every method shades it as it was made to.
        Above = "above",
        /// Below the horizon: it lights nothing.
        Below = "below",
        /// Cut by the horizon: part of the sphere below the surface (the disk clips it as a disc
        /// facing the point; the representative point does not see the cut).
        Cut = "cut by the horizon",
        /// The point is inside the sphere (or on it): the cap is the whole upper hemisphere.
        Inside = "inside the sphere",
    }
}

impl SphereCase {}
