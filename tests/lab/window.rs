//! The window as a whole: every panel's snapshot, the layout at three sizes, the notices bar,
//! the side panel's files (a light typed and saved, a broken table, a table that survives a
//! restart, files dropped on the window), and a scene larger than the adapter shades.

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use egui_kittest::{Harness, SnapshotResults};
use ltc_lab::app::lab::{Part, SideB};
use ltc_lab::app::{LabApp, LabState, PanelId};
use ltc_lab::gpu::renderer::PlaneRenderer;
use ltc_lab::ltc::lut::{Lut, Table};
use ltc_lab::render::View;

use crate::gpu_common;
use crate::harness::{
    drop_file, lab, maximised, notice, options, settle, shows, type_into, unsettled, with_lights,
};

#[test]
fn snapshot_of_every_panel() {
    let Some(mut all) = lab((1600.0, 900.0), LabState::default()) else {
        return;
    };
    let mut results = SnapshotResults::new();
    all.snapshot_options("lab_all", &options(1600 * 900));
    results.extend_harness(&mut all);
    // Below the grid's minimum the panels go under tabs.
    let mut small = lab((1024.0, 640.0), LabState::default()).unwrap();
    assert!(
        small.query_by_label("Matrix and LUT").is_some(),
        "no tabs at 1024×640"
    );
    // Two tables compared: the plane's tab says so, as its frame does.
    small.get_by_label("A | B tables").click();
    small.run_steps(2);
    let title = "Plane: table A (classic) | table B (point)";
    assert_eq!(
        small.query_all_by_label(title).count(),
        2,
        "the tab and the frame name both tables"
    );
    small.get_by_label("LTC | BRDF").click();
    settle(&mut small);
    small.snapshot_options("layout_1024x640", &options(1024 * 640));
    results.extend_harness(&mut small);
    let mut matrix = lab((900.0, 760.0), maximised(PanelId::Matrix)).unwrap();
    matrix.snapshot_options("matrix_heatmaps_colorbars", &options(900 * 760));
    results.extend_harness(&mut matrix);
    // The chart opens with the bundled reference study (measured with `ltc-lab study`).
    let mut chart = lab((900.0, 560.0), maximised(PanelId::Chart)).unwrap();
    let m = chart.state().state().chart.measurement;
    assert!(m.is_some_and(|m| !m.points.is_empty() && !m.scaling.is_empty()));
    chart.snapshot_options("chart_measured", &options(900 * 560));
    results.extend_harness(&mut chart);
    for id in PanelId::GRID {
        let mut h = lab((800.0, 500.0), maximised(id)).unwrap();
        h.snapshot_options(format!("lab_{id:?}").to_lowercase(), &options(800 * 500));
        results.extend_harness(&mut h);
    }
    // Two tables compared: the classic table (A) against the point fit (B), as the
    // difference map, with the lobe and matrix panels showing both.
    let mut state = LabState::default();
    state.lab.side_b = Part::new(SideB::TableB);
    state.plane.view = View::Diff;
    let mut tables = lab((1600.0, 900.0), state).unwrap();
    tables.snapshot_options("lab_tables", &options(1600 * 900));
    results.extend_harness(&mut tables);
    results.unwrap();
}

#[test]
fn moving_alpha_changes_the_matrix_and_the_plane() {
    let Some(mut h) = lab((1600.0, 900.0), LabState::default()) else {
        return;
    };
    let lab_of = |h: &Harness<'static, LabApp>| {
        let lab = h.state().lab();
        (
            lab.alpha(),
            lab.ltc_pair(&lab.tables().a().lut).spec.cos_from_brdf,
        )
    };
    let (before_alpha, before_matrix) = lab_of(&h);
    let before_plane = crate::harness::plane_image(&mut h);
    // The matrix panel's own line ("specular lobe at θo = …, α = …"), not the lobe panel's.
    let shown = |h: &Harness<'static, LabApp>, a: f64| shows(h, &format!(", α = {a:.4} (r = "));
    assert!(shown(&h, before_alpha));
    let slider = h.get_by_role_and_label(Role::Slider, "α");
    slider.focus();
    h.run_steps(1);
    for _ in 0..5 {
        h.key_press(egui::Key::ArrowRight);
    }
    settle(&mut h);
    let (alpha, matrix) = lab_of(&h);
    assert!(
        alpha > before_alpha,
        "α did not move: {before_alpha} → {alpha}"
    );
    assert_ne!(matrix, before_matrix, "the matrix did not change");
    assert!(
        shown(&h, alpha) && !shown(&h, before_alpha),
        "the matrix panel does not show the new α"
    );
    let after_plane = crate::harness::plane_image(&mut h);
    let changed = before_plane
        .pixels
        .iter()
        .zip(&after_plane.pixels)
        .filter(|(a, b)| a != b)
        .count();
    assert!(
        changed > before_plane.pixels.len() / 4,
        "only {changed} plane pixels changed"
    );
}

#[test]
fn a_broken_lut_file_is_reported_and_the_lab_keeps_its_table() {
    let Some(mut h) = lab((1600.0, 900.0), LabState::default()) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let broken = dir.path().join("broken.exr");
    std::fs::write(&broken, b"not an exr").unwrap();
    type_into(&mut h, "table file", &broken.display().to_string());
    h.get_by_label("use LUT").click();
    h.run_steps(2);
    let m = notice(&h).expect("a message");
    assert!(m.is_error && m.text.contains("broken.exr"), "{}", m.text);
    assert_eq!(&h.state().lab().tables().a().lut, Lut::embedded());
    assert!(
        shows(&h, "still using the previous table"),
        "not shown in the window"
    );
    // A good table is taken, and the plane renders with it.
    let good = dir.path().join("small.exr");
    ltc_lab::ltc::fit::fit_table(
        &ltc_lab::ltc::fit::FitSettings {
            size: 4,
            ..Default::default()
        },
        &|| {},
    )
    .lut
    .write(&good)
    .unwrap();
    type_into(&mut h, "table file", &good.display().to_string());
    h.get_by_label("use LUT").click();
    h.run_steps(3);
    assert_eq!(h.state().lab().tables().a().lut.size, 4);
    assert!(!notice(&h).unwrap().is_error);
}

/// A scene with more lights than the adapter shades is cut to the adapter's limit in the
/// scene too, not only on the slider, and the window says so (`lab --lights 100000` on
/// lavapipe kept 100 000 lights behind a slider at 65 024 and showed a black plane).
#[test]
fn more_lights_than_the_adapter_shades_are_cut_and_said() {
    let Some(g) = gpu_common::gpu() else { return };
    let max = PlaneRenderer::max_lights(&g.ctx);
    if max >= ltc_lab::scene::MAX_LIGHTS {
        gpu_common::skipped("this adapter shades every light a scene may hold");
        return;
    }
    let mut state = maximised(PanelId::Chart);
    with_lights(&mut state, max + 1);
    let mut h = unsettled((800.0, 500.0), state);
    assert_eq!(h.state().lab().lights().list.len(), max);
    h.run_steps(2);
    assert!(
        shows(&h, &format!("the first {max} are kept")),
        "the cut is not said in the window"
    );
    assert!(
        shows(&h, &format!("at most {max} lights: this adapter's limit")),
        "the slider's limit is not said beside it"
    );
}

/// A table used from a file is named as table A everywhere and survives a restart: after
/// *use LUT* with an ltc.js, "classic" stayed lit, and after a restart the classic table
/// shaded while the field still showed ltc.js. A file gone since is said, not silently lost.
#[test]
fn a_table_from_a_file_is_the_one_shown_and_survives_a_restart() {
    use egui_kittest::kittest::NodeT;
    use ltc_lab::ltc::formats::{self, Export, Header, dds::Precision};
    use ltc_lab::tables::Source;
    let Some(mut h) = lab((1600.0, 900.0), LabState::default()) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let js = dir.path().join("point.js");
    let point = Lut::shipped(Table::Point);
    let header = Header::new(point, "test", Some(Table::Point));
    formats::export(point, &header, Export::LtcCodeJs, Precision::F32, &js).unwrap();
    let selected = |h: &Harness<'static, LabApp>, label: &str| {
        // egui reports a selectable label's state as toggled.
        h.get_by_label(label).accesskit_node().toggled() == Some(egui::accesskit::Toggled::True)
    };
    assert!(selected(&h, "classic"));
    type_into(&mut h, "table file", &js.display().to_string());
    h.get_by_label("use LUT").click();
    h.run_steps(2);
    assert!(
        !selected(&h, "classic") && !selected(&h, "point"),
        "a shipped table still lit"
    );
    // Named in the side panel, and on the lobe panel's face without its directories.
    assert!(shows(&h, &format!("table A: {}", js.display())));
    assert!(shows(&h, "table A: point.js"));
    // The next start shades with the same file.
    let saved = h.state().state();
    let again = LabApp::new(saved.clone(), None);
    assert_eq!(
        again.lab().tables().a().lut,
        h.state().lab().tables().a().lut
    );
    assert_eq!(again.lab().tables().a().name, js.display().to_string());
    // Gone since: the shipped table shades, and the window says why.
    std::fs::remove_file(&js).unwrap();
    let saved: LabState = ron::from_str(&ron::to_string(&saved).unwrap()).unwrap();
    let lost = LabApp::new(saved, None);
    assert_eq!(&lost.lab().tables().a().lut, Lut::embedded());
    assert_eq!(
        lost.lab().tables().a().source,
        Source::Shipped(Table::Classic)
    );
    let m = lost.lab().message().expect("a message");
    assert!(
        m.is_error && m.text.contains("cannot be read again"),
        "{}",
        m.text
    );
    // Choosing a shipped table lights it again and forgets the file.
    h.get_by_label("point").click();
    h.run_steps(2);
    assert!(selected(&h, "point"));
    assert_eq!(
        h.state().lab().tables().a().source,
        Source::Shipped(Table::Point)
    );
}

/// Notices appear where they move no control: a file's message at the top of the side panel
/// pushed every control below it down, under the pointer. It can be dismissed.
#[test]
fn a_notice_moves_no_control() {
    let Some(mut h) = lab((1600.0, 900.0), LabState::default()) else {
        return;
    };
    let before = (
        h.get_by_label("use LUT").rect(),
        h.get_by_label("screenshot").rect(),
    );
    type_into(&mut h, "table file", "/nonexistent/ltc.js");
    h.get_by_label("use LUT").click();
    h.run_steps(2);
    assert!(shows(&h, "still using the previous table"), "no notice");
    let after = (
        h.get_by_label("use LUT").rect(),
        h.get_by_label("screenshot").rect(),
    );
    assert_eq!(after, before, "a control moved");
    h.get_by_label("×").click();
    h.run_steps(2);
    assert!(
        !shows(&h, "still using the previous table"),
        "not dismissed"
    );
}

/// A light can be placed by typing: the selected light has x, y, z fields (it could only be
/// dragged), and a saved scene writes its numbers rounded (a dragged light was saved with 16
/// decimals); the view becomes what the file holds.
#[test]
fn a_light_is_placed_by_typing_and_saved_rounded() {
    let mut state = maximised(PanelId::Lobe);
    state.lab.selection = Part::new(ltc_lab::app::lab::Selection { light: Some(3) });
    let Some(mut h) = lab((1600.0, 900.0), state) else {
        return;
    };
    let field = h.get_by_role_and_label(Role::SpinButton, "y");
    field.focus();
    h.run_steps(1);
    h.get_by_role_and_label(Role::SpinButton, "y")
        .type_text("0.5");
    h.key_press(egui::Key::Enter);
    h.run_steps(2);
    // Typed over the old value's selected text: the field holds what was typed.
    assert_eq!(h.state().lab().lights().list[3].position[1], 0.5);
    h.get_by_role_and_label(Role::SpinButton, "x")
        .set_value_accesskit(0.123_456_789_012_345);
    h.run_steps(2);
    assert_eq!(
        h.state().lab().lights().list[3].position[0],
        0.123_456_789_012_345
    );
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.toml");
    type_into(&mut h, "scene file", &path.display().to_string());
    h.get_by_label("save").click();
    h.run_steps(2);
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.contains("0.1235"), "not rounded: {text}");
    assert!(!text.contains("0.123456"), "16 decimals saved");
    let saved = ltc_lab::scene::Scene::load(&path).unwrap();
    assert_eq!(
        saved,
        h.state().lab().scene(),
        "the view is not what the file holds"
    );
}

/// The layout scales with the window: at 3840×2160 egui's zoom doubles (1 up to 1920×1080),
/// so pictures and text grow instead of floating small in empty space. Snapshots at the
/// three sizes the lab is tried at (1024×640 is `layout_1024x640`).
#[test]
fn the_layout_scales_with_the_window() {
    let Some(mut hd) = lab((1920.0, 1080.0), LabState::default()) else {
        return;
    };
    assert_eq!(hd.ctx.zoom_factor(), 1.0);
    // A 3840×2160 window, as eframe shows it: once zoomed, its size in points halves
    // (kittest keeps a harness's size in points, so the test does what the window does).
    let mut uhd = unsettled((1920.0, 1080.0), LabState::default());
    // The window resized to 3840×2160: one frame at that size fits the zoom; from then on
    // the window is that many pixels, i.e. half as many points.
    uhd.set_size(egui::vec2(3840.0, 2160.0));
    // The zoom is set in one frame and applies from the next, which still has the old size
    // in points (as a window's does, for a frame).
    uhd.step();
    uhd.step();
    let zoom = uhd.ctx.zoom_factor();
    assert_eq!(zoom, 2.0);
    uhd.set_size(egui::vec2(3840.0, 2160.0) / zoom);
    settle(&mut uhd);
    assert_eq!(uhd.ctx.zoom_factor(), 2.0, "the zoom did not settle");
    // The same widget, about twice as large in pixels: its rect in points times the zoom.
    let pixels = |h: &Harness<'static, LabApp>| {
        h.get_by_label("lobe view").rect().width() * h.ctx.zoom_factor()
    };
    assert!(
        pixels(&uhd) > 1.8 * pixels(&hd),
        "the lobe view did not grow: {} → {} px",
        pixels(&hd),
        pixels(&uhd)
    );
    let mut results = SnapshotResults::new();
    hd.snapshot_options("layout_1920x1080", &options(1920 * 1080));
    results.extend_harness(&mut hd);
    uhd.snapshot_options("layout_3840x2160", &options(3840 * 2160));
    results.extend_harness(&mut uhd);
    results.unwrap();
}

/// A file dropped on the window is taken for what its name says (app/file_io.rs): a scene
/// replaces the lab's, a table becomes table A, and a file the lab does not read is refused
/// by name, changing nothing.
#[test]
fn files_dropped_on_the_window_are_taken() {
    let Some(mut h) = lab((1000.0, 700.0), LabState::default()) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let scene_file = dir.path().join("dropped.toml");
    let mut scene = ltc_lab::scene::preset("paper-100");
    scene.material.alpha = 0.77;
    scene.lights.truncate(3);
    std::fs::write(&scene_file, scene.to_toml()).unwrap();
    drop_file(&mut h, &scene_file);
    assert_eq!(h.state().lab().scene(), scene);
    let said = |h: &Harness<'static, LabApp>| notice(h).unwrap();
    assert!(!said(&h).is_error && said(&h).text.contains("dropped.toml"));

    let table = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("luts/ltc_point.exr");
    drop_file(&mut h, &table);
    assert!(h.state().lab().tables().a().name.ends_with("ltc_point.exr"));

    let notes = dir.path().join("notes.txt");
    std::fs::write(&notes, "not a scene").unwrap();
    drop_file(&mut h, &notes);
    assert!(
        said(&h).is_error && said(&h).text.contains("notes.txt"),
        "{:?}",
        said(&h)
    );
    assert_eq!(h.state().lab().scene(), scene);
    settle(&mut h);
}
