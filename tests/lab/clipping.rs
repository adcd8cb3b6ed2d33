//! The clipping panel: Figure 2's pictures with the lab's rules, the case maps, the profile's
//! line, and one light's error by elevation.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ltc_lab::app::clipping::setup::ClipScene;
use ltc_lab::app::{LabApp, PanelId};
use ltc_lab::ltc::ClipCase;

use crate::harness::{drag_along, lab, maximised, options, settle, shows, slide};

/// The rendered window's pixels inside picture `k` of `preset`'s row.
fn picture_pixels(h: &mut Harness<'static, LabApp>, preset: &str, k: usize) -> Vec<[u8; 3]> {
    let rect = h.get_by_label(&format!("{preset} picture {k}")).rect();
    let image = h.render().expect("a rendered frame");
    let inside = |x: u32, y: u32| rect.contains(egui::pos2(x as f32 + 0.5, y as f32 + 0.5));
    image
        .enumerate_pixels()
        .filter(|(x, y, _)| inside(*x, *y))
        .map(|(_, _, p)| [p[0], p[1], p[2]])
        .collect()
}

/// The first picture's caption (case 1's row comes first) that contains `start`: its name,
/// rules and exposure factor(s).
fn caption(h: &Harness<'static, LabApp>, start: &str) -> String {
    let node = h
        .query_all_by_label_contains(start)
        .next()
        .unwrap_or_else(|| panic!("no caption '{start}'"));
    node.value().unwrap_or_default()
}

/// Pixels bright enough to see on the dark panel (any channel ≥ 64/255: a quarter of full
/// scale, well above the background's 24–28).
fn visible(pixels: &[[u8; 3]]) -> usize {
    pixels.iter().filter(|c| c.iter().any(|&v| v >= 64)).count()
}

/// Pixels in the diverging map's negative (blue) half: blue well above red.
fn blue(pixels: &[[u8; 3]]) -> usize {
    pixels
        .iter()
        .filter(|c| c[2] >= 96 && i32::from(c[2]) > i32::from(c[0]) + 40)
        .count()
}

#[test]
fn clipping_rules_off_show_the_glow_and_the_negative_light() {
    let Some(mut h) = lab((1000.0, 700.0), maximised(PanelId::Clipping)) else {
        return;
    };
    let mut results = egui_kittest::SnapshotResults::new();
    // (c) of case 1: the light below the plane, with both rules on: black; (d) always.
    assert!(caption(&h, "(c) LTC, both rules").ends_with("black"));
    let d = h.query_all_by_label_contains("(d) BRDF").next().unwrap();
    assert!(
        d.value().unwrap_or_default().ends_with("black"),
        "the exact BRDF never lights from below"
    );
    h.get_by_label_contains("case 1 rule").click();
    settle(&mut h);
    // One set of rules: the panel's checkbox is the lab's.
    assert!(!h.state().lab().rules().clipping.case1);
    // The glow, ~1/400 of the lit plane, exposed to itself: its factor printed, and a
    // visible patch, not a dot: more than 2.4% of the picture's pixels on the screen (500 of
    // its 192×108), where the glow covers about 7%.
    let glow = caption(&h, "(c) LTC, rules: transformed");
    let factor: f64 = glow
        .rsplit('×')
        .next()
        .and_then(|f| f.parse().ok())
        .unwrap_or_else(|| panic!("no factor in '{glow}'"));
    assert!(factor > 50.0, "exposure ×{factor}");
    let pixels = picture_pixels(&mut h, "figure2-case1", 2);
    let seen = visible(&pixels);
    assert!(
        seen * 1000 > 24 * pixels.len(),
        "only {seen} of {} pixels show the glow",
        pixels.len()
    );
    h.snapshot_options("clipping_case1_glow", &options(1000 * 700));
    results.extend_harness(&mut h);
    h.get_by_label_contains("case 1 rule").click();
    h.get_by_label_contains("case 2 rule").click();
    settle(&mut h);
    assert!(
        caption(&h, "(c) LTC, rules: horizon").ends_with("black"),
        "the glow did not vanish"
    );
    // Case 2's (c): negative light, exposed to its own peak in the diverging map's blue.
    let negative = h
        .query_all_by_label_contains("(c) LTC, rules: horizon")
        .map(|n| n.value().unwrap_or_default())
        .find(|c| c.contains('−'))
        .expect("no negative light");
    assert!(
        negative.contains("all negative") || negative.contains(" −×"),
        "{negative}"
    );
    // More than a tenth of the picture (2000 of its 192×108), where the negative light
    // covers about a third.
    let pixels = picture_pixels(&mut h, "figure2-case2", 2);
    let blues = blue(&pixels);
    assert!(
        blues * 10 > pixels.len(),
        "only {blues} of {} pixels show the negative light",
        pixels.len()
    );
    // The same rule on in case 1: nothing negative, nothing blue.
    assert_eq!(blue(&picture_pixels(&mut h, "figure2-case1", 2)), 0);
    h.snapshot_options("clipping_case2_negative", &options(1000 * 700));
    results.extend_harness(&mut h);
    results.unwrap();
}

#[test]
fn the_clipping_case_map_is_the_cpu_classification() {
    let mut state = maximised(PanelId::Clipping);
    state.clipping.clip_scene = ClipScene::Case2;
    let Some(mut h) = lab((1000.0, 700.0), state) else {
        return;
    };
    let (w, hgt) = ltc_lab::app::clipping::rows::PICTURE;
    let setup = h.state().state().clipping.setup;
    let lut = &h.state().lab().tables().a().lut;
    let mut counts = Vec::new();
    for which in [ClipScene::Case1, ClipScene::Case2] {
        let scene = setup.scene(which, which);
        let reference = ltc_lab::cpu::cases::clip_counts_map(&scene, lut, w, hgt);
        let mut per_class = [0usize; 4];
        for c in reference
            .iter()
            .flatten()
            .filter_map(ltc_lab::cpu::cases::ClipCounts::class)
        {
            per_class[c.index()] += 1;
        }
        counts.push(per_class);
    }
    // The legend says each class's count, as the CPU classifies the pixels.
    for (row, per_class) in ["case map of case 1", "case map of case 2"]
        .iter()
        .zip(&counts)
    {
        assert!(shows(&h, row));
        for (k, case) in ClipCase::ALL.into_iter().enumerate() {
            let said = format!("{} {}", case.name(), per_class[k]);
            assert!(
                h.query_all_by_label(&said).count() >= 1,
                "no '{said}' in the legend"
            );
        }
    }
    // Case 1's light lifts part of the plane, case 2's pushes most of it below.
    assert!(counts[0][1] > 0);
    assert!(counts[1][2] > w * hgt / 4);
    h.snapshot_options("clipping_case_map", &options(1000 * 700));
    h.run_steps(1);
}

#[test]
fn dragging_on_a_clipping_picture_draws_the_profiles_line() {
    let Some(mut h) = lab((1200.0, 800.0), maximised(PanelId::Clipping)) else {
        return;
    };
    // Case 2's picture (b), from its upper left to its lower right quarter.
    let rect = h.get_by_label("figure2-case2 picture 1").rect();
    let start = rect.min + rect.size() * egui::vec2(0.2, 0.3);
    let end = rect.min + rect.size() * egui::vec2(0.8, 0.7);
    drag_along(&mut h, start, end);
    h.run_steps(2);
    assert_eq!(h.state().state().clipping.clip_scene, ClipScene::Case2);
    // The line is drawn over every picture of the row, where it was dragged: a quarter of
    // the way along it, on picture (a), a pixel of its yellow (255, 240, 80).
    let other = h.get_by_label("figure2-case2 picture 0").rect();
    let on_line = other.min + other.size() * egui::vec2(0.35, 0.4);
    let image = h.render().unwrap();
    let yellow = (-2..=2)
        .flat_map(|dx| (-2..=2).map(move |dy| (dx, dy)))
        .any(|(dx, dy)| {
            let p = image.get_pixel(
                (on_line.x as i32 + dx) as u32,
                (on_line.y as i32 + dy) as u32,
            );
            p[0] > 200 && p[1] > 180 && p[2] < 140
        });
    assert!(yellow, "no line through {on_line:?}");
}

/// The clipping panel shows one light's error by elevation band at the lab's (θo, α), with
/// the lab's rules and the panel's table, as the library measures it; a change of α
/// measures again.
#[test]
fn the_clipping_panel_gives_the_error_by_elevation_at_the_labs_view() {
    use ltc_lab::measure::horizon::band_errors_at;
    let Some(mut h) = lab((1200.0, 1100.0), maximised(PanelId::Clipping)) else {
        return;
    };
    let said = |h: &Harness<'static, LabApp>, alpha: f64| {
        let lab = h.state().lab();
        let at = (lab.lobe_view().theta_o_deg, alpha);
        let lut = &lab.tables().a().lut;
        let b = band_errors_at(
            lut,
            &ltc_lab::render::LtcRules::default(),
            at,
            ltc_lab::app::clipping::elevation::CASES,
            ltc_lab::measure::horizon::SEED,
        )[0];
        let text = format!(
            "0–5°: {:.0}% (energy ×{:.2})",
            100.0 * b.specular,
            b.specular_energy
        );
        h.query_by_label(&text).is_some()
    };
    let alpha = h.state().lab().alpha();
    assert!(said(&h, alpha), "the 0–5° band's error is not shown");
    slide(&mut h, "α", 0.6);
    settle(&mut h);
    assert!(said(&h, 0.6), "not measured again at the new α");
    assert!(shows(&h, "at θo = 45.0°, α = 0.6000"));
}

/// The side panel's horizon choice shades with a remedy, as a user picks it: with exact-band
/// the clipping panel's 0–5° band is exact; constrained-fit makes table A the constrained
/// table (the remedy is that table), and eq30 gives the classic table back.
#[test]
fn the_horizon_choice_shades_with_a_remedy() {
    use ltc_lab::ltc::remedy::{Horizon, HorizonRule};
    let Some(mut h) = lab((1400.0, 1100.0), maximised(PanelId::Clipping)) else {
        return;
    };
    let choose = |h: &mut Harness<'static, LabApp>, name: &str| {
        h.get_by_label("horizon").click();
        h.run_steps(2);
        h.get_by_label(name).click();
        settle(h);
    };
    choose(&mut h, "exact-band");
    assert_eq!(h.state().lab().rules().horizon, HorizonRule::ExactBand);
    assert!(
        h.query_by_label("0–5°: 0% (energy ×1.00)").is_some(),
        "the 0–5° band is not exact under exact-band"
    );
    choose(&mut h, "constrained-fit");
    let lab = h.state().lab();
    assert_eq!(
        (lab.rules().horizon, lab.horizon_remedy()),
        (HorizonRule::Eq30, Horizon::ConstrainedFit)
    );
    assert!(lab.tables().a().name.contains("constrained"));
    choose(&mut h, "eq30");
    assert!(h.state().lab().tables().a().name.contains("classic"));
    assert_eq!(h.state().lab().horizon_remedy(), Horizon::Eq30);
}

/// The rect view under the pictures: a rect across the horizon clipped at the surface's
/// horizon and, mapped by M^-1, at the cosine's, with ∫ D over it by the lab's rules as the
/// library computes it; turning case 1 off lets part of the rect below the surface through
/// (ltc_code's leak), which the view reads out and the rules' value then includes.
#[test]
fn the_clipping_panel_clips_a_rect_at_both_horizons() {
    use ltc_lab::app::clipping::polygon::{radiances, readings, shown_lobe, shown_polygon};
    use ltc_lab::app::lab::TableId;
    let Some(mut h) = lab((1200.0, 1100.0), maximised(PanelId::Clipping)) else {
        return;
    };
    // Below the pictures: scrolled to, as a user does, then opened.
    h.get_by_label("rect clipping: P and M^-1 P").scroll_to_me();
    h.run_steps(4);
    h.get_by_label("rect clipping: P and M^-1 P").click();
    settle(&mut h);
    h.run_steps(4);
    h.query_all_by_label_contains("by the lab's rules")
        .next()
        .expect("the view opened")
        .scroll_to_me();
    h.run_steps(2);
    let said = |h: &Harness<'static, LabApp>| {
        let lab = h.state().lab();
        let (corners, pinned) = shown_polygon(lab.lobe_view());
        assert!(!pinned, "no pixel is pinned: the leaning rect");
        let ltc = shown_lobe(lab, TableId::A);
        let r = readings(&ltc, &corners, lab.rules().clipping);
        let first = h
            .query_all_by_label_contains(&format!("{:.4} by the lab's rules", r[0]))
            .next()
            .is_some();
        let second = shows(
            h,
            &format!(
                "unclipped (signed): {:.4} · proxy (ltc-proxy): {:.4} · case 1 off adds {:.4} (the leak)",
                r[1], r[2], r[3]
            ),
        );
        (first && second, r)
    };
    let (ok, on) = said(&h);
    assert!(ok, "the readings with both rules on are not shown");
    // The lobe's radiance from the rect by the exact integral and each method, as the library
    // computes it: finite, the exact one lit, and said.
    let shown_radiances = |h: &Harness<'static, LabApp>| {
        let lab = h.state().lab();
        let (corners, _) = shown_polygon(lab.lobe_view());
        let r = radiances(lab, TableId::A, &corners);
        assert!(r.iter().all(|x| x.is_finite()) && r[0] > 0.0, "{r:?}");
        let text = format!("exact {:.4} · ltc-polygon {:.4}", r[0], r[1]);
        assert!(shows(h, &text), "not shown: {text}");
        r
    };
    let with_case1 = shown_radiances(&h);
    assert!(
        on[3] > 0.0,
        "the rect across the horizon leaks with case 1 off: {on:?}"
    );
    h.get_by_label_contains("case 1 rule").click();
    settle(&mut h);
    let (ok, off) = said(&h);
    assert!(ok, "the readings with case 1 off are not shown");
    assert!(
        (off[0] - (on[0] + on[3])).abs() <= 1e-12 * off[0],
        "case 1 off: the rules' value is the clipped one plus the leak"
    );
    // The exact integral does not see the rules; ltc-polygon gains the leak.
    let without = shown_radiances(&h);
    assert_eq!(without[0], with_case1[0]);
    assert!(without[1] > with_case1[1]);
}
