//! The speed-versus-accuracy chart: a study read from a file, refused timings, the legends
//! and the LTC/BRDF ratio.

use egui_kittest::kittest::Queryable;
use ltc_lab::app::PanelId;
use ltc_lab::app::chart::measure::{Measurement, Point};
use ltc_lab::measure::study::StudyRow;
use ltc_lab::render::Method;

use crate::harness::{lab, maximised, notice, options, shows, type_into};

#[test]
fn the_chart_reads_a_study_csv_and_reports_a_bad_row() {
    let Some(mut h) = lab((1000.0, 600.0), maximised(PanelId::Chart)) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("study.csv");
    std::fs::write(&good, format!("{}\nltc,0.27,100,320,180,on,2,25.3,0.23,1.06e-2,1.9e-1,4.2e-2\nbrdf,0.27,100,320,180,on,2,27.8,0.21,0,0,0\n", StudyRow::CSV_HEADER)).unwrap();
    type_into(&mut h, "study file", &good.display().to_string());
    h.get_by_label("load study").click();
    h.run_steps(2);
    let m = h
        .state()
        .state()
        .chart
        .measurement
        .expect("the study was read");
    assert_eq!(m.points.len(), 2);
    let p = &m.points[0];
    assert_eq!(
        (p.label.as_str(), p.method, p.ms, p.rel_rmse),
        ("ltc", Some(Method::Ltc), 25.3, 1.06e-2)
    );
    let bad = dir.path().join("bad.csv");
    std::fs::write(
        &bad,
        format!(
            "{}\nltc,0.27,100,320,180,on,2,nan,0.23,1e-2,1e-1,1e-2\n",
            StudyRow::CSV_HEADER
        ),
    )
    .unwrap();
    type_into(&mut h, "study file", &bad.display().to_string());
    h.get_by_label("load study").click();
    h.run_steps(2);
    let e = notice(&h).expect("an error");
    assert!(e.is_error && e.text.contains("bad.csv line 2"), "{e:?}");
    assert!(
        h.query_all_by_label_contains("bad.csv line 2").count() >= 1,
        "the error is not shown in the window"
    );
}

/// No read or kept timing can hang the lab: a study.csv whose ms_median is 0 (fps = 1000/0
/// froze the chart at 100% CPU) is refused naming its line, and a kept chart with an
/// infinite fps is dropped at start with a message in the window instead of a black one.
#[test]
fn zero_or_infinite_timings_are_refused_where_they_are_read() {
    let dir = tempfile::tempdir().unwrap();
    let zero = dir.path().join("zero.csv");
    std::fs::write(
        &zero,
        format!(
            "{}\nltc,0.27,100,320,180,on,2,0,0.23,1e-2,1e-1,1e-2\n",
            StudyRow::CSV_HEADER
        ),
    )
    .unwrap();
    let e = ltc_lab::measure::study::read_csv(&zero).unwrap_err();
    assert!(
        e.to_string().contains("zero.csv line 2") && e.message.contains("ms_median"),
        "{e}"
    );
    let mut state = maximised(PanelId::Chart);
    let mut saved = Measurement::default();
    saved
        .scaling
        .push((Method::Ltc, vec![[100.0, f64::INFINITY]]));
    state.chart.measurement = Some(saved.clone());
    let Some(h) = lab((1000.0, 600.0), state) else {
        return;
    };
    // Dropped; the chart may show its bundled reference study instead, which plots.
    let shown = h.state().state().chart.measurement;
    assert_ne!(shown.as_ref(), Some(&saved));
    assert!(shown.is_none_or(|m| m.validate().is_ok()));
    assert!(
        shows(&h, "the saved chart was dropped"),
        "no message in the window"
    );
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
    let m = h.state().state().chart.measurement.unwrap();
    let fps = |method: Method| m.scaling.iter().find(|(x, _)| *x == method).unwrap().1[0];
    let (ltc, brdf) = (fps(Method::LtcFast), fps(Method::Brdf));
    assert_eq!(ltc[0], brdf[0]);
    let said = format!("×{:.2} at {} lights", ltc[1] / brdf[1], ltc[0]);
    assert!(shows(&h, &said), "no '{said}' under the chart");
    // A live measurement's spread: bars through each point.
    let point = |label: &str, method, ms, rel_rmse, range| Point {
        label: label.into(),
        method: Some(method),
        ms,
        rel_rmse,
        ms_range: Some(range),
    };
    let ranged = Measurement {
        points: vec![
            point("ltc-fast", Method::LtcFast, 40.0, 1e-2, [30.0, 70.0]),
            point("brdf", Method::Brdf, 90.0, 0.0, [85.0, 140.0]),
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
        study: None,
    };
    let mut state = maximised(PanelId::Chart);
    state.chart.measurement = Some(ranged);
    let mut h = lab((900.0, 560.0), state).unwrap();
    let said = "LTC/BRDF speed (ltc-fast over brdf): ×2.27 at 100 lights, ×2.27 at 1000 lights";
    assert!(shows(&h, said), "no '{said}'");
    h.snapshot_options("chart_ranges", &options(900 * 560));
}

/// The chart's table of work per light: every method's counts as the shaders give them
/// (`gpu::work`), beside its measured time per light and its ratio to brdf's.
#[test]
fn the_chart_gives_each_methods_work_per_light_beside_its_time() {
    let Some(mut h) = lab((1200.0, 800.0), maximised(PanelId::Chart)) else {
        return;
    };
    h.get_by_label("work per light, from the shaders").click();
    h.run_steps(3);
    let work = ltc_lab::gpu::work::work_per_light().unwrap();
    for (m, w) in &work {
        for count in [w.arithmetic, w.divisions, w.special, w.reads] {
            assert!(
                h.query_all_by_label(&count.to_string()).count() > 0,
                "{}: no cell {count}",
                m.name()
            );
        }
    }
    // brdf's time over its own is 1.
    assert!(h.query_all_by_label("1.00").count() > 0);
    // Each method measured: its time per light at the largest count.
    assert!(h.query_all_by_label_contains("lights)").count() >= 4);
    h.snapshot_options("chart_work_per_light", &options(1200 * 800));
}

/// `lab --measure --method-file F` (the start's order): the file is loaded before the chart
/// measures, so the measurement times it too, as the *measure* button's does (it was loaded
/// after, and the file's point was missing). Watched as the chart says it: its task comes up.
#[test]
fn a_measurement_asked_at_the_start_measures_the_method_file() {
    let mut state = maximised(PanelId::Chart);
    crate::harness::with_lights(&mut state, 5);
    let Some(mut h) = lab((1000.0, 600.0), state) else {
        return;
    };
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("assets/methods/ltc.wgsl");
    let file = ltc_lab::gpu::method_file::MethodFile::read(&path).unwrap();
    h.state_mut().start_with(ltc_lab::app::Startup {
        scene: None,
        lights: None,
        panel: None,
        measure: true,
        lesson: None,
        method_file: Some(file),
    });
    // The file's task follows the lab's methods on the scene (seconds on lavapipe); the
    // deadline only ends a measurement that never reaches it.
    h.run_steps(2);
    let start = std::time::Instant::now();
    while !shows(&h, "measuring file: ltc.wgsl") {
        assert!(
            start.elapsed() < std::time::Duration::from_secs(240) && shows(&h, "measuring"),
            "the measurement never timed the method file"
        );
        h.step();
    }
    h.get_by_label("cancel").click();
    h.run_steps(2);
}
