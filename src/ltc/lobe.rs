//! The exact lobes an LTC is fitted to (DESIGN §2), with the importance sampling that
//! ltc_code's `brdf_ggx.h` and `brdf_disneyDiffuse.h` use: GGX normals for the specular lobe
//! (F = 1), the cosine for the diffuse lobe (c = 1). All in f64.

use glam::DVec3;

use crate::brdf::{Dots, d_ggx, diffuse_cos, specular_cos};
use crate::ltc::cosine_sample;

/// Which lobe of the BRDF.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Lobe {
    Specular,
    Diffuse,
}

/// A lobe value `f cos` at a direction and the density of the lobe's own sampling there.
#[derive(Clone, Copy, Debug)]
pub struct LobeSample {
    pub value: f64,
    pub pdf: f64,
}

impl Lobe {
    pub const BOTH: [Self; 2] = [Self::Specular, Self::Diffuse];

    pub fn name(self) -> &'static str {
        match self {
            Self::Specular => "spec",
            Self::Diffuse => "diff",
        }
    }

    /// `f cos` (F = 1 / c = 1) toward unit `l` for unit `v`, and the sampling density at `l`.
    pub fn eval(self, v: DVec3, l: DVec3, alpha: f64) -> LobeSample {
        let Some(d) = Dots::new(v.to_array(), l.to_array()) else {
            return LobeSample {
                value: 0.0,
                pdf: 0.0,
            };
        };
        match self {
            Self::Specular => LobeSample {
                value: specular_cos(&d, alpha, 1.0),
                // Density of reflecting v about a GGX-distributed normal: D n·h / (4 |v·h|).
                pdf: if d.v_h.abs() > 0.0 {
                    (d_ggx(d.n_h, alpha) * d.n_h / (4.0 * d.v_h.abs())).max(0.0)
                } else {
                    0.0
                },
            },
            Self::Diffuse => LobeSample {
                value: diffuse_cos(&d, alpha),
                pdf: l.z.max(0.0) / std::f64::consts::PI,
            },
        }
    }

    /// A direction following the lobe's sampling density for stratum `(u1, u2) ∈ [0,1)²`.
    pub fn sample(self, v: DVec3, alpha: f64, u1: f64, u2: f64) -> DVec3 {
        self.sample_stratum(v, alpha, &Stratum::new(u1, u2))
    }

    /// `sample` with the stratum's trigonometry done once (the fitter's inner loop).
    pub fn sample_stratum(self, v: DVec3, alpha: f64, s: &Stratum) -> DVec3 {
        match self {
            Self::Specular => {
                // GGX normal: tan θh = α sqrt(u/(1−u)) (Walter 2007 eq. 35), then reflect v.
                let r = alpha * s.ggx_tan_over_alpha;
                let h = DVec3::new(r * s.ggx_cos_phi, r * s.ggx_sin_phi, 1.0).normalize();
                2.0 * h.dot(v) * h - v
            }
            Self::Diffuse => s.cosine,
        }
    }
}

/// One midpoint stratum `(u1, u2)` with what both sampling routines derive from it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stratum {
    /// The clamped-cosine direction (`cosine_sample(u1, u2)`).
    pub cosine: DVec3,
    /// GGX sampling: `φ = 2π u1`, `tan θh / α = sqrt(u2 / (1 − u2))`.
    pub ggx_cos_phi: f64,
    pub ggx_sin_phi: f64,
    pub ggx_tan_over_alpha: f64,
}

impl Stratum {
    pub fn new(u1: f64, u2: f64) -> Self {
        let phi = std::f64::consts::TAU * u1;
        Self {
            cosine: cosine_sample(u1, u2),
            ggx_cos_phi: phi.cos(),
            ggx_sin_phi: phi.sin(),
            ggx_tan_over_alpha: (u2 / (1.0 - u2)).sqrt(),
        }
    }
}

/// Midpoint strata `((i + ½)/n, (j + ½)/n)` of the unit square, row by row — ltc_code's
/// deterministic sample pattern.
pub fn strata(n: usize) -> Vec<Stratum> {
    let inv = 1.0 / n as f64;
    (0..n)
        .flat_map(|j| {
            (0..n).map(move |i| Stratum::new((i as f64 + 0.5) * inv, (j as f64 + 0.5) * inv))
        })
        .collect()
}

/// What the fitter needs of the exact lobe at one (θo, α), estimated from its own sampling.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LobeMoments {
    /// `∫ f cos dω`.
    pub norm: f64,
    /// `∫ (1 − v·h)⁵ f cos dω` (the Schlick split); zero for the diffuse lobe.
    pub fresnel: f64,
    /// The normalized mean direction of `f cos`, with its y component cleared (isotropy).
    pub average_dir: DVec3,
}

/// `norm`, `fresnel` and the average direction by the lobe's stratified importance sampling
/// over `strata` (ltc_code's `computeAvgTerms`, in f64).
pub fn lobe_moments(lobe: Lobe, v: DVec3, alpha: f64, strata: &[Stratum]) -> LobeMoments {
    let mut norm = 0.0;
    let mut fresnel = 0.0;
    let mut dir = DVec3::ZERO;
    for s in strata {
        let l = lobe.sample_stratum(v, alpha, s);
        let s = lobe.eval(v, l, alpha);
        if s.pdf > 0.0 {
            let w = s.value / s.pdf;
            norm += w;
            if lobe == Lobe::Specular {
                let h = (v + l).normalize_or_zero();
                fresnel += w * (1.0 - v.dot(h).max(0.0)).powi(5);
            }
            dir += w * l;
        }
    }
    let count = strata.len() as f64;
    dir.y = 0.0;
    LobeMoments {
        norm: norm / count,
        fresnel: fresnel / count,
        average_dir: dir.try_normalize().unwrap_or(DVec3::Z),
    }
}
