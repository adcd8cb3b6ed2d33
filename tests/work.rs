//! Each method's work per light, counted from the plane shader as built (`gpu::work`): the
//! counting rules on small functions whose work is known, the design's one square root per
//! light of ltc-fast, and the counts of docs/design.md §4.10's table — which a shader change
//! must bring up to date.

use ltc_lab::gpu::work::{Work, work_of, work_per_light};
use ltc_lab::render::Method;

#[test]
fn the_counting_rules_on_functions_whose_work_is_known() {
    let src = "
override HORIZON: u32 = 0u;
@group(0) @binding(0) var<uniform> scale: vec4<f32>;
fn heavy(x: f32) -> f32 { return pow(x, 3.0) + exp(x) + x / 3.0; }
fn f(a: vec3<f32>, b: vec3<f32>, m: mat3x3<f32>) -> f32 {
    let d = dot(a, b);
    if d <= 0.0 {
        return heavy(d);
    }
    var r = sqrt(d) / 2.0 * scale.x;
    if HORIZON == 1u {
        r += heavy(r);
    }
    let w = m * a;
    return r + w.z;
}
@compute @workgroup_size(1) fn main() { _ = f(vec3<f32>(1.0), vec3<f32>(1.0), mat3x3<f32>()); }
";
    let w = work_of(src, "f").unwrap();
    // dot: 3 multiplies and 2 additions; the early exit's call not counted; sqrt, a division,
    // a multiply; HORIZON is 0, so its branch is not taken; m × a: 9 multiplies, 6 additions;
    // the last addition. One read (the uniform).
    assert_eq!(
        w,
        Work {
            arithmetic: 5 + 1 + 15 + 1,
            divisions: 1,
            special: 1,
            reads: 1,
        }
    );
    // heavy alone: pow and exp, a division, an addition each side.
    let h = work_of(src, "heavy").unwrap();
    assert_eq!((h.special, h.divisions, h.arithmetic), (2, 1, 2));
}

/// docs/design.md §4: "one square root per light" is what makes ltc-fast fast; the exact
/// BRDF needs more.
#[test]
fn ltc_fast_has_one_root_per_light_and_the_brdf_more() {
    let work = work_per_light().unwrap();
    let of = |m: Method| work.iter().find(|(x, _)| *x == m).unwrap().1;
    assert_eq!(of(Method::LtcFast).special, 1);
    assert!(of(Method::Brdf).special > of(Method::LtcFast).special);
    assert!(of(Method::Brdf).divisions > of(Method::LtcFast).divisions);
}

/// The table of docs/design.md §4.10 is the shaders' count: a shader that changes its work
/// per light changes this test's verdict until the table says so too.
#[test]
fn the_design_table_is_the_shaders_count() {
    let design =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/design.md")).unwrap();
    for (m, w) in work_per_light().unwrap() {
        let row = format!(
            "| `{}` | {} | {} | {} | {} |",
            m.name(),
            w.arithmetic,
            w.divisions,
            w.special,
            w.reads
        );
        assert!(
            design.contains(&row),
            "docs/design.md §4.10 lacks the row {row}"
        );
    }
}

/// A method file's work is counted as the lab's own: the lab's `ltc` written as a file costs
/// what `add_ltc` costs in special functions (one root for the distance), and its arithmetic
/// within a fifth of it (the same math; the file takes each |det M⁻¹| per light, which the lab
/// takes once per pixel, and the lab reads its rules from the uniforms); the file without
/// case 2's test costs no more than the file with it (an early return is not counted: a light
/// that reaches the sum does not take it).
#[test]
fn a_method_files_work_is_counted_from_its_ir() {
    use ltc_lab::gpu::method_file::MethodFile;
    let file = |name: &str| {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("assets/methods")
            .join(name);
        let work = ltc_lab::gpu::work::file_work(&MethodFile::read(&path).unwrap()).unwrap();
        assert_eq!(work.len(), 1, "{name} shades one shape");
        work[0].1
    };
    let ltc = file("ltc.wgsl");
    let no_case2 = file("no-case2.wgsl");
    let lab = work_per_light()
        .unwrap()
        .into_iter()
        .find(|(m, _)| *m == ltc_lab::render::Method::Ltc)
        .unwrap()
        .1;
    assert_eq!(ltc.special, lab.special, "{ltc:?} against {lab:?}");
    let apart = f64::from(ltc.arithmetic.abs_diff(lab.arithmetic)) / f64::from(lab.arithmetic);
    assert!(apart < 0.2, "{ltc:?} against {lab:?}");
    assert!(
        no_case2.arithmetic <= ltc.arithmetic,
        "{no_case2:?} against {ltc:?}"
    );
    let rect = ltc_lab::gpu::work::file_work(
        &MethodFile::read(
            &std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("assets/methods/threejs-rect.wgsl"),
        )
        .unwrap(),
    )
    .unwrap();
    assert_eq!(rect[0].0, "rect");
    assert!(rect[0].1.special > 0);
}
