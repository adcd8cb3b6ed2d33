//! `eval`'s anisotropic rows: `exact_spec` against an independent f64 reference, written in
//! the slope form of Heitz 2014 (not the lab's vector form), and a row with α_x = α_y is the
//! isotropic row of the same view, bit for bit.

use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::remedy::HorizonRule;
use ltc_lab::measure::eval::{ANISO_HEADER, HEADER, evaluate, parse_cases};

/// Anisotropic GGX with height-correlated Smith in Heitz 2014's angular form (eqs. 85, 86,
/// 99): `D = 1 / (π α_x α_y cos⁴θh (1 + tan²θh (cos²φh/α_x² + sin²φh/α_y²))²)`,
/// `Λ = (−1 + √(1 + α_o² tan²θ))/2`, `α_o² = cos²φ α_x² + sin²φ α_y²`; times Schlick, over
/// `4 cos θo`.
fn reference(theta_o: f64, phi_o: f64, ax: f64, ay: f64, l: [f64; 3], f0: f64) -> f64 {
    let v = [
        theta_o.sin() * phi_o.cos(),
        theta_o.sin() * phi_o.sin(),
        theta_o.cos(),
    ];
    if l[2] <= 0.0 {
        return 0.0;
    }
    let h = [v[0] + l[0], v[1] + l[1], v[2] + l[2]];
    let n = (h[0] * h[0] + h[1] * h[1] + h[2] * h[2]).sqrt();
    let h = [h[0] / n, h[1] / n, h[2] / n];
    let (theta_h, phi_h) = (h[2].acos(), h[1].atan2(h[0]));
    let t2 = theta_h.tan().powi(2);
    let c4 = theta_h.cos().powi(4);
    let d = 1.0
        / (std::f64::consts::PI
            * ax
            * ay
            * c4
            * (1.0 + t2 * (phi_h.cos().powi(2) / (ax * ax) + phi_h.sin().powi(2) / (ay * ay)))
                .powi(2));
    let lambda = |w: [f64; 3]| {
        let (t, p) = (w[2].acos(), w[1].atan2(w[0]));
        let ao2 = p.cos().powi(2) * ax * ax + p.sin().powi(2) * ay * ay;
        (-1.0 + (1.0 + ao2 * t.tan().powi(2)).sqrt()) / 2.0
    };
    let g2 = 1.0 / (1.0 + lambda(v) + lambda(l));
    let v_h = v[0] * h[0] + v[1] * h[1] + v[2] * h[2];
    let f = f0 + (1.0 - f0) * (1.0 - v_h).powi(5);
    d * g2 * f / (4.0 * v[2])
}

#[test]
fn exact_spec_matches_an_independent_reference() {
    let mut rows = String::from(ANISO_HEADER);
    let mut cases = Vec::new();
    let pairs: [(f64, f64); 4] = [(0.3, 0.05), (0.05, 0.3), (0.8, 0.2), (0.1, 0.1)];
    let views: [(f64, f64); 4] = [(20.0, 0.0), (45.0, 30.0), (70.0, 135.0), (80.0, 250.0)];
    for (k, (ax, ay)) in pairs.iter().enumerate() {
        for (j, (to, po)) in views.iter().enumerate() {
            // A light near the mirror direction, turned a little so D is not at its peak.
            let (t, p): (f64, f64) = (
                (*to + 5.0 * k as f64).min(85.0).to_radians(),
                (*po + 180.0 + 7.0 * j as f64).to_radians(),
            );
            let l = [t.sin() * p.cos(), t.sin() * p.sin(), t.cos()];
            rows += &format!("\n{to},{po},{ax},{ay},{},{},{},0.04", l[0], l[1], l[2]);
            cases.push((*to, *po, *ax, *ay, l));
        }
    }
    let parsed = parse_cases(&rows, "aniso.csv").unwrap();
    for (c, (to, po, ax, ay, l)) in parsed.rows.iter().zip(cases) {
        let out = evaluate(c, Lut::embedded(), HorizonRule::Eq30);
        let values: Vec<f64> = out.split(',').skip(8).map(|x| x.parse().unwrap()).collect();
        let r = reference(to.to_radians(), po.to_radians(), ax, ay, l, 0.04);
        // Two f64 evaluations of one formula by different routes (angles against vectors):
        // rounding, amplified by D's peak, stays far below 1e-4.
        assert!(
            (values[0] - r).abs() <= 1e-4 * r.abs().max(1e-12),
            "{out}: reference {r}"
        );
        assert!(values.iter().all(|x| x.is_finite() && *x >= 0.0), "{out}");
    }
}

#[test]
fn equal_alphas_give_the_isotropic_row_bit_for_bit() {
    let rows = [
        "0,0.27,0,0,1,0.04",
        "60,0.5,0.6,0,0.8,1",
        "85,0.05,-0.99,0.1,0.1,0.5",
        "30,0.0001,-0.5,0,0.866,0.04",
    ];
    for row in rows {
        let f: Vec<&str> = row.split(',').collect();
        let iso = parse_cases(&format!("{HEADER}\n{row}"), "iso.csv").unwrap();
        let aniso_row = format!(
            "{},0,{},{},{},{},{},{}",
            f[0], f[1], f[1], f[2], f[3], f[4], f[5]
        );
        let aniso = parse_cases(&format!("{ANISO_HEADER}\n{aniso_row}"), "aniso.csv").unwrap();
        let a: Vec<String> = evaluate(&iso.rows[0], Lut::embedded(), HorizonRule::Eq30)
            .split(',')
            .skip(6)
            .map(str::to_string)
            .collect();
        let b: Vec<String> = evaluate(&aniso.rows[0], Lut::embedded(), HorizonRule::Eq30)
            .split(',')
            .skip(8)
            .map(str::to_string)
            .collect();
        // brdf_spec,brdf_diffuse,ltc_spec,ltc_diffuse against exact_spec,ltc_spec,exact_diffuse,ltc_diffuse.
        assert_eq!(
            [&a[0], &a[2], &a[1], &a[3]],
            [&b[0], &b[1], &b[2], &b[3]],
            "{row}"
        );
    }
}

#[test]
fn anisotropic_rows_refuse_bad_values_by_line() {
    for (row, what) in [
        ("30,0,0.3,0,0,0,1,0.04", "alpha_y must be in"),
        ("30,0,2,0.3,0,0,1,0.04", "alpha_x must be in"),
        ("30,400,0.3,0.2,0,0,1,0.04", "phi_o"),
        ("30,0,0.3,0.2,0,0,1", "expected 8 values"),
    ] {
        let e = parse_cases(&format!("{ANISO_HEADER}\n{row}"), "a.csv").unwrap_err();
        assert_eq!(e.input, "a.csv line 2", "{row}");
        assert!(e.message.contains(what), "{row}: {e}");
    }
}
