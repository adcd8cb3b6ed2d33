//! A method file in the lab (docs/design.md §5.13), as a user meets it: loaded from the
//! *load method* button's field or dropped on the window, it shades side A as `file`; a file
//! with an error changes nothing and says where; a link naming the method file opens without
//! it and says so.

use crate::harness::{drop_file, lab, notice, plane_image, plane_state, press, settle, type_into};
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
