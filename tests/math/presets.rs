//! The shipped scene presets: they load, hold what their names promise, and the case-2
//! preset's light placement is the one the documented search over the LUT finds.

use std::path::Path;

use ltc_lab::cpu::cases::{ClipCounts, clip_counts_map};
use ltc_lab::cpu::render;
use ltc_lab::ltc::Clipping;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::metrics::luminance_range;
use ltc_lab::render::{Method, RenderSettings};
use ltc_lab::scene::Scene;

fn preset(name: &str) -> Scene {
    Scene::load(
        &Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("assets/scenes")
            .join(name),
    )
    .unwrap()
}

#[test]
fn paper_100_has_100_lights_at_alpha_0_27() {
    let s = preset("paper-100.toml");
    assert_eq!(s.lights.len(), 100);
    assert_eq!(s.material.alpha, 0.27);
    let h = s.plane.half_size;
    assert!(
        s.lights
            .iter()
            .all(|l| l.position[0].abs() <= h && l.position[1].abs() <= h && l.position[2] > 0.0)
    );
}

#[test]
fn figure2_presets_place_the_paper_light() {
    let normal = preset("figure2-normal.toml");
    assert_eq!(normal.lights.len(), 1);
    assert_eq!(normal.lights[0].position, [0.0, 0.0, 1.0]);
    assert_eq!(normal.material.alpha, 0.5);
    let case1 = preset("figure2-case1.toml");
    assert_eq!(case1.lights[0].position, [0.0, 0.0, -0.158731]);
    assert_eq!(case1.material.alpha, 0.5);
}

/// The negative light of case 2 relative to the lit plane: the most negative luminance over
/// the brightest, rendered on the CPU without the case-2 rule.
fn negative_ratio(s: &Scene, lut: &Lut, (w, h): (usize, usize)) -> (f64, usize) {
    let mut r = RenderSettings::single(w, h, Method::Ltc);
    r.rules.clipping = Clipping::CASE1;
    let range = luminance_range(&render(s, lut, &r));
    (-range.min / range.max, range.negative)
}

/// A coarser grid than `examples/case2_search.rs` (whose search the preset documents): the
/// preset must still be its optimum.
fn case2_search(base: &Scene, lut: &Lut) -> (f64, [f64; 3]) {
    let mut best = (0.0, 0.0, [0.0; 3]);
    for alpha in [0.2, 0.5, 1.0] {
        for y in [-2.0, 0.0, 2.0] {
            for z in [0.01, 0.1, 0.4] {
                let mut s = base.clone();
                s.material.alpha = alpha;
                s.lights[0].position = [0.0, y, z];
                let (ratio, _) = negative_ratio(&s, lut, (48, 27));
                if ratio > best.0 {
                    best = (ratio, alpha, [0.0, y, z]);
                }
            }
        }
    }
    (best.1, best.2)
}

#[test]
fn figure2_case2_is_the_search_optimum_and_its_negative_light_is_visible() {
    let s = preset("figure2-case2.toml");
    let lut = Lut::embedded();
    assert_eq!(
        case2_search(&s, lut),
        (s.material.alpha, s.lights[0].position),
        "the preset is not the search's optimum"
    );
    // The preset's comment: −0.99% of the lit plane's peak, on 59% of the plane (96×54).
    // Half a percent is 500× the old placement's 1e-5 and visible in an 8-bit picture
    // exposed to the negative part alone; a third of the plane makes it a region, not a dot.
    let (ratio, negative) = negative_ratio(&s, lut, (96, 54));
    assert!(
        ratio > 0.005,
        "negative peak only {ratio:.2e} of the lit plane"
    );
    assert!(negative > 96 * 54 / 3, "only {negative} negative pixels");
    let counts = clip_counts_map(&s, lut, 64, 64)
        .into_iter()
        .flatten()
        .fold(ClipCounts::default(), std::ops::Add::add);
    assert_eq!(
        counts.lifted + counts.stays_below,
        0,
        "the light is above the whole plane"
    );
    assert!(counts.pushed_below > 64 * 64 / 3, "{counts:?}");
}
