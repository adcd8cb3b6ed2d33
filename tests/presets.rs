//! The shipped scene presets: they load, hold what their names promise, and the case-2
//! preset's light placement is the one the documented search over the LUT finds.

use std::path::Path;

use ltc_lab::cpu::clip_counts_image;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::scene::{Light, Scene};

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

/// The search documented in `figure2-case2.toml`: one light of the preset's intensity on a
/// grid of positions in the plane x = 0 between the camera and the plane's far edge, scored
/// by how many pixels of a 64×64 view see it in clipping case 2.
fn case2_search(base: &Scene, lut: &Lut) -> ([f64; 3], usize) {
    let mut best = ([0.0; 3], 0);
    for iy in 0..=8 {
        let y = -2.0 + 0.5 * iy as f64;
        for z in [0.02, 0.05, 0.1, 0.2, 0.4] {
            let mut s = base.clone();
            s.lights = vec![Light {
                position: [0.0, y, z],
                ..base.lights[0]
            }];
            let n = clip_counts_image(&s, lut, 64, 64).pushed_below;
            if n > best.1 {
                best = ([0.0, y, z], n);
            }
        }
    }
    best
}

#[test]
fn figure2_case2_light_is_the_search_optimum_and_shows_case_2() {
    let s = preset("figure2-case2.toml");
    let lut = Lut::embedded();
    let (position, count) = case2_search(&s, lut);
    assert_eq!(
        s.lights[0].position, position,
        "the preset's light is not the search's optimum"
    );
    // A tenth of the plane's pixels at 64×64 (~1700 of them) shows the case clearly.
    assert!(count > 170, "only {count} pixels in case 2");
    let counts = clip_counts_image(&s, lut, 64, 64);
    assert_eq!(
        counts.below_horizon, 0,
        "the light is above the whole plane"
    );
}
