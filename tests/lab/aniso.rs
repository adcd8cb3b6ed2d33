//! Anisotropic GGX in the lab (docs/design.md §1.13, §2.9): one α until the material is made
//! anisotropic, then α_x, α_y and the tangent; the lobe, matrix and clipping panels on its
//! 4D table; the 4D tables picked per side; the brushed presets on the plane.

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use ltc_lab::app::PanelId;
use ltc_lab::app::lab::TableId;
use ltc_lab::ltc::aniso::AnisoAxes;
use ltc_lab::ltc::aniso::source::AnisoSource;

use crate::harness::{lab, maximised, plane_image, press, settle, shows, slide};

/// The side panel shows one roughness slider while the material is isotropic; the checkbox
/// brings α_x, α_y and the tangent, and the lobe panel's header follows (φo, both 4D tables).
#[test]
fn anisotropic_controls_appear_with_the_checkbox() {
    let Some(mut h) = lab((1280.0, 720.0), maximised(PanelId::Lobe)) else {
        return;
    };
    assert!(h.query_by_role_and_label(Role::Slider, "α").is_some());
    assert!(h.query_by_role_and_label(Role::Slider, "α_y").is_none());
    h.get_by_role_and_label(Role::CheckBox, "anisotropic")
        .click();
    settle(&mut h);
    let m = **h.state().lab().material();
    assert!(m.is_anisotropic(), "{m:?}");
    for label in ["α_x", "α_y", "tangent (°)", "φo (°)"] {
        assert!(
            h.query_by_role_and_label(Role::Slider, label).is_some(),
            "no {label} slider"
        );
    }
    slide(&mut h, "α_y", 0.05);
    slide(&mut h, "φo (°)", 30.0);
    settle(&mut h);
    assert_eq!(h.state().lab().material().roughness().y, 0.05);
    assert!(shows(&h, "φo = 30.0°"), "the lobe panel's header");
    assert!(shows(&h, "4D table A: lab, B: i3d-alphax-alphay"));
    // Off again: one α, the material isotropic as before.
    h.get_by_role_and_label(Role::CheckBox, "anisotropic")
        .click();
    settle(&mut h);
    assert!(!h.state().lab().material().is_anisotropic());
}

/// The matrix panel slices the 4D tables and shows both tables' error maps; picking another
/// 4D table for A in the side panel changes what A shades with.
#[test]
fn matrix_panel_slices_both_4d_tables_and_the_side_panel_picks_them() {
    // Tall enough that the side panel's table rows are in view without scrolling.
    let Some(mut h) = lab((1280.0, 1200.0), maximised(PanelId::Matrix)) else {
        return;
    };
    press(&mut h, "brushed-rect");
    settle(&mut h);
    assert!(h.state().lab().material().is_anisotropic());
    for map in ["lab 4D error map", "i3d-alphax-alphay 4D error map"] {
        assert!(h.query_by_label(map).is_some(), "no {map}");
    }
    assert!(
        h.query_by_role_and_label(Role::Slider, "α_y / α_x")
            .is_some()
    );
    // The first row of 4D tables is A's.
    h.get_all_by_label("i3d-alpha-lambda")
        .next()
        .unwrap()
        .click();
    settle(&mut h);
    let tables = h.state().lab().tables();
    assert_eq!(
        tables.aniso(TableId::A),
        &AnisoSource::I3d(AnisoAxes::I3dAlphaLambda)
    );
    assert!(h.query_by_label("i3d-alpha-lambda 4D error map").is_some());
}

/// The brushed rect preset draws a streak: the plane's image differs from the same scene
/// isotropic at α_x, far beyond rounding (the parity of its LTC and exact sides is
/// tests/gpu/aniso.rs's).
#[test]
fn the_brushed_rect_preset_streaks_the_plane() {
    let Some(mut h) = lab((640.0, 400.0), maximised(PanelId::Plane)) else {
        return;
    };
    press(&mut h, "brushed-rect");
    settle(&mut h);
    let brushed = plane_image(&mut h);
    h.get_by_role_and_label(Role::CheckBox, "anisotropic")
        .click();
    settle(&mut h);
    let round = plane_image(&mut h);
    let (mut diff, mut total) = (0.0, 0.0);
    for (a, b) in brushed.pixels.iter().zip(&round.pixels) {
        diff += (*a - *b).abs().element_sum();
        total += b.abs().element_sum();
    }
    // A brushed highlight moves most of the rect's reflection: over a tenth of the image's
    // energy, where rounding moves a millionth.
    assert!(diff > 0.1 * total, "diff {diff} of {total}");
}
