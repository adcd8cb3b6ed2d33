//! The lobe panel.

use egui_kittest::kittest::Queryable;
use ltc_lab::app::PanelId;
use ltc_lab::app::lab::{LobeView, Part};

use crate::harness::{lab, maximised, options, shows};

#[test]
fn the_lobe_difference_at_80_degrees_shows_the_gap() {
    let mut state = maximised(PanelId::Lobe);
    state.lab.lobe_view = Part::new(LobeView {
        theta_o_deg: 80.0,
        ..LobeView::default()
    });
    state.lab.material = Part::new(ltc_lab::scene::Material {
        alpha: 0.6,
        ..Default::default()
    });
    state.lobe.colour_difference = true;
    let Some(mut h) = lab((800.0, 600.0), state) else {
        return;
    };
    h.snapshot_options("lobe_difference_80deg", &options(800 * 600));
    let view = h.get_by_label("lobe view").rect();
    let image = h.render().expect("a rendered frame");
    // Inside the sphere's view only (the colour bar under it holds both halves of the map):
    // both signs of the difference show in the diverging map's hues, not its dark centre —
    // orange: red well above blue with some green (the red arrow, (255, 0, 0), has none);
    // blue: blue well above red — each over thousands of pixels, where the arrows cover a
    // few hundred. The bug drew a sphere of the centre colour (26, 26, 31): neither.
    let inside = |x: u32, y: u32| view.contains(egui::pos2(x as f32 + 0.5, y as f32 + 0.5));
    let (mut orange, mut blue) = (0, 0);
    for (x, y, p) in image.enumerate_pixels() {
        if !inside(x, y) {
            continue;
        }
        let [r, g, b] = [p[0], p[1], p[2]].map(i32::from);
        orange += usize::from(r > 80 && r > b + 40 && g >= 20);
        blue += usize::from(b > 80 && b > r + 40);
    }
    assert!(orange > 2000 && blue > 2000, "orange {orange}, blue {blue}");
}

/// The lobe panel says on its face what it shows (θo, α, the table), so that a picture of it
/// taken with the controls folded still has its parameters.
#[test]
fn the_lobe_panel_prints_its_parameters_on_its_face() {
    let mut state = maximised(PanelId::Lobe);
    state.lab.lobe_view = Part::new(LobeView {
        theta_o_deg: 47.0,
        ..LobeView::default()
    });
    state.window.controls_hidden = true;
    let Some(h) = lab((900.0, 600.0), state) else {
        return;
    };
    let alpha = h.state().lab().alpha();
    let face = format!("θo = 47.0°   α = {alpha:.4}   table A: classic");
    assert!(shows(&h, &face), "no '{face}' on the lobe panel");
}
