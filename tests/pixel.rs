//! A pixel opened into its lights (`pixel::pixel_terms`): the lights' contributions sum to
//! the pixel's radiance by both methods, as the CPU reference shades it.

use ltc_lab::cpu::{shade_exact, shade_ltc};
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::{ClipCase, Clipping, Normalization};
use ltc_lab::pixel::pixel_terms;
use ltc_lab::render::LutFilter;
use ltc_lab::scene::preset;

#[test]
fn the_lights_contributions_sum_to_the_pixel_for_both_methods() {
    let lut = Lut::embedded();
    let (w, h) = (64, 36);
    let mut pixels = 0;
    for (name, clip) in [
        ("paper-100", Clipping::BOTH),
        ("figure2-case1", Clipping::TRANSFORMED),
        ("figure2-case2", Clipping::HORIZON),
    ] {
        let scene = preset(name);
        for (x, y) in [(8, 30), (32, 18), (50, 20), (60, 5)] {
            let Some(p) = scene.surface_point(x, y, w, h) else {
                continue;
            };
            let n = Normalization::Corrected;
            let t = pixel_terms(&scene, lut, &p, clip, n, LutFilter::Bilinear).unwrap();
            let ltc = shade_ltc(&scene, lut, &p, &scene.lights, clip, n, LutFilter::Bilinear);
            let exact = shade_exact(&scene, &p, &scene.lights);
            let sum_ltc = t.terms.iter().fold(glam::DVec3::ZERO, |a, l| a + l.ltc);
            let sum_exact = t.terms.iter().fold(glam::DVec3::ZERO, |a, l| a + l.exact);
            // Up to 100 terms of f64: 100 roundings of the sum's magnitude, 1e-13 relative.
            let close = |a: glam::DVec3, b: glam::DVec3| {
                (a - b).abs().max_element() <= 1e-13 * b.abs().max_element().max(1e-300)
            };
            assert!(close(sum_ltc, ltc), "{name} ({x}, {y}): {sum_ltc} vs {ltc}");
            assert!(
                close(sum_exact, exact),
                "{name} ({x}, {y}): {sum_exact} vs {exact}"
            );
            assert!(close(t.ltc, ltc) && close(t.exact, exact));
            assert_eq!(t.terms.len(), scene.lights.len());
            if (ltc - exact).length() > 0.0 {
                let shares: f64 = t.terms.iter().map(|l| t.error_share(l)).sum();
                assert!(
                    (shares - 1.0).abs() < 1e-9,
                    "{name}: shares sum to {shares}"
                );
            }
            // Each term is made of the factors the table shows (eq. 30 per lobe).
            for l in &t.terms {
                if l.case != ClipCase::Visible {
                    continue;
                }
                let c = scene.material.base_color[1] * scene.lights[l.index].color[1];
                let g = l.irradiance
                    / ltc_lab::metrics::luminance(glam::DVec3::from(scene.lights[l.index].color))
                    * (l.spec_magnitude * l.d_spec * scene.lights[l.index].color[1]
                        + l.diff_magnitude * l.d_diff * c);
                assert!(
                    (g - l.ltc.y).abs() <= 1e-12 * l.ltc.y.abs().max(1e-300),
                    "{g} vs {}",
                    l.ltc.y
                );
            }
            pixels += 1;
        }
    }
    assert!(pixels >= 9, "only {pixels} pixels on the plane");
}
