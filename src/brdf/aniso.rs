//! Anisotropic GGX (docs/design.md §1.13): α along the shading frame's x axis (the surface's
//! tangent) and α along its y axis (the bitangent), with the anisotropic Smith Λ and the
//! height-correlated G2 of Heitz 2014, and Schlick's Fresnel. Everything is in the tangent
//! frame: `n = +z`, `x` the tangent. With `α_x = α_y` every term equals its isotropic twin
//! in `brdf` to rounding, and `brdf_cos_aniso` *is* `brdf_cos` (the same arithmetic), so
//! that an isotropic material shades as it always did.

use super::{Dots, Lobes, Real, V3, brdf_cos, diffuse_cos, dot, f_schlick, normalize};

/// GGX roughness along the shading frame's x axis (the tangent) and y axis (the bitangent).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Alpha<T> {
    pub x: T,
    pub y: T,
}

impl<T: Real> Alpha<T> {
    /// The same roughness along both axes.
    pub fn isotropic(alpha: T) -> Self {
        Self { x: alpha, y: alpha }
    }

    pub fn is_isotropic(&self) -> bool {
        self.x == self.y
    }

    /// The α of Burley's diffuse for an anisotropic material: the mean of the two, as
    /// Filament's anisotropic materials keep their isotropic roughness for the diffuse lobe
    /// (its `at`, `ab` straddle the roughness symmetrically). Exactly `x` when isotropic.
    pub fn diffuse(&self) -> T {
        (self.x + self.y) * T::lit(0.5)
    }
}

/// Anisotropic GGX normal distribution, Heitz 2014 eq. 85 (Burley 2012, appendix B.2):
/// `D(h) = 1 / (π α_x α_y ((h.x/α_x)² + (h.y/α_y)² + h.z²)²)`, zero for `h.z ≤ 0`, for a
/// unit `h` in the tangent frame. Written as a sum of squares, it has no cancellation at
/// `h = n` for any α (the isotropic form needs `d_ggx`'s rearrangement for that).
pub fn d_ggx_aniso<T: Real>(h: V3<T>, alpha: Alpha<T>) -> T {
    if h[2] <= T::zero() {
        return T::zero();
    }
    let (x, y) = (h[0] / alpha.x, h[1] / alpha.y);
    let k = x * x + y * y + h[2] * h[2];
    T::one() / (T::PI() * alpha.x * alpha.y * k * k)
}

/// Smith's Λ for anisotropic GGX, Heitz 2014 eq. 86: `(−1 + sqrt(1 + α_o² tan²θ)) / 2` with
/// `α_o² tan²θ = (ω.x² α_x² + ω.y² α_y²) / ω.z²` (the roughness seen along the direction's
/// azimuth); infinite at and below the horizon, which makes `g2_correlated_aniso` zero there.
pub fn lambda_ggx_aniso<T: Real>(w: V3<T>, alpha: Alpha<T>) -> T {
    if w[2] <= T::zero() {
        return T::infinity();
    }
    let (x, y) = (w[0] * alpha.x, w[1] * alpha.y);
    let a2_tan2 = (x * x + y * y) / (w[2] * w[2]);
    (-T::one() + (T::one() + a2_tan2).sqrt()) * T::lit(0.5)
}

/// Height-correlated Smith masking-shadowing with the anisotropic Λ, Heitz 2014 eq. 99; zero
/// when either direction is at or below the horizon.
pub fn g2_correlated_aniso<T: Real>(v: V3<T>, l: V3<T>, alpha: Alpha<T>) -> T {
    if v[2] <= T::zero() || l[2] <= T::zero() {
        return T::zero();
    }
    T::one() / (T::one() + lambda_ggx_aniso(v, alpha) + lambda_ggx_aniso(l, alpha))
}

/// The cosine-weighted anisotropic specular lobe `D F G / (4 n·v n·l) · n·l` with the `n·l`
/// cancelled, as `specular_cos` (docs/design.md §1.13); `h` the unit half vector.
pub fn specular_cos_aniso<T: Real>(v: V3<T>, l: V3<T>, h: V3<T>, alpha: Alpha<T>, f0: T) -> T {
    let (v_h, l_h) = (dot(v, h), dot(l, h));
    if v[2] <= T::zero() || l[2] <= T::zero() || v_h <= T::zero() || l_h <= T::zero() {
        return T::zero();
    }
    d_ggx_aniso(h, alpha) * f_schlick(f0, v_h) * g2_correlated_aniso(v, l, alpha)
        / (T::lit(4.0) * v[2])
}

/// Both exact cosine-weighted lobes for unit `v`, `l` in the tangent frame. An isotropic
/// `alpha` takes `brdf_cos` itself, bit for bit; otherwise the specular lobe is
/// `specular_cos_aniso` and the diffuse lobe Burley's at `Alpha::diffuse`.
pub fn brdf_cos_aniso<T: Real>(v: V3<T>, l: V3<T>, alpha: Alpha<T>, f0: T) -> Lobes<T> {
    if alpha.is_isotropic() {
        return brdf_cos(v, l, alpha.x, f0);
    }
    let zero = Lobes {
        specular: T::zero(),
        diffuse: T::zero(),
    };
    let Some(h) = normalize([v[0] + l[0], v[1] + l[1], v[2] + l[2]]) else {
        return zero;
    };
    let dots = Dots {
        n_v: v[2],
        n_l: l[2],
        n_h: h[2],
        v_h: dot(v, h),
        l_h: dot(l, h),
    };
    Lobes {
        specular: specular_cos_aniso(v, l, h, alpha, f0),
        diffuse: diffuse_cos(&dots, alpha.diffuse()),
    }
}
