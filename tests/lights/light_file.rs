//! A light as scene files, links and the lab's stored state write it (`scene::Light`): a
//! table whose shape is named by the vectors its module lists (`ShapeKind::vector_fields`).
//! Each shape's text is what the fields' order gives, RON's too, so that files and stored
//! state of before read back; a table naming two shapes, half a shape or a shape without its
//! radius is refused, naming the fields.

use glam::DVec3;
use ltc_lab::light::{Shape, ShapeKind};
use ltc_lab::scene::{Light, Scene};

fn light(shape: Shape) -> Light {
    Light {
        position: [0.0, 0.5, 1.0],
        color: [1.0, 0.5, 0.25],
        intensity: 2.0,
        range: None,
        shape,
    }
}

/// One light of each shape, as the lab holds them.
fn every_shape() -> Vec<Light> {
    vec![
        light(Shape::Point),
        light(Shape::Sphere { radius: 0.1 }),
        light(Shape::Rect {
            half_u: DVec3::new(0.2, 0.0, 0.0),
            half_v: DVec3::new(0.0, -0.1, 0.0),
        }),
        Light {
            range: Some(3.0),
            ..light(Shape::Disk {
                normal: DVec3::new(0.0, 0.0, -1.0),
                radius: 0.25,
            })
        },
        light(Shape::Tube {
            half_axis: DVec3::new(0.5, 0.0, 0.0),
            radius: 0.03,
        }),
    ]
}

#[derive(serde::Serialize, serde::Deserialize, PartialEq, Debug)]
struct Lights {
    lights: Vec<Light>,
}

/// The TOML of each shape: the fixed fields, then the shape's own in its module's order, an
/// absent range and a zero radius left out.
#[test]
fn each_shape_writes_its_fields_in_order_and_reads_back() {
    let all = Lights {
        lights: every_shape(),
    };
    let text = toml::to_string(&all).unwrap();
    let head = "position = [0.0, 0.5, 1.0]\ncolor = [1.0, 0.5, 0.25]\nintensity = 2.0\n";
    let want = [
        String::new(),
        "radius = 0.1\n".into(),
        "half_u = [0.2, 0.0, 0.0]\nhalf_v = [0.0, -0.1, 0.0]\n".into(),
        "range = 3.0\nradius = 0.25\nnormal = [0.0, 0.0, -1.0]\n".into(),
        "radius = 0.03\nhalf_axis = [0.5, 0.0, 0.0]\n".into(),
    ]
    .map(|tail| format!("[[lights]]\n{head}{tail}"))
    .join("\n");
    assert_eq!(text, want);
    assert_eq!(toml::from_str::<Lights>(&text).unwrap(), all);
    // Every shape's vectors are its module's, named once across the shapes.
    let mut names: Vec<&str> = ShapeKind::ALL
        .iter()
        .flat_map(|k| k.vector_fields().iter().map(|f| f.name))
        .collect();
    let count = names.len();
    names.sort();
    names.dedup();
    assert_eq!(names.len(), count, "{names:?}");
}

/// The lab's stored state (RON): written as before (an optional field as `Some(…)`), and what
/// an earlier lab stored reads back.
#[test]
fn stored_state_of_every_shape_reads_back_and_reads_as_before() {
    for l in every_shape() {
        let text = ron::to_string(&l).unwrap();
        assert_eq!(ron::from_str::<Light>(&text).unwrap(), l, "{text}");
    }
    let rect = ron::to_string(&every_shape()[2]).unwrap();
    assert_eq!(
        rect,
        "(position:[0.0,0.5,1.0],color:[1.0,0.5,0.25],intensity:2.0,half_u:Some([0.2,0.0,0.0]),half_v:Some([0.0,-0.1,0.0]))"
    );
    let earlier = "(position:[0.0,0.5,1.0],color:[1.0,0.5,0.25],intensity:2.0,range:Some(3.0),radius:0.25,normal:Some([0.0,0.0,-1.0]))";
    let disk = ron::from_str::<Light>(earlier).unwrap();
    assert_eq!(
        disk.shape,
        Shape::Disk {
            normal: DVec3::new(0.0, 0.0, -1.0),
            radius: 0.25
        }
    );
    assert_eq!(disk.range, Some(3.0));
    // A field twice, which RON reads: refused, naming it.
    let twice = "(position:[0.0,0.0,1.0],intensity:1.0,half_axis:Some([0.5,0.0,0.0]),radius:0.1,half_axis:Some([0.5,0.0,0.0]))";
    let e = ron::from_str::<Light>(twice).unwrap_err().to_string();
    assert!(
        e.contains("duplicate field") && e.contains("half_axis"),
        "{e}"
    );
}

/// Half a shape, two shapes, a shape without its radius or with one it has not, an unknown or
/// repeated field: refused, naming what is wrong, the file and the light.
#[test]
fn a_light_naming_no_one_shape_is_refused() {
    let base = "[plane]\nhalf_size = 2.0\n[material]\nbase_color = [0.5, 0.5, 0.5]\nf0 = 0.04\nalpha = 0.27\n[camera]\nposition = [0.0, -3.4, 2.8]\ntarget = [0.0, -0.1, 0.0]\nfov_y_degrees = 40.0\n[[lights]]\nposition = [0.0, 0.0, 1.0]\nintensity = 1.0\n";
    for (extra, want) in [
        ("half_axis = [0.5, 0.0, 0.0]\n", "needs a radius"),
        ("half_u = [0.1, 0.0, 0.0]\n", "needs both half_u and half_v"),
        (
            "radius = 0.1\nhalf_u = [0.1, 0.0, 0.0]\nhalf_v = [0.0, 0.1, 0.0]\n",
            "not both",
        ),
        (
            "radius = 0.1\nhalf_axis = [0.5, 0.0, 0.0]\nnormal = [0.0, 0.0, -1.0]\n",
            "not both",
        ),
        (
            "radius = 0.1\nhalf_axis = [0.5, 0.0, 0.0]\nnormal = [0.0, 0.0, -1.0]\nhalf_u = [0.1, 0.0, 0.0]\nhalf_v = [0.0, 0.1, 0.0]\n",
            "one shape's, not several",
        ),
        ("radius = 0.1\nhalf_axis = [0.5, 0.0]\n", "exactly 3"),
        (
            "radius = 0.1\nhalf_axis = [nan, 0.0, 0.0]\n",
            "lights[0].half_axis",
        ),
        (
            "radius = 0.1\nhalf_axes = [0.5, 0.0, 0.0]\n",
            "unknown field `half_axes`",
        ),
        // TOML refuses a repeated key itself.
        ("radius = 0.1\nradius = 0.2\n", "duplicate key"),
        ("colour = [1.0, 1.0, 1.0]\n", "unknown field `colour`"),
    ] {
        let e = Scene::from_toml(&format!("{base}{extra}"), "s.toml")
            .unwrap_err()
            .to_string();
        assert!(e.contains("s.toml") && e.contains(want), "{extra}: {e}");
    }
    // Missing what every light needs.
    let e = Scene::from_toml(&base.replace("intensity = 1.0\n", ""), "s.toml")
        .unwrap_err()
        .to_string();
    assert!(e.contains("intensity"), "{e}");
}
