//! A method file in the lab (docs/design.md §5.13), as a user meets it: loaded from the
//! *load method* button's field or dropped on the window, it shades side A as `file`; a file
//! with an error changes nothing and says where; a link naming the method file opens without
//! it and says so.

use crate::harness::{
    click_at, drop_file, lab, load_sized_preset, maximised, notice, options, plane_image,
    plane_state, press, settle, shows, type_into, with_lights,
};
use egui_kittest::kittest::Queryable;
use ltc_lab::app::lab::{Forms, Part};
use ltc_lab::render::Method;

fn example(name: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("assets/methods")
        .join(name)
}

#[test]
fn a_method_loaded_by_its_button_shades_side_a() {
    let Some(mut h) = lab((1280.0, 720.0), plane_state(20)) else {
        return;
    };
    let path = example("ltc-disk-points.wgsl");
    type_into(&mut h, "method file", &path.display().to_string());
    press(&mut h, "load method");
    settle(&mut h);
    let said = notice(&h).expect("a notice");
    assert!(!said.is_error, "{}", said.text);
    assert!(said.text.contains("ltc-disk-points.wgsl"), "{}", said.text);
    assert_eq!(h.state().lab().forms().ltc, Method::File);
    let image = plane_image(&mut h);
    let lit = image.pixels.iter().filter(|p| p.length() > 0.0).count();
    assert!(image.pixels.iter().all(|p| p.is_finite()));
    assert!(lit > image.pixels.len() / 10, "{lit} lit pixels");
}

#[test]
fn a_dropped_method_with_an_error_changes_nothing_and_says_where() {
    let Some(mut h) = lab((1280.0, 720.0), plane_state(5)) else {
        return;
    };
    let dir = std::env::temp_dir().join(format!("ltc-lab-method-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let broken = dir.join("broken.wgsl");
    std::fs::write(
        &broken,
        "fn method_point(pixel: MethodPixel, light: MethodPoint) -> MethodRadiance {\n    let x = brightness;\n    return MethodRadiance(vec3<f32>(x), vec3<f32>(0.0));\n}\n",
    )
    .unwrap();
    let before = h.state().lab().forms().ltc;
    drop_file(&mut h, &broken);
    settle(&mut h);
    let said = notice(&h).expect("a notice");
    assert!(said.is_error, "{}", said.text);
    assert!(
        said.text.contains("broken.wgsl") && said.text.contains("line 2, column 13"),
        "{}",
        said.text
    );
    assert_eq!(h.state().lab().forms().ltc, before);
    assert!(h.state().lab().method_file().is_none());
    // A good one dropped after it loads.
    drop_file(&mut h, &example("no-case2.wgsl"));
    settle(&mut h);
    assert_eq!(
        h.state().lab().method_file().map(|f| f.name.as_str()),
        Some("no-case2.wgsl")
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_link_naming_the_method_file_opens_without_it_and_says_so() {
    let mut state = plane_state(5);
    state.lab.forms = Part::new(Forms {
        ltc: Method::File,
        ..Forms::default()
    });
    // As a link carries it: the state's text, decoded (no shader code in it, only the name).
    let link = ltc_lab::app::link::encode(&state);
    let opened = ltc_lab::app::link::decode(&link, &ltc_lab::app::LabState::default()).unwrap();
    assert_eq!(
        opened.lab.forms.ltc,
        Method::File,
        "the link names the method"
    );
    let Some(h) = lab((1280.0, 720.0), opened) else {
        return;
    };
    assert_eq!(h.state().lab().forms().ltc, Forms::default().ltc);
    assert!(h.state().lab().method_file().is_none());
    let said = notice(&h).expect("a notice");
    assert!(
        said.text.contains("never carries shader code"),
        "{}",
        said.text
    );
}

/// The pinned pixel's table gives each light by the file, evaluated on the GPU, beside the
/// CPU's LTC and exact values (the values themselves: tests/gpu/method_file.rs).
/// The shipped example `name` loaded by the *load method* field, then the plane's pixel at
/// `[u, v]` of its image pinned by a click.
fn load_and_pin(
    h: &mut egui_kittest::Harness<'static, ltc_lab::app::LabApp>,
    name: &str,
    [u, v]: [f32; 2],
) {
    type_into(h, "method file", &example(name).display().to_string());
    press(h, "load method");
    settle(h);
    let rect = h.get_by_label("plane image").rect();
    click_at(
        h,
        egui::pos2(
            rect.min.x + rect.width() * u,
            rect.min.y + rect.height() * v,
        ),
    );
    settle(h);
}

#[test]
fn the_pinned_pixel_gives_each_light_by_the_file() {
    let Some(mut h) = lab((1000.0, 700.0), maximised(ltc_lab::app::PanelId::Plane)) else {
        return;
    };
    load_and_pin(&mut h, "ltc.wgsl", [0.2, 0.8]);
    assert!(shows(
        &h,
        "each light by the method file ltc.wgsl (on the GPU)"
    ));
    assert!(!shows(&h, "the method file's values:"), "the probe failed");
}

/// At 1280×720 with a rect preset and three.js's rect as the file, the pinned pixel's
/// headline names each side's method (the file, then the BRDF with its rect method), the
/// file's rows come first, and the lights table's columns, the rects' methods to the last,
/// lie inside the plane's panel: none is cut off.
#[test]
fn the_pinned_pixel_names_each_side_and_fits_1280_by_720() {
    let Some(mut h) = lab((1280.0, 720.0), maximised(ltc_lab::app::PanelId::Plane)) else {
        return;
    };
    load_sized_preset(&mut h, "rect-horizon");
    // The image unpinned spans the panel's width (less its margins): the table must fit it.
    let rect = h.get_by_label("plane image").rect();
    load_and_pin(&mut h, "threejs-rect.wgsl", [0.45, 0.6]);
    let headline = h
        .query_by_label_contains("pinned (")
        .and_then(|n| n.value())
        .expect("the pinned pixel's headline");
    assert!(
        headline.contains("threejs-rect.wgsl (rect: file) ")
            && headline.contains("| BRDF (rect: exact) "),
        "{headline}"
    );
    let file_title = h
        .query_by_label_contains("each light by the method file threejs-rect.wgsl (on the GPU)")
        .expect("the file's rows")
        .rect();
    let first_header = h.get_by_label("#").rect();
    assert!(
        file_title.max.y <= first_header.min.y,
        "the file's rows ({file_title:?}) are not above the lab's ({first_header:?})"
    );
    // Every column of both tables within the image's width (the panel's, less its margins).
    // (The sorted column's header ends in its arrow: "error share v".)
    for label in ["E", "error share", "F(v·h)", "ltc-point", "exact"] {
        let nodes: Vec<_> = h.query_all_by_label_contains(label).collect();
        assert!(!nodes.is_empty(), "no column {label:?}");
        for node in nodes {
            assert!(
                node.rect().max.x <= rect.max.x + 1.0,
                "column {label:?} ends at x = {}, past the panel's {}",
                node.rect().max.x,
                rect.max.x
            );
        }
    }
    h.snapshot_options("plane_pinned_file_1280x720", &options(1280 * 720));
}

/// A method whose loop never ends is stopped — by its step guard, or by the lab's limit on a
/// batch, whichever comes first — and the lab says which file and why, puts its side back to
/// the lab's form, and goes on drawing.
#[test]
fn a_method_that_never_ends_is_stopped_and_named() {
    // Three lights: each costs the guard's 16 384 steps at every pixel (a second on lavapipe).
    let mut state = maximised(ltc_lab::app::PanelId::Plane);
    with_lights(&mut state, 3);
    let Some(mut h) = lab((640.0, 400.0), state) else {
        return;
    };
    let dir = std::env::temp_dir().join(format!("ltc-lab-forever-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let forever = dir.join("forever.wgsl");
    std::fs::write(
        &forever,
        "fn method_point(pixel: MethodPixel, light: MethodPoint) -> MethodRadiance {\n    var x = 0.0;\n    loop { x += 1.0; }\n    return MethodRadiance(vec3<f32>(x), vec3<f32>(0.0));\n}\n",
    )
    .unwrap();
    drop_file(&mut h, &forever);
    assert_eq!(h.state().lab().forms().ltc, Method::File);
    settle(&mut h);
    let said = notice(&h).expect("a notice");
    assert!(said.is_error, "{}", said.text);
    assert!(
        said.text.contains("forever.wgsl") && said.text.contains("stopped"),
        "{}",
        said.text
    );
    assert_ne!(h.state().lab().forms().ltc, Method::File);
    // The lab goes on: its own method renders (begun once the side went back).
    settle(&mut h);
    let image = plane_image(&mut h);
    assert!(image.pixels.iter().any(|p| p.length() > 0.0));
    std::fs::remove_dir_all(&dir).ok();
}
