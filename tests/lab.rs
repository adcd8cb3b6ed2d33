//! The lab under egui_kittest with the wgpu renderer (lavapipe in CI): a snapshot of every
//! panel, and interactions checked on values, not only on pictures.

mod gpu_common;

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use egui_kittest::{Harness, SnapshotOptions, SnapshotResults};
use ltc_lab::app::{LabApp, LabState, PanelId};
use ltc_lab::render::View;

/// A harness showing the lab at `size`, with the live GPU times hidden (they change run to
/// run), or `None` (loudly) without an adapter.
fn lab(size: (f32, f32), state: LabState) -> Option<Harness<'static, LabApp>> {
    gpu_common::gpu()?;
    let mut app = LabApp::new(state);
    app.plane.hide_timings = true;
    let mut harness = Harness::builder()
        .with_size(egui::vec2(size.0, size.1))
        .wgpu()
        .build_ui_state(|ui, app: &mut LabApp| app.show(ui), app);
    harness.run_steps(4);
    Some(harness)
}

/// lavapipe renders bit-identically run to run; the threshold (kittest's default colour
/// distance) and 0.2% of the pixels absorb antialiasing changes of another Mesa version,
/// while a blank, garbled or re-laid-out panel changes far more than that.
fn options(pixels: usize) -> SnapshotOptions {
    SnapshotOptions::new().max_failed_pixels(pixels / 500)
}

#[test]
fn snapshot_of_every_panel() {
    let Some(mut all) = lab((1200.0, 700.0), LabState::default()) else {
        return;
    };
    let mut results = SnapshotResults::new();
    all.snapshot_options("lab_all", &options(1200 * 700));
    results.extend_harness(&mut all);
    for id in PanelId::ALL {
        let state = LabState {
            maximised: Some(id),
            ..LabState::default()
        };
        let mut h = lab((800.0, 500.0), state).unwrap();
        h.snapshot_options(format!("lab_{id:?}").to_lowercase(), &options(800 * 500));
        results.extend_harness(&mut h);
    }
    results.unwrap();
}

#[test]
fn moving_alpha_changes_the_matrix_and_the_plane() {
    let Some(mut h) = lab((1200.0, 700.0), LabState::default()) else {
        return;
    };
    let before_alpha = h.state().state.alpha();
    let before_matrix = h.state().state.ltc_pair(&h.state().lut).spec.cos_from_brdf;
    let before_plane = h
        .state()
        .plane
        .frame
        .clone()
        .expect("the plane was rendered");
    assert!(
        h.query_by_label_contains(&format!("α = {before_alpha:.4}"))
            .is_some()
    );
    let slider = h.get_by_role_and_label(Role::Slider, "α");
    slider.focus();
    h.run_steps(1);
    for _ in 0..5 {
        h.key_press(egui::Key::ArrowRight);
    }
    h.run_steps(3);
    let app = h.state();
    assert!(
        app.state.alpha() > before_alpha,
        "α did not move: {} → {}",
        before_alpha,
        app.state.alpha()
    );
    assert_ne!(
        app.state.ltc_pair(&app.lut).spec.cos_from_brdf,
        before_matrix,
        "the matrix did not change"
    );
    let shown = |a: f64| h.query_by_label_contains(&format!("α = {a:.4}")).is_some();
    assert!(
        shown(app.state.alpha()) && !shown(before_alpha),
        "the matrix panel does not show the new α"
    );
    let after_plane = h.state().plane.frame.as_ref().unwrap();
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
fn clicking_a_heat_map_cell_selects_it() {
    let state = LabState {
        maximised: Some(PanelId::Matrix),
        ..LabState::default()
    };
    let Some(mut h) = lab((1000.0, 800.0), state) else {
        return;
    };
    let rect = h.get_by_label("spec.norm heat map").rect();
    // Cell (i, j) = (10, 50) of 64: its centre, in the map's pixels.
    let at = rect.min + (egui::vec2(10.5, 50.5) / 64.0) * rect.size();
    h.hover_at(at);
    h.run_steps(1);
    h.event(egui::Event::PointerButton {
        pos: at,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: Default::default(),
    });
    h.run_steps(1);
    h.event(egui::Event::PointerButton {
        pos: at,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: Default::default(),
    });
    h.run_steps(3);
    let app = h.state();
    let lut = &app.lut;
    assert_eq!(app.state.alpha(), lut.alpha(10));
    assert!((app.state.theta_o_deg - lut.theta_o(50).to_degrees()).abs() < 1e-9);
    assert_eq!(app.matrix.current_cell, (10, 50));
}

#[test]
fn case_1_rule_off_makes_the_glow_appear() {
    let state = LabState {
        maximised: Some(PanelId::Clipping),
        ..LabState::default()
    };
    let Some(mut h) = lab((1000.0, 700.0), state) else {
        return;
    };
    // (c): the light below the plane, with both rules on: black.
    assert_eq!(h.state().clipping.picture_energy(2), 0.0);
    assert_eq!(
        h.state().clipping.picture_energy(3),
        0.0,
        "the exact BRDF never lights from below"
    );
    h.get_by_label_contains("case 1 rule").click();
    h.run_steps(3);
    assert!(!h.state().state.clip_panel.horizon);
    let glow = h.state().clipping.picture_energy(2);
    assert!(glow > 0.0, "no glow without the horizon rule");
    assert_eq!(h.state().clipping.picture_energy(3), 0.0);
    h.get_by_label_contains("case 1 rule").click();
    h.run_steps(3);
    assert_eq!(
        h.state().clipping.picture_energy(2),
        0.0,
        "the glow did not vanish"
    );
}

#[test]
fn dragging_the_divider_moves_it() {
    let state = LabState {
        maximised: Some(PanelId::Plane),
        view: View::Split,
        ..LabState::default()
    };
    let Some(mut h) = lab((1000.0, 700.0), state) else {
        return;
    };
    let rect = h.get_by_label("plane image").rect();
    let start = egui::pos2(
        rect.min.x + rect.width() * 0.5,
        rect.center().y + 0.25 * rect.height(),
    );
    let end = egui::pos2(rect.min.x + rect.width() * 0.25, start.y);
    h.drag_at(start);
    h.run_steps(1);
    for k in 1..=10 {
        h.hover_at(start + (end - start) * (k as f32 / 10.0));
        h.run_steps(1);
    }
    h.drop_at(end);
    h.run_steps(3);
    let divider = h.state().state.divider;
    assert!((divider - 0.25).abs() < 0.02, "divider at {divider}");
    let frame = h.state().plane.frame.as_ref().unwrap();
    let expected = (frame.width as f64 * divider).round() as usize;
    assert_eq!(
        frame.divider,
        Some(expected),
        "the rendered split follows the divider"
    );
}

#[test]
fn refit_runs_the_fitter_live_and_the_lobe_panel_follows() {
    let state = LabState {
        maximised: Some(PanelId::Matrix),
        ..LabState::default()
    };
    let Some(mut h) = lab((1000.0, 700.0), state) else {
        return;
    };
    h.get_by_label("refit this cell").click();
    h.run_steps(2);
    let ctx = h.ctx.clone();
    h.state_mut().matrix.wait_for_refit(&ctx);
    h.run_steps(2);
    let app = h.state();
    let refit = app.matrix.refit.as_ref().expect("a refit ran");
    assert_eq!(refit.cell, app.matrix.current_cell);
    // Nelder–Mead keeps its best point: the best objective never rises.
    let best: Vec<f64> = refit.history.iter().map(|p| p[1]).collect();
    assert!(best.len() > 5, "only {} iterations reported", best.len());
    assert!(
        best.windows(2).all(|w| w[1] <= w[0]),
        "the best objective rose"
    );
    assert!(best.last() < best.first(), "the objective did not fall");
    let (lobe, ltc) = app
        .matrix
        .refit_ltc()
        .expect("the lobe panel gets the refitted lobe");
    assert_eq!(lobe, app.state.lobe);
    assert!(ltc.det_cos_from_brdf.is_finite() && ltc.det_cos_from_brdf > 0.0);
}

#[test]
fn a_broken_lut_file_is_reported_and_the_lab_keeps_its_table() {
    let Some(mut h) = lab((1200.0, 700.0), LabState::default()) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let broken = dir.path().join("broken.exr");
    std::fs::write(&broken, b"not an exr").unwrap();
    h.state_mut().state.lut_path = broken.display().to_string();
    h.run_steps(1);
    h.get_by_label("use LUT").click();
    h.run_steps(2);
    let m = h.state().message.clone().expect("a message");
    assert!(m.is_error && m.text.contains("broken.exr"), "{}", m.text);
    assert_eq!(&h.state().lut, ltc_lab::ltc::lut::Lut::embedded());
    assert!(
        h.query_by_label_contains("still using the previous table")
            .is_some(),
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
    h.state_mut().state.lut_path = good.display().to_string();
    h.run_steps(1);
    h.get_by_label("use LUT").click();
    h.run_steps(3);
    assert_eq!(h.state().lut.size, 4);
    assert!(!h.state().message.as_ref().unwrap().is_error);
}

#[test]
fn the_chart_reads_a_study_csv_and_reports_a_bad_row() {
    let state = LabState {
        maximised: Some(PanelId::Chart),
        ..LabState::default()
    };
    let Some(mut h) = lab((1000.0, 600.0), state) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("study.csv");
    std::fs::write(&good, format!("{}\nltc,0.27,100,320,180,on,2,25.3,0.23,1.06e-2,1.9e-1,4.2e-2\nbrdf,0.27,100,320,180,on,2,27.8,0.21,0,0,0\n", ltc_lab::study::StudyRow::CSV_HEADER)).unwrap();
    h.state_mut().chart.study_path = good.display().to_string();
    h.run_steps(1);
    h.get_by_label("load study").click();
    h.run_steps(2);
    let m = h
        .state()
        .chart
        .measurement
        .clone()
        .expect("the study was read");
    assert_eq!(m.points.len(), 2);
    assert_eq!(
        (
            m.points[0].label.as_str(),
            m.points[0].ms,
            m.points[0].rel_rmse
        ),
        ("ltc", 25.3, 1.06e-2)
    );
    let bad = dir.path().join("bad.csv");
    std::fs::write(
        &bad,
        format!(
            "{}\nltc,0.27,100,320,180,on,2,nan,0.23,1e-2,1e-1,1e-2\n",
            ltc_lab::study::StudyRow::CSV_HEADER
        ),
    )
    .unwrap();
    h.state_mut().chart.study_path = bad.display().to_string();
    h.run_steps(1);
    h.get_by_label("load study").click();
    h.run_steps(2);
    let e = h.state().chart.error.clone().expect("an error");
    assert!(e.contains("bad.csv line 2"), "{e}");
    assert!(
        h.query_by_label_contains("bad.csv line 2").is_some(),
        "the error is not shown in the window"
    );
}

#[test]
fn the_table_switch_shades_with_the_point_fit_and_both_fits_are_shown() {
    let state = LabState {
        maximised: Some(PanelId::Matrix),
        ..LabState::default()
    };
    let Some(mut h) = lab((1100.0, 700.0), state) else {
        return;
    };
    assert!(
        h.query_by_label_contains("classic fit: M^-1").is_some()
            && h.query_by_label_contains("point fit: M^-1").is_some()
    );
    assert_eq!(&h.state().lut, ltc_lab::ltc::lut::Lut::embedded());
    h.get_by_label("point").click();
    h.run_steps(3);
    assert_eq!(h.state().state.table, ltc_lab::ltc::lut::Table::Point);
    assert_eq!(&h.state().lut, ltc_lab::ltc::lut::Lut::embedded_point());
}
