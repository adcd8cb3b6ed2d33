//! Rect lights in the lab (docs/design.md §1.11): a failure preset loaded from the side panel,
//! each side's rect method chosen there and rendered, the pinned pixel's rects by every rect
//! method and one shown on the lobe panel from its row, and a rect's width dragged, checked where it
//! enters.

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use ltc_lab::app::PanelId;
use ltc_lab::app::lab::{Lights, Part, Selection};
use ltc_lab::colormap::short_number;
use ltc_lab::light::Shape;
use ltc_lab::light::rect::RectMethod;
use ltc_lab::metrics::luminance;
use ltc_lab::pixel::pixel_terms;
use ltc_lab::scene::preset;

use crate::harness::{click_at, lab, load_sized_preset, maximised, settle, shows};

#[test]
fn a_rect_preset_is_shaded_by_each_sides_rect_method() {
    let Some(mut h) = lab((1000.0, 800.0), maximised(PanelId::Plane)) else {
        return;
    };
    load_sized_preset(&mut h, "rect-horizon");
    let lights = &h.state().lab().lights().list;
    assert!(lights.iter().all(|l| matches!(l.shape, Shape::Rect { .. })));
    assert_eq!(
        [
            h.state().lab().shape_forms().ltc.get::<RectMethod>(),
            h.state().lab().shape_forms().brdf.get::<RectMethod>()
        ],
        [RectMethod::LtcPolygon, RectMethod::Exact]
    );
    // The LTC side's method, picked from its list as a user does.
    h.get_by_label("rect LTC side").click();
    h.run_steps(2);
    h.get_by_label(RectMethod::LtcProxyFast.name()).click();
    settle(&mut h);
    assert_eq!(
        h.state().lab().shape_forms().ltc.get::<RectMethod>(),
        RectMethod::LtcProxyFast
    );
    // The split names each side's rect method under its name (spheres and disks: none here).
    let names = ltc_lab::app::plane::sized_side_names(
        h.state().lab(),
        &h.state().state().plane,
        ("LTC", "BRDF"),
    );
    assert_eq!(
        names,
        (
            "LTC\nrect: ltc-proxy-fast".to_string(),
            "BRDF\nrect: exact".to_string()
        )
    );
}

#[test]
fn the_pinned_pixel_gives_each_rect_by_every_method() {
    let Some(mut h) = lab((1000.0, 800.0), maximised(PanelId::Plane)) else {
        return;
    };
    load_sized_preset(&mut h, "rect-ceiling");
    let image = h.get_by_label("plane image").rect();
    click_at(&mut h, image.center());
    settle(&mut h);
    assert!(shows(&h, "rect lights, by each method"));
    let lab_ = h.state().lab();
    let [u, v] = h.state().state().plane.pinned.expect("a pixel pinned");
    let [w, hgt] = h.state().report().plane_size.expect("a render");
    let scene = lab_.shaded_scene();
    let p = scene
        .surface_point_at(u * w as f64, v * hgt as f64, w, hgt)
        .unwrap();
    let t = pixel_terms(
        &scene,
        (&lab_.tables().a().lut, None),
        &p,
        lab_.rules(),
        (&lab_.shape_forms().ltc, &lab_.shape_forms().brdf),
    )
    .unwrap();
    // The ceiling's cell by the clipped polygon: its value and its error against the exact
    // integral, as `pixel_terms` has them at the pinned pixel.
    let by = |m| t.terms[0].by(m).expect("the preset's light is a rect");
    let (polygon, exact) = (
        luminance(by(RectMethod::LtcPolygon)),
        luminance(by(RectMethod::Exact)),
    );
    assert!(exact > 0.0);
    let cell = format!(
        "{} ({:+.1}%)",
        short_number(polygon),
        100.0 * (polygon - exact) / exact
    );
    assert!(h.query_all_by_label(&cell).count() > 0, "no cell '{cell}'");
    // What the row's number hands the lobe panel (the paper's Figure 1: P over the lobe,
    // M^-1 P over the cosine): the rect's corners as the pixel sees them, unit directions in
    // its shading frame, whose centre is the row's ω.
    let corners = t.terms[0].corners.expect("a rect's corners");
    let mean: glam::DVec3 = corners.iter().sum();
    assert!(corners.iter().all(|c| (c.length() - 1.0).abs() < 1e-12));
    assert!(mean.normalize().dot(t.terms[0].omega) > 0.9, "{corners:?}");
    // The row's number hands them over, and again takes them off.
    h.get_by_role_and_label(Role::Button, "0").click();
    h.run_steps(2);
    let shown = h
        .state()
        .lab()
        .lobe_view()
        .polygon
        .expect("the rect on the lobe");
    for (shown, seen) in shown.iter().zip(corners) {
        assert!(glam::DVec3::from(*shown).distance(seen) < 1e-12);
    }
    h.get_by_role_and_label(Role::Button, "0").click();
    h.run_steps(2);
    assert_eq!(h.state().lab().lobe_view().polygon, None);
}

#[test]
fn a_rects_width_is_dragged_along_its_edge_and_checked() {
    // The lab starts from this state as stored (RON): rects survive it, as they once did not.
    let mut state = maximised(PanelId::Plane);
    state.lab.selection = Part::new(Selection { light: Some(0) });
    state.lab.lights = Part::new(Lights {
        list: preset("rect-ceiling").lights,
        seed: 0,
    });
    let Some(mut h) = lab((1000.0, 800.0), state) else {
        return;
    };
    let Shape::Rect { half_u, half_v } = h.state().lab().lights().list[0].shape else {
        panic!("a rect");
    };
    h.get_by_role_and_label(Role::SpinButton, "w")
        .set_value_accesskit(1.0);
    settle(&mut h);
    let Shape::Rect {
        half_u: u,
        half_v: v,
    } = h.state().lab().lights().list[0].shape
    else {
        panic!("still a rect");
    };
    // Its width is 1 along the same edge; its height and orientation stay.
    assert!((2.0 * u.length() - 1.0).abs() < 1e-12, "{u:?}");
    assert!(u.normalize().dot(half_u.normalize()) > 1.0 - 1e-12);
    assert_eq!(v, half_v);
}
