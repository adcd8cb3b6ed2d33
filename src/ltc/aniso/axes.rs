//! The 4D table's axes (docs/design.md §2.9): how a node's four indices map to
//! `(α_x, α_y, θo, φo)`, and how a material and a view fold into the table's quarter of
//! views. Three kinds: the lab's own, and the two of the I3D 2022 tables.

use glam::{DMat3, DVec3};

use crate::brdf::Alpha;
use crate::ltc::lut::{ALPHA_MIN, THETA_MAX};

/// How a 4D table's node indices `(a, b, t, p)` map to a material and a view. In every kind
/// the view is `(sin θ cos φ, sin θ sin φ, cos θ)` in the table's frame, whose x axis is the
/// one α_x acts along, and φ covers `[0, π/2]`: the other quadrants are mirror images.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum AnisoAxes {
    /// The lab's: `a` ↔ `r`, `α_x = α_min + (1 − α_min) r²` (ltc_code's roughness axis
    /// `α = r²`, moved so that `r = 0` is exactly α_min), `b` ↔ `q`, `α_y = α_min + (α_x −
    /// α_min) q²` (the ratio of the perceptual roughnesses, from α_min), `t` ↔ `s`,
    /// `1 − cos θ = s² (1 − cos θ_max)` (ltc_code's view axis, scaled so that its last node
    /// is exactly `THETA_MAX`), `p` ↔ `φ` linearly. Every axis is read back exactly at its
    /// nodes, none clamped. α_x is the larger roughness (a material rougher along its
    /// bitangent is the same table turned by 90°).
    Lab,
    /// I3D 2022's `alphax_alphay_theta_phi`: `α_x = a/7`, `α_y = b/7` (each at least 1e-4),
    /// `θ = t/7 · 0.9999 · π/2`, `φ = p/7 · π/2`: linear axes, both orders of α_x and α_y.
    I3dAlphaXY,
    /// I3D 2022's `alpha_lambda_theta_phi`: `α_x = a/7`, `α_y = α_x · b/7` (each at least
    /// 1e-4), θ and φ as above; α_x is the larger.
    I3dAlphaLambda,
}

/// I3D 2022's grazing limit: θ = 0.9999 · π/2 at its last node.
pub const I3D_THETA_MAX: f64 = 0.9999 * std::f64::consts::FRAC_PI_2;

/// I3D 2022's smallest α (its fitting script's `max(α, 0.0001)`).
pub const I3D_ALPHA_MIN: f64 = 1e-4;

/// A point of the table's domain: the material and the view in the table's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AnisoPoint {
    pub alpha: Alpha<f64>,
    pub theta: f64,
    pub phi: f64,
}

impl AnisoPoint {
    /// The unit view vector in the table's frame.
    pub fn view(&self) -> DVec3 {
        let (st, ct) = self.theta.sin_cos();
        let (sp, cp) = self.phi.sin_cos();
        DVec3::new(st * cp, st * sp, ct)
    }
}

/// A material and view folded into a table's domain: the point there, the unit view in the
/// table's frame (the point's view, not rebuilt from its angles), and the rotation or mirror
/// `table_from_tangent` that takes the tangent frame's vectors to the table's frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Folded {
    pub point: AnisoPoint,
    pub w: DVec3,
    /// Orthogonal, fixing `z`: a quarter turn where the material is rougher along its
    /// bitangent (for the kinds that keep α_x the larger), then mirrors of x and y.
    pub table_from_tangent: DMat3,
}

impl AnisoAxes {
    pub const ALL: [Self; 3] = [Self::Lab, Self::I3dAlphaXY, Self::I3dAlphaLambda];

    /// Whether the table holds only materials with `α_x ≥ α_y`.
    pub fn major_first(self) -> bool {
        !matches!(self, Self::I3dAlphaXY)
    }

    /// The smallest α the table's nodes hold.
    pub fn alpha_min(self) -> f64 {
        match self {
            Self::Lab => ALPHA_MIN,
            Self::I3dAlphaXY | Self::I3dAlphaLambda => I3D_ALPHA_MIN,
        }
    }

    /// The material and view of node `(a, b, t, p)` of a table of `dims` nodes per axis.
    pub fn node(self, [a, b, t, p]: [usize; 4], dims: [usize; 4]) -> AnisoPoint {
        let x = |k: usize, axis: usize| k as f64 / (dims[axis] - 1) as f64;
        let phi = x(p, 3) * std::f64::consts::FRAC_PI_2;
        match self {
            Self::Lab => {
                let r = x(a, 0);
                let alpha_x = ALPHA_MIN + (1.0 - ALPHA_MIN) * r * r;
                let q = x(b, 1);
                let alpha_y = ALPHA_MIN + (alpha_x - ALPHA_MIN) * q * q;
                let s = x(t, 2);
                let theta = (1.0 - s * s * (1.0 - THETA_MAX.cos()))
                    .clamp(-1.0, 1.0)
                    .acos();
                AnisoPoint {
                    alpha: Alpha {
                        x: alpha_x,
                        y: alpha_y,
                    },
                    theta,
                    phi,
                }
            }
            Self::I3dAlphaXY | Self::I3dAlphaLambda => {
                let alpha_x = x(a, 0).max(I3D_ALPHA_MIN);
                let alpha_y = match self {
                    Self::I3dAlphaXY => x(b, 1),
                    _ => x(a, 0) * x(b, 1),
                }
                .max(I3D_ALPHA_MIN);
                AnisoPoint {
                    alpha: Alpha {
                        x: alpha_x,
                        y: alpha_y,
                    },
                    theta: x(t, 2) * I3D_THETA_MAX,
                    phi,
                }
            }
        }
    }

    /// The continuous coordinates of a point of the domain, each in `[0, 1]` between the
    /// first and the last node (node `k` of `N` at `k/(N−1)`); outside, clamped.
    pub fn coordinates(self, q: &AnisoPoint) -> [f64; 4] {
        let phi = (q.phi / std::f64::consts::FRAC_PI_2).clamp(0.0, 1.0);
        let c = match self {
            Self::Lab => [
                ((q.alpha.x - ALPHA_MIN) / (1.0 - ALPHA_MIN))
                    .max(0.0)
                    .sqrt(),
                ((q.alpha.y - ALPHA_MIN) / (q.alpha.x - ALPHA_MIN))
                    .max(0.0)
                    .sqrt(),
                ((1.0 - q.theta.cos()) / (1.0 - THETA_MAX.cos()))
                    .max(0.0)
                    .sqrt(),
                phi,
            ],
            Self::I3dAlphaXY => [
                i3d_alpha(q.alpha.x),
                i3d_alpha(q.alpha.y),
                q.theta / I3D_THETA_MAX,
                phi,
            ],
            Self::I3dAlphaLambda => [
                i3d_alpha(q.alpha.x),
                i3d_lambda(q.alpha.y, q.alpha.x),
                q.theta / I3D_THETA_MAX,
                phi,
            ],
        };
        c.map(|x| {
            if x.is_finite() {
                x.clamp(0.0, 1.0)
            } else {
                0.0
            }
        })
    }

    /// A material and a unit view `v` (tangent frame, `v.z > 0`) folded into the domain: a
    /// quarter turn where the kind keeps α_x the larger and the material is rougher along
    /// its bitangent, then the mirrors of x and y that bring `v` into the first quadrant.
    pub fn fold(self, alpha: Alpha<f64>, v: DVec3) -> Folded {
        let (alpha, turn) = if self.major_first() && alpha.y > alpha.x {
            // x' = y, y' = −x: a proper rotation, so that α_x' = α_y is the larger.
            let turn = DMat3::from_cols(DVec3::new(0.0, -1.0, 0.0), DVec3::X, DVec3::Z);
            (
                Alpha {
                    x: alpha.y,
                    y: alpha.x,
                },
                turn,
            )
        } else {
            (alpha, DMat3::IDENTITY)
        };
        let w = turn * v;
        let mirror = DMat3::from_diagonal(DVec3::new(sign(w.x), sign(w.y), 1.0));
        let w = mirror * w;
        let theta = w.z.clamp(-1.0, 1.0).acos();
        let phi = if w.x > 0.0 || w.y > 0.0 {
            w.y.atan2(w.x)
        } else {
            0.0
        };
        Folded {
            point: AnisoPoint { alpha, theta, phi },
            w,
            table_from_tangent: mirror * turn,
        }
    }
}

/// I3D 2022's α axis: nodes at `max(k/7, 1e-4)`, so the first node sits at 1e-4; linear
/// between the nodes, each node read exactly.
fn i3d_alpha(alpha: f64) -> f64 {
    first_interval(alpha, I3D_ALPHA_MIN, 1.0 / 7.0)
}

/// I3D 2022's λ axis: `α_y = max(α_x · k/7, 1e-4)`, so its first node sits at `λ = 1e-4/α_x`.
fn i3d_lambda(alpha_y: f64, alpha_x: f64) -> f64 {
    first_interval(alpha_y / alpha_x, I3D_ALPHA_MIN / alpha_x, 1.0 / 7.0)
}

/// A linear axis of nodes `k · step` whose first node was raised to `first`: `x` between the
/// first two nodes mapped linearly onto `[0, step]`, and as it is beyond.
fn first_interval(x: f64, first: f64, step: f64) -> f64 {
    if x >= step || first >= step {
        x
    } else {
        step * (x - first) / (step - first)
    }
}

/// +1 for a non-negative value, −1 for a negative one.
fn sign(x: f64) -> f64 {
    if x < 0.0 { -1.0 } else { 1.0 }
}
