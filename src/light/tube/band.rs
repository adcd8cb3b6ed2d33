//! A capsule's silhouette as a band about the great circle of its segment (docs/design.md
//! §1.15): the tube's own rule, which converges over a long thin tube where the polar rule of
//! `region` does not. In longitude `ψ` about the normal `o` of the plane of the segment and the
//! shading point, and latitude `λ` from that plane, the capsule is symmetric about `λ = 0`, so
//! its silhouette is `|λ| ≤ Λ(ψ)`: between the longitudes of the tangent points `Λ` is the
//! band's, `tan Λ = r |sin β| / √(ρ² − r²)` (`β` between the direction and the axis, `ρ` the
//! axis line's distance), and beyond them an end ball's cap's, `cos Λ = cos σ / cos(ψ − ψ_c)`.
//! `∫ g dω = ∫∫ g cos λ dλ dψ` is then smooth on each piece of longitude between the cuts (the
//! caps' extents and crossing, the tangent points, the horizon's corners and the lobe's peak),
//! each latitude interval cut by the horizon in closed form, and a glossy lobe is followed by
//! `x = peak + W tan t` in each coordinate (GGX's `1/(W² + x²)²` made smooth).

use std::f64::consts::{FRAC_PI_2, PI};

use glam::DVec3;

use crate::brdf::{Alpha, Lobes, brdf_cos_aniso};
use crate::light::polar::{mirror, rule};
use crate::light::tube::Tube;
use crate::light::tube::region::{Silhouette, horizon_corners};

/// The silhouette in longitude and latitude.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Band {
    /// Longitude 0, longitude π/2 and the pole: `u`, `w` in the segment's plane, `o` its normal.
    pub frame: [DVec3; 3],
    /// Each end ball's cap: its centre's longitude and its angular radius.
    pub caps: [(f64, f64); 2],
    /// Where the band is (the origin outside the cylinder about the axis): the tangent points'
    /// longitudes, the axis, and `r / √(ρ² − r²)`.
    pub band: Option<([f64; 2], DVec3, f64)>,
    /// The longitudes the silhouette spans.
    pub range: [f64; 2],
}

/// `x` brought into `(−π, π]`.
fn wrap(x: f64) -> f64 {
    let y = (x + PI).rem_euclid(2.0 * PI) - PI;
    if y == -PI { PI } else { y }
}

impl Band {
    /// The band of `tube`, whose silhouette is `s` (the origin outside the capsule).
    pub fn of(tube: &Tube, s: &Silhouette) -> Self {
        let r = tube.radius;
        let e = tube.axis();
        let cross = tube.a.cross(tube.b);
        let o = if cross.length() > 1e-12 * tube.a.length() * tube.b.length() {
            cross.normalize()
        } else {
            // Seen end-on (or a ball): any plane through the axis.
            let any = if tube.length() > 0.0 { e } else { tube.a };
            any.any_orthonormal_vector()
        };
        let u = tube.a.normalize();
        let w = o.cross(u);
        let frame = [u, w, o];
        let lon = |x: DVec3| x.dot(w).atan2(x.dot(u));
        let psi_b = lon(tube.b);
        let cap = |p: DVec3, psi: f64| (psi, (r / p.length()).min(1.0).asin());
        let caps = [cap(tube.a, 0.0), cap(tube.b, psi_b)];
        let near = |x: DVec3, at: f64| at + wrap(lon(x) - at);
        let band = s.band.map(|_| {
            let (ta, tb) = (near(s.tangents[0], 0.0), near(s.tangents[2], psi_b));
            let rho = (tube.a - e * tube.a.dot(e)).length();
            ([ta.min(tb), ta.max(tb)], e, r / (rho * rho - r * r).sqrt())
        });
        let range = [
            caps.iter().map(|c| c.0 - c.1).fold(f64::INFINITY, f64::min),
            caps.iter()
                .map(|c| c.0 + c.1)
                .fold(f64::NEG_INFINITY, f64::max),
        ];
        Self {
            frame,
            caps,
            band,
            range,
        }
    }

    /// The upper hemisphere as a band, for a point inside the capsule (which sees it all):
    /// longitude about `z`, the band everywhere and as wide as a hemisphere (`k = ∞`), the
    /// horizon cutting each meridian at latitude 0, and the caps of no width at longitude 0.
    pub fn hemisphere() -> Self {
        Self {
            frame: [DVec3::X, DVec3::Y, DVec3::Z],
            caps: [(0.0, 0.0); 2],
            band: Some(([-PI, PI], DVec3::Z, f64::INFINITY)),
            range: [-PI, PI],
        }
    }

    /// The direction at longitude `psi`, latitude 0.
    pub fn along(&self, psi: f64) -> DVec3 {
        let [u, w, _] = self.frame;
        u * psi.cos() + w * psi.sin()
    }

    /// The longitude of `x`, taken within π of the middle of the range.
    pub fn longitude(&self, x: DVec3) -> f64 {
        let [u, w, _] = self.frame;
        let mid = 0.5 * (self.range[0] + self.range[1]);
        mid + wrap(x.dot(w).atan2(x.dot(u)) - mid)
    }

    /// `Λ(ψ)`: the silhouette's half-width in latitude at longitude `psi` (0 outside it).
    pub fn half_width(&self, psi: f64) -> f64 {
        if let Some((at, e, k)) = self.band
            && (at[0]..=at[1]).contains(&psi)
        {
            return (k * self.along(psi).cross(e).length()).atan();
        }
        self.caps
            .iter()
            .map(|&(centre, sigma)| {
                let off = (psi - centre).abs();
                if off >= sigma {
                    0.0
                } else {
                    cap_half_width(sigma, off)
                }
            })
            .fold(0.0, f64::max)
    }

    /// The longitudes the rule's pieces end at, in order: the range's ends, each cap's extent,
    /// where the caps' circles cross, the tangent points, then `more` (corners, the peak),
    /// each kept within the range.
    pub fn cuts(&self, more: &[f64]) -> Vec<f64> {
        let [lo, hi] = self.range;
        let [(pa, sa), (pb, sb)] = self.caps;
        let mut cuts = vec![lo, hi, pa - sa, pa + sa, pb - sb, pb + sb];
        // cos σA cos(ψ − ψB) = cos σB cos(ψ − ψA): P cos ψ + Q sin ψ = 0.
        let p = sa.cos() * pb.cos() - sb.cos() * pa.cos();
        let q = sa.cos() * pb.sin() - sb.cos() * pa.sin();
        if p != 0.0 || q != 0.0 {
            let x = (-p).atan2(q);
            let mid = 0.5 * (lo + hi);
            for c in [x, x + PI] {
                cuts.push(mid + wrap(c - mid));
            }
        }
        if let Some((at, _, _)) = self.band {
            cuts.extend(at);
        }
        cuts.extend(more);
        let mut cuts: Vec<f64> = cuts.into_iter().map(|c| c.clamp(lo, hi)).collect();
        cuts.sort_by(f64::total_cmp);
        cuts.dedup_by(|a, b| (*a - *b).abs() <= PIECE_MIN);
        cuts
    }
}

/// A cap's half-width in latitude `off` radians of longitude from its centre (`off < σ`):
/// `cos Λ = cos σ / cos off`, taken as `sin Λ = √(sin(σ − off) sin(σ + off)) / cos off`, which
/// does not cancel for a small cap (`acos` of a ratio near 1 would, most of all in f32).
fn cap_half_width(sigma: f64, off: f64) -> f64 {
    (((sigma - off).sin() * (sigma + off).sin()).sqrt() / off.cos())
        .min(1.0)
        .asin()
}

/// Pieces of longitude or latitude narrower than this are dropped (two cuts at one place).
const PIECE_MIN: f64 = 1e-12;

/// Gauss–Legendre's `n` nodes over `[a, b]` with their weights, stretched toward `anchor` (an
/// end of the interval, or `None` for none) as `x = anchor ± width tan t`.
fn nodes(n: usize, [a, b]: [f64; 2], stretch: Option<(f64, f64)>) -> Vec<(f64, f64)> {
    let gl = rule(n);
    match stretch {
        None => gl
            .iter()
            .map(|&(x, w)| (a + 0.5 * (b - a) * (x + 1.0), 0.5 * (b - a) * w))
            .collect(),
        Some((anchor, width)) => {
            let (far, sign) = if (anchor - a).abs() <= (anchor - b).abs() {
                (b, 1.0)
            } else {
                (a, -1.0)
            };
            let top = ((far - anchor).abs() / width).atan();
            gl.iter()
                .map(|&(x, w)| {
                    let tan = (0.5 * top * (x + 1.0)).tan();
                    (
                        anchor + sign * width * tan,
                        0.5 * top * w * width * (1.0 + tan * tan),
                    )
                })
                .collect()
        }
    }
}

/// `[a, b]` split at `at` where it lies inside, each part with the end nearest `at` to
/// stretch toward.
fn around(at: f64, [a, b]: [f64; 2]) -> Vec<([f64; 2], f64)> {
    if at > a && at < b {
        vec![([a, at], at), ([at, b], at)]
    } else {
        vec![([a, b], at.clamp(a, b))]
    }
}

/// The latitudes at longitude `psi` inside the silhouette and above the surface, with the
/// direction `d` at latitude 0 there; `None` where none are: `[−Λ, Λ]` cut by
/// `z = cos λ d_z + sin λ o_z = R cos(λ − λ₀) ≥ 0`.
fn latitudes(band: &Band, psi: f64) -> Option<([f64; 2], DVec3)> {
    let half = band.half_width(psi);
    let d = band.along(psi);
    let o = band.frame[2];
    if half <= 0.0 || (d.z == 0.0 && o.z == 0.0) {
        return None;
    }
    let l0 = o.z.atan2(d.z);
    let (lo, hi) = ((-half).max(l0 - FRAC_PI_2), half.min(l0 + FRAC_PI_2));
    (hi > lo).then_some(([lo, hi], d))
}

/// `∫ g dω` over the silhouette above the surface by the band's rule, `n` nodes a dimension
/// and piece, stretched toward `peak` (longitude, latitude) by `width` radians where given.
pub fn band_integral(
    band: &Band,
    cuts: &[f64],
    n: usize,
    peak: Option<([f64; 2], f64)>,
    g: impl Fn(DVec3) -> f64,
) -> f64 {
    let o = band.frame[2];
    let mut total = 0.0;
    for piece in cuts.windows(2) {
        let parts = match peak {
            Some(([psi_p, lambda_p], width)) => around(psi_p, [piece[0], piece[1]])
                .into_iter()
                .map(|(p, anchor)| {
                    let w_psi = (width + (psi_p - anchor).abs()) / lambda_p.cos().max(0.05);
                    (p, Some((anchor, w_psi)))
                })
                .collect(),
            None => vec![([piece[0], piece[1]], None)],
        };
        for (p, stretch) in parts {
            if p[1] - p[0] <= PIECE_MIN {
                continue;
            }
            for (psi, w_psi) in nodes(n, p, stretch) {
                let Some((lat, d)) = latitudes(band, psi) else {
                    continue;
                };
                let lat_parts = match peak {
                    Some(([_, lambda_p], width)) => around(lambda_p, lat)
                        .into_iter()
                        .map(|(l, anchor)| (l, Some((anchor, width + (lambda_p - anchor).abs()))))
                        .collect(),
                    None => vec![(lat, None)],
                };
                for (l, stretch) in lat_parts {
                    if l[1] - l[0] <= PIECE_MIN {
                        continue;
                    }
                    for (lambda, w_lambda) in nodes(n, l, stretch) {
                        let x = d * lambda.cos() + o * lambda.sin();
                        total += w_psi * w_lambda * lambda.cos() * g(x);
                    }
                }
            }
        }
    }
    total
}

/// Both lobes over the silhouette above the surface toward `v` by the band's rule (base colour
/// 1, unit radiance): `(specular, diffuse)` nodes a dimension and piece, the specular lobe
/// stretched toward the mirror direction by `2 max(αx, αy)`. A point inside the capsule sees
/// the upper hemisphere (`Band::hemisphere`; `region::tube_exact`'s polar rule is its check).
pub fn tube_band(
    v: DVec3,
    tube: &Tube,
    alpha: Alpha<f64>,
    f0: f64,
    (n, n_diffuse): (usize, usize),
) -> Lobes<f64> {
    let silhouette = Silhouette::of(tube);
    let band = silhouette.map_or_else(Band::hemisphere, |s| Band::of(tube, &s));
    let lobes = |l: DVec3| brdf_cos_aniso(v.to_array(), l.to_array(), alpha, f0);
    let focus = mirror(v);
    let peak = [
        band.longitude(focus),
        focus.dot(band.frame[2]).clamp(-1.0, 1.0).asin(),
    ];
    let mut more: Vec<f64> = silhouette
        .map(|s| horizon_corners(&s))
        .unwrap_or_default()
        .iter()
        .map(|&c| band.longitude(c))
        .collect();
    let diffuse_cuts = band.cuts(&more);
    more.push(peak[0]);
    let cuts = band.cuts(&more);
    let width = 2.0 * alpha.x.max(alpha.y);
    Lobes {
        specular: band_integral(&band, &cuts, n, Some((peak, width)), |l| lobes(l).specular),
        diffuse: band_integral(&band, &diffuse_cuts, n_diffuse, None, |l| lobes(l).diffuse),
    }
}
