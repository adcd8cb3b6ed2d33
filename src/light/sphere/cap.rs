//! The directions a sphere light covers from a shading point (`Cap`), and where they are
//! against the surface (`SphereCase`): the geometry every sphere method starts from
//! (docs/design.md §1.10).

use glam::DVec3;

use crate::ltc::sphere::illuminance_sphere;
use crate::named::named_enum;

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
