//! A pixel opened into its lights (`pixel::pixel_terms`): the lights' contributions sum to
//! the pixel's radiance by both methods, as the CPU reference shades it; with two tables,
//! each table's contributions sum to its side's pixel, and the shares of their difference
//! are each light's own difference as the CPU reference shades that light alone. And the CPU
//! render made in bands of rows (the browser's) is the one-shot render.

use glam::DVec3;
use ltc_lab::cpu::{Bands, render, shade_exact, shade_ltc};
use ltc_lab::light::sphere::SphereMethod;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::{ClipCase, Clipping, Normalization};
use ltc_lab::metrics::luminance;
use ltc_lab::pixel::pixel_terms;
use ltc_lab::render::{LtcRules, Method, RenderSettings, ShapeMethods, Tables, View};
use ltc_lab::scene::{SPHERE_PRESETS, preset};

/// The lab's sphere methods (the LTC side's, the exact side's).
const SPHERES: [SphereMethod; 2] = [SphereMethod::LtcDisk, SphereMethod::Exact];

/// The lab's methods for every shape with a size (the LTC side's, the exact side's): point
/// scenes never read them.
fn sides() -> (ShapeMethods, ShapeMethods) {
    (ShapeMethods::approximations(), ShapeMethods::references())
}

#[test]
fn the_lights_contributions_sum_to_the_pixel_for_both_methods() {
    let lut = Lut::embedded();
    let (w, h) = (64, 36);
    let mut pixels = 0;
    for (name, clip) in [
        ("paper-100", Clipping::BOTH),
        ("figure2-case1", Clipping::CASE2),
        ("figure2-case2", Clipping::CASE1),
    ] {
        let scene = preset(name);
        for (x, y) in [(8, 30), (32, 18), (50, 20), (60, 5)] {
            let Some(p) = scene.surface_point(x, y, w, h) else {
                continue;
            };
            let n = Normalization::Corrected;
            let t = pixel_terms(
                &scene,
                (lut, None),
                &p,
                &rules(clip, n),
                (&sides().0, &sides().1),
            )
            .unwrap();
            let ltc = shade_ltc(&scene, lut, &p, &scene.lights, &rules(clip, n));
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

/// Two tables compared: each light is evaluated with table A and with table B, and each
/// side's contributions sum to that side's pixel as the CPU reference renders it (`render`
/// with view A, and view B with `table_b`: the renderer's own choice of table); each light's
/// share of |A − B| is its difference as `shade_ltc` shades it alone with either table.
#[test]
fn with_two_tables_each_sides_lights_sum_to_its_render_and_shares_are_each_lights_own() {
    let (a, b) = (Lut::embedded(), Lut::embedded_point());
    let (w, h) = (48, 27);
    let mut pixels = 0;
    for (name, clip) in [
        ("paper-100", Clipping::BOTH),
        ("figure2-case1", Clipping::CASE2),
        ("figure2-normal", Clipping::BOTH),
    ] {
        let scene = preset(name);
        let n = Normalization::Corrected;
        let settings = |view| RenderSettings {
            view,
            b_reads_table_b: true,
            b: ltc_lab::render::ShapeMethods::references().with(Method::Ltc),
            rules: LtcRules {
                clipping: clip,
                normalization: n,
                ..LtcRules::default()
            },
            ..RenderSettings::single(w, h, Method::Ltc)
        };
        let side = |view| render(&scene, Tables { a, b }, &settings(view));
        let (frame_a, frame_b) = (side(View::A), side(View::B));
        for (x, y) in [(6, 22), (24, 13), (38, 15), (45, 4), (12, 8), (30, 24)] {
            let Some(p) = scene.surface_point(x, y, w, h) else {
                continue;
            };
            let t = pixel_terms(
                &scene,
                (a, Some(b)),
                &p,
                &rules(clip, n),
                (&sides().0, &sides().1),
            )
            .unwrap();
            let k = y * w + x;
            let sum_b = t
                .terms
                .iter()
                .fold(DVec3::ZERO, |s, l| s + l.ltc_b.unwrap());
            // Up to 100 terms of f64 summed in the renderer's order: 100 roundings of the
            // sum's magnitude, 1e-13 relative.
            let close = |u: DVec3, v: DVec3| {
                (u - v).abs().max_element() <= 1e-13 * v.abs().max_element().max(1e-300)
            };
            assert!(close(t.ltc, frame_a.pixels[k]), "{name} ({x}, {y}): side A");
            assert!(
                close(sum_b, frame_b.pixels[k]),
                "{name} ({x}, {y}): {sum_b} vs {}",
                frame_b.pixels[k]
            );
            assert!(close(t.side_b(), frame_b.pixels[k]));
            // Each light alone through the CPU reference with either table.
            let alone = |lut, i: usize| {
                let one = &scene.lights[i..=i];
                luminance(shade_ltc(&scene, lut, &p, one, &rules(clip, n)))
            };
            let diffs: Vec<f64> = (0..scene.lights.len())
                .map(|i| (alone(a, i) - alone(b, i)).abs())
                .collect();
            let total: f64 = diffs.iter().sum();
            if total == 0.0 {
                // No light reaches the point (case 1's light, where M^-1 lifts none of it):
                // no share either.
                assert!(t.terms.iter().all(|l| t.difference_share(l) == 0.0));
                continue;
            }
            let mut shares = 0.0;
            for l in &t.terms {
                let share = t.difference_share(l);
                // One light's difference and a sum of ≤ 100 of them, each a few roundings
                // of f64 apart from the reference's: 1e-12 of a share ≤ 1.
                assert!(
                    (share - diffs[l.index] / total).abs() <= 1e-12,
                    "{name} ({x}, {y}) light {}: {share} vs {}",
                    l.index,
                    diffs[l.index] / total
                );
                shares += share;
            }
            assert!(
                (shares - 1.0).abs() < 1e-12,
                "{name}: shares sum to {shares}"
            );
            pixels += 1;
        }
        // The two tables must make the sides differ, or the sums above would not tell them
        // apart.
        let apart = frame_a
            .pixels
            .iter()
            .zip(&frame_b.pixels)
            .any(|(u, v)| (luminance(*u) - luminance(*v)).abs() > 1e-6 * luminance(*v).abs());
        assert!(apart, "{name}: table B renders as table A");
    }
    assert!(pixels >= 9, "only {pixels} pixels where the tables differ");
}

/// Without table B, nothing of it is made up: the terms compare LTC with the exact BRDF.
#[test]
fn without_table_b_side_b_is_the_exact_brdf() {
    let scene = preset("paper-100");
    let p = scene.surface_point(30, 20, 64, 36).unwrap();
    let n = Normalization::Corrected;
    let t = pixel_terms(
        &scene,
        (Lut::embedded(), None),
        &p,
        &rules(Clipping::BOTH, n),
        (&sides().0, &sides().1),
    )
    .unwrap();
    assert!(t.ltc_b.is_none() && t.terms.iter().all(|l| l.ltc_b.is_none()));
    assert_eq!(t.side_b(), t.exact);
    assert_eq!(t.relative_difference(), t.relative_error());
}

/// The rules of a render with the table read bilinearly and eq. 30's horizon handling.
fn rules(clipping: Clipping, normalization: Normalization) -> LtcRules {
    LtcRules {
        clipping,
        normalization,
        ..LtcRules::default()
    }
}

/// The browser renders the CPU plane in bands of rows over frames (`cpu::Bands`):
/// the image is the one-shot render's to the bit, in every view (the difference view's floor
/// is taken over the whole image, after the bands are stacked).
#[test]
fn a_render_in_bands_is_the_whole_render() {
    let scene = preset("paper-100");
    let lut = Lut::embedded();
    for view in [View::A, View::Split, View::Diff] {
        let s = RenderSettings {
            view,
            ..RenderSettings::single(48, 37, Method::LtcFast)
        };
        let whole = render(&scene, lut, &s);
        let mut bands = Bands::new(&s);
        let mut steps = 0;
        let banded = loop {
            steps += 1;
            if let Some(f) = bands.step(&scene, lut, 5) {
                break f;
            }
        };
        // 37 rows in bands of 5: 8 steps a pass.
        assert_eq!(
            steps,
            8 * if view == View::Diff { 2 } else { 1 },
            "{view:?}"
        );
        assert_eq!((banded.width, banded.height), (whole.width, whole.height));
        assert_eq!(banded.divider, whole.divider, "{view:?}");
        assert_eq!(banded.on_plane, whole.on_plane, "{view:?}");
        let bits = |f: &ltc_lab::render::Frame| -> Vec<[u64; 3]> {
            f.pixels
                .iter()
                .map(|p| p.to_array().map(f64::to_bits))
                .collect()
        };
        assert!(bits(&banded) == bits(&whole), "{view:?}");
    }
}

/// Lights with a size: each side's terms sum to that side's render with its sphere method,
/// whichever pair of methods the sides use, and each light's row of sphere methods holds the
/// value its side shades it with.
#[test]
fn sized_lights_sum_to_each_sides_render_by_its_sphere_method() {
    let lut = Lut::embedded();
    let (w, h) = (40, 24);
    let mut pixels = 0;
    for (name, _) in SPHERE_PRESETS {
        let scene = preset(name);
        for spheres in [
            SPHERES,
            [SphereMethod::RepresentativePoint, SphereMethod::LtcPoint],
        ] {
            let settings = |method| RenderSettings {
                a: ltc_lab::render::ShapeMethods::approximations()
                    .with(Method::Ltc)
                    .with(spheres[0]),
                b: ltc_lab::render::ShapeMethods::references()
                    .with(method)
                    .with(spheres[1]),
                view: View::B,
                ..RenderSettings::single(w, h, Method::Ltc)
            };
            let a = render(
                &scene,
                lut,
                &RenderSettings {
                    view: View::A,
                    ..settings(Method::Brdf)
                },
            );
            let b = render(&scene, lut, &settings(Method::Brdf));
            for (x, y) in [(5, 20), (20, 12), (33, 6), (12, 16)] {
                let Some(p) = scene.surface_point(x, y, w, h) else {
                    continue;
                };
                let rules = LtcRules::default();
                let sides = (&settings(Method::Brdf).a, &settings(Method::Brdf).b);
                let t = pixel_terms(&scene, (lut, None), &p, &rules, sides).unwrap();
                let k = y * w + x;
                // A handful of terms in f64: 1e-13 relative.
                let close = |u: DVec3, v: DVec3| {
                    (u - v).abs().max_element() <= 1e-13 * v.abs().max_element().max(1e-300)
                };
                assert!(
                    close(t.ltc, a.pixels[k]),
                    "{name} ({x}, {y}): A {} vs {}",
                    t.ltc,
                    a.pixels[k]
                );
                assert!(
                    close(t.exact, b.pixels[k]),
                    "{name} ({x}, {y}): B {} vs {}",
                    t.exact,
                    b.pixels[k]
                );
                for l in &t.terms {
                    assert_eq!(l.by_method.len(), SphereMethod::ALL.len());
                    assert_eq!(l.by(spheres[0]), Some(l.ltc));
                    assert_eq!(l.by(spheres[1]), Some(l.exact));
                }
                pixels += 1;
            }
        }
    }
    assert!(pixels >= 16, "only {pixels} pixels on the plane");
}
