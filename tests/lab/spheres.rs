//! Lights with a size in the lab (docs/design.md §1.10): a failure preset loaded from the side
//! panel and the plane's map of its sphere cases against the CPU's classification, the pinned
//! pixel's lights by every sphere method, a light's own radius checked where it enters, and
//! the clipping panel's sphere over its elevation.

use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ltc_lab::app::lab::Selection;
use ltc_lab::app::{LabApp, PanelId};
use ltc_lab::colormap::short_number;
use ltc_lab::cpu::cases::sphere_case_map;
use ltc_lab::light::Shape;
use ltc_lab::light::sphere::SphereMethod;
use ltc_lab::light::sphere::cap::SphereCase;
use ltc_lab::metrics::luminance;
use ltc_lab::pixel::pixel_terms;
use ltc_lab::scene::MIN_RADIUS;

use crate::harness::{click_at, lab, maximised, notice, settle, shows, slide};

fn open_sized_section(h: &mut Harness<'static, LabApp>) {
    h.get_by_label("lights with a size").click();
    h.run_steps(2);
}

#[test]
fn a_failure_preset_shows_its_sphere_cases_on_the_plane() {
    let Some(mut h) = lab((1000.0, 700.0), maximised(PanelId::Plane)) else {
        return;
    };
    // Point lights: the map is not offered.
    assert!(h.query_by_label("sphere cases").is_none());
    open_sized_section(&mut h);
    h.get_by_label("sphere-horizon").click();
    settle(&mut h);
    assert!(
        h.state()
            .lab()
            .lights()
            .list
            .iter()
            .all(|l| matches!(l.shape, Shape::Sphere { .. }))
    );
    h.get_by_label("sphere cases").click();
    settle(&mut h);
    // The legend's shares are the CPU's classification at the map's size (a quarter).
    let [w, hgt] = h.state().report().plane_size.expect("a render");
    let scene = h.state().lab().shaded_scene();
    let cases = sphere_case_map(&scene, w.div_ceil(4), hgt.div_ceil(4));
    let total = cases.iter().flatten().count();
    assert!(total > 0);
    for case in SphereCase::ALL {
        let n = cases.iter().filter(|&&c| c == Some(case)).count();
        let share = format!("{} {:.0}%", case.name(), 100.0 * n as f64 / total as f64);
        assert!(shows(&h, &share), "no '{share}'");
    }
    // Every plane point sees a sphere the plane cuts as cut, or is inside it.
    assert!(cases.contains(&Some(SphereCase::Cut)) && cases.contains(&Some(SphereCase::Inside)));
    assert!(!cases.contains(&Some(SphereCase::Above)));
}

#[test]
fn the_pinned_pixel_gives_each_sized_light_by_every_method() {
    let Some(mut h) = lab((1000.0, 700.0), maximised(PanelId::Plane)) else {
        return;
    };
    open_sized_section(&mut h);
    h.get_by_label("sphere-black-spots").click();
    settle(&mut h);
    let rect = h.get_by_label("plane image").rect();
    click_at(&mut h, rect.center());
    settle(&mut h);
    assert!(shows(&h, "lights with a size, by each method"));
    for m in SphereMethod::ALL {
        let columns = h.query_all_by_label(m.name()).count();
        assert!(columns > 0, "no column {}", m.name());
    }
    // Each light's LTC disk cell: its value and its error against the exact integral, as
    // `pixel_terms` has them at the pinned pixel.
    let lab_ = h.state().lab();
    let [u, v] = h.state().state().plane.pinned.expect("a pixel pinned");
    let [w, hgt] = h.state().report().plane_size.expect("a render");
    let scene = lab_.shaded_scene();
    let p = scene
        .surface_point_at(u * w as f64, v * hgt as f64, w, hgt)
        .unwrap();
    let lut = &lab_.tables().a().lut;
    let t = pixel_terms(
        &scene,
        (lut, None),
        &p,
        lab_.rules(),
        (&lab_.shape_forms().ltc, &lab_.shape_forms().brdf),
    )
    .unwrap();
    for l in &t.terms {
        let by = |m| l.by(m).expect("every light of the preset has a size");
        let (disk, exact) = (
            luminance(by(SphereMethod::LtcDisk)),
            luminance(by(SphereMethod::Exact)),
        );
        let cell = format!(
            "{} ({:+.1}%)",
            short_number(disk),
            100.0 * (disk - exact) / exact.abs().max(1e-300)
        );
        assert!(h.query_all_by_label(&cell).count() > 0, "no cell '{cell}'");
    }
}

#[test]
fn a_lights_radius_is_checked_where_it_enters() {
    let mut state = maximised(PanelId::Plane);
    state.lab.selection = ltc_lab::app::lab::Part::new(Selection { light: Some(0) });
    let Some(mut h) = lab((1000.0, 700.0), state) else {
        return;
    };
    h.get_by_role_and_label(Role::SpinButton, "r")
        .set_value_accesskit(0.1);
    settle(&mut h);
    assert_eq!(
        h.state().lab().lights().list[0].shape,
        Shape::Sphere { radius: 0.1 }
    );
    // Below the smallest sphere: raised to it, and said with the field's name.
    h.get_by_role_and_label(Role::SpinButton, "r")
        .set_value_accesskit(1e-7);
    settle(&mut h);
    assert_eq!(
        h.state().lab().lights().list[0].shape,
        Shape::Sphere { radius: MIN_RADIUS }
    );
    let said = notice(&h).map(|m| m.text).unwrap_or_default();
    assert!(said.contains("lights[0].radius"), "{said}");
}

#[test]
fn the_clipping_panel_measures_a_sphere_over_its_elevation() {
    let Some(mut h) = lab((1100.0, 800.0), maximised(PanelId::Clipping)) else {
        return;
    };
    slide(&mut h, "sphere σ (°)", 10.0);
    settle(&mut h);
    assert!(shows(&h, "a sphere of σ = 10.0°"));
    // Each band gives each method's error against the exact integral.
    // Each band gives each method's error against the exact integral: a line per band
    // naming the three.
    for band in ["0–5°:", "5–15°:", "15–30°:", "30–90°:"] {
        assert!(shows(&h, band), "{band}");
    }
    for m in ["ltc-point", "ltc-disk", "representative-point"] {
        let lines = h.query_all_by_label_contains(m).count();
        assert!(lines >= 4, "{m} in {lines} lines");
    }
}
