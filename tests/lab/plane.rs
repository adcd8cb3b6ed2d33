//! The plane panel: its render summed over frames, the split and its divider, the pinned
//! pixel's lights, two tables compared, the worst pixel, new lights.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ltc_lab::app::plane::render_settings;
use ltc_lab::app::{LabApp, PanelId};
use ltc_lab::gpu::plane::ShaderChecks;
use ltc_lab::gpu::renderer::PlaneRenderer;
use ltc_lab::metrics::luminance;
use ltc_lab::pixel::{PixelTerms, pixel_terms};
use ltc_lab::render::{Frame, RenderSettings, View};

use crate::gpu_common::{self, bits};
use crate::harness::{
    click_at, drag_along, lab, maximised, notice, opened, plane_image, plane_state, settle, shows,
    slide, type_into,
};

/// What the plane renders at `size`, as the lab's settings say, shown as `view`.
fn settings(h: &Harness<'static, LabApp>, view: View, size: (usize, usize)) -> RenderSettings {
    let plane = h.state().state().plane;
    RenderSettings {
        view,
        ..render_settings(h.state().lab(), &plane, size)
    }
}

/// `settings` rendered whole, in one submission, on the lab's own device, with its tables.
fn one_shot(h: &Harness<'static, LabApp>, settings: &RenderSettings) -> Frame {
    let lab = h.state().lab();
    let ctx = lab.device().expect("the lab has a GPU");
    let (a, b) = (&lab.tables().a().lut, &lab.tables().b().lut);
    let mut r = PlaneRenderer::new(ctx, a, ShaderChecks::Checked).unwrap();
    r.set_tables(ctx, a, Some(b)).unwrap();
    r.render(ctx, &lab.shaded_scene(), settings).unwrap().0
}

/// The plane's image saved, and the lab's render of it made whole as `view` shows it.
fn saved_and_whole(h: &mut Harness<'static, LabApp>, view: View) -> (Frame, Frame) {
    let saved = plane_image(h);
    let whole = one_shot(h, &settings(h, view, (saved.width, saved.height)));
    (saved, whole)
}

/// The plane's render's size, as the lab reports it.
fn plane_size(h: &Harness<'static, LabApp>) -> (usize, usize) {
    let [w, hgt] = h
        .state()
        .report()
        .plane_size
        .expect("the plane has rendered");
    (w, hgt)
}

fn same_pixels(a: &Frame, b: &Frame) -> bool {
    bits(a) == bits(b)
}

#[test]
fn dragging_the_divider_moves_it() {
    let Some(mut h) = lab((1000.0, 700.0), plane_state(100)) else {
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
    let divider = h.state().state().plane.divider;
    assert!((divider - 0.25).abs() < 0.02, "divider at {divider}");
    // The rendered split follows it: left of its column LTC alone, right of it the BRDF.
    let split = plane_image(&mut h);
    let size = (split.width, split.height);
    let (a, b) = (
        one_shot(&h, &settings(&h, View::A, size)),
        one_shot(&h, &settings(&h, View::B, size)),
    );
    let column = (split.width as f64 * divider).round() as usize;
    let from = |f: &Frame, x: usize| -> Vec<glam::DVec3> {
        (0..f.height).map(|y| f.pixels[y * f.width + x]).collect()
    };
    for x in [0, column - 1, column, split.width - 1] {
        let side = if x < column { &a } else { &b };
        assert!(
            from(&split, x) == from(side, x),
            "column {x} of {}",
            split.width
        );
    }
}

/// Summed over many frames in paced chunks, the plane is the one-shot render to the bit: the
/// same f32 operations in the same order, the sums kept exactly in between (as
/// tests/gpu/render.rs shows for hand-picked chunks; here the lab's pacer picks them).
#[test]
fn the_plane_summed_over_frames_is_the_one_shot_render() {
    if gpu_common::gpu().is_none() {
        return;
    }
    let mut h = opened((900.0, 600.0), plane_state(300), None);
    let mut frames = 0;
    while h.state().report().plane[0] < 300 {
        h.step();
        frames += 1;
        assert!(frames < 100_000, "{:?}", h.state().report());
    }
    // 1, 2, 4 … 256: at least nine chunks, whatever the chunks' times.
    assert!(frames >= 9, "summed in only {frames} frames");
    settle(&mut h);
    assert_eq!(h.state().report().plane, [300, 300]);
    let (progressive, whole) = saved_and_whole(&mut h, View::Split);
    assert!(
        progressive.pixels.iter().any(|p| p.x > 0.0),
        "a black plane"
    );
    assert!(same_pixels(&progressive, &whole), "the images differ");
    assert!(
        shows(&h, "done: 300 / 300 lights"),
        "the progress line does not say it is done"
    );
}

/// A render in flight leaves every frame free: the window keeps running, shows the render in
/// progress, answers a change (which restarts the render) and finishes it. 2 000 lights: the
/// pacer's chunks start at one light and at most double, so the sums take at least eleven
/// frames after the tile lists.
#[test]
fn a_render_in_flight_never_stops_the_window() {
    if gpu_common::gpu().is_none() {
        return;
    }
    let mut h = opened((900.0, 600.0), plane_state(2000), None);
    // The first frame starts the render, the next draws its progress line.
    h.run_steps(2);
    assert!(h.state().busy(), "{:?}", h.state().report());
    // Culled (the default): the tile lists come first, then the sums.
    let said = ["binning lights into tiles", "rendering "]
        .iter()
        .any(|text| shows(&h, text));
    assert!(said, "the window does not show the render in progress");
    // The window still answers: the view changes, and the render starts again with it.
    h.get_by_label("difference").click();
    h.run_steps(1);
    assert!(h.state().report().remade.contains(&"plane.render"));
    assert!(h.state().busy());
    settle(&mut h);
    assert_eq!(h.state().report().plane, [2000, 2000]);
    let (saved, whole) = saved_and_whole(&mut h, View::Diff);
    assert!(same_pixels(&saved, &whole));
}

/// "A | B tables": side B shades the same LTC form with table B, as the CPU reference does
/// with the two tables (the GPU–CPU tolerance of tests/gpu/parity.rs); a table loaded "as B"
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
    let gpu = plane_image(&mut h);
    let s = settings(&h, View::Split, (gpu.width, gpu.height));
    assert!(s.b_reads_table_b && s.b.point() == s.a.point());
    let tables = ltc_lab::render::Tables {
        a: ltc_lab::ltc::lut::Lut::embedded(),
        b: ltc_lab::ltc::lut::Lut::embedded_point(),
    };
    let mut cpu = ltc_lab::cpu::render(&h.state().lab().shaded_scene(), tables, &s);
    // The saved image holds the plane's radiance only: off it, 0.
    for (p, on) in cpu.pixels.iter_mut().zip(&cpu.on_plane) {
        if !on {
            *p = glam::DVec3::ZERO;
        }
    }
    // Off the plane the saved image holds the background; the reference holds 0 there.
    let mut gpu = gpu;
    for (p, on) in gpu.pixels.iter_mut().zip(&cpu.on_plane) {
        if !on {
            *p = glam::DVec3::ZERO;
        }
    }
    gpu.on_plane = cpu.on_plane.clone();
    gpu_common::assert_close("A | B split", &gpu, &cpu);
    assert!(
        !same_pixels(&gpu, &ltc_against_brdf),
        "side B is still the BRDF"
    );
    // A file as table B.
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("mine.exr");
    ltc_lab::ltc::lut::Lut::embedded_point()
        .write(&file)
        .unwrap();
    type_into(&mut h, "table file", &file.display().to_string());
    // The matrix panel, under its tab (the grid does not fit 1000 points).
    h.get_by_label("restore").click();
    h.run_steps(2);
    h.get_by_label("Matrix and LUT").click();
    h.run_steps(1);
    h.get_by_label("as B").click();
    settle(&mut h);
    let tables = h.state().lab().tables();
    assert!(!tables.b_is_default() && tables.b().name.ends_with("mine.exr"));
    assert!(!notice(&h).unwrap().is_error);
    assert!(
        shows(&h, "mine.exr): M^-1"),
        "the matrix panel does not name table B"
    );
    // The next start compares with the same file.
    let again = LabApp::new(h.state().state(), None);
    let b = again.lab().tables().b();
    assert!(b.name.ends_with("mine.exr"));
    assert_eq!(b.lut, h.state().lab().tables().b().lut);
    h.get_by_label("point").click();
    settle(&mut h);
    assert!(
        h.state().lab().tables().b().name.ends_with("mine.exr"),
        "table B did not stay"
    );
    h.get_by_label("reset").click();
    settle(&mut h);
    assert_eq!(h.state().lab().tables().b().name, "classic");
    assert_eq!(
        h.state().state().lab.tables.b().source,
        ltc_lab::tables::Source::Shipped(ltc_lab::ltc::lut::Table::Classic)
    );
}

/// The pinned pixel's lights as the library opens them (`pixel::pixel_terms`, what the
/// panel's table shows), at the lab's pinned pixel of an image of `size`.
fn pinned_terms(
    h: &Harness<'static, LabApp>,
    size: (usize, usize),
) -> (PixelTerms, [f64; 2], ltc_lab::render::SurfacePoint) {
    let lab = h.state().lab();
    let [u, v] = h.state().state().plane.pinned.expect("a pixel pinned");
    let scene = lab.shaded_scene();
    let (w, hgt) = size;
    let p = scene
        .surface_point_at(u * w as f64, v * hgt as f64, w, hgt)
        .unwrap();
    let tables = lab.tables();
    let b = (**lab.side_b() == ltc_lab::app::lab::SideB::TableB).then_some(&tables.b().lut);
    let terms = pixel_terms(
        &scene,
        (&tables.a().lut, b),
        &p,
        lab.rules(),
        (&lab.shape_forms().ltc, &lab.shape_forms().brdf),
    )
    .unwrap();
    (terms, [u, v], p)
}

#[test]
fn a_pinned_pixel_opens_into_its_lights_and_one_shows_on_the_lobe() {
    let Some(mut h) = lab((1000.0, 700.0), maximised(PanelId::Plane)) else {
        return;
    };
    let size = plane_size(&h);
    let rect = h.get_by_label("plane image").rect();
    // Beside the lights' markers: the near half of the plane, a fifth from the left.
    let at = egui::pos2(
        rect.min.x + rect.width() * 0.2,
        rect.min.y + rect.height() * 0.8,
    );
    click_at(&mut h, at);
    settle(&mut h);
    let (t, [u, v], _) = pinned_terms(&h, size);
    assert!(
        (u - 0.2).abs() < 0.01 && (v - 0.8).abs() < 0.01,
        "pinned at ({u}, {v})"
    );
    assert_eq!(t.terms.len(), h.state().lab().lights().list.len());
    // The readout, in its own strip: the pixel's exact radiance as the CPU reference has it,
    // under side B's name as the split gives it.
    let exact = ltc_lab::colormap::short_number(luminance(t.exact));
    assert!(shows(&h, "pinned (0.2"));
    assert!(
        shows(&h, &format!("| BRDF {exact} (luminance)")),
        "no exact {exact}"
    );
    // Sorted by the share of the error, largest first: click the top row's index.
    let top =
        ltc_lab::app::plane::pixel_table::sorted_rows(&t, h.state().state().plane.light_sort)[0];
    let (index, omega) = (top.index, top.omega);
    h.get_by_label(&index.to_string()).click();
    h.run_steps(2);
    let lab = h.state().lab();
    assert_eq!(lab.lobe_view().light, Some(omega.to_array()));
    assert_eq!(lab.selection().light, Some(index));
    h.snapshot_options(
        "plane_pixel_pinned_lights",
        &crate::harness::options(1000 * 700),
    );
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
    let exposure = h.state().lab().exposure().0;
    slide(&mut h, "exposure", exposure * 4.0);
    assert_eq!(h.state().lab().exposure().0, exposure * 4.0);
    assert!(
        !h.state().report().remade.contains(&"plane.render") && !h.state().busy(),
        "an exposure change restarted the render"
    );
    h.run_steps(2);
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
    slide(&mut h, "lights", 0.0);
    settle(&mut h);
    assert_eq!(h.state().report().plane, [0, 0]);
    assert_eq!(
        lit(&plane_image(&mut h)),
        0,
        "the last image is still there"
    );
}

/// In "A | B tables" the title says which tables are compared, and the pinned pixel opens
/// into table A against table B per light: each light's LTC with either table, as the CPU
/// reference shades that light alone, and its share of Σ|A − B|, sortable.
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
    let size = plane_size(&h);
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
    assert!(shows(&h, "(luminance), difference"));
    let (t, _, p) = pinned_terms(&h, size);
    let lab = h.state().lab();
    let scene = lab.shaded_scene();
    let y = ltc_lab::metrics::luminance;
    let (a, b) = (&lab.tables().a().lut, &lab.tables().b().lut);
    let rules = lab.rules();
    let alone = |lut, i: usize| {
        y(ltc_lab::cpu::shade_ltc(
            &scene,
            lut,
            &p,
            &scene.lights[i..=i],
            rules,
        ))
    };
    let largest = |f: &dyn Fn(usize) -> f64| {
        (0..scene.lights.len())
            .max_by(|&i, &j| f(i).total_cmp(&f(j)))
            .unwrap()
    };
    // Sorted by the share of |A − B|, largest first: the light whose own |A − B| is largest
    // is the table's first row.
    let first_row = |h: &Harness<'static, LabApp>| {
        let sort = h.state().state().plane.light_sort;
        ltc_lab::app::plane::pixel_table::sorted_rows(&t, sort)[0].index
    };
    assert_eq!(
        first_row(&h),
        largest(&|i| (alone(a, i) - alone(b, i)).abs())
    );
    // Sorted by table B's column: the brightest light under table B.
    let by_b = largest(&|i| alone(b, i));
    h.get_by_label("table B").click();
    h.run_steps(2);
    assert_eq!(first_row(&h), by_b);
}

/// *worst pixel* pins the pixel where the two sides differ most, LTC against the BRDF and
/// then table A against table B: the largest |L_A − L_B| / max(L_B, floor) of the two sides
/// rendered alone and compared here in f64 with the difference view's floor
/// (metrics::relative_floor), within the GPU's diff-view tolerance (tests/gpu_common).
#[test]
fn the_worst_pixel_button_pins_the_largest_difference_in_either_mode() {
    let Some(mut h) = lab((1000.0, 700.0), maximised(PanelId::Plane)) else {
        return;
    };
    for (mode, readout) in [
        ("LTC | BRDF", "(luminance), error"),
        ("A | B tables", "(luminance), difference"),
    ] {
        h.get_by_label(mode).click();
        settle(&mut h);
        h.get_by_label("worst pixel").click();
        settle(&mut h);
        let state = h.state().state();
        assert_eq!(state.plane.view, View::Diff, "{mode}");
        let [u, v] = state.plane.pinned.expect("worst pixel pinned none");
        let size = {
            let f = plane_image(&mut h);
            (f.width, f.height)
        };
        let (sa, sb) = (
            one_shot(&h, &settings(&h, View::A, size)),
            one_shot(&h, &settings(&h, View::B, size)),
        );
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
        assert!(shows(&h, readout), "{mode}: no '{readout}'");
    }
}

/// *+ light* puts each new light where it is seen: projected inside the image, away from the
/// split's divider and from every other light's marker.
#[test]
fn a_new_light_is_seen_away_from_the_divider_and_the_other_lights() {
    let Some(mut h) = lab((1000.0, 700.0), maximised(PanelId::Plane)) else {
        return;
    };
    let held = h.state().lab().lights().list.len();
    for _ in 0..2 {
        h.get_by_label("+ light").click();
        h.run_steps(2);
    }
    let (w, hgt) = plane_size(&h);
    let scene = h.state().lab().scene();
    assert_eq!(scene.lights.len(), held + 2);
    let seen = |k: usize| {
        scene
            .project(glam::DVec3::from(scene.lights[k].position), w, hgt)
            .unwrap()
    };
    let divider = h.state().state().plane.divider * w as f64;
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

/// An image in flight is a preview of the whole: its partial sum scaled to every light (a
/// dark fraction of the image looked finished), said so, with the time left once the render
/// has run a second (`Progress::time_left`, at the rate so far).
#[test]
fn a_render_in_flight_is_previewed_at_full_scale_and_says_so() {
    use ltc_lab::app::plane::shading::Progress;
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
    crate::harness::with_lights(&mut state, 1000);
    let Some(mut h) = lab((800.0, 500.0), state) else {
        return;
    };
    // A restart: binned into tiles first, then summed in chunks that start at one light
    // (the pacer), so its first summed frames leave it in flight.
    slide(&mut h, "lights", 1001.0);
    for _ in 0..1000 {
        h.step();
        if h.state().report().plane[0] > 0 {
            break;
        }
    }
    // One more frame: the progress line is drawn before the frame's chunk is summed.
    h.step();
    let [done, total] = h.state().report().plane;
    assert!(done < total, "the render finished at once");
    assert!(
        shows(&h, "preview: the sum so far × "),
        "the preview is not said"
    );
    settle(&mut h);
    assert!(!shows(&h, "preview"));
}
