//! The exact BRDF of docs/design.md §1: GGX specular with height-correlated Smith masking and
//! Burley's diffuse, one small function per term, generic over `f32` (rendering) and `f64`
//! (fitting, integration). Everything is written in the shading frame: `n = +z`, and the
//! dot products with `n` are the `z` components. Anisotropic GGX is `aniso`.

pub mod aniso;

pub use aniso::{Alpha, brdf_cos_aniso};

use num_traits::{Float, FloatConst};

/// The scalar types the BRDF is evaluated in.
pub trait Real: Float + FloatConst + Send + Sync + std::fmt::Debug + 'static {
    /// A constant given in f64, converted (rounded) to `Self`.
    fn lit(x: f64) -> Self {
        Self::from(x).unwrap_or_else(Self::nan)
    }
}
impl Real for f32 {}
impl Real for f64 {}

/// A 3-vector in the shading frame; generic so that the f32 and f64 paths share one text.
pub type V3<T> = [T; 3];

pub fn dot<T: Real>(a: V3<T>, b: V3<T>) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// `a / |a|`, or `None` for a zero (or non-finite) vector.
pub fn normalize<T: Real>(a: V3<T>) -> Option<V3<T>> {
    let len = dot(a, a).sqrt();
    (len > T::zero() && len.is_finite()).then(|| [a[0] / len, a[1] / len, a[2] / len])
}

/// The dot products every term needs, for unit `v` and `l` in the shading frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dots<T> {
    pub n_v: T,
    pub n_l: T,
    pub n_h: T,
    pub v_h: T,
    pub l_h: T,
}

impl<T: Real> Dots<T> {
    /// `None` when `v = −l` (the half vector is undefined; both lobes are zero there).
    pub fn new(v: V3<T>, l: V3<T>) -> Option<Self> {
        let h = normalize([v[0] + l[0], v[1] + l[1], v[2] + l[2]])?;
        Some(Self {
            n_v: v[2],
            n_l: l[2],
            n_h: h[2],
            v_h: dot(v, h),
            l_h: dot(l, h),
        })
    }
}

/// GGX normal distribution, Walter et al. 2007 eq. 33 (docs/design.md §1); zero for `n·h ≤ 0`.
/// The denominator `(n·h)²(α² − 1) + 1` is evaluated as `(n·h)²α² + (1 − n·h)(1 + n·h)`:
/// equal in exact arithmetic, but the first form cancels to 0 in f32 at `n·h = 1` for
/// α < 2.4e-4 (Filament's `D_GGX` avoids the same cancellation with `|n × h|²`).
pub fn d_ggx<T: Real>(n_h: T, alpha: T) -> T {
    if n_h <= T::zero() {
        return T::zero();
    }
    let a2 = alpha * alpha;
    let k = n_h * n_h * a2 + (T::one() - n_h) * (T::one() + n_h);
    a2 / (T::PI() * k * k)
}

/// Smith's Λ for GGX, Heitz 2014 eq. 72: `(−1 + sqrt(1 + α² tan²θ)) / 2`; infinite at and
/// below the horizon, which makes `g2_correlated` zero there.
pub fn lambda_ggx<T: Real>(cos_theta: T, alpha: T) -> T {
    if cos_theta <= T::zero() {
        return T::infinity();
    }
    let c2 = cos_theta * cos_theta;
    let tan2 = ((T::one() - c2) / c2).max(T::zero());
    (-T::one() + (T::one() + alpha * alpha * tan2).sqrt()) * T::lit(0.5)
}

/// Height-correlated Smith masking-shadowing, Heitz 2014 eq. 99 (Lagarde 2014 §4.4.2).
pub fn g2_correlated<T: Real>(n_v: T, n_l: T, alpha: T) -> T {
    if n_v <= T::zero() || n_l <= T::zero() {
        return T::zero();
    }
    T::one() / (T::one() + lambda_ggx(n_v, alpha) + lambda_ggx(n_l, alpha))
}

/// Filament's `V_SmithGGXCorrelated` (Lagarde 2014 eq. 72 rearranged): `G2 / (4 n·v n·l)`
/// in one division, with the view factor `sqrt(n·v²(1 − α²) + α²)` passed in so that it is
/// computed once per pixel. The `brdf-fast` GPU method's form; equal to `g2_correlated`'s.
pub fn v_smith_ggx_correlated<T: Real>(n_v: T, n_l: T, a2: T, view_factor: T) -> T {
    let light_factor = (n_l * n_l * (T::one() - a2) + a2).sqrt();
    T::lit(0.5) / (n_l * view_factor + n_v * light_factor)
}

/// Schlick's Fresnel, Schlick 1994 eq. 15, with the exponent on `(1 − v·h)` — the paper's
/// eq. 6 misprints it as `(1 − (v·h)⁵)` (docs/design.md §1).
pub fn f_schlick<T: Real>(f0: T, v_h: T) -> T {
    let x = (T::one() - v_h).max(T::zero()).min(T::one());
    f0 + (T::one() - f0) * x.powi(5)
}

/// Burley's diffuse for white base colour, Burley 2012 eq. 3, with `FD = 0.5 + 2α(l·h)²` —
/// the paper's α, as in Filament's `Fd_Burley` (ltc_code and Unity use `sqrt(α)`).
pub fn fd_burley<T: Real>(n_v: T, n_l: T, l_h: T, alpha: T) -> T {
    let f90 = T::lit(0.5) + T::lit(2.0) * alpha * l_h * l_h;
    let scatter = |cos: T| T::one() + (f90 - T::one()) * (T::one() - cos).max(T::zero()).powi(5);
    scatter(n_l) * scatter(n_v) / T::PI()
}

/// The cosine-weighted specular lobe `D F G / (4 n·v n·l) · n·l` (docs/design.md §1). Written with
/// the `n·l` cancelled so that grazing lights cost no division by a vanishing cosine.
pub fn specular_cos<T: Real>(d: &Dots<T>, alpha: T, f0: T) -> T {
    if d.n_v <= T::zero() || d.n_l <= T::zero() || d.v_h <= T::zero() || d.l_h <= T::zero() {
        return T::zero();
    }
    d_ggx(d.n_h, alpha) * f_schlick(f0, d.v_h) * g2_correlated(d.n_v, d.n_l, alpha)
        / (T::lit(4.0) * d.n_v)
}

/// The cosine-weighted diffuse lobe `fd · n·l` for base colour 1 (docs/design.md §1).
pub fn diffuse_cos<T: Real>(d: &Dots<T>, alpha: T) -> T {
    if d.n_v <= T::zero() || d.n_l <= T::zero() {
        return T::zero();
    }
    fd_burley(d.n_v, d.n_l, d.l_h, alpha) * d.n_l
}

/// What one unit-irradiance light reflects toward `v`, per lobe, before the material's
/// colours: the exact BRDF here, the LTC approximation in `ltc`. Radiance is
/// `E · (specular + c · diffuse)`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Lobes<T> {
    pub specular: T,
    pub diffuse: T,
}

/// Both exact cosine-weighted lobes for unit `v`, `l` in the shading frame; zero where the
/// half vector is undefined or either direction is below the horizon.
pub fn brdf_cos<T: Real>(v: V3<T>, l: V3<T>, alpha: T, f0: T) -> Lobes<T> {
    match Dots::new(v, l) {
        Some(d) => Lobes {
            specular: specular_cos(&d, alpha, f0),
            diffuse: diffuse_cos(&d, alpha),
        },
        None => Lobes {
            specular: T::zero(),
            diffuse: T::zero(),
        },
    }
}

/// Distance below which a light counts as sitting on the shading point. Such a light lies in
/// the surface's tangent plane (`n·l = 0`), so it contributes nothing; the cut keeps `1/d²`
/// finite. 1e-6 is far below any scene scale the lab uses (the plane is metres wide) and far
/// above f32's smallest normal number squared.
pub const MIN_LIGHT_DISTANCE: f64 = 1e-6;

/// Windowed inverse-square falloff `w(d) = clamp(1 − (d/R)⁴, 0, 1)²` (Karis 2013, "Real
/// Shading in UE4", eq. 9; docs/design.md §1). An infinite range gives `w = 1`.
pub fn window_falloff<T: Real>(d: T, range: T) -> T {
    window_falloff_d2(d * d, range)
}

/// `window_falloff` from `d²`, which needs no square root (the GPU's fast methods use it;
/// WGSL encodes an infinite range as `range ≤ 0`, Rust as a non-finite one).
pub fn window_falloff_d2<T: Real>(d2: T, range: T) -> T {
    if !range.is_finite() {
        return T::one();
    }
    let x2 = d2 / (range * range);
    let w = (T::one() - x2 * x2).max(T::zero()).min(T::one());
    w * w
}

/// The irradiance scale of a point light of intensity `I` at distance `d`: `E = I/d² · w(d)`
/// (docs/design.md §1); zero for a light at the shading point (see `MIN_LIGHT_DISTANCE`).
pub fn irradiance_scale<T: Real>(intensity: T, d: T, range: T) -> T {
    if d < T::lit(MIN_LIGHT_DISTANCE) {
        return T::zero();
    }
    intensity / (d * d) * window_falloff(d, range)
}

/// Eq. 28 for one light: the exact radiance toward unit `v` from a light at offset `u = p − x`
/// (both in the shading frame), per lobe, as `E · f · max(n·l, 0)`.
pub fn point_light_exact<T: Real>(
    v: V3<T>,
    u: V3<T>,
    intensity: T,
    range: T,
    alpha: T,
    f0: T,
) -> Lobes<T> {
    point_light_exact_aniso(v, u, intensity, range, Alpha::isotropic(alpha), f0)
}

/// `point_light_exact` for an anisotropic roughness (the shading frame's x the tangent):
/// the same arithmetic, `brdf_cos_aniso` for the lobes.
pub fn point_light_exact_aniso<T: Real>(
    v: V3<T>,
    u: V3<T>,
    intensity: T,
    range: T,
    alpha: Alpha<T>,
    f0: T,
) -> Lobes<T> {
    let d = dot(u, u).sqrt();
    let e = irradiance_scale(intensity, d, range);
    if e <= T::zero() {
        return Lobes {
            specular: T::zero(),
            diffuse: T::zero(),
        };
    }
    let l = [u[0] / d, u[1] / d, u[2] / d];
    let lobes = brdf_cos_aniso(v, l, alpha, f0);
    Lobes {
        specular: e * lobes.specular,
        diffuse: e * lobes.diffuse,
    }
}

/// The unit view vector `v = (sin θo, 0, cos θo)` of docs/design.md §1.
pub fn view_from_theta<T: Real>(theta_o: T) -> V3<T> {
    [theta_o.sin(), T::zero(), theta_o.cos()]
}
