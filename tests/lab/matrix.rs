//! The matrix panel: the cell readout, the heat maps, refits.

use egui_kittest::kittest::Queryable;
use ltc_lab::app::{LabState, PanelId};
use ltc_lab::ltc::lut::{Lut, Table};

use crate::harness::{click_at, lab, maximised, options, settle, shows};

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
    let lab = h.state().lab();
    let lut = &lab.tables().a().lut;
    assert_eq!(lab.alpha(), lut.alpha(10));
    assert!((lab.lobe_view().theta_o_deg - lut.theta_o(50).to_degrees()).abs() < 1e-9);
    assert_eq!(lab.nearest_cell(), (10, 50));
}

#[test]
fn refit_runs_the_fitter_live_and_the_lobe_panel_follows() {
    let Some(mut h) = lab((1000.0, 700.0), maximised(PanelId::Matrix)) else {
        return;
    };
    // The classic table, refitted by the fitter that made it.
    h.get_by_label("ltc_code").click();
    settle(&mut h);
    let lab = h.state().lab();
    let refit = lab.refit().0.as_ref().expect("a refit ran");
    assert_eq!(refit.cell, lab.nearest_cell());
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
    let (lobe, ltc) = lab
        .refit_ltc()
        .expect("the lobe panel gets the refitted lobe");
    assert_eq!(lobe, lab.lobe_view().lobe);
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
    settle(&mut h);
    let lab = h.state().lab();
    let r = lab.refit().0.clone().expect("a refit ran");
    assert_eq!(r.cell, lab.nearest_cell());
    // Started from the stored cell and kept the best point by its own objective (a
    // quadrature of the same L1 integral the error estimates by strata): it may not end above
    // the stored error by more than tests/fit/refit.rs allows a refit (5% of the albedo).
    assert!(
        r.error <= r.stored_error + 0.05,
        "{} vs {}",
        r.error,
        r.stored_error
    );
    for what in ["as stored", "refitted"] {
        let label = format!("cell ({}, {}) {what} (÷ middle)", r.cell.0, r.cell.1);
        assert!(shows(&h, &label), "no {label}");
    }
    let line = format!("refitted {:.2}%", 100.0 * r.error);
    assert!(shows(&h, &line), "no '{line}'");
    h.snapshot_options("matrix_refit_worst_cell", &options(1000 * 900));
}

/// A refit cancelled stops at its next iteration, is reported as cancelled, and — like a
/// finished one — is kept with the lab's state (eframe keeps it between runs).
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
        .lab()
        .refit()
        .0
        .as_ref()
        .expect("the cancelled refit is kept");
    assert!(r.cancelled && !r.converged, "{r:?}");
    assert!(
        r.iterations < ltc_lab::ltc::fit::FitSettings::default().max_iterations,
        "the refit ran to its limit"
    );
    assert!(shows(&h, "cancelled"));
    let saved = ron::to_string(&app.state()).unwrap();
    let restored: LabState = ron::from_str(&saved).expect("eframe reads the state back");
    assert_eq!(restored, app.state());
}

#[test]
fn the_table_switch_shades_with_the_point_fit_and_both_fits_are_shown() {
    let Some(mut h) = lab((1100.0, 700.0), maximised(PanelId::Matrix)) else {
        return;
    };
    assert!(shows(&h, "A (classic): M^-1") && shows(&h, "B (point): M^-1"));
    assert_eq!(&h.state().lab().tables().a().lut, Lut::embedded());
    h.get_by_label("point").click();
    h.run_steps(3);
    let tables = h.state().lab().tables();
    assert_eq!(tables.shipped, Table::Point);
    assert_eq!(&tables.a().lut, Lut::embedded_point());
    // Table B follows: the other shipped table.
    assert_eq!(tables.b().lut.cells, Lut::embedded().cells);
    assert!(shows(&h, "A (point): M^-1") && shows(&h, "B (classic): M^-1"));
}
