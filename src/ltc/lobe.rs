//! The exact lobes an LTC is fitted to (docs/design.md §2), with the importance sampling that
//! ltc_code's `brdf_ggx.h` and `brdf_disneyDiffuse.h` use: GGX normals for the specular lobe
//! (F = 1), the cosine for the diffuse lobe (c = 1). All in f64.

use glam::DVec3;

use crate::brdf::{Alpha, Dots, d_ggx, diffuse_cos, g2_correlated, lambda_ggx, specular_cos};
use crate::ltc::cosine_sample;
use crate::named::named_enum;

named_enum! {
    /// Which lobe of the BRDF.
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
    pub enum Lobe {
        Specular = "spec",
        Diffuse = "diff",
    }
}

/// A lobe value `f cos` at a direction and the density of the lobe's own sampling there.
#[derive(Clone, Copy, Debug)]
pub struct LobeSample {
    pub value: f64,
    pub pdf: f64,
}

impl Lobe {
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

    /// `f cos` (F = 1 / c = 1) toward unit `l` for unit `v`, both in the tangent frame, for
    /// an anisotropic roughness; an isotropic one is `eval`'s value.
    pub fn value_aniso(self, v: DVec3, l: DVec3, alpha: Alpha<f64>) -> f64 {
        if alpha.is_isotropic() {
            return self.eval(v, l, alpha.x).value;
        }
        let lobes = crate::brdf::brdf_cos_aniso(v.to_array(), l.to_array(), alpha, 1.0);
        match self {
            Self::Specular => lobes.specular,
            Self::Diffuse => lobes.diffuse,
        }
    }

    /// The true density of `sample`'s directions at `l`. For the specular lobe it differs
    /// from `eval`'s pdf (ltc_code's formula, kept by the fit): reflecting `v` about a sampled
    /// normal with `v·h < 0` lands on a direction whose `normalize(v + l)` is `−h`, which that
    /// formula gives density zero. Only grazing views sample such normals.
    pub fn sampling_density(self, v: DVec3, l: DVec3, alpha: f64) -> f64 {
        match self {
            Self::Specular => {
                let Some(h) = (v + l).try_normalize() else {
                    return 0.0;
                };
                let h = if h.z < 0.0 { -h } else { h };
                let v_h = v.dot(h).abs();
                if v_h > 0.0 {
                    d_ggx(h.z, alpha) * h.z / (4.0 * v_h)
                } else {
                    0.0
                }
            }
            Self::Diffuse => l.z.max(0.0) / std::f64::consts::PI,
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
    /// The stratum's midpoint in the unit square.
    pub u: [f64; 2],
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
            u: [u1, u2],
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

/// `norm`, `fresnel` and the average direction (ltc_code's `computeAvgTerms`, in f64), by
/// stratified importance sampling over `strata`. The diffuse lobe samples the cosine, as
/// ltc_code does. The specular lobe samples GGX's *visible* normals (Heitz 2018) rather than
/// ltc_code's plain normals: the weight `f cos / pdf = G2/G1(v)` is then bounded by 1,
/// whereas with plain normals most samples leave below the horizon at grazing views and
/// even 512² strata miss the norm by 1.6e-3 at θo = 85° (quadrature in tests/fit/classic.rs).
pub fn lobe_moments(lobe: Lobe, v: DVec3, alpha: f64, strata: &[Stratum]) -> LobeMoments {
    let mut norm = 0.0;
    let mut fresnel = 0.0;
    let mut dir = DVec3::ZERO;
    for s in strata {
        let (l, weight) = match lobe {
            Lobe::Specular => {
                let h = visible_normal(v, alpha, s);
                let l = 2.0 * h.dot(v) * h - v;
                let g1 = 1.0 / (1.0 + lambda_ggx(v.z, alpha));
                (l, g2_correlated(v.z, l.z, alpha) / g1)
            }
            Lobe::Diffuse => {
                let l = s.cosine;
                let sample = lobe.eval(v, l, alpha);
                (
                    l,
                    if sample.pdf > 0.0 {
                        sample.value / sample.pdf
                    } else {
                        0.0
                    },
                )
            }
        };
        if weight > 0.0 {
            norm += weight;
            if lobe == Lobe::Specular {
                let h = (v + l).normalize_or_zero();
                fresnel += weight * (1.0 - v.dot(h).max(0.0)).powi(5);
            }
            dir += weight * l;
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

/// A GGX normal visible from `v`, distributed as `G1(v) max(v·h, 0) D(h) / v.z` (Heitz 2018,
/// "Sampling the GGX Distribution of Visible Normals", JCGT 7(4), listing 1). The stratum's
/// cosine sample supplies the disk point `(sqrt(u1) cos 2πu2, sqrt(u1) sin 2πu2)`.
pub fn visible_normal(v: DVec3, alpha: f64, s: &Stratum) -> DVec3 {
    visible_normal_aniso(v, Alpha::isotropic(alpha), s)
}

/// `visible_normal` for an anisotropic roughness: listing 1 stretches by α_x and α_y apart.
pub fn visible_normal_aniso(v: DVec3, alpha: Alpha<f64>, s: &Stratum) -> DVec3 {
    let vh = DVec3::new(alpha.x * v.x, alpha.y * v.y, v.z).normalize();
    let len2 = vh.x * vh.x + vh.y * vh.y;
    let t1 = if len2 > 0.0 {
        DVec3::new(-vh.y, vh.x, 0.0) / len2.sqrt()
    } else {
        DVec3::X
    };
    let t2 = vh.cross(t1);
    let (p1, p2) = (s.cosine.x, s.cosine.y);
    let blend = 0.5 * (1.0 + vh.z);
    let p2 = (1.0 - blend) * (1.0 - p1 * p1).max(0.0).sqrt() + blend * p2;
    let nh = p1 * t1 + p2 * t2 + (1.0 - p1 * p1 - p2 * p2).max(0.0).sqrt() * vh;
    DVec3::new(alpha.x * nh.x, alpha.y * nh.y, nh.z.max(0.0)).normalize()
}
