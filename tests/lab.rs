//! The lab under egui_kittest with the wgpu renderer (lavapipe in CI): a snapshot of every
//! panel, and interactions checked on values, not only on pictures.

mod gpu_common;

use egui::accesskit::Role;
use egui_kittest::kittest::Queryable;
use std::time::{Duration, Instant};

use egui_kittest::wgpu::WgpuTestRenderer;
use egui_kittest::{Harness, SnapshotOptions, SnapshotResults};
use gpu_common::bits;
use ltc_lab::app::clip_rows::expose;
use ltc_lab::app::lab::Shared;
use ltc_lab::app::plane::PlaneState;
use ltc_lab::app::state::WindowState;
use ltc_lab::app::{Aspect, Compare, LabApp, LabState, PanelId};
use ltc_lab::gpu::plane::ShaderChecks;
use ltc_lab::gpu::renderer::PlaneRenderer;
use ltc_lab::render::{Frame, View};

/// A harness showing the lab at `size`, drawing with the same wgpu device the lab renders on
/// (as eframe's window does), with the live GPU times hidden (they change run to run) and
/// its render finished; or `None` (loudly) without an adapter.
fn lab(size: (f32, f32), state: LabState) -> Option<Harness<'static, LabApp>> {
    gpu_common::gpu()?;
    let mut harness = unsettled(size, state);
    settle(&mut harness);
    Some(harness)
}

/// The same, its first frames run and its work not waited for (the caller has checked that
/// there is an adapter).
fn unsettled(size: (f32, f32), mut state: LabState) -> Harness<'static, LabApp> {
    let render_state = egui_kittest::wgpu::create_render_state(
        ltc_lab::app::shading::wgpu_setup(),
        egui_wgpu::RendererOptions::PREDICTABLE,
    );
    // The live GPU times change run to run: off, as a user would for a slide.
    state.plane.show_gpu_times = false;
    let app = LabApp::new(state, Some(&render_state));
    assert!(app.lab.gpu.is_some(), "{}", app.lab.describe_device());
    Harness::builder()
        .with_size(egui::vec2(size.0, size.1))
        .renderer(WgpuTestRenderer::from_render_state(render_state))
        .build_ui_state(|ui, app: &mut LabApp| app.show(ui), app)
}

/// Runs frames until nothing is in flight (the plane summed, a refit or measurement done).
/// Five minutes is far beyond any of these tests' renders on lavapipe (seconds): only a
/// render that never completes reaches it.
fn settle(h: &mut Harness<'static, LabApp>) {
    let start = Instant::now();
    h.run_steps(2);
    while h.state().busy() {
        assert!(
            start.elapsed() < Duration::from_secs(300),
            "the lab never settled: {}",
            h.state().plane.shading.progress.describe()
        );
        h.step();
        std::thread::sleep(Duration::from_millis(1));
    }
    h.run_steps(2);
}

/// A primary click at `at`, as a pointer would: move there, press, release.
fn click_at(h: &mut Harness<'static, LabApp>, at: egui::Pos2) {
    h.hover_at(at);
    h.run_steps(1);
    for pressed in [true, false] {
        h.event(egui::Event::PointerButton {
            pos: at,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: Default::default(),
        });
        h.run_steps(1);
    }
}

/// A press at `start`, ten moves to `end` a frame each, and the release there.
fn drag_along(h: &mut Harness<'static, LabApp>, start: egui::Pos2, end: egui::Pos2) {
    h.drag_at(start);
    h.run_steps(1);
    for k in 1..=10 {
        h.hover_at(start + (end - start) * (k as f32 / 10.0));
        h.run_steps(1);
    }
    h.drop_at(end);
}

/// The plane's finished image, read back from the lab's device (the read never waits: it
/// is asked for again until the copy has landed).
fn plane_image(h: &mut Harness<'static, LabApp>) -> Frame {
    for _ in 0..10_000 {
        if let Some(frame) = h.state_mut().plane.shading.read() {
            return frame;
        }
        assert!(
            h.state().plane.shading.read_pending(),
            "the plane's render is complete"
        );
        std::thread::sleep(std::time::Duration::from_millis(1));
    }
    panic!("the plane's image never came back");
}

/// lavapipe renders bit-identically run to run; the threshold (kittest's default colour
/// distance) and 0.2% of the pixels absorb antialiasing changes of another Mesa version,
/// while a blank, garbled or re-laid-out panel changes far more than that.
fn options(pixels: usize) -> SnapshotOptions {
    SnapshotOptions::new().max_failed_pixels(pixels / 500)
}

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
    assert!(
        chart
            .state()
            .chart
            .state
            .measurement
            .as_ref()
            .is_some_and(|m| !m.points.is_empty() && !m.scaling.is_empty())
    );
    chart.snapshot_options("chart_measured", &options(900 * 560));
    results.extend_harness(&mut chart);
    for id in PanelId::ALL {
        let mut h = lab((800.0, 500.0), maximised(id)).unwrap();
        h.snapshot_options(format!("lab_{id:?}").to_lowercase(), &options(800 * 500));
        results.extend_harness(&mut h);
    }
    // Two tables compared: the classic table (A) against the point fit (B), as the
    // difference map, with the lobe and matrix panels showing both.
    let mut tables = lab(
        (1600.0, 900.0),
        LabState {
            lab: Shared {
                compare: Compare::TableB,
                ..Shared::default()
            },
            plane: PlaneState {
                view: View::Diff,
                ..PlaneState::default()
            },
            ..LabState::default()
        },
    )
    .unwrap();
    tables.snapshot_options("lab_tables", &options(1600 * 900));
    results.extend_harness(&mut tables);
    results.unwrap();
}

#[test]
fn moving_alpha_changes_the_matrix_and_the_plane() {
    let Some(mut h) = lab((1600.0, 900.0), LabState::default()) else {
        return;
    };
    let before_alpha = h.state().lab.shared().alpha();
    let before_matrix = h
        .state()
        .lab
        .shared()
        .ltc_pair(&h.state().lab.tables().a.lut)
        .spec
        .cos_from_brdf;
    let before_plane = plane_image(&mut h);
    // The matrix panel's own line ("specular lobe at θo = …, α = …"), not the lobe panel's.
    let shown = |h: &Harness<'static, LabApp>, a: f64| {
        h.query_by_label_contains(&format!(", α = {a:.4} (r = "))
            .is_some()
    };
    assert!(shown(&h, before_alpha));
    let slider = h.get_by_role_and_label(Role::Slider, "α");
    slider.focus();
    h.run_steps(1);
    for _ in 0..5 {
        h.key_press(egui::Key::ArrowRight);
    }
    settle(&mut h);
    let app = h.state();
    assert!(
        app.lab.shared().alpha() > before_alpha,
        "α did not move: {} → {}",
        before_alpha,
        app.lab.shared().alpha()
    );
    assert_ne!(
        app.lab
            .shared()
            .ltc_pair(&app.lab.tables().a.lut)
            .spec
            .cos_from_brdf,
        before_matrix,
        "the matrix did not change"
    );
    assert!(
        shown(&h, app.lab.shared().alpha()) && !shown(&h, before_alpha),
        "the matrix panel does not show the new α"
    );
    let after_plane = plane_image(&mut h);
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
    let Some(mut h) = lab((1000.0, 1000.0), maximised(PanelId::Matrix)) else {
        return;
    };
    let rect = h.get_by_label("spec.norm heat map").rect();
    // Cell (i, j) = (10, 50) of 64: its centre, in the map's pixels.
    let at = rect.min + (egui::vec2(10.5, 50.5) / 64.0) * rect.size();
    click_at(&mut h, at);
    h.run_steps(3);
    let app = h.state();
    let lut = &app.lab.tables().a.lut;
    assert_eq!(app.lab.shared().alpha(), lut.alpha(10));
    assert!((app.lab.shared().theta_o_deg - lut.theta_o(50).to_degrees()).abs() < 1e-9);
    assert_eq!(app.lab.shared().nearest_cell(lut), (10, 50));
}

/// Total positive luminance of a clipping picture (row 0: case 1, row 1: case 2).
fn picture_energy(h: &Harness<'static, LabApp>, row: usize, k: usize) -> f64 {
    let f = &h.state().clipping.rows[row].thumbs[k].frame;
    f.pixels
        .iter()
        .map(|&p| ltc_lab::metrics::luminance(p).max(0.0))
        .sum()
}

/// Pixels of a shown picture bright enough to see on the dark panel (any channel ≥ 64/255:
/// a quarter of full scale, well above the background's 24–28).
fn visible_pixels(image: &egui::ColorImage) -> usize {
    image
        .pixels
        .iter()
        .filter(|c| c.r().max(c.g()).max(c.b()) >= 64)
        .count()
}

/// Pixels in the diverging map's negative (blue) half: blue well above red.
fn blue_pixels(image: &egui::ColorImage) -> usize {
    image
        .pixels
        .iter()
        .filter(|c| c.b() >= 96 && i32::from(c.b()) > i32::from(c.r()) + 40)
        .count()
}

#[test]
fn clipping_rules_off_show_the_glow_and_the_negative_light() {
    let Some(mut h) = lab((1000.0, 700.0), maximised(PanelId::Clipping)) else {
        return;
    };
    let mut results = SnapshotResults::new();
    // (c) of case 1: the light below the plane, with both rules on: black; (d) always.
    assert_eq!(picture_energy(&h, 0, 2), 0.0);
    assert_eq!(
        picture_energy(&h, 0, 3),
        0.0,
        "the exact BRDF never lights from below"
    );
    h.get_by_label_contains("case 1 rule").click();
    settle(&mut h);
    // One set of rules: the panel's checkbox is the lab's.
    assert!(!h.state().lab.shared().clipping.case1);
    assert!(
        picture_energy(&h, 0, 2) > 0.0,
        "no glow without the horizon rule"
    );
    assert_eq!(picture_energy(&h, 0, 3), 0.0);
    let glow = &h.state().clipping.rows[0].thumbs[2];
    // The glow, ~1/200 of the lit plane, exposed to itself: a visible patch, not a dot.
    assert!(glow.factor > 50.0, "exposure ×{}", glow.factor);
    let seen = visible_pixels(&expose(&glow.frame).image);
    assert!(seen > 500, "only {seen} visible pixels in the exposed glow");
    h.snapshot_options("clipping_case1_glow", &options(1000 * 700));
    results.extend_harness(&mut h);
    h.get_by_label_contains("case 1 rule").click();
    h.get_by_label_contains("case 2 rule").click();
    settle(&mut h);
    assert_eq!(picture_energy(&h, 0, 2), 0.0, "the glow did not vanish");
    let negative = &h.state().clipping.rows[1].thumbs[2];
    let min = negative
        .frame
        .pixels
        .iter()
        .map(|&p| ltc_lab::metrics::luminance(p))
        .fold(0.0, f64::min);
    assert!(
        min < 0.0 && negative.negative_factor.is_some(),
        "no negative light: {min}"
    );
    let blue = blue_pixels(&expose(&negative.frame).image);
    assert!(blue > 2000, "only {blue} pixels show the negative light");
    // The same rule on: nothing negative, nothing blue.
    let case1 = &h.state().clipping.rows[0].thumbs[2].frame;
    assert_eq!(blue_pixels(&expose(case1).image), 0);
    h.snapshot_options("clipping_case2_negative", &options(1000 * 700));
    results.extend_harness(&mut h);
    results.unwrap();
}

#[test]
fn the_clipping_case_map_is_the_cpu_classification() {
    let Some(mut h) = lab((1000.0, 700.0), {
        let mut state = maximised(PanelId::Clipping);
        state.clipping.clip_scene = ltc_lab::app::clip_setup::ClipScene::Case2;
        state
    }) else {
        return;
    };
    let app = h.state();
    let (w, hgt) = ltc_lab::app::clip_rows::PICTURE;
    for (r, which) in [
        ltc_lab::app::clip_setup::ClipScene::Case1,
        ltc_lab::app::clip_setup::ClipScene::Case2,
    ]
    .into_iter()
    .enumerate()
    {
        let scene = app.clipping.state.setup.scene(which, which);
        let reference = ltc_lab::cpu::clip_counts_map(&scene, &app.lab.tables().a.lut, w, hgt);
        let row = &app.clipping.rows[r];
        assert_eq!(row.case_map, reference, "{which:?}");
        let classified = reference
            .iter()
            .flatten()
            .filter(|c| c.class().is_some())
            .count();
        assert_eq!(row.class_counts.iter().sum::<usize>(), classified);
    }
    // Case 1's light lifts part of the plane, case 2's pushes most of it below.
    assert!(app.clipping.rows[0].class_counts[1] > 0);
    assert!(app.clipping.rows[1].class_counts[2] > w * hgt / 4);
    h.snapshot_options("clipping_case_map", &options(1000 * 700));
    h.run_steps(1);
}

#[test]
fn dragging_the_divider_moves_it() {
    let mut state = maximised(PanelId::Plane);
    state.plane.view = View::Split;
    let Some(mut h) = lab((1000.0, 700.0), state) else {
        return;
    };
    let rect = h.get_by_label("plane image").rect();
    let start = egui::pos2(
        rect.min.x + rect.width() * 0.5,
        rect.center().y + 0.25 * rect.height(),
    );
    let end = egui::pos2(rect.min.x + rect.width() * 0.25, start.y);
    drag_along(&mut h, start, end);
    settle(&mut h);
    let divider = h.state().plane.state.divider;
    assert!((divider - 0.25).abs() < 0.02, "divider at {divider}");
    let frame = plane_image(&mut h);
    let expected = (frame.width as f64 * divider).round() as usize;
    assert_eq!(
        frame.divider,
        Some(expected),
        "the rendered split follows the divider"
    );
}

#[test]
fn refit_runs_the_fitter_live_and_the_lobe_panel_follows() {
    let Some(mut h) = lab((1000.0, 700.0), maximised(PanelId::Matrix)) else {
        return;
    };
    // The classic table, refitted by the fitter that made it.
    h.get_by_label("ltc_code").click();
    h.run_steps(2);
    let app = h.state_mut();
    app.matrix.wait_for_refit(&mut app.lab);
    h.run_steps(2);
    let app = h.state();
    let refit = app.lab.shared().refit.as_ref().expect("a refit ran");
    assert_eq!(
        refit.cell,
        app.lab.shared().nearest_cell(&app.lab.tables().a.lut)
    );
    // Nelder–Mead keeps its best point: the best objective never rises.
    let best: Vec<f64> = refit.history.iter().map(|p| p[1]).collect();
    assert!(best.len() > 5, "only {} iterations reported", best.len());
    assert!(
        best.windows(2).all(|w| w[1] <= w[0]),
        "the best objective rose"
    );
    // The shipped table was made by this fitter with these settings, and the refit starts at
    // its cell. Nelder–Mead keeps its best vertex, so the result is the start or a point of
    // lower objective: near the minimum that is the level set of the start, whose distance
    // from the optimum is the f32 rounding of the stored entries (6e-8 relative) times at
    // most the square root of the objective's condition number. 1e-4 allows a condition
    // number of 1e6; a refit that wandered off, or a wrong cell, lands far outside it.
    for (row, stored) in refit.cos_from_brdf.iter().zip(&refit.stored) {
        for (x, y) in row.iter().zip(stored) {
            assert!(
                (x - y).abs() < 1e-4,
                "refit {row:?} against stored {stored:?}"
            );
        }
    }
    let (lobe, ltc) = app
        .lab
        .refit_ltc()
        .expect("the lobe panel gets the refitted lobe");
    assert_eq!(lobe, app.lab.shared().lobe);
    assert!(ltc.det_cos_from_brdf.is_finite() && ltc.det_cos_from_brdf > 0.0);
}

#[test]
fn the_worst_cell_refitted_by_the_point_objective_shows_both_matrices_and_errors() {
    let Some(mut h) = lab((1000.0, 900.0), maximised(PanelId::Matrix)) else {
        return;
    };
    h.get_by_label("worst cell of spec.err").click();
    h.run_steps(2);
    h.get_by_label("point L1").click();
    h.run_steps(2);
    let app = h.state_mut();
    app.matrix.wait_for_refit(&mut app.lab);
    settle(&mut h);
    let app = h.state();
    let r = app.lab.shared().refit.as_ref().expect("a refit ran");
    assert_eq!(
        r.cell,
        app.lab.shared().nearest_cell(&app.lab.tables().a.lut)
    );
    // Started from the stored cell and kept the best point by its own objective (a
    // quadrature of the same L1 integral the error estimates by strata): it may not end above
    // the stored error by more than tests/refit.rs allows a refit (5% of the albedo).
    assert!(
        r.error <= r.stored_error + 0.05,
        "{} vs {}",
        r.error,
        r.stored_error
    );
    for what in ["as stored", "refitted"] {
        let label = format!("cell ({}, {}) {what} (÷ middle)", r.cell.0, r.cell.1);
        assert!(h.query_by_label_contains(&label).is_some(), "no {label}");
    }
    let line = format!("refitted {:.2}%", 100.0 * r.error);
    assert!(h.query_by_label_contains(&line).is_some(), "no '{line}'");
    h.snapshot_options("matrix_refit_worst_cell", &options(1000 * 900));
}

#[test]
fn a_broken_lut_file_is_reported_and_the_lab_keeps_its_table() {
    let Some(mut h) = lab((1600.0, 900.0), LabState::default()) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let broken = dir.path().join("broken.exr");
    std::fs::write(&broken, b"not an exr").unwrap();
    h.state_mut().controls.state.lut_path = broken.display().to_string();
    h.run_steps(1);
    h.get_by_label("use LUT").click();
    h.run_steps(2);
    let m = h.state().lab.message.clone().expect("a message");
    assert!(m.is_error && m.text.contains("broken.exr"), "{}", m.text);
    assert_eq!(
        &h.state().lab.tables().a.lut,
        ltc_lab::ltc::lut::Lut::embedded()
    );
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
    h.state_mut().controls.state.lut_path = good.display().to_string();
    h.run_steps(1);
    h.get_by_label("use LUT").click();
    h.run_steps(3);
    assert_eq!(h.state().lab.tables().a.lut.size, 4);
    assert!(!h.state().lab.message.as_ref().unwrap().is_error);
}

#[test]
fn the_chart_reads_a_study_csv_and_reports_a_bad_row() {
    let Some(mut h) = lab((1000.0, 600.0), maximised(PanelId::Chart)) else {
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
        .state
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
    let Some(mut h) = lab((1100.0, 700.0), maximised(PanelId::Matrix)) else {
        return;
    };
    assert!(
        h.query_by_label_contains("A (classic): M^-1").is_some()
            && h.query_by_label_contains("B (point): M^-1").is_some()
    );
    assert_eq!(
        &h.state().lab.tables().a.lut,
        ltc_lab::ltc::lut::Lut::embedded()
    );
    h.get_by_label("point").click();
    h.run_steps(3);
    assert_eq!(
        h.state().lab.shared().table,
        ltc_lab::ltc::lut::Table::Point
    );
    assert_eq!(
        &h.state().lab.tables().a.lut,
        ltc_lab::ltc::lut::Lut::embedded_point()
    );
    // Table B follows: the other shipped table.
    assert_eq!(
        &h.state().lab.tables().b.lut,
        ltc_lab::ltc::lut::Lut::embedded()
    );
    assert!(
        h.query_by_label_contains("A (point): M^-1").is_some()
            && h.query_by_label_contains("B (classic): M^-1").is_some()
    );
}

/// The default state with panel `id` shown alone.
fn maximised(id: PanelId) -> LabState {
    LabState {
        window: WindowState {
            maximised: Some(id),
            ..WindowState::default()
        },
        ..LabState::default()
    }
}

/// The plane's state for the render tests: maximised, split (both methods shaded), a few
/// hundred lights so that the pacer, which starts at one light per chunk and at most doubles,
/// needs many frames.
fn plane_state(lights: usize) -> LabState {
    let mut state = maximised(PanelId::Plane);
    state.plane.view = View::Split;
    state.lab.set_light_count(lights);
    state
}

/// The same scene and settings rendered whole, in one submission, on the lab's own device.
fn one_shot(h: &Harness<'static, LabApp>) -> Frame {
    let app = h.state();
    let ctx = app.plane.shading.context().expect("the lab has a GPU");
    let settings = app.plane.shading.settings().expect("a render started");
    let mut r = PlaneRenderer::new(ctx, &app.lab.tables().a.lut, ShaderChecks::Checked).unwrap();
    let scene = app.lab.shared().shaded_scene();
    r.render(ctx, &scene, settings).unwrap().0
}

/// Summed over many frames in paced chunks, the plane is the one-shot render to the bit: the
/// same f32 operations in the same order, the sums kept exactly in between (as
/// tests/gpu_render.rs shows for hand-picked chunks; here the lab's pacer picks them).
#[test]
fn the_plane_summed_over_frames_is_the_one_shot_render() {
    let Some(mut h) = lab((900.0, 600.0), plane_state(300)) else {
        return;
    };
    let p = h.state().plane.shading.progress;
    assert!(p.complete() && p.total == 300, "{p:?}");
    // 1, 2, 4 … 256: at least nine chunks, whatever the chunks' times.
    assert!(p.frames >= 9, "summed in only {} frames", p.frames);
    let progressive = plane_image(&mut h);
    assert!(
        progressive.pixels.iter().any(|p| p.x > 0.0),
        "a black plane"
    );
    assert!(
        bits(&progressive) == bits(&one_shot(&h)),
        "the images differ"
    );
    assert!(
        h.query_by_label_contains("done: 300 / 300 lights")
            .is_some(),
        "the progress line does not say it is done"
    );
}

/// A render in flight leaves every frame free: the window keeps running, shows the render in
/// progress, answers a change (which restarts the render) and finishes it. 2 000 lights: the
/// pacer's chunks start at one light and at most double, so the sums take at least eleven
/// frames after the tile lists.
#[test]
fn a_render_in_flight_never_stops_the_window() {
    let Some(mut h) = lab((900.0, 600.0), plane_state(2000)) else {
        return;
    };
    h.state_mut().plane.shading.invalidate();
    // The restart's frame, then one that draws its progress line.
    h.run_steps(2);
    assert!(h.state().busy(), "{:?}", h.state().plane.shading.progress);
    // Culled (the default): the tile lists come first, then the sums.
    let said = ["binning lights into tiles", "rendering "]
        .iter()
        .any(|text| h.query_by_label_contains(text).is_some());
    assert!(said, "the window does not show the render in progress");
    // The window still answers: the divider moves, and the render restarts with it.
    h.state_mut().plane.state.divider = 0.3;
    h.run_steps(1);
    assert!(h.state().busy());
    let settings = h.state().plane.shading.settings().unwrap();
    assert_eq!(settings.divider, 0.3, "the render did not restart");
    settle(&mut h);
    assert!(h.state().plane.shading.progress.complete());
    assert!(bits(&plane_image(&mut h)) == bits(&one_shot(&h)));
}

/// A refit cancelled stops at its next iteration, is reported as cancelled, and — like a
/// finished one — is kept with the lab's state (eframe persists it between runs).
#[test]
fn a_cancelled_refit_stops_and_is_kept_with_the_state() {
    let Some(mut h) = lab((1000.0, 700.0), maximised(PanelId::Matrix)) else {
        return;
    };
    // The classic table, refitted by the fitter that made it.
    h.get_by_label("ltc_code").click();
    h.run_steps(2);
    h.get_by_label("cancel").click();
    settle(&mut h);
    let app = h.state();
    let r = app
        .lab
        .shared()
        .refit
        .as_ref()
        .expect("the cancelled refit is kept");
    assert!(r.cancelled && !r.converged, "{r:?}");
    assert!(
        r.iterations < ltc_lab::ltc::fit::FitSettings::default().max_iterations,
        "the refit ran to its limit"
    );
    assert!(h.query_by_label_contains("cancelled").is_some());
    let saved = ron::to_string(&app.state()).unwrap();
    let restored: LabState = ron::from_str(&saved).expect("eframe reads the state back");
    assert_eq!(restored, app.state());
}

/// "A | B tables": side B shades the same LTC form with table B, as the CPU reference does
/// with the two tables (the GPU–CPU tolerance of tests/gpu_parity.rs); a table loaded "as B"
/// becomes table B, is named in the matrix panel, and stays when table A changes.
#[test]
fn two_tables_compared_on_the_plane_and_in_the_matrix() {
    // Tall enough that the side panel's table rows are on screen, not scrolled away.
    let Some(mut h) = lab((1000.0, 900.0), plane_state(100)) else {
        return;
    };
    let ltc_against_brdf = plane_image(&mut h);
    h.get_by_label("A | B tables").click();
    settle(&mut h);
    let settings = *h.state().plane.shading.settings().unwrap();
    assert!(settings.b_reads_table_b && settings.method_b == settings.method_a);
    let gpu = plane_image(&mut h);
    let tables = ltc_lab::render::Tables {
        a: ltc_lab::ltc::lut::Lut::embedded(),
        b: ltc_lab::ltc::lut::Lut::embedded_point(),
    };
    let scene = h.state().lab.shared().shaded_scene();
    let cpu = ltc_lab::cpu::render(&scene, tables, &settings);
    gpu_common::assert_close("A | B split", &gpu, &cpu);
    assert!(
        bits(&gpu) != bits(&ltc_against_brdf),
        "side B is still the BRDF"
    );
    // A file as table B.
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("mine.exr");
    ltc_lab::ltc::lut::Lut::embedded_point()
        .write(&file)
        .unwrap();
    h.state_mut().controls.state.lut_path = file.display().to_string();
    h.state_mut().window.maximised = Some(PanelId::Matrix);
    h.run_steps(1);
    h.get_by_label("as B").click();
    settle(&mut h);
    let app = h.state();
    assert!(app.lab.tables().b_chosen && app.lab.tables().b.name.ends_with("mine.exr"));
    assert!(!app.lab.message.as_ref().unwrap().is_error);
    assert!(
        h.query_by_label_contains("mine.exr): M^-1").is_some(),
        "the matrix panel does not name table B"
    );
    // The next start compares with the same file (it went back to the shipped table).
    let again = LabApp::new(h.state().state(), None);
    assert!(again.lab.tables().b_chosen && again.lab.tables().b.name.ends_with("mine.exr"));
    assert_eq!(again.lab.tables().b.lut, h.state().lab.tables().b.lut);
    h.get_by_label("point").click();
    settle(&mut h);
    assert!(
        h.state().lab.tables().b.name.ends_with("mine.exr"),
        "table B did not stay"
    );
    h.get_by_label("reset").click();
    settle(&mut h);
    assert_eq!(h.state().lab.tables().b.name, "classic");
    assert_eq!(h.state().lab.shared().table_b_file, None);
}

#[test]
fn a_pinned_pixel_opens_into_its_lights_and_one_shows_on_the_lobe() {
    let Some(mut h) = lab((1000.0, 700.0), maximised(PanelId::Plane)) else {
        return;
    };
    let rect = h.get_by_label("plane image").rect();
    // Beside the lights' markers: the near half of the plane, a fifth from the left.
    let at = egui::pos2(
        rect.min.x + rect.width() * 0.2,
        rect.min.y + rect.height() * 0.8,
    );
    click_at(&mut h, at);
    settle(&mut h);
    let app = h.state();
    let [u, v] = app.plane.state.pinned.expect("the click pinned a pixel");
    assert!(
        (u - 0.2).abs() < 0.01 && (v - 0.8).abs() < 0.01,
        "pinned at ({u}, {v})"
    );
    let t = app.plane.pinned().expect("the pinned pixel's lights");
    assert_eq!(t.terms.len(), app.lab.shared().scene.lights.len());
    // The table's pixel is the plane's: the CPU reference at the same point.
    let scene = app.lab.shared().shaded_scene();
    let (w, hgt) = app.plane.shown.unwrap().size;
    let p = scene
        .surface_point_at(u * w as f64, v * hgt as f64, w, hgt)
        .unwrap();
    let exact = ltc_lab::cpu::shade_exact(&scene, &p, &scene.lights);
    assert_eq!(t.exact, exact);
    // The readout sits in its own strip.
    assert!(h.query_by_label_contains("pinned (0.2").is_some());
    // Sorted by the share of the error, largest first: click the top row's index.
    let top = ltc_lab::app::pixel_table::sorted_rows(t, h.state().plane.state.light_sort)[0];
    let (index, omega) = (top.index, top.omega);
    h.get_by_label(&index.to_string()).click();
    h.run_steps(2);
    assert_eq!(h.state().lab.shared().lobe_light, Some(omega.to_array()));
    assert_eq!(h.state().lab.shared().selected_light, Some(index));
    h.snapshot_options("plane_pixel_pinned_lights", &options(1000 * 700));
}

#[test]
fn the_lobe_difference_at_80_degrees_shows_the_gap() {
    let mut state = maximised(PanelId::Lobe);
    state.lab.theta_o_deg = 80.0;
    state.lab.scene.material.alpha = 0.6;
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

#[test]
fn the_exposure_slider_brightens_the_plane_without_restarting_it() {
    let Some(mut h) = lab((900.0, 600.0), plane_state(100)) else {
        return;
    };
    let rect = h.get_by_label("plane image").rect();
    // The mean of the image's grey level over its middle third (markers and the divider
    // cover a few percent of it either way).
    let mean = |h: &mut Harness<'static, LabApp>| {
        let image = h.render().expect("a rendered frame");
        let (x0, y0) = (
            rect.min.x + rect.width() / 3.0,
            rect.min.y + rect.height() / 3.0,
        );
        let (w, hgt) = (rect.width() / 3.0, rect.height() / 3.0);
        let mut sum = 0.0;
        let mut n = 0.0;
        for y in (y0 as u32)..((y0 + hgt) as u32) {
            for x in (x0 as u32)..((x0 + w) as u32) {
                let p = image.get_pixel(x, y);
                sum += f64::from(p[0]) + f64::from(p[1]) + f64::from(p[2]);
                n += 3.0;
            }
        }
        sum / n
    };
    let before = mean(&mut h);
    let settings = h.state().plane.shading.settings().copied();
    h.state_mut()
        .lab
        .edit(Aspect::Exposure, |s| s.scene.exposure *= 4.0);
    h.run_steps(3);
    assert!(
        !h.state().plane.shading.in_flight(),
        "an exposure change restarted the render"
    );
    assert_eq!(h.state().plane.shading.settings().copied(), settings);
    let after = mean(&mut h);
    // Four times the exposure through x/(1+x) and sRGB raises every lit grey level: a mid
    // grey of 118/255 (this plane's middle at exposure 1.5) is 0.221 before the tone map,
    // and 4 × 0.221 comes out at 182/255. 10 levels leaves room for darker pixels and the
    // markers; an exposure that is not applied changes nothing.
    assert!(
        after > before + 10.0,
        "grey level {before:.1} -> {after:.1} at 4x the exposure"
    );
}

#[test]
fn dragging_on_a_clipping_picture_draws_the_profiles_line() {
    let Some(mut h) = lab((1200.0, 800.0), maximised(PanelId::Clipping)) else {
        return;
    };
    // Case 2's picture (b), from its upper left to its lower right quarter.
    let rect = h.get_by_label("figure2-case2 picture 1").rect();
    let start = rect.min + rect.size() * egui::vec2(0.2, 0.3);
    let end = rect.min + rect.size() * egui::vec2(0.8, 0.7);
    drag_along(&mut h, start, end);
    h.run_steps(2);
    let app = h.state();
    assert_eq!(
        app.clipping.state.clip_scene,
        ltc_lab::app::clip_setup::ClipScene::Case2
    );
    let line = app.clipping.line.expect("a dragged line");
    // In the pictures' unit square, within the drag's first step (1/10 of it) of the ends.
    for (got, want) in line.iter().zip([(0.2, 0.3), (0.8, 0.7)]) {
        assert!(
            (got.x - want.0).abs() < 0.07 && (got.y - want.1).abs() < 0.05,
            "line {line:?}"
        );
    }
}

/// No read or persisted timing can hang the lab: a study.csv whose ms_median is 0 (fps =
/// 1000/0 froze the chart at 100% CPU) is refused naming its line, and a saved chart with an
/// infinite fps is dropped at start with a message in the window instead of a black one.
#[test]
fn zero_or_infinite_timings_are_refused_where_they_are_read() {
    let dir = tempfile::tempdir().unwrap();
    let zero = dir.path().join("zero.csv");
    std::fs::write(
        &zero,
        format!(
            "{}\nltc,0.27,100,320,180,on,2,0,0.23,1e-2,1e-1,1e-2\n",
            ltc_lab::study::StudyRow::CSV_HEADER
        ),
    )
    .unwrap();
    let e = ltc_lab::study::read_csv(&zero).unwrap_err();
    assert!(
        e.to_string().contains("zero.csv line 2") && e.message.contains("ms_median"),
        "{e}"
    );
    let mut state = maximised(PanelId::Chart);
    let mut saved = ltc_lab::app::measure::Measurement::default();
    saved
        .scaling
        .push((ltc_lab::render::Method::Ltc, vec![[100.0, f64::INFINITY]]));
    state.chart.measurement = Some(saved.clone());
    let Some(h) = lab((1000.0, 600.0), state) else {
        return;
    };
    // Dropped; the chart may show its bundled reference study instead, which plots.
    let shown = h.state().chart.state.measurement.clone();
    assert_ne!(shown.as_ref(), Some(&saved));
    assert!(shown.is_none_or(|m| m.validate().is_ok()));
    assert!(
        h.query_by_label_contains("the saved chart was dropped")
            .is_some(),
        "no message in the window"
    );
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
    state.lab.set_light_count(max + 1);
    let mut h = unsettled((800.0, 500.0), state);
    assert_eq!(h.state().lab.shared().scene.lights.len(), max);
    h.run_steps(2);
    assert!(
        h.query_by_label_contains(&format!("the first {max} are kept"))
            .is_some(),
        "the cut is not said in the window"
    );
    assert!(
        h.query_by_label_contains(&format!("at most {max} lights: this adapter's limit"))
            .is_some(),
        "the slider's limit is not said beside it"
    );
}

/// An image that is out of date is never shown as if current: at 0 lights the plane is
/// black (the last 100-light image stayed on screen under "done: 0 / 0 lights").
#[test]
fn no_lights_leave_no_old_image_on_the_plane() {
    let Some(mut h) = lab((800.0, 500.0), maximised(PanelId::Plane)) else {
        return;
    };
    let lit = |f: &Frame| f.pixels.iter().filter(|p| p.x + p.y + p.z > 0.0).count();
    assert!(
        lit(&plane_image(&mut h)) > 0,
        "the default scene lights the plane"
    );
    h.state_mut().lab.set_light_count(0);
    settle(&mut h);
    let frame = plane_image(&mut h);
    assert_eq!(h.state().plane.shading.progress.total, 0);
    assert_eq!(lit(&frame), 0, "the last image is still there");
}

/// A table used from a file is named as table A everywhere and survives a restart: after
/// *use LUT* with an ltc.js, "classic" stayed lit, and after a restart the classic table
/// shaded while the field still showed ltc.js. A file gone since is said, not silently lost.
#[test]
fn a_table_from_a_file_is_the_one_shown_and_survives_a_restart() {
    use egui_kittest::kittest::NodeT;
    use ltc_lab::ltc::formats::{self, Export, Header, dds::Precision};
    use ltc_lab::ltc::lut::{Lut, Table};
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
    h.state_mut().controls.state.lut_path = js.display().to_string();
    h.run_steps(1);
    h.get_by_label("use LUT").click();
    h.run_steps(2);
    assert!(
        !selected(&h, "classic") && !selected(&h, "point"),
        "a shipped table still lit"
    );
    // Named in the side panel, and on the lobe panel's face without its directories.
    assert!(
        h.query_by_label_contains(&format!("table A: {}", js.display()))
            .is_some()
    );
    assert!(h.query_by_label_contains("table A: point.js").is_some());
    // The next start shades with the same file.
    let saved = h.state().state();
    let again = LabApp::new(saved.clone(), None);
    assert_eq!(again.lab.tables().a.lut, h.state().lab.tables().a.lut);
    assert_eq!(again.lab.tables().a.name, js.display().to_string());
    // Gone since: the shipped table shades, and the window says why.
    std::fs::remove_file(&js).unwrap();
    let lost = LabApp::new(saved, None);
    assert_eq!(&lost.lab.tables().a.lut, Lut::embedded());
    assert_eq!(lost.lab.shared().table_file, None);
    let m = lost.lab.message.expect("a message");
    assert!(
        m.is_error && m.text.contains("cannot be read again"),
        "{}",
        m.text
    );
    // Choosing a shipped table lights it again and forgets the file.
    h.get_by_label("point").click();
    h.run_steps(2);
    assert!(selected(&h, "point"));
    assert_eq!(h.state().lab.shared().table_file, None);
}

/// The lobe panel says on its face what it shows (θo, α, the table), so that a picture of it
/// taken with the controls folded still has its parameters.
#[test]
fn the_lobe_panel_prints_its_parameters_on_its_face() {
    let mut state = maximised(PanelId::Lobe);
    state.lab.theta_o_deg = 47.0;
    state.window.controls_hidden = true;
    let Some(h) = lab((900.0, 600.0), state) else {
        return;
    };
    let alpha = h.state().lab.shared().alpha();
    let face = format!("θo = 47.0°   α = {alpha:.4}   table A: classic");
    assert!(
        h.query_by_label_contains(&face).is_some(),
        "no '{face}' on the lobe panel"
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
    h.state_mut().controls.state.lut_path = "/nonexistent/ltc.js".into();
    h.run_steps(1);
    h.get_by_label("use LUT").click();
    h.run_steps(2);
    assert!(
        h.query_by_label_contains("still using the previous table")
            .is_some(),
        "no notice"
    );
    let after = (
        h.get_by_label("use LUT").rect(),
        h.get_by_label("screenshot").rect(),
    );
    assert_eq!(after, before, "a control moved");
    h.get_by_label("×").click();
    h.run_steps(2);
    assert!(
        h.query_by_label_contains("still using the previous table")
            .is_none(),
        "not dismissed"
    );
}

/// A light can be placed by typing: the selected light has x, y, z fields (it could only be
/// dragged), and a saved scene writes its numbers rounded (a dragged light was saved with 16
/// decimals); the view becomes what the file holds.
#[test]
fn a_light_is_placed_by_typing_and_saved_rounded() {
    let Some(mut h) = lab((1600.0, 900.0), maximised(PanelId::Lobe)) else {
        return;
    };
    h.state_mut()
        .lab
        .edit(Aspect::Selection, |s| s.selected_light = Some(3));
    h.run_steps(2);
    let field = h.get_by_role_and_label(Role::SpinButton, "y");
    field.focus();
    h.run_steps(1);
    h.get_by_role_and_label(Role::SpinButton, "y")
        .type_text("0.5");
    h.key_press(egui::Key::Enter);
    h.run_steps(2);
    // Typed over the old value's selected text: the field holds what was typed.
    assert_eq!(h.state().lab.shared().scene.lights[3].position[1], 0.5);
    h.state_mut().lab.edit(Aspect::Scene, |s| {
        s.scene.lights[3].position[0] = 0.123_456_789_012_345;
    });
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.toml");
    h.state_mut().controls.state.scene_path = path.display().to_string();
    h.run_steps(1);
    h.get_by_label("save").click();
    h.run_steps(2);
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.contains("0.1235"), "not rounded: {text}");
    assert!(!text.contains("0.123456"), "16 decimals saved");
    let saved = ltc_lab::scene::Scene::load(&path).unwrap();
    assert_eq!(
        saved,
        h.state().lab.shared().scene,
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

/// One side of the plane alone (`view` A or B) as the lab's current render shades it, whole,
/// on the lab's own device, with the lab's tables A and B.
fn plane_side_alone(h: &Harness<'static, LabApp>, view: View) -> Frame {
    let app = h.state();
    let ctx = app.plane.shading.context().expect("the lab has a GPU");
    let current = app.plane.shading.settings().expect("a render started");
    let tables = app.lab.tables();
    let mut r = PlaneRenderer::new(ctx, &tables.a.lut, ShaderChecks::Checked).unwrap();
    r.set_tables(ctx, &tables.a.lut, Some(&tables.b.lut))
        .unwrap();
    let settings = ltc_lab::render::RenderSettings { view, ..*current };
    let scene = app.lab.shared().shaded_scene();
    r.render(ctx, &scene, &settings).unwrap().0
}

/// Issue 19: in "A | B tables" the title says which tables are compared, and the pinned
/// pixel opens into table A against table B per light: each light's LTC with either table,
/// as the CPU reference shades that light alone, and its share of Σ|A − B|, sortable.
#[test]
fn with_two_tables_the_pinned_pixel_compares_table_a_with_table_b_per_light() {
    // Wide enough that the table's last columns are on screen, not scrolled away.
    let Some(mut h) = lab((1600.0, 800.0), maximised(PanelId::Plane)) else {
        return;
    };
    assert!(h.query_by_label("Plane: LTC | BRDF").is_some());
    h.get_by_label("A | B tables").click();
    settle(&mut h);
    assert!(
        h.query_by_label("Plane: table A (classic) | table B (point)")
            .is_some(),
        "the title does not name the tables compared"
    );
    let rect = h.get_by_label("plane image").rect();
    click_at(
        &mut h,
        egui::pos2(
            rect.min.x + rect.width() * 0.2,
            rect.min.y + rect.height() * 0.8,
        ),
    );
    settle(&mut h);
    // The value columns name the tables; the exact BRDF is not a column here.
    for header in ["table A", "table B", "share of |A−B| v"] {
        assert!(h.query_by_label(header).is_some(), "no column {header:?}");
    }
    assert!(h.query_by_label("exact").is_none() && h.query_by_label("error share v").is_none());
    // The readout compares the tables, too.
    assert!(
        h.query_by_label_contains("(luminance), difference")
            .is_some()
    );
    let app = h.state();
    let t = app.plane.pinned().expect("the pinned pixel's lights");
    let scene = app.lab.shared().shaded_scene();
    let (w, hgt) = app.plane.shown.unwrap().size;
    let [u, v] = app.plane.state.pinned.unwrap();
    let p = scene
        .surface_point_at(u * w as f64, v * hgt as f64, w, hgt)
        .unwrap();
    let rules = app.lab.shared().ltc_rules();
    let shade = |lut, lights: &[ltc_lab::scene::Light]| {
        ltc_lab::cpu::shade_ltc(&scene, lut, &p, lights, &rules)
    };
    let (a, b) = (&app.lab.tables().a.lut, &app.lab.tables().b.lut);
    // Summed in the same order as the reference sums: the same f64 operations.
    assert_eq!(t.ltc_b, Some(shade(b, &scene.lights)));
    assert_eq!(t.ltc, shade(a, &scene.lights));
    let y = ltc_lab::metrics::luminance;
    let alone = |lut, i: usize| y(shade(lut, &scene.lights[i..=i]));
    let largest = |f: &dyn Fn(usize) -> f64| {
        (0..scene.lights.len())
            .max_by(|&i, &j| f(i).total_cmp(&f(j)))
            .unwrap()
    };
    // Sorted by the share of |A − B|, largest first: the light whose own |A − B| is largest.
    let top = |h: &Harness<'static, LabApp>| {
        let app = h.state();
        let t = app.plane.pinned().unwrap();
        ltc_lab::app::pixel_table::sorted_rows(t, app.plane.state.light_sort)[0].index
    };
    assert_eq!(top(&h), largest(&|i| (alone(a, i) - alone(b, i)).abs()));
    // Sorted by table B's column: the brightest light under table B.
    let by_b = largest(&|i| alone(b, i));
    h.get_by_label("table B").click();
    h.run_steps(2);
    assert_eq!(top(&h), by_b);
}

/// Issue 19: *worst pixel* pins the pixel where the two sides differ most, LTC against the
/// BRDF and then table A against table B: the largest |L_A − L_B| / max(L_B, floor) of the
/// two sides rendered alone and compared here in f64 with the difference view's floor
/// (metrics::relative_floor), within the GPU's diff-view tolerance (tests/gpu_common).
#[test]
fn the_worst_pixel_button_pins_the_largest_difference_in_either_mode() {
    let Some(mut h) = lab((1000.0, 700.0), maximised(PanelId::Plane)) else {
        return;
    };
    for mode in ["LTC | BRDF", "A | B tables"] {
        h.get_by_label(mode).click();
        settle(&mut h);
        h.state_mut().plane.state.pinned = None;
        h.get_by_label("worst pixel").click();
        settle(&mut h);
        assert_eq!(h.state().plane.state.view, View::Diff, "{mode}");
        let [u, v] = h
            .state()
            .plane
            .state
            .pinned
            .expect("worst pixel pinned none");
        let (sa, sb) = (plane_side_alone(&h, View::A), plane_side_alone(&h, View::B));
        let floor = ltc_lab::metrics::relative_floor(&sb, &sa);
        let y = ltc_lab::metrics::luminance;
        let rel =
            |k: usize| ltc_lab::metrics::relative_error(y(sa.pixels[k]), y(sb.pixels[k]), floor);
        let worst = (0..sb.pixels.len())
            .filter(|&k| sb.on_plane[k])
            .map(rel)
            .fold(0.0, f64::max);
        let x = (u * sb.width as f64) as usize;
        let row = (v * sb.height as f64) as usize;
        let pinned = rel(row * sb.width + x);
        assert!(
            pinned >= worst - gpu_common::diff_tolerance(worst),
            "{mode}: pinned ({x}, {row}) differs by {pinned}, the worst pixel by {worst}"
        );
        // The pixel's lights are open, in the mode's comparison.
        let t = h.state().plane.pinned().expect("the worst pixel's lights");
        assert_eq!(t.ltc_b.is_some(), mode == "A | B tables");
    }
}

/// Issue 19: *+ light* puts each new light where it is seen: projected inside the image,
/// away from the split's divider and from every other light's marker.
#[test]
fn a_new_light_is_seen_away_from_the_divider_and_the_other_lights() {
    let Some(mut h) = lab((1000.0, 700.0), maximised(PanelId::Plane)) else {
        return;
    };
    let held = h.state().lab.shared().scene.lights.len();
    for _ in 0..2 {
        h.get_by_label("+ light").click();
        h.run_steps(2);
    }
    let app = h.state();
    let scene = &app.lab.shared().scene;
    assert_eq!(scene.lights.len(), held + 2);
    let (w, hgt) = app.plane.shown.unwrap().size;
    let seen = |k: usize| {
        scene
            .project(glam::DVec3::from(scene.lights[k].position), w, hgt)
            .unwrap()
    };
    let divider = app.plane.state.divider * w as f64;
    for k in held..held + 2 {
        let (x, y) = seen(k);
        let p = scene.lights[k].position;
        assert!(p[2] > 0.0, "light {k} at {p:?} is not above the plane");
        assert!(
            (0.0..w as f64).contains(&x) && (0.0..hgt as f64).contains(&y),
            "light {k} at ({x}, {y}) is outside the {w}×{hgt} image"
        );
        // 5% of the width: the divider's grab band (8 points) and a marker (6) are far
        // narrower at this size, so the marker is clear of both.
        assert!(
            (x - divider).abs() > 0.05 * w as f64,
            "light {k} at x = {x} sits on the divider at {divider}"
        );
        // 16 px: two markers (radius ≤ 6) picked within 8 points stay apart at 1 point per
        // pixel (kittest's scale).
        for other in (0..scene.lights.len()).filter(|&o| o != k) {
            let (ox, oy) = seen(other);
            assert!(
                (ox - x).hypot(oy - y) > 16.0,
                "light {k} lies on light {other}"
            );
        }
    }
}

/// Both axes of both charts span whole decades around their data, so that each has at least
/// two labelled ticks (times spanning 30–90 ms, as GL llvmpipe's did, showed one or none).
#[test]
fn chart_axes_span_whole_decades() {
    use ltc_lab::app::chart::decade_span;
    assert_eq!(decade_span([30.0, 90.0].into_iter()), [1.0, 2.0]);
    assert_eq!(decade_span([0.02, 250.0].into_iter()), [-2.0, 3.0]);
    assert_eq!(decade_span([100.0].into_iter()), [2.0, 3.0]);
    assert_eq!(decade_span([f64::NAN, 0.0, -1.0].into_iter()), [0.0, 1.0]);
}

/// The chart's legends sit outside the points (they covered them), the LTC/BRDF speed ratio
/// is given per light count, and the timed renders' spread is drawn as bars
/// (`chart_ranges`, looked at).
#[test]
fn the_chart_keeps_its_legends_outside_and_gives_the_speed_ratio() {
    use ltc_lab::app::measure::{Measurement, Point};
    use ltc_lab::render::Method;
    let Some(h) = lab((900.0, 560.0), maximised(PanelId::Chart)) else {
        return;
    };
    let plots = [
        h.get_by_label("time vs error plot").rect(),
        h.get_by_label("fps vs lights plot").rect(),
    ];
    let entries: Vec<egui::Rect> = h
        .query_all_by_label("ltc-fast")
        .chain(h.query_all_by_label("paper LTC (GTX 1060)"))
        .map(|n| n.rect())
        .collect();
    assert!(entries.len() >= 3, "legend entries missing");
    for e in &entries {
        assert!(
            plots.iter().all(|p| !p.intersects(*e)),
            "a legend entry {e:?} lies over a plot {plots:?}"
        );
    }
    // The ratio, from the measurement shown (the bundled study): ltc-fast's fps over brdf's.
    let m = h.state().chart.state.measurement.clone().unwrap();
    let fps = |method: Method| m.scaling.iter().find(|(x, _)| *x == method).unwrap().1[0];
    let (ltc, brdf) = (fps(Method::LtcFast), fps(Method::Brdf));
    assert_eq!(ltc[0], brdf[0]);
    let said = format!("×{:.2} at {} lights", ltc[1] / brdf[1], ltc[0]);
    assert!(
        h.query_by_label_contains(&said).is_some(),
        "no '{said}' under the chart"
    );
    // A live measurement's spread: bars through each point.
    let ranged = Measurement {
        points: vec![
            Point {
                label: "ltc-fast".into(),
                ms: 40.0,
                rel_rmse: 1e-2,
                ms_range: Some([30.0, 70.0]),
            },
            Point {
                label: "brdf".into(),
                ms: 90.0,
                rel_rmse: 0.0,
                ms_range: Some([85.0, 140.0]),
            },
        ],
        scaling: vec![
            (Method::LtcFast, vec![[100.0, 25.0], [1000.0, 2.5]]),
            (Method::Brdf, vec![[100.0, 11.0], [1000.0, 1.1]]),
        ],
        scaling_range: vec![
            (
                Method::LtcFast,
                vec![[100.0, 15.0, 33.0], [1000.0, 2.0, 3.0]],
            ),
            (Method::Brdf, vec![[100.0, 7.0, 12.0], [1000.0, 0.9, 1.2]]),
        ],
        device: "a test's numbers".into(),
    };
    let mut state = maximised(PanelId::Chart);
    state.chart.measurement = Some(ranged);
    let mut h = lab((900.0, 560.0), state).unwrap();
    let said = "LTC/BRDF speed (ltc-fast over brdf): ×2.27 at 100 lights, ×2.27 at 1000 lights";
    assert!(h.query_by_label_contains(said).is_some(), "no '{said}'");
    h.snapshot_options("chart_ranges", &options(900 * 560));
}

/// An image in flight is a preview of the whole: its partial sum scaled to every light (a
/// dark fraction of the image looked finished), said so, with the time left once the render
/// has run a second (`Progress::time_left`, at the rate so far).
#[test]
fn a_render_in_flight_is_previewed_at_full_scale_and_says_so() {
    use ltc_lab::app::shading::Progress;
    use std::time::Duration;
    let p = Progress {
        done: 250,
        total: 1000,
        ..Progress::default()
    };
    assert_eq!(p.preview_scale(), 4.0);
    assert_eq!(
        p.time_left(Duration::from_millis(500)),
        None,
        "under a second"
    );
    assert_eq!(
        p.time_left(Duration::from_secs(2)),
        Some(Duration::from_secs(6))
    );
    let done = Progress { done: 1000, ..p };
    assert_eq!(
        (done.preview_scale(), done.time_left(Duration::from_secs(9))),
        (1.0, None)
    );
    let mut state = maximised(PanelId::Plane);
    state.lab.set_light_count(1000);
    let Some(mut h) = lab((800.0, 500.0), state) else {
        return;
    };
    // A restart: binned into tiles first, then summed in chunks that start at one light
    // (the pacer), so its first summed frames leave it in flight.
    h.state_mut().lab.set_light_count(1001);
    for _ in 0..1000 {
        h.step();
        if h.state().plane.shading.progress.done > 0 {
            break;
        }
    }
    // One more frame: the progress line is drawn before the frame's chunk is summed.
    h.step();
    assert!(
        h.state().plane.shading.in_flight(),
        "the render finished at once"
    );
    assert!(h.state().plane.shading.progress.preview_scale() > 1.0);
    assert!(
        h.query_by_label_contains("preview: the sum so far × ")
            .is_some(),
        "the preview is not said"
    );
    settle(&mut h);
    assert!(h.query_by_label_contains("preview").is_none());
}

/// Issue 22: the clipping panel shows one light's error by elevation band at the lab's
/// (θo, α), with the lab's rules and the panel's table, as the library measures it; a change
/// of α measures again.
#[test]
fn the_clipping_panel_gives_the_error_by_elevation_at_the_labs_view() {
    use ltc_lab::horizon::band_errors_at;
    let Some(mut h) = lab((1200.0, 1100.0), maximised(PanelId::Clipping)) else {
        return;
    };
    let said = |h: &Harness<'static, LabApp>, alpha: f64| {
        let app = h.state();
        let at = (app.lab.shared().theta_o_deg, alpha);
        let lut = &app.lab.tables().a.lut;
        let b = band_errors_at(
            lut,
            &ltc_lab::render::LtcRules::default(),
            at,
            ltc_lab::app::elevation::CASES,
            ltc_lab::horizon::SEED,
        )[0];
        let text = format!(
            "0–5°: {:.0}% (energy ×{:.2})",
            100.0 * b.specular,
            b.specular_energy
        );
        h.query_by_label(&text).is_some()
    };
    let alpha = h.state().lab.shared().alpha();
    assert!(said(&h, alpha), "the 0–5° band's error is not shown");
    h.state_mut()
        .lab
        .edit(Aspect::Scene, |s| s.scene.material.alpha = 0.6);
    settle(&mut h);
    assert!(said(&h, 0.6), "not measured again at the new α");
    assert!(
        h.query_by_label_contains("at θo = 45.0°, α = 0.6000")
            .is_some()
    );
}

/// Issue 22: the side panel's horizon choice shades with a remedy, as a user picks it: with
/// exact-band the clipping panel's 0–5° band is exact; constrained-fit makes table A the
/// constrained table (the remedy is that table), and eq30 gives the classic table back.
#[test]
fn the_horizon_choice_shades_with_a_remedy() {
    use ltc_lab::ltc::remedy::{Horizon, HorizonRule};
    let Some(mut h) = lab((1400.0, 1100.0), maximised(PanelId::Clipping)) else {
        return;
    };
    let choose = |h: &mut Harness<'static, LabApp>, name: &str| {
        h.get_by_label("horizon").click();
        h.run_steps(2);
        h.get_by_label(name).click();
        settle(h);
    };
    choose(&mut h, "exact-band");
    assert_eq!(h.state().lab.shared().horizon, HorizonRule::ExactBand);
    assert!(
        h.query_by_label("0–5°: 0% (energy ×1.00)").is_some(),
        "the 0–5° band is not exact under exact-band"
    );
    choose(&mut h, "constrained-fit");
    let s = h.state().lab.shared();
    assert_eq!(
        (s.horizon, s.horizon_remedy()),
        (HorizonRule::Eq30, Horizon::ConstrainedFit)
    );
    assert!(h.state().lab.tables().a.name.contains("constrained"));
    choose(&mut h, "eq30");
    assert!(h.state().lab.tables().a.name.contains("classic"));
    assert_eq!(h.state().lab.shared().horizon_remedy(), Horizon::Eq30);
}

/// A file from the disk, as eframe hands a dropped one to the app.
#[derive(Debug)]
struct DroppedFromDisk(std::path::PathBuf);

impl egui::DroppedFile for DroppedFromDisk {
    fn path(&self) -> &std::path::Path {
        &self.0
    }

    fn bytes(&self) -> Result<Vec<u8>, String> {
        std::fs::read(&self.0).map_err(|e| e.to_string())
    }
}

fn drop_file(h: &mut Harness<'static, LabApp>, path: &std::path::Path) {
    h.input_mut()
        .dropped_files
        .push(std::sync::Arc::new(DroppedFromDisk(path.to_path_buf())));
    h.run_steps(2);
}

/// Issue 21: a file dropped on the window is taken for what its name says (app/file_io.rs):
/// a scene replaces the lab's, a table becomes table A, and a file the lab does not read is
/// refused by name, changing nothing.
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
    assert_eq!(h.state().lab.shared().scene, scene);
    let said = |h: &Harness<'static, LabApp>| h.state().lab.message.clone().unwrap();
    assert!(!said(&h).is_error && said(&h).text.contains("dropped.toml"));

    let table = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("luts/ltc_point.exr");
    drop_file(&mut h, &table);
    assert!(h.state().lab.tables().a.name.ends_with("ltc_point.exr"));

    let notes = dir.path().join("notes.txt");
    std::fs::write(&notes, "not a scene").unwrap();
    drop_file(&mut h, &notes);
    assert!(
        said(&h).is_error && said(&h).text.contains("notes.txt"),
        "{:?}",
        said(&h)
    );
    assert_eq!(h.state().lab.shared().scene, scene);
    settle(&mut h);
}
