//! The lab's view links (app/link.rs): what *share view* writes opens the same view, in the
//! browser (`#view=…`) and on the desktop (`ltc-lab lab --view`); a string that is not a
//! view is refused with a reason, never half-applied; what a view holds is checked where it
//! enters the lab, as any state is (tests/lab/parts.rs).

use base64::Engine;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use ltc_lab::app::lab::{Forms, Lights, LobeView, Part, Selection, SideB, Stage, Tables};
use ltc_lab::app::link::{decode, encode};
use ltc_lab::app::{LabState, PanelId};
use ltc_lab::ltc::lut::Table;
use ltc_lab::ltc::remedy::HorizonRule;
use ltc_lab::render::{LtcRules, View};
use ltc_lab::scene::Material;

/// A state far from the defaults in every part a link carries (and in some it does not).
fn changed_state() -> LabState {
    let mut s = LabState::default();
    s.lab.lobe_view = Part::new(LobeView {
        theta_o_deg: 63.5,
        ..LobeView::default()
    });
    s.lab.material = Part::new(Material {
        alpha: 0.61,
        ..Material::default()
    });
    let mut stage = Stage::default();
    stage.camera.position = [1.0, -2.0, 1.5];
    s.lab.stage = Part::new(stage);
    s.lab.lights = Part::new(Lights {
        list: Vec::new(),
        seed: 9,
    });
    let list = s.lab.generated_lights(2500);
    s.lab.lights = Part::new(Lights { list, seed: 9 });
    s.lab.rules = Part::new(LtcRules {
        horizon: HorizonRule::ExactBand,
        ..LtcRules::default()
    });
    s.lab.side_b = Part::new(SideB::TableB);
    s.lab.forms = Part::new(Forms {
        cull: false,
        ..Forms::default()
    });
    s.lab.selection = Part::new(Selection { light: Some(7) });
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
    let mut lights = (*state.lab.lights).clone();
    lights.list[3].position = [0.123456789, -1.0, 0.333333333];
    state.lab.lights = Part::new(lights);
    let opened = decode(&encode(&state), &LabState::default()).unwrap();
    let scene = ltc_lab::scene::Scene {
        lights: state.lab.lights.list.clone(),
        ..ltc_lab::scene::preset("paper-100")
    };
    assert_eq!(opened.lab.lights.list, scene.rounded_for_saving().lights);
    assert_eq!(opened.lab.lights.list[3].position, [0.1235, -1.0, 0.3333]);
}

/// What belongs to one machine stays on it: the files tables came from, a refit, the chart
/// and the file fields keep the opening lab's values.
#[test]
fn machine_parts_do_not_travel() {
    let mut sender = changed_state();
    let mine = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("luts/ltc_point.exr");
    let (table, _) = ltc_lab::tables::NamedTable::from_file(&mine.display().to_string()).unwrap();
    sender.lab.tables = Part::new(Tables::shipped(Table::Classic).with_a(table, Table::Classic));
    sender.controls.scene_path = "/home/teacher/lecture.toml".into();
    let mut receiver = LabState::default();
    receiver.controls.scene_path = "mine.toml".into();
    let opened = decode(&encode(&sender), &receiver).unwrap();
    assert_eq!(
        opened.lab.tables.a().source,
        ltc_lab::tables::Source::Shipped(Table::Classic)
    );
    assert_eq!(opened.controls.scene_path, "mine.toml");
    let link = encode(&sender);
    assert!(!link.contains("teacher") && !link.contains("ltc_point"));
}

fn packed(ron_text: &str) -> String {
    let bytes = miniz_oxide::deflate::compress_to_vec(ron_text.as_bytes(), 6);
    format!("v1.{}", URL_SAFE_NO_PAD.encode(bytes))
}

/// A hand-made link with only some parts: the rest are the defaults.
#[test]
fn a_partial_view_fills_in_defaults() {
    let opened = decode(
        &packed("(lab:(lobe_view:(theta_o_deg:30.0)),window:(maximised:Some(Matrix)))"),
        &LabState::default(),
    )
    .unwrap();
    assert_eq!(opened.lab.lobe_view.theta_o_deg, 30.0);
    assert_eq!(opened.window.maximised, Some(PanelId::Matrix));
    assert_eq!(opened.lab.material, LabState::default().lab.material);
}

/// A side's method for one shape travels by its name, the shape's others and the other
/// side as they were.
#[test]
fn a_shapes_method_travels_by_name() {
    use ltc_lab::light::ShapeKind;
    let opened = decode(
        &packed("(lab:(shape_forms:{\"rect\":(ltc:Some(\"ltc-proxy\"))}))"),
        &LabState::default(),
    )
    .unwrap();
    let forms = &opened.lab.shape_forms;
    assert_eq!(forms.ltc.of(ShapeKind::Rect).name(), "ltc-proxy");
    let defaults = LabState::default().lab.shape_forms;
    assert_eq!(forms.brdf, defaults.brdf);
    assert_eq!(
        forms.ltc.of(ShapeKind::Disk),
        defaults.ltc.of(ShapeKind::Disk)
    );
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
        (
            packed("(lab:(lobe_view:(theta_o_deg:\"high\")))"),
            "does not read",
        ),
        (
            packed("(lab:(stage:(plane:(half_size:-1.0))))"),
            "does not read",
        ),
        (packed("(generated:Some(99999999999))"), "lights"),
        // A field this lab does not have (a link of another format, or a typo) is refused
        // by name rather than opened without it.
        (packed("(lab:(theta_o_deg:30.0))"), "theta_o_deg"),
        (packed("(zoom:2.0)"), "zoom"),
    ];
    for (link, why) in cases {
        let e = decode(&link, &LabState::default()).unwrap_err();
        assert!(e.contains(why), "{link:?}: {e}");
    }
}

/// A view whose numbers are out of range opens with them brought within it, each said
/// naming its field (it was refused whole, which a teacher's hand-edited link did not
/// deserve for one number).
#[test]
fn an_out_of_range_view_opens_clamped_and_says_so() {
    let mut state = decode(
        &packed("(lab:(material:(base_color:[0.8,0.8,0.8],f0:0.04,alpha:0.0)))"),
        &LabState::default(),
    )
    .unwrap();
    let notes = state.check();
    assert_eq!(state.lab.material.alpha, ltc_lab::ltc::lut::ALPHA_MIN);
    assert!(
        notes.iter().any(|n| n.contains("material.alpha")),
        "{notes:?}"
    );
}
