//! The search behind `assets/scenes/figure2-case2.toml`: one light over the plane, placed and
//! with α chosen so that case 2's negative light is as large as it can be relative to the lit
//! plane, rendered on the CPU without the case-2 rule (`--clip horizon`).
//!
//! `cargo run --release --example case2_search`

use ltc_lab::cpu::render;
use ltc_lab::ltc::Clipping;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::metrics::luminance_range;
use ltc_lab::render::{Method, RenderSettings};
use ltc_lab::scene::preset;

fn main() {
    let base = preset("figure2-case2");
    let lut = Lut::embedded();
    let mut results = Vec::new();
    for alpha in [0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0] {
        for iy in 0..=16 {
            let y = -2.0 + 0.25 * iy as f64;
            for z in [0.01, 0.02, 0.05, 0.1, 0.2, 0.4, 0.8] {
                for x in [0.0, 0.5, 1.0] {
                    let mut s = base.clone();
                    s.material.alpha = alpha;
                    s.lights[0].position = [x, y, z];
                    let mut r = RenderSettings::single(96, 54, Method::Ltc);
                    r.rules.clipping = Clipping::CASE1;
                    let r = luminance_range(&render(&s, lut, &r));
                    results.push((-r.min / r.max, alpha, [x, y, z], r.min, r.max, r.negative));
                }
            }
        }
    }
    results.sort_by(|a, b| b.0.total_cmp(&a.0));
    for r in results.iter().take(25) {
        println!(
            "ratio {:.3e} alpha {} pos {:?} min {:.3e} max {:.3e} neg px {}",
            r.0, r.1, r.2, r.3, r.4, r.5
        );
    }
}
