//! What the panels share: each edit changes one part, and exactly the caches that read that
//! part are made again (the frame's report names them); a view from anyone — every number of
//! it non-finite, zero, negative or huge — opens a drawn lab, each value brought within its
//! range and said, or is refused whole.

use std::collections::BTreeSet;

use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use ltc_lab::app::lab::{Part, Selection};
use ltc_lab::app::{LabApp, LabState, PanelId, STORAGE_KEY};

use crate::gpu_common;
use crate::harness::{Kept, lab, opened, opened_from, settle, type_into};

/// Every cache of the lab, by the name the frame's report gives it.
const CACHES: [&str; 7] = [
    "lobe.sphere",
    "matrix.heat_maps",
    "plane.render",
    "plane.tables",
    "plane.pinned",
    "clipping.pictures",
    "clipping.elevation",
];

/// A slider set to `value` (a screen reader's way), taken at the next frame.
fn set(h: &mut Harness<'static, LabApp>, label: &str, value: f64) {
    h.get_by_role_and_label(Role::Slider, label)
        .set_value_accesskit(value);
}

/// The caches made again while `h` takes an edit (sent, not yet taken) and settles: the
/// union of every frame's.
fn remade(h: &mut Harness<'static, LabApp>) -> BTreeSet<&'static str> {
    let mut all = BTreeSet::new();
    let start = std::time::Instant::now();
    for _ in 0..3 {
        h.step();
        all.extend(h.state().report().remade);
    }
    while h.state().busy() {
        assert!(start.elapsed().as_secs() < 300, "{:?}", h.state().report());
        h.step();
        all.extend(h.state().report().remade);
    }
    all
}

/// The lab in its grid, where every panel and so every cache is shown, with a pixel pinned
/// (the pinned pixel's lights are a cache) and light 3 selected (its fields in the side
/// panel).
fn grid() -> Option<Harness<'static, LabApp>> {
    let mut state = LabState::default();
    state.plane.pinned = Some([0.3, 0.8]);
    state.lab.selection = Part::new(Selection { light: Some(3) });
    let mut h = lab((1600.0, 900.0), state)?;
    // Every cache made once, and nothing left in flight.
    let caches = h.state().report();
    assert!(!caches.busy, "{caches:?}");
    remade(&mut h);
    Some(h)
}

/// Dragging a light moves that light and redraws only what reads the lights: the plane (its
/// render and the pinned pixel's lights), not the lobe's sphere or the elevation view, which
/// read the material and the view (the drag re-measured the 20 ms elevation view every
/// frame).
#[test]
fn dragging_a_light_redraws_only_what_reads_the_lights() {
    let Some(mut h) = grid() else {
        return;
    };
    let [w, hgt] = h
        .state()
        .report()
        .plane_size
        .expect("the plane has rendered");
    let size = (w, hgt);
    let rect = h.get_by_label("plane image").rect();
    let scene = h.state().lab().scene();
    // Light 5's marker, where the plane's image draws it.
    let k = 5;
    let (x, y) = scene
        .project(glam::DVec3::from(scene.lights[k].position), size.0, size.1)
        .expect("light 5 is in view");
    let at =
        rect.min + egui::vec2(x as f32 / size.0 as f32, y as f32 / size.1 as f32) * rect.size();
    let before = h.state().lab().lights().list[k].position;
    h.drag_at(at);
    h.run_steps(1);
    let mut made = BTreeSet::new();
    for step in 1..=10 {
        h.hover_at(at + egui::vec2(3.0 * step as f32, 2.0 * step as f32));
        h.step();
        made.extend(h.state().report().remade);
    }
    h.drop_at(at + egui::vec2(30.0, 20.0));
    made.extend(remade(&mut h));
    let after = h.state().lab().lights().list[k].position;
    assert!(
        after[0] != before[0] && after[2] == before[2],
        "{before:?} -> {after:?}"
    );
    assert_eq!(
        made,
        BTreeSet::from(["plane.render", "plane.pinned"]),
        "a light's drag made these again"
    );
}

/// Each edit the side panel makes changes the parts it names, and exactly the caches that
/// read those parts are made again: what each panel's work reads (app/lab/parts/ names the
/// parts) is the specification here.
#[test]
fn every_side_panel_edit_invalidates_exactly_the_caches_that_read_it() {
    let Some(mut h) = grid() else {
        return;
    };
    let material = [
        "lobe.sphere",
        "plane.render",
        "plane.pinned",
        "clipping.elevation",
    ];
    let lights = ["plane.render", "plane.pinned"];
    let rules = [
        "plane.render",
        "plane.pinned",
        "clipping.pictures",
        "clipping.elevation",
    ];
    let tables = CACHES;
    type Edit = fn(&mut Harness<'static, LabApp>);
    let cases: Vec<(&str, Edit, Vec<&str>)> = vec![
        (
            "the selected light's x",
            |h| {
                // The side panel's (the clipping panel's light fields come after it).
                h.query_all_by_role_and_label(Role::SpinButton, "x")
                    .next()
                    .unwrap()
                    .set_value_accesskit(0.3);
            },
            lights.to_vec(),
        ),
        ("α", |h| set(h, "α", 0.4), material.to_vec()),
        (
            "roughness",
            |h| set(h, "roughness r = √α", 0.5),
            material.to_vec(),
        ),
        ("F0", |h| set(h, "F0", 0.5), material.to_vec()),
        (
            "θo",
            |h| set(h, "θo (°)", 60.0),
            vec!["lobe.sphere", "clipping.elevation"],
        ),
        (
            "intensity ×",
            |h| set(h, "intensity ×", 2.0),
            lights.to_vec(),
        ),
        ("range R", |h| set(h, "range R", 1.5), lights.to_vec()),
        (
            "radius r",
            |h| {
                h.get_by_label("lights with a size").click();
                h.run_steps(2);
                set(h, "radius r", 0.05);
            },
            lights.to_vec(),
        ),
        // Back to points: the sized lights' exact side is slow on a software GPU.
        (
            "radius r to 0",
            |h| set(h, "radius r", 0.0),
            lights.to_vec(),
        ),
        (
            "cull by range",
            |h| {
                // "lights with a size" folded again first, as a user leaves it: the rect
                // and disk controls under it push the rules below the side panel's view.
                h.get_by_label("lights with a size").click();
                h.run_steps(2);
                h.get_by_label("cull by range").click();
            },
            vec!["plane.render"],
        ),
        (
            "clip case 1",
            |h| h.get_by_label("clip case 1 (n·l ≤ 0)").click(),
            rules.to_vec(),
        ),
        (
            "clip case 2",
            |h| h.get_by_label("clip case 2 ((M^-1l).z ≤ 0)").click(),
            rules.to_vec(),
        ),
        (
            "paper-literal",
            |h| h.get_by_label("paper-literal normalization").click(),
            rules.to_vec(),
        ),
        ("lights", |h| set(h, "lights", 50.0), lights.to_vec()),
        (
            "the point table",
            |h| h.get_by_label("point").click(),
            tables.to_vec(),
        ),
        (
            "the embedded table",
            |h| {
                type_into(h, "table file", "");
                h.get_by_label("use LUT").click();
            },
            tables.to_vec(),
        ),
        ("a preset", |h| h.get_by_label("figure2-normal").click(), {
            let mut v = material.to_vec();
            v.extend(lights);
            v
        }),
    ];
    for (what, edit, expected) in cases {
        edit(&mut h);
        let made = remade(&mut h);
        let expected: BTreeSet<&str> = expected.into_iter().collect();
        assert_eq!(made, expected, "{what}");
    }
    // The forms, in their combo boxes: what the plane shades with, alone.
    // An entry of the combo box `combo`, as a user picks it: the box opened, then the open
    // list's entry (the chart's legend names the forms too, as labels).
    let pick = |h: &mut Harness<'static, LabApp>, combo: &str, entry: &str| {
        h.get_by_role_and_label(Role::ComboBox, combo).click();
        h.run_steps(2);
        h.query_all_by_label(entry)
            .find(|n| n.accesskit_node().role() != Role::Label)
            .unwrap()
            .click();
    };
    for (combo, form) in [("LTC form", "ltc"), ("BRDF form", "brdf-fast")] {
        pick(&mut h, combo, form);
        let made = remade(&mut h);
        assert_eq!(made, BTreeSet::from(["plane.render"]), "{combo}");
    }
    // How each side shades lights with a size: the plane and its pinned pixel read it (the
    // header opened again, which makes nothing).
    h.get_by_label("lights with a size").click();
    h.run_steps(2);
    for (combo, method) in [
        ("LTC side", "representative-point"),
        ("reference side", "ltc-point"),
    ] {
        pick(&mut h, combo, method);
        let made = remade(&mut h);
        assert_eq!(
            made,
            BTreeSet::from(["plane.render", "plane.pinned"]),
            "{combo}"
        );
    }
    // The plane's exposure is shown, not summed: nothing is made again.
    let exposure = h.state().lab().exposure().0;
    set(&mut h, "exposure", exposure * 2.0);
    assert_eq!(remade(&mut h), BTreeSet::new(), "the exposure");
    assert_eq!(h.state().lab().exposure().0, exposure * 2.0);
}

/// Every number a view can hold (here: of a kept state with two lights of its own), made
/// non-finite, zero, negative or huge, is brought within its range where the state enters
/// the lab — refused (its field keeps the default) or clamped, and said naming the field —
/// so that nothing non-finite or out of range is left, and checking again finds nothing.
/// A value the state's format cannot hold (NaN in an integer) fails to read: the view is
/// then refused whole.
#[test]
fn every_number_of_a_view_is_checked_where_it_enters() {
    let mut state = LabState::default();
    state.lab.lights = Part::new(ltc_lab::app::lab::Lights {
        list: ltc_lab::scene::preset("figure2-case2").lights,
        seed: 27,
    });
    state.plane.pinned = Some([0.4, 0.6]);
    let text = ron::to_string(&state).unwrap();
    let numbers = number_spans(&text);
    // The material's, the stage's, the light's, the panels' settings: some forty.
    assert!(
        numbers.len() > 30,
        "only {} numbers in the state",
        numbers.len()
    );
    let hostile = ["NaN", "inf", "-inf", "0", "0.0", "-1.0", "1e300", "-1e300"];
    let (mut read, mut refused) = (0, 0);
    for &(start, end) in &numbers {
        for value in hostile {
            let changed = format!("{}{value}{}", &text[..start], &text[end..]);
            let Ok(mut hostile_state) = ron::from_str::<LabState>(&changed) else {
                refused += 1;
                continue;
            };
            read += 1;
            let notes = hostile_state.check();
            let again = ron::to_string(&hostile_state).unwrap();
            let field = &text[start.saturating_sub(24)..end];
            assert!(
                !again.contains("NaN") && !again.contains("inf"),
                "{field}{value}: a non-finite value was kept"
            );
            if value.contains("inf") || value == "NaN" {
                assert!(!notes.is_empty(), "{field}{value}: refused without a word");
            }
            let mut checked = hostile_state.clone();
            assert_eq!(checked.check(), Vec::<String>::new(), "{field}{value}");
            assert_eq!(
                checked, hostile_state,
                "{field}{value}: the check is not settled"
            );
        }
    }
    // The floats take every hostile value; the integers refuse the non-integer ones.
    assert!(read > refused, "{read} read, {refused} refused");
}

/// Where each number literal of RON `text` lies: a digit (or a minus and a digit) that
/// starts a value, after ':', '(', '[' or ','.
fn number_spans(text: &str) -> Vec<(usize, usize)> {
    let bytes = text.as_bytes();
    let mut spans = Vec::new();
    let (mut k, mut before) = (0, b' ');
    while k < bytes.len() {
        let c = bytes[k];
        let digit_at = |i: usize| bytes.get(i).is_some_and(u8::is_ascii_digit);
        let starts = digit_at(k) || (c == b'-' && digit_at(k + 1));
        if starts && b":([,".contains(&before) {
            let end = (k + 1..bytes.len())
                .find(|&i| !(bytes[i].is_ascii_digit() || b"+-.eE".contains(&bytes[i])))
                .unwrap_or(bytes.len());
            spans.push((k, end));
            before = bytes[end - 1];
            k = end;
            continue;
        }
        if !c.is_ascii_whitespace() {
            before = c;
        }
        k += 1;
    }
    spans
}

/// Views that a hostile or broken link could carry, opened as the desktop and the browser
/// open them: each opens a drawn lab within seconds, with its field named in the notices bar
/// (a divider of NaN left the plane's render unfinished for ever; an intensity of NaN opened
/// as 100 with a white plane; a range of 1e-300 showed as "0.00" beside a black plane).
#[test]
fn hostile_views_open_a_drawn_lab_with_the_field_named() {
    if gpu_common::gpu().is_none() {
        return;
    }
    let cases = [
        ("(plane:(divider:NaN))", "the divider"),
        ("(lab:(overrides:(intensity_scale:NaN)))", "intensity ×"),
        ("(lab:(overrides:(range:1e-300)))", "range R"),
        (
            "(lab:(material:(base_color:[0.8,0.8,0.8],f0:0.04,alpha:inf)))",
            "material.alpha",
        ),
        ("(lab:(lobe_view:(theta_o_deg:-inf)))", "θo"),
        ("(lab:(exposure:0.0))", "exposure"),
        ("(plane:(pinned:Some((NaN,0.5))))", "pinned"),
        ("(lobe:(morph:1e300,orbit_pitch:NaN))", "the lobe's"),
        (
            "(clipping:(setup:(alpha:(NaN,0.5,1.0),light:((0.0,0.0,1.0),(0.0,0.0,-0.158731),(0.0,2.0,0.01)),table:A)))",
            "the clipping panel's α",
        ),
    ];
    for (ron_text, field) in cases {
        let view = packed(ron_text);
        let started = std::time::Instant::now();
        let mut h = opened((1600.0, 900.0), LabState::default(), Some(&view));
        settle(&mut h);
        // Seconds on lavapipe; a render that never finishes fails `settle` at its bound.
        assert!(
            started.elapsed().as_secs() < 120,
            "{ron_text}: {:?}",
            started.elapsed()
        );
        let said = h
            .state()
            .lab()
            .message()
            .map(|m| m.text.clone())
            .unwrap_or_default();
        assert!(said.contains(field), "{ron_text}: said '{said}'");
        let report = h.state().report();
        assert_eq!(report.plane[0], report.plane[1], "{ron_text}: {report:?}");
        assert!(report.panels.contains(&"plane"), "{ron_text}: {report:?}");
    }
}

/// A view's string as *share view* packs one: RON, raw deflate, URL-safe base64.
fn packed(ron_text: &str) -> String {
    use base64::Engine;
    let bytes = miniz_oxide::deflate::compress_to_vec(ron_text.as_bytes(), 6);
    format!(
        "v1.{}",
        base64::engine::general_purpose::URL_SAFE_NO_PAD.encode(bytes)
    )
}

/// What a previous run kept is input too: a store this lab cannot read (another version's,
/// or edited by hand) opens the defaults and says so, naming what it could not read.
#[test]
fn unreadable_kept_settings_open_the_defaults_and_say_so() {
    if gpu_common::gpu().is_none() {
        return;
    }
    let mut kept = Kept::default();
    eframe::Storage::set_string(
        &mut kept,
        STORAGE_KEY,
        "(lab:(theta_o_deg:30.0))".to_string(),
    );
    let mut h = opened_from((1600.0, 900.0), &kept, None);
    settle(&mut h);
    let said = h
        .state()
        .lab()
        .message()
        .map(|m| m.text.clone())
        .unwrap_or_default();
    assert!(
        said.contains("kept from the last run") && said.contains("theta_o_deg"),
        "said '{said}'"
    );
    let defaults = LabState::default().lab;
    assert_eq!(**h.state().lab().lobe_view(), *defaults.lobe_view);
    assert_eq!(**h.state().lab().material(), *defaults.material);
}

/// Only the grid's panels are shown alone: a view maximising the side panel is refused by
/// field, the lab opening in its grid.
#[test]
fn a_view_maximising_the_side_panel_opens_the_grid() {
    let mut state = LabState::default();
    state.window.maximised = Some(PanelId::Controls);
    let notes = state.check();
    assert_eq!(state.window.maximised, None);
    assert!(notes.iter().any(|n| n.contains("maximised")), "{notes:?}");
}
