//! The horizon-clipped sphere form factor: the projected (cosine-weighted) solid angle of a
//! spherical cap cut by the horizon, the fourth channel of ltc_code's second texture. Area
//! lights use it to clip a polygon's vector form factor without clipping the polygon: they
//! look it up by the vector's elevation and length.

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
