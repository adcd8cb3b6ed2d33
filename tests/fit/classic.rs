//! The fitter: an 8×8 table fitted inside the suite (errors within bounds taken from the
//! published ltc_code table, parameters smooth), parallel = serial, magnitudes and stored
//! errors against independent f64 quadrature.

use crate::common::{mirror, sphere_integral};
use glam::DVec3;
use ltc_lab::brdf::brdf_cos;
use ltc_lab::ltc::fit::{CellFit, CellProblem, FitSettings, FitStrata, fit_lobe, fit_table};
use ltc_lab::ltc::lobe::{Lobe, lobe_moments, strata};
use ltc_lab::ltc::lut::{Channel, Lut};
use ltc_lab::ltc::{Clipping, Normalization};

fn small(size: usize) -> FitSettings {
    FitSettings {
        size,
        ..FitSettings::default()
    }
}

/// Upper bound of a fitted cell's specular pointwise error by view angle. Measured on
/// ltc_code's published 64×64 table with this metric: 1–4% at normal view, 5–14% at θo ≈ 42°,
/// 24–32% at 65°, 27–49% at 78°, 70–100% near grazing. An 8×8 table warm-starts across 15°
/// steps (a worse start than 64×64's 1.4°), so the bounds allow about 1.5× those figures, and
/// 1.9× at 74.6° where the α_min column's delta-like lobe is hardest.
fn spec_bound(theta_degrees: f64, alpha: f64) -> f64 {
    match theta_degrees {
        t if t < 1.0 => 0.05,
        t if t <= 50.0 => 0.25,
        t if t <= 65.0 => 0.45,
        t if t <= 80.0 => 0.9,
        // Near grazing the exact lobe is cut by the horizon. For rough surfaces the published
        // fit stays under 100%; for smooth ones the lobe is a sliver along the horizon and
        // the fit may miss it entirely: 2 is the error of two disjoint lobes of equal mass,
        // plus 10% for the 64×64-stratum estimate of the err channel (see
        // `stored_errors_match_quadrature`).
        _ if alpha >= 0.3 => 1.0,
        _ => 2.2,
    }
}

#[test]
fn an_8x8_fit_is_accurate_and_smooth() {
    let lut = fit_table(&small(8), &|| {}).lut;
    let n = lut.size;
    for j in 0..n {
        for i in 0..n {
            let cell = lut.cell(i, j);
            assert!(
                cell.0.iter().all(|x| x.is_finite()),
                "non-finite cell ({i}, {j})"
            );
            let (theta, alpha) = (lut.theta_o(j).to_degrees(), lut.alpha(i));
            let s = f64::from(cell.get(Channel::SpecErr));
            assert!(
                s <= spec_bound(theta, alpha),
                "spec.err {s} at θ={theta:.1} α={alpha:.4}"
            );
            // Burley's diffuse is nearly a cosine; ltc_code's diffuse fit is within a few %.
            // The largest, at α = 1 grazing, is where FD's retro-reflection peak is strongest.
            let d = f64::from(cell.get(Channel::DiffErr));
            assert!(d <= 0.1, "diff.err {d} at θ={theta:.1} α={alpha:.4}");
        }
    }

    // Smoothness, away from the α_min column (a delta lobe) and the grazing row (a lobe cut
    // by the horizon), where the fit is ill-posed: along every row and column each stored
    // entry of M⁻¹ changes by less than 0.5 per step (entries lie in [−1, 1.7]) and turns at
    // most once — a fit that jumped between local minima would zig-zag.
    let entries = [
        Channel::SpecM00,
        Channel::SpecM02,
        Channel::SpecM20,
        Channel::SpecM22,
    ];
    let check = |name: &str, xs: Vec<f64>| {
        for w in xs.windows(2) {
            assert!((w[1] - w[0]).abs() < 0.5, "{name}: step {w:?}");
        }
        // Steps below 1e-3 count as flat: f32 storage and fit tolerance.
        let signs: Vec<f64> = xs
            .windows(2)
            .map(|w| w[1] - w[0])
            .filter(|d| d.abs() > 1e-3)
            .map(f64::signum)
            .collect();
        let turns = signs.windows(2).filter(|s| s[0] != s[1]).count();
        assert!(turns <= 1, "{name} zig-zags: {xs:?}");
    };
    for c in entries {
        for j in 0..n - 1 {
            let row = (1..n).map(|i| f64::from(lut.cell(i, j).get(c))).collect();
            check(&format!("{c:?} row {j}"), row);
        }
        for i in 1..n {
            let col = (0..n - 1)
                .map(|j| f64::from(lut.cell(i, j).get(c)))
                .collect();
            check(&format!("{c:?} column {i}"), col);
        }
    }
}

/// ltc_code's serial loop, written out: α from 1 down, θo from normal to grazing; the
/// normal-view cell starts from the previous α's normal-view fit, every other cell from the
/// cell before it.
fn serial_fit(lobe: Lobe, s: &FitSettings) -> Vec<CellFit> {
    let n = s.size;
    let strata = FitStrata::new(s);
    let mut table: Vec<Option<CellFit>> = vec![None; n * n];
    let mut previous: Option<CellFit> = None;
    for a in (0..n).rev() {
        for t in 0..n {
            let start = match (t, a) {
                (0, a) if a == n - 1 => [1.0, 1.0, 0.0],
                (0, a) => table[a + 1].unwrap().params.m,
                _ => previous.unwrap().params.m,
            };
            let fit = CellProblem::new(lobe, a, t, s, &strata).fit(start, s, &strata, |_, _| {
                ltc_lab::ltc::nelder_mead::CONTINUE
            });
            table[t * n + a] = Some(fit);
            previous = Some(fit);
        }
    }
    table.into_iter().map(Option::unwrap).collect()
}

#[test]
fn parallel_columns_reproduce_the_serial_order_exactly() {
    let s = small(6);
    for lobe in Lobe::ALL {
        let parallel: Vec<CellFit> = fit_lobe(lobe, &s, &|| {})
            .into_iter()
            .map(|(f, _)| f)
            .collect();
        assert_eq!(parallel, serial_fit(lobe, &s), "{lobe:?}");
    }
}

/// Cells where the magnitudes are checked: roughness from nearly smooth to 1, view from
/// normal to 85°.
const CELLS: [(f64, f64); 12] = [
    (0.0, 0.02),
    (0.0, 0.3),
    (0.0, 1.0),
    (30.0, 0.05),
    (30.0, 0.5),
    (50.0, 0.1),
    (60.0, 0.27),
    (60.0, 1.0),
    (75.0, 0.05),
    (75.0, 0.6),
    (85.0, 0.2),
    (85.0, 1.0),
];

#[test]
fn magnitudes_match_quadrature_to_1e_3() {
    let strata = strata(FitSettings::default().moment_samples);
    for (theta, alpha) in CELLS {
        let v = crate::common::view(theta);
        let spec = lobe_moments(Lobe::Specular, v, alpha, &strata);
        let diff = lobe_moments(Lobe::Diffuse, v, alpha, &strata);
        let eval = |l: DVec3| brdf_cos(v.to_array(), l.to_array(), alpha, 1.0);
        let schlick = |l: DVec3| (1.0 - v.dot((v + l).normalize()).max(0.0)).powi(5);
        let q_norm = sphere_integral(mirror(v), 800, |l| eval(l).specular);
        let q_fresnel = sphere_integral(mirror(v), 800, |l| schlick(l) * eval(l).specular);
        let q_diff = sphere_integral(DVec3::Z, 400, |l| eval(l).diffuse);
        for (name, got, want) in [
            ("spec.norm", spec.norm, q_norm),
            ("spec.fresnel", spec.fresnel, q_fresnel),
            ("diff.norm", diff.norm, q_diff),
        ] {
            assert!(
                (got - want).abs() < 1e-3,
                "{name} at θ={theta} α={alpha}: {got} vs quadrature {want}"
            );
        }
    }
}

#[test]
fn stored_errors_match_quadrature() {
    let lut = Lut::embedded();
    for (i, j) in [(20, 0), (30, 20), (17, 32), (45, 45), (63, 50), (40, 58)] {
        let (alpha, theta) = (lut.alpha(i), lut.theta_o(j));
        let v = DVec3::new(theta.sin(), 0.0, theta.cos());
        // The cell itself (bilinear at a cell centre returns the cell).
        let pair = lut.sample(alpha, v.z).ltc_pair();
        for (lobe, ltc, ch) in [
            (Lobe::Specular, pair.spec, Channel::SpecErr),
            (Lobe::Diffuse, pair.diff, Channel::DiffErr),
        ] {
            let exact = |l: DVec3| lobe.eval(v, l, alpha).value;
            let approx =
                |l: DVec3| ltc.norm * ltc.ltc_eval(l, Clipping::CASE2, Normalization::Corrected);
            // One quadrature centred on the exact lobe's peak; at these cells (α ≥ 0.07) both
            // lobes are broad enough for its resolution everywhere on the sphere.
            let centre = if lobe == Lobe::Specular {
                mirror(v)
            } else {
                DVec3::Z
            };
            let l1 = sphere_integral(centre, 800, |l| (approx(l) - exact(l)).abs());
            let norm = sphere_integral(centre, 800, exact);
            let want = l1 / norm;
            let got = f64::from(lut.cell(i, j).get(ch));
            // The err channel is a 2×64² stratified estimate: within 5% of itself plus 0.003.
            assert!(
                (got - want).abs() < 0.05 * want + 0.003,
                "{ch:?} at α={alpha:.3} θ={:.1}: stored {got} vs quadrature {want}",
                theta.to_degrees()
            );
        }
    }
}
