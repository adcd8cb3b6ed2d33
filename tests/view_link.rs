//! The lab's view links (app/link.rs): what *share view* writes opens the same view, in the
//! browser (`#view=…`) and on the desktop (`ltc-lab lab --view`); a link that is broken or
//! edited by hand is refused with a reason, never half-applied.

use base64::Engine;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use ltc_lab::app::link::{decode, encode};
use ltc_lab::app::state::PanelId;
use ltc_lab::app::{Compare, LabState};
use ltc_lab::ltc::remedy::HorizonRule;
use ltc_lab::render::View;

/// A state far from the defaults in every part a link carries (and in some it does not).
fn changed_state() -> LabState {
    let mut s = LabState::default();
    s.lab.theta_o_deg = 63.5;
    s.lab.scene.material.alpha = 0.61;
    s.lab.scene.camera.position = [1.0, -2.0, 1.5];
    s.lab.seed = 9;
    s.lab.set_light_count(2500);
    s.lab.horizon = HorizonRule::ExactBand;
    s.lab.compare = Compare::TableB;
    s.lab.cull = false;
    s.lab.selected_light = Some(7);
    s.lobe.morph = 0.25;
    s.plane.view = View::Diff;
    s.plane.divider = 0.3;
    s.plane.pinned = Some([0.25, 0.75]);
    s.window.maximised = Some(PanelId::Clipping);
    s
}

#[test]
fn a_view_round_trips_exactly() {
    let state = changed_state();
    let link = encode(&state);
    assert_eq!(decode(&link, &LabState::default()).unwrap(), state);
    // As a whole URL, and as the fragment alone.
    let url = format!("http://127.0.0.1:8000/index.html#view={link}");
    assert_eq!(decode(&url, &LabState::default()).unwrap(), state);
    assert_eq!(
        decode(&format!("#view={link}"), &LabState::default()).unwrap(),
        state
    );
}

/// 2500 generated lights travel as their count: the link stays short enough to paste into a
/// chat or a slide (well under the ~2000 characters old tools cut URLs at).
#[test]
fn a_generated_scene_is_a_short_link() {
    let link = encode(&changed_state());
    assert!(link.len() < 1000, "{} characters", link.len());
    assert!(encode(&LabState::default()).len() < 1000);
}

/// A dragged light is carried as the scene file would save it (rounded to 1e-4).
#[test]
fn moved_lights_travel_as_saved() {
    let mut state = LabState::default();
    state.lab.scene.lights[3].position = [0.123456789, -1.0, 0.333333333];
    let opened = decode(&encode(&state), &LabState::default()).unwrap();
    assert_eq!(opened.lab.scene, state.lab.scene.rounded_for_saving());
    assert_eq!(opened.lab.scene.lights[3].position, [0.1235, -1.0, 0.3333]);
}

/// What belongs to one machine stays on it: the files tables came from, a refit, the chart
/// and the file fields keep the opening lab's values.
#[test]
fn machine_parts_do_not_travel() {
    let mut sender = changed_state();
    sender.lab.table_file = Some("/home/teacher/my.exr".into());
    sender.controls.scene_path = "/home/teacher/lecture.toml".into();
    let mut receiver = LabState::default();
    receiver.controls.scene_path = "mine.toml".into();
    let opened = decode(&encode(&sender), &receiver).unwrap();
    assert_eq!(opened.lab.table_file, None);
    assert_eq!(opened.controls.scene_path, "mine.toml");
    assert!(!encode(&sender).contains("teacher"));
}

fn packed(ron_text: &str) -> String {
    let bytes = miniz_oxide::deflate::compress_to_vec(ron_text.as_bytes(), 6);
    format!("v1.{}", URL_SAFE_NO_PAD.encode(bytes))
}

/// A hand-made link with only some parts: the rest are the defaults.
#[test]
fn a_partial_view_fills_in_defaults() {
    let opened = decode(
        &packed("(lab:(theta_o_deg:30.0),window:(maximised:Some(Matrix)))"),
        &LabState::default(),
    )
    .unwrap();
    assert_eq!(opened.lab.theta_o_deg, 30.0);
    assert_eq!(opened.window.maximised, Some(PanelId::Matrix));
    assert_eq!(opened.lab.scene, LabState::default().lab.scene);
}

#[test]
fn broken_views_say_why() {
    let good = encode(&changed_state());
    let cases = [
        (String::new(), "starts with v1."),
        ("v2.AAAA".to_string(), "starts with v1."),
        (good[..good.len() / 2].to_string(), "cut short"),
        (
            format!("v1.{}", &good[3..3 + (good.len() - 3) / 2 / 4 * 4]),
            "unpack",
        ),
        (format!("{good}!"), "base64"),
        (packed("(lab:(theta_o_deg:\"high\"))"), "does not read"),
        (
            packed("(lab:(scene:(plane:(half_size:-1.0))))"),
            "does not read",
        ),
        (packed("(generated:Some(99999999999))"), "lights"),
    ];
    for (link, why) in cases {
        let e = decode(&link, &LabState::default()).unwrap_err();
        assert!(e.contains(why), "{link:?}: {e}");
    }
}

/// A scene the lab cannot shade is refused whole, never half-applied.
#[test]
fn an_unshadable_scene_is_refused() {
    let mut state = LabState::default();
    state.lab.scene.material.alpha = 0.0;
    let e = decode(&encode(&state), &LabState::default()).unwrap_err();
    assert!(e.contains("material.alpha"), "{e}");
}
