//! The horizon-clipped sphere form factor: the projected (cosine-weighted) solid angle of a
//! spherical cap cut by the horizon, the fourth channel of ltc_code's second texture. Area
//! lights use it to clip a polygon's vector form factor without clipping the polygon: they
//! look it up by the vector's elevation and length. A sphere light's irradiance is the same
//! integral over the cap it covers (`light::sphere::cap`, docs/design.md §1.10).

use std::f64::consts::{FRAC_PI_2, PI};

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
