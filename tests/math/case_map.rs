//! The four-class case map (`cpu::cases::clip_counts_map`) against a classification read off the
//! rules themselves: a light is visible where both one-rule evaluations agree and are
//! positive, case 1 where only the horizon rule removes it, case 2 where only the transformed
//! rule removes it (and without it, it is negative), and "stays below" where either removes
//! it — pixel by pixel, for the three Figure-2 scenes and many lights.

use glam::DVec3;
use ltc_lab::cpu::LtcPixel;
use ltc_lab::cpu::cases::clip_counts_map;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::ltc::{ClipCase, Clipping, Ltc, Normalization};
use ltc_lab::render::LtcRules;
use ltc_lab::scene::{Scene, preset};

/// A lobe's case from what `ltc_eval` returns with one rule at a time.
fn case_from_rules(ltc: &Ltc, l: DVec3) -> ClipCase {
    let n = Normalization::Corrected;
    let horizon_only = ltc.ltc_eval(l, Clipping::CASE1, n);
    let transformed_only = ltc.ltc_eval(l, Clipping::CASE2, n);
    match (horizon_only, transformed_only) {
        (h, t) if h > 0.0 && t > 0.0 => ClipCase::Visible,
        (h, t) if h == 0.0 && t > 0.0 => ClipCase::Lifted,
        (h, t) if h < 0.0 && t == 0.0 => ClipCase::PushedBelow,
        (h, t) if h == 0.0 && t == 0.0 => ClipCase::StaysBelow,
        other => panic!("no case gives {other:?}"),
    }
}

/// The pixel's class as the case map paints it, from the rules: an artifact of either lobe
/// first (case 1, then case 2), then visible, then "stays below".
fn reference_class(
    scene: &Scene,
    lut: &Lut,
    x: usize,
    y: usize,
    w: usize,
    h: usize,
) -> Option<ClipCase> {
    let p = scene.surface_point(x, y, w, h)?;
    let px = LtcPixel::new(lut, &scene.material.gloss(), p.view, &LtcRules::default());
    let cases: Vec<ClipCase> = scene
        .lights
        .iter()
        .flat_map(|light| {
            let l = px
                .frame
                .tangent_from_world(DVec3::from(light.position) - p.position)
                .normalize();
            [
                case_from_rules(&px.pair.spec, l),
                case_from_rules(&px.pair.diff, l),
            ]
        })
        .collect();
    [
        ClipCase::Lifted,
        ClipCase::PushedBelow,
        ClipCase::Visible,
        ClipCase::StaysBelow,
    ]
    .into_iter()
    .find(|c| cases.contains(c))
}

#[test]
fn the_case_map_agrees_with_the_rules_pixel_by_pixel() {
    let lut = Lut::embedded();
    let (w, h) = (96, 54);
    let mut seen = std::collections::HashSet::new();
    for name in [
        "figure2-normal",
        "figure2-case1",
        "figure2-case2",
        "paper-100",
    ] {
        let scene = preset(name);
        let map = clip_counts_map(&scene, lut, w, h);
        for y in 0..h {
            for x in 0..w {
                let ours = map[y * w + x].and_then(|c| c.class());
                let reference = reference_class(&scene, lut, x, y, w, h);
                assert_eq!(ours, reference, "{name} pixel ({x}, {y})");
                seen.extend(ours);
            }
        }
    }
    // The scenes exercise all four classes, so that none of the arms above went untested.
    assert_eq!(seen.len(), 4, "classes seen: {seen:?}");
}
